// The options of a regular surface as the page takes them, from its form or from a link: every
// value is checked here before it reaches the core.

export const SURFACE_DEFAULTS = Object.freeze({ base: 'auto', radius: 0, smoothness: 4 });
// The tube radius in tube lengths (junction to edge midpoint), 0 for the core's automatic radius;
// beyond half a length the tubes swallow their junctions.
export const RADIUS_LIMITS = Object.freeze({ min: 0, max: 0.5 });
// Quads across a quarter tube: the mesh grows with its square, 16 gives 16 times the default faces.
export const SMOOTHNESS_LIMITS = Object.freeze({ min: 2, max: 16 });
const BASES = ['auto', 'platonic', 'relax'];

const inRange = (value, { min, max }) => (value >= min && value <= max ? value : undefined);

/** Each option's parser: text -> value, or undefined when the text is not a valid value. */
export const SURFACE_PARSERS = Object.freeze({
  base: (text) => (BASES.includes(text) ? text : undefined),
  radius: (text) => (/^(\d+\.?\d*|\.\d+)$/.test(text) ? inRange(Number(text), RADIUS_LIMITS) : undefined),
  smoothness: (text) => (/^\d{1,2}$/.test(text) ? inRange(Number(text), SMOOTHNESS_LIMITS) : undefined),
});

const PROBLEMS = Object.freeze({
  base: 'The base must be "auto", "platonic" or "relax".',
  radius: `The tube radius must be a number from ${RADIUS_LIMITS.min} (automatic) to ${RADIUS_LIMITS.max} tube lengths.`,
  smoothness: `The smoothness must be a whole number of quads from ${SMOOTHNESS_LIMITS.min} to ${SMOOTHNESS_LIMITS.max}.`,
});

/**
 * The options from the texts of a form { base, radius, smoothness } (surrounding blanks ignored).
 * Returns { options, problems }: options holds the valid values, problems a message per invalid key.
 */
export function readSurfaceOptions(texts) {
  const options = {};
  const problems = {};
  for (const [key, parse] of Object.entries(SURFACE_PARSERS)) {
    const value = parse(String(texts[key] ?? '').trim());
    if (value === undefined) problems[key] = PROBLEMS[key];
    else options[key] = value;
  }
  return { options, problems };
}

/** The options as the worker's regmapSurface command takes them. */
export const coreOptions = ({ base, radius, smoothness }) => ({ base, tubeRadius: radius, smoothness });
