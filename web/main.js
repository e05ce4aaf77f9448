// hullkit demo page: the shell shared by the views. One canvas (app/stage.js), one worker running
// the wasm module (app/worker-client.js), the URL naming the view and its options
// (app/url-state.js); one module per view (views/*.js) created the first time it is shown.
//
// Shared by every view: a busy overlay with elapsed time and Cancel for any computation that takes
// longer than 100 ms (Cancel asks the view, which restarts the worker: a wasm call cannot be
// interrupted), and files in: "Open file…" or a file dropped anywhere on the page goes to the
// view shown (view.openFile), which reads it with the C++ readers in the worker.
// Each view's "What am I looking at?" opens its explanation in a dialog (app/explain.js).
//
// Test hooks: <body data-view="hull|delaunay|delaunay3|route"> names the view shown and
// <body data-state> its state ('loading' | 'computing' | 'ready' | 'error' | 'cancelled');
// each view publishes its own results (window.hullkitStats, hullkitDelaunay, hullkitDelaunay3,
// hullkitRoute);
// <body data-busy> is present while the busy overlay is shown.
import { createStage } from './app/stage.js';
import { WorkerClient } from './app/worker-client.js';
import { viewFromUrl, queryFromUrl, writeUrl } from './app/url-state.js';
import { setUpExplain } from './app/explain.js';
import { createHullView } from './views/hull.js';
import { createDelaunayView } from './views/delaunay.js';
import { createDelaunay3View } from './views/delaunay3.js';
import { createRouteView } from './views/route.js';

const FACTORIES = { hull: createHullView, delaunay: createDelaunayView, delaunay3: createDelaunay3View, route: createRouteView };
const TITLES = {
  hull: 'hullkit · 3D convex hulls',
  delaunay: 'hullkit · Delaunay by lifting',
  delaunay3: 'hullkit · Delaunay tetrahedralization by lifting to 4D',
  route: 'hullkit · route checking with swept hulls',
};

// "What am I looking at?" works even where WebGL does not.
setUpExplain();

const viewport = document.getElementById('viewport');
let stage;
try {
  stage = createStage(document.getElementById('canvas'), viewport);
} catch (err) {
  const el = document.getElementById('fatal');
  el.textContent = `WebGL is not available in this browser: ${err.message}`;
  el.hidden = false;
  document.body.dataset.state = 'error';
  throw err;
}
const worker = new WorkerClient(new URL('./worker.js', import.meta.url));

const views = {};
const states = {};
let current = null;

/** The state setter a view gets: remembered per view, shown on <body> while it is current. */
const stateSetter = (name) => (state) => {
  states[name] = state;
  if (current === name) {
    document.body.dataset.state = state;
    updateBusy();
  }
};

// ---- busy overlay: shown once a computation has run 100 ms, with its elapsed time and Cancel
const busy = {
  el: document.getElementById('busy'),
  text: document.getElementById('busy-text'),
  cancel: document.getElementById('busy-cancel'),
  timer: 0, // the timeout that shows the overlay, then the interval that updates its text
  t0: 0,
};
const BUSY_AFTER_MS = 100;

function updateBusy() {
  const computing = current !== null && states[current] === 'computing';
  if (computing && !busy.timer) {
    busy.t0 = performance.now();
    // A timeout, not the first tick of an interval: that tick may come a hair before 100 ms have
    // passed by performance.now(), which would put the overlay off by a whole period.
    busy.timer = setTimeout(() => {
      busy.timer = setInterval(tickBusy, 100);
      tickBusy();
    }, BUSY_AFTER_MS);
  } else if (!computing && busy.timer) {
    clearTimeout(busy.timer);
    clearInterval(busy.timer);
    busy.timer = 0;
    busy.el.hidden = true;
    delete document.body.dataset.busy;
  }
}

function tickBusy() {
  const ms = performance.now() - busy.t0;
  const what = views[current]?.busyLabel?.() ?? 'Computing';
  busy.text.textContent = `${what}… ${(ms / 1000).toFixed(1)} s`;
  if (busy.el.hidden) {
    busy.el.hidden = false;
    document.body.dataset.busy = '';
  }
}

