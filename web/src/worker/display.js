// Display data for the viewer, computed in the worker so that large meshes never block the page.

/**
 * Area-weighted vertex normals.
 * positions: Float32Array (3V); triangles: Uint32Array (3T) -> Float32Array (3V), unit length
 * (zero for vertices of degenerate triangles only).
 */
export function vertexNormals(positions, triangles) {
  const normals = new Float32Array(positions.length);
  for (let t = 0; t < triangles.length; t += 3) {
    const a = 3 * triangles[t];
    const b = 3 * triangles[t + 1];
    const c = 3 * triangles[t + 2];
    const ux = positions[b] - positions[a];
    const uy = positions[b + 1] - positions[a + 1];
    const uz = positions[b + 2] - positions[a + 2];
    const vx = positions[c] - positions[a];
    const vy = positions[c + 1] - positions[a + 1];
    const vz = positions[c + 2] - positions[a + 2];
    const nx = uy * vz - uz * vy;
    const ny = uz * vx - ux * vz;
    const nz = ux * vy - uy * vx;
    for (const v of [a, b, c]) {
      normals[v] += nx;
      normals[v + 1] += ny;
      normals[v + 2] += nz;
    }
  }
  for (let v = 0; v < normals.length; v += 3) {
    const length = Math.hypot(normals[v], normals[v + 1], normals[v + 2]);
    if (length > 0) {
      normals[v] /= length;
      normals[v + 1] /= length;
      normals[v + 2] /= length;
    }
  }
  return normals;
}

/**
 * The edges of the original polygons, without the diagonals that triangulated them.
 * triangles: Uint32Array (3T); triangleFace: Uint32Array (T), the polygon of each triangle, the
 * triangles of one polygon one after another (as the core writes them).
 * Returns Uint32Array of vertex pairs; an edge between two polygons appears once per polygon.
 */
export function polygonEdges(triangles, triangleFace) {
  const edges = new Uint32Array(2 * triangles.length);
  let count = 0;
  for (let first = 0; first < triangleFace.length; ) {
    let end = first + 1;
    while (end < triangleFace.length && triangleFace[end] === triangleFace[first]) end++;
    for (const [a, b] of polygonBoundary(triangles, first, end)) {
      edges[count++] = a;
      edges[count++] = b;
    }
    first = end;
  }
  return edges.slice(0, count);
}

function triangleSides(triangles, t) {
  const [a, b, c] = triangles.subarray(3 * t, 3 * t + 3);
  return [
    [a, b],
    [b, c],
    [c, a],
  ];
}

// The sides of triangles [first, end) that are not shared by two of them.
function polygonBoundary(triangles, first, end) {
  if (end - first === 1) return triangleSides(triangles, first);
  const sides = [];
  for (let t = first; t < end; t++) sides.push(...triangleSides(triangles, t));
  const key = ([a, b]) => (a < b ? `${a},${b}` : `${b},${a}`);
  const uses = new Map();
  for (const side of sides) uses.set(key(side), (uses.get(key(side)) ?? 0) + 1);
  return sides.filter((side) => uses.get(key(side)) === 1);
}
