// The Delaunay view: 2D points lifted onto the paraboloid z = x² + y²; the lower faces of their
// convex hull (shaded) project to the Delaunay triangulation of the plane. Side by side (the
// paraboloid in 3D | the plane seen from above) or blended (the paraboloid over the plane in one
// 3D view). Clicks add points, hovering a triangle shows its empty circumcircle (and its lift,
// which lies in the plane of the lifted face), Voronoi cells on request.
//
// This module asks the worker for triangulations (and cancels them) and wires the view's parts:
// the scenes and panes (delaunay-scene.js), the drawing of a triangulation (delaunay-draw.js),
// hover and clicks (delaunay-hover.js), the panel's inputs and URL state (delaunay-panel.js),
// files in and out (delaunay-files.js) and the lifted gift wrap step by step
// (giftwrap-stepper.js).
//
// The Triangulation select switches to the constrained modes (views/constrained/): a polygon
// with holes drawn by clicks or opened from a file, triangulated with its edges as constraints,
// or as a quality mesh; they draw through the same scenes and drawing.
//
// Test hook: window.hullkitDelaunay = {n, distinct, duplicates, triangles, hull, dimension,
// ms, set, seed, added, run} after each triangulation drawn (the constrained modes' is
// window.hullkitConstrained).
import { fmtInt, fmtMs } from '../app/format.js';
import { writeUrl } from '../app/url-state.js';
import { showError } from '../app/panel.js';
import { createGiftwrapStepper } from './giftwrap-stepper.js';
import { generatePoints2 } from '../points2d.js';
import { createDelaunayScene } from './delaunay-scene.js';
import { createDelaunayDrawing, liftedAndPlanePositions } from './delaunay-draw.js';
import { createDelaunayHover } from './delaunay-hover.js';
import { delaunayUi, createDelaunayPanel } from './delaunay-panel.js';
import { createDelaunayFiles } from './delaunay-files.js';
import { createConstrainedMode } from './constrained/constrained.js';

const GIFTWRAP_MAX = 5000;

function boundsOf(points) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i < points.length; i += 2) {
    x0 = Math.min(x0, points[i]); x1 = Math.max(x1, points[i]);
    y0 = Math.min(y0, points[i + 1]); y1 = Math.max(y1, points[i + 1]);
  }
  if (!(x0 <= x1)) return { cx: 0, cy: 0, r: 1 };
  return { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, r: Math.max(0.5, (x1 - x0) / 2, (y1 - y0) / 2) };
}

