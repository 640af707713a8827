// The Quad mesh view of the Quad layout mode (thesis Ch. 8): the quad mesh of a valid layout
// computed in the worker, drawn coloured by patch with its edges, remeshed from the count slider
// on what the worker keeps, exported as OBJ and GLB.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { RESULTS, test } from './harness.js';
import { idle, message, openPage, pixelShares } from './helpers.js';

const quadFigure = (page, key) => page.locator(`[data-role=quad-mesh-figures] [data-figure=${key}]`).textContent();
const view = (page) => page.locator('[data-role=quad-mesh-view]');
const slider = (page) => page.locator('[data-role=quad-count]');
// The quads' edges (#111318, as the arcs) are the only near-black pixels: the background is
// #23272e, the patches are lit colours.
const EDGES = { edges: '(r, g, b) => r < 28 && g < 30 && b < 34' };

/** Waits until the quad mesh for `target` quads is in the panel and no job runs. */
async function remeshed(page, target) {
  await page.locator('[data-role=quad-mesh-figures] [data-figure=target]').filter({ hasText: new RegExp(`^${target.toLocaleString('en-US')}$`) }).waitFor();
  await idle(page);
}

/** The slider position whose count the page shows is `target` (read from the page's own scale). */
async function moveSlider(page, target) {
  const position = await slider(page).evaluate((input, wanted) => {
    for (let p = Number(input.min); p <= Number(input.max); p++) {
      input.value = String(p);
      input.dispatchEvent(new Event('input'));
      if (document.querySelector('[data-role=quad-count-value]').textContent === String(wanted)) return p;
    }
    return null;
  }, target);
  assert.notEqual(position, null, `no slider position shows ${target}`);
  await slider(page).fill(String(position));
}

test('Quad mesh: the sphere layout gives a quad mesh drawn with its edges; the slider remeshes; OBJ and GLB download', async ({ page, url }) => {
  await openPage(page, url, '#sample=sphere');
  assert.ok(await view(page).isHidden(), 'the Quad mesh view shows before a layout');
  await page.getByRole('button', { name: 'Compute quad layout' }).click();
  await page.locator('[data-role=layout-figures] [data-figure=alpha]').filter({ hasText: /^5$/ }).waitFor();
  await idle(page);
  await view(page).waitFor();
  const layoutEdges = (await pixelShares(page, EDGES)).edges;

  // The slider to 400 quads, then compute.
  await moveSlider(page, 400);
  await page.getByRole('button', { name: 'Compute quad mesh' }).click();
  await remeshed(page, 400);
  assert.ok(await message(page).isHidden(), 'an error was shown');
  const coarse = Number((await quadFigure(page, 'quads')).replace(/,/g, ''));
  assert.ok(Math.abs(coarse - 400) <= 0.25 * 400, `${coarse} quads for 400`);
  assert.match(await page.locator('[data-role=quad-mesh-verdict]').textContent(), new RegExp(`^${coarse} quads, \\d+ irregular vertices: conforming, no flips(, \\d+ quads? with a scaled Jacobian ≤ 0)?$`));
  assert.equal(await quadFigure(page, 'patches'), await page.locator('[data-role=layout-figures] [data-figure=patches]').textContent());
  const coarseEdges = (await pixelShares(page, EDGES)).edges;
  assert.ok(coarseEdges > 2 * layoutEdges, `the quads' edges are drawn: ${coarseEdges} of the view against the layout's arcs ${layoutEdges}`);
  await page.screenshot({ path: `${RESULTS}/quad-mesh-sphere-400.png` });

  // The slider to 2,000 quads: a finer mesh, more edges on screen, from the prep the worker kept.
  const stages = [];
  await page.exposeFunction('reportStage', (text) => stages.push(text));
  await page.evaluate(() => {
    const stage = document.querySelector('#status [data-role=stage]');
    new MutationObserver(() => window.reportStage(stage.textContent)).observe(stage, { childList: true, characterData: true, subtree: true });
  });
  await moveSlider(page, 2000);
  await remeshed(page, 2000);
  const fine = Number((await quadFigure(page, 'quads')).replace(/,/g, ''));
  assert.ok(Math.abs(fine - 2000) <= 0.25 * 2000, `${fine} quads for 2,000`);
  assert.match(await quadFigure(page, 'time_prep'), /./);
  assert.match(await page.locator('[data-role=quad-mesh-figures]').textContent(), /Time: prep \(kept\)/);
  assert.ok(!stages.some((text) => /fresh core|separatrices|Unfolding|Cancelled/.test(text)), `stages: ${[...new Set(stages)].join(' | ')}`);
  const fineEdges = (await pixelShares(page, EDGES)).edges;
  assert.ok(fineEdges > 1.5 * coarseEdges, `more edges at ${fine} quads (${fineEdges}) than at ${coarse} (${coarseEdges})`);
  await page.screenshot({ path: `${RESULTS}/quad-mesh-sphere-2000.png` });

  // Wireframe off: the edges go, the coloured quads stay.
  await page.locator('[data-role=quad-wireframe]').uncheck();
  const bare = (await pixelShares(page, EDGES)).edges;
  assert.ok(bare < 0.3 * fineEdges, `edges still drawn without the wireframe: ${bare}`);
  await page.locator('[data-role=quad-wireframe]').check();

  const [obj] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Export the quad mesh as OBJ' }).click()]);
  assert.equal(obj.suggestedFilename(), 'sphere-quads.obj');
  await obj.saveAs(`${RESULTS}/sphere-quads.obj`);
  const faces = readFileSync(`${RESULTS}/sphere-quads.obj`, 'latin1')
    .split('\n')
    .filter((line) => line.startsWith('f '));
  assert.equal(faces.length, fine);
  assert.ok(faces.every((line) => line.trim().split(/\s+/).length === 5), 'all quads');
  const [glb] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Export the quad mesh as GLB' }).click()]);
  assert.equal(glb.suggestedFilename(), 'sphere-quads.glb');
  await glb.saveAs(`${RESULTS}/sphere-quads.glb`);
  const bytes = readFileSync(`${RESULTS}/sphere-quads.glb`);
  assert.equal(bytes.subarray(0, 4).toString('latin1'), 'glTF');
  assert.match(bytes.toString('latin1'), /_PATCH/);

  // A new alpha lays out again: the quad mesh of the old layout goes.
  await page.locator('[data-role=alpha]').fill('10');
  await page.locator('[data-role=layout-figures] [data-figure=alpha]').filter({ hasText: /^10$/ }).waitFor();
  await idle(page);
  assert.ok(await page.locator('[data-role=quad-mesh-result]').isHidden(), 'the old quad mesh is still listed');
});

