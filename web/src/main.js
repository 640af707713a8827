// The page: composes the viewer, the worker client, the status line, the modes and the URL state.
// The 3D view (three.js) and the Quad layout mode are chunks of their own: a page opened on the
// gallery paints its cards first and loads them after.
import './style.css';
import { WorkerClient } from './worker/client.js';
import { Status } from './ui/status.js';
import { Jobs } from './ui/jobs.js';
import { acceptFiles } from './ui/file-drop.js';
import { createViewControls } from './ui/view-controls.js';
import { createTabs } from './ui/tabs.js';
import { RegularMapMode } from './ui/regmap-mode.js';
import { GalleryMode, readGalleryIndex } from './ui/gallery-mode.js';
import { ThumbnailMaker } from './ui/thumbnails.js';
import { DEFAULT_STATE, cameraOf, cameraText, formatHash, parseHash } from './ui/hash.js';
import { TilingView } from './ui/tiling-view.js';
import { DrawnView } from './ui/drawn-view.js';
import { SurfaceView } from './ui/surface-view.js';
import { MODES } from './ui/modes.js';

const byId = (id) => document.getElementById(id);
const client = new WorkerClient(
  () => new Worker(new URL('./worker/worker.js', import.meta.url), { type: 'module' }),
);
const status = new Status(byId('status'), { onCancel: () => client.cancel() });
const jobs = new Jobs(client, status);
window.addEventListener('unhandledrejection', (event) => status.showError(event.reason));

let { state, problems: linkProblems } = parseHash(location.hash);
if (state.mode === 'gallery') readGalleryIndex();
const reportLinkProblems = () => {
  if (linkProblems.length > 0) status.showNotice('Parts of the link were ignored.', linkProblems.join(' '));
};

function updateState(partial) {
  state = { ...state, ...partial };
  history.replaceState(null, '', formatHash(state));
}

const request = (label, command, payload) =>
  jobs.run(label, (onProgress) => client.request(command, payload, { onProgress }));

let viewer; // the 3D view, once its code is loaded (null where WebGL 2 is missing)
const modes = {
  gallery: new GalleryMode({
    panel: byId('gallery-panel'),
    grid: byId('gallery'),
    status,
    base: import.meta.env.BASE_URL,
    mapLink: (map) => formatHash({ ...DEFAULT_STATE, mode: 'regmap', map }),
    onStateChange: updateState,
    maker: new ThumbnailMaker({
      createWorker: () => new Worker(new URL('./worker/thumbnail-worker.js', import.meta.url), { type: 'module' }),
      cacheKey: (file) => new URL(`thumbnails/rendered/${encodeURIComponent(file)}`, document.baseURI).href,
    }),
  }),
};
const started = new Set();

const selectTab = createTabs(byId('modes'), MODES, (mode) => {
  updateState({ mode });
  showMode();
});

const sceneOf = (id) => MODES.find((mode) => mode.id === id).scene;

/**
 * Shows the mode of the state (its tab, panel and view) and brings it to the state. A mode whose
 * parts are not loaded yet starts once they are (the end of this file).
 */
function showMode() {
  const id = state.mode;
  selectTab(id);
  viewer?.showScene(sceneOf(id));
  for (const part of document.querySelectorAll('[data-for-mode]')) part.hidden = part.dataset.forMode !== id;
  const mode = modes[id];
  if (!mode) return Promise.resolve();
  if (started.has(id)) return mode.applyState(state);
  started.add(id);
  return mode.start(state);
}

// The gallery's cards are on screen before the 3D view's code is fetched.
if (state.mode === 'gallery') {
  await showMode();
  await new Promise((painted) => requestAnimationFrame(() => setTimeout(painted)));
}
const [{ Viewer }, { QuadLayoutMode }] = await Promise.all([
  import('./viewer/viewer.js'),
  import('./ui/quad-layout-mode.js'),
]);
// The state as the link now says (a card or a tab may have been followed meanwhile).
({ state, problems: linkProblems } = parseHash(location.hash));

