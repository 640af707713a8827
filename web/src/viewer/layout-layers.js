// Three.js objects for a quad layout: the refined mesh coloured by patch and the arcs as lines
// (the singularities use field-layers.js). Each object owns its geometry and material.
import { BufferAttribute, BufferGeometry, DoubleSide, LineBasicMaterial, LineSegments, Mesh, MeshStandardMaterial } from 'three';

export const ARC_COLOR = '#111318';

/** The patches: { positions, normals, colors, triangles } from the worker (layout-display.js). */
export function patchMesh(surface) {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(surface.positions, 3));
  geometry.setAttribute('normal', new BufferAttribute(surface.normals, 3));
  geometry.setAttribute('color', new BufferAttribute(surface.colors, 3));
  geometry.setIndex(new BufferAttribute(surface.triangles, 1));
  geometry.computeBoundingSphere();
  const material = new MeshStandardMaterial({
    vertexColors: true,
    roughness: 0.7,
    metalness: 0,
    side: DoubleSide,
    flatShading: true,
    polygonOffset: true, // keeps the arcs drawn on top of the patches they bound
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  });
  return new Mesh(geometry, material);
}

/** The arcs: line segments (Float32Array, 6 numbers per segment). */
export function arcLines(segments) {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(segments, 3));
  return new LineSegments(geometry, new LineBasicMaterial({ color: ARC_COLOR }));
}
