// npm run build:gallery: the gallery's thumbnails and per-map pages, rendered from the real page.
//
// Serves the static build (web/dist, from `npm run build`) with `vite preview`, opens every
// realized map of data/regmaps/realizations.json in Debian's Chromium (headless, two pages at a
// time), waits until the page has drawn it on its surface, takes the 3D view's middle square and
// encodes it as a 256 px WebP in the page itself. Writes into web/dist:
//   thumbnails/<name>.webp (R3.1' -> R3.1d.webp) and thumbnails/index.json { files },
//   maps/<name>.html: the map's <title> and Open Graph meta (name, type, genus, thumbnail), which
//     sends the browser on to the page's link of the map (keeping a link's own hash).
// Thumbnails are kept in build/gallery/ between runs; only missing ones are rendered (--force
// renders all). --site-url https://host/path/ makes og:image absolute, as link previews want.
//
// usage: node scripts/build-gallery.mjs [--force] [--only R3.1,R9.3'] [--site-url URL] [--jobs 2]
import { copyFile, mkdir, readFile, stat, writeFile } from 'node:fs/promises';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { preview } from 'vite';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
const DIST = `${ROOT}web/dist`;
const CACHE = `${ROOT}build/gallery`;
const CHROMIUM = process.env.TESSERA_CHROMIUM ?? '/usr/bin/chromium';
const SIZE = 256; // thumbnail pixels
const DRAW_TIMEOUT_MS = 120_000; // a map not drawn by then is skipped (and named)

const args = process.argv.slice(2);
const option = (name) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : undefined;
};
const force = args.includes('--force');
const only = option('--only')?.split(',');
const siteUrl = option('--site-url');
const jobs = Math.max(1, Number(option('--jobs') ?? 2));

const thumbnailFile = (name) => `${name.replace(/'$/, 'd')}.webp`;
const pageFile = (name) => `${name.replace(/'$/, 'd')}.html`;
const escapeHtml = (text) =>
  String(text).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]);

