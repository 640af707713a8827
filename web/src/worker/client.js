import { PAGE_ERROR_KINDS, jobError } from './protocol.js';

/**
 * The page's side of the worker protocol (see protocol.js): one promise per request, progress
 * callbacks, cancel by replacing the worker, and recovery from a dead worker.
 *
 * createWorker: () => Worker-like object (postMessage, terminate, onmessage, onerror, onmessageerror)
 */
export class WorkerClient {
  constructor(createWorker) {
    this.createWorker = createWorker;
    this.nextId = 1;
    this.pending = new Map();
    this.worker = null;
    this.start();
  }

  /**
   * Sends one request. Resolves with the result payload; rejects with an Error whose `kind` is the
   * worker's error kind, 'cancelled' or 'crash'. onProgress(stage, fraction) is called per event.
   */
  request(command, payload, { onProgress, transfer = [] } = {}) {
    const id = this.nextId++;
    return new Promise((resolve, reject) => {
      try {
        this.worker.postMessage({ id, command, payload }, transfer);
      } catch (error) {
        reject(jobError('internal', `The request "${command}" could not be sent to the worker: ${error.message}`));
        return;
      }
      this.pending.set(id, { resolve, reject, onProgress });
    });
  }

  get busy() {
    return this.pending.size > 0;
  }

  /** Stops every running request (they reject with kind 'cancelled') and starts a fresh worker. */
  cancel() {
    this.restart(jobError(PAGE_ERROR_KINDS.cancelled, 'Cancelled.'));
  }

  start() {
    const worker = this.createWorker();
    worker.onmessage = (event) => this.receive(event.data);
    worker.onerror = (event) => {
      event.preventDefault?.();
      this.restart(crashError(event.message));
    };
    worker.onmessageerror = () => this.restart(crashError('a message could not be read'));
    this.worker = worker;
  }

  restart(reason) {
    this.worker.terminate();
    const pending = [...this.pending.values()];
    this.pending.clear();
    this.start();
    for (const request of pending) request.reject(reason);
  }

  receive(message) {
    const request = this.pending.get(message?.id);
    if (!request) return;
    if (message.type === 'progress') {
      request.onProgress?.(message.stage, message.fraction);
    } else if (message.type === 'result') {
      this.pending.delete(message.id);
      request.resolve(message.payload);
    } else if (message.type === 'error') {
      this.pending.delete(message.id);
      request.reject(jobError(message.kind, message.message));
    }
  }
}

function crashError(detail) {
  const why = detail ? ` (${detail})` : '';
  return jobError(
    PAGE_ERROR_KINDS.crash,
    `The computation stopped unexpectedly${why}. A fresh worker has been started: try again, ` +
      'or with a smaller mesh if it happens again.',
  );
}
