// The Route view: a traverse moved along legs past obstacles; a leg moves it in a straight line
// and may turn it (waypoints carry a rotation: the ring around a waypoint's handle sets its yaw).
// Each leg's swept volume is drawn as the hulls of its sub-intervals (one for a leg that does not
// turn; hullkit.hull of the traverse's vertices at both ends of each), green when the leg is clear
// and red when it hits; the traverse is ghosted at its first contact; the per-leg table shows
// status, fraction, obstacle and clearance from hullkit's RouteChecker (kept in the worker, so
// dragging a waypoint re-checks without rebuilding the scene). An overlay draws the poses of
// N-step sampling to show what it finds and misses.
//
// This module runs the checks and wires the view's parts: the three.js scene (route-scene.js),
// the handles and yaw rings under the pointer (route-handles.js), the panel's tables and the route
// in the URL (route-panel.js), files in and out (route-files.js).
//
// Test hooks: window.hullkitRoute = {preset, clear, legs: [{status, fraction, obstacle, clearance,
// sampledHit, grazing, rotation, turn (degrees), subintervals}], samples, overlay, waypoints,
// yaws (degrees per waypoint), obstacles, parts, run} after each report drawn;
// window.hullkitRouteScene() is the scene checked ({...scene, route, margin});
// window.hullkitRouteHandle(i) and window.hullkitRouteRing(i, degrees) are in route-handles.js.
import { fmtMs } from '../app/format.js';
import { writeUrl, validNumber, correctUrl } from '../app/url-state.js';
import { showError } from '../app/panel.js';
import { PRESETS, presetScene } from '../route-scenes.js';
import { copyRoute, legMotion, poseAt, positionOf, quaternionOf, waypointAt, withYaw, yawOf } from '../route-poses.js';
import { createRouteScene } from './route-scene.js';
import { createRouteHandles } from './route-handles.js';
import { SAMPLES_MAX, routeUi, legRows, showWaypoints, fmtLength, routeParam, parseRoute } from './route-panel.js';
import { createRouteFiles } from './route-files.js';

