import { describe, expect, it } from 'vitest';
import { WorkerClient } from '../../web/src/worker/client.js';

// A stand-in for a Worker: records what the page sends, and lets a test answer or die.
class FakeWorker {
  constructor() {
    this.sent = [];
    this.terminated = false;
  }
  postMessage(message, transfer) {
    this.sent.push({ message, transfer });
  }
  terminate() {
    this.terminated = true;
  }
  reply(message) {
    this.onmessage({ data: message });
  }
  get lastId() {
    return this.sent.at(-1).message.id;
  }
}

function clientWithFakes() {
  const workers = [];
  const client = new WorkerClient(() => {
    workers.push(new FakeWorker());
    return workers.at(-1);
  });
  return { client, workers };
}

describe('WorkerClient', () => {
  it('sends { id, command, payload } with the transfer list and resolves with the result payload', async () => {
    const { client, workers } = clientWithFakes();
    const buffer = new ArrayBuffer(8);
    const reply = client.request('loadMesh', { bytes: buffer }, { transfer: [buffer] });
    const [{ message, transfer }] = workers[0].sent;
    expect(message).toEqual({ id: 1, command: 'loadMesh', payload: { bytes: buffer } });
    expect(transfer).toEqual([buffer]);
    workers[0].reply({ id: 1, type: 'result', payload: { name: 'cube' } });
    await expect(reply).resolves.toEqual({ name: 'cube' });
    expect(client.busy).toBe(false);
  });

  it('matches answers to requests by id and reports progress to the right one', async () => {
    const { client, workers } = clientWithFakes();
    const seen = [];
    const first = client.request('a', null, { onProgress: (stage, f) => seen.push(['a', stage, f]) });
    const second = client.request('b', null, { onProgress: (stage, f) => seen.push(['b', stage, f]) });
    workers[0].reply({ id: 2, type: 'progress', stage: 'reading', fraction: 0.5 });
    workers[0].reply({ id: 2, type: 'result', payload: 'B' });
    workers[0].reply({ id: 1, type: 'result', payload: 'A' });
    await expect(second).resolves.toBe('B');
    await expect(first).resolves.toBe('A');
    expect(seen).toEqual([['b', 'reading', 0.5]]);
  });

  it('rejects with the kind and message of an error event', async () => {
    const { client, workers } = clientWithFakes();
    const reply = client.request('loadMesh', {});
    workers[0].reply({ id: 1, type: 'error', kind: 'parse', message: 'line 3: index 9 out of range' });
    await expect(reply).rejects.toMatchObject({ kind: 'parse', message: 'line 3: index 9 out of range' });
  });

  it('ignores messages for unknown or finished requests', async () => {
    const { client, workers } = clientWithFakes();
    const reply = client.request('x', null);
    workers[0].reply({ id: 7, type: 'result', payload: 'stray' });
    workers[0].reply(null);
    workers[0].reply({ id: 1, type: 'result', payload: 'mine' });
    workers[0].reply({ id: 1, type: 'error', kind: 'internal', message: 'late' });
    await expect(reply).resolves.toBe('mine');
  });

  it('cancel terminates the worker, rejects every pending request as cancelled and starts a fresh worker', async () => {
    const { client, workers } = clientWithFakes();
    const first = client.request('a', null);
    const second = client.request('b', null);
    client.cancel();
    await expect(first).rejects.toMatchObject({ kind: 'cancelled' });
    await expect(second).rejects.toMatchObject({ kind: 'cancelled' });
    expect(workers).toHaveLength(2);
    expect(workers[0].terminated).toBe(true);
    expect(client.busy).toBe(false);

    const next = client.request('c', null);
    expect(workers[1].sent).toHaveLength(1);
    workers[1].reply({ id: workers[1].lastId, type: 'result', payload: 'after cancel' });
    await expect(next).resolves.toBe('after cancel');
  });

  it('a dying worker is replaced and its pending requests reject with kind crash', async () => {
    const { client, workers } = clientWithFakes();
    const pending = client.request('a', null);
    let prevented = false;
    workers[0].onerror({ message: 'RuntimeError: unreachable', preventDefault: () => (prevented = true) });
    await expect(pending).rejects.toMatchObject({ kind: 'crash', message: expect.stringContaining('unreachable') });
    expect(prevented).toBe(true);
    expect(workers[0].terminated).toBe(true);

    const next = client.request('b', null);
    workers[1].reply({ id: workers[1].lastId, type: 'result', payload: 'alive' });
    await expect(next).resolves.toBe('alive');
  });

  it('a request that cannot be sent rejects at once and leaves the client idle', async () => {
    const { client, workers } = clientWithFakes();
    workers[0].postMessage = () => {
      throw new Error('could not be cloned');
    };
    await expect(client.request('loadMesh', { f: () => {} })).rejects.toMatchObject({
      kind: 'internal',
      message: expect.stringContaining('could not be cloned'),
    });
    expect(client.busy).toBe(false);
  });

  it('an unreadable message from the worker counts as a crash', async () => {
    const { client, workers } = clientWithFakes();
    const pending = client.request('a', null);
    workers[0].onmessageerror();
    await expect(pending).rejects.toMatchObject({ kind: 'crash' });
    expect(workers).toHaveLength(2);
  });
});
