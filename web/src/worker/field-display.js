// Display data of the cross field and the seamless parameterization, computed in the worker from
// the mesh's arrays and the core's per-triangle and per-corner results.

// A cross's arms reach this share of sqrt(triangle area) from the centroid: inside the triangle
// for any triangle that is not very thin.
export const GLYPH_ARM = 0.3;
// Singularity markers: this share of the mean sqrt(triangle area), a few triangles across, within
// these shares of the bounding-box diagonal: visible on fine meshes, not hiding coarse ones.
const MARKER_SIZE = 0.6;
const MARKER_MIN = 0.007;
const MARKER_MAX = 0.025;

/**
 * The crosses as line segments, two per triangle through its centroid.
 * positions: Float32Array (3V); triangles: Uint32Array (3T); directions: Float32Array (3T), a unit
 * tangent u per triangle. Returns Float32Array (12T): the points centroid -/+ arm * u, then
 * centroid -/+ arm * (n x u), with n the unit normal and arm = GLYPH_ARM * sqrt(area); a
 * degenerate triangle gets a cross of length zero.
 */
export function crossGlyphs(positions, triangles, directions) {
  const glyphs = new Float32Array(4 * triangles.length);
  for (let t = 0; t < triangles.length / 3; t++) {
    const { centroid, normal, area } = triangleShape(positions, triangles, t);
    const arm = GLYPH_ARM * Math.sqrt(area);
    const u = [directions[3 * t], directions[3 * t + 1], directions[3 * t + 2]];
    const w = cross(normal, u);
    const out = 12 * t;
    for (let k = 0; k < 3; k++) {
      glyphs[out + k] = centroid[k] - arm * u[k];
      glyphs[out + 3 + k] = centroid[k] + arm * u[k];
      glyphs[out + 6 + k] = centroid[k] - arm * w[k];
      glyphs[out + 9 + k] = centroid[k] + arm * w[k];
    }
  }
  return glyphs;
}

/**
 * The radius of the singularity markers for a mesh: MARKER_SIZE * mean sqrt(triangle area), kept
 * between MARKER_MIN and MARKER_MAX times the diagonal of the bounding box.
 */
export function markerRadius(positions, triangles) {
  const count = triangles.length / 3;
  if (count === 0) return 0;
  let sum = 0;
  for (let t = 0; t < count; t++) sum += Math.sqrt(triangleShape(positions, triangles, t).area);
  const diagonal = boxDiagonal(positions);
  return Math.min(Math.max((MARKER_SIZE * sum) / count, MARKER_MIN * diagonal), MARKER_MAX * diagonal);
}

function boxDiagonal(positions) {
  const low = [Infinity, Infinity, Infinity];
  const high = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i++) {
    low[i % 3] = Math.min(low[i % 3], positions[i]);
    high[i % 3] = Math.max(high[i % 3], positions[i]);
  }
  return Math.hypot(...high.map((x, k) => x - low[k]));
}

/** The positions of some vertices: Float32Array (3n) for the vertex numbers in `vertices`. */
export function vertexPoints(positions, vertices) {
  const points = new Float32Array(3 * vertices.length);
  vertices.forEach((v, i) => points.set(positions.subarray(3 * v, 3 * v + 3), 3 * i));
  return points;
}

/**
 * The mesh as separate corners, for attributes that jump across seams (texture coordinates).
 * positions, normals: Float32Array (3V); triangles: Uint32Array (3T).
 * Returns { positions, normals }: Float32Array (9T) each, corner k of triangle t at 3 * (3t + k).
 */
export function cornerArrays(positions, normals, triangles) {
  const cornerPositions = new Float32Array(3 * triangles.length);
  const cornerNormals = new Float32Array(3 * triangles.length);
  triangles.forEach((v, corner) => {
    cornerPositions.set(positions.subarray(3 * v, 3 * v + 3), 3 * corner);
    cornerNormals.set(normals.subarray(3 * v, 3 * v + 3), 3 * corner);
  });
  return { positions: cornerPositions, normals: cornerNormals };
}

// Centroid, unit normal (zero if degenerate) and area of triangle t.
function triangleShape(positions, triangles, t) {
  const [a, b, c] = [0, 1, 2].map((k) => 3 * triangles[3 * t + k]);
  const point = (i) => [positions[i], positions[i + 1], positions[i + 2]];
  const [pa, pb, pc] = [point(a), point(b), point(c)];
  const n = cross(
    pb.map((x, k) => x - pa[k]),
    pc.map((x, k) => x - pa[k]),
  );
  const length = Math.hypot(...n);
  return {
    centroid: pa.map((x, k) => (x + pb[k] + pc[k]) / 3),
    normal: length > 0 ? n.map((x) => x / length) : [0, 0, 0],
    area: length / 2,
  };
}

const cross = (p, q) => [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]];
