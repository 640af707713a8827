// Display data of a regular surface, computed in the worker from the core's arrays: the mesh with
// its vertices split where quarter tubes meet, so that each quarter tube has its own colour while
// the shading stays smooth across the seams.
import { quarterTubeColor } from '../viewer/palette.js';
import { vertexNormals } from './display.js';

/**
 * positions: Float32Array (3V); triangles: Uint32Array (3T); triangleFace: Uint32Array (T), the
 * face of the surface mesh of each triangle; tile: Int32Array (one per face), its quarter tube.
 * Returns { positions, normals, colors } (Float32Array, 3 per vertex of the split mesh) and
 * triangles (Uint32Array, 3T, the same triangles over the split vertices). A vertex is split once
 * per quarter tube around it; its copies keep the vertex normal of the whole surface.
 * color(tile) -> [r, g, b] in 0..1: the colour of a tile, by default the core's of a quarter tube.
 */
export function tiledSurface({ positions, triangles, triangleFace, tile }, color = quarterTubeColor) {
  const normals = vertexNormals(positions, triangles);
  const { split, source, tileOf } = splitByTile(triangles, triangleFace, tile);
  const colorOf = new Map();
  const out = {
    positions: new Float32Array(3 * source.length),
    normals: new Float32Array(3 * source.length),
    colors: new Float32Array(3 * source.length),
    triangles: split,
  };
  source.forEach((v, w) => {
    if (!colorOf.has(tileOf[w])) colorOf.set(tileOf[w], color(tileOf[w]));
    out.positions.set(positions.subarray(3 * v, 3 * v + 3), 3 * w);
    out.normals.set(normals.subarray(3 * v, 3 * v + 3), 3 * w);
    out.colors.set(colorOf.get(tileOf[w]), 3 * w);
  });
  return out;
}

// The triangles over one vertex per (vertex, quarter tube) pair: split (3T), and for each new
// vertex its source vertex and its quarter tube.
function splitByTile(triangles, triangleFace, tile) {
  let tiles = 1;
  for (const t of tile) tiles = Math.max(tiles, t + 1);
  const index = new Map(); // source vertex * tiles + tile -> new vertex
  const source = [];
  const tileOf = [];
  const split = new Uint32Array(triangles.length);
  for (let corner = 0; corner < triangles.length; corner++) {
    const v = triangles[corner];
    const t = tile[triangleFace[Math.floor(corner / 3)]];
    const key = v * tiles + t;
    let w = index.get(key);
    if (w === undefined) {
      w = source.length;
      index.set(key, w);
      source.push(v);
      tileOf.push(t);
    }
    split[corner] = w;
  }
  return { split, source, tileOf };
}
