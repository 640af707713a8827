// The table of bench/solvers.sh: per instance the CPU seconds of every solver, whether their
// answers agree, and the exact solver's speed-up; then the median ratios per set of instances, by
// process CPU seconds and, between the solvers of tessera solve, by the seconds of the solve alone.
// The confirmation runs (solvers "cbc-reduced" and "glpk-reduced", CBC and glpk-tuned on the
// instance `tessera reduce` leaves below the exact optimum; "cbc-cutoff", CBC given that optimum as
// cutoff; "glpk-long", glpk-tuned given more time) count in the agreement and have columns of
// their own, not ratios. Column "confirmed" names the solvers besides exact that finished with the
// same answer: GLPK (any of its runs) and CBC (any of its runs).
//   node bench/solvers_table.mjs <solvers.tsv> <time-limit>
import { readFileSync } from 'node:fs';

const [tsvPath, limitText] = process.argv.slice(2);
const limit = Number(limitText);
const rows = readFileSync(tsvPath, 'utf8').trim().split('\n').slice(1)
  .map((line) => line.split('\t'))
  .map(([set, instance, edges, conflicts, solver, status, objective, cpu, wall, solve]) => ({
    set, instance, edges: Number(edges), conflicts: Number(conflicts), solver, status,
    objective: Number(objective), cpu: Number(cpu), wall: Number(wall),
    solve: solve ? Number(solve) : NaN,
  }));
const solvers = ['exact', 'glpk', 'glpk-tuned', 'glpsol', 'cbc']
  .filter((s) => rows.some((r) => r.solver === s));
const compared = solvers.filter((s) => s !== 'exact');
const instances = [...new Set(rows.map((r) => `${r.set}/${r.instance}`))];
const finished = (r) => r.status === 'optimal' || r.status === 'infeasible';

// Every finished solver gives the same answer: the optimal objectives agree within 1e-6
// (relative), and no solver calls infeasible what another solved.
function agreement(results) {
  const done = results.filter(finished);
  const optimal = done.filter((r) => r.status === 'optimal').map((r) => r.objective);
  if (done.some((r) => r.status === 'infeasible') && optimal.length > 0) return false;
  return optimal.every((x) => Math.abs(x - optimal[0]) <= 1e-6 * Math.max(1, Math.abs(x)));
}

function answer(results) {
  const done = results.filter(finished);
  return done.length === 0 ? 'unsolved' : done[0].status;
}

const time = (r) => (finished(r) ? r.cpu.toFixed(3) : `>${limit}`);
// other / exact; a bound when either did not finish. Process seconds have a 1 ms resolution,
// solve seconds (steady clock) are taken down to 1 us.
function ratio(other, exact, key) {
  const value = other[key] / Math.max(exact[key], key === 'solve' ? 1e-6 : 1e-3);
  const prefix = !finished(other) ? '>' : !finished(exact) ? '<' : '';
  return { value, text: `${prefix}${value.toFixed(1)}` };
}
const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length === 0 ? NaN : s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

// The solvers of tessera solve, whose rows carry the seconds of the solve alone.
const inProcess = compared.filter((s) => rows.some((r) => r.solver === s && Number.isFinite(r.solve)));
const confirmations = ['cbc-reduced', 'cbc-cutoff', 'glpk-reduced', 'glpk-long'].filter((s) => rows.some((r) => r.solver === s));
const confirmation = (r) => (!r ? '-' : finished(r) ? r.cpu.toFixed(3) : 'unfinished');
const families = {
  GLPK: ['glpk', 'glpk-tuned', 'glpsol', 'glpk-reduced', 'glpk-long'],
  CBC: ['cbc', 'cbc-reduced', 'cbc-cutoff'],
};
// The families with a finished run, given that the answers agree.
const confirmedBy = (results) => Object.keys(families)
  .filter((f) => results.some((r) => families[f].includes(r.solver) && finished(r)));
