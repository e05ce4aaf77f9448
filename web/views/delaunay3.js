// The Delaunay 3D view: the Hull view's point sets (or a file), their Delaunay tetrahedralization
// computed in the shared worker (hullkit.delaunay3, with its progress), drawn shrunk and cut by a
// plane; the circumsphere of the tetrahedron under the pointer with the points on it; the Voronoi
// cell of a clicked point with its volume (hullkit.voronoi3, computed in the worker after each
// tetrahedralization, in the background).
//
// This module runs the jobs (request, progress, cancel, answer) and wires the view's parts: the
// panel's inputs and URL state (delaunay3-panel.js), the three.js scene (delaunay3-scene.js) and
// the pointer (delaunay3-pick.js).
//
// Test hooks: window.hullkitDelaunay3 = {n, distinct, duplicates, tetrahedra, hullTriangles,
// triangles, dimension, ms, distribution, seed, run, voronoi, voronoiMs} after each
// tetrahedralization drawn (voronoi: true once the Voronoi diagram came);
// window.hullkitDelaunay3Cell = {point, volume, bounded, faces} for the cell shown (null when none);
// window.hullkitDelaunay3Hover and the screen hooks of delaunay3-pick.js.
import { fmtInt, fmtMs, fmtReal } from '../app/format.js';
import { writeUrl } from '../app/url-state.js';
import { showError, readFileForView, chooseFileOption } from '../app/panel.js';
import { createDelaunay3Scene } from './delaunay3-scene.js';
import { createDelaunay3Pick } from './delaunay3-pick.js';
import { delaunay3Ui, createDelaunay3Panel, planeNormal } from './delaunay3-panel.js';

const FILE_MAX = 200_000; // points of an opened file the page draws (the library takes any number)

