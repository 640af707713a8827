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
    const corners = triangles.subarray(3 * first, 3 * end);
    for (let side = 0; side < corners.length; side++) {
      if (sideCount(corners, corners[side], corners[nextCorner(side)]) > 1) continue;
      edges[count++] = corners[side];
      edges[count++] = corners[nextCorner(side)];
    }
    first = end;
  }
  return edges.slice(0, count);
}

// Corner i of a triangle list and the next corner of the same triangle bound side i.
const nextCorner = (i) => (i % 3 === 2 ? i - 2 : i + 1);

// How many sides of the triangles in `corners` join a and b, in either direction.
function sideCount(corners, a, b) {
  let count = 0;
  for (let side = 0; side < corners.length; side++) {
    const c = corners[side];
    const d = corners[nextCorner(side)];
    if ((c === a && d === b) || (c === b && d === a)) count++;
  }
  return count;
}
