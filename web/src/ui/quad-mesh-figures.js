// The quad-count slider of the Quad mesh view and the figures of a quad mesh, as its panel shows
// them.
import { count } from './info-panel.js';
import { formatSeconds } from './map-figures.js';

// The slider runs over positions 0..SLIDER_STEPS, the quad count logarithmically from MIN_QUADS to
// MAX_QUADS (a coarse base mesh to a fine one), rounded to two significant digits.
export const MIN_QUADS = 100;
export const MAX_QUADS = 20000;
export const SLIDER_STEPS = 100;
export const DEFAULT_QUADS = 2000;

const roundTo2Digits = (x) => {
  const unit = 10 ** Math.max(0, Math.floor(Math.log10(x)) - 1);
  return Math.round(x / unit) * unit;
};

/** The target quad count at slider position p (0..SLIDER_STEPS, clamped). */
export function quadCountAt(position) {
  const p = Math.min(SLIDER_STEPS, Math.max(0, Number(position) || 0));
  return roundTo2Digits(MIN_QUADS * (MAX_QUADS / MIN_QUADS) ** (p / SLIDER_STEPS));
}

/** The first slider position whose count is nearest to `quads` (on the logarithmic scale). */
export function sliderPositionOf(quads) {
  const q = Number(quads) > 0 ? Number(quads) : DEFAULT_QUADS;
  let best = 0;
  for (let p = 1; p <= SLIDER_STEPS; p++) {
    if (Math.abs(Math.log(quadCountAt(p) / q)) < Math.abs(Math.log(quadCountAt(best) / q))) best = p;
  }
  return best;
}

const fixed = (digits) => (x) => (x === null || x === undefined ? '–' : Number(x).toFixed(digits));
const degrees = (x) => `${Number(x).toFixed(1)}°`;
const percentOfDiagonal = (x) => (Number.isFinite(Number(x)) ? `${(100 * Number(x)).toFixed(2)} % of the diagonal` : '–');

// The core's steps of a remesh in the order they run; it lists their times by name.
const STEPS = ['prep', 'integer lengths', 'patch maps', 'check', 'hausdorff'];

/**
 * The figures of a quad mesh result { info, target, remeshSeconds } for fillFigures:
 * { figures, values }. info: the core's (`tessera remesh --json` plus prepared_before);
 * remeshSeconds: the worker's time in the core, from the target to the checked mesh.
 */
export function quadMeshFigures({ info, target, remeshSeconds }) {
  const figures = [
    ['target', 'Target quads', count],
    ['quads', 'Quads', count],
    ['vertices', 'Vertices', count],
    ['irregular_vertices', 'Irregular vertices', count],
    ['patches', 'Patches', count],
    ['chains', 'Chains of opposite sides', count],
    ['lambda', 'lambda (parameter units per quad)', (x) => Number(x).toPrecision(4)],
    ['min_scaled_jacobian', 'Scaled Jacobian, least', fixed(3)],
    ['mean_scaled_jacobian', 'Scaled Jacobian, mean', fixed(3)],
    ['nonpositive_jacobian_quads', 'Quads with a scaled Jacobian ≤ 0', count],
    ['flipped_quads', 'Flipped quads', count],
    ['max_angle_deviation', 'Angle deviation, largest', degrees],
    ['mean_angle_deviation', 'Angle deviation, mean', degrees],
    ['hausdorff_relative', 'Hausdorff distance to the input', percentOfDiagonal],
    ['euler_characteristic', 'Euler characteristic', String],
    ['remesh_seconds', 'Remesh at this count', formatSeconds],
  ];
  const values = {
    ...info,
    target,
    remesh_seconds: remeshSeconds,
    euler_characteristic: `${info.euler_characteristic} (input ${info.input_euler_characteristic})`,
  };
  const rank = (step) => (STEPS.includes(step) ? STEPS.indexOf(step) : STEPS.length);
  const steps = Object.entries(info.seconds ?? {}).sort(([a], [b]) => rank(a) - rank(b));
  for (const [step, seconds] of steps) {
    const key = `time_${step.replace(/\W+/g, '_')}`;
    figures.push([key, `Time: ${step}${step === 'prep' && info.prepared_before ? ' (kept)' : ''}`, formatSeconds]);
    values[key] = seconds;
  }
  return { figures, values };
}

/**
 * The panel's one-line verdict on a quad mesh: conforming (a manifold of the input's Euler
 * characteristic) or what is wrong, its flips, and its quads with a scaled Jacobian <= 0 (reflex
 * or folded corners, most at the layout's own corners: `nonpositive_corners_at_nodes`).
 */
export function quadMeshVerdict(info) {
  const parts = [];
  if (!info.manifold) parts.push('not a manifold');
  if (info.euler_characteristic !== info.input_euler_characteristic) parts.push('another Euler characteristic than the input');
  if (parts.length === 0) parts.push('conforming');
  parts.push(info.flipped_quads > 0 ? `${count(info.flipped_quads)} flipped quads` : 'no flips');
  const folded = Number(info.nonpositive_jacobian_quads) || 0;
  if (folded > 0) parts.push(`${count(folded)} ${folded === 1 ? 'quad' : 'quads'} with a scaled Jacobian ≤ 0`);
  return `${count(info.quads)} quads, ${count(info.irregular_vertices)} irregular vertices: ${parts.join(', ')}`;
}
