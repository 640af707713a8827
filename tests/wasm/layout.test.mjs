// Quad layouts in the wasm module: the same layout as the native CLI on the same file (patch count,
// P1 objective, validity), alpha solved again on the kept graph, GLB and PLY of the layout, clear
// errors.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import validator from 'gltf-validator';
import { loadTessera, writeSampleObj } from './tessera_module.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const cli = path.join(root, 'build/native/cli/tessera');
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'tessera-layout-'));
const tessera = await loadTessera();

const sampleFile = (name) => writeSampleObj(tessera, name, dir);

// The layout of a file in the module at alpha, with the CLI's defaults (smooth field, sharp 35).
function wasmLayout(file, alpha, stages = []) {
  tessera.loadMesh(fs.readFileSync(file), path.basename(file));
  tessera.crossField({ sharp: 35 }, undefined);
  tessera.seamlessParam({}, undefined);
  const graph = tessera.layoutGraph({}, (stage, fraction) => stages.push([stage, fraction]));
  return { graph, layout: tessera.layoutSolve(alpha, {}, undefined) };
}

const nativeLayout = (file, alpha) =>
  JSON.parse(execFileSync(cli, ['layout', file, '--alpha', String(alpha), '--json'], { encoding: 'utf8' }));

// The icosphere has no constraint: its field is the smoothest one, whose global rotation the
// core fixes (smoothest.cpp), where rounding once gave the two builds z and -z (106 and 119 graph
// edges). The mechanical part's field follows its sharp edges. The double torus (the page's
// first sample) is symmetric: its graph once differed by an edge (901 and 900) because the
// growth took events at one time in the order rounding gave them (growth.h).
for (const name of ['sphere', 'part', 'genus2']) {
  test(`native and wasm give the same layout of the ${name} sample`, () => {
    const file = sampleFile(name);
    const stages = [];
    const { graph, layout } = wasmLayout(file, 5, stages);
    const native = nativeLayout(file, 5);
    const wasm = layout.info;
    for (const key of ['singularities', 'graph_edges', 'conflicts', 'patches', 'valid', 'nodes', 'arcs', 'matching_status']) {
      assert.deepEqual(wasm[key], native[key], key);
    }
    assert.ok(Math.abs(wasm.objective - native.objective) <= 1e-6 * Math.abs(native.objective), `objective ${wasm.objective} vs ${native.objective}`);
    assert.ok(Math.abs(wasm.angle_rsd - native.angle_rsd) < 1e-6, 'angle RSD');
    assert.equal(graph.info.graph_edges, native.graph_edges);
    assert.ok(stages.length > 0, 'progress');
    assert.ok(stages.some(([stage]) => stage === 'conflicts'), 'conflicts progress');
    assert.ok(stages.every(([stage, fraction]) => typeof stage === 'string' && fraction >= 0 && fraction <= 1));

    // The display arrays: one patch id per refined triangle, a colour per id, the matching's arcs,
    // singularities.
    const { refined, patchColors, arcs, singularities } = layout;
    assert.equal(refined.patch.length, refined.triangles.length / 3);
    const ids = new Set(refined.patch);
    assert.equal(ids.size, wasm.patches);
    assert.equal(patchColors.length, 3 * (Math.max(...ids) + 1));
    assert.equal(wasm.virtual_ports, 0);
    assert.equal(arcs.offsets.length - 1, wasm.ports / 2, 'one arc polyline per matched pair of ports');
    assert.equal(arcs.offsets.at(-1), arcs.points.length / 3);
    assert.equal(singularities.valences.length, wasm.singularities);
    assert.equal(wasm.valid, true, `${name}: ${wasm.problem_count} problems`);
    assert.equal(wasm.problem_count, 0);
  });
}

