// The page: composes the viewer, the worker client, the status line, the mode and the URL state.
import './style.css';
import { Viewer } from './viewer/viewer.js';
import { WorkerClient } from './worker/client.js';
import { Status } from './ui/status.js';
import { Jobs } from './ui/jobs.js';
import { acceptFiles } from './ui/file-drop.js';
import { createViewControls } from './ui/view-controls.js';
import { createTabs } from './ui/tabs.js';
import { formatHash, parseHash } from './ui/hash.js';
import { QuadLayoutMode } from './ui/quad-layout-mode.js';
import { MODES } from './ui/modes.js';

const byId = (id) => document.getElementById(id);
const client = new WorkerClient(
  () => new Worker(new URL('./worker/worker.js', import.meta.url), { type: 'module' }),
);
const status = new Status(byId('status'), { onCancel: () => client.cancel() });
window.addEventListener('unhandledrejection', (event) => status.showError(event.reason));

let { state, problems: linkProblems } = parseHash(location.hash);
const reportLinkProblems = () => {
  if (linkProblems.length > 0) status.showNotice('Parts of the link were ignored.', linkProblems.join(' '));
};

function updateState(partial) {
  state = { ...state, ...partial };
  history.replaceState(null, '', formatHash(state));
}

const selectTab = createTabs(byId('modes'), MODES, (mode) => updateState({ mode }));
selectTab(state.mode);

let viewer;
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

if (viewer) {
  const view = { shading: state.shading, wireframe: state.wireframe };
  const applyView = (settings) => {
    viewer.setShading(settings.shading);
    viewer.setWireframe(settings.wireframe);
  };
  const viewControls = createViewControls(byId('view-controls'), view, (settings) => {
    applyView(settings);
    updateState(settings);
  });
  applyView(view);

  const mode = new QuadLayoutMode({
    panel: byId('quad-panel'),
    viewer,
    client,
    jobs: new Jobs(client, status),
    status,
    onStateChange: updateState,
  });
  acceptFiles({ target: document.body, input: byId('file-input'), onFiles: (files) => mode.openFiles(files) });

  window.addEventListener('hashchange', () => {
    ({ state, problems: linkProblems } = parseHash(location.hash));
    selectTab(state.mode);
    viewControls.update({ shading: state.shading, wireframe: state.wireframe });
    applyView(state);
    mode.applyState(state).then(reportLinkProblems);
  });

  mode.start(state).then(reportLinkProblems);
}