export function createRouteView({ stage, worker, setState, viewport }) {
  const ui = routeUi();
  const state = {
    active: false,
    preset: 'doorway',
    sceneJson: presetScene('doorway'),
    route: [],
    selected: -1,
    report: null,
    sweeps: [], // from the worker: [{leg, sub, of, part, points, triangles}]
    fileNote: '', // what opened files changed in the preset, for the status line
  };
  state.route = copyRoute(state.sceneJson.route);
  let runCount = 0;
  let inFlight = false;
  let dirty = false;
  let cancelled = false; // Cancel restarted the worker: do not re-run the check when it is ready

  const view3d = createRouteScene({ stage, state, viewport });
  const { requestRender } = view3d;

  // Out-of-range values become the nearest valid one (samples = 0 → 1, a margin of -2 → 0).
  const parseSamples = (text) => validNumber(text, { min: 1, max: SAMPLES_MAX, fallback: 20 });
  const parseMargin = (text, fallback) => validNumber(text, { min: 0, round: null, fallback });
  const currentSamples = () => parseSamples(ui.samples.value);
  const currentMargin = () => parseMargin(ui.margin.value, 0);
  const drawReport = () => view3d.drawReport(ui.showSamples.checked ? currentSamples() : 0);

  // ------------------------------------------------------------ checking

  /** Sends the route to the worker; while an answer is pending, only the latest route follows. */
  function check() {
    cancelled = false;
    if (!worker.ready) {
      if (worker.loadError) fail(`Cannot check the route: ${worker.loadError}`);
      else ui.status.textContent = 'Loading the WebAssembly module…';
      return;
    }
    if (inFlight) {
      dirty = true;
      return;
    }
    inFlight = true;
    dirty = false;
    const samples = currentSamples();
    const sent = copyRoute(state.route);
    const scene = { ...state.sceneJson, route: sent, margin: currentMargin() };
    const t0 = performance.now();
    if (!state.report) setState('computing');
    worker.request({ type: 'route', scene, route: sent, samples }).then(
      (msg) => {
        inFlight = false;
        if (dirty) {
          check();
          return;
        }
        if (msg.type !== 'result') {
          fail(`${msg.kind === 'input' ? 'Cannot check the route' : 'Route check failed'}: ${msg.message}`, msg.kind !== 'input');
          return;
        }
        show(msg, samples, performance.now() - t0);
      },
      (err) => {
        inFlight = false;
        if (!err.cancelled) fail(err.message, false);
      },
    );
  }

  function show(msg, samples, roundTripMs) {
    const report = msg.report;
    state.report = report;
    state.sweeps = msg.sweeps;
    ui.error.hidden = true;
    drawReport();
    runCount++;
    const turns = report.legs.map((_, i) => legMotion(state.route[i], state.route[i + 1]).degrees);
    const subintervals = report.legs.map((_, i) => msg.sweeps.find((s) => s.leg === i)?.of ?? 0);
    ui.legs.replaceChildren(...legRows(report, turns, subintervals));
    const hits = report.legs.filter((l) => l.status !== 'clear').length;
    const sampledHits = report.legs.filter((l) => l.sampled?.hit).length;
    ui.stat.verdict.textContent = report.clear ? 'clear' : `${hits} hit${hits === 1 ? '' : 's'}`;
    ui.stat.verdict.className = report.clear ? 'status-clear' : 'status-hit';
    ui.stat.clearance.textContent = fmtLength(report.min_clearance);
    ui.stat.ms.textContent = fmtMs(1000 * report.seconds);
    ui.stat.ms.title = `all legs checked in ${fmtMs(1000 * report.seconds)} inside the worker; scene prepared in ${fmtMs(1000 * (report.build_seconds ?? 0))}; round trip ${fmtMs(roundTripMs)}`;
    const missed = hits - report.legs.filter((l) => l.status !== 'clear' && l.sampled?.hit).length;
    const turning = turns.filter((d) => d > 0).length;
    const grazes = report.legs.filter((l) => l.grazing).length;
    const n = report.legs.length;
    let status = `${state.fileNote}${PRESETS[state.preset].note} ${n} leg${n === 1 ? '' : 's'}` +
      `${turning ? ` (${turning} turning, drawn as ${subintervals.filter((_, i) => turns[i] > 0).reduce((a, b) => a + b, 0)} sub-interval hulls)` : ''}: ` +
      `${hits ? `${hits} hit${hits === 1 ? '' : 's'}` : 'all clear'}${grazes ? ` (${grazes} a graze the bounds could not resolve)` : ''}` +
      ` (margin ${currentMargin()}).`;
    status += ` ${samples}-step sampling finds ${sampledHits} of ${hits}${missed > 0 ? `: it misses ${missed}` : ''}.`;
    ui.status.textContent = status;
    ui.exports.report.disabled = false;
    window.hullkitRoute = {
      obstacles: state.sceneJson.obstacles.length, parts: state.sceneJson.traverse.parts.length,
      preset: state.preset, clear: report.clear, samples, overlay: ui.showSamples.checked, waypoints: state.route.length, run: runCount,
      yaws: state.route.map(yawOf),
      legs: report.legs.map((l, i) => ({
        status: l.status, fraction: l.fraction ?? null, obstacle: l.obstacle ?? null, clearance: l.clearance ?? null,
        sampledHit: l.sampled ? l.sampled.hit : null, grazing: Boolean(l.grazing), rotation: l.rotation ?? null,
        turn: Number(turns[i].toFixed(9)), subintervals: subintervals[i],
      })),
    };
    setState('ready');
    requestRender();
  }

  function fail(message, logged = true) {
    ui.exports.report.disabled = true;
    showError(ui.error, message, logged);
    setState('error');
  }

  window.hullkitRouteScene = () => ({ ...state.sceneJson, route: copyRoute(state.route), margin: currentMargin() });

  // ------------------------------------------------------------ waypoints: drag, turn, add, remove

  /** Redraws what shows the waypoints: handles, rings and poses, the waypoints table, Remove. */
  function drawRoute() {
    view3d.drawRoute();
    showWaypoints(ui, state.route, state.selected, { onYaw: setYaw, onSelect: select });
    ui.remove.disabled = state.selected < 0 || state.route.length <= 2;
    requestRender();
  }

  function select(i) {
    state.selected = i;
    drawRoute();
  }

  function setYaw(i, degrees) {
    state.route[i] = withYaw(state.route[i], degrees);
    state.selected = i;
    routeChanged();
  }

  createRouteHandles({
    view3d, state,
    onSelect: drawRoute,
    onMove: () => { drawRoute(); check(); },
    onEnd: () => writeUrl('route', urlParams(), { push: true }),
  });

  /** A waypoint after `selected` (or the last): halfway along its leg, or beyond the last, turned alike. */
  function addWaypoint() {
    const { route } = state;
    const i = state.selected >= 0 ? state.selected : route.length - 1;
    let position, quaternion;
    if (i + 1 < route.length) {
      ({ position, quaternion } = poseAt(legMotion(route[i], route[i + 1]), 0.5));
    } else {
      const p = positionOf(route[i]);
      const prev = route[i - 1] ? positionOf(route[i - 1]) : p.map((x, k) => x - (k === 0 ? 1 : 0));
      position = p.map((x, k) => x + 0.5 * (x - prev[k]));
      quaternion = quaternionOf(route[i]);
    }
    route.splice(i + 1, 0, waypointAt(position.map((x) => Number(x.toFixed(3))), quaternion));
    state.selected = i + 1;
    routeChanged();
  }

  function removeWaypoint() {
    if (state.selected < 0 || state.route.length <= 2) return;
    state.route.splice(state.selected, 1);
    state.selected = Math.min(state.selected, state.route.length - 1);
    routeChanged();
  }

  function routeChanged() {
    drawRoute();
    writeUrl('route', urlParams(), { push: true });
    check();
  }

  ui.add.addEventListener('click', addWaypoint);
  ui.remove.addEventListener('click', removeWaypoint);
  ui.reset.addEventListener('click', () => {
    state.route = copyRoute(state.sceneJson.route);
    state.selected = -1;
    routeChanged();
  });
  document.addEventListener('keydown', (event) => {
    if (!state.active || (event.key !== 'Delete' && event.key !== 'Backspace')) return;
    if (event.target instanceof HTMLElement && event.target.closest('input, select, textarea')) return;
    removeWaypoint();
  });

  // ------------------------------------------------------------ presets, options, URL

  /** Draws a new scene (preset or file): static geometry, route, no report yet, framed. */
  function sceneChanged() {
    state.report = null;
    view3d.buildStatic();
    drawRoute();
    drawReport();
    view3d.reframe();
  }

  function loadPreset(name, waypoints = null) {
    state.preset = PRESETS[name] ? name : 'doorway';
    ui.preset.value = state.preset;
    state.sceneJson = presetScene(state.preset);
    state.fileNote = '';
    ui.margin.value = String(state.sceneJson.margin);
    state.route = waypoints ?? copyRoute(state.sceneJson.route);
    state.selected = -1;
    sceneChanged();
  }

  function urlParams() {
    const presetRoute = JSON.stringify(state.sceneJson.route);
    return {
      preset: state.preset,
      margin: currentMargin() !== state.sceneJson.margin ? currentMargin() : undefined,
      samples: currentSamples() !== 20 ? currentSamples() : undefined,
      overlay: ui.showSamples.checked ? 1 : undefined,
      route: JSON.stringify(state.route) !== presetRoute ? routeParam(state.route) : undefined,
    };
  }

  function applyUrl(q) {
    const name = PRESETS[q.get('preset')] ? q.get('preset') : 'doorway';
    loadPreset(name, parseRoute(q.get('route')));
    const margin = parseMargin(q.get('margin'), state.sceneJson.margin);
    const samples = parseSamples(q.get('samples'));
    ui.margin.value = String(margin);
    ui.samples.value = String(samples);
    correctUrl({ margin, samples }); // out-of-range values, made valid
    ui.showSamples.checked = q.get('overlay') === '1';
    if (state.active) check();
  }

  ui.form.addEventListener('submit', (event) => event.preventDefault());
  ui.preset.addEventListener('change', () => {
    loadPreset(ui.preset.value);
    writeUrl('route', urlParams(), { push: true });
    check();
  });
  for (const input of [ui.margin, ui.samples]) {
    input.addEventListener('change', () => {
      // What was typed, made valid, as the URL will say.
      ui.margin.value = String(currentMargin());
      ui.samples.value = String(currentSamples());
      writeUrl('route', urlParams(), { push: true });
      check();
    });
  }
  ui.showSamples.addEventListener('change', () => {
    drawReport();
    writeUrl('route', urlParams(), { push: true });
    if (window.hullkitRoute) window.hullkitRoute = { ...window.hullkitRoute, overlay: ui.showSamples.checked };
    requestRender();
  });

  // ------------------------------------------------------------ files in and out

  const openFile = createRouteFiles({
    ui, state, worker, margin: currentMargin, fail,
    sceneChanged: () => { sceneChanged(); check(); },
  });

  function cancel() {
    if (!inFlight) return;
    worker.restart(); // a wasm call cannot be interrupted
    inFlight = false;
    dirty = false;
    cancelled = true;
    ui.status.textContent = 'Cancelled; the worker was restarted. Move a waypoint to check again.';
    setState('cancelled');
  }

  worker.on('ready', () => { if (state.active && !cancelled) check(); });
  loadPreset('doorway');
  worker.on('load-error', () => { if (state.active) check(); });

  return {
    name: 'route',
    render: view3d.render,
    resize: view3d.resize,
    activate() {
      state.active = true;
      view3d.controls.enabled = true;
      check();
      requestRender();
    },
    deactivate() {
      state.active = false;
      view3d.controls.enabled = false;
    },
    applyUrl,
    urlParams,
    openFile,
    cancel,
    fileHint: 'a mesh (OBJ, OFF, PLY, STL, glTF) as an obstacle or the traverse',
    busyLabel: () => 'Checking the route',
  };
}
