// Three.js geometry from the typed arrays the worker sends, one way for every layer and scene.
import { BufferAttribute, BufferGeometry, LineBasicMaterial, LineSegments } from 'three';

/**
 * A triangle surface: positions and normals (3 per vertex), with optional per-vertex colors (3)
 * and uv (2), and optional triangles (3 vertex indices each; none: every 3 vertices make one).
 * Its bounding sphere is computed.
 */
export function surfaceGeometry({ positions, normals, colors, uv, triangles }) {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new BufferAttribute(normals, 3));
  if (colors) geometry.setAttribute('color', new BufferAttribute(colors, 3));
  if (uv) geometry.setAttribute('uv', new BufferAttribute(uv, 2));
  if (triangles) geometry.setIndex(new BufferAttribute(triangles, 1));
  geometry.computeBoundingSphere();
  return geometry;
}

/** Line segments in one colour from pairs of points (Float32Array, 6 numbers per segment). */
export function segmentLines(segments, color) {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(segments, 3));
  return new LineSegments(geometry, new LineBasicMaterial({ color }));
}
