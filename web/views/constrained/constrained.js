// The Delaunay view's constrained modes: "constrained" triangulates a polygon with holes (or a
// planar graph from a .poly file) so that its edges are edges of the result; "quality mesh" also
// refines it to a minimum angle and an optional maximum area. The polygon is drawn by clicks
// (constrained/rings.js), starts as a sample with two holes, or comes from a GeoJSON or .poly file
// (read in the worker by polygons.js). Every change is triangulated in the worker
// (hullkit.triangulatePolygon, or constrainedDelaunay for a graph), one request at a time: while
// one runs, only the latest polygon follows. The triangulation is drawn by delaunay-draw.js, the
// constraints and added points over it by constrained/draw.js, and a note says what the
// constraints change: triangles, constrained edges, points added, the smallest angle, and how
// many of the polygon's edges the unconstrained Delaunay triangulation of the same vertices lacks.
//
// Test hook: window.hullkitConstrained = {mode, source, rings, open, points, triangles, edges,
// constrainedEdges, inputCount, addedCount, crossingCount, steinerCount, unrefinedCount,
// polygonEdges, notDelaunay, smallestAngle, belowBound, angleBound, maxArea, keepSegments, largestArea, graph,
// wholeHull, error, run} after each result (or error) shown; non-enumerable `coords`,
// `triangleList` and `constrainedList` (per half-edge) hold the arrays.
import { fmtInt, fmtMs } from '../../app/format.js';
import { writeUrl, correctUrl } from '../../app/url-state.js';
import { showError } from '../../app/panel.js';
import { SAMPLE_RINGS, smallestAngle, countEdges } from '../../polygons.js';
import { createConstrainedDrawing } from './draw.js';
import { createRingEditor } from './rings.js';
import { MODES, ANGLE_DEFAULT, polygonUi, parseAngle, parseArea, parseKeep, showModeElements, encodeRings, decodeRings } from './panel.js';

// A maximum area that asks for more triangles than this (the drawing's box over the area) is
// refused before it reaches the worker, and refinement stops with hullkit's message after adding
// as many points (maxSteinerPoints): the page draws every triangle.
const ESTIMATE_MAX = 500_000;

/**
 * The model edited: points and the rings through them (closed rings, and the open one being
 * drawn), a graph's segments and hole points (Triangle's .poly), where it came from.
 *   {source: 'sample' | 'drawn' | 'file', name, points: [[x, y]], rings: [[i]], open: [i],
 *    segments: [i, j, ...], holes: [x, y, ...], graph, fixed}
 * `graph`: triangulated as Triangle does (constrainedDelaunay of every point, the exterior and the
 * hole regions removed); `fixed`: how many of the points are the file's (all triangulated).
 */
function emptyModel(source = 'drawn', name = '') {
  return { source, name, points: [], rings: [], open: [], segments: [], holes: [], graph: false, fixed: 0 };
}

function ringsModel(rings, source, name) {
  const model = emptyModel(source, name);
  for (const ring of rings) model.rings.push(ring.map((p) => model.points.push([p[0], p[1]]) - 1));
  return model;
}

const sampleModel = () => ringsModel(SAMPLE_RINGS, 'sample', 'the sample polygon');

/** The model of a polygon file the worker read ({kind: 'rings', xy, starts} or {kind: 'poly', xy, segments, holes}). */
function fileModel(polygon, name) {
  const model = emptyModel('file', name);
  const { xy } = polygon;
  for (let i = 0; i < xy.length; i += 2) model.points.push([xy[i], xy[i + 1]]);
  if (polygon.kind === 'poly') {
    Object.assign(model, { segments: Array.from(polygon.segments), holes: Array.from(polygon.holes), graph: true, fixed: model.points.length });
  } else {
    const { starts } = polygon;
    for (let r = 0; r + 1 < starts.length; r++) model.rings.push(Array.from({ length: starts[r + 1] - starts[r] }, (_, k) => starts[r] + k));
  }
  return model;
}

function boundsOf(points, fallback) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const [x, y] of points) {
    x0 = Math.min(x0, x); x1 = Math.max(x1, x);
    y0 = Math.min(y0, y); y1 = Math.max(y1, y);
  }
  if (!(x0 <= x1)) return fallback;
  return { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, r: Math.max((x1 - x0) / 2, (y1 - y0) / 2) || 0.5 };
}

