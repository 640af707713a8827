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
