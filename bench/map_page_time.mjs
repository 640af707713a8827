// A map's page, timed: opens `#mode=regmap&map=NAME` (the map drawn on its surface) in fresh
// browser contexts and prints the time from navigation to the drawing on screen, per run and the
// median; with --busy N, N busy loops (other processes) hold the cores meanwhile, as on a loaded
// machine. Builds the page and serves it like the browser tests; Debian's Chromium.
//
// usage: node bench/map_page_time.mjs [--map R3.1] [--runs 5] [--busy 2]
import { fork } from 'node:child_process';
import { launchBrowser, servePage } from '../tests/browser/harness.js';

if (process.argv[2] === '--spin') {
  for (;;);
}
const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : fallback;
};
const map = option('--map', 'R3.1');
const runs = Number(option('--runs', 5));
const busy = Number(option('--busy', 0));

const { server, url } = await servePage();
const browser = await launchBrowser();
const spinners = Array.from({ length: busy }, () => fork(new URL(import.meta.url), ['--spin']));
const times = [];
try {
  for (let run = 0; run < runs; ++run) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'block' });
    const page = await context.newPage();
    await page.goto(`${url}#mode=regmap&map=${encodeURIComponent(map)}`);
    await page.waitForFunction((name) => document.querySelector('[data-role=drawn-view]')?.dataset.drawn === name, map, { timeout: 120_000 });
    const ms = await page.evaluate(() => performance.now());
    times.push(ms);
    console.log(`run ${run + 1}: ${map} drawn ${ms.toFixed(0)} ms after navigation`);
    await context.close();
  }
} finally {
  for (const spinner of spinners) spinner.kill();
}
const sorted = [...times].sort((a, b) => a - b);
console.log(`${map}: median ${sorted[Math.floor(runs / 2)].toFixed(0)} ms, max ${sorted.at(-1).toFixed(0)} ms over ${runs} fresh pages, ${busy} busy loops beside`);
await browser.close();
await server.close();
