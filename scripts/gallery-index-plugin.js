// A Vite plugin: the module 'virtual:gallery-index', the gallery's cards read from the realization
// manifest (data/regmaps/realizations.json) at build time and packed (web/src/ui/gallery-data.js,
// packGallery) as one JSON text, so that the page reads about 200 kB before its first paint
// instead of the 900 kB manifest, which only the worker needs.
import { readFileSync } from 'node:fs';
import { galleryEntries, packGallery } from '../web/src/ui/gallery-data.js';

const ID = 'virtual:gallery-index';

export function galleryIndex({ manifest }) {
  return {
    name: 'tessera-gallery-index',
    resolveId: (source) => (source === ID ? `\0${ID}` : null),
    load(id) {
      if (id !== `\0${ID}`) return null;
      this.addWatchFile(manifest);
      const rows = packGallery(galleryEntries(JSON.parse(readFileSync(manifest, 'utf8'))));
      // JSON.parse of a string literal is quicker to load than the same object as code.
      return `export default JSON.parse(${JSON.stringify(JSON.stringify(rows))});`;
    },
  };
}
