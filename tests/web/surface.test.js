import { describe, expect, it } from 'vitest';
import { SURFACE_DEFAULTS, coreOptions, readSurfaceOptions } from '../../web/src/ui/surface-options.js';
import { SURFACE_FIGURES, surfaceFigureValues } from '../../web/src/ui/surface-figures.js';
import { tiledSurface } from '../../web/src/worker/surface-display.js';
import { quarterTubeColor } from '../../web/src/viewer/palette.js';
import { SURFACE_STAGES } from '../../web/src/worker/stages.js';

// The core's statistics of R2.4's surface (tessera regmap surface R2.4 --json).
const R24_STATS = {
  genus: 5,
  euler_characteristic: -8,
  quarter_tubes: 20,
  closed: true,
  oriented: true,
  self_intersections: 17,
  relations_hold: true,
  seconds: 0.105,
  failed_relations: [],
  base: 'relaxation',
  junctions: 1,
  tubes: 5,
  vertices: 552,
  faces: 560,
  tube_radius: 0.08441661333828594,
  relaxation: { iterations: 400, energy: 10.6, energy_change: 0.009, rms_motion: 0.0003, max_dart_angle: 2.4 },
};

describe('readSurfaceOptions', () => {
  it('reads the form, blanks around values ignored', () => {
    expect(readSurfaceOptions({ base: 'relax', radius: ' 0.25 ', smoothness: '8' })).toEqual({
      options: { base: 'relax', radius: 0.25, smoothness: 8 },
      problems: {},
    });
    expect(readSurfaceOptions({ base: 'auto', radius: '0', smoothness: '4' }).options).toEqual(SURFACE_DEFAULTS);
  });

  it('names each option it cannot use', () => {
    const { options, problems } = readSurfaceOptions({ base: 'cube', radius: '0.9', smoothness: '1' });
    expect(options).toEqual({});
    expect(problems.base).toMatch(/"auto", "platonic" or "relax"/);
    expect(problems.radius).toMatch(/from 0 \(automatic\) to 0.5 tube lengths/);
    expect(problems.smoothness).toMatch(/whole number of quads from 2 to 16/);
    expect(Object.keys(readSurfaceOptions({ base: 'auto', radius: 'thick', smoothness: '' }).problems)).toEqual(['radius', 'smoothness']);
  });

  it('gives the core its option names', () => {
    expect(coreOptions({ base: 'relax', radius: 0.2, smoothness: 6 })).toEqual({ base: 'relax', tubeRadius: 0.2, smoothness: 6 });
  });
});

describe('surfaceFigureValues', () => {
  const shown = (stats) => {
    const values = surfaceFigureValues(stats);
    return Object.fromEntries(SURFACE_FIGURES.map(([key, , format]) => [key, format(values[key])]));
  };

  it("shows R2.4's surface with its genus and quarter tubes as the edge graph gives them", () => {
    expect(shown(R24_STATS)).toEqual({
      genus: '5 = 1 − 1 + 5',
      euler_characteristic: '-8',
      quarter_tubes: '20 = 4 × 5',
      closed: 'yes',
      oriented: 'yes',
      relations: 'hold',
      self_intersections: '17 triangle pairs',
      base: 'relaxation',
      steps: '400',
      tube_radius: '0.0844',
      faces: '560',
      seconds: '105 ms',
    });
  });

  it('says when the surface is not what its graph says, and which relations fail', () => {
    const broken = { ...R24_STATS, genus: 4, quarter_tubes: 19, relations_hold: false, failed_relations: ['(AB)^5', 'C^2'] };
    expect(shown(broken)).toMatchObject({ genus: '4, not 1 − 1 + 5', quarter_tubes: '19, not 4 × 5', relations: 'fail: (AB)^5, C^2' });
    const open = { ...R24_STATS, closed: false, relations_hold: false, self_intersections: null };
    expect(shown(open)).toMatchObject({ closed: 'no', relations: 'not checked', self_intersections: 'not searched' });
    expect(shown({ ...R24_STATS, self_intersections: 0 }).self_intersections).toBe('none');
    expect(shown({ ...R24_STATS, self_intersections: 1 }).self_intersections).toBe('1 triangle pair');
  });
});

describe('quarterTubeColor', () => {
  it("gives the core's pastel colours: hue 0.13 turns for tile 0, then golden-angle steps", () => {
    const close = (actual, expected) => actual.forEach((c, i) => expect(c).toBeCloseTo(expected[i], 12));
    close(quarterTubeColor(0), [1, 0.25 + 0.75 * 0.78, 0.25]);
    // tile 1: hue 0.748 turns = 4.488 sextants, in the fifth (blue to magenta): [x, 0, 1], x = 0.488
    const close6 = (actual, expected) => actual.forEach((c, i) => expect(c).toBeCloseTo(expected[i], 6));
    close6(quarterTubeColor(1), [0.616153, 0.25, 1]);
    for (let tile = 0; tile < 200; tile++) {
      const color = quarterTubeColor(tile);
      expect(Math.min(...color)).toBeCloseTo(0.25, 12);
      expect(Math.max(...color)).toBeCloseTo(1, 12);
    }
  });
});

