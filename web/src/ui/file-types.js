import { PAGE_ERROR_KINDS, jobError } from '../worker/protocol.js';

/** The mesh formats the core reads, by file extension. */
export const MESH_EXTENSIONS = Object.freeze(['obj', 'off', 'ply', 'stl', 'glb', 'gltf']);

/** The extension of fileName in lower case, or '' when it has none. */
export function extensionOf(fileName) {
  const base = String(fileName).split(/[\\/]/).pop();
  const dot = base.lastIndexOf('.');
  return dot > 0 ? base.slice(dot + 1).toLowerCase() : '';
}

/** The mesh format of fileName ('obj', ..., 'gltf'), or null when the core cannot read it. */
export function meshFormat(fileName) {
  const extension = extensionOf(fileName);
  return MESH_EXTENSIONS.includes(extension) ? extension : null;
}

/**
 * The one mesh file among the files a user dropped or picked, or an error (kind 'unsupported')
 * that says in plain words why none can be taken.
 */
export function pickMeshFile(files) {
  const list = [...files];
  if (list.length === 0) {
    throw jobError(PAGE_ERROR_KINDS.unsupported, 'No file was given: drop or pick one mesh file.');
  }
  if (list.length > 1) {
    throw jobError(
      PAGE_ERROR_KINDS.unsupported,
      `${list.length} files were given: Tessera opens one mesh file at a time. A .gltf with a ` +
        'separate .bin buffer can be opened as .glb (binary glTF) instead.',
    );
  }
  const [file] = list;
  if (!meshFormat(file.name)) {
    throw jobError(
      PAGE_ERROR_KINDS.unsupported,
      `"${file.name}" is not a mesh file Tessera reads. Open a file ending in ` +
        `${MESH_EXTENSIONS.map((e) => '.' + e).join(', ')}.`,
    );
  }
  return file;
}
