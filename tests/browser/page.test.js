// The page as a user meets it: a sample on screen, files opened, errors explained, GLB exported,
// jobs cancelled, links restored.
import { readFile } from 'node:fs/promises';
import assert from 'node:assert/strict';
import validator from 'gltf-validator';
import { RESULTS, test } from './harness.js';
import { chooseSample, cubeObj, dropFiles, figure, foregroundShare, gridObj, idle, meshName, message, openPage, pickFiles } from './helpers.js';

const number = (text) => Number(text.replaceAll(',', ''));

test('opens with the genus-2 sample on screen and its figures in the panel', async ({ page, url }) => {
  await openPage(page, url);
  assert.match(await meshName(page), /genus2/);
  assert.equal(await figure(page, 'genus'), '2');
  assert.equal(await figure(page, 'euler_characteristic'), '-2');
  assert.equal(await figure(page, 'boundary_loops'), '0');
  assert.equal(await figure(page, 'manifold'), 'yes');
  const [v, e, f] = await Promise.all(['vertices', 'edges', 'faces'].map(async (key) => number(await figure(page, key))));
  assert.equal(v - e + f, -2, `V - E + F from the panel: ${v} - ${e} + ${f}`);
  const share = await foregroundShare(page);
  assert.ok(share > 0.05, `the mesh covers ${(share * 100).toFixed(1)} % of the canvas`);
  await page.screenshot({ path: `${RESULTS}/genus2.png` });
});

test('the wireframe and shading settings change the picture', async ({ page, url }) => {
  await openPage(page, url);
  const canvas = page.locator('#viewport canvas');
  const flat = await canvas.screenshot();
  await page.getByLabel('Wireframe').check();
  const wireframe = await canvas.screenshot();
  assert.ok(!flat.equals(wireframe), 'the wireframe toggle changed nothing on screen');
  await page.screenshot({ path: `${RESULTS}/wireframe.png` });
  await page.getByLabel('Wireframe').uncheck();
  await page.getByLabel('Shading').selectOption('Smooth');
  const smooth = await canvas.screenshot();
  assert.ok(!flat.equals(smooth), 'smooth shading looks the same as flat shading');
  assert.match(await page.evaluate(() => location.hash), /shading=smooth/);
});

test('opens an OBJ dropped on the page and shows its figures', async ({ page, url }) => {
  await openPage(page, url);
  await dropFiles(page, [{ name: 'cube.obj', text: cubeObj() }]);
  await page.locator('[data-role=mesh-name]').filter({ hasText: 'cube' }).waitFor();
  await idle(page);
  assert.equal(await figure(page, 'vertices'), '8');
  assert.equal(await figure(page, 'faces'), '6');
  assert.equal(await figure(page, 'edges'), '12');
  assert.equal(await figure(page, 'face_sizes'), '6 quads');
  assert.equal(await figure(page, 'genus'), '0');
  assert.equal(await figure(page, 'euler_characteristic'), '2');
  assert.ok(!(await page.evaluate(() => location.hash)).includes('sample='), 'a file is not a shareable sample');
  assert.ok((await foregroundShare(page)) > 0.05, 'the cube is not drawn');
});

test('a broken OBJ gets a clear error and the page keeps working', async ({ page, url }) => {
  await openPage(page, url);
  const broken = cubeObj().replace('f 1 2 4 3', 'f 1 2 4 99');
  await pickFiles(page, [{ name: 'broken.obj', text: broken }]);
  const alert = page.getByRole('alert');
  await alert.waitFor();
  const text = await alert.textContent();
  assert.match(text, /could not be read/);
  assert.match(text, /99|out of range|index/i, `the error does not say what is wrong: ${text}`);
  assert.match(await meshName(page), /genus2/, 'the mesh on screen was lost');
  await page.screenshot({ path: `${RESULTS}/broken-obj.png` });
  await chooseSample(page, 'torus');
  assert.equal(await figure(page, 'genus'), '1');
  assert.ok(await message(page).isHidden(), 'the old error stays after a successful job');
});

