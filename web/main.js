// hullkit demo page: the shell shared by the views. One canvas (app/stage.js), one worker running
// the wasm module (app/worker-client.js), the URL naming the view and its options
// (app/url-state.js); one module per view (views/*.js) created the first time it is shown.
//
// Test hooks: <body data-view="hull|delaunay|route"> names the view shown and
// <body data-state> its state ('loading' | 'computing' | 'ready' | 'error' | 'cancelled');
// each view publishes its own results (window.hullkitStats, hullkitDelaunay, hullkitRoute).
import { createStage } from './app/stage.js';
import { WorkerClient } from './app/worker-client.js';
import { viewFromUrl, queryFromUrl, writeUrl } from './app/url-state.js';
import { createHullView } from './views/hull.js';
import { createDelaunayView } from './views/delaunay.js';
import { createRouteView } from './views/route.js';

const FACTORIES = { hull: createHullView, delaunay: createDelaunayView, route: createRouteView };
const TITLES = {
  hull: 'hullkit · 3D convex hulls',
  delaunay: 'hullkit · Delaunay by lifting',
  route: 'hullkit · route checking with swept hulls',
};

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
  if (current === name) document.body.dataset.state = state;
};

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
    document.title = TITLES[name];
    for (const el of document.querySelectorAll('[data-for]')) el.hidden = !el.dataset.for.split(' ').includes(name);
    for (const link of document.querySelectorAll('[data-view-link]')) {
      const on = link.dataset.viewLink === name;
      link.classList.toggle('active', on);
      if (on) link.setAttribute('aria-current', 'page');
      else link.removeAttribute('aria-current');
    }
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
