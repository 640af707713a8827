import { describe, expect, it } from 'vitest';
import { segmentLines, surfaceGeometry } from '../../web/src/viewer/geometry.js';

// A unit square in z = 0 as two triangles, with its corners 2 units from the origin along x.
const positions = new Float32Array([2, 0, 0, 3, 0, 0, 3, 1, 0, 2, 1, 0]);
const normals = new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]);
const triangles = new Uint32Array([0, 1, 2, 0, 2, 3]);

describe('surfaceGeometry', () => {
  it('takes the attributes it is given and bounds the surface', () => {
    const colors = new Float32Array(12).fill(0.5);
    const geometry = surfaceGeometry({ positions, normals, colors, triangles });
    expect(geometry.getAttribute('position').count).toBe(4);
    expect(geometry.getAttribute('color').array).toBe(colors);
    expect(geometry.getAttribute('uv')).toBeUndefined();
    expect(Array.from(geometry.getIndex().array)).toEqual([0, 1, 2, 0, 2, 3]);
    const sphere = geometry.boundingSphere;
    expect(sphere.center.x).toBeCloseTo(2.5);
    expect(sphere.center.y).toBeCloseTo(0.5);
    expect(sphere.radius).toBeCloseTo(Math.SQRT1_2);
  });

  it('leaves a surface without triangles unindexed, with uv of 2 numbers per vertex', () => {
    const uv = new Float32Array([0, 0, 1, 0, 1, 1, 0, 1]);
    const geometry = surfaceGeometry({ positions, normals, uv });
    expect(geometry.getIndex()).toBeNull();
    expect(geometry.getAttribute('uv').itemSize).toBe(2);
    expect(geometry.getAttribute('uv').count).toBe(4);
    expect(geometry.getAttribute('color')).toBeUndefined();
  });
});

describe('segmentLines', () => {
  it('draws one segment per 6 numbers in the colour given', () => {
    const lines = segmentLines(new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1]), '#112233');
    expect(lines.isLineSegments).toBe(true);
    expect(lines.geometry.getAttribute('position').count).toBe(4);
    expect(lines.material.color.getHexString()).toBe('112233');
  });
});