test('malformed files of every kind get a specific error and the page stays usable', async ({ page, url }) => {
  await openPage(page, url);
  const truncatedStl = Buffer.alloc(84 + 50);
  truncatedStl.writeUInt32LE(1000, 80); // announces 1000 triangles, holds 1
  const hugePly = ['ply', 'format ascii 1.0', 'element vertex 3', 'property float x', 'property float y', 'property float z',
    'element face 4000000000', 'property list uchar int vertex_indices', 'end_header', '0 0 0', '1 0 0', '0 1 0', '3 0 1 2', ''].join('\n');
  const cases = [
    [{ name: 'empty.obj', text: '' }, /could not be read/],
    [{ name: 'truncated.stl', bytes: truncatedStl }, /could not be read/],
    [{ name: 'nan.obj', text: 'v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n' }, /unusable geometry/],
    [{ name: 'fin.obj', text: 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n' }, /connectivity/],
    [{ name: 'huge.ply', text: hugePly }, /beyond a limit/],
  ];
  for (const [file, title] of cases) {
    await pickFiles(page, [file]);
    const alert = page.getByRole('alert');
    await alert.waitFor();
    const text = await alert.textContent();
    assert.match(text, title, file.name);
    assert.ok(text.includes(file.name), `the error does not say which file: ${text}`);
    await page.getByRole('button', { name: 'Dismiss' }).click();
  }
  assert.match(await meshName(page), /genus2/, 'the mesh on screen was lost');
  await chooseSample(page, 'sphere');
  assert.equal(await figure(page, 'euler_characteristic'), '2');
});

test('files the page cannot take are explained in plain words', async ({ page, url }) => {
  await openPage(page, url);
  const gltf = { asset: { version: '2.0' }, buffers: [{ uri: 'scene.bin', byteLength: 96 }] };
  const cases = [
    [pickFiles, [{ name: 'notes.txt', text: 'hello' }], /not a mesh file/],
    [dropFiles, [{ name: 'a.obj', text: cubeObj() }, { name: 'b.obj', text: cubeObj() }], /one mesh file at a time/],
    [pickFiles, [{ name: 'scene.gltf', text: JSON.stringify(gltf) }], /scene\.bin/],
  ];
  for (const [give, files, expected] of cases) {
    await give(page, files);
    const alert = page.getByRole('alert');
    await alert.waitFor();
    assert.match(await alert.textContent(), expected);
    await page.getByRole('button', { name: 'Dismiss' }).click();
  }
  assert.match(await meshName(page), /genus2/);
});

test('exports a GLB that gltf-validator accepts with 0 errors', async ({ page, url }) => {
  await openPage(page, url);
  await pickFiles(page, [{ name: 'cube.obj', text: cubeObj() }]);
  await page.locator('[data-role=mesh-name]').filter({ hasText: 'cube' }).waitFor();
  await idle(page);
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Export GLB' }).click()]);
  assert.equal(download.suggestedFilename(), 'cube.glb');
  const path = `${RESULTS}/cube.glb`;
  await download.saveAs(path);
  const report = await validator.validateBytes(new Uint8Array(await readFile(path)));
  assert.equal(report.issues.numErrors, 0, JSON.stringify(report.issues.messages.slice(0, 5)));
  assert.equal(report.info.totalTriangleCount, 12);
});

test('Cancel stops a long job and the next job runs', async ({ page, url }) => {
  await openPage(page, url);
  await pickFiles(page, [{ name: 'big-grid.obj', text: gridObj(500) }]);
  await page.getByRole('button', { name: 'Cancel' }).click();
  await page.getByRole('status').filter({ hasText: 'Cancelled.' }).waitFor();
  assert.ok(await page.locator('[data-role=progress]').isHidden());
  assert.match(await meshName(page), /genus2/, 'the mesh on screen was lost');
  await chooseSample(page, 'torus');
  assert.equal(await figure(page, 'genus'), '1');
});

test('a link restores the sample and the view; a bad link falls back to the default', async ({ page, url }) => {
  await openPage(page, url, '#mode=quad&sample=torus&shading=smooth&wireframe=1');
  assert.match(await meshName(page), /torus/);
  assert.ok(await page.getByLabel('Wireframe').isChecked());
  assert.equal(await page.getByLabel('Shading').inputValue(), 'Smooth');
  await chooseSample(page, 'sphere');
  assert.match(await page.evaluate(() => location.hash), /sample=sphere/);

  await page.goto('about:blank');
  await openPage(page, url, '#sample=%3Cimg%20src%3Dx%3E&zoom=3');
  assert.match(await meshName(page), /genus2/);
  const notice = page.getByRole('status').filter({ hasText: 'Parts of the link were ignored.' });
  assert.match(await notice.textContent(), /zoom/);
});

test('a core that cannot be loaded is reported, and the page recovers once it can be', async ({ page, url }) => {
  await page.route('**/wasm/tessera.mjs', (route) => route.abort());
  await page.goto(url);
  const alert = page.getByRole('alert');
  await alert.waitFor();
  assert.match(await alert.textContent(), /geometry core .* could not be started/);
  await page.unroute('**/wasm/tessera.mjs');
  await pickFiles(page, [{ name: 'cube.obj', text: cubeObj() }]);
  await page.locator('[data-role=mesh-name]').filter({ hasText: 'cube' }).waitFor();
  assert.equal(await figure(page, 'faces'), '6');
});

test('a trap inside the core is reported and the next job gets a fresh core', async ({ page, url }) => {
  // The real module, with one extra sample whose call aborts the instance as a failing wasm module
  // does: it throws a RuntimeError, and every later call on that instance throws too.
  const trapping = `
    const real = await import(new URL('tessera.mjs?real', import.meta.url).href);
    export default async function createTessera(options) {
      const module = await real.default(options);
      let aborted = false;
      const call = (fn) => (...args) => {
        if (aborted) throw new WebAssembly.RuntimeError('program has already aborted');
        return fn(...args);
      };
      return {
        sampleNames: call(() => [...module.sampleNames(), 'trap']),
        sampleMesh: call((name) => {
          if (name !== 'trap') return module.sampleMesh(name);
          aborted = true;
          throw new WebAssembly.RuntimeError('unreachable executed');
        }),
        loadMesh: call((bytes, fileName) => module.loadMesh(bytes, fileName)),
        exportGlb: call((payload) => module.exportGlb(payload)),
      };
    }`;
  await page.route('**/wasm/tessera.mjs', (route) => route.fulfill({ contentType: 'text/javascript', body: trapping }));
  await openPage(page, url);
  await page.locator('[data-role=samples]').selectOption('trap');
  const alert = page.getByRole('alert');
  await alert.waitFor();
  assert.match(await alert.textContent(), /The computation stopped.*unreachable executed/s);
  assert.match(await meshName(page), /genus2/, 'the mesh on screen was lost');
  await chooseSample(page, 'torus');
  assert.equal(await figure(page, 'genus'), '1');
});
