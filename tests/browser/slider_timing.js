// node tests/browser/slider_timing.js <mesh> [alpha...]: the alpha slider in the page, timed. Opens
// the page in Debian's Chromium, picks the mesh file, computes its quad layout (alpha 5), then sets
// the slider to each alpha in turn (by default the slider's 41 positions, 0 to 20) as a user's
// release of it would. Prints per position the re-solve time the page shows (the worker's, from
// alpha to the checked layout) and, measured in the page from the release, the time until the
// figures showed the new layout (the re-solve, its display data, the messages) and until the frame
// after it was drawn (headless Chromium draws with its software renderer: slow on large meshes).
// Ends with the median and the largest of each and how many took 100 ms or more. --wait S: the
// slider is first moved S seconds after the layout, so that the worker has presolved positions
// (web/src/worker/presolve.js; the P1 rounds column says "solved ahead" for those).
// A development tool, not part of `npm test`.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { launchBrowser, servePage } from './harness.js';
import { idle, pickFiles } from './helpers.js';
import { milliseconds, releaseSliderAt, summary } from './slider_timing_util.js';

const args = process.argv.slice(2);
const waitAt = args.indexOf('--wait');
const waitSeconds = waitAt >= 0 ? Number(args[waitAt + 1]) : 0;
if (waitAt >= 0) args.splice(waitAt, 2);
const [file, ...alphaArgs] = args;
if (!file || !(waitSeconds >= 0)) {
  console.error('usage: node tests/browser/slider_timing.js <mesh> [--wait SECONDS] [alpha...]');
  process.exit(2);
}
const SLIDER = Array.from({ length: 41 }, (_, k) => k / 2);
const alphas = alphaArgs.length > 0 ? alphaArgs.map(Number) : SLIDER;
const LAYOUT_TIMEOUT_MS = 600_000;

const figure = (page, key) => page.locator(`[data-role=layout-figures] [data-figure=${key}]`).textContent();

async function shownAlpha(page, alpha) {
  await page
    .locator('[data-role=layout-figures] [data-figure=alpha]')
    .filter({ hasText: new RegExp(`^${alpha}$`) })
    .waitFor({ timeout: LAYOUT_TIMEOUT_MS });
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
  const started = Date.now();
  await page.getByRole('button', { name: 'Compute quad layout' }).click();
  await shownAlpha(page, 5);
  console.log(`${path.basename(file)}: layout at alpha 5 in ${Date.now() - started} ms, ${await figure(page, 'patches')} patches`);
  if (waitSeconds > 0) {
    console.log(`waiting ${waitSeconds} s (the worker presolves the slider's positions meanwhile)`);
    await page.waitForTimeout(1000 * waitSeconds);
  }
  console.log(' alpha  re-solve ms  shown after ms  drawn after ms  patches  P1 rounds');
  const worker = [];
  const shown = [];
  const drawn = [];
  for (const alpha of alphas) {
    const times = await page.evaluate(releaseSliderAt, {
      slider: 'alpha',
      figures: 'layout-figures',
      key: 'alpha',
      value: alpha,
      shown: String(alpha),
    });
    if (!times) {
      console.log(`${String(alpha).padStart(6)}  already shown, skipped`);
      continue;
    }
    await shownAlpha(page, alpha);
    worker.push(milliseconds(await figure(page, 'solve_seconds')));
    shown.push(times.shown);
    drawn.push(times.drawn);
    const columns = [worker, shown, drawn].map((list, k) => list.at(-1).toFixed(0).padStart([12, 15, 15][k]));
    console.log(`${String(alpha).padStart(6)} ${columns.join(' ')} ${(await figure(page, 'patches')).padStart(8)}  ${await figure(page, 'rounds')}`);
  }
  console.log(summary('re-solve (worker)', worker, 100));
  console.log(summary('shown after (page)', shown, 100));
  console.log(summary('drawn after (page)', drawn, 100));
} finally {
  await browser.close();
  await new Promise((resolve) => server.httpServer.close(resolve));
}
