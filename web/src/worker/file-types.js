import { PAGE_ERROR_KINDS, jobError } from './protocol.js';

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

/**
 * The buffer URIs of a glTF JSON document that point to other files (not embedded data: URIs).
 * A single dropped .gltf cannot bring those files along. Returns [] when the text is not JSON:
 * the core's reader then says what is wrong with it.
 */
export function externalBufferUris(gltfText) {
  let document;
  try {
    document = JSON.parse(gltfText);
  } catch {
    return [];
  }
  const buffers = Array.isArray(document?.buffers) ? document.buffers : [];
  return buffers
    .map((buffer) => buffer?.uri)
    .filter((uri) => typeof uri === 'string' && !uri.startsWith('data:'));
}

/** The error for a .gltf file whose buffers live in other files. */
export function externalBuffersError(fileName, uris) {
  return jobError(
    PAGE_ERROR_KINDS.unsupported,
    `"${fileName}" keeps its geometry in separate files (${uris.join(', ')}), which a single ` +
      'opened file cannot bring along. Open the model as .glb (binary glTF, one file), or as a ' +
      '.gltf with embedded buffers.',
  );
}
