// The figures of a cross field and its seamless parameterization, as the Field panel lists them.
import { count } from './info-panel.js';
import { formatSeconds } from './map-figures.js';

// The parameterization's steps in the order they run; the core lists its times by name.
const PARAM_STEPS = ['cut graph', 'assembly', 'solve', 'injectivity'];

/** [[valence, number of singularities]] by increasing valence. */
export function valenceCounts(valences) {
  const counts = new Map();
  for (const valence of valences) counts.set(valence, (counts.get(valence) ?? 0) + 1);
  return [...counts].sort(([a], [b]) => a - b);
}

/** An index or a sum of indices (multiples of 1/4) as people write it: "-2", "0.25", "1.75". */
export const formatIndex = (value) => String(Number(Number(value).toFixed(4)));

/** The Poincare-Hopf check: the sum of the indices against the Euler characteristic. */
export function poincareHopf(indexSum, euler) {
  const holds = Math.abs(indexSum - euler) < 1e-9;
  return `${formatIndex(indexSum)} ${holds ? '=' : '≠'} ${euler} ${holds ? '✓' : '✗ (violated)'}`;
}

/**
 * The figures of a field result { info, seconds } and, once there, a parameterization result
 * { info } (null before). Returns { figures: [[key, label, format]], values } for fillFigures.
 */
export function fieldFigures(field, param) {
  const { info } = field;
  const figures = [
    ['singularities', 'Singularities', count],
    ['index_sum', 'Index sum', formatIndex],
    ['euler_characteristic', 'Euler characteristic', String],
    ['poincare_hopf', 'Poincaré–Hopf (sum = χ)', String],
    ['flipped_before_injectivity', 'Flips before injectivity', count],
    ['flipped_triangles', 'Flips after injectivity', count],
    ['flipped_outside_singular_rings', '… outside singular rings', count],
    ['max_seam_error', 'Largest seam mismatch', (e) => Number(e).toExponential(1)],
    ['h', 'Parameter unit length', (h) => Number(h).toPrecision(3)],
    ['energy', 'Poisson energy', (e) => Number(e).toPrecision(4)],
  ];
  const values = {
    singularities: info.singularities.length,
    index_sum: info.index_sum,
    euler_characteristic: info.euler_characteristic,
    poincare_hopf: poincareHopf(info.index_sum, info.euler_characteristic),
  };
  const times = [['cross field', field.seconds]];
  if (param) {
    for (const key of ['flipped_before_injectivity', 'flipped_triangles', 'flipped_outside_singular_rings', 'max_seam_error', 'h', 'energy']) {
      values[key] = param.info[key];
    }
    times.push(...stepTimes(param.info.seconds));
  }
  times.push(['total', times.reduce((sum, [, seconds]) => sum + seconds, 0)]);
  for (const [step, seconds] of times) {
    const key = `time_${step.replace(/\W+/g, '_')}`;
    figures.push([key, `Time: ${step}`, formatSeconds]);
    values[key] = seconds;
  }
  return { figures, values };
}

// [[step, seconds]] in the order the steps run, steps the page does not know last.
function stepTimes(seconds) {
  const rank = (step) => (PARAM_STEPS.includes(step) ? PARAM_STEPS.indexOf(step) : PARAM_STEPS.length);
  return Object.entries(seconds ?? {}).sort(([a], [b]) => rank(a) - rank(b));
}
