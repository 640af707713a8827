// The static build's service worker (emitted as sw.js by scripts/service-worker-plugin.js, which
// fills in PRECACHE): on install it caches the app, the wasm module and the bundled catalog and
// manifest, and the thumbnails that thumbnails/index.json lists; it then answers every same-origin
// GET from the cache first, caching what it fetches, so that the page works offline after the
// first visit. A new build is a new sw.js (its file list changes), which replaces the old caches.
const PRECACHE = self.__PRECACHE__; // { version, files: [paths relative to this script] }
const CACHE = `tessera-${PRECACHE.version}`;

async function thumbnails() {
  try {
    const response = await fetch('thumbnails/index.json', { cache: 'no-store' });
    if (!response.ok) return [];
    const { files } = await response.json();
    return ['thumbnails/index.json', ...files.filter((f) => typeof f === 'string').map((f) => `thumbnails/${encodeURIComponent(f)}`)];
  } catch {
    return [];
  }
}

self.addEventListener('install', (event) => {
  event.waitUntil(
    (async () => {
      const cache = await caches.open(CACHE);
      await cache.addAll(['./', ...PRECACHE.files]);
      // Thumbnails are a nicety: one that fails does not stop the install.
      await Promise.allSettled((await thumbnails()).map((file) => cache.add(file)));
      await self.skipWaiting();
    })(),
  );
});

self.addEventListener('activate', (event) => {
  event.waitUntil(
    (async () => {
      for (const name of await caches.keys()) if (name.startsWith('tessera-') && name !== CACHE) await caches.delete(name);
      await self.clients.claim();
    })(),
  );
});

self.addEventListener('fetch', (event) => {
  const { request } = event;
  if (request.method !== 'GET' || new URL(request.url).origin !== self.location.origin) return;
  event.respondWith(
    (async () => {
      const cache = await caches.open(CACHE);
      // A page's address carries its state in the hash, which the request does not: every
      // navigation is the app's page.
      const cached = await cache.match(request.mode === 'navigate' ? './' : request, { ignoreSearch: true, ignoreVary: true });
      if (cached) return cached;
      const response = await fetch(request);
      if (response.ok && response.type === 'basic') await cache.put(request, response.clone());
      return response;
    })(),
  );
});
