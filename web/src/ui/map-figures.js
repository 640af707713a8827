// The figures of a regular map (the core's info and the shape of its fundamental polygon), as the
// panel lists them.
import { count } from './info-panel.js';

/** "16 ms", "0.09 ms", "2.35 s": an enumeration time in seconds, readable. */
export function formatSeconds(seconds) {
  const s = Number(seconds);
  if (!(s >= 0)) return '–';
  if (s >= 1) return `${s.toFixed(2)} s`;
  const ms = 1000 * s;
  return ms >= 1 ? `${Math.round(ms)} ms` : `${ms.toFixed(2)} ms`;
}

/** [key, label, format] of each figure (see fillFigures). */
export const MAP_FIGURES = Object.freeze([
  ['type', 'Type {p,q}', String],
  ['order', 'Group order |G|', count],
  ['vertices', 'Vertices', count],
  ['edges', 'Edges', count],
  ['faces', 'Faces', count],
  ['genus', 'Genus', String],
  ['euler', 'Euler characteristic', String],
  ['petrie', 'Petrie length', count],
  ['seconds', 'Enumeration time', formatSeconds],
  ['triangles', 'Triangles of the polygon', count],
  ['boundaryPairs', 'Boundary edge pairs', count],
]);

/** The values of MAP_FIGURES from a tiling result { info, polygon }. */
export function mapFigureValues({ info, polygon }) {
  return { ...info, type: `{${info.p},${info.q}}`, triangles: polygon.triangles, boundaryPairs: polygon.boundaryPairs };
}
