// Display data of a quad mesh from a layout (thesis Ch. 8), computed in the worker from the core's
// arrays: the quads as triangles coloured by the layout's patch (the colours of the layout's
// patches) and the quads' edges as line segments, each edge once.
import { patchSurface } from './layout-display.js';

/**
 * quads: Uint32Array (4 vertex indices per quad) -> { triangles: Uint32Array (two per quad, a b c
 * and a c d), triangleFace: Uint32Array (per triangle, its quad) }.
 */
export function quadTriangles(quads) {
  const count = Math.floor(quads.length / 4);
  const triangles = new Uint32Array(6 * count);
  const triangleFace = new Uint32Array(2 * count);
  for (let q = 0; q < count; q++) {
    const [a, b, c, d] = quads.subarray(4 * q, 4 * q + 4);
    triangles.set([a, b, c, a, c, d], 6 * q);
    triangleFace[2 * q] = q;
    triangleFace[2 * q + 1] = q;
  }
  return { triangles, triangleFace };
}

/**
 * The quad mesh { positions, quads, patch (per quad) } coloured by patch with patchColors
 * (Float32Array, 3 per patch): { positions, normals, colors, triangles } as patchSurface() makes
 * them.
 */
export function quadSurface({ positions, quads, patch }, patchColors) {
  const { triangles, triangleFace } = quadTriangles(quads);
  return patchSurface({ positions, triangles, triangleFace, patch }, patchColors);
}

/**
 * The edges of the quads, each once (an edge two quads share, and a boundary edge of one), as
 * line segments: Float32Array, 6 numbers per edge.
 */
export function quadEdges(positions, quads) {
  const vertexCount = positions.length / 3;
  const seen = new Set();
  const pairs = [];
  for (let corner = 0; corner < quads.length; corner++) {
    const a = quads[corner];
    const b = quads[corner % 4 === 3 ? corner - 3 : corner + 1];
    const key = Math.min(a, b) * vertexCount + Math.max(a, b);
    if (seen.has(key)) continue;
    seen.add(key);
    pairs.push(a, b);
  }
  const segments = new Float32Array(3 * pairs.length);
  pairs.forEach((v, i) => segments.set(positions.subarray(3 * v, 3 * v + 3), 3 * i));
  return segments;
}
