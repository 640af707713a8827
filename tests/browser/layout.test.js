// The Layout view of the Quad layout mode: a quad layout computed in the worker, drawn as coloured
// patches with arcs, judged by the project's checker, solved again for a new alpha, exported.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { RESULTS, test } from './harness.js';
import { idle, message, openPage, pixelShares } from './helpers.js';

// Saturated pixels by hue sextant: the patches' colours spread over the hues (golden-ratio steps;
// lit, the palest reach a max - min of 50 to 60), the dark background and the grey arcs are not
// saturated enough to count, and the beige surface (#d9c3a0, 57 unlit) at most one sextant.
const HUES = Object.fromEntries(
  [0, 1, 2, 3, 4, 5].map((k) => [
    `hue${k}`,
    `(r, g, b) => {
      const max = Math.max(r, g, b), min = Math.min(r, g, b);
      if (max - min < 50) return false;
      const d = max - min;
      const h = max === r ? ((g - b) / d + 6) % 6 : max === g ? (b - r) / d + 2 : (r - g) / d + 4;
      return Math.floor(h) === ${k};
    }`,
  ]),
);

const layoutFigure = (page, key) => page.locator(`[data-role=layout-figures] [data-figure=${key}]`).textContent();
const verdict = (page) => page.locator('[data-role=layout-verdict]');

/** The hue sextants that cover at least `share` of the view. */
async function colouredHues(page, share = 0.004) {
  const shares = await pixelShares(page, HUES);
  return Object.entries(shares).filter(([, s]) => s >= share).map(([name]) => name);
}

async function laidOut(page, alpha) {
  await page.locator('[data-role=layout-figures] [data-figure=alpha]').filter({ hasText: new RegExp(`^${alpha}$`) }).waitFor();
  await idle(page);
}

test('Layout: the sphere gets a valid layout of coloured patches; alpha solves again; GLB and PLY download', async ({ page, url }) => {
  await openPage(page, url, '#sample=sphere');
  assert.ok((await colouredHues(page)).length <= 1, 'the plain mesh is already colourful');
  await page.getByRole('button', { name: 'Compute quad layout' }).click();
  await laidOut(page, 5);
  assert.ok(await message(page).isHidden(), 'an error was shown');
  assert.match(await verdict(page).textContent(), /^valid: \d+ patches, all quads$/);
  const patches = Number(await layoutFigure(page, 'patches'));
  assert.ok(patches >= 6, `${patches} patches`);
  const hues = await colouredHues(page);
  assert.ok(hues.length >= 3, `patches in ${hues.length} hue ranges: ${hues}`);
  await page.screenshot({ path: `${RESULTS}/layout-sphere.png` });
  assert.match(await layoutFigure(page, 'solve_seconds'), /\d+(\.\d+)? m?s/);
  assert.ok(await page.locator('[data-role=field-result]').isVisible(), 'the field behind the layout is not listed');

  const stats = await page.locator('[data-role=layout-figures]').textContent();
  await page.locator('[data-role=alpha]').fill('0');
  await laidOut(page, 0);
  assert.notEqual(await page.locator('[data-role=layout-figures]').textContent(), stats, 'the figures did not change');
  assert.match(await verdict(page).textContent(), /^valid: \d+ patches, all quads$/);
  await page.screenshot({ path: `${RESULTS}/layout-sphere-alpha0.png` });

  // Keys move the slider step by step, each a change: the re-solves queue, the last alpha wins, and
  // the worker keeps its graph (no cancel, no rebuild in a fresh core).
  const stages = [];
  await page.exposeFunction('reportStage', (text) => stages.push(text));
  await page.evaluate(() => {
    const stage = document.querySelector('#status [data-role=stage]');
    new MutationObserver(() => window.reportStage(stage.textContent)).observe(stage, { childList: true, characterData: true, subtree: true });
  });
  for (let i = 0; i < 3; i++) await page.locator('[data-role=alpha]').press('ArrowRight');
  await laidOut(page, 1.5);
  assert.equal(await page.locator('[data-role=alpha-value]').textContent(), '1.5');
  assert.ok(!stages.some((text) => /fresh core|separatrices|Cancelled/.test(text)), `stages: ${[...new Set(stages)].join(' | ')}`);

  const [glb] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Download GLB' }).click()]);
  assert.equal(glb.suggestedFilename(), 'sphere-layout.glb');
  await glb.saveAs(`${RESULTS}/sphere-layout.glb`);
  const bytes = readFileSync(`${RESULTS}/sphere-layout.glb`);
  assert.equal(bytes.subarray(0, 4).toString('latin1'), 'glTF');
  assert.match(bytes.toString('latin1'), /_PATCH/);
  const [ply] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Download PLY' }).click()]);
  assert.equal(ply.suggestedFilename(), 'sphere-layout.ply');
  await ply.saveAs(`${RESULTS}/sphere-layout.ply`);
  assert.match(readFileSync(`${RESULTS}/sphere-layout.ply`).subarray(0, 400).toString('latin1'), /property int patch/);
});

test('Layout: the worker solves the slider ahead while idle; a move there lays out its matching', async ({ page, url }) => {
  await openPage(page, url, '#sample=genus2');
  await page.getByRole('button', { name: 'Compute quad layout' }).click();
  await laidOut(page, 5);
  assert.match(await layoutFigure(page, 'rounds'), /^\d+$/, 'the first layout was solved');
  const patchesAt5 = await layoutFigure(page, 'patches');
  await page.waitForTimeout(3000); // 4.5 is presolved first, in tens of milliseconds
  await page.locator('[data-role=alpha]').fill('4.5');
  await laidOut(page, 4.5);
  assert.match(await layoutFigure(page, 'rounds'), /^\d+, solved ahead$/);
  await page.screenshot({ path: `${RESULTS}/layout-genus2-presolved.png` });
  assert.match(await verdict(page).textContent(), /^valid: \d+ patches, all quads$/);
  await page.locator('[data-role=alpha]').fill('5');
  await laidOut(page, 5);
  assert.equal(await layoutFigure(page, 'patches'), patchesAt5, 'alpha 5 again');
});

test('Layout: a torus without a parameterization is a clear error and the page stays usable', async ({ page, url }) => {
  await openPage(page, url, '#sample=torus');
  await page.getByRole('button', { name: 'Compute quad layout' }).click();
  const alert = page.getByRole('alert');
  await alert.waitFor();
  assert.match(await alert.textContent(), /parameterization/);
  await idle(page);
  assert.ok(await page.locator('[data-role=layout-result]').isHidden(), 'a layout is shown after the error');
  await page.getByLabel('Align').selectOption('curvature');
  await page.getByRole('button', { name: 'Compute quad layout' }).click();
  await laidOut(page, 5);
  assert.match(await verdict(page).textContent(), /^(valid: \d+ patches, all quads|invalid: .+)$/);
});
