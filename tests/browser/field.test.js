// The Field view of the Quad layout mode: a cross field and its seamless parameterization computed
// in the worker, drawn on the mesh, checked in the panel, shared by link, cancelled.
import assert from 'node:assert/strict';
import { RESULTS, test } from './harness.js';
import { changedShare, chooseSample, figure, idle, message, openPage, pickFiles, pixelShares, torusObj } from './helpers.js';

// Singularity markers by their colours (web/src/viewer/palette.js: valence 3 red, 5 blue); the
// beige surface and the dark background have neither.
const MARKERS = {
  red: '(r, g, b) => r - g > 90 && r - b > 90',
  blue: '(r, g, b) => b - r > 80 && b - g > 30',
};
// The dark squares of the checkerboard (web/src/viewer/textures.js), lit.
const CHECKER = { dark: '(r, g, b) => r < 140 && r > g && g > b && r - b > 25' };

const canvas = (page) => page.locator('#viewport canvas');
const fieldFigure = (page, key) => page.locator(`[data-role=field-figures] [data-figure=${key}]`).textContent();
const hash = (page) => page.evaluate(() => location.hash);
const compute = (page) => page.getByRole('button', { name: 'Compute field and parameterization' }).click();

/** Waits until the parameterization's figures are in the panel and no job runs. */
async function parameterized(page) {
  await page.locator('[data-role=field-figures] [data-figure=max_seam_error]').filter({ hasText: /\d/ }).waitFor();
  await idle(page);
}

/** The legend as [[valence, count]]. */
async function legend(page) {
  const items = await page.locator('[data-role=legend] li[data-valence]').allTextContents();
  return items.map((text) => text.match(/valence (\d+): (\d+)/).slice(1).map(Number));
}

test('Field: genus 2 shows crosses, singularities by valence, Poincaré–Hopf, a checkerboard; another mesh clears it', async ({ page, url }) => {
  await openPage(page, url);
  const plain = await canvas(page).screenshot();
  assert.deepEqual(await pixelShares(page, MARKERS), { red: 0, blue: 0 }, 'the plain mesh has marker colours');

  await compute(page);
  await parameterized(page);
  await page.screenshot({ path: `${RESULTS}/field-genus2.png` });
  assert.equal(await fieldFigure(page, 'euler_characteristic'), '-2');
  assert.equal(await fieldFigure(page, 'index_sum'), '-2');
  assert.equal(await fieldFigure(page, 'poincare_hopf'), '-2 = -2 ✓');
  assert.equal(await fieldFigure(page, 'flipped_outside_singular_rings'), '0');
  assert.ok(Number(await fieldFigure(page, 'max_seam_error')) < 1e-8);
  const byValence = await legend(page);
  assert.deepEqual(byValence.map(([valence]) => valence), [3, 5], 'a smooth genus-2 field has valences 3 and 5');
  const [[, threes], [, fives]] = byValence;
  assert.equal(threes - fives, 4 * -2, 'valence 3 counts +1/4, valence 5 -1/4: together chi');
  assert.equal(Number(await fieldFigure(page, 'singularities')), threes + fives);
  assert.match(await hash(page), /field=1/);

  const shares = await pixelShares(page, MARKERS);
  assert.ok(shares.red > 0.0005 && shares.blue > 0.0005, `markers drawn: ${JSON.stringify(shares)}`);
  const field = await canvas(page).screenshot();
  assert.ok((await changedShare(page, plain, field)) > 0.01, 'the field view looks like the plain mesh');
  await page.getByLabel('Show the crosses').uncheck();
  const uncrossed = await canvas(page).screenshot();
  const crosses = await changedShare(page, uncrossed, field);
  assert.ok(crosses > 0.005, `the crosses cover ${(crosses * 100).toFixed(2)} % of the view`);
  await page.getByLabel('Show the crosses').check();

  const { dark: plainDark } = await pixelShares(page, CHECKER);
  await page.getByLabel('Texture').selectOption('checker');
  const { dark } = await pixelShares(page, CHECKER);
  assert.ok(dark > 0.03 && dark > 10 * plainDark, `dark checker squares: ${dark} (before: ${plainDark})`);
  await page.screenshot({ path: `${RESULTS}/field-genus2-checker.png` });
  assert.match(await hash(page), /texture=checker/);
  await page.getByLabel('Texture').selectOption('grid');
  assert.ok((await changedShare(page, field, await canvas(page).screenshot())) > 0.01, 'the grid changed nothing');

  await chooseSample(page, 'sphere');
  assert.ok(await page.locator('[data-role=field-result]').isHidden(), 'the old field is still listed');
  assert.deepEqual(await pixelShares(page, MARKERS), { red: 0, blue: 0 }, 'the old markers are still drawn');
  assert.doesNotMatch(await hash(page), /field=1/);
});

