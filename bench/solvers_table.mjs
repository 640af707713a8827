// The table of bench/solvers.sh: per instance the CPU seconds of every solver, whether their
// optimal objectives agree, and the exact solver's speed-up; then the median ratios.
//   node bench/solvers_table.mjs <solvers.tsv> <time-limit> <synthetic 0|1>
import { readFileSync } from 'node:fs';

const [tsvPath, limitText, syntheticText] = process.argv.slice(2);
const limit = Number(limitText);
const solvers = ['exact', 'glpk', 'glpk-tuned', 'glpsol', 'cbc'];
const compared = ['glpk', 'glpsol', 'cbc', 'glpk-tuned'];

const rows = readFileSync(tsvPath, 'utf8').trim().split('\n').slice(1)
  .map((line) => line.split('\t'))
  .map(([instance, edges, conflicts, solver, status, objective, cpu, wall]) => ({
    instance, edges, conflicts, solver, status, objective: Number(objective),
    cpu: Number(cpu), wall: Number(wall),
  }));
const instances = [...new Set(rows.map((r) => r.instance))];
const finished = (r) => r.status === 'optimal' || r.status === 'infeasible';

// The optimal objectives agree within 1e-6 (relative), and no solver calls infeasible what
// another solved.
function agreement(results) {
  const done = results.filter(finished);
  const optimal = done.filter((r) => r.status === 'optimal').map((r) => r.objective);
  if (done.some((r) => r.status === 'infeasible') && optimal.length > 0) return false;
  return optimal.every((x) => Math.abs(x - optimal[0]) <= 1e-6 * Math.max(1, Math.abs(x)));
}

const time = (r) => (finished(r) ? r.cpu.toFixed(2) : `>${limit}`);
// other / exact; a bound when either did not finish.
function ratio(other, exact, key) {
  const value = other[key] / Math.max(exact[key], 1e-3);
  const prefix = !finished(other) ? '>' : !finished(exact) ? '<' : '';
  return { value, text: `${prefix}${value.toFixed(1)}` };
}
const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length === 0 ? NaN : s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

const header = ['instance', '|E|', '|I|', ...solvers, 'agree', ...compared.map((s) => `${s}/exact`)];
const table = [header];
const ratios = Object.fromEntries(compared.map((s) => [s, { cpu: [], wall: [] }]));
let disagreements = 0;
for (const instance of instances) {
  const results = rows.filter((r) => r.instance === instance);
  const by = Object.fromEntries(results.map((r) => [r.solver, r]));
  const agree = agreement(results);
  disagreements += agree ? 0 : 1;
  const cells = [instance, by.exact.edges, by.exact.conflicts, ...solvers.map((s) => time(by[s])),
    agree ? 'yes' : 'NO'];
  for (const s of compared) {
    const r = ratio(by[s], by.exact, 'cpu');
    ratios[s].cpu.push(r.value);
    ratios[s].wall.push(ratio(by[s], by.exact, 'wall').value);
    cells.push(r.text);
  }
  table.push(cells);
}
const widths = header.map((_, i) => Math.max(...table.map((row) => String(row[i]).length)));
if (syntheticText === '1')
  console.log('SYNTHETIC instances (tessera_p1_instances: random singularities on a flat torus, ' +
    'shaped like thesis Appendix B), not port graphs of real layouts.');
console.log(`CPU seconds per solver (time limit ${limit} s; >${limit}: not finished); ` +
  'ratio = other / exact (> : a lower bound, the other did not finish).');
for (const row of table) console.log(row.map((c, i) => String(c).padStart(widths[i])).join('  '));
const summary = compared.map((s) =>
  `${s}/exact ${median(ratios[s].cpu).toFixed(1)}x (wall ${median(ratios[s].wall).toFixed(1)}x)`);
console.log(`median speed-up of exact over: ${summary.join(', ')}; ` +
  `${instances.length} instances, ${disagreements} with disagreeing optima`);
process.exitCode = disagreements ? 1 : 0;