export function createDelaunayView({ stage, worker, setState, viewport }) {
  const ui = delaunayUi();

  // What the view's parts share.
  const state = {
    active: false,
    mode: 'unconstrained', // or 'constrained', 'quality' (views/constrained/)
    fileInput: null, // {name, xy}: the points of the last file opened
    added: [], // clicked points [[x, y], ...]
    xy: new Float64Array(0), // base + added
    tri: null, // the last triangulation drawn
    cells: null,
    extent: { cx: 0, cy: 0, r: 1 },
    lastTriangle: 0,
    framed: false,
    lastExport: null,
  };
  let base = null; // {set, n, seed, xy}: the generated points
  let runCount = 0;
  let pendingKey = null; // what is being computed
  let drawnKey = null;
  let requestSeq = 0;
  let cancelledKey = null;

  const scene = createDelaunayScene({ stage, ui, state, viewport });
  const { controls, requestRender, layoutPanes, frame3d, render, resize } = scene;
  const drawing = createDelaunayDrawing({ ui, state, scene });
  const { showHover } = createDelaunayHover({ state, scene, compute });
  const panel = createDelaunayPanel({ ui, state, scene, drawing, compute, viewUrlParams: () => viewUrlParams() });
  const { readParams, updateHint, encodeAdded, urlParams, applyUrl, setAlgorithms } = panel;

  // ------------------------------------------------------------ compute

  const keyOf = (p) => `${p.set}|${p.n}|${p.seed}|${p.algorithm}|${p.voronoi}|${encodeAdded()}|${p.set === 'file' ? state.fileInput.name : ''}`;

  /**
   * Generates the points, asks the worker for the triangulation (and cells) and draws it; in a
   * constrained mode, triangulates its polygon instead.
   */
  function compute({ push = false, force = false } = {}) {
    if (polygon.polygonMode()) {
      // What the points mode had drawn or asked for is no longer shown.
      requestSeq++;
      pendingKey = null;
      drawnKey = null;
      polygon.compute({ push, force });
      return;
    }
    if (!worker.ready) {
      setState('loading');
      ui.status.textContent = worker.loadError ? '' : 'Loading the WebAssembly module…';
      if (worker.loadError) fail(`Cannot triangulate: ${worker.loadError}`);
      return;
    }
    const p = readParams();
    if (p.set !== 'file') {
      // What was typed, made valid (n = -5 → 3), as the URL will say.
      ui.n.value = String(p.n);
      ui.seed.value = String(p.seed);
      updateHint();
    }
    const key = keyOf(p);
    if (!force && (key === pendingKey || key === cancelledKey || (key === drawnKey && pendingKey === null))) return;
    cancelledKey = null;
    if (p.set === 'file') {
      if (!base || base.xy !== state.fileInput.xy) base = { set: 'file', n: p.n, seed: p.seed, xy: state.fileInput.xy };
    } else if (!base || base.set !== p.set || base.n !== p.n || base.seed !== p.seed) {
      base = { set: p.set, n: p.n, seed: p.seed, xy: generatePoints2(p.set, p.n, p.seed) };
    }
    state.xy = new Float64Array(base.xy.length + 2 * state.added.length);
    state.xy.set(base.xy);
    state.added.forEach(([x, y], i) => state.xy.set([x, y], base.xy.length + 2 * i));
    state.extent = boundsOf(state.xy);
    const bounds = [state.extent.cx - 1.3 * state.extent.r, state.extent.cy - 1.3 * state.extent.r, state.extent.cx + 1.3 * state.extent.r, state.extent.cy + 1.3 * state.extent.r];

    if (state.active && p.set !== 'file') writeUrl('delaunay', urlParams(), { push });
    if (p.algorithm === 'giftwrap' && state.xy.length / 2 > GIFTWRAP_MAX) {
      // Every lifted point is a hull vertex, so gift wrapping them costs O(n²).
      fail(`Gift wrapping the lifted points takes O(n²) time (every lifted point is a hull vertex): ` +
        `at most ${fmtInt(GIFTWRAP_MAX)} points here; pick incremental insertion for more.`, false);
      return;
    }
    pendingKey = key;
    const id = ++requestSeq;
    const t0 = performance.now();
    setState('computing');
    ui.error.hidden = true;
    ui.status.textContent = `Triangulating ${fmtInt(state.xy.length / 2)} points…`;
    const points = state.xy;
    worker.request({ type: 'delaunay', xy: points.slice(), algorithm: p.algorithm || undefined, voronoi: p.voronoi ? bounds : null }).then(
      (msg) => {
        if (id !== requestSeq) return;
        pendingKey = null;
        if (msg.type !== 'result') {
          fail(`${msg.kind === 'input' ? 'Cannot triangulate' : 'Triangulation failed'}: ${String(msg.message).replace(/^delaunay:\s*/, '')}`, msg.kind !== 'input');
          return;
        }
        drawnKey = key;
        show(msg, p, performance.now() - t0, points);
      },
      (err) => {
        if (id !== requestSeq) return;
        pendingKey = null;
        if (!err.cancelled) fail(err.message, false);
      },
    );
  }

  function show(msg, p, roundTripMs, points) {
    state.xy = points;
    state.tri = msg;
    state.cells = msg.cells ?? null;
    state.lastTriangle = 0;
    showHover(-1);
    layoutPanes();
    if (!state.framed) {
      frame3d();
      state.framed = true;
    }
    drawing.drawTriangulation();
    runCount++;
    const n = state.xy.length / 2;
    const triangles = state.tri.triangles.length / 3;
    const distinct = n - state.tri.duplicateCount;
    setStats({
      n: fmtInt(n), triangles: fmtInt(triangles), hull: fmtInt(state.tri.hull.length),
      ms: fmtMs(msg.ms), rtt: fmtMs(roundTripMs), dup: fmtInt(state.tri.duplicateCount),
    });
    ui.stat.ms.title = 'hullkit.delaunay() inside the worker';
    const setLabel = p.set === 'file' ? state.fileInput.name : ui.set.selectedOptions[0]?.textContent ?? p.set;
    state.lastExport = { xy: points, triangles: state.tri.triangles, hull: state.tri.hull, cells: msg.cells ?? null, name: p.set === 'file' ? `${state.fileInput.name.replace(/\.[^.]*$/, '')}-delaunay` : `delaunay-${p.set}-${p.n}-seed${p.seed}` };
    for (const b of files.exportButtons) b.disabled = state.tri.triangles.length === 0;
    let status = `${fmtInt(distinct)} points (${setLabel}${state.added.length ? `, ${state.added.length} clicked` : ''}): ` +
      `${fmtInt(triangles)} ${triangles === 1 ? 'triangle' : 'triangles'} = 2n − h − 2 with h = ${fmtInt(state.tri.hull.length)} hull points.`;
    if (state.tri.dimension === 1) status = `${fmtInt(distinct)} distinct points, all on one line: no triangles, the hull is the ordered line of points.`;
    else if (state.tri.dimension < 1) status = `${distinct === 1 ? 'One point' : 'No points'}: no triangles.`;
    if (state.tri.duplicateCount) status += ` ${fmtInt(state.tri.duplicateCount)} exact duplicates merged into their first copy.`;
    if (state.cells) status += ` Voronoi cells in ${fmtMs(msg.voronoiMs)}.`;
    ui.status.textContent = status;
    window.hullkitDelaunay = {
      n, distinct, duplicates: state.tri.duplicateCount, triangles, hull: state.tri.hull.length, dimension: state.tri.dimension,
      ms: msg.ms, set: p.set, seed: p.seed, added: state.added.length, voronoi: Boolean(state.cells), run: runCount,
    };
    liftStepper.offer({
      coords: state.xy, n: distinct, eligible: state.tri.dimension === 2 && state.tri.duplicateCount === 0,
      why: state.tri.dimension !== 2 ? 'Available when the points span the plane.'
        : state.tri.duplicateCount ? 'Available for points without duplicates.' : `Available for at most ${LIFT_STEP_MAX} points (set n to ${LIFT_STEP_MAX} or fewer).`,
    });
    // The coordinates too (non-enumerable: JSON of the hook stays short).
    Object.defineProperty(window.hullkitDelaunay, 'points', { value: Array.from(state.xy) });
    const drawn = state.tri.triangles;
    Object.defineProperty(window.hullkitDelaunay, 'triangleList', { get: () => Array.from(drawn) });
    setState('ready');
    requestRender();
  }

  function fail(message, logged = true) {
    liftStepper.offer({ why: 'Triangulate first.' });
    state.lastExport = null;
    for (const b of files.exportButtons) b.disabled = true;
    showError(ui.error, message, logged);
    ui.status.textContent = '';
    setState('error');
  }

  function setStats(values) {
    for (const [k, el] of Object.entries(ui.stat)) el.textContent = values[k] ?? '—';
  }

  // ------------------------------------------------------------ controls

  ui.form.addEventListener('submit', (event) => {
    event.preventDefault();
    compute({ push: true, force: true });
  });
  // ------------------------------------------------------------ the lifted gift wrap, step by step

  const LIFT_STEP_MAX = 300;
  const liftStepper = createGiftwrapStepper({
    worker, requestRender, prefix: 'dl-step', hook: 'hullkitLiftStepper', lifted: true, limit: LIFT_STEP_MAX,
    targets: (coords) => {
      const { liftedPos, planePos } = liftedAndPlanePositions(coords);
      return [{ scene: scene.scene3d, positions: liftedPos }, { scene: scene.scene2d, positions: planePos }];
    },
    request: (coords) => ({ type: 'trace', xy: coords, lifted: true }),
    hideResult: (hidden) => {
      scene.lifted.visible = scene.plane.visible = scene.planeIn3d.visible = !hidden;
      requestRender();
    },
  });

  // ------------------------------------------------------------ files in and out

  const files = createDelaunayFiles({
    ui, state, worker, setState, updateHint, compute,
    onPolygon: (name, shape) => polygon.openPolygon(name, shape),
    beforePoints: () => { if (polygon.polygonMode()) polygon.setMode('unconstrained'); },
  });

  // ------------------------------------------------------------ the constrained modes

  const polygon = createConstrainedMode({
    ui, state, scene, drawing, worker, setState, setStats, exportButtons: files.exportButtons,
    hideStepper: () => {
      liftStepper.offer({ why: 'Available in the unconstrained mode.' });
      document.getElementById('dl-stepper').hidden = true;
    },
  });
  const viewUrlParams = () => (polygon.polygonMode() ? polygon.urlParams() : urlParams());
  document.getElementById('dl-mode').addEventListener('change', (event) => {
    polygon.setMode(event.target.value);
    compute({ push: true, force: true });
  });

  function cancel() {
    if (polygon.polygonMode()) {
      polygon.cancel();
      return;
    }
    if (pendingKey === null) return;
    worker.restart(); // a wasm call cannot be interrupted
    cancelledKey = pendingKey;
    pendingKey = null;
    requestSeq++;
    ui.status.textContent = 'Cancelled; the worker was restarted.';
    setState('cancelled');
  }

  panel.listen();

  worker.on('ready', (info) => {
    setAlgorithms(info);
    if (state.active) compute();
  });
  worker.on('load-error', () => { if (state.active) compute(); });
  if (worker.info) setAlgorithms(worker.info);

  return {
    name: 'delaunay',
    render,
    resize() {
      resize();
      polygon.redraw();
    },
    activate() {
      state.active = true;
      controls.enabled = true;
      layoutPanes();
      compute();
      requestRender();
    },
    deactivate() {
      state.active = false;
      controls.enabled = false;
      showHover(-1);
    },
    applyUrl(q) {
      polygon.applyUrl(q); // the mode first: the panel's applyUrl computes
      applyUrl(q);
    },
    urlParams: viewUrlParams,
    openFile: files.openFile,
    cancel,
    fileHint: '2D points (x y per line, rbox "2 n", or OBJ/OFF/PLY/STL vertices: x and y), or a polygon (GeoJSON, Triangle .poly)',
    busyLabel: () => (state.mode === 'quality' ? 'Meshing' : 'Triangulating'),
  };
}