try {
  viewer = new Viewer(byId('viewport'), {
    onContextLost: () =>
      status.showError({
        kind: 'internal',
        message: 'The 3D view lost its graphics context (the GPU was reset or is out of memory). It comes back by itself when the browser allows; reload the page if it does not.',
      }),
  });
} catch (error) {
  status.showError({ kind: 'internal', message: `The 3D view could not start (${error.message}). Tessera needs a browser with WebGL 2.` });
}

const tilingView = new TilingView(byId('tiling-view'));
// A 3D view of the Regular maps mode (DrawnView, SurfaceView) on its section of the panel.
const mapView = (View, role) =>
  viewer
    ? new View({
        root: byId('regmap-panel').querySelector(`[data-role=${role}]`),
        note: byId('surface-note'),
        viewer,
        status,
        request,
        onStateChange: updateState,
        exportSvg: () => tilingView.download(),
      })
    : null;
modes.regmap = new RegularMapMode({
  panel: byId('regmap-panel'),
  view: tilingView,
  viewChoices: [...byId('regmap-views').querySelectorAll('input')],
  drawn: mapView(DrawnView, 'drawn-view'),
  surface: mapView(SurfaceView, 'surface-view'),
  client,
  jobs,
  status,
  onStateChange: updateState,
});

// The camera and its turning are part of every link (the link's camera is taken by the next
// framing, so a link reproduces the view once its surface is drawn).
if (viewer) {
  viewer.onViewChange = (view) => updateState({ cam: cameraText(view) });
  viewer.setLinkedView(cameraOf(state.cam));
  viewer.setAutoRotate(state.spin);
}
const spinBox = document.querySelector('#share-tools [data-role=spin]');
spinBox.checked = state.spin;
spinBox.disabled = !viewer;
spinBox.addEventListener('change', () => {
  viewer?.setAutoRotate(spinBox.checked);
  updateState({ spin: spinBox.checked });
});
document.querySelector('#share-tools [data-role=copy-link]').addEventListener('click', async () => {
  try {
    await navigator.clipboard.writeText(location.href);
    status.showNotice('Link copied.', 'It opens this map with this view, camera and colours.');
  } catch {
    status.showNotice('The browser did not let the page copy.', `The link: ${location.href}`);
  }
});

let viewControls;
const applyView = (settings) => {
  viewer?.setShading(settings.shading);
  viewer?.setWireframe(settings.wireframe);
};

if (viewer) {
  const view = { shading: state.shading, wireframe: state.wireframe };
  viewControls = createViewControls(byId('view-controls'), view, (settings) => {
    applyView(settings);
    updateState(settings);
  });
  applyView(view);

  modes.quad = new QuadLayoutMode({
    panel: byId('quad-panel'),
    viewer,
    client,
    jobs,
    status,
    onStateChange: updateState,
  });
  // A mesh file dropped in another mode opens in the Quad layout mode.
  acceptFiles({
    target: document.body,
    input: byId('file-input'),
    onFiles: async (files) => {
      if (state.mode !== 'quad') {
        updateState({ mode: 'quad' });
        await showMode();
      }
      await modes.quad.openFiles(files);
    },
  });
}

window.addEventListener('hashchange', () => {
  const camera = state.cam;
  ({ state, problems: linkProblems } = parseHash(location.hash));
  if (state.cam !== camera) viewer?.setLinkedView(cameraOf(state.cam));
  viewer?.setAutoRotate(state.spin);
  spinBox.checked = state.spin;
  viewControls?.update({ shading: state.shading, wireframe: state.wireframe });
  applyView(state);
  showMode().then(reportLinkProblems);
});

if (started.has(state.mode)) {
  viewer?.showScene(sceneOf(state.mode));
  reportLinkProblems();
} else {
  showMode().then(reportLinkProblems);
}

// The static build works offline after the first visit (web/src/offline/service-worker.js).
if (import.meta.env.PROD && 'serviceWorker' in navigator) {
  navigator.serviceWorker.register('./sw.js').catch(() => {});
}
