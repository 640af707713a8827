// The options of the cross field and of the seamless parameterization as the page takes them, from
// its form or from a link: every value is checked here before it reaches the core.

export const FIELD_DEFAULTS = Object.freeze({ align: 'smooth', sharp: 35, h: 0.01 });
export const SHARP_LIMITS = Object.freeze({ min: 1, max: 180 }); // degrees; 180: no sharp edges
// Below this h the texture coordinates (float32 in the view) lose the precision the texture needs.
export const H_LIMITS = Object.freeze({ min: 0.0001, max: 1 });

const inRange = (value, { min, max }) => (value >= min && value <= max ? value : undefined);

/** Each option's parser: text -> value, or undefined when the text is not a valid value. */
export const FIELD_PARSERS = Object.freeze({
  align: (text) => (text === 'smooth' || text === 'curvature' ? text : undefined),
  sharp: (text) => (/^\d{1,3}$/.test(text) ? inRange(Number(text), SHARP_LIMITS) : undefined),
  h: (text) => (/^(\d+\.?\d*|\.\d+)(e-?\d{1,2})?$/i.test(text) ? inRange(Number(text), H_LIMITS) : undefined),
});

const PROBLEMS = Object.freeze({
  align: 'Align must be "smooth" or "curvature".',
  sharp: `The sharp-edge angle must be a whole number of degrees from ${SHARP_LIMITS.min} to ${SHARP_LIMITS.max} (${SHARP_LIMITS.max}: no sharp edges).`,
  h: `h must be a number from ${H_LIMITS.min} to ${H_LIMITS.max}: one parameter unit as a share of the bounding-box diagonal.`,
});

/**
 * The options from the texts of a form { align, sharp, h } (surrounding blanks ignored).
 * Returns { options, problems }: options holds the valid values, problems a message per invalid key.
 */
export function readFieldOptions(texts) {
  const options = {};
  const problems = {};
  for (const [key, parse] of Object.entries(FIELD_PARSERS)) {
    const value = parse(String(texts[key] ?? '').trim());
    if (value === undefined) problems[key] = PROBLEMS[key];
    else options[key] = value;
  }
  return { options, problems };
}

/** Whether two sets of options give the same cross field (h only scales the parameterization). */
export const sameField = (a, b) => a.align === b.align && a.sharp === b.sharp;
