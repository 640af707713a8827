// The figures of a regular surface (the core's statistics), as the panel lists them.
import { count } from './info-panel.js';
import { formatSeconds } from './map-figures.js';

const yesNo = (value) => (value ? 'yes' : 'no');

/** [key, label, format] of each figure (see fillFigures). */
export const SURFACE_FIGURES = Object.freeze([
  ['genus', 'Genus', String],
  ['euler_characteristic', 'Euler characteristic', String],
  ['quarter_tubes', 'Quarter tubes', String],
  ['closed', 'Closed', yesNo],
  ['oriented', 'Oriented', yesNo],
  ['relations', 'Relations of A, B, C', String],
  ['self_intersections', 'Self-intersections', String],
  ['base', 'Base', String],
  ['steps', 'Relaxation steps', count],
  ['tube_radius', 'Tube radius', (radius) => Number(radius).toPrecision(3)],
  ['faces', 'Quads', count],
  ['seconds', 'Build time', formatSeconds],
]);

/**
 * The values of SURFACE_FIGURES from the core's statistics of a surface. The genus and the number
 * of quarter tubes are shown with what they should be for an edge graph of V junctions and E tubes:
 * 1 - V + E and 4E.
 */
export function surfaceFigureValues(stats) {
  const { genus, quarter_tubes: quarters, junctions: v, tubes: e } = stats;
  return {
    ...stats,
    genus: expected(genus, 1 - v + e, `1 − ${count(v)} + ${count(e)}`),
    quarter_tubes: expected(quarters, 4 * e, `4 × ${count(e)}`),
    relations: relations(stats.relations_hold, stats.failed_relations ?? []),
    self_intersections: selfIntersections(stats.self_intersections),
    steps: stats.relaxation.iterations,
  };
}

// "5 = 1 − 1 + 5", or "4, not 1 − 1 + 5" when the surface is not what its graph says.
const expected = (value, should, formula) => `${count(value)}${value === should ? ' =' : ', not'} ${formula}`;

// The relations are checked on a closed, oriented surface only.
function relations(hold, failed) {
  if (hold) return 'hold';
  return failed.length > 0 ? `fail: ${failed.join(', ')}` : 'not checked';
}

function selfIntersections(pairs) {
  if (pairs === null || pairs === undefined) return 'not searched';
  if (pairs === 0) return 'none';
  return `${count(pairs)} triangle ${pairs === 1 ? 'pair' : 'pairs'}`;
}
