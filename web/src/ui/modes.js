/** The page's modes, one tab each. A mode joins this list when it exists. */
export const MODES = Object.freeze([
  { id: 'quad', label: 'Quad layout' },
  { id: 'regmap', label: 'Regular maps' },
]);
