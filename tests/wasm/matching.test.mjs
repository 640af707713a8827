// Program P1 in the wasm module (matchingSolve) against the native CLI (`tessera solve --json`) on
// generated instances: random graphs with a planted perfect matching and random conflict pairs,
// some of them infeasible. Both must give the same status and objective, and the wasm matching
// must pass an independent check (degrees, conflicts, objective). Runs the CLI of build/native.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadTessera } from './tessera_module.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const cli = path.join(root, 'build/native/cli/tessera');
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'tessera-matching-'));
const tessera = await loadTessera();

// A small deterministic generator (mulberry32).
function random(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

// `ports` ports (the first ones) and `virtuals` virtual ports; a planted matching of the ports in
// pairs, `extra` random edges, `conflicts` random pairs (sparing the planted edges when `keep`).
function plantedInstance(seed, { ports, virtuals, extra, conflicts, keep }) {
  const next = random(seed);
  const pick = (n) => Math.floor(next() * n);
  const nodes = ports + virtuals;
  const edges = [];
  const weight = () => Math.round(1000 * (1 + 9 * next())) / 1000;
  for (let p = 0; p + 1 < ports; p += 2) edges.push([p, p + 1, weight()]);
  const planted = edges.length;
  while (edges.length < planted + extra) {
    const u = pick(nodes);
    const v = pick(nodes);
    if (u !== v) edges.push([Math.min(u, v), Math.max(u, v), weight()]);
  }
  const pairs = new Set();
  while (pairs.size < conflicts) {
    const a = pick(edges.length);
    const b = pick(edges.length);
    if (a === b || (keep && (a < planted || b < planted))) continue;
    pairs.add(`${Math.min(a, b)},${Math.max(a, b)}`);
  }
  const virtual = Array.from({ length: virtuals }, (_, i) => ports + i);
  return {
    format: 'tessera-p1', version: 1, nodes, virtual, edges,
    conflicts: [...pairs].map((pair) => pair.split(',').map(Number)),
  };
}

// Every port covered once, every virtual port at most once, no conflict pair, the objective.
function checkMatching(instance, chosen, objective) {
  const degree = new Array(instance.nodes).fill(0);
  let total = 0;
  for (const e of chosen) {
    const [u, v, w] = instance.edges[e];
    degree[u] += 1;
    degree[v] += 1;
    total += w;
  }
  const virtual = new Set(instance.virtual);
  degree.forEach((d, node) => assert.ok(virtual.has(node) ? d <= 1 : d === 1, `node ${node}`));
  const set = new Set(chosen);
  for (const [a, b] of instance.conflicts) assert.ok(!(set.has(a) && set.has(b)), `conflict ${a} ${b}`);
  assert.ok(Math.abs(total - objective) <= 1e-9 * Math.max(1, total));
}

function solveNative(instance, name) {
  const file = path.join(dir, `${name}.json`);
  fs.writeFileSync(file, JSON.stringify(instance));
  return JSON.parse(execFileSync(cli, ['solve', file, '--json'], { encoding: 'utf8' }));
}

const planted = [];
for (let seed = 1; seed <= 24; ++seed) {
  const ports = 16 + 2 * (seed % 9) + (seed % 8 === 0 ? 1 : 0);  // some odd: infeasible
  const keep = seed % 3 !== 0;  // the others may lose every feasible matching
  planted.push([`planted_${seed}`, plantedInstance(seed, {
    ports, virtuals: seed % 4, extra: 3 * ports, conflicts: keep ? 6 * ports : 4 * ports, keep,
  })]);
}
// Few edges, dense conflicts: perfect matchings exist, but the conflicts may forbid them all.
const crowded = [];
for (let seed = 25; seed <= 32; ++seed) {
  crowded.push([`crowded_${seed}`, plantedInstance(seed, {
    ports: 12, virtuals: 0, extra: 18, conflicts: 40 + 10 * (seed % 8), keep: false,
  })]);
}
const cases = [...planted, ...crowded];

test('wasm and native solve generated P1 instances alike, infeasible ones included', () => {
  const statuses = new Set();
  for (const [name, instance] of cases) {
    const native = solveNative(instance, name);
    const wasm = tessera.matchingSolve(JSON.stringify(instance), 'exact', 60);
    statuses.add(wasm.status);
    assert.equal(wasm.status, native.status, name);
    assert.ok(wasm.status === 'optimal' || wasm.status === 'infeasible', name);
    if (wasm.status === 'optimal') {
      assert.ok(Math.abs(wasm.objective - native.objective) <= 1e-9 * Math.max(1, native.objective), name);
      assert.equal(wasm.gap, 0, name);
      checkMatching(instance, wasm.edges, wasm.objective);
    } else {
      assert.equal(wasm.objective, null, name);
    }
  }
  assert.ok(statuses.has('optimal') && statuses.has('infeasible'), [...statuses].join(' '));
});

// An odd number of ports and no virtual port: no perfect matching, which the exact solver's
// blossom check sees at once but GLPK's branch-and-bound only proves after exhausting its tree
// (a minute here), so those stay out of the GLPK comparison.
const oddPortsOnly = (instance) => instance.virtual.length === 0 && instance.nodes % 2 === 1;

test('the wasm exact solver agrees with GLPK in wasm and is deterministic', () => {
  const compared = [...planted.filter(([, i]) => !oddPortsOnly(i)).slice(0, 8), ...crowded];
  const statuses = new Set();
  for (const [name, instance] of compared) {
    const text = JSON.stringify(instance);
    const exact = tessera.matchingSolve(text, 'exact', 60);
    const glpk = tessera.matchingSolve(text, 'glpk', 60);
    statuses.add(glpk.status);
    assert.equal(exact.status, glpk.status, name);
    if (exact.status === 'optimal')
      assert.ok(Math.abs(exact.objective - glpk.objective) <= 1e-6 * Math.max(1, glpk.objective), name);
    assert.deepEqual(tessera.matchingSolve(text, 'exact', 60).edges, exact.edges, name);
  }
  assert.ok(statuses.has('optimal') && statuses.has('infeasible'), [...statuses].join(' '));
});

test('bad instances and options are JS errors with the core message', () => {
  assert.throws(() => tessera.matchingSolve('{"format": "tessera-p1"', 'exact', 1), (e) => e.kind === 'parse');
  const text = JSON.stringify(cases[0][1]);
  assert.throws(() => tessera.matchingSolve(text, 'cplex', 1), /exact/);
  assert.throws(() => tessera.matchingSolve(text, 'exact', 0), /time limit/);
});
