import { describe, expect, it } from 'vitest';
import { formatAlpha, layoutFigures, layoutVerdict } from '../../web/src/ui/layout-figures.js';
import { arcSegments, patchSurface } from '../../web/src/worker/layout-display.js';
import { sameLayout } from '../../web/src/ui/layout-view.js';
import { GRAPH_STAGES, SOLVE_STAGES, planStages, stagedProgress } from '../../web/src/worker/stages.js';

// The core's figures of the sphere's layout (tessera layout sphere.obj --json), trimmed.
const SPHERE = {
  singularities: 8,
  graph_edges: 155,
  conflicts: 1194,
  patches: 6,
  angle_rsd: 7.5,
  valid: true,
  objective: 1055.6363970828174,
  seconds: { check: 0.002, separatrices: 0.05, P1: 0.001, conflicts: 0.001, layout: 0.004 },
  alpha: 5,
  ports: 24,
  virtual_ports: 0,
  nodes: 8,
  arcs: 12,
  solver: 'exact',
  matching_status: 'optimal',
  lower_bound: 1055.6363970828174,
  unmatchable_ports: [],
  average_separatrix_length: 40.1,
  problems: [],
  problem_count: 0,
  patches_not_quads: 0,
};

describe('layoutVerdict', () => {
  it('says valid with the patch count', () => {
    expect(layoutVerdict(SPHERE)).toEqual({ valid: true, text: 'valid: 6 patches, all quads' });
  });

  it('counts the patches that are not quads', () => {
    const info = { ...SPHERE, valid: false, patches: 9, patches_not_quads: 2, problem_count: 3 };
    expect(layoutVerdict(info)).toEqual({ valid: false, text: 'invalid: 2 of 9 patches not quads' });
  });

  it('names a P1 without a matching and the ports no matching covers', () => {
    const info = { ...SPHERE, valid: false, patches: 1, objective: null, matching_status: 'infeasible', unmatchable_ports: [0, 2, 3] };
    expect(layoutVerdict(info).text).toBe('invalid: program P1 found no matching (infeasible; 3 ports no matching of G covers)');
  });

  it('says which limit stopped P1 before any matching, and that a node limit is the same everywhere', () => {
    const info = { ...SPHERE, valid: false, objective: null, matching_status: 'node_limit', unmatchable_ports: [] };
    expect(layoutVerdict(info).text).toMatch(/stopped at its node limit: the same on every machine/);
    const guard = { ...info, matching_status: 'time_limit' };
    expect(layoutVerdict(guard).text).toMatch(/stopped at its time guard/);
  });

  it('shows the limit that stopped a feasible matching short of optimal', () => {
    const { values } = layoutFigures({ info: { ...SPHERE, matching_status: 'feasible', matching_stopped_by: 'node_limit' }, solveSeconds: 1 });
    expect(values.matching_status).toBe('feasible, stopped by the node limit');
    expect(layoutFigures({ info: SPHERE, solveSeconds: 1 }).values.matching_status).toBe(SPHERE.matching_status);
  });

  it('says when folded singular rings took ports away', () => {
    const info = {
      ...SPHERE,
      valid: false,
      objective: null,
      matching_status: 'infeasible',
      unmatchable_ports: [2, 8, 11, 14, 16],
      folded_singularities: [54, 317, 475],
    };
    expect(layoutVerdict(info).text).toBe(
      'invalid: program P1 found no matching (infeasible; 5 ports no matching of G covers; the parameterization folds the rings of 3 singularities, leaving them fewer ports than their valence: a smoother field avoids this)',
    );
  });

  it('falls back to the number of problems', () => {
    const info = { ...SPHERE, valid: false, patches_not_quads: 0, problem_count: 4 };
    expect(layoutVerdict(info).text).toBe('invalid: 4 problems found by the checker');
  });
});

describe('layoutFigures', () => {
  it('lists the figures of issue 4, the re-solve time and the stage times in pipeline order', () => {
    const { figures, values } = layoutFigures({ info: SPHERE, solveSeconds: 0.0123 });
    const keys = figures.map(([key]) => key);
    for (const key of ['singularities', 'graph_edges', 'conflicts', 'patches', 'angle_rsd', 'objective', 'solve_seconds']) {
      expect(keys).toContain(key);
    }
    expect(keys.filter((key) => key.startsWith('time_'))).toEqual(['time_separatrices', 'time_conflicts', 'time_P1', 'time_layout', 'time_check']);
    const shown = Object.fromEntries(figures.map(([key, , format]) => [key, format(values[key])]));
    expect(shown.angle_rsd).toBe('7.50 %');
    expect(shown.ports).toBe('24 (0)');
    expect(shown.solve_seconds).toBe('12 ms');
    expect(shown.objective).toBe('1055.64');
  });

  it('says how many rounds P1 took and whether the worker solved them ahead', () => {
    expect(layoutFigures({ info: { ...SPHERE, rounds: 3, solved_before: true }, solveSeconds: 0.01 }).values.rounds).toBe(
      '3, solved ahead',
    );
    expect(layoutFigures({ info: { ...SPHERE, rounds: 1, solved_before: false }, solveSeconds: 0.01 }).values.rounds).toBe('1');
  });

  it('shows a missing objective as a dash', () => {
    const { figures, values } = layoutFigures({ info: { ...SPHERE, objective: null }, solveSeconds: 1 });
    const [, , format] = figures.find(([key]) => key === 'objective');
    expect(format(values.objective)).toBe('–');
  });
});

