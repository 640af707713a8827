// node tests/wasm/layout_timing.mjs <mesh> [--jumps] [--presolve] [alpha...]: times the quad layout of a mesh in
// the wasm module (each stage, then P1 solved again on the kept graph for each alpha, as the page's
// slider does, with the session's ResolveCache) beside the native CLI on the same file. Prints one
// line per step, then the median and the largest re-solve and how many took 100 ms or more. The
// alphas are solved one after the other; with --jumps each is reached in one move from the first
// layout at alpha 5 instead (the graph is built again before each, so the cache holds only what
// that first layout left). --presolve: the slider's positions are presolved after the first
// layout, as the page's worker does when idle, and the time that took is printed.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadTessera } from './tessera_module.mjs';
import { MAX_PRESOLVE_SECONDS, presolveOrder } from '../../web/src/worker/presolve.js';

const [file, ...rest] = process.argv.slice(2);
if (!file) {
  console.error('usage: node tests/wasm/layout_timing.mjs <mesh> [--jumps] [--presolve] [alpha...]');
  process.exit(2);
}
const jumps = rest.includes('--jumps');
const presolve = rest.includes('--presolve');
const alphaArgs = rest.filter((arg) => arg !== '--jumps' && arg !== '--presolve');
const SLIDER = Array.from({ length: 41 }, (_, k) => k / 2); // the page's alpha slider
const alphas = alphaArgs.length > 0 ? alphaArgs.map(Number) : [0, 1, 20, 5];
const cli = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../build/native/cli/tessera');
const tessera = await loadTessera();

const timed = (label, run) => {
  const start = performance.now();
  const result = run();
  const ms = performance.now() - start;
  console.log(`wasm ${label.padEnd(28)} ${ms.toFixed(1).padStart(9)} ms`);
  return { result, ms };
};

const steps = [
  timed('load', () => tessera.loadMesh(fs.readFileSync(file), path.basename(file))),
  timed('cross field', () => tessera.crossField({ sharp: 35 }, undefined)),
  timed('seamless param', () => tessera.seamlessParam({}, undefined)),
  timed('graph of the ports', () => tessera.layoutGraph({}, undefined)),
  timed('layout at alpha 5', () => tessera.layoutSolve(5, {}, undefined)),
];
const first = steps.at(-1).result.info;
const total = steps.reduce((sum, { ms }) => sum + ms, 0);
console.log(`wasm total (alpha 5)                  ${total.toFixed(1).padStart(9)} ms`);
const describe = (info) =>
  `|S| ${info.singularities}, |E_G| ${info.graph_edges}, |I| ${info.conflicts}, |P| ${info.patches}, ` +
  `valid ${info.valid}, P1 ${info.matching_status} ${info.objective}, RSD ${info.angle_rsd.toFixed(2)} %`;
console.log(`wasm layout: ${describe(first)}`);
// The worker's presolve after the first layout (web/src/worker/presolve.js): the slider's other
// positions, nearest to 5 first, each within MAX_PRESOLVE_SECONDS.
function presolveSlider() {
  const times = [];
  for (const alpha of presolveOrder(SLIDER, 5)) {
    const start = performance.now();
    const solved = tessera.layoutPresolve(alpha, { maxSeconds: MAX_PRESOLVE_SECONDS });
    times.push(performance.now() - start);
    if (!solved) break;
  }
  const sum = times.reduce((a, b) => a + b, 0);
  console.log(`wasm presolve of ${times.length} slider positions ${sum.toFixed(1).padStart(9)} ms (largest ${Math.max(...times).toFixed(1)} ms)`);
}

const resolves = [];
if (presolve) presolveSlider();
for (const alpha of alphas) {
  if (jumps) {
    tessera.layoutGraph({}, undefined);
    tessera.layoutSolve(5, {}, undefined);
    if (presolve) presolveSlider();
  }
  const { result, ms } = timed(`re-solve at alpha ${alpha}`, () => tessera.layoutSolve(alpha, {}, undefined));
  resolves.push(ms);
  const { info } = result;
  const s = info.seconds;
  console.log(`     P1 ${(1000 * s.P1).toFixed(1)} ms, arcs+refine ${(1000 * s.layout).toFixed(1)} ms, check ${(1000 * s.check).toFixed(1)} ms, rounds ${info.rounds} (${info.reused_rounds} laid out before); ${describe(info)}`);
}
if (resolves.length > 0) {
  const sorted = [...resolves].sort((a, b) => a - b);
  const slow = sorted.filter((ms) => ms >= 100).length;
  console.log(`wasm ${sorted.length} re-solves: median ${sorted[Math.floor(sorted.length / 2)].toFixed(1)} ms, largest ${sorted.at(-1).toFixed(1)} ms, ${slow} of ${sorted.length} took 100 ms or more`);
}

if (fs.existsSync(cli)) {
  const start = performance.now();
  const native = JSON.parse(execFileSync(cli, ['layout', file, '--alpha', '5', '--json'], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }));
  const ms = performance.now() - start;
  console.log(`native CLI layout at alpha 5 (whole process) ${ms.toFixed(1)} ms; stages ${JSON.stringify(native.seconds)}`);
  console.log(`native layout: ${describe(native)}`);
}
