// The 3D view of the Regular maps mode: a map's regular surface built in the worker, drawn in the
// shared viewer coloured by quarter tube, its figures, its GLB, shared links, map changes, Cancel.
import { readFile } from 'node:fs/promises';
import assert from 'node:assert/strict';
import validator from 'gltf-validator';
import { RESULTS, test } from './harness.js';
import { changedShare, foregroundShare, idle, mapShown, openMap, pixelShares } from './helpers.js';

const surfaceFigure = (page, key) => page.locator(`[data-role=surface-figures] [data-figure=${key}]`).textContent();
// The link without its camera (which every framing updates).
const hash = (page) => page.evaluate(() => location.hash.replace(/&cam=[^&]*/, ''));
const canvas = (page) => page.locator('#viewport canvas');
const note = (page) => page.locator('#surface-note');

// Lit pixels by hue sextant (red, yellow, green, cyan, blue, magenta), saturated ones only: the
// quarter tubes' pastel colours (web/src/viewer/palette.js) against the grey background and the
// beige mesh of the Quad layout mode.
const HUES = Object.fromEntries(
  ['red', 'yellow', 'green', 'cyan', 'blue', 'magenta'].map((name, sextant) => [
    name,
    `(r, g, b) => {
      const max = Math.max(r, g, b), min = Math.min(r, g, b);
      if (max - min < 60) return false;
      const h = max === r ? (g - b) / (max - min) : max === g ? 2 + (b - r) / (max - min) : 4 + (r - g) / (max - min);
      return Math.floor((h + 6) % 6) === ${sextant};
    }`,
  ]),
);

/** The hue sextants that cover more than 0.3 % of the 3D view. */
async function huesDrawn(page) {
  const shares = await pixelShares(page, HUES);
  return Object.keys(shares).filter((name) => shares[name] > 0.003);
}

/** Waits until the surface's figures are in the panel and no job runs. */
async function surfaceShown(page) {
  await page.locator('[data-role=surface-result]').waitFor();
  await idle(page);
}

async function assertSurfaceDrawn(page, what) {
  const hues = await huesDrawn(page);
  assert.ok(hues.length >= 4, `${what}: the quarter tubes show only the hues ${hues.join(', ')}`);
  assert.ok((await foregroundShare(page)) > 0.05, `${what}: the surface covers little of the view`);
}

test('Regular surface: R2.4 in the 3D view, coloured by quarter tube, genus 5, 20 quarter tubes, a valid GLB', async ({ page, url }) => {
  await openMap(page, url, '#mode=regmap&map=R2.4&view=tiling');
  await page.getByLabel('3D surface').check();
  await surfaceShown(page);
  await page.screenshot({ path: `${RESULTS}/surface-R2.4.png` });
  assert.equal(await surfaceFigure(page, 'genus'), '5 = 1 − 1 + 5');
  assert.equal(await surfaceFigure(page, 'quarter_tubes'), '20 = 4 × 5');
  assert.equal(await surfaceFigure(page, 'euler_characteristic'), '-8');
  for (const key of ['closed', 'oriented']) assert.equal(await surfaceFigure(page, key), 'yes', key);
  assert.equal(await surfaceFigure(page, 'relations'), 'hold');
  assert.match(await surfaceFigure(page, 'self_intersections'), /^(none|\d+ triangle pairs?)$/);
  assert.match(await surfaceFigure(page, 'seconds'), /^\d+(\.\d+)? (ms|s)$/);
  assert.ok(await page.locator('#tiling-view').isHidden(), 'the tiling covers the 3D view');
  assert.ok(await note(page).isHidden());
  assert.equal(await hash(page), '#mode=regmap&map=R2.4&view=surface');
  await assertSurfaceDrawn(page, 'R2.4');

  // A cancelled job replaces the worker: the export builds the surface again in the fresh one.
  const bigTorus = 'BigTorus : Type {4,4}\n[ T^2, R^4, S^4, (R * S)^2, (R * T)^2, (S * T)^2, (R * S^-1)^300 ]';
  await page.getByLabel("A map's group in Conder's text format").fill(bigTorus);
  await page.getByRole('button', { name: 'Run the presentation' }).click();
  await page.locator('[data-role=progress]').waitFor();
  await page.waitForTimeout(300);
  await page.getByRole('button', { name: 'Cancel' }).click();
  await page.getByRole('status').filter({ hasText: 'Cancelled.' }).waitFor();
  assert.equal(await surfaceFigure(page, 'genus'), '5 = 1 − 1 + 5');

  const [download] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Export GLB' }).click()]);
  assert.equal(download.suggestedFilename(), 'R2.4-surface.glb');
  const path = `${RESULTS}/R2.4-surface.glb`;
  await download.saveAs(path);
  const bytes = new Uint8Array(await readFile(path));
  const report = await validator.validateBytes(bytes);
  assert.equal(report.issues.numErrors, 0, JSON.stringify(report.issues.messages.slice(0, 5)));
  const json = new TextDecoder().decode(bytes.subarray(20, 20 + new DataView(bytes.buffer).getUint32(12, true)));
  assert.match(json, /"_TILE"/, 'the GLB has no quarter-tube attribute');
  assert.match(json, /"quarter_tubes":20/);

  await page.getByLabel('2D tiling').check();
  assert.ok(await page.locator('#tiling-view img').isVisible(), 'the tiling does not come back');
  assert.equal(await hash(page), '#mode=regmap&map=R2.4&view=tiling');
});

