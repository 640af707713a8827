import { describe, expect, it } from 'vitest';
import { GLYPH_ARM, cornerArrays, crossGlyphs, markerRadius, vertexPoints } from '../../web/src/worker/field-display.js';

// Two triangles of the unit square in the xy-plane (normal +z), and one degenerate triangle.
const positions = new Float32Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 0]);
const square = new Uint32Array([0, 1, 2, 0, 2, 3]);
const points = (array) => [...Array(array.length / 3).keys()].map((i) => [...array.subarray(3 * i, 3 * i + 3)]);
const close = (actual, expected) => actual.forEach((x, i) => expect(x).toBeCloseTo(expected[i], 6));

describe('crossGlyphs', () => {
  it('draws u and n x u through the centroid, scaled to the triangle', () => {
    const directions = new Float32Array([1, 0, 0, 0, 1, 0]);
    const glyphs = crossGlyphs(positions, square, directions);
    expect(glyphs).toHaveLength(24);
    const arm = GLYPH_ARM * Math.sqrt(0.5);
    const [a, b, c, d] = points(glyphs.subarray(0, 12));
    const centroid = [2 / 3, 1 / 3, 0];
    close(a, [centroid[0] - arm, centroid[1], 0]);
    close(b, [centroid[0] + arm, centroid[1], 0]);
    // n x u with n = +z and u = +x is +y
    close(c, [centroid[0], centroid[1] - arm, 0]);
    close(d, [centroid[0], centroid[1] + arm, 0]);
    // the second triangle's u is +y, so its second arm is n x u = -x
    const [, , e, f] = points(glyphs.subarray(12));
    close(e, [1 / 3 + arm, 2 / 3, 0]);
    close(f, [1 / 3 - arm, 2 / 3, 0]);
  });

  it('keeps every arm inside the triangle for a rotated direction', () => {
    const angle = 0.7;
    const glyphs = crossGlyphs(positions, square.subarray(0, 3), new Float32Array([Math.cos(angle), Math.sin(angle), 0]));
    for (const [x, y] of points(glyphs)) {
      expect(x).toBeLessThanOrEqual(1);
      expect(y).toBeGreaterThanOrEqual(0);
      expect(y).toBeLessThanOrEqual(x);
    }
  });

  it('gives a degenerate triangle a cross of length zero at its centroid', () => {
    const glyphs = crossGlyphs(positions, new Uint32Array([0, 1, 4]), new Float32Array([1, 0, 0]));
    for (const point of points(glyphs)) close(point, [1, 0, 0]);
  });
});

describe('markerRadius', () => {
  // A strip of n unit squares along x: the triangles keep their size, the mesh grows.
  const strip = (n) => {
    const points = [];
    for (let i = 0; i <= n; i++) points.push(i, 0, 0, i, 1, 0);
    const corners = [];
    for (let i = 0; i < n; i++) corners.push(2 * i, 2 * i + 2, 2 * i + 3, 2 * i, 2 * i + 3, 2 * i + 1);
    return [new Float32Array(points), new Uint32Array(corners)];
  };

  it('follows the size of the triangles', () => {
    const [points, corners] = strip(40);
    const radius = markerRadius(points, corners);
    expect(radius).toBeCloseTo(0.6 * Math.sqrt(0.5), 6);
    expect(markerRadius(points.map((x) => 10 * x), corners)).toBeCloseTo(10 * radius, 5);
    expect(markerRadius(positions, new Uint32Array())).toBe(0);
  });

  it('keeps markers visible on fine meshes and small on coarse ones', () => {
    const [fine, fineCorners] = strip(1000);
    expect(markerRadius(fine, fineCorners)).toBeCloseTo(0.007 * Math.hypot(1000, 1), 3);
    expect(markerRadius(positions, square)).toBeCloseTo(0.025 * Math.hypot(2, 1), 6); // the box of all five points
  });
});

describe('vertexPoints', () => {
  it('gives the positions of the listed vertices in order', () => {
    expect([...vertexPoints(positions, new Uint32Array([2, 0]))]).toEqual([1, 1, 0, 0, 0, 0]);
    expect(vertexPoints(positions, new Uint32Array())).toHaveLength(0);
  });
});

describe('cornerArrays', () => {
  it('repeats each vertex at every corner in triangle order, for texture coordinates per corner', () => {
    const normals = new Float32Array(15).map((_, i) => i);
    const corners = cornerArrays(positions, normals, square);
    expect(points(corners.positions)).toEqual([0, 1, 2, 0, 2, 3].map((v) => [...positions.subarray(3 * v, 3 * v + 3)]));
    expect(points(corners.normals)).toEqual([0, 1, 2, 0, 2, 3].map((v) => [3 * v, 3 * v + 1, 3 * v + 2]));
  });
});
