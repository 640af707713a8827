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
 * With recolor(tile) -> [r, g, b], also `recolored`: the same split mesh's colours by recolor (a
 * coarser colouring of the same tiles, such as orbits of faces), without a second mesh.
 */
export function tiledSurface({ positions, triangles, triangleFace, tile }, color = quarterTubeColor, recolor = null) {
  const normals = vertexNormals(positions, triangles);
  const { split, source, tileOf } = splitByTile(positions.length / 3, triangles, triangleFace, tile);
  const out = {
    positions: new Float32Array(3 * source.length),
    normals: new Float32Array(3 * source.length),
    colors: new Float32Array(3 * source.length),
    triangles: split,
  };
  for (let w = 0; w < source.length; w++) {
    for (let k = 0; k < 3; k++) {
      out.positions[3 * w + k] = positions[3 * source[w] + k];
      out.normals[3 * w + k] = normals[3 * source[w] + k];
    }
  }
  out.colors = tileColors(tileOf, color);
  if (recolor) out.recolored = tileColors(tileOf, recolor);
  return out;
}

// Per split vertex, the colour of its tile (3 floats), each tile's colour computed once.
function tileColors(tileOf, color) {
  const colorOf = new Map();
  const colors = new Float32Array(3 * tileOf.length);
  for (let w = 0; w < tileOf.length; w++) {
    if (!colorOf.has(tileOf[w])) colorOf.set(tileOf[w], color(tileOf[w]));
    colors.set(colorOf.get(tileOf[w]), 3 * w);
  }
  return colors;
}

// The triangles over one vertex per (vertex, quarter tube) pair: split (3T), and for each new
// vertex, numbered in the order the corners first reach it, its source vertex and its quarter
// tube. The copies of a vertex are a list (first, next), short: a vertex is in few tiles.
function splitByTile(vertexCount, triangles, triangleFace, tile) {
  const first = new Int32Array(vertexCount).fill(-1);
  const next = new Int32Array(triangles.length);
  const source = new Uint32Array(triangles.length);
  const tileOf = new Int32Array(triangles.length);
  const split = new Uint32Array(triangles.length);
  let count = 0;
  for (let corner = 0; corner < triangles.length; corner++) {
    const v = triangles[corner];
    const t = tile[triangleFace[Math.floor(corner / 3)]];
    let w = first[v];
    while (w >= 0 && tileOf[w] !== t) w = next[w];
    if (w < 0) {
      w = count++;
      source[w] = v;
      tileOf[w] = t;
      next[w] = first[v];
      first[v] = w;
    }
    split[corner] = w;
  }
  return { split, source: source.subarray(0, count), tileOf: tileOf.subarray(0, count) };
}
