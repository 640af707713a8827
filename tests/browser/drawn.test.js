// The "On a surface" view of the Regular maps mode (thesis Sec. 9.5-9.6): the Klein quartic drawn
// on the tetrahedron's regular surface from the shipped manifest, its figures, faces in colours and
// edges in dark lines, the bare surface, the other surfaces, the GLB, and the link that shares it.
import { readFile } from 'node:fs/promises';
import assert from 'node:assert/strict';
import validator from 'gltf-validator';
import { RESULTS, test } from './harness.js';
import { foregroundShare, idle, openMap, pixelShares } from './helpers.js';

const drawnFigure = (page, key) => page.locator(`[data-role=drawn-figures] [data-figure=${key}]`).textContent();

async function drawnShown(page) {
  await page.locator('[data-role=drawn-result]').waitFor();
  await idle(page);
}

// Dark pixels (the map's edges) and saturated ones (its faces).
const SHARES = {
  dark: '(r, g, b) => Math.max(r, g, b) < 70',
  colour: '(r, g, b) => Math.max(r, g, b) - Math.min(r, g, b) > 60',
};

test('On a surface: R3.1 drawn on the tetrahedron, V 24, E 84, F 56, edges drawn, a valid GLB, a shared link', async ({ page, url }) => {
  await openMap(page, url, '#mode=regmap&map=R3.1&view=tiling');
  const start = Date.now();
  await page.getByRole('radio', { name: 'On a surface' }).check();
  await drawnShown(page);
  const seconds = (Date.now() - start) / 1000;
  console.log(`    R3.1 drawn on its surface in the page: ${seconds.toFixed(2)} s from the click`);
  await page.screenshot({ path: `${RESULTS}/drawn-R3.1.png` });
  assert.equal(await drawnFigure(page, 'target'), 'Tetrahedron (platonic)');
  assert.equal(await drawnFigure(page, 'pairing'), 'rotations');
  assert.equal(await drawnFigure(page, 'V'), '24 = 24');
  assert.equal(await drawnFigure(page, 'E'), '84 = 84');
  assert.equal(await drawnFigure(page, 'F'), '56 = 56');
  assert.equal(await drawnFigure(page, 'genus'), '3');
  for (const key of ['faces_are_disks', 'covers_once', 'closed', 'oriented']) assert.equal(await drawnFigure(page, key), 'yes', key);
  // The drawn map is the default view: its link names no view.
  assert.equal(await page.evaluate(() => location.hash.replace(/&cam=[^&]*/, '')), '#mode=regmap&map=R3.1');
  const shares = await pixelShares(page, SHARES);
  assert.ok(shares.colour > 0.03, `the faces cover ${shares.colour} of the view`);
  assert.ok(shares.dark > 0.001, `the edges cover ${shares.dark} of the view`);

  await page.getByLabel('Show the bare surface').check();
  const bare = await pixelShares(page, SHARES);
  assert.ok(bare.dark < shares.dark, 'the bare surface still shows the edges');
  await page.getByLabel('Show the bare surface').uncheck();

  const [download] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Export GLB' }).click()]);
  assert.equal(download.suggestedFilename(), 'R3.1-drawn.glb');
  const path = `${RESULTS}/R3.1-drawn.glb`;
  await download.saveAs(path);
  const report = await validator.validateBytes(new Uint8Array(await readFile(path)));
  assert.equal(report.issues.numErrors, 0, JSON.stringify(report.issues.messages.slice(0, 5)));
  assert.ok((await foregroundShare(page)) > 0.05);
});

test('On a surface: the default view of a map; a link names the surface; R2.4, with no realization, says what was tried and the page stays usable', async ({ page, url }) => {
  const start = Date.now();
  await openMap(page, url, "#mode=regmap&map=R13.2'");
  await drawnShown(page);
  console.log(`    R13.2' drawn on its surface in the page: ${((Date.now() - start) / 1000).toFixed(2)} s from opening the link`);
  assert.equal(await drawnFigure(page, 'target'), "R3.4' (catalog)");
  assert.equal(await drawnFigure(page, 'F'), '24 = 24');
  assert.ok(await page.getByRole('radio', { name: 'On a surface' }).isChecked());
  assert.ok(await page.locator('#tiling-view').isHidden());

  await openMap(page, url, "#mode=regmap&map=R9.3'&view=map&on=R2.1'");
  await drawnShown(page);
  assert.equal(await drawnFigure(page, 'target'), "R2.1' (catalog)");
  assert.equal(await drawnFigure(page, 'F'), '32 = 32');
  assert.equal(await drawnFigure(page, 'V'), '48 = 48');

  // R2.4 {5,10} has no target it pairs with (the hosohedron {2,3}'s junctions of valence 3 fit
  // neither its faces nor its vertices): the message names what was tried.
  await page.evaluate(() => {
    location.hash = '#mode=regmap&map=R2.4&view=map';
  });
  await page.getByRole('alert').filter({ hasText: /R2\.4 has no pairing with \{2,3\}/ }).waitFor();
  await idle(page);
  assert.ok(await page.locator('[data-role=drawn-result]').isHidden());
  await page.getByLabel('2D tiling').check();
  await page.locator('#tiling-view img').waitFor();
});
