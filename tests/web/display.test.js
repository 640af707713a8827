import { describe, expect, it } from 'vitest';
import { polygonEdges, vertexNormals } from '../../web/src/worker/display.js';

const pairs = (edges) => [...Array(edges.length / 2).keys()].map((i) => [edges[2 * i], edges[2 * i + 1]]);

describe('polygonEdges', () => {
  it('keeps all three sides of faces that are triangles', () => {
    const triangles = new Uint32Array([0, 1, 2, 0, 2, 3]);
    expect(pairs(polygonEdges(triangles, new Uint32Array([0, 1])))).toEqual([
      [0, 1], [1, 2], [2, 0], [0, 2], [2, 3], [3, 0],
    ]);
  });

  it('drops the diagonals that fan-triangulated a polygon', () => {
    // a pentagon 0..4 as the fan (0 1 2) (0 2 3) (0 3 4), then a triangle (4 3 5)
    const triangles = new Uint32Array([0, 1, 2, 0, 2, 3, 0, 3, 4, 4, 3, 5]);
    const edges = pairs(polygonEdges(triangles, new Uint32Array([0, 0, 0, 1])));
    expect(edges).toEqual([
      [0, 1], [1, 2], [2, 3], [3, 4], [4, 0], [4, 3], [3, 5], [5, 4],
    ]);
  });

  it('gives nothing for an empty mesh', () => {
    expect(polygonEdges(new Uint32Array(), new Uint32Array())).toHaveLength(0);
  });
});

describe('vertexNormals', () => {
  it('gives unit normals that follow the triangles orientation', () => {
    const square = new Float32Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]);
    const normals = vertexNormals(square, new Uint32Array([0, 1, 2, 0, 2, 3]));
    expect([...normals]).toEqual([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]);
  });

  it('weights the triangles around a vertex by area', () => {
    // vertex 0 joins a large triangle in the xy-plane and a small one in the xz-plane
    const positions = new Float32Array([0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 1]);
    const [x, y, z] = vertexNormals(positions, new Uint32Array([0, 1, 2, 0, 3, 1]));
    expect(Math.hypot(x, y, z)).toBeCloseTo(1, 6);
    expect(z).toBeGreaterThan(0.9);
    expect(y).toBeGreaterThan(0.2);
  });

  it('leaves a zero normal at vertices of degenerate triangles only', () => {
    const positions = new Float32Array([0, 0, 0, 1, 0, 0, 2, 0, 0]);
    expect([...vertexNormals(positions, new Uint32Array([0, 1, 2]))]).toEqual(new Array(9).fill(0));
  });
});