describe('formatAlpha', () => {
  it('writes the slider value as people do', () => {
    expect(formatAlpha('5')).toBe('5');
    expect(formatAlpha(0.5)).toBe('0.5');
    expect(formatAlpha('12.50')).toBe('12.5');
  });
});

describe('arcSegments', () => {
  it('turns polylines into consecutive segments, skipping one-point arcs', () => {
    const points = new Float32Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 5, 5, 5, 2, 2, 2, 3, 3, 3]);
    const offsets = new Uint32Array([0, 3, 4, 6]);
    expect([...arcSegments(points, offsets)]).toEqual([0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 1, 0, 2, 2, 2, 3, 3, 3]);
    expect(arcSegments(new Float32Array(), new Uint32Array([0]))).toHaveLength(0);
  });
});

describe('patchSurface', () => {
  it('splits vertices between patches and colours each patch with the core colour', () => {
    // Two triangles over a shared edge, in patches 0 and 1.
    const refined = {
      positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0]),
      triangles: new Uint32Array([0, 1, 2, 1, 3, 2]),
      triangleFace: new Uint32Array([0, 1]),
      patch: new Int32Array([0, 1]),
    };
    const colors = new Float32Array([1, 0, 0, 0, 0, 1]);
    const surface = patchSurface(refined, colors);
    expect(surface.positions.length / 3).toBe(6);
    expect(surface.triangles).toHaveLength(6);
    const colorOf = (corner) => [...surface.colors.subarray(3 * surface.triangles[corner], 3 * surface.triangles[corner] + 3)];
    expect(colorOf(0)).toEqual([1, 0, 0]);
    expect(colorOf(3)).toEqual([0, 0, 1]);
    expect(surface.triangles[1]).not.toBe(surface.triangles[3]); // vertex 1 split between the patches
  });

  it('shows patch ids without a colour grey', () => {
    const refined = {
      positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]),
      triangles: new Uint32Array([0, 1, 2]),
      triangleFace: new Uint32Array([0]),
      patch: new Int32Array([4]),
    };
    expect([...patchSurface(refined, new Float32Array(3)).colors.subarray(0, 3)]).toEqual([0.5, 0.5, 0.5]);
  });
});

describe('layout stages', () => {
  it('map the core stage names onto the bar', () => {
    const seen = [];
    const stages = [...GRAPH_STAGES, ...SOLVE_STAGES];
    const onProgress = stagedProgress(planStages(stages, stages.map(() => 1), 0, 1), (label, f) => seen.push([label, f]));
    onProgress('separatrices', 0.5);
    onProgress('arcs', 1);
    expect(seen).toEqual([
      ['Growing the separatrices (motorcycle growing)', 0.5 / stages.length],
      ['Tracing the arcs and cutting the mesh into patches', 1],
    ]);
  });
});

describe('sameLayout', () => {
  const layout = () => ({
    arcs: new Float32Array([0, 0, 0, 1, 0, 0]),
    surface: { positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]), colors: new Float32Array(9).fill(0.5), triangles: new Uint32Array([0, 1, 2]) },
    singularities: { positions: new Float32Array([0, 0, 0]), valences: new Int32Array([3]) },
    markerRadius: 0.1,
  });

  it('keeps the layers of a result that draws the same', () => {
    expect(sameLayout(layout(), layout())).toBe(true);
  });

  it('sees a moved arc, a recoloured patch, a new triangle or another singularity', () => {
    const moved = layout();
    moved.arcs[4] = 0.5;
    const recoloured = layout();
    recoloured.surface.colors[0] = 0.25;
    const longer = layout();
    longer.surface.triangles = new Uint32Array([0, 1, 2, 0, 2, 1]);
    const singular = layout();
    singular.singularities.valences = new Int32Array([5]);
    for (const other of [moved, recoloured, longer, singular]) expect(sameLayout(layout(), other)).toBe(false);
  });
});
