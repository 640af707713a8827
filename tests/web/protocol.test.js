import { describe, expect, it } from 'vitest';
import { errorEvent, jobError, ownedBuffers, progressEvent, resultEvent } from '../../web/src/worker/protocol.js';

describe('protocol messages', () => {
  it('have the documented shapes', () => {
    expect(progressEvent(3, 'reading', 0.25)).toEqual({ id: 3, type: 'progress', stage: 'reading', fraction: 0.25 });
    expect(resultEvent(3, { a: 1 })).toEqual({ id: 3, type: 'result', payload: { a: 1 } });
    expect(errorEvent(3, 'parse', 'bad')).toEqual({ id: 3, type: 'error', kind: 'parse', message: 'bad' });
    const error = jobError('limit', 'too many faces');
    expect(error).toBeInstanceOf(Error);
    expect(error).toMatchObject({ kind: 'limit', message: 'too many faces' });
  });
});

describe('ownedBuffers', () => {
  it('transfers arrays that own their buffer as they are', () => {
    const positions = new Float32Array([1, 2, 3]);
    const { payload, transfer } = ownedBuffers({ positions });
    expect(payload.positions).toBe(positions);
    expect(transfer).toEqual([positions.buffer]);
  });

  it('copies views into a larger buffer (such as the wasm heap) instead of transferring that buffer', () => {
    const heap = new ArrayBuffer(64);
    new Uint32Array(heap).set([9, 8, 7, 6], 4);
    const view = new Uint32Array(heap, 16, 3);
    const { payload, transfer } = ownedBuffers({ mesh: { triangles: view } });
    expect([...payload.mesh.triangles]).toEqual([9, 8, 7]);
    expect(payload.mesh.triangles.buffer).not.toBe(heap);
    expect(transfer).toEqual([payload.mesh.triangles.buffer]);
  });

  it('lists a buffer once when two arrays share it, and walks arrays and nested objects', () => {
    const a = new Uint8Array(4);
    const { payload, transfer } = ownedBuffers({ list: [a, { again: a }], name: 'x', count: 2, none: null });
    expect(transfer).toEqual([a.buffer]);
    expect(payload).toEqual({ list: [a, { again: a }], name: 'x', count: 2, none: null });
  });

  it('leaves objects that are not plain data (such as File) untouched', () => {
    class Handle {}
    const handle = new Handle();
    expect(ownedBuffers({ handle }).payload.handle).toBe(handle);
  });
});
