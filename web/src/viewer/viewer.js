import {
  BufferAttribute,
  BufferGeometry,
  Color,
  DoubleSide,
  Group,
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
import { segmentLines, surfaceGeometry } from './geometry.js';
import { BACKGROUND, coloredSurfaceMaterial, framing, lightScene } from './look.js';
import { uvTexture } from './textures.js';

export const SCENES = Object.freeze(['mesh', 'surface']);
const SURFACE = '#d9c3a0';
const EDGES = '#1b1d22';

/**
 * The 3D view: orbit controls, rendered on demand, drawing one of two scenes (SCENES), each with the
 * camera where it was left:
 * - 'mesh': one surface mesh with optional polygon edges; drawn with it, named layers of what the
 *   stages found on it (crosses, singularities), and the mesh again with texture coordinates that
 *   show a parameterization in place of the plain one;
 * - 'surface': a smooth surface coloured per vertex (a regular map's tubified surface).
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
    lightScene(this.scene, this.camera);
    // name -> { root: Group, bounds: bounding sphere of what it shows, view: the camera left there }
    this.scenes = new Map(SCENES.map((name) => [name, { root: new Group(), bounds: null, view: null }]));
    this.shownScene = 'mesh';
    this.scene.add(this.scenes.get('mesh').root);

    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.requestRender());
    this.controls.addEventListener('end', () => this.onViewChange?.(this.view()));
    this.onViewChange = null; // (view) when the camera comes to rest where the user or a framing put it
    this.linkedView = null; // a link's camera, taken by the next framing instead of its own

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
    this.texturedMaterial = this.material.clone();
    this.texturedMaterial.color.set('#ffffff');
    this.surface = null;
    this.edges = null;
    this.wireframe = false;
    this.uvSurface = null; // the mesh as separate corners with texture coordinates
    this.texture = 'off';
    this.covered = false; // a layer (the patches of a layout) draws the surface in its place
    this.layers = new Map(); // name -> object
    this.coloredMaterial = coloredSurfaceMaterial();
    this.coloredSurface = null;
    this.surfaceLines = null;

    this.renderPending = false;
    new ResizeObserver(() => this.resize(container)).observe(container);
    this.resize(container);
  }

  /** Shows a mesh from the worker ({ positions, triangles, normals, edges }) and frames it. */
  showMesh({ positions, triangles, normals, edges }) {
    this.clear();
    const geometry = surfaceGeometry({ positions, normals, triangles });
    this.surface = new Mesh(geometry, this.material);

    const edgeGeometry = new BufferGeometry();
    edgeGeometry.setAttribute('position', geometry.getAttribute('position'));
    edgeGeometry.setIndex(new BufferAttribute(edges, 1));
    this.edges = new LineSegments(edgeGeometry, this.edgeMaterial);
    this.edges.visible = this.wireframe;

    this.meshRoot().add(this.surface, this.edges);
    this.setBounds('mesh', geometry.boundingSphere);
  }

  /**
   * Shows a surface coloured per vertex ({ positions, normals, colors, triangles }) in the scene
   * 'surface' and frames it there; null removes it.
   */
  showColoredSurface(surface) {
    remove(this.coloredSurface);
    this.coloredSurface = null;
    if (!surface) return this.setBounds('surface', null);
    const geometry = surfaceGeometry(surface);
    this.coloredSurface = new Mesh(geometry, this.coloredMaterial);
    this.scenes.get('surface').root.add(this.coloredSurface);
    this.setBounds('surface', geometry.boundingSphere);
  }

  /** Shows line segments (Float32Array, 6 per segment) over the surface scene; null removes them. */
  showSurfaceLines(segments, color = 0x000000) {
    remove(this.surfaceLines, { withMaterial: true });
    this.surfaceLines = null;
    if (segments) {
      this.surfaceLines = segmentLines(segments, color);
      this.scenes.get('surface').root.add(this.surfaceLines);
    }
    this.requestRender();
  }

  /** Draws the scene `name` of SCENES, with the camera where it was left (or framing what it shows). */
  showScene(name) {
    if (name === this.shownScene) return;
    const [shown, next] = [this.scenes.get(this.shownScene), this.scenes.get(name)];
    shown.view = { position: this.camera.position.clone(), target: this.controls.target.clone() };
    this.scene.remove(shown.root);
    this.scene.add(next.root);
    this.shownScene = name;
    if (next.view) this.look(next.view);
    else if (next.bounds) this.frame(next.bounds);
    this.requestRender();
  }

  meshRoot() {
    return this.scenes.get('mesh').root;
  }

  // What a scene shows has changed: frame it if it is drawn, else when it is drawn next.
  setBounds(name, bounds) {
    const scene = this.scenes.get(name);
    scene.bounds = bounds;
    scene.view = null;
    if (name === this.shownScene && bounds) this.frame(bounds);
    this.requestRender();
  }

  /** 'flat': one normal per triangle; 'smooth': interpolated vertex normals. */
  setShading(shading) {
    for (const material of [this.material, this.texturedMaterial]) {
      material.flatShading = shading === 'flat';
      material.needsUpdate = true;
    }
    this.requestRender();
  }

  /** Shows `object` as the layer `name` in place of the layer's previous object; null removes it. */
  setLayer(name, object) {
    remove(this.layers.get(name), { withMaterial: true });
    this.layers.delete(name);
    if (object) {
      this.layers.set(name, object);
      this.meshRoot().add(object);
    }
    this.requestRender();
  }

  setLayerVisible(name, visible) {
    const layer = this.layers.get(name);
    if (layer) layer.visible = visible;
    this.requestRender();
  }

  /**
   * The shown mesh as separate corners { positions, normals (3 per corner), uv (2 per corner) },
   * drawn with the texture of setTexture in place of the plain surface; null removes it.
   */
  setUvSurface(corners) {
    remove(this.uvSurface);
    this.uvSurface = null;
    if (corners) {
      this.uvSurface = new Mesh(surfaceGeometry(corners), this.texturedMaterial);
      this.meshRoot().add(this.uvSurface);
    }
    this.showTexture();
  }

  /** 'off', or a kind of UV_TEXTURES (textures.js) for the surface with texture coordinates. */
  setTexture(kind) {
    this.texture = kind;
    if (kind !== 'off') {
      this.texturedMaterial.map = uvTexture(kind, this.renderer.capabilities.getMaxAnisotropy());
      this.texturedMaterial.needsUpdate = true;
    }
    this.showTexture();
  }

  showTexture() {
    const textured = this.uvSurface !== null && this.texture !== 'off' && !this.covered;
    if (this.uvSurface) this.uvSurface.visible = textured;
    if (this.surface) this.surface.visible = !textured && !this.covered;
    this.requestRender();
  }

  /** Whether a layer covers the surface (the plain and the textured one are then hidden). */
  setSurfaceCovered(covered) {
    this.covered = covered;
    this.showTexture();
  }

  setWireframe(visible) {
    this.wireframe = visible;
    if (this.edges) this.edges.visible = visible;
    this.requestRender();
  }

  /** Removes the mesh and everything drawn with it. */
  clear() {
    for (const object of [this.surface, this.edges]) remove(object);
    this.surface = null;
    this.edges = null;
    for (const name of [...this.layers.keys()]) this.setLayer(name, null);
    this.covered = false;
    this.setUvSurface(null);
  }

  /** The camera as a link keeps it: { position: [x, y, z], target: [x, y, z] }, rounded to 1e-4. */
  view() {
    const rounded = (v) => [v.x, v.y, v.z].map((c) => Math.round(c * 10000) / 10000);
    return { position: rounded(this.camera.position), target: rounded(this.controls.target) };
  }

  /**
   * A link's camera ({ position, target } as view() gives them; null for none): applied now when
   * the scene on screen shows something, else by the next framing in place of its own.
   */
  setLinkedView(view) {
    this.linkedView = view;
    if (view && this.scenes.get(this.shownScene).bounds) this.frame(null);
  }

  /** Turns the camera about its target by itself (true) or stops it. */
  setAutoRotate(on) {
    const was = this.controls.autoRotate;
    this.controls.autoRotate = on;
    if (on && !was) this.spin();
  }

  spin() {
    if (!this.controls.autoRotate) return;
    requestAnimationFrame(() => {
      this.controls.update();
      this.spin();
    });
  }

  // Puts the camera where the bounding sphere just fits the narrower of the two view angles, or
  // where a link put it (see setLinkedView).
  frame(bounds) {
    if (this.linkedView) {
      const { position, target } = this.linkedView;
      this.linkedView = null;
      this.look({ position: new Vector3(...position), target: new Vector3(...target) });
    } else {
      this.fit(bounds);
    }
    this.onViewChange?.(this.view());
  }

  fit(bounds) {
    this.look(framing(this.camera, bounds));
  }

  // Puts the camera at `position` looking at `target`, with near and far planes for that distance.
  look({ position, target }) {
    const distance = position.distanceTo(target);
    this.camera.position.copy(position);
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(target);
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

function remove(object, { withMaterial = false } = {}) {
  if (!object) return;
  object.removeFromParent();
  object.geometry.dispose();
  if (withMaterial) object.material.dispose();
  object.dispose?.(); // the per-instance buffers of an InstancedMesh
}