describe('tiledSurface', () => {
  // Two quads (0 1 4 3) and (1 2 5 4) of a strip, fanned into triangles, in quarter tubes 7 and 2.
  const strip = {
    positions: new Float32Array([0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0]),
    triangles: new Uint32Array([0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4]),
    triangleFace: new Uint32Array([0, 0, 1, 1]),
    tile: new Int32Array([7, 2]),
  };

  it('splits the vertices where quarter tubes meet, each copy with its quarter tube colour', () => {
    const surface = tiledSurface(strip);
    expect(surface.positions).toHaveLength(3 * 8); // 1 and 4 lie on both quads
    expect([...surface.triangles]).toEqual([0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7]);
    const vertex = (array, i) => [...array.subarray(3 * i, 3 * i + 3)];
    expect(vertex(surface.positions, 1)).toEqual(vertex(surface.positions, 4)); // vertex 1 twice
    expect(vertex(surface.positions, 2)).toEqual(vertex(surface.positions, 7)); // vertex 4 twice
    const [a, b] = [quarterTubeColor(7), quarterTubeColor(2)].map((c) => [...new Float32Array(c)]);
    for (const i of [0, 1, 2, 3]) expect(vertex(surface.colors, i)).toEqual(a);
    for (const i of [4, 5, 6, 7]) expect(vertex(surface.colors, i)).toEqual(b);
  });

  it('gives each corner a copy of its own vertex, also for faces in no tile (-1)', () => {
    // Vertex 1 in tile -1 and vertex 0 in tile 1 (the last): v * tiles + tile would be one key.
    const apart = {
      positions: new Float32Array([0, 0, 0, 5, 5, 5, 1, 0, 0, 0, 1, 0, 6, 5, 5, 5, 6, 5]),
      triangles: new Uint32Array([0, 2, 3, 1, 4, 5]),
      triangleFace: new Uint32Array([0, 1]),
      tile: new Int32Array([1, -1]),
    };
    const surface = tiledSurface(apart, () => [0.5, 0.5, 0.5]);
    expect(surface.positions).toHaveLength(3 * 6);
    apart.triangles.forEach((v, corner) => {
      const w = surface.triangles[corner];
      expect([...surface.positions.subarray(3 * w, 3 * w + 3)]).toEqual([...apart.positions.subarray(3 * v, 3 * v + 3)]);
    });
  });

  it("keeps the whole surface's vertex normals on every copy, so the shading stays smooth", () => {
    const bent = { ...strip, positions: strip.positions.map((x, i) => (i % 3 === 2 && i >= 6 && i < 9 ? 0.5 : x)) };
    const surface = tiledSurface(bent);
    const normal = (i) => [...surface.normals.subarray(3 * i, 3 * i + 3)];
    expect(normal(1)).toEqual(normal(4));
    expect(normal(1)[2]).not.toBeCloseTo(1, 3); // tilted by the bent quad
    expect(Math.hypot(...normal(0))).toBeCloseTo(1, 6);
  });
});

describe('SURFACE_STAGES', () => {
  it("names the core's stages of a regular surface in order", () => {
    expect(SURFACE_STAGES.map(([stage]) => stage)).toEqual(['hyperbolic tiling', 'relaxation', 'tubification', 'self-intersections']);
  });
});

describe('drawnFigureValues', () => {
  it("shows each count found on the drawing beside the map's own, and the pairing kind", async () => {
    const { DRAWN_FIGURES, drawnFigureValues } = await import('../../web/src/ui/drawn-figures.js');
    const drawn = {
      target: 'Tetrahedron', target_kind: 'platonic', pairing: { kind: 'rotations' }, genus: 3,
      V: 24, E: 84, F: 55, expected: { V: 24, E: 84, F: 56 }, faces_are_disks: true, covers_once: true,
      face_orbits: 6, closed: true, oriented: true, mesh_faces: 166680, seconds: 1.5,
    };
    const values = drawnFigureValues(drawn);
    expect(values.V).toBe('24 = 24');
    expect(values.F).toBe('55, not 56');
    expect(values.target).toBe('Tetrahedron (platonic)');
    expect(values.pairing).toBe('rotations');
    for (const [key] of DRAWN_FIGURES) expect(values).toHaveProperty(key);
  });
});