test('alpha is solved again on the kept graph; the result matches a fresh run', () => {
  const file = sampleFile('sphere');
  const first = wasmLayout(file, 5).layout.info;
  const coarse = tessera.layoutSolve(0, {}, undefined).info;
  assert.equal(coarse.alpha, 0);
  assert.equal(coarse.graph_edges, first.graph_edges);
  const again = tessera.layoutSolve(5, {}, undefined).info;
  assert.equal(again.patches, first.patches);
  assert.equal(again.objective, first.objective);
  assert.equal(tessera.layoutSolve(5, { solver: 'glpk' }, undefined).info.objective.toFixed(6), first.objective.toFixed(6));
  assert.equal(nativeLayout(file, 0).patches, coarse.patches, 'native at alpha 0');
});

test('presolved alphas give the layouts of fresh runs without solving; the shown layout stays', () => {
  const file = sampleFile('genus2');
  const first = wasmLayout(file, 5).layout.info;
  const shownGlb = tessera.layoutGlb();
  const alphas = [0, 1, 20];
  for (const alpha of alphas) assert.equal(tessera.layoutPresolve(alpha, { maxSeconds: 30 }), true, `alpha ${alpha}`);
  assert.ok(Buffer.from(tessera.layoutGlb()).equals(Buffer.from(shownGlb)), 'the shown layout is exported');
  const shown = tessera.layoutSolve(5, {}, undefined).info;
  assert.equal(shown.objective, first.objective);
  const presolved = alphas.map((alpha) => tessera.layoutSolve(alpha, {}, undefined).info);
  alphas.forEach((alpha, k) => {
    const fresh = wasmLayout(file, alpha).layout.info; // a fresh graph and cache
    assert.equal(presolved[k].solved_before, true, `alpha ${alpha}`);
    assert.equal(fresh.solved_before, false, `alpha ${alpha}`);
    for (const key of ['objective', 'patches', 'rounds', 'loop_conflicts', 'angle_rsd', 'valid']) {
      assert.equal(presolved[k][key], fresh[key], `alpha ${alpha}: ${key}`);
    }
  });
  assert.throws(() => tessera.layoutPresolve(-1, {}), (e) => e.kind === 'input' && /alpha/.test(e.message));
  assert.throws(() => tessera.layoutPresolve(1, { maxSeconds: 0 }), (e) => e.kind === 'input' && /maxSeconds/.test(e.message));
});

test('the layout exports as GLB (0 validator errors, _PATCH) and PLY (face property patch)', async () => {
  wasmLayout(sampleFile('sphere'), 5);
  const glb = tessera.layoutGlb();
  const report = await validator.validateBytes(glb);
  assert.equal(report.issues.numErrors, 0, JSON.stringify(report.issues.messages.slice(0, 3)));
  assert.match(Buffer.from(glb).toString('latin1'), /_PATCH/);
  const ply = Buffer.from(tessera.layoutPly()).toString('latin1');
  assert.match(ply.slice(0, 400), /property int patch/);
});

test('layout calls out of order and bad options are clear errors', () => {
  tessera.sampleMesh('sphere');
  const input = (pattern) => (e) => e.kind === 'input' && pattern.test(e.message);
  assert.throws(() => tessera.layoutGraph({}, undefined), input(/parameterization/));
  assert.throws(() => tessera.layoutSolve(5, {}, undefined), input(/parameterization/));
  assert.throws(() => tessera.layoutGlb(), input(/no quad layout/));
  tessera.seamlessParam({}, undefined);
  assert.throws(() => tessera.layoutSolve(5, {}, undefined), input(/graph of the ports/));
  assert.throws(() => tessera.layoutGraph({ rho: 0.5 }, undefined), input(/rho/));
  tessera.layoutGraph({}, undefined);
  assert.throws(() => tessera.layoutSolve(-1, {}, undefined), input(/alpha/));
  assert.throws(() => tessera.layoutSolve(5, { solver: 'cplex' }, undefined), (e) => e.kind === 'input');
  tessera.crossField({}, undefined);
  assert.throws(() => tessera.layoutSolve(5, {}, undefined), input(/parameterization/), 'a new field keeps a stale graph');
});
