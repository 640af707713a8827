// The "On a surface" view of the Regular maps mode (thesis Sec. 9.5-9.6): the Klein quartic drawn
// on the tetrahedron's regular surface from the shipped manifest, its figures, faces in colours and
// edges in dark lines, the bare surface, the other surfaces, the exports (GLB, PLY, OBJ, SVG, the
// STL to print and its check), and the link that shares it.
import { readFile } from 'node:fs/promises';
import assert from 'node:assert/strict';
import validator from 'gltf-validator';
import { RESULTS, test } from './harness.js';
import { changedShare, foregroundShare, idle, openMap, pixelShares } from './helpers.js';

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

  assert.equal(await drawnFigure(page, 'face_orbits'), '6');
  const colours = page.getByLabel('Colours');
  await colours.selectOption('tubes');
  const bare = await pixelShares(page, SHARES);
  assert.ok(bare.dark < shares.dark, 'the bare surface still shows the edges');
  // Faces by orbit: the 56 faces in 6 colours (the tetrahedron's 12 rotations), edges still drawn;
  // the link keeps the colouring, and a fresh page opened on it shows the same picture.
  await colours.selectOption('orbits');
  await idle(page);
  const orbits = await pixelShares(page, SHARES);
  assert.ok(orbits.dark > 0.001 && orbits.colour > 0.03, JSON.stringify(orbits));
  assert.match(await page.evaluate(() => location.hash), /&colors=orbits/);
  const orbitPicture = await page.locator('#viewport canvas').screenshot();
  const other = await page.context().newPage();
  await other.goto(await page.evaluate(() => location.href));
  await drawnShown(other);
  assert.equal(await other.getByLabel('Colours').inputValue(), 'orbits');
  const share = await changedShare(page, orbitPicture, await other.locator('#viewport canvas').screenshot());
  assert.ok(share < 0.01, `the link's picture differs in ${share} of the pixels`);
  await other.close();
  await colours.selectOption('faces');

  const exportPart = page.locator('[data-role=drawn-export]');
  const save = async (button, file) => {
    const [download] = await Promise.all([page.waitForEvent('download'), exportPart.getByRole('button', { name: button, exact: true }).click()]);
    assert.equal(download.suggestedFilename(), file);
    const path = `${RESULTS}/${file}`;
    await download.saveAs(path);
    return readFile(path);
  };
  const report = await validator.validateBytes(new Uint8Array(await save('GLB', 'R3.1-drawn.glb')));
  assert.equal(report.issues.numErrors, 0, JSON.stringify(report.issues.messages.slice(0, 5)));
  assert.match((await save('PLY', 'R3.1-drawn.ply')).subarray(0, 400).toString('latin1'), /^ply\n[^]*property int face\n/);
  assert.match((await save('OBJ', 'R3.1-drawn.obj')).toString('latin1'), /\nf \d+ \d+ \d+\n/);
  assert.match((await save('SVG of the polygon', 'R3.1.svg')).toString('utf8'), /<svg/);
  assert.ok((await foregroundShare(page)) > 0.05);

  // The STL to print: 60 mm across, walls checked against 1 mm, then against a wall thicker than
  // the tubes, which is named as the problem.
  await page.getByLabel('Print size').fill('60');
  await page.getByLabel('Wall').fill('1');
  const stl = await save('STL to print', 'R3.1-drawn.stl');
  assert.equal(stl.length, 84 + 50 * stl.readUInt32LE(80));
  const printReport = page.locator('[data-role=print-report]');
  await printReport.waitFor();
  assert.match(await printReport.textContent(), /Printed 60\.0 mm × [\d.]+ mm × [\d.]+ mm; thinnest wall [\d.]+ mm \(1\.0 mm asked\)\.Printable/);
  await page.getByLabel('Wall').fill('20');
  await save('STL to print', 'R3.1-drawn.stl');
  await page.waitForFunction(() => document.querySelector('[data-role=print-report]').dataset.printable === 'false');
  assert.match(await printReport.textContent(), /Not printable as it is:The solid is thinner than the 20 mm wall/);
  await page.getByLabel('Wall').fill('-3');
  await exportPart.getByRole('button', { name: 'STL to print' }).click();
  assert.equal(await page.getByLabel('Wall').getAttribute('aria-invalid'), 'true');
  await page.locator('#status').getByText('The print size or wall cannot be used.').waitFor();
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
  await page.getByRole('alert').filter({ hasText: /R2\.4 has no pairing, by reflections or by rotations, with \{2,3\}/ }).waitFor();
  await idle(page);
  assert.ok(await page.locator('[data-role=drawn-result]').isHidden());
  await page.getByLabel('2D tiling').check();
  await page.locator('#tiling-view img').waitFor();
});
