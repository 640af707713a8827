// Display data of a quad layout, computed in the worker from the core's arrays: the refined mesh
// split into patches (each with the core's colour, the one its GLB carries) and the arcs as line
// segments.
import { tiledSurface } from './surface-display.js';

/**
 * The arcs as line segments for LineSegments.
 * points: Float32Array (3 per point); offsets: Uint32Array (arcs + 1), arc i the points
 * offsets[i] .. offsets[i + 1] - 1. Returns Float32Array, 6 numbers per segment.
 */
export function arcSegments(points, offsets) {
  let segments = 0;
  for (let i = 0; i + 1 < offsets.length; i++) segments += Math.max(0, offsets[i + 1] - offsets[i] - 1);
  const out = new Float32Array(6 * segments);
  let k = 0;
  for (let i = 0; i + 1 < offsets.length; i++) {
    for (let p = offsets[i]; p + 1 < offsets[i + 1]; p++) {
      out.set(points.subarray(3 * p, 3 * p + 6), k);
      k += 6;
    }
  }
  return out;
}

/**
 * The refined mesh { positions, triangles, triangleFace, patch } coloured by patch, with
 * patchColors (Float32Array, 3 per patch id): { positions, normals, colors, triangles } as
 * tiledSurface() makes them. A patch id without a colour (a broken layout) shows grey.
 */
export function patchSurface({ positions, triangles, triangleFace, patch }, patchColors) {
  const color = (p) => (p >= 0 && 3 * p + 3 <= patchColors.length ? [...patchColors.subarray(3 * p, 3 * p + 3)] : [0.5, 0.5, 0.5]);
  return tiledSurface({ positions, triangles, triangleFace, tile: patch }, color);
}
