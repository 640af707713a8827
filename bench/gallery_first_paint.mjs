// The gallery's first paint: opens the static build (web/dist, `npm run build` and
// `npm run build:gallery` first) served under a sub-path by a plain static file server, in fresh
// browser contexts (a first visit: nothing cached), and prints per run the time from navigation
// to the first frame that shows gallery cards, the first contentful paint, and the bytes fetched
// before it; then the median.
//
// usage: node bench/gallery_first_paint.mjs [--runs 10] [--path /tessera/]
import { createReadStream, existsSync, statSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join, normalize } from 'node:path';
import { ROOT, launchBrowser } from '../tests/browser/harness.js';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : fallback;
};
const runs = Number(option('--runs', 10));
const prefix = option('--path', '/tessera/');
const DIST = `${ROOT}web/dist`;
if (!existsSync(`${DIST}/index.html`)) throw new Error('no web/dist: run npm run build (and npm run build:gallery) first');

const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.json': 'application/json', '.wasm': 'application/wasm', '.webp': 'image/webp', '.png': 'image/png', '.svg': 'image/svg+xml' };
// Files as they are, no compression (as the simplest static host serves them).
const server = createServer((request, response) => {
  const path = decodeURIComponent(new URL(request.url, 'http://host').pathname);
  if (!path.startsWith(prefix)) return response.writeHead(404).end();
  let file = normalize(join(DIST, path.slice(prefix.length)));
  if (!file.startsWith(DIST)) return response.writeHead(403).end();
  if (existsSync(file) && statSync(file).isDirectory()) file = join(file, 'index.html');
  if (!existsSync(file)) return response.writeHead(404).end();
  response.writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'application/octet-stream' });
  createReadStream(file).pipe(response);
});
await new Promise((listening) => server.listen(0, '127.0.0.1', listening));
const url = `http://127.0.0.1:${server.address().port}${prefix}#mode=gallery&realized=1`;

// In the page before its scripts: the time of the first frame after the first card exists.
const watchCards = () => {
  const observer = new MutationObserver(() => {
    if (!document.querySelector('.gallery-card')) return;
    observer.disconnect();
    requestAnimationFrame(() => {
      window.__cardsPainted = performance.now();
    });
  });
  observer.observe(document, { childList: true, subtree: true });
};

const browser = await launchBrowser();
const results = [];
for (let run = 0; run < runs; ++run) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'block' });
  const page = await context.newPage();
  await page.addInitScript(watchCards);
  await page.goto(url);
  await page.waitForFunction(() => window.__cardsPainted !== undefined, null, { timeout: 30_000 });
  const r = await page.evaluate(() => {
    const painted = window.__cardsPainted;
    const fcp = performance.getEntriesByName('first-contentful-paint')[0]?.startTime ?? NaN;
    const bytes = performance
      .getEntriesByType('resource')
      .filter((e) => e.responseEnd <= painted)
      .reduce((sum, e) => sum + e.encodedBodySize, 0);
    return { painted, fcp, bytes, cards: document.querySelectorAll('.gallery-card').length };
  });
  results.push(r);
  console.log(`run ${run + 1}: cards painted at ${r.painted.toFixed(0)} ms (${r.cards} cards), first contentful paint ${r.fcp.toFixed(0)} ms, ${(r.bytes / 1024).toFixed(0)} kB fetched before`);
  await context.close();
}
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
console.log(`gallery first paint: median ${median(results.map((r) => r.painted)).toFixed(0)} ms, max ${Math.max(...results.map((r) => r.painted)).toFixed(0)} ms over ${runs} first visits (${prefix}, uncompressed static server)`);
await browser.close();
server.close();
