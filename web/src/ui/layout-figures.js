// The verdict and the figures of a quad layout, as the Layout panel shows them.
import { count } from './info-panel.js';
import { formatSeconds } from './map-figures.js';

// The core's stages in the order they run; it lists their times by name.
const STAGES = ['separatrices', 'conflicts', 'P1', 'layout', 'check'];

// Why P1 stopped before any matching, in words. The node limit is work, the same on every machine;
// the time guard is the machine's speed and load.
const STOPPED = {
  node_limit: 'stopped at its node limit: the same on every machine; raise --max-solve-nodes natively',
  time_limit: "stopped at its time guard: this machine's speed decided, a faster or idle one may find one",
};

/**
 * The checker's verdict on a layout, in words: { valid, text }. info: the core's layout figures
 * (valid, patches, patches_not_quads, problem_count, matching_status, unmatchable_ports,
 * folded_singularities).
 */
export function layoutVerdict(info) {
  if (info.valid) return { valid: true, text: `valid: ${count(info.patches)} patches, all quads` };
  const status = info.matching_status;
  if (status !== 'optimal' && status !== 'feasible') {
    const ports = info.unmatchable_ports?.length ?? 0;
    const folded = info.folded_singularities?.length ?? 0;
    const foldedDetail =
      ports > 0 && folded > 0
        ? `; the parameterization folds the rings of ${count(folded)} singularities, leaving them fewer ports than their valence: a smoother field avoids this`
        : '';
    const detail = ports > 0 ? `; ${count(ports)} ports no matching of G covers${foldedDetail}` : '';
    return { valid: false, text: `invalid: program P1 found no matching (${STOPPED[status] ?? status}${detail})` };
  }
  const notQuads = Number(info.patches_not_quads) || 0;
  if (notQuads > 0) {
    return { valid: false, text: `invalid: ${count(notQuads)} of ${count(info.patches)} patches not quads` };
  }
  return { valid: false, text: `invalid: ${count(info.problem_count)} problems found by the checker` };
}

const percent = (x) => `${Number(x).toFixed(2)} %`;
const number = (x) => (x === null || x === undefined ? '–' : Number(x).toPrecision(6));

/**
 * The figures of a layout result { info, solveSeconds } for fillFigures: { figures, values }.
 * The re-solve time is the worker's, from alpha to the checked layout on the kept graph.
 */
export function layoutFigures({ info, solveSeconds }) {
  const figures = [
    ['alpha', 'alpha', String],
    ['singularities', 'Singularities |S|', count],
    ['ports', 'Ports (virtual)', String],
    ['graph_edges', 'Graph edges |E_G|', count],
    ['conflicts', 'Conflicts |I|', count],
    ['patches', 'Patches |P|', count],
    ['nodes', 'Nodes', count],
    ['arcs', 'Arcs', count],
    ['angle_rsd', 'Corner angle RSD', percent],
    ['objective', 'P1 objective', number],
    ['lower_bound', 'P1 lower bound', number],
    ['matching_status', 'P1 status', String],
    ['rounds', 'P1 rounds', String],
    ['solver', 'Solver', String],
    ['average_separatrix_length', 'Mean separatrix length', (x) => Number(x).toPrecision(4)],
    ['solve_seconds', 'Re-solve at this alpha', formatSeconds],
  ];
  const values = {
    ...info,
    ports: `${count(info.ports)} (${count(info.virtual_ports)})`,
    solve_seconds: solveSeconds,
    // A feasible matching that a limit stopped short of optimal says which limit.
    matching_status: info.matching_stopped_by ? `${info.matching_status}, stopped by the ${info.matching_stopped_by.replace('_', ' ')}` : info.matching_status,
    // The worker solves the slider's positions ahead while idle (presolve.js).
    rounds: `${info.rounds ?? '–'}${info.solved_before ? ', solved ahead' : ''}`,
  };
  for (const [stage, seconds] of stageTimes(info.seconds)) {
    const key = `time_${stage.replace(/\W+/g, '_')}`;
    figures.push([key, `Time: ${stage}`, formatSeconds]);
    values[key] = seconds;
  }
  return { figures, values };
}

// [[stage, seconds]] in the order the stages run, stages the page does not know last.
function stageTimes(seconds) {
  const rank = (stage) => (STAGES.includes(stage) ? STAGES.indexOf(stage) : STAGES.length);
  return Object.entries(seconds ?? {}).sort(([a], [b]) => rank(a) - rank(b));
}

/** The alpha slider's text: "5" or "0.5". */
export const formatAlpha = (alpha) => String(Number(Number(alpha).toFixed(2)));
