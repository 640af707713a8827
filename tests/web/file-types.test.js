import { describe, expect, it } from 'vitest';
import { extensionOf, meshFormat, pickMeshFile } from '../../web/src/ui/file-types.js';

describe('meshFormat', () => {
  it('knows the formats the core reads, in any case, from a name or a path', () => {
    expect(meshFormat('bunny.obj')).toBe('obj');
    expect(meshFormat('BUNNY.OFF')).toBe('off');
    expect(meshFormat('scans/part.v2.Ply')).toBe('ply');
    expect(meshFormat('C:\\models\\gear.stl')).toBe('stl');
    expect(meshFormat('scene.glb')).toBe('glb');
    expect(meshFormat('scene.gltf')).toBe('gltf');
  });

  it('refuses other files, files without an extension and dot-files', () => {
    for (const name of ['notes.txt', 'mesh.obj.zip', 'obj', '.obj', 'mesh.', '']) {
      expect(meshFormat(name), name).toBeNull();
    }
    expect(extensionOf('archive.tar.GZ')).toBe('gz');
  });
});

const thrown = (fn) => {
  try {
    fn();
  } catch (error) {
    return error;
  }
  throw new Error('expected an error');
};

describe('pickMeshFile', () => {
  const file = (name) => ({ name });

  it('takes exactly one mesh file', () => {
    const cube = file('cube.obj');
    expect(pickMeshFile([cube])).toBe(cube);
  });

  it('explains what is wrong with other selections', () => {
    const cases = [
      [[], /No file was given/],
      [[file('a.obj'), file('a.bin')], /2 files were given: .*one mesh file at a time/],
      [[file('photo.png')], /"photo.png" is not a mesh file.*\.obj, \.off/],
    ];
    for (const [files, message] of cases) {
      expect(thrown(() => pickMeshFile(files))).toMatchObject({ kind: 'unsupported', message: expect.stringMatching(message) });
    }
  });
});