export function createDelaunay3View({ stage, worker, setState, viewport }) {
  const ui = delaunay3Ui();
  // The view's layer over the canvas: it orbits, hovers and picks.
  const pane = Object.assign(document.createElement('div'), { className: 'pane pane-d3', hidden: true });
  pane.dataset.for = 'delaunay3';
  pane.style.inset = '0';
  viewport.append(pane);

  // What the view's parts share.
  const state = {
    active: false,
    fileInput: null, // {name, xyz}: the points of the last file opened
    job: null, // {key, params, t0, done, total}
    drawn: null, // the tetrahedralization drawn (see delaunay3-pick.js), with key, xyz, centre
    voronoi: null, // {key, volume, tetrahedronVertex, ms} of the drawn tetrahedralization
    picked: -1,
  };
  let runCount = 0;
  let drawnKey = null; // the parameters drawn
  let voronoiRequest = null; // the key of the drawn tetrahedralization whose diagram is asked for
  let cellSeq = 0;

  const scene = createDelaunay3Scene({ stage, state, pane });
  const panel = createDelaunay3Panel({ ui, state });
  const { readParams, readDisplay, urlParams } = panel;
  createDelaunay3Pick({
    scene, state, pane,
    onHover: showHover,
    onPick: pick,
    onPlaneDrag: (offset) => { panel.setOffset(offset); applyDisplay(); },
    onPlaneDragEnd: () => writeUrl('delaunay3', urlParams()),
  });

  const paramsKey = (p) => `${p.distribution}|${p.n}|${p.seed}|${p.sites}|${p.text ?? ''}|${p.file ?? ''}`;

  const describe = (p) => {
    if (p.distribution === 'custom') return 'the pasted points';
    if (p.distribution === 'file') return `${fmtInt(p.n)} points from ${p.file}`;
    return `${fmtInt(p.n)} ${p.n === 1 ? 'point' : 'points'} ${ui.distribution.selectedOptions[0]?.textContent ?? p.distribution}`;
  };

  // ------------------------------------------------------------ the tetrahedralization

  function compute({ push = false, force = false } = {}) {
    if (!worker.ready) {
      if (worker.loadError) fail(`Cannot tetrahedralize: ${worker.loadError}`, true);
      else {
        setState('loading');
        ui.status.textContent = 'Loading the WebAssembly module…';
      }
      return;
    }
    const params = readParams();
    if (params.distribution !== 'custom' && params.distribution !== 'file') panel.writeParams(params); // what was typed, made valid
    const key = paramsKey(params);
    if (!force && (key === state.job?.paramsKey || (key === drawnKey && !state.job))) return;
    // A wasm call cannot be interrupted: a run (or a Voronoi diagram) still going is dropped.
    if (state.job || voronoiRequest !== null) restartWorker();
    if (state.active && params.distribution !== 'file') writeUrl('delaunay3', urlParams(), { push });
    const job = { paramsKey: key, params, t0: performance.now(), done: 0, total: 0 };
    state.job = job;
    setState('computing');
    ui.error.hidden = true;
    ui.compute.disabled = true;
    ui.cancel.disabled = false;
    ui.status.textContent = `${busyLabel()}…`;
    const request = {
      type: 'delaunay3', distribution: params.distribution, n: params.n, seed: params.seed, text: params.text, furthestSite: params.sites === 'furthest',
    };
    if (params.distribution === 'file') request.xyz = state.fileInput.xyz.slice();
    const onProgress = ({ done, total }) => {
      if (state.job !== job) return;
      Object.assign(job, { done, total });
      ui.status.textContent = `${busyLabel()}…`;
    };
    worker.request(request, [], { onProgress }).then(
      (msg) => {
        if (state.job !== job) return;
        finishJob();
        if (msg.type !== 'result') {
          fail(`${msg.kind === 'input' ? 'Cannot tetrahedralize' : 'The tetrahedralization failed'}: ${String(msg.message).replace(/^delaunay3:\s*/, '')}`, msg.kind !== 'input');
          return;
        }
        drawnKey = key;
        try {
          show(msg, params, performance.now() - job.t0);
        } catch (err) {
          console.error(err);
          fail(`Drawing the tetrahedralization failed: ${err.message}`, true);
        }
      },
      (err) => {
        if (state.job !== job) return;
        finishJob();
        if (!err.cancelled) fail(err.message, true);
      },
    );
  }

  function busyLabel() {
    const job = state.job;
    if (!job) return 'Working';
    const progress = job.total ? ` (${Math.round((100 * job.done) / job.total)}% inserted)` : '';
    return `Tetrahedralizing ${describe(job.params)}${progress}`;
  }

  function finishJob() {
    state.job = null;
    ui.compute.disabled = false;
    ui.cancel.disabled = true;
  }

  function restartWorker() {
    worker.restart(); // every pending request rejects as cancelled
    voronoiRequest = null;
  }

  function cancel() {
    if (!state.job && voronoiRequest === null) return;
    const job = state.job;
    restartWorker();
    finishJob();
    if (job) {
      ui.status.textContent = `Cancelled after ${((performance.now() - job.t0) / 1000).toFixed(1)} s; the worker was restarted.`;
      setState('cancelled');
    } else {
      ui.stat.voronoi.textContent = 'cancelled';
    }
  }

  /** Draws the worker's answer and asks for its Voronoi diagram. */
  function show(msg, params, roundTripMs) {
    const d0 = performance.now();
    scene.draw(msg.drawing);
    if (state.active) stage.renderNow();
    const drawMs = performance.now() - d0;
    const { dimension, tetrahedra, neighbors, representative, triangles } = msg;
    const { positions, centre, boundary, distinct } = msg.drawing;
    const furthest = Boolean(msg.furthestSite);
    state.drawn = {
      key: msg.key, dimension, xyz: msg.xyz, centre, positions, tetrahedra, neighbors, representative,
      triangles, vertices: msg.vertices, boundary, distinct, furthest,
    };
    state.voronoi = null;
    state.picked = -1;
    showHover(null);
    showCell(null);
    runCount++;
    const count = tetrahedra.length / 4;
    setStats({
      n: fmtInt(msg.n), tetrahedra: fmtInt(count), hull: fmtInt(msg.hull.length / 3), ms: fmtMs(msg.ms),
      voronoi: dimension === 3 ? 'computing…' : '—', rtt: fmtMs(roundTripMs), dup: fmtInt(msg.duplicateCount), draw: fmtMs(drawMs),
    });
    ui.stat.ms.title = `hullkit.delaunay3() inside the worker; points ${params.distribution === 'file' ? 'copied' : 'generated'} in ${fmtMs(msg.genMs)}`;
    ui.stat.draw.title = `the first render of the geometry on the main thread (prepared in the worker in ${fmtMs(msg.drawingMs)})`;
    const n = distinct.length;
    const what = describe({ ...params, n: msg.n });
    const corners = new Set(tetrahedra).size;
    let status = {
      3: () => (furthest
        ? `${what}, furthest sites: ${fmtInt(count)} tetrahedra on the hull's ${fmtInt(corners)} corners (the upper lifted hull). Every circumsphere holds every point; the points inside the hull are in no tetrahedron; none is flat.`
        : `${what}: ${fmtInt(count)} tetrahedra, ${fmtInt(msg.hull.length / 3)} hull triangles. No point lies inside any circumsphere, and no tetrahedron is flat.`),
      2: () => `${what}: all on one plane, so no tetrahedra: their ${furthest ? 'furthest-site' : 'Delaunay'} triangulation in that plane, ${fmtInt(triangles.length / 3)} triangles (drawn flat).`,
      1: () => `${what}: all on one line, so no tetrahedra (${fmtInt(n)} distinct points).`,
      0: () => `${what}: one distinct point, no tetrahedra.`,
    }[dimension]?.() ?? 'No points.';
    if (msg.duplicateCount) status += ` ${fmtInt(msg.duplicateCount)} exact duplicates merged into their first copy.`;
    ui.status.textContent = status;
    window.hullkitDelaunay3 = {
      n: msg.n, distinct: n, duplicates: msg.duplicateCount, tetrahedra: count, hullTriangles: msg.hull.length / 3,
      triangles: triangles.length / 3, dimension, ms: msg.ms, drawMs, distribution: params.distribution, seed: params.seed,
      run: runCount, voronoi: false, voronoiMs: null, sites: furthest ? 'furthest' : 'nearest', corners,
    };
    setState('ready');
    requestVoronoi();
  }

  function fail(message, logged) {
    showError(ui.error, message, logged);
    ui.status.textContent = '';
    setState('error');
  }

  function setStats(values) {
    for (const [key, el] of Object.entries(ui.stat)) {
      el.textContent = values[key] ?? '—';
      el.title = '';
    }
  }

  // ------------------------------------------------------------ the Voronoi diagram and cells

  /** The drawn tetrahedralization's arrays, for a worker that no longer has them (restarted). */
  function drawnPoints() {
    const d = state.drawn;
    return {
      xyz: d.xyz, dimension: d.dimension, tetrahedra: d.tetrahedra, neighbors: d.neighbors, triangles: d.triangles,
      vertices: d.vertices, representative: d.representative, furthestSite: d.furthest,
    };
  }

  function requestVoronoi(resend = false) {
    const d = state.drawn;
    if (!d || d.dimension !== 3) return;
    const key = d.key;
    voronoiRequest = key;
    worker.request({ type: 'delaunay3-voronoi', key, points: resend ? drawnPoints() : undefined }).then((msg) => {
      if (state.drawn?.key !== key || voronoiRequest !== key) return;
      if (msg.type === 'error' && msg.kind === 'stale' && !resend) {
        requestVoronoi(true);
        return;
      }
      voronoiRequest = null;
      if (msg.type !== 'result') {
        ui.stat.voronoi.textContent = 'failed';
        console.error(`[hullkit] the Voronoi diagram failed: ${msg.message}`);
        return;
      }
      state.voronoi = { key, volume: msg.volume, tetrahedronVertex: msg.tetrahedronVertex, ms: msg.ms };
      ui.stat.voronoi.textContent = fmtMs(msg.ms);
      ui.stat.voronoi.title = `hullkit.voronoi3() inside the worker: ${fmtInt(msg.vertexCount)} vertices, ${fmtInt(msg.faceCount)} faces`;
      Object.assign(window.hullkitDelaunay3, { voronoi: true, voronoiMs: msg.ms });
      if (state.picked >= 0) fetchCell(state.picked);
    }, (err) => {
      if (voronoiRequest === key) voronoiRequest = null;
      if (!err.cancelled) console.error(`[hullkit] the Voronoi diagram failed: ${err.message}`);
    });
  }

  function pick(point) {
    state.picked = point;
    if (point < 0) {
      showCell(null);
      return;
    }
    const d = state.drawn;
    if (d.dimension !== 3) {
      ui.cell.textContent = `Point ${point}: without tetrahedra every Voronoi cell is unbounded.`;
      return;
    }
    if (!state.voronoi) {
      ui.cell.textContent = `Point ${point}: waiting for the Voronoi diagram…`;
      if (voronoiRequest === null) requestVoronoi();
      return;
    }
    fetchCell(point);
  }

  function fetchCell(point) {
    const key = state.drawn.key;
    const seq = ++cellSeq;
    worker.request({ type: 'delaunay3-cell', key, point }).then((msg) => {
      if (seq !== cellSeq || state.drawn?.key !== key || state.picked !== point) return;
      if (msg.type === 'error' && msg.kind === 'stale') {
        // The worker was restarted since: the diagram again, from the arrays drawn; then the cell.
        state.voronoi = null;
        ui.cell.textContent = `Point ${point}: computing the Voronoi diagram again…`;
        requestVoronoi(true);
        return;
      }
      if (msg.type !== 'result') {
        ui.cell.textContent = `Point ${point}: ${msg.message}`;
        return;
      }
      showCell(msg);
    }, (err) => {
      if (!err.cancelled) console.error(`[hullkit] a Voronoi cell failed: ${err.message}`);
    });
  }

  function showCell(cell) {
    if (!cell) {
      scene.showCell(null);
      ui.cell.textContent = 'Click (or tap) a point to see its Voronoi cell.';
      window.hullkitDelaunay3Cell = null;
      return;
    }
    const { centre, positions } = state.drawn;
    const vertices = Float64Array.from(cell.vertices, (v, i) => v - centre[i % 3]);
    const p = cell.point;
    scene.showCell({ ...cell, vertices, point: positions.subarray(3 * p, 3 * p + 3) });
    const faces = cell.faceOffsets.length - 1;
    const [x, y, z] = state.drawn.xyz.subarray(3 * p, 3 * p + 3);
    const at = `Point ${p} (${fmtReal(x)}, ${fmtReal(y)}, ${fmtReal(z)})`;
    ui.cell.innerHTML = '';
    const strong = document.createElement('strong');
    if (state.drawn.furthest) {
      strong.textContent = faces ? 'unbounded' : 'empty';
      ui.cell.append(faces ? `${at}: its furthest-site cell (where it is the farthest point) is ` : `${at} is no corner of the hull: its furthest-site cell is `, strong,
        faces ? `, as every one is; ${fmtInt(faces)} faces, the part near the points drawn.` : ' (no point of space has it farthest).');
    } else if (cell.bounded) {
      strong.textContent = `volume ${fmtReal(cell.volume)}`;
      ui.cell.append(`${at}: its Voronoi cell has `, strong, `, ${fmtInt(faces)} faces (one per Delaunay neighbour), ${fmtInt(cell.vertices.length / 3)} vertices at circumcentres.`);
    } else {
      strong.textContent = 'unbounded';
      ui.cell.append(`${at} is on the convex hull: its Voronoi cell is `, strong, ` (volume ∞); ${fmtInt(faces)} faces, the part near the points drawn.`);
    }
    ui.cell.title = cell.bounded ? `volume ${cell.volume}` : '';
    window.hullkitDelaunay3Cell = { point: p, volume: cell.volume, bounded: cell.bounded, faces, neighbours: Array.from(cell.neighbours) };
  }

  // ------------------------------------------------------------ hover

  function showHover(hover) {
    scene.showHover(hover);
    window.hullkitDelaunay3Hover = hover
      ? { tetrahedron: hover.tetrahedron, corners: hover.cornerIndices, centre: hover.centre, radius: hover.radius, onSphere: hover.points, exact: hover.exact }
      : null;
    if (!hover) {
      ui.hover.textContent = state.drawn?.furthest
        ? 'Hover (or tap) a tetrahedron to see its circumsphere, which holds every point.'
        : 'Hover (or tap) a tetrahedron to see its empty circumsphere.';
      return;
    }
    const extra = hover.points.length - 4;
    const [inside, none] = state.drawn?.furthest ? ['outside', 'every other point inside it'] : ['inside', 'no other point on or inside its sphere.'];
    ui.hover.textContent = `Tetrahedron ${fmtInt(hover.tetrahedron)} (points ${hover.cornerIndices.join(', ')}): circumradius ${fmtReal(hover.radius)}; ` +
      (extra > 0 ? `${extra} more ${extra === 1 ? 'point lies' : 'points lie'} exactly on its sphere (cospherical), none ${inside}.` : state.drawn?.furthest ? `${none}.` : none) +
      (hover.exact ? '' : ' (Cospherical points show once the Voronoi diagram is in.)');
  }

  // ------------------------------------------------------------ display

  function applyDisplay() {
    const d = readDisplay();
    scene.setShrink(d.shrink);
    scene.setCut({ mode: d.cut, normal: planeNormal(d.azimuth, d.elevation), offset: d.offset });
  }

  // ------------------------------------------------------------ files

  async function openFile(file) {
    const msg = await readFileForView(worker, file, 'points', { ui, onError: (message) => fail(message, false) });
    if (!msg) return;
    const count = msg.xyz.length / 3;
    if (count > FILE_MAX) {
      fail(`${file.name} has ${fmtInt(count)} points; this page tetrahedralizes at most ${fmtInt(FILE_MAX)} (the hullkit command and hullkit.delaunay3 take any number).`, false);
      return;
    }
    state.fileInput = { name: file.name, xyz: msg.xyz };
    chooseFileOption(ui.distribution, file.name);
    panel.updateSourceFields();
    compute({ push: true, force: true });
  }

  // ------------------------------------------------------------ wiring

  ui.form.addEventListener('submit', (event) => {
    event.preventDefault();
    compute({ push: true, force: true });
  });
  ui.cancel.addEventListener('click', cancel);
  panel.listen({ compute, applyDisplay, scene });
  applyDisplay();
  scene.warmUpShaders();
  worker.on('ready', () => { if (state.active) compute(); });
  worker.on('load-error', () => { if (state.active) compute(); });

  return {
    name: 'delaunay3',
    render: scene.render,
    resize: scene.resize,
    activate() {
      state.active = true; // main.js shows the pane (data-for) with the panel
      scene.controls.enabled = true;
      compute();
      scene.requestRender();
    },
    deactivate() {
      state.active = false;
      scene.controls.enabled = false;
      showHover(null);
    },
    /** The URL changed (back/forward, or the first load): its options, and a new run if they differ. */
    applyUrl(q) {
      panel.applyUrl(q);
      applyDisplay();
      if (state.active) compute();
    },
    urlParams,
    openFile,
    cancel,
    fileHint: 'points from OBJ, OFF, PLY, STL, glTF or x y z text',
    busyLabel,
  };
}
