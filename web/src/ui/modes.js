/**
 * The page's modes, one tab each. A mode joins this list when it exists. scene: the 3D viewer's
 * scene it draws in (viewer.js).
 */
export const MODES = Object.freeze([
  { id: 'quad', label: 'Quad layout', scene: 'mesh' },
  { id: 'regmap', label: 'Regular maps', scene: 'surface' },
  { id: 'gallery', label: 'Gallery', scene: 'surface' },
]);
