// A Vite plugin that emits the service worker (web/src/offline/service-worker.js) as sw.js at the
// build's root, with the list of the build's files (bundle and public/) and a version that
// changes with them.
import { createHash } from 'node:crypto';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';

function filesUnder(dir) {
  const out = [];
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) out.push(...filesUnder(path));
    else out.push(path);
  }
  return out;
}

export function serviceWorker({ source, publicDir }) {
  return {
    name: 'tessera-service-worker',
    apply: 'build',
    generateBundle(_, bundle) {
      const files = [
        ...Object.keys(bundle),
        ...filesUnder(publicDir).map((path) => relative(publicDir, path).split('\\').join('/')),
      ]
        .filter((file) => file !== 'sw.js' && !file.endsWith('.map'))
        .sort();
      const version = createHash('sha256').update(files.join('\n')).digest('hex').slice(0, 16);
      const code = readFileSync(source, 'utf8').replace('self.__PRECACHE__', JSON.stringify({ version, files }));
      this.emitFile({ type: 'asset', fileName: 'sw.js', source: code });
    },
  };
}
