import { describe, expect, it } from 'vitest';
import {
  DEFAULT_QUADS,
  MAX_QUADS,
  MIN_QUADS,
  SLIDER_STEPS,
  quadCountAt,
  quadMeshFigures,
  quadMeshVerdict,
  sliderPositionOf,
} from '../../web/src/ui/quad-mesh-figures.js';
import { quadEdges, quadSurface, quadTriangles } from '../../web/src/worker/quad-mesh-display.js';
import { REMESH_STAGES, planStages, stagedProgress } from '../../web/src/worker/stages.js';

// The core's figures of a quad mesh of the sphere (tessera remesh sphere.obj --quads 400 --json),
// trimmed, with the wasm module's prepared_before.
const SPHERE = {
  quads: 384,
  vertices: 386,
  irregular_vertices: 8,
  patches: 6,
  layout_valid: true,
  lambda: 4.6,
  chains: 3,
  compressed_sides: 0,
  min_scaled_jacobian: 0.52,
  mean_scaled_jacobian: 0.93,
  nonpositive_jacobian_quads: 0,
  flipped_quads: 0,
  max_angle_deviation: 31.2,
  mean_angle_deviation: 6.04,
  manifold: true,
  boundary_edges: 0,
  euler_characteristic: 2,
  input_euler_characteristic: 2,
  hausdorff_relative: 0.0042,
  seconds: { hausdorff: 0.003, check: 0.001, prep: 0, 'integer lengths': 0.0001, 'patch maps': 0.002 },
  prepared_before: true,
};

describe('the quad-count slider', () => {
  it('runs from MIN_QUADS to MAX_QUADS, two significant digits, increasing', () => {
    expect(quadCountAt(0)).toBe(MIN_QUADS);
    expect(quadCountAt(SLIDER_STEPS)).toBe(MAX_QUADS);
    expect(quadCountAt(-5)).toBe(MIN_QUADS);
    expect(quadCountAt('abc')).toBe(MIN_QUADS);
    const counts = Array.from({ length: SLIDER_STEPS + 1 }, (_, p) => quadCountAt(p));
    counts.forEach((q, p) => {
      if (p > 0) expect(q).toBeGreaterThanOrEqual(counts[p - 1]);
      expect(String(q).replace(/0+$/, '').length).toBeLessThanOrEqual(2);
    });
  });

  it('finds the position of a count, and the default count is near its position', () => {
    for (let p = 0; p <= SLIDER_STEPS; p++) expect(quadCountAt(sliderPositionOf(quadCountAt(p)))).toBe(quadCountAt(p));
    const q = quadCountAt(sliderPositionOf(DEFAULT_QUADS));
    expect(Math.abs(q - DEFAULT_QUADS) / DEFAULT_QUADS).toBeLessThan(0.05);
    expect(sliderPositionOf(10)).toBe(0);
    expect(sliderPositionOf(1e9)).toBe(SLIDER_STEPS);
  });
});

describe('quadMeshFigures', () => {
  it('lists the figures of issue 39, the target and the remesh time, the steps in the order they run', () => {
    const { figures, values } = quadMeshFigures({ info: SPHERE, target: 400, remeshSeconds: 0.0123 });
    const shown = Object.fromEntries(figures.map(([key, label, format]) => [key, [label, format(values[key])]]));
    for (const key of ['quads', 'vertices', 'irregular_vertices', 'patches', 'min_scaled_jacobian', 'mean_scaled_jacobian', 'max_angle_deviation', 'hausdorff_relative']) {
      expect(shown[key]).toBeDefined();
    }
    expect(shown.target[1]).toBe('400');
    expect(shown.quads[1]).toBe('384');
    expect(shown.min_scaled_jacobian[1]).toBe('0.520');
    expect(shown.max_angle_deviation[1]).toBe('31.2°');
    expect(shown.hausdorff_relative[1]).toBe('0.42 % of the diagonal');
    expect(shown.euler_characteristic[1]).toBe('2 (input 2)');
    expect(shown.remesh_seconds[1]).toBe('12 ms');
    expect(figures.map(([key]) => key).filter((key) => key.startsWith('time_'))).toEqual([
      'time_prep',
      'time_integer_lengths',
      'time_patch_maps',
      'time_check',
      'time_hausdorff',
    ]);
    expect(shown.time_prep[0]).toBe('Time: prep (kept)');
  });
});

describe('quadMeshVerdict', () => {
  it('says conforming without flips, or what is wrong', () => {
    expect(quadMeshVerdict(SPHERE)).toBe('384 quads, 8 irregular vertices: conforming, no flips');
    expect(quadMeshVerdict({ ...SPHERE, flipped_quads: 2, manifold: false })).toBe('384 quads, 8 irregular vertices: not a manifold, 2 flipped quads');
    expect(quadMeshVerdict({ ...SPHERE, quads: 2228, nonpositive_jacobian_quads: 9 })).toBe(
      '2,228 quads, 8 irregular vertices: conforming, no flips, 9 quads with a scaled Jacobian ≤ 0',
    );
    expect(quadMeshVerdict({ ...SPHERE, euler_characteristic: 0 })).toBe('384 quads, 8 irregular vertices: another Euler characteristic than the input, no flips');
  });
});

// Two unit quads side by side: 0 1 2 3 and 1 4 5 2, in patches 0 and 1.
const TWO = {
  positions: new Float32Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 0, 2, 1, 0]),
  quads: new Uint32Array([0, 1, 2, 3, 1, 4, 5, 2]),
  patch: new Int32Array([0, 1]),
};

describe('quad mesh display', () => {
  it('splits each quad into two triangles of the same quad', () => {
    const { triangles, triangleFace } = quadTriangles(TWO.quads);
    expect([...triangles]).toEqual([0, 1, 2, 0, 2, 3, 1, 4, 5, 1, 5, 2]);
    expect([...triangleFace]).toEqual([0, 0, 1, 1]);
  });

  it('colours the quads by patch, splitting the vertices the patches share', () => {
    const colors = new Float32Array([1, 0, 0, 0, 0, 1]);
    const surface = quadSurface(TWO, colors);
    expect(surface.triangles).toHaveLength(12);
    expect(surface.positions.length / 3).toBe(8); // 1 and 2 once per patch
    const colorOf = (corner) => [...surface.colors.subarray(3 * surface.triangles[corner], 3 * surface.triangles[corner] + 3)];
    expect(colorOf(0)).toEqual([1, 0, 0]);
    expect(colorOf(6)).toEqual([0, 0, 1]);
    expect(surface.normals[2]).toBeCloseTo(1);
  });

  it('draws each edge once: the shared one too', () => {
    const segments = quadEdges(TWO.positions, TWO.quads);
    expect(segments).toHaveLength(6 * 7);
    const edges = new Set();
    for (let i = 0; i < segments.length; i += 6) {
      const a = [...segments.subarray(i, i + 3)].join(',');
      const b = [...segments.subarray(i + 3, i + 6)].join(',');
      edges.add([a, b].sort().join(' '));
    }
    expect(edges.size).toBe(7);
    expect(edges.has('1,0,0 1,1,0')).toBe(true);
  });

  it('has a label for each stage the core reports', () => {
    const seen = [];
    const onProgress = stagedProgress(planStages(REMESH_STAGES, [2, 2, 1], 0, 1), (label, fraction) => seen.push([label, fraction]));
    for (const [stage] of REMESH_STAGES) onProgress(stage, 0);
    expect(seen.map(([label]) => label)).toEqual(REMESH_STAGES.map(([, label]) => label));
    expect(seen.map(([, fraction]) => fraction)).toEqual([0, 0.4, 0.8]);
  });
});
