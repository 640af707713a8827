import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';
import { galleryIndex } from './scripts/gallery-index-plugin.js';
import { serviceWorker } from './scripts/service-worker-plugin.js';

const projectRoot = fileURLToPath(new URL('.', import.meta.url));

export default defineConfig({
  root: 'web',
  // Relative URLs: the static build works from any static host under any path.
  base: './',
  // three.js alone is about 600 kB minified, a chunk the page loads after its first paint. The
  // realization manifest (a chunk of its own, loaded by the worker) is about 900 kB.
  build: { outDir: 'dist', emptyOutDir: true, target: 'es2022', chunkSizeWarningLimit: 1000 },
  worker: { format: 'es' },
  plugins: [
    galleryIndex({ manifest: fileURLToPath(new URL('data/regmaps/realizations.json', import.meta.url)) }),
    serviceWorker({
      source: fileURLToPath(new URL('web/src/offline/service-worker.js', import.meta.url)),
      publicDir: fileURLToPath(new URL('web/public', import.meta.url)),
    }),
  ],
  server: { port: 5173, strictPort: true },
  preview: { port: 4173, strictPort: true },
  test: { root: projectRoot, include: ['tests/web/**/*.test.js'] },
});
