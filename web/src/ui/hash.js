// The page state that a link can share, kept in the URL hash as `#key=value&key=value`.
// The hash comes from anywhere (a pasted link): it is parsed defensively, and every key that is
// unknown, repeated or malformed is dropped with a note instead of reaching the page.

import { MODES } from './modes.js';
import { FIELD_DEFAULTS, FIELD_PARSERS } from './field-options.js';
import { SURFACE_DEFAULTS, SURFACE_PARSERS } from './surface-options.js';
import { BASE_KINDS, SORT_KEYS } from './gallery-data.js';

const MAX_HASH_LENGTH = 2000;

const oneOf = (values) => (text) => (values.includes(text) ? text : undefined);
const name = (text) => (/^[A-Za-z0-9][A-Za-z0-9_.'-]{0,63}$/.test(text) ? text : undefined);
const flag = (text) => ({ 1: true, 0: false })[text];
// A catalog name (Rg.n, a prime for the dual); whether the catalog holds it is the mode's question.
const mapName = (text) => (/^R\d{1,4}\.\d{1,5}'?$/.test(text) ? text : undefined);
// A target map's name: a catalog name, a Platonic solid, a hosohedron {2,n} or a torus map
// {4,4}_(b,c); whether there is such a target is the core's question.
const targetName = (text) =>
  /^(R\d{1,4}\.\d{1,5}'?|[A-Z][a-z]{2,15}|\{\d{1,3},\d{1,3}\}(_\(\d{1,3},\d{1,3}\))?)$/.test(text) ? text : undefined;

/** Each shareable key, with its parser (text -> value, or undefined when malformed). */
const FIELDS = Object.freeze({
  mode: oneOf(MODES.map(({ id }) => id)),
  sample: name,
  shading: oneOf(['flat', 'smooth']),
  wireframe: flag,
  map: mapName,
  // The Regular maps mode's view (the map drawn on a surface, the default; its 2D tiling; or its own
  // regular surface, built on opening), the surface a map is drawn on (none: the best), the surface
  // options.
  view: oneOf(['tiling', 'map', 'surface']),
  on: targetName,
  // The drawn map's colours: each face its own, faces by orbit of the surface's rotations, or the
  // bare surface by quarter tube.
  colors: oneOf(['faces', 'orbits', 'tubes']),
  ...SURFACE_PARSERS,
  // The Field view: shown (computed on opening the link), its options, the texture on the surface.
  field: flag,
  ...FIELD_PARSERS,
  texture: oneOf(['off', 'checker', 'grid']),
  // The Gallery's filters: a name fragment, a genus or genus range, p, q, realized maps only, the
  // kind of surface base, the order (genus when absent).
  find: (text) => (/^[A-Za-z0-9.']{1,16}$/.test(text) ? text : undefined),
  genus: (text) => (/^\d{1,4}(-\d{1,4})?$/.test(text) ? text : undefined),
  p: (text) => (/^\d{1,4}$/.test(text) ? text : undefined),
  q: (text) => (/^\d{1,4}$/.test(text) ? text : undefined),
  realized: flag,
  kind: oneOf(BASE_KINDS),
  sort: oneOf(SORT_KEYS.filter((key) => key !== 'genus')),
  // The 3D view's camera: its position and target, six numbers to 1e-4 (cameraText); and whether
  // it turns by itself.
  cam: (text) => (CAMERA.test(text) ? text : undefined),
  spin: flag,
});

const NUMBER = '-?\\d{1,5}(?:\\.\\d{1,4})?';
const CAMERA = new RegExp(`^${NUMBER}(?:_${NUMBER}){5}$`);

/** A camera ({ position: [x, y, z], target: [x, y, z] }) as the link keeps it, and back. */
export const cameraText = ({ position, target }) => [...position, ...target].join('_');
export function cameraOf(text) {
  if (typeof text !== 'string' || !CAMERA.test(text)) return null;
  const v = text.split('_').map(Number);
  return { position: v.slice(0, 3), target: v.slice(3) };
}

export const DEFAULT_STATE = Object.freeze({
  mode: 'quad',
  sample: null,
  shading: 'flat',
  wireframe: false,
  map: null,
  view: 'map',
  on: null,
  colors: 'faces',
  ...SURFACE_DEFAULTS,
  field: false,
  ...FIELD_DEFAULTS,
  texture: 'off',
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

/**
 * Parses a location.hash string.
 * Returns { state, problems }: state holds every key of DEFAULT_STATE (defaults where the hash has
 * no valid value); problems lists, in plain words, what was ignored.
 */
export function parseHash(hash) {
  const state = { ...DEFAULT_STATE };
  const problems = [];
  const text = String(hash ?? '').replace(/^#/, '');
  if (text.length > MAX_HASH_LENGTH) {
    return { state, problems: [`The link's state is longer than ${MAX_HASH_LENGTH} characters and was ignored.`] };
  }
  const seen = new Set();
  for (const [key, raw] of new URLSearchParams(text)) {
    const parse = Object.hasOwn(FIELDS, key) ? FIELDS[key] : null;
    if (!parse) {
      problems.push(`Unknown link setting "${key}" ignored.`);
    } else if (seen.has(key)) {
      problems.push(`Link setting "${key}" given twice: the first value is used.`);
    } else {
      seen.add(key);
      const value = parse(raw);
      if (value === undefined) problems.push(`Link setting "${key}" has an invalid value and was ignored.`);
      else state[key] = value;
    }
  }
  return { state, problems };
}

/** The hash for a state: mode always, other keys only where they differ from the defaults. */
export function formatHash(state) {
  const params = new URLSearchParams();
  for (const key of Object.keys(FIELDS)) {
    const value = state[key];
    if (value === undefined || value === null) continue;
    if (key !== 'mode' && value === DEFAULT_STATE[key]) continue;
    params.set(key, typeof value === 'boolean' ? (value ? '1' : '0') : value);
  }
  return `#${params}`;
}
