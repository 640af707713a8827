// Colours of singularities by valence (the number of isolines that leave them), shared by the 3D
// markers and the page's legend.

const BY_VALENCE = new Map([
  [1, '#b05cff'],
  [2, '#ff7ad9'],
  [3, '#e5483b'],
  [4, '#5fd0e0'],
  [5, '#3b82e5'],
  [6, '#2fb36b'],
  [7, '#f2b01e'],
]);
const OTHER = '#f4f4f4';

/** '#rrggbb' for a valence (4 and 0 occur on boundaries only); valences above 7 share one colour. */
export function valenceColor(valence) {
  return BY_VALENCE.get(valence) ?? OTHER;
}
