// A picture of a map drawn on its surface, as the gallery's card shows it: rendered off screen
// (an OffscreenCanvas, in the thumbnail worker) with the viewer's look, framed as the viewer
// frames it, encoded as WebP.
import { Color, Mesh, PerspectiveCamera, Scene, WebGLRenderer } from 'three';
import { segmentLines, surfaceGeometry } from './geometry.js';
import { BACKGROUND, coloredSurfaceMaterial, framing, lightScene } from './look.js';
import { MAP_EDGE_COLOR } from './palette.js';

/**
 * surface: { positions, normals, colors, triangles } (tiledSurface); edges: Float32Array, 6 per
 * segment; size: the square picture's side in pixels. Resolves with the WebP's bytes (Uint8Array).
 */
export async function renderThumbnail({ surface, edges }, size) {
  const canvas = new OffscreenCanvas(size, size);
  const renderer = new WebGLRenderer({ canvas, antialias: true });
  try {
    renderer.setSize(size, size, false);
    const scene = new Scene();
    scene.background = new Color(BACKGROUND);
    const camera = new PerspectiveCamera(40, 1, 0.01, 100);
    lightScene(scene, camera);
    const geometry = surfaceGeometry(surface);
    const material = coloredSurfaceMaterial();
    const lines = segmentLines(edges, MAP_EDGE_COLOR);
    scene.add(new Mesh(geometry, material), lines);
    const { position, target } = framing(camera, geometry.boundingSphere);
    const distance = position.distanceTo(target);
    camera.position.copy(position);
    camera.near = distance / 100;
    camera.far = distance * 100;
    camera.lookAt(target);
    camera.updateProjectionMatrix();
    renderer.render(scene, camera);
    const blob = await canvas.convertToBlob({ type: 'image/webp', quality: 0.85 });
    geometry.dispose();
    material.dispose();
    lines.geometry.dispose();
    lines.material.dispose();
    return new Uint8Array(await blob.arrayBuffer());
  } finally {
    renderer.dispose();
    renderer.forceContextLoss();
  }
}