busy.cancel.addEventListener('click', () => {
  const view = views[current];
  if (view?.cancel) view.cancel();
  else worker.restart();
});

// ---- the panel folds away at phone width
const panelToggle = document.getElementById('panel-toggle');
panelToggle.addEventListener('click', () => {
  const folded = document.body.dataset.panel !== 'folded';
  if (folded) document.body.dataset.panel = 'folded';
  else delete document.body.dataset.panel;
  panelToggle.textContent = folded ? 'Show controls' : 'Hide controls';
  panelToggle.setAttribute('aria-expanded', String(!folded));
  window.dispatchEvent(new Event('resize')); // the canvas takes the freed space
});

// ---- files in: the "Open file…" button and drops anywhere on the page go to the view shown
const fileInput = document.getElementById('file-input');
document.getElementById('open-file').addEventListener('click', () => fileInput.click());
fileInput.addEventListener('change', () => {
  const file = fileInput.files?.[0];
  fileInput.value = ''; // the same file again is a new choice
  if (file) openFile(file);
});

function openFile(file) {
  const view = views[current];
  if (!view?.openFile) return;
  view.openFile(file).catch((err) => console.error('[hullkit] reading a file failed', err));
}

let dragDepth = 0;
const hasFiles = (event) => [...(event.dataTransfer?.types ?? [])].includes('Files');
window.addEventListener('dragenter', (event) => {
  if (!hasFiles(event)) return;
  event.preventDefault();
  dragDepth++;
  document.body.dataset.dropping = '';
});
window.addEventListener('dragover', (event) => {
  if (hasFiles(event)) event.preventDefault(); // allow the drop
});
window.addEventListener('dragleave', () => {
  if (dragDepth > 0 && --dragDepth === 0) delete document.body.dataset.dropping;
});
window.addEventListener('drop', (event) => {
  if (!hasFiles(event)) return;
  event.preventDefault();
  dragDepth = 0;
  delete document.body.dataset.dropping;
  const file = event.dataTransfer.files?.[0];
  if (file) openFile(file);
});

function viewNamed(name) {
  if (!views[name]) views[name] = FACTORIES[name]({ stage, worker, setState: stateSetter(name), viewport });
  return views[name];
}

/** Shows view `name`; `fromUrl` hands it the URL's options (first load, back/forward). */
function show(name, { fromUrl = false } = {}) {
  const view = viewNamed(name);
  if (fromUrl) view.applyUrl?.(queryFromUrl());
  if (current !== name) {
    if (current) views[current].deactivate();
    current = name;
    document.body.dataset.view = name;
    document.body.dataset.state = states[name] ?? 'loading';
    updateBusy();
    document.title = TITLES[name];
    for (const el of document.querySelectorAll('[data-for]')) el.hidden = !el.dataset.for.split(' ').includes(name);
    for (const link of document.querySelectorAll('[data-view-link]')) {
      const on = link.dataset.viewLink === name;
      link.classList.toggle('active', on);
      if (on) link.setAttribute('aria-current', 'page');
      else link.removeAttribute('aria-current');
    }
    document.getElementById('file-hint').textContent = view.fileHint ?? '';
    stage.setActive(view);
    view.activate();
  }
}

for (const link of document.querySelectorAll('[data-view-link]')) {
  link.addEventListener('click', (event) => {
    if (event.button !== 0 || event.metaKey || event.ctrlKey || event.shiftKey || event.altKey) return; // new tab: the href
    event.preventDefault();
    const name = link.dataset.viewLink;
    if (name === current) return;
    // The new history entry first: showing the view may rewrite the URL in place.
    writeUrl(name, viewNamed(name).urlParams(), { push: true });
    show(name);
  });
}

window.addEventListener('popstate', () => show(viewFromUrl(), { fromUrl: true }));

show(viewFromUrl(), { fromUrl: true });