const plural = (n, one, many = `${one}s`) => `${fmtInt(n)} ${n === 1 ? one : many}`;
const degrees = (d) => `${(Math.floor(d * 10) / 10).toFixed(1)}°`; // never more than it is

/**
 * The constrained modes of the Delaunay view over its `ui` (delaunayUi), shared `state`
 * (state.mode: 'unconstrained' | 'constrained' | 'quality'), `scene` and `drawing`; `setStats`
 * fills the stats panel, `hideStepper` takes the lifted gift wrap away, `exportButtons` are
 * enabled with a result.
 */
export function createConstrainedMode({ ui, state, scene, drawing, worker, setState, setStats, hideStepper, exportButtons }) {
  const pui = polygonUi();
  const cdraw = createConstrainedDrawing({ scene, state });
  let model = sampleModel();
  let geometryVersion = 0; // changes with what is triangulated (not with the open ring)
  let inFlight = false;
  let dirty = false;
  let sentKey = null;
  let drawnKey = null;
  let cancelledKey = null;
  let requestSeq = 0;
  let runCount = 0;
  let last = null; // {msg, key}: the result drawn, redrawn after a resize
  let badPoint = -1;

  const polygonMode = () => state.mode === 'constrained' || state.mode === 'quality';

  // ------------------------------------------------------------ what is asked

  function options() {
    if (state.mode !== 'quality') return {};
    const opts = { minAngle: parseAngle(pui.minAngle.value), maxSteinerPoints: ESTIMATE_MAX };
    const area = parseArea(pui.maxArea.value);
    if (area !== null) opts.maxArea = area;
    if (pui.conforming.checked) opts.conforming = true;
    const keep = parseKeep(pui.keep.value);
    if (keep !== 'none') opts.keepSegments = keep;
    return opts;
  }

  /** What the worker is sent: the graph's points and the closed rings', renumbered; `sent[k]` is point k's index in the model. */
  function request() {
    const sent = [];
    const index = new Map();
    const use = (i) => {
      if (!index.has(i)) index.set(i, sent.push(i) - 1);
      return index.get(i);
    };
    for (let i = 0; i < model.fixed; i++) use(i);
    const rings = model.rings.map((ring) => ring.map(use));
    const segments = Uint32Array.from(model.segments.map(use));
    const coords = new Float64Array(2 * sent.length);
    sent.forEach((i, k) => coords.set(model.points[i], 2 * k));
    return { coords, rings, segments, holes: Float64Array.from(model.holes), regions: model.graph, sent };
  }

  const hasGeometry = () => model.rings.length > 0 || model.segments.length > 0 || model.fixed > 0;

  // ------------------------------------------------------------ triangulating

  /** Asks the worker for the triangulation of the model (`live`: while dragging, no busy state, no URL). */
  function compute({ push = false, force = false, live = false } = {}) {
    if (!state.active || !polygonMode()) return;
    if (!live) writeUrl('delaunay', urlParams(), { push });
    if (!worker.ready) {
      setState('loading');
      ui.status.textContent = worker.loadError ? '' : 'Loading the WebAssembly module…';
      if (worker.loadError) fail(`Cannot triangulate: ${worker.loadError}`, { logged: true });
      return;
    }
    const opts = options();
    const key = `${geometryVersion}|${state.mode}|${JSON.stringify(opts)}`;
    if (inFlight) {
      dirty = key !== sentKey;
      return;
    }
    if (!force && (key === drawnKey || key === cancelledKey)) return;
    cancelledKey = null;
    if (!hasGeometry()) {
      showEmpty(key);
      return;
    }
    if (opts.maxArea !== undefined) {
      const { r } = boundsOf(model.points, state.extent);
      const estimate = (4 * r * r) / opts.maxArea;
      if (estimate > ESTIMATE_MAX) {
        drawnKey = key;
        fail(`A maximum area of ${opts.maxArea} asks for about ${fmtInt(Math.round(estimate))} triangles; this page draws at most ${fmtInt(ESTIMATE_MAX)}: take a larger one (or none).`);
        return;
      }
    }
    const req = request();
    inFlight = true;
    dirty = false;
    sentKey = key;
    const id = ++requestSeq;
    const t0 = performance.now();
    if (!live) {
      setState('computing');
      ui.status.textContent = state.mode === 'quality' ? 'Meshing…' : 'Triangulating…';
    }
    const { sent, ...message } = req;
    worker.request({ type: 'constrained', ...message, options: opts }).then(
      (msg) => {
        if (id !== requestSeq) return;
        inFlight = false;
        if (msg.type === 'result') show(msg, key, sent, performance.now() - t0);
        else {
          drawnKey = key;
          const point = Number.isInteger(msg.pointIndex) ? sent[msg.pointIndex] : -1;
          const prefix = msg.kind === 'input' ? 'Cannot triangulate' : 'Triangulation failed';
          fail(`${prefix}: ${String(msg.message)}`, { point, logged: msg.kind !== 'input' });
        }
        if (dirty) compute({ live: true });
      },
      (err) => {
        if (id !== requestSeq) return;
        inFlight = false;
        if (!err.cancelled) fail(err.message);
      },
    );
  }

  /** Nothing closed yet: nothing to triangulate, say how to start. */
  function showEmpty(key) {
    drawnKey = key;
    last = null;
    badPoint = -1;
    place();
    cdraw.clearResult();
    cdraw.drawEditing(model);
    state.tri = null;
    state.lastExport = null;
    for (const b of exportButtons) b.disabled = true;
    ui.error.hidden = true;
    setStats({});
    pui.note.textContent = 'Click in the plane to draw the outline: each click adds a vertex; click the first vertex (or press Enter) to close the ring. The rings drawn next are holes.';
    describeInput();
    publish({ triangles: 0, error: null });
    hideStepper();
    setState('ready');
  }

  function show(msg, key, sent, roundTripMs) {
    drawnKey = key;
    last = { msg, key };
    badPoint = -1;
    const { coords, triangles, halfedges, constrained } = msg;
    state.xy = coords;
    state.tri = { triangles, halfedges, hull: new Uint32Array(0), dimension: 2, duplicateCount: msg.duplicateCount };
    state.cells = null;
    state.lastTriangle = 0;
    place();
    drawing.drawTriangulation();
    cdraw.drawResult(msg);
    cdraw.drawEditing(model);
    const count = triangles.length / 3;
    const { edges, constrainedEdges } = countEdges(halfedges, constrained);
    const bound = state.mode === 'quality' ? parseAngle(pui.minAngle.value) : null;
    const angle = smallestAngle(coords, triangles, bound);
    const largestArea = largestTriangleArea(coords, triangles);
    const maxArea = state.mode === 'quality' ? parseArea(pui.maxArea.value) : null;
    setStats({
      n: fmtInt(coords.length / 2), triangles: fmtInt(count), hull: fmtInt(constrainedEdges),
      ms: fmtMs(msg.ms), rtt: fmtMs(roundTripMs), dup: fmtInt(msg.addedCount),
    });
    ui.stat.ms.title = `${msg.graph ? 'hullkit.constrainedDelaunay' : 'hullkit.triangulatePolygon'}() inside the worker; the unconstrained hullkit.delaunay() of the same vertices took ${fmtMs(msg.delaunayMs)}`;
    ui.error.hidden = true;
    pui.note.textContent = noteText(msg, { count, constrainedEdges, angle, bound, largestArea, maxArea });
    describeInput(count);
    state.lastExport = {
      xy: coords, triangles, hull: new Uint32Array(0), cells: null,
      name: `${model.source === 'file' ? model.name.replace(/\.[^.]*$/, '') : 'polygon'}-${state.mode === 'quality' ? 'quality-mesh' : 'constrained'}`,
      title: state.mode === 'quality' ? 'Quality mesh' : 'Constrained Delaunay triangulation',
    };
    for (const b of exportButtons) b.disabled = count === 0;
    hideStepper();
    publish({
      triangles: count, edges, constrainedEdges, inputCount: msg.inputCount, addedCount: msg.addedCount,
      crossingCount: msg.crossingCount, steinerCount: msg.steinerCount, unrefinedCount: msg.unrefinedCount,
      polygonEdges: msg.polygonEdges, notDelaunay: msg.notDelaunay, smallestAngle: angle.degrees, belowBound: angle.below,
      angleBound: bound, maxArea, keepSegments: state.mode === 'quality' ? parseKeep(pui.keep.value) : null, largestArea, graph: msg.graph, wholeHull: msg.wholeHull, error: null,
    }, { coords, triangles, constrained });
    setState('ready');
    scene.requestRender();
  }

  function largestTriangleArea(coords, triangles) {
    let largest = 0;
    for (let t = 0; t < triangles.length; t += 3) {
      const [a, b, c] = [triangles[t], triangles[t + 1], triangles[t + 2]];
      const area = Math.abs((coords[2 * b] - coords[2 * a]) * (coords[2 * c + 1] - coords[2 * a + 1]) -
        (coords[2 * b + 1] - coords[2 * a + 1]) * (coords[2 * c] - coords[2 * a])) / 2;
      largest = Math.max(largest, area);
    }
    return largest;
  }

  /** What the constraints change, in words. */
  function noteText(msg, { count, constrainedEdges, angle, bound, largestArea, maxArea }) {
    const parts = [];
    const crossings = msg.crossingCount ?? 0;
    const steiner = msg.steinerCount ?? 0;
    if (state.mode === 'quality') {
      const keep = parseKeep(pui.keep.value);
      let s = `Smallest angle ${Number.isFinite(angle.degrees) ? degrees(angle.degrees) : '—'} (bound ${bound}°)`;
      if (angle.below) s += `: ${plural(angle.below, 'triangle')} below it`;
      s += `; ${plural(steiner, 'Steiner point')} added by refinement`;
      if (msg.unrefinedCount) {
        s += `, ${plural(msg.unrefinedCount, 'triangle')} left below the bound at small input angles${keep === 'none' ? '' : ' or next to segments kept whole'}`;
      }
      parts.push(`${s}. Largest triangle area ${Number(largestArea.toPrecision(3))}${maxArea !== null ? ` (bound ${maxArea})` : ''}.`);
      if (keep !== 'none') {
        parts.push(`${keep === 'all' ? 'Every segment is' : 'The boundary\'s segments are'} kept whole (no point added on ${keep === 'all' ? 'them' : 'the rings'}): next to them the angle bound is not guaranteed.`);
      }
    }
    let cdt = `${plural(count, 'triangle')}, ${plural(constrainedEdges, 'constrained edge')}, `;
    cdt += msg.addedCount ? `${plural(msg.addedCount, 'point')} added${crossings ? ` (${fmtInt(crossings)} where constraints cross)` : ''}` : 'no points added';
    if (state.mode !== 'quality' && Number.isFinite(angle.degrees)) cdt += `; smallest angle ${degrees(angle.degrees)}`;
    parts.push(`${cdt}.`);
    const { polygonEdges: edges, notDelaunay: missing } = msg;
    if (edges > 0) {
      parts.push(missing
        ? `Without constraints, the Delaunay triangulation of the same vertices cuts across the polygon: ${fmtInt(missing)} of its ${plural(edges, 'edge')} ${missing === 1 ? 'is' : 'are'} not Delaunay edges; the constraints put them in and triangulate around them.`
        : `Here all ${plural(edges, 'polygon edge')} are edges of the unconstrained Delaunay triangulation too: the constraints only remove the holes and the outside.`);
    }
    if (msg.graph) {
      parts.push(msg.wholeHull
        ? `The segments enclose no region, so the whole convex hull is triangulated (as triangle -pc)${model.holes.length ? ' and the hole points are ignored' : ''}.`
        : `As Triangle does: what lies outside the segments${model.holes.length ? ` and the regions around the ${plural(model.holes.length / 2, 'hole point')}` : ''} removed.`);
    }
    return parts.join(' ');
  }

  /** The status line: where the polygon comes from and what is being drawn. */
  function describeInput(count = null) {
    const from = model.source === 'file' ? `${model.name}${model.edited ? ' (edited)' : ''}` : model.source === 'sample' ? 'Sample polygon' : 'Drawn';
    const closed = model.graph ? `${plural(model.fixed, 'point')}, ${plural(model.segments.length / 2, 'segment')}` : plural(model.rings.length, 'ring');
    let text = `${from}: ${closed}${model.graph && model.rings.length ? ` and ${plural(model.rings.length, 'drawn ring')}` : ''}`;
    if (count !== null) text += ` → ${plural(count, 'triangle')}`;
    text += '.';
    if (model.open.length) {
      text += ` Drawing ring ${model.rings.length + 1}: ${plural(model.open.length, 'vertex', 'vertices')}` +
        (model.open.length >= 3 ? '; click its first vertex or press Enter to close it.' : ' (3 at least to close it).');
    }
    ui.status.textContent = text;
  }

  function fail(message, { point = -1, logged = false } = {}) {
    last = null;
    badPoint = point;
    place();
    cdraw.clearResult();
    cdraw.drawEditing(model, { badPoint });
    state.tri = null;
    state.lastExport = null;
    for (const b of exportButtons) b.disabled = true;
    showError(ui.error, message, logged);
    pui.note.textContent = `Nothing triangulated: the rings are drawn as they are${point >= 0 ? '; the red ring marks the vertex the message names' : ''}.`;
    describeInput();
    hideStepper();
    publish({ triangles: 0, error: message });
    setState('error');
    scene.requestRender();
  }

  function publish(values, arrays = null) {
    runCount++;
    window.hullkitConstrained = {
      mode: state.mode, source: model.source, rings: model.rings.length, open: model.open.length, points: model.points.length,
      ...values, run: runCount,
    };
    const hook = window.hullkitConstrained;
    Object.defineProperty(hook, 'coords', { value: arrays ? Array.from(arrays.coords) : [] });
    Object.defineProperty(hook, 'triangleList', { value: arrays ? Array.from(arrays.triangles) : [] });
    Object.defineProperty(hook, 'constrainedList', { value: arrays ? Array.from(arrays.constrained) : [] });
  }

  // ------------------------------------------------------------ editing

  /** The model changed what is triangulated (true) or only the open ring (false). */
  function edited(geometry, { push = true, live = false } = {}) {
    if (model.source === 'sample') model.source = 'drawn';
    if (model.source === 'file') model.edited = true;
    cdraw.drawEditing(model, { badPoint: geometry ? -1 : badPoint });
    pui.closeRing.disabled = model.open.length < 3;
    pui.undoVertex.disabled = model.open.length === 0;
    if (geometry) {
      geometryVersion++;
      compute({ push, live });
    } else {
      describeInput(last ? last.msg.triangles.length / 3 : null);
      if (!live) writeUrl('delaunay', urlParams(), { push });
      if (window.hullkitConstrained) Object.assign(window.hullkitConstrained, { open: model.open.length, points: model.points.length, source: model.source });
    }
  }

  const inClosedGeometry = (i) => i < model.fixed || model.rings.some((ring) => ring.includes(i)) || model.segments.includes(i);

  createRingEditor({
    scene, state,
    editing: () => state.active && polygonMode(),
    model: () => model,
    onAdd(x, y) {
      model.open.push(model.points.push([x, y]) - 1);
      edited(false);
    },
    onClose: closeRing,
    onUndo: undoVertex,
    onMove(i, x, y) {
      model.points[i] = [x, y];
      edited(inClosedGeometry(i), { live: true });
    },
    onMoveEnd() {
      writeUrl('delaunay', urlParams(), { push: true });
    },
  });

  function closeRing() {
    if (model.open.length < 3) {
      if (model.open.length) ui.status.textContent = `A ring needs 3 vertices at least; this one has ${model.open.length}.`;
      return;
    }
    model.rings.push(model.open);
    model.open = [];
    edited(true);
  }

  function undoVertex() {
    if (!model.open.length) return;
    const i = model.open.pop();
    if (i === model.points.length - 1 && !inClosedGeometry(i)) model.points.pop();
    edited(false);
  }

  /** A new model: framed, drawn, triangulated. */
  function load(next, { push = true } = {}) {
    model = next;
    geometryVersion++;
    frame();
    cdraw.drawEditing(model);
    pui.closeRing.disabled = model.open.length < 3;
    pui.undoVertex.disabled = model.open.length === 0;
    compute({ push, force: true });
  }

  /** Fits both panes to the model (a model with no points keeps the frame it has). */
  function frame() {
    if (!polygonMode()) return;
    state.extent = boundsOf(model.points, state.extent);
    state.framed = false;
    place();
  }

  /** Lays the panes out; frames the 3D pane once it has a size (not before the view is shown). */
  function place() {
    scene.layoutPanes();
    if (!state.framed && scene.panes.a.w > 1 && scene.panes.a.h > 1) {
      scene.frame3d();
      state.framed = true;
    }
  }

  pui.closeRing.addEventListener('click', closeRing);
  pui.undoVertex.addEventListener('click', undoVertex);
  pui.clearRings.addEventListener('click', () => {
    model = emptyModel('drawn');
    edited(true);
  });
  pui.sample.addEventListener('click', () => load(sampleModel()));
  pui.minAngle.addEventListener('input', () => {
    pui.minAngleValue.textContent = `${parseAngle(pui.minAngle.value)}°`;
    compute({ live: true });
  });
  pui.minAngle.addEventListener('change', () => compute({ push: true }));
  pui.maxArea.addEventListener('change', () => compute({ push: true }));
  pui.conforming.addEventListener('change', () => compute({ push: true }));
  pui.keep.addEventListener('change', () => compute({ push: true }));
  ui.layout.addEventListener('change', () => redraw());

  /** The drawing again at the panes' new size (edge widths and markers are in pixels). */
  function redraw() {
    if (!polygonMode()) return;
    if (last && last.key === drawnKey) {
      drawing.drawTriangulation();
      cdraw.drawResult(last.msg);
    }
    cdraw.drawEditing(model, { badPoint });
  }

  // ------------------------------------------------------------ modes, URL, files

  /** Shows `mode`'s panel and drawing (the caller computes). */
  function setMode(mode) {
    const was = state.mode;
    state.mode = MODES.includes(mode) ? mode : 'unconstrained';
    pui.mode.value = state.mode;
    showModeElements(state.mode, ui.stat);
    if (was !== state.mode) {
      requestSeq++; // an answer for the other mode is dropped
      inFlight = false;
      drawnKey = null;
      state.framed = false;
    }
    if (!polygonMode()) {
      cdraw.drawEditing(null);
      scene.layoutPanes();
      return;
    }
    pui.closeRing.disabled = model.open.length < 3;
    pui.undoVertex.disabled = model.open.length === 0;
    if (!state.framed) frame();
    else place();
    cdraw.drawEditing(model, { badPoint });
  }

  function urlParams() {
    const p = { mode: state.mode, layout: ui.layout.value === 'blend' ? 'blend' : undefined };
    if (state.mode === 'quality') {
      const angle = parseAngle(pui.minAngle.value);
      p.angle = angle === ANGLE_DEFAULT ? undefined : angle;
      p.area = parseArea(pui.maxArea.value) ?? undefined;
      p.conforming = pui.conforming.checked ? 1 : undefined;
      const keep = parseKeep(pui.keep.value);
      p.keep = keep === 'none' ? undefined : keep;
    }
    if (model.source === 'drawn') Object.assign(p, encodeRings(model));
    return p;
  }

  /** The URL's mode, quality options and drawn rings (before the Delaunay panel reads the rest and computes). */
  function applyUrl(q) {
    const angle = parseAngle(q.get('angle'));
    pui.minAngle.value = String(angle);
    pui.minAngleValue.textContent = `${angle}°`;
    pui.maxArea.value = String(parseArea(q.get('area')) ?? '');
    pui.conforming.checked = q.get('conforming') === '1';
    pui.keep.value = parseKeep(q.get('keep'));
    correctUrl({ angle });
    const drawn = decodeRings(q.get('rings'), q.get('open'));
    const before = model;
    if (drawn) model = { ...emptyModel('drawn'), ...drawn };
    else if (model.source !== 'file') model = sampleModel();
    if (model !== before) {
      geometryVersion++;
      state.framed = false;
    }
    setMode(q.get('mode'));
  }

  /** A GeoJSON or .poly file read by the worker: the polygon to triangulate (a mode with constraints). */
  function openPolygon(name, polygon) {
    if (!polygonMode()) setMode('constrained');
    load(fileModel(polygon, name));
  }

  function cancel() {
    if (!inFlight) return false;
    worker.restart(); // a wasm call cannot be interrupted
    cancelledKey = sentKey;
    inFlight = false;
    dirty = false;
    requestSeq++;
    ui.status.textContent = 'Cancelled; the worker was restarted.';
    setState('cancelled');
    return true;
  }

  return { polygonMode, compute, setMode, applyUrl, urlParams, openPolygon, cancel, redraw };
}
