// The Regular maps mode as a user meets it: the catalog searched, a map's figures and tiling, shared
// links, typed presentations (good, infinite, hostile), zoom/pan/download and Cancel.
import { readFile } from 'node:fs/promises';
import assert from 'node:assert/strict';
import { RESULTS, test } from './harness.js';
import { dropFiles, idle, mapFigure, mapShown, message, openMap, openPage, tilingImage } from './helpers.js';

const figures = (page, keys) => Promise.all(keys.map((key) => mapFigure(page, key)));
const presentation = (name, type, relators) => `${name} : Type {${type}}\n[ ${relators.join(', ')} ]`;
const TRIANGLE_RELATORS = ['T^2', '(R * S)^2', '(R * T)^2', '(S * T)^2'];
const searchField = (page, label) => page.getByLabel(label, { exact: true });

async function runPresentation(page, text) {
  await page.getByLabel("A map's group in Conder's text format").fill(text);
  await page.getByRole('button', { name: 'Run the presentation' }).click();
}

async function assertTilingDrawn(page, what) {
  const image = await tilingImage(page);
  assert.ok(image.complete && image.naturalWidth > 0, `${what}: the tiling image did not load`);
  assert.match(image.src, /^blob:/, `${what}: the tiling is not shown from a Blob URL`);
  assert.ok(image.drawn > 0.2, `${what}: only ${(image.drawn * 100).toFixed(1)} % of the tiling image is drawn`);
}

test('Regular maps: a link to R3.1 shows its figures and its tiling', async ({ page, url }) => {
  await openMap(page, url, '#mode=regmap&map=R3.1&view=tiling');
  assert.equal(await page.locator('[data-role=map-name]').textContent(), 'R3.1');
  assert.deepEqual(await figures(page, ['order', 'vertices', 'edges', 'faces', 'genus']), ['336', '24', '84', '56', '3']);
  assert.deepEqual(await figures(page, ['type', 'petrie', 'euler']), ['{3,7}', '8', '-4']);
  assert.match(await mapFigure(page, 'seconds'), /^\d+(\.\d+)? (ms|s)$/);
  await assertTilingDrawn(page, 'R3.1');
  assert.equal(await page.getByRole('tab', { name: 'Regular maps' }).getAttribute('aria-selected'), 'true');
  assert.ok(await page.locator('#quad-panel').isHidden(), 'the Quad layout panel shows in the Regular maps mode');
  await page.screenshot({ path: `${RESULTS}/regmap-R3.1.png` });
});

