import { describe, expect, it } from 'vitest';
import { DEFAULT_STATE, formatHash, parseHash } from '../../web/src/ui/hash.js';

describe('parseHash', () => {
  it('gives the defaults for an empty or missing hash', () => {
    for (const hash of ['', '#', undefined, null]) {
      expect(parseHash(hash)).toEqual({ state: DEFAULT_STATE, problems: [] });
    }
  });

  it('reads every shareable key', () => {
    const { state, problems } = parseHash(
      '#mode=regmap&sample=genus2&shading=smooth&wireframe=1&map=R3.1&view=surface&colors=orbits&base=relax&radius=0.2' +
        '&smoothness=8&field=1&align=curvature&sharp=180&h=0.05&texture=grid',
    );
    expect(problems).toEqual([]);
    expect(state).toEqual({
      mode: 'regmap',
      sample: 'genus2',
      shading: 'smooth',
      wireframe: true,
      map: 'R3.1',
      view: 'surface',
      on: null,
      colors: 'orbits',
      base: 'relax',
      radius: 0.2,
      smoothness: 8,
      field: true,
      align: 'curvature',
      sharp: 180,
      h: 0.05,
      texture: 'grid',
      find: null,
      genus: null,
      p: null,
      q: null,
      realized: false,
      kind: null,
      sort: null,
      cam: null,
      spin: false,
    });
    expect(parseHash('wireframe=0').state.wireframe).toBe(false);
  });

  it('checks the Field options as the form does, and drops invalid ones with a note', () => {
    for (const hash of ['sharp=0', 'sharp=500', 'sharp=3e1', 'h=0', 'h=7', 'h=1%2F0', 'h=NaN', 'align=best', 'texture=marble', 'field=yes']) {
      const { state, problems } = parseHash(`#${hash}`);
      expect(state, hash).toEqual(DEFAULT_STATE);
      expect(problems, hash).toEqual([`Link setting "${hash.split('=')[0]}" has an invalid value and was ignored.`]);
    }
    expect(parseHash('#h=1e-3&sharp=1').state).toMatchObject({ h: 0.001, sharp: 1 });
  });

  it('checks the surface view and its options as the form does, and drops invalid ones with a note', () => {
    const refused = ['view=3d', 'base=octahedron', 'radius=-0.1', 'radius=0.6', 'radius=1e-2', 'radius=.', 'smoothness=1', 'smoothness=17', 'smoothness=4.5'];
    for (const hash of refused) {
      const { state, problems } = parseHash(`#${hash}`);
      expect(state, hash).toEqual(DEFAULT_STATE);
      expect(problems, hash).toEqual([`Link setting "${hash.split('=')[0]}" has an invalid value and was ignored.`]);
    }
    expect(parseHash('#radius=.5&smoothness=16&base=platonic').state).toMatchObject({ radius: 0.5, smoothness: 16, base: 'platonic' });
    expect(parseHash('#radius=0').state.radius).toBe(0);
  });

  it('drops malformed values with a note and keeps the defaults', () => {
    const { state, problems } = parseHash('#mode=atlas&shading=shiny&wireframe=yes&sample=&map=');
    expect(state).toEqual(DEFAULT_STATE);
    expect(problems).toHaveLength(5);
    expect(problems.join(' ')).toMatch(/"mode".*"shading".*"wireframe".*"sample".*"map"/);
  });

  it('refuses sample names that could be markup, paths or anything long', () => {
    for (const sample of ['<img src=x onerror=alert(1)>', '../../etc/passwd', 'a b', 'x'.repeat(65), '.hidden']) {
      const { state, problems } = parseHash(`#sample=${encodeURIComponent(sample)}`);
      expect(state.sample, sample).toBeNull();
      expect(problems, sample).toHaveLength(1);
    }
    expect(parseHash("#sample=R2.4'").state.sample).toBe("R2.4'");
  });

  it('ignores unknown keys and keeps the first of repeated keys', () => {
    const { state, problems } = parseHash('#zoom=3&sample=torus&sample=sphere&__proto__=x&constructor=y');
    expect(state.sample).toBe('torus');
    expect(problems).toEqual([
      'Unknown link setting "zoom" ignored.',
      'Link setting "sample" given twice: the first value is used.',
      'Unknown link setting "__proto__" ignored.',
      'Unknown link setting "constructor" ignored.',
    ]);
    expect(Object.getPrototypeOf(state)).toBe(Object.prototype);
  });

  it('ignores a hash longer than its limit as a whole', () => {
    const { state, problems } = parseHash(`#sample=torus&pad=${'x'.repeat(3000)}`);
    expect(state).toEqual(DEFAULT_STATE);
    expect(problems[0]).toMatch(/longer than 2000 characters/);
  });

  it('survives broken percent-encoding', () => {
    expect(() => parseHash('#sample=%E0%A4%A&shading=%')).not.toThrow();
    expect(parseHash('#sample=%E0%A4%A').state.sample).toBeNull();
  });

  it('takes map names of the form Rg.n, with a prime for the dual, and nothing else', () => {
    for (const map of ['R2.4', "R2.4'", 'R101.56', 'R3.1']) {
      expect(parseHash(`#map=${encodeURIComponent(map)}`)).toEqual({ state: { ...DEFAULT_STATE, map }, problems: [] });
    }
    const refused = ['r3.1', 'R3', 'R3.', 'R.1', "R3.1''", 'R3.1 ', 'R-3.1', 'R3.1x', '<script>', 'R12345.1', 'R3.123456'];
    for (const map of refused) {
      const { state, problems } = parseHash(`#map=${encodeURIComponent(map)}`);
      expect(state.map, map).toBeNull();
      expect(problems, map).toEqual(['Link setting "map" has an invalid value and was ignored.']);
    }
  });
});

