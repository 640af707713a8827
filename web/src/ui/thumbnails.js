// Thumbnails made on demand, for the gallery's realized maps that the static build has no picture
// of: rendered by the thumbnail worker (web/src/worker/thumbnail-worker.js) one at a time, only
// for maps whose card is still on screen when their turn comes, and kept in the browser's Cache
// storage, so that a second visit shows them at once. A new build's service worker clears them
// (its caches are all named tessera-...).
const CACHE = 'tessera-rendered-thumbnails';

export class ThumbnailMaker {
  /** createWorker(): the thumbnail worker; cacheKey(file): the URL a thumbnail is cached under. */
  constructor({ createWorker, cacheKey }) {
    Object.assign(this, { createWorker, cacheKey });
    this.worker = null;
    this.queue = []; // { map, file, wanted, resolve }
    this.running = false;
    this.nextId = 1;
  }

  /**
   * The thumbnail of `map` (file: its thumbnailFile) as an object URL, or null when it cannot be
   * made; wanted() says whether it is still needed when its turn comes (null when not). Answers
   * from the cache without waiting for the queue; source says where it came from.
   */
  async get(map, file, wanted) {
    const cached = await this.cached(file);
    if (cached) return { url: URL.createObjectURL(cached), source: 'cache' };
    const bytes = await new Promise((resolve) => {
      this.queue.push({ map, file, wanted, resolve });
      this.run();
    });
    if (!bytes) return null;
    const blob = new Blob([bytes], { type: 'image/webp' });
    await this.store(file, blob);
    return { url: URL.createObjectURL(blob), source: 'rendered' };
  }

  async run() {
    if (this.running) return;
    this.running = true;
    while (this.queue.length > 0) {
      // The newest request first: the cards the user just scrolled to.
      const job = this.queue.pop();
      job.resolve(job.wanted() ? await this.render(job.map) : null);
    }
    this.running = false;
  }

  render(map) {
    this.worker ??= this.createWorker();
    const id = this.nextId++;
    return new Promise((resolve) => {
      const done = (bytes) => {
        this.worker.removeEventListener('message', onMessage);
        this.worker.removeEventListener('error', onError);
        resolve(bytes);
      };
      const onMessage = ({ data }) => {
        if (data.id === id) done(data.bytes ?? null);
      };
      // A worker that fails to start or dies: this one is lost, the next request starts another.
      const onError = () => {
        this.worker.terminate();
        this.worker = null;
        resolve(null);
      };
      this.worker.addEventListener('message', onMessage);
      this.worker.addEventListener('error', onError);
      this.worker.postMessage({ id, map });
    });
  }

  async cached(file) {
    try {
      const response = await (await caches.open(CACHE)).match(this.cacheKey(file));
      return response ? await response.blob() : null;
    } catch {
      return null; // no Cache storage here (a file:// page, a private window that refuses it)
    }
  }

  async store(file, blob) {
    try {
      await (await caches.open(CACHE)).put(this.cacheKey(file), new Response(blob, { headers: { 'content-type': 'image/webp' } }));
    } catch {
      // Not kept: the next visit renders it again.
    }
  }
}
