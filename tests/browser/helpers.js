// What the browser tests share: opening the page, reading it, and meshes made in code.

export const BACKGROUND_RGB = [0x23, 0x27, 0x2e]; // the viewer's background (web/src/viewer/look.js)

/** Opens the page (with an optional hash) and waits until a mesh is shown and no job runs. */
export async function openPage(page, url, hash = '') {
  await page.goto(`${url}${hash}`);
  await page.locator('[data-role=mesh-name]').filter({ hasText: /\S/ }).waitFor();
  await idle(page);
}

export async function idle(page) {
  await page.locator('[data-role=progress]').waitFor({ state: 'hidden' });
}

/** The text of one figure of the mesh's info panel, e.g. figure(page, 'genus'). */
export function figure(page, key) {
  return page.locator(`#quad-panel [data-figure=${key}]`).textContent();
}

export const meshName = (page) => page.locator('[data-role=mesh-name]').textContent();
export const message = (page) => page.locator('[data-role=message]');

/** Gives files to the page's file input, as a user picking them would. */
export async function pickFiles(page, files) {
  await page.locator('#file-input').setInputFiles(
    files.map(({ name, text, bytes }) => ({
      name,
      mimeType: 'application/octet-stream',
      buffer: bytes ?? Buffer.from(text),
    })),
  );
}

/** Drops files on the page, as a user dragging them from a file manager would. */
export async function dropFiles(page, files) {
  await page.evaluate((entries) => {
    const transfer = new DataTransfer();
    for (const { name, text } of entries) transfer.items.add(new File([text], name));
    for (const type of ['dragenter', 'dragover', 'drop']) {
      document.body.dispatchEvent(new DragEvent(type, { dataTransfer: transfer, bubbles: true, cancelable: true }));
    }
  }, files);
}

/** Chooses a sample in the samples menu and waits for it to be shown. */
export async function chooseSample(page, name) {
  await page.locator('[data-role=samples]').selectOption(name);
  await page.locator('[data-role=mesh-name]').filter({ hasText: name }).waitFor();
  await idle(page);
}

/**
 * The share of an element's pixels (by default the 3D view's canvas) that differ from a background
 * colour, from a screenshot decoded in the page itself (no image library needed here).
 */
export async function foregroundShare(page, selector = '#viewport canvas', background = BACKGROUND_RGB) {
  const [r, g, b] = background;
  const test = `(R, G, B) => Math.abs(R - ${r}) + Math.abs(G - ${g}) + Math.abs(B - ${b}) > 30`;
  const { foreground } = await pixelShares(page, { foreground: test }, selector);
  return foreground;
}

/**
 * The shares of an element's pixels that pass tests given as the source of (r, g, b) => boolean,
 * by name, e.g. { red: '(r, g, b) => r - g > 100' } -> { red: 0.012 }.
 */
export async function pixelShares(page, tests, selector = '#viewport canvas') {
  const png = await page.locator(selector).screenshot();
  return analyse(page, [png], tests, ([data], sources) => {
    const checks = Object.entries(sources).map(([name, source]) => [name, new Function(`return ${source}`)()]);
    const counts = Object.fromEntries(checks.map(([name]) => [name, 0]));
    for (let i = 0; i < data.length; i += 4) {
      for (const [name, check] of checks) if (check(data[i], data[i + 1], data[i + 2])) counts[name]++;
    }
    return Object.fromEntries(Object.entries(counts).map(([name, n]) => [name, n / (data.length / 4)]));
  });
}

/** The share of pixels that differ (by more than 60 in R + G + B) between two screenshots (PNG). */
export async function changedShare(page, before, after) {
  return analyse(page, [before, after], null, ([a, b]) => {
    if (a.length !== b.length) return 1;
    let changed = 0;
    for (let i = 0; i < a.length; i += 4) {
      if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 60) changed++;
    }
    return changed / (a.length / 4);
  });
}

