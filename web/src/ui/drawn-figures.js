// The figures of a map drawn on a target's surface (the core's drawn_map_json), as the panel lists
// them: what was found on the built mesh next to what the map has.
import { count } from './info-panel.js';
import { formatSeconds } from './map-figures.js';

const yesNo = (value) => (value ? 'yes' : 'no');

/** [key, label, format] of each figure (see fillFigures). */
export const DRAWN_FIGURES = Object.freeze([
  ['target', 'Surface of', String],
  ['pairing', 'Paired by', String],
  ['genus', 'Genus', String],
  ['V', 'Vertices found', String],
  ['E', 'Edges found', String],
  ['F', 'Faces found', String],
  ['face_orbits', "Face orbits under the surface's rotations", count],
  ['faces_are_disks', 'Every face a disk', yesNo],
  ['covers_once', 'Flags covered once', yesNo],
  ['closed', 'Closed', yesNo],
  ['oriented', 'Oriented', yesNo],
  ['mesh_faces', 'Triangles', count],
  ['seconds', 'Drawn in', formatSeconds],
]);

/** The values of DRAWN_FIGURES from the core's figures: each count beside the map's own. */
export function drawnFigureValues(drawn) {
  const found = (key) => `${count(drawn[key])}${drawn[key] === drawn.expected[key] ? ' =' : ', not'} ${count(drawn.expected[key])}`;
  return {
    ...drawn,
    target: `${drawn.target} (${drawn.target_kind})`,
    pairing: drawn.pairing.kind,
    V: found('V'),
    E: found('E'),
    F: found('F'),
  };
}

const polygon = (p) => ({ 1: 'one-sided', 2: 'two-sided', 3: 'triangular', 4: 'square', 5: 'pentagonal', 6: 'hexagonal' })[p] ?? `${p}-sided`;
const plural = (n, one, many) => `${count(n)} ${n === 1 ? one : many}`;

/**
 * What the drawn view shows, in words, from the map's name and the core's figures of the drawing
 * (drawn: target, target_kind, genus, pairing, expected { V, E, F }) and the map's type (p, q):
 * what p, q and the genus mean, and what is drawn. Plain text (the page shows it as text).
 */
export function drawnDescription(name, { p, q }, drawn) {
  const { V, E, F } = drawn.expected;
  const genus = drawn.genus;
  const handles = genus === 1 ? 'a torus' : `a sphere with ${count(genus)} handles`;
  const paired = drawn.pairing.kind === 'reflections' ? "its mirror symmetries" : 'its rotations';
  return [
    `${name} is a regular map of type {${p},${q}}: ${plural(F, `${polygon(p)} face`, `${polygon(p)} faces`)} (p = ${p} sides each), ` +
      `${q} of them around each of its ${plural(V, 'vertex', 'vertices')} (q = ${q}), joined by ${plural(E, 'edge', 'edges')}, ` +
      `on a closed surface of genus ${count(genus)} (${handles}). Regular: a symmetry of the map takes any face, any edge of it and either ` +
      `end of that edge to any other.`,
    `Here it is drawn on the regular surface of ${drawn.target} (that map's edges as tubes, its vertices as junctions), which has the same ` +
      `genus and whose symmetries are ${paired} of ${name}: each of the ${count(F)} faces is a region of one colour, the ${count(E)} edges are ` +
      'the dark curves, and the surface\'s symmetries move the drawing onto itself.',
  ];
}