async function main() {
  if (!existsSync(`${DIST}/index.html`)) throw new Error('web/dist has no build: run `npm run build` first.');
  const manifest = JSON.parse(await readFile(`${ROOT}data/regmaps/realizations.json`, 'utf8'));
  const catalog = await readCatalog();
  const maps = manifest.maps.filter((m) => /^R\d+\.\d+'?$/.test(m.source) && (!only || only.includes(m.source)));
  await mkdir(CACHE, { recursive: true });

  const todo = [];
  for (const m of maps) if (force || !existsSync(`${CACHE}/${thumbnailFile(m.source)}`)) todo.push(m);
  console.log(`build:gallery: ${maps.length} realized maps, ${todo.length} thumbnails to render`);
  const failed = await render(todo);
  await mkdir(`${DIST}/thumbnails`, { recursive: true });
  await mkdir(`${DIST}/maps`, { recursive: true });

  const files = [];
  for (const m of maps) {
    const file = thumbnailFile(m.source);
    if (!existsSync(`${CACHE}/${file}`)) continue;
    await copyFile(`${CACHE}/${file}`, `${DIST}/thumbnails/${file}`);
    files.push(file);
  }
  await writeFile(`${DIST}/thumbnails/index.json`, `${JSON.stringify({ files })}\n`);
  for (const m of maps) await writeFile(`${DIST}/maps/${pageFile(m.source)}`, mapPage(m, catalog.get(m.source), files.includes(thumbnailFile(m.source))));
  console.log(`build:gallery: ${files.length} thumbnails and ${maps.length} map pages in web/dist`);
  if (failed.length > 0) {
    console.log(`build:gallery: not drawn: ${failed.join(', ')}`);
    process.exitCode = 1;
  }
}

// Catalog rows by name, duals too: { p, q, genus, order }.
async function readCatalog() {
  const rows = new Map();
  for (const line of (await readFile(`${ROOT}data/regmaps/catalog_g2-101.tsv`, 'utf8')).split('\n')) {
    if (line.startsWith('#') || !line.trim()) continue;
    const [name, genus, p, q, , order] = line.split('\t');
    rows.set(name, { p, q, genus, order });
    rows.set(`${name}'`, { p: q, q: p, genus, order });
  }
  return rows;
}

function mapPage(m, row, hasThumbnail) {
  const link = `#mode=regmap&map=${encodeURIComponent(m.source)}`;
  const title = row ? `${m.source} {${row.p},${row.q}}, genus ${row.genus}` : m.source;
  const description = `The regular map ${m.source}${row ? ` of type {${row.p},${row.q}}, genus ${row.genus}, |G| ${row.order},` : ''} drawn on the regular surface of ${m.target}, in Tessera.`;
  const image = hasThumbnail ? `${siteUrl ? new URL('thumbnails/', siteUrl).href : '../thumbnails/'}${thumbnailFile(m.source)}` : null;
  return [
    '<!doctype html>',
    '<html lang="en">',
    '<head>',
    '<meta charset="utf-8" />',
    `<title>${escapeHtml(title)} · Tessera</title>`,
    `<meta name="description" content="${escapeHtml(description)}" />`,
    `<meta property="og:title" content="${escapeHtml(title)}" />`,
    `<meta property="og:description" content="${escapeHtml(description)}" />`,
    '<meta property="og:type" content="website" />',
    image ? `<meta property="og:image" content="${escapeHtml(image)}" />` : '',
    `<meta http-equiv="refresh" content="0; url=../${escapeHtml(link)}" />`,
    `<script>location.replace('../' + (location.hash.length > 1 ? location.hash : ${JSON.stringify(link)}));</script>`,
    '</head>',
    `<body><p><a href="../${escapeHtml(link)}">${escapeHtml(title)}</a></p></body>`,
    '</html>',
    '',
  ]
    .filter(Boolean)
    .join('\n');
}

async function render(todo) {
  if (todo.length === 0) return [];
  const server = await preview({
    configFile: `${ROOT}vite.config.js`,
    preview: { port: 0, host: '127.0.0.1' },
    logLevel: 'warn',
  });
  const url = server.resolvedUrls.local[0];
  const browser = await chromium.launch({
    executablePath: CHROMIUM,
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--no-first-run'],
  });
  const failed = [];
  const queue = [...todo];
  const started = Date.now();
  let done = 0;
  const worker = async () => {
    let page = null;
    for (let m = queue.shift(); m; m = queue.shift()) {
      try {
        page ??= await openPage(browser, url);
        await drawOn(page, m.source);
        await writeFile(`${CACHE}/${thumbnailFile(m.source)}`, await thumbnail(page));
      } catch (error) {
        failed.push(m.source);
        console.log(`build:gallery: ${m.source}: ${error.message.split('\n')[0]}`);
        await page?.close().catch(() => {});
        page = null;
      }
      done++;
      if (done % 25 === 0 || done === todo.length) {
        console.log(`build:gallery: ${done}/${todo.length} rendered, ${((Date.now() - started) / 1000).toFixed(0)} s`);
      }
    }
    await page?.close().catch(() => {});
  };
  await Promise.all(Array.from({ length: jobs }, worker));
  await browser.close();
  await new Promise((resolve) => server.httpServer.close(resolve));
  return failed;
}

async function openPage(browser, url) {
  const context = await browser.newContext({ viewport: { width: 900, height: 640 } });
  const page = await context.newPage();
  await page.goto(`${url}#mode=regmap&map=R2.1&view=tiling`);
  await page.locator('[data-role=map-name]').filter({ hasText: /\S/ }).waitFor({ timeout: DRAW_TIMEOUT_MS });
  return page;
}

// Opens the map's drawn view and waits until the view names it as drawn and no job runs.
async function drawOn(page, name) {
  await page.evaluate((hash) => {
    location.hash = hash;
  }, `#mode=regmap&map=${encodeURIComponent(name)}`);
  await page.waitForFunction(
    (map) =>
      document.querySelector('[data-role=drawn-view]')?.dataset.drawn === map &&
      document.querySelector('[data-role=progress]')?.hidden !== false,
    name,
    { timeout: DRAW_TIMEOUT_MS, polling: 100 },
  );
  await page.waitForTimeout(150); // the render after the last frame request
}

// The canvas's middle square, scaled to SIZE and encoded as WebP in the page.
async function thumbnail(page) {
  const png = await page.locator('#viewport canvas').screenshot({ style: '#viewport > :not(canvas) { visibility: hidden !important; }' });
  const base64 = await page.evaluate(
    async ({ data, size }) => {
      const image = await createImageBitmap(await (await fetch(`data:image/png;base64,${data}`)).blob());
      const side = Math.min(image.width, image.height);
      const canvas = new OffscreenCanvas(size, size);
      const context = canvas.getContext('2d');
      context.imageSmoothingQuality = 'high';
      context.drawImage(image, (image.width - side) / 2, (image.height - side) / 2, side, side, 0, 0, size, size);
      const blob = await canvas.convertToBlob({ type: 'image/webp', quality: 0.85 });
      const bytes = new Uint8Array(await blob.arrayBuffer());
      let text = '';
      for (const b of bytes) text += String.fromCharCode(b);
      return btoa(text);
    },
    { data: png.toString('base64'), size: SIZE },
  );
  return Buffer.from(base64, 'base64');
}

main().catch((error) => {
  console.error(`build:gallery: ${error.message}`);
  process.exitCode = 2;
});
