// Three.js objects for a quad layout: the refined mesh coloured by patch and the arcs as lines
// (the singularities use field-layers.js). Each object owns its geometry and material.
import { DoubleSide, Mesh, MeshStandardMaterial } from 'three';
import { segmentLines, surfaceGeometry } from './geometry.js';

export const ARC_COLOR = '#111318';

/** The patches: { positions, normals, colors, triangles } from the worker (layout-display.js). */
export function patchMesh(surface) {
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
  return new Mesh(surfaceGeometry(surface), material);
}

/** The arcs: line segments (Float32Array, 6 numbers per segment). */
export function arcLines(segments) {
  return segmentLines(segments, ARC_COLOR);
}