test('Quad mesh: Cancel stops a remesh, the view keeps its quad mesh, and the next count lays out again in a fresh core', async ({ page, url }) => {
  await openPage(page, url, '#sample=sphere');
  await page.getByRole('button', { name: 'Compute quad layout' }).click();
  await page.locator('[data-role=layout-figures] [data-figure=alpha]').filter({ hasText: /^5$/ }).waitFor();
  await idle(page);
  await moveSlider(page, 400);
  await page.getByRole('button', { name: 'Compute quad mesh' }).click();
  await remeshed(page, 400);
  const shown = await quadFigure(page, 'quads');

  // A move of the slider and Cancel in the same task: the remesh is stopped before it answers.
  const target = await slider(page).evaluate((input) => {
    input.value = String(Number(input.value) + 20);
    input.dispatchEvent(new Event('input'));
    input.dispatchEvent(new Event('change'));
    document.querySelector('#status [data-role=cancel]').click();
    return Number(document.querySelector('[data-role=quad-count-value]').textContent);
  });
  await page.getByText('Cancelled.').waitFor();
  await idle(page);
  assert.equal(await quadFigure(page, 'quads'), shown, 'the quad mesh on screen changed');
  assert.equal(await quadFigure(page, 'target'), '400');

  // The fresh worker has no layout: the remesh builds the mesh, field, graph and layout again.
  const stages = [];
  await page.exposeFunction('reportStage', (text) => stages.push(text));
  await page.evaluate(() => {
    const stage = document.querySelector('#status [data-role=stage]');
    new MutationObserver(() => window.reportStage(stage.textContent)).observe(stage, { childList: true, characterData: true, subtree: true });
  });
  await page.getByRole('button', { name: 'Compute quad mesh' }).click();
  await remeshed(page, target);
  assert.ok(stages.some((text) => /fresh core/.test(text)), `stages: ${[...new Set(stages)].join(' | ')}`);
  assert.ok(await message(page).isHidden(), 'an error was shown');
  const quads = Number((await quadFigure(page, 'quads')).replace(/,/g, ''));
  assert.ok(Math.abs(quads - target) <= 0.25 * target, `${quads} quads for ${target}`);
});
