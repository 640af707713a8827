import { COMMANDS } from '../worker/protocol.js';
import { pickMeshFile } from './file-types.js';
import { showInfo } from './info-panel.js';
import { downloadBytes, downloadName } from './download.js';
import { FieldView } from './field-view.js';
import { LayoutView } from './layout-view.js';
import { QuadMeshView } from './quad-mesh-view.js';

const DEFAULT_SAMPLE = 'genus2';

/**
 * The Quad layout mode: a mesh from a sample or a file, its figures, its export, the Field view
 * of its cross field and parameterization, the Layout view of its quad layout and the Quad mesh
 * view of the quad mesh extracted from a valid layout.
 * panel: the mode's section of the page; viewer, client (WorkerClient), jobs (Jobs), status (Status);
 * onStateChange(partial state) when what a link should share changes.
 */
export class QuadLayoutMode {
  constructor({ panel, viewer, client, jobs, status, onStateChange }) {
    Object.assign(this, { panel, viewer, client, jobs, status, onStateChange });
    this.part = (role) => panel.querySelector(`[data-role=${role}]`);
    this.mesh = null; // the mesh on screen
    this.sample = null; // its sample name, null for a file
    this.sampleNames = [];
    this.meshCount = 0; // numbers the meshes asked of the worker (see COMMANDS.sampleMesh)
    this.field = new FieldView({
      root: this.part('field-view'),
      viewer,
      status,
      request: (...args) => this.request(...args),
      onStateChange,
      onFieldChange: () => this.layout.fieldChanged(),
    });
    this.quadMesh = new QuadMeshView({
      root: this.part('quad-mesh-view'),
      viewer,
      request: (...args) => this.request(...args),
    });
    this.layout = new LayoutView({
      root: this.part('layout-view'),
      viewer,
      field: this.field,
      request: (...args) => this.request(...args),
      onLayoutChange: (layout) => this.quadMesh.setLayout(layout),
    });

    this.part('samples').addEventListener('change', (event) => this.showSample(event.target.value));
    this.part('export-glb').addEventListener('click', () => this.exportGlb());
  }

  /** Lists the samples and shows state.sample (or the default sample). */
  async start(state) {
    const reply = await this.request('Starting the geometry core', COMMANDS.sampleNames, null);
    if (!reply) return;
    this.sampleNames = reply.names;
    this.fillSampleMenu();
    await this.applyState(state);
  }

  /**
   * Shows the sample a link names; without a valid one, keeps the mesh on screen (or the default).
   * Then brings the Field view to the link's options.
   */
  async applyState(state) {
    if (this.sampleNames.length === 0) return;
    const { sample } = state;
    const known = this.sampleNames.includes(sample);
    if (known && sample !== this.sample) await this.showSample(sample);
    if (!known && !this.mesh) await this.showSample(this.defaultSample());
    if (sample && !known) {
      this.status.showNotice(`There is no sample named "${sample}".`, `Samples: ${this.sampleNames.join(', ')}.`);
    }
    if (this.mesh) await this.field.applyState(state);
  }

  defaultSample() {
    return this.sampleNames.includes(DEFAULT_SAMPLE) ? DEFAULT_SAMPLE : this.sampleNames[0];
  }

  async showSample(name) {
    const meshId = ++this.meshCount;
    const mesh = await this.request(`Building the sample "${name}"`, COMMANDS.sampleMesh, { name, meshId });
    if (mesh) this.show(mesh, { id: meshId, sample: name });
    else this.syncSampleMenu();
  }

  /** Files dropped or picked by the user: exactly one mesh file is taken. */
  async openFiles(files) {
    let file;
    try {
      file = pickMeshFile(files);
    } catch (error) {
      this.status.showError(error);
      return;
    }
    const meshId = ++this.meshCount;
    const mesh = await this.request(`Opening ${file.name}`, COMMANDS.loadMesh, { file, meshId });
    if (mesh) this.show(mesh, { id: meshId, file });
  }

  async exportGlb() {
    if (!this.mesh) return;
    const { name, info, positions, triangles, triangleFace } = this.mesh;
    const payload = {
      positions,
      triangles,
      faceIds: triangleFace,
      extras: { generator: 'Tessera', source: name, info },
    };
    const reply = await this.request('Writing the GLB file', COMMANDS.exportGlb, payload);
    if (reply) downloadBytes(reply.bytes, downloadName(name, 'glb'), 'model/gltf-binary');
  }

  request(label, command, payload) {
    return this.jobs.run(label, (onProgress) => this.client.request(command, payload, { onProgress }));
  }

  /** A mesh from the worker, with where it came from: { id, sample } or { id, file }. */
  show(mesh, source) {
    this.mesh = mesh;
    this.sample = source.sample ?? null;
    this.viewer.showMesh(mesh);
    this.field.setMesh(source);
    this.layout.setMesh(source);
    showInfo(this.part('info'), mesh);
    this.part('export-glb').disabled = false;
    this.syncSampleMenu();
    this.onStateChange({ sample: this.sample, field: false });
  }

  fillSampleMenu() {
    const placeholder = new Option('Samples…', '');
    placeholder.disabled = true;
    const options = this.sampleNames.map((name) => new Option(name, name));
    this.part('samples').replaceChildren(placeholder, ...options);
    this.part('samples').disabled = false;
  }

  syncSampleMenu() {
    this.part('samples').value = this.sample ?? '';
  }
}
