// The Gallery mode and the links it hands out: the cards, the filters, a map opened from its card,
// its permalink (camera included) reproducing the view in a fresh browser context.
import assert from 'node:assert/strict';
import { RESULTS, test } from './harness.js';
import { changedShare, foregroundShare, idle } from './helpers.js';

const cards = (page) => page.locator('#gallery .gallery-card');

async function drawn(page, name) {
  await page.waitForFunction((map) => document.querySelector('[data-role=drawn-view]')?.dataset.drawn === map, name, {
    timeout: 60_000,
  });
  await idle(page);
  await page.waitForTimeout(300); // the frame after the last render request
}

test('Gallery: every map as a card, filtered to genus 3, R3.1 opened from its card', async ({ page, url }) => {
  const start = Date.now();
  await page.goto(`${url}#mode=gallery`);
  await cards(page).first().waitFor();
  console.log(`    gallery's first cards after ${Date.now() - start} ms`);
  assert.match(await page.locator('[data-role=gallery-count]').textContent(), /^6,756 of 6,756 maps$/);
  // Only the rows in view are in the page.
  assert.ok((await cards(page).count()) < 200, 'the grid is virtualized');

  await page.locator('[data-role=gallery-genus]').fill('3');
  await page.locator('[data-role=gallery-realized]').check();
  const counted = await page.locator('[data-role=gallery-count]').textContent();
  const [, shown] = /^(\d+) of/.exec(counted);
  assert.ok(Number(shown) >= 10, counted);
  for (const label of await cards(page).evaluateAll((links) => links.map((a) => a.getAttribute('aria-label')))) {
    assert.match(label, /genus 3, drawn on /);
  }
  assert.match(await page.evaluate(() => location.hash), /genus=3&realized=1/);
  // The link keeps what was read of a field, in its own spelling, and nothing it cannot read.
  await page.locator('[data-role=gallery-genus]').fill('3..4');
  assert.match(await page.evaluate(() => location.hash), /genus=3-4&realized=1/);
  await page.locator('[data-role=gallery-genus]').fill('3-');
  assert.doesNotMatch(await page.evaluate(() => location.hash), /genus=/);
  await page.locator('[data-role=gallery-genus]').fill('3');
  await page.screenshot({ path: `${RESULTS}/gallery-genus-3.png` });

  await page.getByRole('link', { name: /^R3\.1, type/ }).click();
  await drawn(page, 'R3.1');
  assert.match(await page.evaluate(() => location.hash), /mode=regmap&map=R3\.1/);
  assert.ok((await foregroundShare(page)) > 0.05, 'the canvas shows the drawn map');
  // Its fundamental polygon beside the 3D view, which opens the 2D view.
  const beside = page.locator('[data-role=tiling-beside]');
  assert.ok(await beside.isVisible(), 'the polygon is beside the 3D view');
  assert.match(await page.locator('[data-role=drawn-text]').textContent(), /R3\.1 is a regular map of type \{3,7\}: 56 triangular faces/);
  await beside.click();
  await page.locator('#tiling-view').waitFor();
  assert.match(await page.evaluate(() => location.hash), /view=tiling/);
  assert.ok(!(await beside.isVisible()), 'not beside the 2D view itself');
});

// A card's picture: its source and how much of it is not the background.
const cardPicture = (page, name) =>
  page.evaluate((map) => {
    const card = [...document.querySelectorAll('#gallery .gallery-card')].find((a) => a.getAttribute('aria-label').startsWith(`${map},`));
    const image = card?.querySelector('img.thumbnail');
    if (!image?.complete || image.naturalWidth === 0) return null;
    const canvas = document.createElement('canvas');
    [canvas.width, canvas.height] = [image.naturalWidth, image.naturalHeight];
    const context = canvas.getContext('2d');
    context.drawImage(image, 0, 0);
    const { data } = context.getImageData(0, 0, canvas.width, canvas.height);
    let drawn = 0;
    for (let i = 0; i < data.length; i += 4) drawn += Math.abs(data[i] - 0x23) + Math.abs(data[i + 1] - 0x27) + Math.abs(data[i + 2] - 0x2e) > 40;
    return { source: image.dataset.source, width: image.naturalWidth, drawn: drawn / (data.length / 4) };
  }, name);