const header = ['instance', '|E|', '|I|', 'answer', ...solvers,
  ...confirmations.map((s) => s.replace('-', ' ')), 'agree', 'confirmed',
  ...compared.map((s) => `${s}/exact`), ...inProcess.map((s) => `${s}/exact solve`)];
const table = [header];
const measured = [];  // per instance: its set, size and ratios
let disagreements = 0;
for (const key of instances) {
  const results = rows.filter((r) => `${r.set}/${r.instance}` === key);
  const by = Object.fromEntries(results.map((r) => [r.solver, r]));
  const agree = agreement(results);
  disagreements += agree ? 0 : 1;
  const confirmed = agree && finished(by.exact) ? confirmedBy(results) : [];
  const cells = [key, by.exact.edges, by.exact.conflicts, answer(results),
    ...solvers.map((s) => time(by[s])), ...confirmations.map((s) => confirmation(by[s])),
    agree ? 'yes' : 'NO', confirmed.join('+') || '-'];
  const ratios = {};
  for (const s of compared) {
    const r = ratio(by[s], by.exact, 'cpu');
    ratios[s] = { cpu: r.value, wall: ratio(by[s], by.exact, 'wall').value };
    cells.push(r.text);
  }
  for (const s of inProcess) {
    const r = ratio(by[s], by.exact, 'solve');
    ratios[s].solve = r.value;
    cells.push(r.text);
  }
  measured.push({ set: by.exact.set, edges: by.exact.edges, ratios, confirmed });
  table.push(cells);
}
const widths = header.map((_, i) => Math.max(...table.map((row) => String(row[i]).length)));
console.log(`CPU seconds per process (start-up and reading included; time limit ${limit} s, ` +
  `>${limit}: not finished); ratio = other / exact (>: a lower bound, the other did not finish).`);
for (const row of table) console.log(row.map((c, i) => String(c).padStart(widths[i])).join('  '));

function summary(label, chosen) {
  if (chosen.length === 0) return;
  const parts = compared.map((s) => `${s} ${median(chosen.map((m) => m.ratios[s].cpu)).toFixed(1)}x` +
    ` (wall ${median(chosen.map((m) => m.ratios[s].wall)).toFixed(1)}x)`);
  console.log(`median speed-up of exact, ${label} (${chosen.length}): ${parts.join(', ')}`);
  if (inProcess.length === 0) return;
  console.log(`  the solve alone (start-up and reading left out): ${inProcess.map((s) =>
    `${s} ${median(chosen.map((m) => m.ratios[s].solve)).toFixed(1)}x`).join(', ')}`);
}
const sets = [...new Set(measured.map((m) => m.set))];
for (const set of sets) summary(`${set} instances`, measured.filter((m) => m.set === set));
for (const set of sets)
  summary(`${set} instances with |E| >= 1000`, measured.filter((m) => m.set === set && m.edges >= 1000));
summary('all instances', measured);
const finishedOf = (solver, text) => {
  const runs = rows.filter((r) => r.solver === solver);
  if (runs.length > 0) console.log(`${text}: ${runs.filter(finished).length} of ${runs.length} finished`);
};
finishedOf('cbc-reduced', 'CBC below the exact optimum, where CBC alone did not finish');
finishedOf('cbc-cutoff', 'CBC with the exact optimum as cutoff, where CBC below it did not finish');
finishedOf('glpk-reduced', 'glpk-tuned below the exact optimum, where no run of GLPK finished');
finishedOf('glpk-long', 'glpk-tuned with more time, where glpk-tuned below it did not finish');
const by = (f) => measured.filter((m) => m.confirmed.includes(f)).length;
console.log(`answers confirmed by GLPK on ${by('GLPK')}, by CBC on ${by('CBC')}, by both on ` +
  `${measured.filter((m) => m.confirmed.length === 2).length} of ${measured.length} instances`);
console.log(`${instances.length} instances, ${disagreements} with disagreeing answers`);
process.exitCode = disagreements ? 1 : 0;
