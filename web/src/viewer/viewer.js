import {
  AmbientLight,
  BufferAttribute,
  BufferGeometry,
  Color,
  DirectionalLight,
  DoubleSide,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshStandardMaterial,
  PerspectiveCamera,
  Scene,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

export const BACKGROUND = '#23272e';
const SURFACE = '#d9c3a0';
const EDGES = '#1b1d22';

/**
 * The 3D view: one surface mesh with optional polygon edges, orbit controls, rendered on demand.
 * container: an element the canvas fills; onContextLost() when the browser takes the GPU context
 * away (three.js rebuilds what it needs once the context is restored). Throws if WebGL cannot start.
 */
export class Viewer {
  constructor(container, { onContextLost }) {
    this.renderer = new WebGLRenderer({ antialias: true });
    this.renderer.setPixelRatio(window.devicePixelRatio);
    container.append(this.renderer.domElement);
    this.renderer.domElement.addEventListener('webglcontextlost', onContextLost);
    this.renderer.domElement.addEventListener('webglcontextrestored', () => this.requestRender());

    this.scene = new Scene();
    this.scene.background = new Color(BACKGROUND);
    this.camera = new PerspectiveCamera(40, 1, 0.01, 100);
    const headlight = new DirectionalLight('#ffffff', 2.2);
    headlight.position.set(0.4, 0.6, 1);
    this.camera.add(headlight);
    this.scene.add(this.camera, new AmbientLight('#ffffff', 0.9));

    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.requestRender());

    this.material = new MeshStandardMaterial({
      color: SURFACE,
      roughness: 0.75,
      metalness: 0,
      side: DoubleSide,
      flatShading: true,
      polygonOffset: true, // keeps the edges drawn on top of the faces they bound
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    });
    this.edgeMaterial = new LineBasicMaterial({ color: EDGES });
    this.surface = null;
    this.edges = null;
    this.wireframe = false;

    this.renderPending = false;
    new ResizeObserver(() => this.resize(container)).observe(container);
    this.resize(container);
  }

  /** Shows a mesh from the worker ({ positions, triangles, normals, edges }) and frames it. */
  showMesh({ positions, triangles, normals, edges }) {
    this.clear();
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(positions, 3));
    geometry.setAttribute('normal', new BufferAttribute(normals, 3));
    geometry.setIndex(new BufferAttribute(triangles, 1));
    geometry.computeBoundingSphere();
    this.surface = new Mesh(geometry, this.material);

    const edgeGeometry = new BufferGeometry();
    edgeGeometry.setAttribute('position', geometry.getAttribute('position'));
    edgeGeometry.setIndex(new BufferAttribute(edges, 1));
    this.edges = new LineSegments(edgeGeometry, this.edgeMaterial);
    this.edges.visible = this.wireframe;

    this.scene.add(this.surface, this.edges);
    this.frame(geometry.boundingSphere);
  }

  /** 'flat': one normal per triangle; 'smooth': interpolated vertex normals. */
  setShading(shading) {
    this.material.flatShading = shading === 'flat';
    this.material.needsUpdate = true;
    this.requestRender();
  }

  setWireframe(visible) {
    this.wireframe = visible;
    if (this.edges) this.edges.visible = visible;
    this.requestRender();
  }

  clear() {
    for (const object of [this.surface, this.edges]) {
      if (!object) continue;
      this.scene.remove(object);
      object.geometry.dispose();
    }
    this.surface = null;
    this.edges = null;
  }

  // Puts the camera where the bounding sphere just fits the narrower of the two view angles.
  frame({ center, radius }) {
    const halfHeight = (this.camera.fov * Math.PI) / 360;
    const halfWidth = Math.atan(Math.tan(halfHeight) * this.camera.aspect);
    const distance = (radius || 1) / Math.sin(Math.min(halfHeight, halfWidth));
    const direction = new Vector3(0.55, 0.45, 1).normalize();
    this.camera.position.copy(center).addScaledVector(direction, distance);
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
    this.requestRender();
  }

  resize(container) {
    const { clientWidth: width, clientHeight: height } = container;
    if (width === 0 || height === 0) return;
    this.renderer.setSize(width, height);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  requestRender() {
    if (this.renderPending) return;
    this.renderPending = true;
    requestAnimationFrame(() => {
      this.renderPending = false;
      this.renderer.render(this.scene, this.camera);
    });
  }
}
