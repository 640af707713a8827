// `npm run test:browser [-- name-filter]`: the Playwright tests of the page (see harness.js).
import { runTests } from './harness.js';
import './page.test.js';
import './regmap.test.js';
import './field.test.js';
import './surface.test.js';
import './drawn.test.js';
import './large-mesh.test.js';
import './layout.test.js';
import './quad-mesh.test.js';
import './gallery.test.js';

const ok = await runTests(process.argv[2] ?? '');
process.exit(ok ? 0 : 1);