// Decodes PNG screenshots in the page and runs analysis(rgbaArrays, arg) there (it travels as
// source text, so it may use only its arguments).
function analyse(page, pngs, arg, analysis) {
  return page.evaluate(
    async ({ images, source, arg }) => {
      const pixels = async (base64) => {
        const image = await createImageBitmap(await (await fetch(`data:image/png;base64,${base64}`)).blob());
        const canvas = new OffscreenCanvas(image.width, image.height);
        const context = canvas.getContext('2d');
        context.drawImage(image, 0, 0);
        return context.getImageData(0, 0, image.width, image.height).data;
      };
      const decoded = await Promise.all(images.map(pixels));
      return new Function(`return ${source}`)()(decoded, arg);
    },
    { images: pngs.map((png) => png.toString('base64')), source: analysis.toString(), arg },
  );
}

/** A unit cube of 6 quads as OBJ text: V 8, E 12, F 6, genus 0. */
export function cubeObj() {
  const corners = [];
  for (const x of [0, 1]) for (const y of [0, 1]) for (const z of [0, 1]) corners.push(`v ${x} ${y} ${z}`);
  const faces = ['1 2 4 3', '5 7 8 6', '1 5 6 2', '3 4 8 7', '1 3 7 5', '2 6 8 4'].map((f) => `f ${f}`);
  return ['# cube made by the browser tests', ...corners, ...faces, ''].join('\n');
}

/** A torus of n x m quads, each split into two triangles, as OBJ text: 2nm faces, genus 1. */
export function torusObj(n, m) {
  const lines = [];
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < m; j++) {
      const [a, b] = [(2 * Math.PI * i) / n, (2 * Math.PI * j) / m];
      const r = 2 + 0.7 * Math.cos(b);
      lines.push(`v ${r * Math.cos(a)} ${r * Math.sin(a)} ${0.7 * Math.sin(b)}`);
    }
  }
  const at = (i, j) => (i % n) * m + (j % m) + 1;
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < m; j++) {
      lines.push(`f ${at(i, j)} ${at(i + 1, j)} ${at(i + 1, j + 1)}`, `f ${at(i, j)} ${at(i + 1, j + 1)} ${at(i, j + 1)}`);
    }
  }
  lines.push('');
  return lines.join('\n');
}

/** An n x n grid of quads, each split into two triangles, as OBJ text: (n+1)^2 vertices, 2n^2 faces. */
export function gridObj(n) {
  const lines = [];
  for (let i = 0; i <= n; i++) for (let j = 0; j <= n; j++) lines.push(`v ${i / n} ${j / n} ${0.1 * Math.sin(i / 7) * Math.cos(j / 5)}`);
  const at = (i, j) => i * (n + 1) + j + 1;
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < n; j++) {
      lines.push(`f ${at(i, j)} ${at(i + 1, j)} ${at(i + 1, j + 1)}`, `f ${at(i, j)} ${at(i + 1, j + 1)} ${at(i, j + 1)}`);
    }
  }
  lines.push('');
  return lines.join('\n');
}

export const PAPER_RGB = [0xf6, 0xf3, 0xec]; // the sheet behind a tiling (.tiling-stage img in style.css)

/** Opens the page on a link of the Regular maps mode (by default its 2D tiling) and waits until a map is shown and no job runs. */
export async function openMap(page, url, hash = '#mode=regmap&view=tiling') {
  await page.goto(`${url}${hash}`);
  await page.locator('[data-role=map-name]').filter({ hasText: /\S/ }).waitFor();
  await idle(page);
}

/** Waits until the panel's title is exactly `title` (a map name) and no job runs. */
export async function mapShown(page, title) {
  const exactly = new RegExp(`^${title.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}$`);
  await page.locator('[data-role=map-name]').filter({ hasText: exactly }).waitFor();
  await idle(page);
}

/** The text of one figure of the map's panel, e.g. mapFigure(page, 'order'). */
export function mapFigure(page, key) {
  return page.locator(`#regmap-panel [data-figure=${key}]`).textContent();
}

/** The tiling image's state: decoded, its source a Blob URL, its share of drawn (non-paper) pixels. */
export async function tilingImage(page) {
  const image = page.locator('#tiling-view img');
  const { complete, naturalWidth, src } = await image.evaluate((img) => ({
    complete: img.complete,
    naturalWidth: img.naturalWidth,
    src: img.src,
  }));
  return { complete, naturalWidth, src, drawn: await foregroundShare(page, '#tiling-view img', PAPER_RGB) };
}
