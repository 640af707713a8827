import { describe, expect, it } from 'vitest';
import { faceSizes } from '../../web/src/ui/info-panel.js';
import { downloadName } from '../../web/src/ui/download.js';

describe('faceSizes', () => {
  it('names face sizes in order of size, one per line', () => {
    expect(faceSizes({ 6: 1, 3: 27954, 4: 12 })).toBe('27,954 triangles\n12 quads\n1 6-gon');
    expect(faceSizes({ 4: 1 })).toBe('1 quad');
    expect(faceSizes(undefined)).toBe('');
  });
});

describe('downloadName', () => {
  it('keeps a mesh name readable and safe as a file name', () => {
    expect(downloadName('fertility.obj', 'glb')).toBe('fertility.glb');
    expect(downloadName('genus2', 'glb')).toBe('genus2.glb');
    expect(downloadName('../../my scan (final).PLY', 'glb')).toBe('my_scan_final_.glb');
    expect(downloadName('C:\\data\\part.v2.stl', 'glb')).toBe('part.v2.glb');
    expect(downloadName('..', 'glb')).toBe('tessera.glb');
    expect(downloadName(undefined, 'ply')).toBe('tessera.ply');
  });
});
