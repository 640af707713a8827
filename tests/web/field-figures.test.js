import { describe, expect, it } from 'vitest';
import { fieldFigures, formatIndex, poincareHopf, valenceCounts } from '../../web/src/ui/field-figures.js';
import { FIELD_DEFAULTS, readFieldOptions, sameField } from '../../web/src/ui/field-options.js';
import { valenceColor } from '../../web/src/viewer/palette.js';

const field = {
  info: {
    euler_characteristic: -2,
    index_sum: -2,
    singularities: [
      { vertex: 4, index: 0.25, valence: 3 },
      { vertex: 9, index: -0.25, valence: 5 },
      { vertex: 1, index: -0.5, valence: 6 },
      { vertex: 7, index: -0.25, valence: 5 },
      { vertex: 8, index: -0.25, valence: 5 },
      { vertex: 2, index: -0.25, valence: 5 },
      { vertex: 3, index: -0.25, valence: 5 },
      { vertex: 5, index: -0.5, valence: 6 },
    ],
  },
  seconds: 0.25,
};
const param = {
  info: {
    flipped_before_injectivity: 4,
    flipped_triangles: 1,
    flipped_outside_singular_rings: 0,
    max_seam_error: 3.7e-16,
    h: 0.0678,
    energy: 0.0555,
    seconds: { solve: 0.5, injectivity: 2, 'cut graph': 0.001, assembly: 0.25 },
  },
};
const row = ({ figures, values }, key) => {
  const [, label, format] = figures.find(([k]) => k === key);
  return [label, format(values[key])];
};

describe('valenceCounts', () => {
  it('counts the singularities of each valence, by increasing valence', () => {
    expect(valenceCounts(new Int32Array([5, 3, 5, 6, 5]))).toEqual([[3, 1], [5, 3], [6, 1]]);
    expect(valenceCounts([])).toEqual([]);
  });
});

describe('poincareHopf', () => {
  it('shows the check, and a violation plainly', () => {
    expect(poincareHopf(-2, -2)).toBe('-2 = -2 ✓');
    expect(poincareHopf(2, 2)).toBe('2 = 2 ✓');
    expect(poincareHopf(1.75, 2)).toBe('1.75 ≠ 2 ✗ (violated)');
    expect(formatIndex(0.25)).toBe('0.25');
    expect(formatIndex(-1.9999999999)).toBe('-2');
  });
});

describe('fieldFigures', () => {
  it('lists the field, with dashes to come for the parameterization', () => {
    const figures = fieldFigures(field, null);
    expect(row(figures, 'singularities')).toEqual(['Singularities', '8']);
    expect(row(figures, 'poincare_hopf')[1]).toBe('-2 = -2 ✓');
    expect('flipped_triangles' in figures.values).toBe(false);
    expect(figures.figures.map(([key]) => key).filter((key) => key.startsWith('time_'))).toEqual(['time_cross_field', 'time_total']);
    expect(row(figures, 'time_total')[1]).toBe('250 ms');
  });

  it('adds flips, seam error, unit and the time of each step in the order they run', () => {
    const figures = fieldFigures(field, param);
    expect(row(figures, 'flipped_before_injectivity')[1]).toBe('4');
    expect(row(figures, 'flipped_triangles')[1]).toBe('1');
    expect(row(figures, 'flipped_outside_singular_rings')[1]).toBe('0');
    expect(row(figures, 'max_seam_error')[1]).toBe('3.7e-16');
    expect(row(figures, 'h')[1]).toBe('0.0678');
    const times = figures.figures.filter(([key]) => key.startsWith('time_')).map(([key, label, format]) => [label, format(figures.values[key])]);
    expect(times).toEqual([
      ['Time: cross field', '250 ms'],
      ['Time: cut graph', '1 ms'],
      ['Time: assembly', '250 ms'],
      ['Time: solve', '500 ms'],
      ['Time: injectivity', '2.00 s'],
      ['Time: total', '3.00 s'],
    ]);
  });
});

describe('readFieldOptions', () => {
  it('takes valid options from the texts of the form', () => {
    expect(readFieldOptions({ align: 'curvature', sharp: '180', h: ' 0.05 ' })).toEqual({
      options: { align: 'curvature', sharp: 180, h: 0.05 },
      problems: {},
    });
    expect(readFieldOptions({ align: 'smooth', sharp: '1', h: '1e-4' }).options).toEqual({ align: 'smooth', sharp: 1, h: 0.0001 });
    expect(readFieldOptions(Object.fromEntries(Object.entries(FIELD_DEFAULTS).map(([k, v]) => [k, String(v)]))).options).toEqual(FIELD_DEFAULTS);
  });

  it('names each invalid option: out of range, not a number, or not one of the choices', () => {
    const bad = [
      [{ sharp: '0' }, 'sharp'], [{ sharp: '181' }, 'sharp'], [{ sharp: '35.5' }, 'sharp'], [{ sharp: '' }, 'sharp'],
      [{ h: '0' }, 'h'], [{ h: '2' }, 'h'], [{ h: 'abc' }, 'h'], [{ h: '-0.01' }, 'h'], [{ h: '0.00001' }, 'h'],
      [{ h: 'Infinity' }, 'h'], [{ h: '0x10' }, 'h'], [{ align: 'sideways' }, 'align'], [{ align: 'Smooth' }, 'align'],
    ];
    for (const [texts, key] of bad) {
      const { options, problems } = readFieldOptions({ align: 'smooth', sharp: '35', h: '0.01', ...texts });
      expect(Object.keys(problems), JSON.stringify(texts)).toEqual([key]);
      expect(options[key]).toBeUndefined();
    }
    expect(readFieldOptions({ align: 'smooth', sharp: '35', h: '2' }).problems.h).toMatch(/from 0.0001 to 1/);
  });

  it('sees that h alone does not change the field', () => {
    expect(sameField({ align: 'smooth', sharp: 35, h: 0.01 }, { align: 'smooth', sharp: 35, h: 0.1 })).toBe(true);
    expect(sameField({ align: 'smooth', sharp: 35 }, { align: 'smooth', sharp: 36 })).toBe(false);
    expect(sameField({ align: 'smooth', sharp: 35 }, { align: 'curvature', sharp: 35 })).toBe(false);
  });
});

describe('valenceColor', () => {
  it('gives the common valences distinct colours and the rare high ones a shared one', () => {
    const common = [1, 2, 3, 4, 5, 6, 7].map(valenceColor);
    expect(new Set(common).size).toBe(common.length);
    expect(valenceColor(8)).toBe(valenceColor(12));
    expect(common).not.toContain(valenceColor(8));
  });
});
