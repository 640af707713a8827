// Figures (of a mesh, of a map) as a definition list, written as text only: every string here may
// come from a user's file or a typed presentation.

export const count = (n) => Number(n).toLocaleString('en-US');
const yesNo = (value) => (value ? 'yes' : 'no');

const FIGURES = [
  ['vertices', 'Vertices', count],
  ['faces', 'Faces', count],
  ['edges', 'Edges', count],
  ['face_sizes', 'Face sizes', faceSizes],
  ['components', 'Components', count],
  ['boundary_loops', 'Boundary loops', count],
  ['genus', 'Genus', String],
  ['euler_characteristic', 'Euler characteristic', String],
  ['manifold', 'Manifold', yesNo],
  ['oriented', 'Oriented', yesNo],
  ['bbox_diagonal', 'Bounding box diagonal', (d) => Number(d).toPrecision(4)],
];

/** "27,954 triangles\n12 quads\n1 6-gon" from { "3": 27954, "4": 12, "6": 1 }. */
export function faceSizes(sizes) {
  const names = { 3: ['triangle', 'triangles'], 4: ['quad', 'quads'] };
  return Object.entries(sizes ?? {})
    .sort(([a], [b]) => Number(a) - Number(b))
    .map(([size, n]) => {
      const [one, many] = names[size] ?? [`${size}-gon`, `${size}-gons`];
      return `${count(n)} ${Number(n) === 1 ? one : many}`;
    })
    .join('\n');
}

/**
 * Writes figures into a definition list, as text. figures: [key, label, format]; values: an object
 * with the keys (a missing key shows a dash).
 */
export function fillFigures(list, figures, values) {
  list.replaceChildren(
    ...figures.flatMap(([key, label, format]) => {
      const term = document.createElement('dt');
      term.textContent = label;
      const value = document.createElement('dd');
      value.dataset.figure = key;
      value.textContent = key in values ? format(values[key]) : '–';
      return [term, value];
    }),
  );
}

/** Fills `panel` (the info section) with the mesh's name, figures and warnings. */
export function showInfo(panel, { name, info }) {
  panel.querySelector('[data-role=mesh-name]').textContent = name;
  fillFigures(panel.querySelector('[data-role=figures]'), FIGURES, info);
  const warnings = panel.querySelector('[data-role=warnings]');
  warnings.replaceChildren(
    ...(info.warnings ?? []).map((text) => {
      const item = document.createElement('li');
      item.textContent = text;
      return item;
    }),
  );
  warnings.hidden = warnings.childElementCount === 0;
}
