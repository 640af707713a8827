// Permalinks of random realized maps: for each of N maps of the manifest (a seeded sample), opens
// it drawn on its surface, turns the camera by a drag, takes the link the page keeps (what Copy
// link copies), opens it in a fresh browser context and compares the two pictures of the 3D view.
// Prints each map's share of differing pixels and how many stay under the threshold.
//
// usage: node bench/gallery_permalinks.mjs [--maps 50] [--seed 1] [--threshold 0.01]
// (builds the page and serves it like the browser tests; Debian's Chromium)
import { readFile } from 'node:fs/promises';
import { ROOT, launchBrowser, servePage } from '../tests/browser/harness.js';
import { changedShare } from '../tests/browser/helpers.js';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? Number(args[i + 1]) : fallback;
};
const count = option('--maps', 50);
const threshold = option('--threshold', 0.01);
let seed = option('--seed', 1);
const random = () => {
  seed = (seed * 1103515245 + 12345) % 2147483648;
  return seed / 2147483648;
};

const viewport = { width: 1280, height: 800 };

async function drawn(page, name) {
  await page.waitForFunction((map) => document.querySelector('[data-role=drawn-view]')?.dataset.drawn === map, name, {
    timeout: 120_000,
  });
  await page.locator('[data-role=progress]').waitFor({ state: 'hidden' });
  await page.waitForTimeout(300);
}

const manifest = JSON.parse(await readFile(`${ROOT}data/regmaps/realizations.json`, 'utf8'));
const pool = manifest.maps.map((m) => m.source);
const sample = [];
while (sample.length < Math.min(count, pool.length)) {
  const name = pool[Math.floor(random() * pool.length)];
  if (!sample.includes(name)) sample.push(name);
}

const { server, url } = await servePage();
const browser = await launchBrowser();
let good = 0;
const started = Date.now();
for (const name of sample) {
  const first = await browser.newContext({ viewport, serviceWorkers: 'block' });
  const second = await browser.newContext({ viewport, serviceWorkers: 'block' });
  try {
    const page = await first.newPage();
    await page.goto(`${url}#mode=regmap&map=${encodeURIComponent(name)}`);
    await drawn(page, name);
    const box = await page.locator('#viewport canvas').boundingBox();
    const x = box.x + box.width / 2 + (random() - 0.5) * 100;
    const y = box.y + box.height / 2 + (random() - 0.5) * 100;
    await page.mouse.move(x, y);
    await page.mouse.down();
    await page.mouse.move(x + 60 + random() * 120, y + (random() - 0.5) * 120, { steps: 8 });
    await page.mouse.up();
    await page.waitForTimeout(300);
    const link = await page.evaluate(() => location.href);
    const before = await page.locator('#viewport canvas').screenshot();
    const other = await second.newPage();
    await other.goto(link);
    await drawn(other, name);
    const after = await other.locator('#viewport canvas').screenshot();
    const share = await changedShare(page, before, after);
    const ok = share < threshold && /&cam=/.test(link);
    if (ok) good++;
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${name}: ${(share * 100).toFixed(2)} % of the pixels differ`);
  } catch (error) {
    console.log(`FAIL ${name}: ${error.message.split('\n')[0]}`);
  } finally {
    await first.close();
    await second.close();
  }
}
console.log(`permalinks: ${good} of ${sample.length} reproduce their view (under ${threshold * 100} % of the pixels), ${((Date.now() - started) / 1000).toFixed(0)} s`);
await browser.close();
await new Promise((resolve) => server.httpServer.close(resolve));
process.exit(good === sample.length ? 0 : 1);