test('Regular surface: a shared link reopens it with its options; each mode keeps its own 3D scene', async ({ page, url }) => {
  await openMap(page, url, '#mode=regmap&map=R3.1&view=surface&radius=0.1&smoothness=3');
  await surfaceShown(page);
  await page.screenshot({ path: `${RESULTS}/surface-R3.1.png` });
  assert.equal(await page.getByLabel('3D surface').isChecked(), true);
  assert.equal(await page.getByLabel('Tube radius').inputValue(), '0.1');
  assert.equal(await page.locator('[name=smoothness]').inputValue(), '3');
  assert.equal(await surfaceFigure(page, 'genus'), '61 = 1 − 24 + 84');
  assert.equal(await surfaceFigure(page, 'quarter_tubes'), '336 = 4 × 84');
  assert.equal(await surfaceFigure(page, 'tube_radius'), '0.100');
  await assertSurfaceDrawn(page, 'R3.1');
  const surface = await canvas(page).screenshot();

  await page.getByRole('tab', { name: 'Quad layout' }).click();
  await page.locator('[data-role=mesh-name]').filter({ hasText: 'genus2' }).waitFor();
  await idle(page);
  assert.deepEqual(await huesDrawn(page), [], 'the surface shows over the Quad layout mesh');
  await page.getByRole('tab', { name: 'Regular maps' }).click();
  await idle(page);
  assert.ok((await changedShare(page, surface, await canvas(page).screenshot())) < 0.01, 'the surface or its camera changed');
  assert.match(await hash(page), /view=surface&radius=0\.1&smoothness=3/);
});

test('Regular surface: another map clears it, Cancel keeps the page usable, bad options are refused', async ({ page, url }) => {
  await openMap(page, url, '#mode=regmap&map=R2.4&view=surface');
  await surfaceShown(page);
  await page.getByLabel('Name', { exact: true }).fill('R85.1');
  await page.getByRole('option', { name: /^R85\.1\b/ }).click();
  // Genus 85, 2016 edges: its relaxation runs for many seconds.
  await page.getByText('Relaxing the edge graph in space').waitFor();
  assert.ok(await page.locator('[data-role=surface-result]').isHidden(), "R2.4's figures stay for R85.1");
  assert.deepEqual(await huesDrawn(page), [], "R2.4's surface stays for R85.1");
  await page.getByRole('button', { name: 'Cancel' }).click();
  await page.getByRole('status').filter({ hasText: 'Cancelled.' }).waitFor();
  assert.ok(await page.locator('[data-role=progress]').isHidden());
  assert.equal(await note(page).textContent(), 'The regular surface of R85.1 was not built. "Build the surface" tries again.');
  assert.ok(await note(page).isVisible());
  // Coming back to the mode does not start the cancelled build again.
  await page.getByRole('tab', { name: 'Quad layout' }).click();
  await page.locator('[data-role=mesh-name]').filter({ hasText: 'genus2' }).waitFor();
  await idle(page);
  await page.getByRole('tab', { name: 'Regular maps' }).click();
  assert.ok(await page.locator('[data-role=progress]').isHidden(), 'the cancelled build started again');
  assert.ok(await note(page).isVisible());

  await page.getByLabel('Tube radius').fill('thick');
  await page.getByRole('button', { name: 'Build the surface' }).click();
  const alert = page.getByRole('alert');
  await alert.waitFor();
  assert.match(await alert.textContent(), /The surface options cannot be used.*number from 0 \(automatic\) to 0.5/s);
  assert.equal(await page.getByLabel('Tube radius').getAttribute('aria-invalid'), 'true');

  // A typed map whose surface the core refuses: the error in plain words, the view says so.
  const dihedral = 'Dihedral : Type {4,2}\n[ T^2, R^4, S^2, (R * S)^2, (R * T)^2, (S * T)^2 ]';
  await page.getByLabel("A map's group in Conder's text format").fill(dihedral);
  await page.getByRole('button', { name: 'Run the presentation' }).click();
  await page.getByRole('alert').filter({ hasText: /junctions of valence 2.*at least 3 tubes/ }).waitFor();
  assert.match(await note(page).textContent(), /^The regular surface of Dihedral was not built/);

  await page.getByLabel('Name', { exact: true }).fill('R2.4');
  await page.getByRole('option', { name: /^R2\.4\b/ }).click();
  await mapShown(page, 'R2.4');
  await surfaceShown(page);
  assert.equal(await surfaceFigure(page, 'genus'), '5 = 1 − 1 + 5');
  await page.getByLabel('Tube radius').fill('0.2');
  await page.getByRole('button', { name: 'Build the surface' }).click();
  await page.locator('[data-figure=tube_radius]').filter({ hasText: '0.200' }).waitFor();
  await idle(page);
  assert.equal(await page.getByLabel('Tube radius').getAttribute('aria-invalid'), 'false');
  assert.match(await hash(page), /&map=R2\.4&view=surface&radius=0\.2$/);
  await assertSurfaceDrawn(page, 'R2.4 with thick tubes');
});