test('Field: a link computes the field; the torus refusal, curvature alignment and bad options are clear', async ({ page, url }) => {
  await page.goto(`${url}#sample=torus&field=1`);
  const alert = page.getByRole('alert');
  await alert.waitFor();
  assert.match(await alert.textContent(), /no seamless parameterization exists.*curvature/s);
  assert.equal(await fieldFigure(page, 'singularities'), '0', "a torus's smoothest field");
  assert.equal(await fieldFigure(page, 'poincare_hopf'), '0 = 0 ✓');
  assert.equal(await page.locator('[data-role=legend]').textContent(), 'No singularities');
  assert.ok(await page.getByLabel('Texture').isDisabled(), 'a texture is offered without a parameterization');

  await page.getByLabel('Align').selectOption('curvature');
  await compute(page);
  await parameterized(page);
  assert.ok(await message(page).isHidden());
  assert.match(await hash(page), /field=1&align=curvature/);
  const unit = await fieldFigure(page, 'h');
  const diagonal = Number(await figure(page, 'bbox_diagonal'));
  assert.ok(Math.abs(Number(unit) - 0.01 * diagonal) < 0.01 * diagonal * 0.01, `unit ${unit}, diagonal ${diagonal}`);

  for (const [label, value, problem] of [['h', 'abc', /h must be a number/], ['h', '2', /from 0.0001 to 1/]]) {
    await page.getByLabel(label, { exact: true }).fill(value);
    await compute(page);
    await alert.waitFor();
    assert.match(await alert.textContent(), problem);
    assert.equal(await page.getByLabel(label, { exact: true }).getAttribute('aria-invalid'), 'true');
    assert.equal(await fieldFigure(page, 'h'), unit, 'a refused option changed the view');
  }
  await page.getByLabel('h', { exact: true }).fill('0.05');
  await compute(page);
  await page.locator('[data-role=field-figures] [data-figure=h]').filter({ hasText: (0.05 * diagonal).toPrecision(3) }).waitFor();
  await idle(page);
  assert.ok(await message(page).isHidden());
  assert.match(await hash(page), /h=0.05/);
  await page.screenshot({ path: `${RESULTS}/field-torus-curvature.png` });

  await page.goto(`${url}#sample=sphere&field=1&sharp=0&h=5`);
  await page.getByRole('status').filter({ hasText: 'Parts of the link were ignored.' }).waitFor();
  const notice = await page.getByRole('status').filter({ hasText: 'Parts of the link were ignored.' }).textContent();
  assert.match(notice, /"sharp"/);
  assert.match(notice, /"h"/);
  await parameterized(page);
  assert.equal(await fieldFigure(page, 'poincare_hopf'), '2 = 2 ✓');
  assert.equal(await page.getByLabel('h', { exact: true }).inputValue(), '0.01');
});

test('Field: Cancel stops the computation; the next one builds the mesh again in a fresh worker', async ({ page, url }) => {
  await openPage(page, url);
  await pickFiles(page, [{ name: 'torus-64k.obj', text: torusObj(320, 100) }]);
  await page.locator('[data-role=mesh-name]').filter({ hasText: 'torus-64k' }).waitFor();
  await idle(page);
  await page.getByLabel('Align').selectOption('curvature');
  await compute(page);
  await page.locator('[data-role=stage]').filter({ hasText: 'cross field' }).waitFor();
  await page.getByRole('button', { name: 'Cancel' }).click();
  await page.getByRole('status').filter({ hasText: 'Cancelled.' }).waitFor();
  assert.ok(await page.locator('[data-role=progress]').isHidden());
  assert.ok(await page.locator('[data-role=field-result]').isHidden(), 'a cancelled field is shown');
  assert.match(await page.locator('[data-role=mesh-name]').textContent(), /torus-64k/, 'the mesh on screen was lost');

  const stages = [];
  await page.exposeFunction('reportStage', (text) => stages.push(text));
  await page.evaluate(() => {
    const stage = document.querySelector('#status [data-role=stage]');
    new MutationObserver(() => window.reportStage(stage.textContent)).observe(stage, { childList: true, characterData: true, subtree: true });
  });
  await compute(page);
  await parameterized(page);
  assert.ok(stages.some((text) => /again in a fresh core/.test(text)), `stages: ${[...new Set(stages)].join(' | ')}`);
  assert.ok(stages.some((text) => /Poisson/.test(text)), `stages: ${[...new Set(stages)].join(' | ')}`);
  assert.equal(await fieldFigure(page, 'poincare_hopf'), '0 = 0 ✓');
  assert.equal(await fieldFigure(page, 'flipped_triangles'), '0');
});