describe('formatHash', () => {
  it('writes the mode and only what differs from the defaults', () => {
    expect(formatHash(DEFAULT_STATE)).toBe('#mode=quad');
    expect(formatHash({ ...DEFAULT_STATE, sample: 'torus', wireframe: true })).toBe('#mode=quad&sample=torus&wireframe=1');
    expect(formatHash({ ...DEFAULT_STATE, mode: 'regmap', map: "R2.4'" })).toBe('#mode=regmap&map=R2.4%27');
  });

  it('round-trips through parseHash', () => {
    const state = {
      ...DEFAULT_STATE,
      mode: 'regmap',
      sample: "R3.1'",
      shading: 'smooth',
      wireframe: true,
      map: "R3.1'",
      view: 'surface',
      base: 'platonic',
      radius: 0.125,
      smoothness: 2,
      field: true,
      align: 'curvature',
      sharp: 90,
      h: 0.0025,
      texture: 'checker',
    };
    expect(parseHash(formatHash(state))).toEqual({ state, problems: [] });
  });

  it('writes the view and the surface options only when they differ from the defaults', () => {
    const regmap = { ...DEFAULT_STATE, mode: 'regmap', map: 'R2.4' };
    expect(formatHash({ ...regmap, view: 'surface' })).toBe('#mode=regmap&map=R2.4&view=surface');
    expect(formatHash({ ...regmap, view: 'surface', radius: 0.2, smoothness: 4 })).toBe('#mode=regmap&map=R2.4&view=surface&radius=0.2');
  });

  it('keeps the drawn-map view and the surface it is drawn on, and drops malformed target names', () => {
    const { state, problems } = parseHash("#mode=regmap&map=R3.1&view=map&on=Tetrahedron");
    expect(problems).toEqual([]);
    expect([state.view, state.on]).toEqual(['map', 'Tetrahedron']);
    for (const on of ["R2.1'", '{2,4}', '{4,4}_(1,1)']) expect(parseHash(`#on=${encodeURIComponent(on)}`).state.on).toBe(on);
    for (const on of ['<img>', 'tetrahedron', '{4,4}_(1,', 'R2', 'x'.repeat(40)]) {
      const parsed = parseHash(`#on=${encodeURIComponent(on)}`);
      expect(parsed.state.on).toBeNull();
      expect(parsed.problems).toHaveLength(1);
    }
    const regmap = { ...DEFAULT_STATE, mode: 'regmap', map: 'R3.1' };
    // The drawn map is the mode's default view: a link names the others.
    expect(DEFAULT_STATE.view).toBe('map');
    expect(formatHash({ ...regmap, on: 'Tetrahedron' })).toBe('#mode=regmap&map=R3.1&on=Tetrahedron');
    expect(formatHash(regmap)).toBe('#mode=regmap&map=R3.1');
    expect(formatHash({ ...regmap, view: 'tiling' })).toBe('#mode=regmap&map=R3.1&view=tiling');
  });

  it('writes Field options only when they differ from the defaults', () => {
    expect(formatHash({ ...DEFAULT_STATE, sample: 'torus', field: true })).toBe('#mode=quad&sample=torus&field=1');
    expect(formatHash({ ...DEFAULT_STATE, field: true, h: 0.05, sharp: 180 })).toBe('#mode=quad&field=1&sharp=180&h=0.05');
  });
});
