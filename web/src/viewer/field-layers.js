// Three.js objects for the cross field: the crosses as line segments and the singularities as
// spheres coloured by valence. Each object owns its geometry and material.
import { Color, InstancedMesh, Matrix4, MeshStandardMaterial, SphereGeometry } from 'three';
import { segmentLines } from './geometry.js';
import { valenceColor } from './palette.js';

export const CROSS_COLOR = '#26324a';

/** Line segments from pairs of points (Float32Array, 6 numbers per segment). */
export function crossLines(glyphs) {
  return segmentLines(glyphs, CROSS_COLOR);
}

/** A sphere of `radius` at each point (Float32Array, 3 per point) in the colour of its valence. */
export function singularityMarkers(positions, valences, radius) {
  const markers = new InstancedMesh(
    new SphereGeometry(1, 20, 14),
    new MeshStandardMaterial({ roughness: 0.45, metalness: 0 }),
    valences.length,
  );
  const place = new Matrix4();
  valences.forEach((valence, i) => {
    place.makeScale(radius, radius, radius).setPosition(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
    markers.setMatrixAt(i, place);
    markers.setColorAt(i, new Color(valenceColor(valence)));
  });
  markers.computeBoundingSphere();
  return markers;
}
