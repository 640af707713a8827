import { describe, expect, it } from 'vitest';
import { PARAM_STAGES, planStages, stagedProgress } from '../../web/src/worker/stages.js';
import { checkerTexels, gridTexels, UV_TEXTURES } from '../../web/src/viewer/textures.js';

describe('planStages', () => {
  it('gives the stages consecutive parts of the bar in proportion to their weights', () => {
    const plan = planStages([['a', 'A'], ['b', 'B'], ['c', 'C']], [1, 2, 1], 0.2, 1);
    expect(plan.map(([stage, label]) => [stage, label])).toEqual([['a', 'A'], ['b', 'B'], ['c', 'C']]);
    const bounds = plan.map(([, , start, end]) => [start, end]);
    [[0.2, 0.4], [0.4, 0.8], [0.8, 1]].forEach(([start, end], i) => {
      expect(bounds[i][0]).toBeCloseTo(start, 12);
      expect(bounds[i][1]).toBeCloseTo(end, 12);
    });
  });
});

describe('stagedProgress', () => {
  it('maps the core stages to labels and one fraction over the job', () => {
    const seen = [];
    const onProgress = stagedProgress(planStages(PARAM_STAGES, [1, 1, 1, 1, 1], 0, 1), (label, fraction) => seen.push([label, fraction]));
    onProgress('field', 0.5);
    onProgress('solve', 0);
    onProgress('injectivity', 1);
    expect(seen.map(([label]) => label)).toEqual(['Designing the cross field', 'Solving the Poisson system', 'Injectivity constraints near singularities (GLPK)']);
    [0.1, 0.6, 1].forEach((fraction, i) => expect(seen[i][1]).toBeCloseTo(fraction, 12));
  });

  it('shows a stage it does not know under its own name, keeping the bar, and clamps fractions', () => {
    const seen = [];
    const onProgress = stagedProgress([['solve', 'Solving', 0.5, 0.7]], (label, fraction) => seen.push([label, fraction]));
    onProgress('new step', 0.9);
    onProgress('solve', 7);
    onProgress('another', NaN);
    expect(seen).toEqual([['new step', 0.5], ['Solving', 0.7], ['another', 0.7]]);
  });
});

describe('uv textures', () => {
  const texel = (texels, size, x, y) => [...texels.subarray(4 * (y * size + x), 4 * (y * size + x) + 4)];

  it('checker: two light and two dark squares, opaque, spanning two units', () => {
    const texels = checkerTexels(8);
    expect(texels).toHaveLength(4 * 64);
    expect(texel(texels, 8, 0, 0)).toEqual(texel(texels, 8, 7, 7));
    expect(texel(texels, 8, 7, 0)).toEqual(texel(texels, 8, 0, 7));
    expect(texel(texels, 8, 3, 3)).not.toEqual(texel(texels, 8, 4, 3));
    expect(texels.filter((_, i) => i % 4 === 3).every((alpha) => alpha === 255)).toBe(true);
    expect(UV_TEXTURES.checker.units).toBe(2);
  });

  it('grid: ink along the cell border only, one cell per unit', () => {
    const texels = gridTexels(16, 2);
    const ink = texel(texels, 16, 0, 0);
    for (const [x, y] of [[1, 8], [15, 8], [14, 3], [8, 0], [8, 15]]) expect(texel(texels, 16, x, y)).toEqual(ink);
    for (const [x, y] of [[2, 2], [8, 8], [13, 13]]) expect(texel(texels, 16, x, y)).not.toEqual(ink);
    expect(UV_TEXTURES.grid.units).toBe(1);
  });
});