test('Regular maps: R2.4 found by search, its link reopens it in a fresh page', async ({ page, url, context }) => {
  await openMap(page, url);
  await searchField(page, 'Genus').fill('2');
  await searchField(page, 'Type').fill('{5,10}');
  const list = page.getByRole('listbox', { name: 'Maps of the catalog' });
  await list.getByRole('option', { name: /^R2\.4\b/ }).click();
  await mapShown(page, 'R2.4');
  assert.deepEqual(await figures(page, ['order', 'vertices', 'edges', 'faces', 'genus']), ['20', '1', '5', '2', '2']);
  await assertTilingDrawn(page, 'R2.4');
  await page.screenshot({ path: `${RESULTS}/regmap-R2.4.png` });
  const link = page.url();
  assert.match(link, /#mode=regmap&map=R2\.4&view=tiling$/);

  const fresh = await context.newPage();
  await openMap(fresh, link, '');
  assert.equal(await fresh.locator('[data-role=map-name]').textContent(), 'R2.4');
  assert.equal(await mapFigure(fresh, 'order'), '20');
  await assertTilingDrawn(fresh, 'R2.4 reopened');

  await fresh.getByRole('button', { name: "Show its dual, R2.4'" }).click();
  await mapShown(fresh, "R2.4'");
  assert.deepEqual(await figures(fresh, ['type', 'vertices', 'faces']), ['{10,5}', '2', '1']);
  assert.equal(new URL(fresh.url()).hash, '#mode=regmap&map=R2.4%27&view=tiling');

  await fresh.evaluate(() => {
    location.hash = '#mode=regmap&map=R2.1&view=tiling';
  });
  await mapShown(fresh, 'R2.1');
  assert.equal(await mapFigure(fresh, 'order'), '96');
});

test('Regular maps: the catalog list stays small in the page and is searchable from the keyboard', async ({ page, url }) => {
  await openMap(page, url);
  const list = page.getByRole('listbox', { name: 'Maps of the catalog' });
  const count = page.locator('[data-role=catalog-count]');
  assert.equal(await count.textContent(), '3,378 of 3,378 maps');
  const drawn = await list.getByRole('option').count();
  assert.ok(drawn > 5 && drawn < 40, `${drawn} rows are in the page for 3,378 maps`);
  await list.evaluate((element) => {
    element.scrollTop = element.scrollHeight;
  });
  await list.getByRole('option', { name: /^R101\.56\b/ }).waitFor();

  await searchField(page, 'Type').fill('7,3'); // p > q: the duals
  assert.match(await count.textContent(), /^\d+ of 3,378 maps$/);
  await list.getByRole('option', { name: /^R3\.1'/ }).waitFor();
  await searchField(page, 'Type').fill('');
  await searchField(page, 'Genus').fill('two');
  assert.equal(await searchField(page, 'Genus').getAttribute('aria-invalid'), 'true');
  assert.match(await count.textContent(), /^Genus: a number \(3\) or a range \(2-10\)\./);
  await searchField(page, 'Genus').fill('3-4');
  await searchField(page, 'Name').fill('R4.');
  assert.match(await count.textContent(), /^\d+ of 3,378 maps$/);
  const names = await list.getByRole('option').evaluateAll((rows) => rows.map((row) => row.firstChild.textContent));
  assert.ok(names.length > 0 && names.every((name) => name.startsWith('R4.')), names.join(' '));

  await list.focus();
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('Enter');
  await mapShown(page, names[1]);
  assert.equal(await mapFigure(page, 'genus'), '4');
  assert.equal(await list.getByRole('option', { selected: true }).getAttribute('aria-posinset'), '2');
});

test('Regular maps: a typed infinite presentation gets a clear error and the page keeps working', async ({ page, url }) => {
  await openMap(page, url);
  const started = Date.now();
  await runPresentation(page, presentation('Hyperbolic', '3,7', [...TRIANGLE_RELATORS, 'R^3', 'S^7']));
  const alert = page.getByRole('alert');
  await alert.waitFor();
  const text = await alert.textContent();
  assert.match(text, /beyond a limit/);
  assert.match(text, /infinite/, `the error does not say why: ${text}`);
  assert.ok(Date.now() - started < 15_000, 'the limit took longer than 15 s');
  await page.screenshot({ path: `${RESULTS}/regmap-infinite.png` });
  assert.equal(await page.locator('[data-role=map-name]').textContent(), 'R3.1', 'the map on screen was lost');

  await runPresentation(page, presentation('Cube', '4,3', [...TRIANGLE_RELATORS, 'R^4', 'S^3']));
  await mapShown(page, 'Cube (typed presentation)');
  assert.deepEqual(await figures(page, ['order', 'vertices', 'edges', 'faces', 'genus']), ['48', '8', '12', '6', '0']);
  assert.ok(await message(page).isHidden(), 'the old error stays after a successful job');
  assert.equal(new URL(page.url()).hash, '#mode=regmap&view=tiling', 'a typed presentation is not a catalog link');
  await assertTilingDrawn(page, 'the cube');
});

test('Regular maps: malformed and hostile presentations are shown as text, never as markup', async ({ page, url }) => {
  await openMap(page, url);
  await runPresentation(page, 'X : Type {3,7}\n[ T^2, R^3, Q^7 ]');
  const alert = page.getByRole('alert');
  await alert.waitFor();
  assert.match(await alert.textContent(), /could not be read.*unknown generator 'Q'/s);
  await runPresentation(page, presentation('Collapsed', '3,7', [...TRIANGLE_RELATORS, 'R^3', 'S^7', '(R * S^-1)^60']));
  await page.getByRole('alert').filter({ hasText: 'The input cannot be used' }).waitFor();
  assert.match(await alert.textContent(), /R of order 1 instead of 3/);

  const hostile = '<img/src=x/onerror=window.hacked=1>';
  await runPresentation(page, presentation(hostile, '4,3', [...TRIANGLE_RELATORS, 'R^4', 'S^3']));
  await mapShown(page, `${hostile} (typed presentation)`);
  // The panel's one image is the polygon beside the 3D view.
  assert.equal(await page.locator('#regmap-panel img:not([data-role=tiling-beside-image])').count(), 0, 'the name was parsed as markup');
  assert.equal(await page.evaluate(() => window.hacked), undefined);
});

test('Regular maps: a bad map in the link gets a notice and the default map', async ({ page, url }) => {
  await openMap(page, url, '#mode=regmap&map=R999.1&view=tiling');
  assert.equal(await page.locator('[data-role=map-name]').textContent(), 'R3.1');
  const notice = page.getByRole('status').filter({ hasText: 'There is no map named "R999.1" in the catalog.' });
  assert.match(await notice.textContent(), /R2\.1 to R101\.56/);

  await page.goto('about:blank');
  await openMap(page, url, '#mode=regmap&map=%3Cscript%3E&view=tiling');
  assert.equal(await page.locator('[data-role=map-name]').textContent(), 'R3.1');
  const ignored = page.getByRole('status').filter({ hasText: 'Parts of the link were ignored.' });
  assert.match(await ignored.textContent(), /"map" has an invalid value/);
});

test('Regular maps: the tiling zooms, pans, fits and downloads as SVG', async ({ page, url }) => {
  await openMap(page, url, '#mode=regmap&map=R2.4&view=tiling');
  const image = page.locator('#tiling-view img');
  const box = async () => image.evaluate((img) => img.getBoundingClientRect().toJSON());
  const fitted = await box();
  await page.getByRole('button', { name: 'Zoom in' }).click();
  const zoomed = await box();
  assert.ok(zoomed.width > 1.4 * fitted.width, `zoom in: ${fitted.width} -> ${zoomed.width}`);
  const stage = page.locator('#tiling-view [data-role=stage]');
  const stageBox = await stage.boundingBox();
  await page.mouse.move(stageBox.x + 300, stageBox.y + 300);
  await page.mouse.down();
  await page.mouse.move(stageBox.x + 200, stageBox.y + 250, { steps: 4 });
  await page.mouse.up();
  const panned = await box();
  assert.deepEqual([Math.round(panned.x - zoomed.x), Math.round(panned.y - zoomed.y)], [-100, -50]);
  await page.mouse.wheel(0, -400);
  assert.ok((await box()).width > zoomed.width, 'the wheel did not zoom in');
  await page.getByRole('button', { name: 'Fit' }).click();
  assert.deepEqual(await box(), fitted);
  await stage.focus();
  await page.keyboard.press('+');
  await page.keyboard.press('ArrowLeft');
  const keyed = await box();
  assert.ok(keyed.width > 1.4 * fitted.width, 'the + key did not zoom in');
  await page.keyboard.press('0');
  assert.deepEqual(await box(), fitted);

  const [download] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Download SVG' }).click()]);
  assert.equal(download.suggestedFilename(), 'R2.4.svg');
  const path = `${RESULTS}/R2.4.svg`;
  await download.saveAs(path);
  const svg = await readFile(path, 'utf8');
  assert.match(svg, /^<\?xml[^>]*>\s*<svg /);
  assert.match(svg, /<title>R2\.4<\/title>/);
});

test('Regular maps: a typed map too large to draw shows its figures and is kept for download', async ({ page, url }) => {
  await openMap(page, url);
  await runPresentation(page, presentation('Torus50', '4,4', [...TRIANGLE_RELATORS, 'R^4', 'S^4', '(R * S^-1)^50']));
  await mapShown(page, 'Torus50 (typed presentation)');
  assert.deepEqual(await figures(page, ['order', 'genus', 'triangles']), ['20,000', '1', '20,000']);
  const note = page.locator('#tiling-view [data-role=note]');
  assert.match(await note.textContent(), /20,000 triangles, more than the page draws \(16,000\)/);
  assert.ok(await page.locator('#tiling-view img').isHidden(), 'the previous tiling still shows');
  assert.ok(await page.getByRole('button', { name: 'Zoom in' }).isDisabled());
  await page.screenshot({ path: `${RESULTS}/regmap-too-large.png` });
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Download SVG' }).click()]);
  assert.equal(download.suggestedFilename(), 'Torus50.svg');
  const path = `${RESULTS}/Torus50.svg`;
  await download.saveAs(path);
  assert.match(await readFile(path, 'utf8'), /<title>Torus50<\/title>/);

  await page.getByRole('option', { name: /^R2\.4\b/ }).click();
  await mapShown(page, 'R2.4');
  assert.ok(await note.isHidden(), 'the note stays over a drawn tiling');
  await assertTilingDrawn(page, 'R2.4 after a large map');
});

test('Regular maps: Cancel stops a long enumeration and the next map is shown', async ({ page, url }) => {
  await openMap(page, url);
  // A torus map of order 720,000: its enumeration runs for seconds (and ends at the time limit).
  await runPresentation(page, presentation('BigTorus', '4,4', [...TRIANGLE_RELATORS, 'R^4', 'S^4', '(R * S^-1)^300']));
  await page.locator('[data-role=progress]').waitFor();
  await page.waitForTimeout(500);
  const cancelled = Date.now();
  await page.getByRole('button', { name: 'Cancel' }).click();
  await page.getByRole('status').filter({ hasText: 'Cancelled.' }).waitFor();
  assert.ok(Date.now() - cancelled < 2000, 'Cancel took longer than 2 s');
  assert.ok(await page.locator('[data-role=progress]').isHidden());
  assert.equal(await page.locator('[data-role=map-name]').textContent(), 'R3.1', 'the map on screen was lost');
  await searchField(page, 'Name').fill('R2.4');
  await page.getByRole('option', { name: /^R2\.4\b/ }).click();
  await mapShown(page, 'R2.4');
  assert.equal(await mapFigure(page, 'order'), '20');
});

test('Regular maps: the tabs switch modes, each keeps what it shows, a dropped mesh opens in Quad layout', async ({ page, url }) => {
  await openPage(page, url);
  await page.getByRole('tab', { name: 'Regular maps' }).click();
  await mapShown(page, 'R3.1');
  // The mode opens on its default view, the map drawn on a surface.
  assert.ok(await page.getByRole('radio', { name: 'On a surface' }).isChecked());
  assert.ok(await page.locator('#tiling-view').isHidden(), 'the 2D tiling covers the drawn map');
  await page.locator('[data-role=drawn-result]').waitFor();
  assert.match(new URL(page.url()).hash, /mode=regmap/);
  await page.getByRole('tab', { name: 'Quad layout' }).click();
  assert.ok(await page.locator('#tiling-view').isHidden());
  assert.match(await page.locator('[data-role=mesh-name]').textContent(), /genus2/);
  await page.getByRole('tab', { name: 'Regular maps' }).click();
  assert.equal(await page.locator('[data-role=map-name]').textContent(), 'R3.1');

  await dropFiles(page, [{ name: 'triangle.obj', text: 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' }]);
  await page.locator('[data-role=mesh-name]').filter({ hasText: 'triangle' }).waitFor();
  await idle(page);
  assert.equal(await page.getByRole('tab', { name: 'Quad layout' }).getAttribute('aria-selected'), 'true');
});

test('Regular maps: a core that cannot be loaded is reported, and the catalog loads when the mode is shown again', async ({ page, url }) => {
  await page.route('**/wasm/tessera.mjs', (route) => route.abort());
  await page.goto(`${url}#mode=regmap&map=R2.4&view=tiling`);
  const alert = page.getByRole('alert');
  await alert.waitFor();
  assert.match(await alert.textContent(), /geometry core .* could not be started/);
  await page.unroute('**/wasm/tessera.mjs');
  await page.getByRole('tab', { name: 'Quad layout' }).click();
  await page.locator('[data-role=mesh-name]').filter({ hasText: 'genus2' }).waitFor();
  await page.getByRole('tab', { name: 'Regular maps' }).click();
  await mapShown(page, 'R2.4');
  assert.equal(await page.locator('[data-role=catalog-count]').textContent(), '3,378 of 3,378 maps');
});