test('Gallery: a realized map without a built thumbnail gets one rendered in a worker, cached for the next visit', async ({ page, url }) => {
  // The test's build has no thumbnails (build:gallery did not run): each realized card's picture
  // is made on demand.
  await page.goto(`${url}#mode=gallery&genus=3&realized=1&find=R3.1`);
  await page.waitForFunction(() => document.querySelector('#gallery img.thumbnail[data-source=rendered]')?.complete, null, { timeout: 60_000 });
  const rendered = await cardPicture(page, 'R3.1');
  assert.equal(rendered.source, 'rendered');
  assert.equal(rendered.width, 256);
  assert.ok(rendered.drawn > 0.05, `the picture shows the map on ${rendered.drawn} of its pixels`);
  await page.reload();
  await page.waitForFunction(() => document.querySelector('#gallery img.thumbnail')?.complete, null, { timeout: 10_000 });
  const cached = await cardPicture(page, 'R3.1');
  assert.equal(cached.source, 'cache');
  assert.ok(Math.abs(cached.drawn - rendered.drawn) < 0.01, `cached ${cached.drawn}, rendered ${rendered.drawn}`);
  await page.locator('#gallery').screenshot({ path: `${RESULTS}/gallery-rendered-thumbnail.png` });
});

test('Gallery: a copied permalink reproduces the view, camera included, in a fresh context', async ({ page, url, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: url });
  await page.goto(`${url}#mode=regmap&map=R9.3'`);
  await drawn(page, "R9.3'");
  // Turn the camera by a drag, as a user would.
  const box = await page.locator('#viewport canvas').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 140, box.y + box.height / 2 + 60, { steps: 8 });
  await page.mouse.up();
  await page.waitForTimeout(300);
  const before = await page.locator('#viewport canvas').screenshot();
  await page.locator('[data-role=copy-link]').click();
  const link = await page.evaluate(() => navigator.clipboard.readText());
  assert.match(link, /#mode=regmap&map=R9\.3%27&cam=(-?[\d.]+_){5}-?[\d.]+$/);

  const fresh = await context.browser().newContext({ viewport: { width: 1280, height: 800 } });
  try {
    const other = await fresh.newPage();
    await other.goto(link);
    await drawn(other, "R9.3'");
    const after = await other.locator('#viewport canvas').screenshot();
    await other.screenshot({ path: `${RESULTS}/gallery-permalink.png` });
    const share = await changedShare(page, before, after);
    console.log(`    permalink: ${(share * 100).toFixed(2)} % of the pixels differ`);
    assert.ok(share < 0.01, `the linked view differs in ${(share * 100).toFixed(2)} % of its pixels`);
  } finally {
    await fresh.close();
  }
});

test('Offline: after one visit the built site reloads and opens another map with the network off', async ({ context, url }) => {
  const online = await context.browser().newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'allow' });
  try {
    const page = await online.newPage();
    await page.goto(`${url}#mode=regmap&map=R3.1`);
    await drawn(page, 'R3.1');
    await page.waitForFunction(() => navigator.serviceWorker.controller !== null, null, { timeout: 30_000 });
    await page.evaluate(() => navigator.serviceWorker.ready);
    await online.setOffline(true);
    await page.reload();
    await drawn(page, 'R3.1');
    await page.evaluate(() => {
      location.hash = '#mode=regmap&map=R13.2%27';
    });
    await drawn(page, "R13.2'");
    assert.ok((await foregroundShare(page)) > 0.05, 'the canvas shows the drawn map offline');
    await page.evaluate(() => {
      location.hash = '#mode=gallery&genus=3';
    });
    await cards(page).first().waitFor();
    await page.screenshot({ path: `${RESULTS}/offline-gallery.png` });
  } finally {
    await online.close();
  }
});
