// The page's colours that are not the 3D view's look (look.js): singularities by valence (the number
// of isolines that leave them), shared by the 3D markers and the legend; quarter tubes and patches;
// a drawn map's edges.

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

// The core's colour of a quarter tube (quarter_tube_color in core/regmap/surface_export.cpp), so
// that the page shows the colours the exported GLB carries: hues spread by the golden angle over
// the tile numbers, pastel (no channel below LOW).
const GOLDEN_TURN = 0.6180339887498949;
const LOW = 0.25;
const SEXTANTS = [
  (x) => [1, x, 0],
  (x) => [x, 1, 0],
  (x) => [0, 1, x],
  (x) => [0, x, 1],
  (x) => [x, 0, 1],
  (x) => [1, 0, x],
];

/** [r, g, b] in 0..1 (linear, as glTF colours are) for a quarter tube's number. */
export function quarterTubeColor(tile) {
  const hue = ((0.13 + GOLDEN_TURN * tile) % 1) * 6;
  const x = 1 - Math.abs((hue % 2) - 1);
  return SEXTANTS[Math.floor(hue) % 6](x).map((channel) => LOW + (1 - LOW) * channel);
}

// The colour of a drawn map's edges over its faces: dark, thin.
export const MAP_EDGE_COLOR = 0x1d1d1f;
