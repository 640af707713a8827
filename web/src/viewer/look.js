// The 3D view's look, shared by the page's viewer (viewer.js) and the gallery's thumbnails
// (thumbnail.js): the background, the light that travels with the camera, the material of a
// surface coloured per vertex, and where the camera frames what it shows from.
import { AmbientLight, DirectionalLight, DoubleSide, MeshStandardMaterial, Vector3 } from 'three';

export const BACKGROUND = '#23272e';
const VIEW_DIRECTION = new Vector3(0.55, 0.45, 1).normalize();

/** A headlight on the camera and an ambient light, added to the scene with the camera. */
export function lightScene(scene, camera) {
  const headlight = new DirectionalLight('#ffffff', 2.2);
  headlight.position.set(0.4, 0.6, 1);
  camera.add(headlight);
  scene.add(camera, new AmbientLight('#ffffff', 0.9));
}

export const coloredSurfaceMaterial = () =>
  new MeshStandardMaterial({ vertexColors: true, roughness: 0.6, metalness: 0, side: DoubleSide });

/**
 * The camera's position and target that show the bounding sphere { center, radius } whole, seen
 * from the front, a little from the right and above, for a perspective camera (fov, aspect).
 */
export function framing({ fov, aspect }, { center, radius }) {
  const halfHeight = (fov * Math.PI) / 360;
  const halfWidth = Math.atan(Math.tan(halfHeight) * aspect);
  const distance = (radius || 1) / Math.sin(Math.min(halfHeight, halfWidth));
  return { position: center.clone().addScaledVector(VIEW_DIRECTION, distance), target: center.clone() };
}
