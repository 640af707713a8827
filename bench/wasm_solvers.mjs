// The exact P1 solver in the wasm build against the native one (issue 5: "wasm within 2x of
// native"), on the instances of bench/solvers.sh (build/bench-p1, or a directory given):
//   node bench/wasm_solvers.mjs [instance-dir] [--time-limit S]
// Per instance: the native `tessera solve --json` process (CPU seconds from the shell's children
// times: start-up and reading included) and the wasm module's matchingSolve() on the JSON text
// (CPU seconds of this process around the call: parsing included), the solvers' own seconds
// (wall clock inside the solver, reading excluded), whether both give the same answer, and the
// wasm / native ratios with their medians. The wasm module solves each instance twice: the first
// call may run code V8 has not optimized yet (it compiles hot functions again in the background,
// which the CPU seconds count), the second shows the optimized code ("again"); both calls must
// give the native answer, and the table says whether all three searched as many nodes.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadTessera } from '../tests/wasm/tessera_module.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const limitAt = args.indexOf('--time-limit');
const limit = limitAt >= 0 ? Number(args.splice(limitAt, 2)[1]) : 60;
const dir = args[0] ?? path.join(root, 'build/bench-p1');
const tessera = process.env.TESSERA ?? path.join(root, 'build/native/cli/tessera');

function instanceFiles(folder) {
  return fs.readdirSync(folder, { withFileTypes: true }).flatMap((entry) => {
    const full = path.join(folder, entry.name);
    if (entry.isDirectory()) return instanceFiles(full);
    return entry.name.endsWith('.json') ? [full] : [];
  }).sort();
}

// `bash -c 'times'` prints "0m0.001s 0m0.000s" twice, the second line for the children.
const childrenSeconds = (line) => line.trim().split(/\s+/)
  .map((t) => t.match(/(\d+)m([\d.]+)s/)).reduce((sum, m) => sum + 60 * Number(m[1]) + Number(m[2]), 0);

function solveNative(file) {
  const out = path.join(fs.mkdtempSync(path.join(process.env.TMPDIR ?? '/tmp', 'p1-')), 'out.json');
  const run = spawnSync('bash', ['-c', '"$@" > "$OUT" && times', '_', tessera, 'solve', file,
    '--json', '--time-limit', String(limit)], { env: { ...process.env, OUT: out }, encoding: 'utf8' });
  if (run.status !== 0) throw new Error(`tessera solve ${file} failed: ${run.stderr}`);
  const result = JSON.parse(fs.readFileSync(out, 'utf8'));
  fs.rmSync(path.dirname(out), { recursive: true });
  return { result, cpu: childrenSeconds(run.stdout.trim().split('\n').at(-1)) };
}

function solveWasm(module, text) {
  const before = process.cpuUsage();
  const result = module.matchingSolve(text, 'exact', limit);
  const used = process.cpuUsage(before);
  return { result, cpu: (used.user + used.system) / 1e6 };
}

const sameAnswer = (a, b) => a.status === b.status && (a.status !== 'optimal' ||
  Math.abs(a.objective - b.objective) <= 1e-9 * Math.max(1, Math.abs(a.objective)));
const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

const files = instanceFiles(dir);
if (files.length === 0) {
  console.error(`wasm_solvers: no instances in ${dir}; run bench/solvers.sh first`);
  process.exit(2);
}
const module = await loadTessera();
const table = [['instance', '|E|', '|I|', 'status', 'native cpu', 'wasm cpu', 'native solver',
  'wasm solver', 'wasm again', 'same', 'same nodes', 'wasm/native cpu', 'wasm/native solver',
  'again/native solver']];
const cpuRatios = [];
const solverRatios = [];
const againRatios = [];
let different = 0;
for (const file of files) {
  const native = solveNative(file);
  const text = fs.readFileSync(file, 'utf8');
  const wasm = solveWasm(module, text);
  const again = solveWasm(module, text);
  const same = sameAnswer(native.result, wasm.result) && sameAnswer(native.result, again.result);
  different += same ? 0 : 1;
  const sameNodes = wasm.result.nodes === native.result.nodes &&
    again.result.nodes === native.result.nodes;
  const solverRatio = (result) => result.seconds / Math.max(native.result.seconds, 1e-4);
  const cpuRatio = wasm.cpu / Math.max(native.cpu, 1e-3);
  cpuRatios.push(cpuRatio);
  solverRatios.push(solverRatio(wasm.result));
  againRatios.push(solverRatio(again.result));
  table.push([path.relative(dir, file).replace(/\.json$/, ''), native.result.instance.edges,
    native.result.instance.conflicts, native.result.status, native.cpu.toFixed(3),
    wasm.cpu.toFixed(3), native.result.seconds.toFixed(4), wasm.result.seconds.toFixed(4),
    again.result.seconds.toFixed(4), same ? 'yes' : 'NO', sameNodes ? 'yes' : 'no',
    cpuRatio.toFixed(2), solverRatio(wasm.result).toFixed(2), solverRatio(again.result).toFixed(2)]);
}
const widths = table[0].map((_, i) => Math.max(...table.map((row) => String(row[i]).length)));
for (const row of table) console.log(row.map((c, i) => String(c).padStart(widths[i])).join('  '));
console.log(`median wasm / native: ${median(cpuRatios).toFixed(2)}x CPU (process vs module call), ` +
  `${median(solverRatios).toFixed(2)}x solver seconds (second call: ` +
  `${median(againRatios).toFixed(2)}x); ${files.length} instances, ` +
  `${different} with different answers`);
process.exitCode = different ? 1 : 0;
