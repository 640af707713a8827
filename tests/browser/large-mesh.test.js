// A mesh of 3 million triangles (issue #8): the page either loads it or refuses it up front with a
// message naming the limit; either way the tab survives and stays usable.
import assert from 'node:assert/strict';
import { mkdtemp, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { RESULTS, test } from './harness.js';
import { chooseSample, figure, idle, meshName, openPage } from './helpers.js';

/** A binary PLY of a torus as a grid of `around` x `across` quads, each split in two triangles. */
function torusPly(around, across) {
  const vertices = around * across;
  const faces = 2 * vertices;
  const header = Buffer.from(
    ['ply', 'format binary_little_endian 1.0', `element vertex ${vertices}`, 'property float x', 'property float y',
      'property float z', `element face ${faces}`, 'property list uchar int vertex_indices', 'end_header', ''].join('\n'),
  );
  const body = Buffer.alloc(vertices * 12 + faces * 13);
  let at = 0;
  for (let i = 0; i < around; i++) {
    const u = (2 * Math.PI * i) / around;
    for (let j = 0; j < across; j++) {
      const v = (2 * Math.PI * j) / across;
      const ring = 3 + Math.cos(v);
      at = body.writeFloatLE(ring * Math.cos(u), at);
      at = body.writeFloatLE(ring * Math.sin(u), at);
      at = body.writeFloatLE(Math.sin(v), at);
    }
  }
  const index = (i, j) => (i % around) * across + (j % across);
  for (let i = 0; i < around; i++) {
    for (let j = 0; j < across; j++) {
      for (const triangle of [[index(i, j), index(i + 1, j), index(i + 1, j + 1)], [index(i, j), index(i + 1, j + 1), index(i, j + 1)]]) {
        at = body.writeUInt8(3, at);
        for (const corner of triangle) at = body.writeInt32LE(corner, at);
      }
    }
  }
  return Buffer.concat([header, body]);
}

test('a 3-million-triangle mesh loads or is refused by a named limit, and the tab survives', async ({ page, url }) => {
  let crashed = false;
  page.on('crash', () => {
    crashed = true;
  });
  await openPage(page, url);
  const path = join(await mkdtemp(join(tmpdir(), 'tessera-')), 'big-torus.ply');
  await writeFile(path, torusPly(1500, 1000));
  await page.locator('#file-input').setInputFiles(path);
  await page.waitForFunction(
    () => document.querySelector('[data-role=mesh-name]')?.textContent.includes('big-torus') || document.querySelector('[role=alert]'),
    null,
    { timeout: 80_000, polling: 500 },
  );
  const alert = page.getByRole('alert');
  if (await alert.isVisible()) {
    assert.match(await alert.textContent(), /limit/, 'a refusal must name the limit');
    await page.getByRole('button', { name: 'Dismiss' }).click();
  } else {
    await idle(page);
    assert.equal(await figure(page, 'faces'), (3_000_000).toLocaleString('en-US'));
    assert.equal(await figure(page, 'genus'), '1');
    await page.screenshot({ path: `${RESULTS}/big-torus.png` });
  }
  assert.ok(!crashed, 'the tab crashed');
  await chooseSample(page, 'sphere');
  assert.match(await meshName(page), /sphere/);
  assert.equal(await figure(page, 'euler_characteristic'), '2');
});
