// The gallery's thumbnails where the static build has none (the dev server, a build without
// `npm run build:gallery`): a worker of its own, with its own core, so that the page's jobs never
// wait for it. A request { id, map } draws the map on its surface as the Regular maps mode does
// (the manifest's pairing) and renders it (viewer/thumbnail.js); the answer is { id, bytes } (a
// WebP) or { id, error }.
import { renderThumbnail } from '../viewer/thumbnail.js';
import { drawMap, dropCore } from './core.js';
import { tiledSurface } from './surface-display.js';

const SIZE = 256; // pixels, as build:gallery's

self.onmessage = async ({ data: { id, map } }) => {
  try {
    const { positions, triangles, triangleFace, face, edges } = await drawMap(String(map), null, () => {}, 1);
    const bytes = await renderThumbnail({ surface: tiledSurface({ positions, triangles, triangleFace, tile: face }), edges }, SIZE);
    self.postMessage({ id, bytes }, [bytes.buffer]);
  } catch (error) {
    // A trap may leave the core broken: the next request starts a fresh one.
    if (typeof error?.kind !== 'string') dropCore();
    self.postMessage({ id, error: error?.message ?? String(error) });
  }
};
