// node tests/browser/remesh_slider_timing.js <mesh> [position...]: the Quad mesh view's count
// slider in the page, timed (issue 39: it answers within 200 ms). Opens the page in Debian's
// Chromium, picks the mesh file, computes its quad layout (alpha 5) and its first quad mesh (the
// default count: the worker makes what the count does not change), then sets the slider to each
// position in turn (by default 0 to 100 by 10, then around the default) as a user's release of it
// would. Prints per position the target, the quads, the remesh time the page shows (the worker's,
// in the core), and, measured in the page from the release, the time until the figures showed the
// new quad mesh (remesh, display data, messages, layers built) and until the frame after it was
// drawn (headless Chromium draws with its software renderer). Ends with the median and the largest
// of each and how many took 200 ms or more. A development tool, not part of `npm test`.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { launchBrowser, servePage } from './harness.js';
import { idle, pickFiles } from './helpers.js';
import { milliseconds, releaseSliderAt, summary } from './slider_timing_util.js';
import { quadCountAt } from '../../web/src/ui/quad-mesh-figures.js';

const [file, ...positionArgs] = process.argv.slice(2);
if (!file) {
  console.error('usage: node tests/browser/remesh_slider_timing.js <mesh> [position...]');
  process.exit(2);
}
const positions = positionArgs.length > 0 ? positionArgs.map(Number) : [0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 55, 57, 59, 61];
const TIMEOUT_MS = 600_000;

const figure = (page, key) => page.locator(`[data-role=quad-mesh-figures] [data-figure=${key}]`).textContent();
const shownCount = (count) => Number(count).toLocaleString('en-US');

async function remeshed(page, target) {
  const exactly = new RegExp(`^${shownCount(target)}$`);
  await page.locator('[data-role=quad-mesh-figures] [data-figure=target]').filter({ hasText: exactly }).waitFor({ timeout: TIMEOUT_MS });
  await idle(page);
}

const { server, url } = await servePage();
const browser = await launchBrowser();
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await page.goto(url);
  await idle(page);
  await pickFiles(page, [{ name: path.basename(file), bytes: readFileSync(file) }]);
  await page.locator('[data-role=mesh-name]').filter({ hasText: path.basename(file) }).waitFor();
  await idle(page);
  let started = Date.now();
  await page.getByRole('button', { name: 'Compute quad layout' }).click();
  await page.locator('[data-role=layout-figures] [data-figure=alpha]').filter({ hasText: /^5$/ }).waitFor({ timeout: TIMEOUT_MS });
  await idle(page);
  console.log(`${path.basename(file)}: layout at alpha 5 in ${Date.now() - started} ms`);
  const first = quadCountAt(await page.locator('[data-role=quad-count]').inputValue());
  started = Date.now();
  await page.getByRole('button', { name: 'Compute quad mesh' }).click();
  await remeshed(page, first);
  console.log(`first quad mesh (${first} quads asked, ${await figure(page, 'quads')} made) in ${Date.now() - started} ms, remesh ${await figure(page, 'remesh_seconds')} in the worker (prep ${await figure(page, 'time_prep')})`);
  await page.screenshot({ path: `test-results/browser/quad-mesh-${path.basename(file, path.extname(file))}.png` });

  console.log(' position  target   quads  remesh ms  shown after ms  drawn after ms');
  const worker = [];
  const shown = [];
  const drawn = [];
  for (const position of positions) {
    const target = quadCountAt(position);
    const times = await page.evaluate(releaseSliderAt, {
      slider: 'quad-count',
      figures: 'quad-mesh-figures',
      key: 'target',
      value: position,
      shown: shownCount(target),
    });
    if (!times) {
      console.log(`${String(position).padStart(9)}  ${String(target).padStart(6)}  already shown, skipped`);
      continue;
    }
    await remeshed(page, target);
    worker.push(milliseconds(await figure(page, 'remesh_seconds')));
    shown.push(times.shown);
    drawn.push(times.drawn);
    const columns = [worker, shown, drawn].map((list, k) => list.at(-1).toFixed(0).padStart([10, 15, 15][k]));
    console.log(`${String(position).padStart(9)}  ${String(target).padStart(6)}  ${(await figure(page, 'quads')).padStart(6)} ${columns.join(' ')}`);
  }
  console.log(summary('remesh (worker)', worker, 200));
  console.log(summary('shown after (page)', shown, 200));
  console.log(summary('drawn after (page)', drawn, 200));
} finally {
  await browser.close();
  await new Promise((resolve) => server.httpServer.close(resolve));
}
