// The Route view: a traverse moved along straight legs past obstacles. Each leg's swept hull
// (hullkit.hull of the traverse's vertices at both ends) is drawn green when the leg is clear and
// red when it hits; the traverse is ghosted at its first contact; the per-leg table shows status,
// fraction, obstacle and clearance from hullkit's RouteChecker (kept in the worker, so dragging a
// waypoint re-checks without rebuilding the scene). An overlay draws the poses of N-step sampling
// to show what it finds and misses.
//
// Test hook: window.hullkitRoute = {preset, clear, legs: [{status, fraction, obstacle, clearance,
// sampledHit}], samples, overlay, waypoints, run} after each report drawn.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { clearGroup, zUpCamera } from '../app/stage.js';
import { fmtMs } from '../app/format.js';
import { writeUrl } from '../app/url-state.js';
import { showError, readInWorker } from '../app/panel.js';
import { download } from '../app/export.js';
import { PRESETS, presetScene, partVertices, partTriangles } from '../route-scenes.js';

const COLORS = {
  obstacle: 0x8796b0,
  obstacleEdge: 0xc4cede,
  traverse: 0x5fd3e3,
  clear: 0x4ade80,
  hit: 0xff5f5f,
  ghost: 0xffb547,
  sample: 0xb8c3d6,
  handle: 0xffffff,
  selected: 0xffb547,
  route: 0xdbe3ee,
  grid: 0x243040,
};
const SAMPLES_MAX = 200;

export function createRouteView({ stage, worker, setState, viewport }) {
  const $ = (id) => document.getElementById(id);
  const ui = {
    form: $('rt-controls'), preset: $('rt-preset'), margin: $('rt-margin'), samples: $('rt-samples'), fileRole: $('rt-file-role'),
    showSamples: $('rt-show-samples'), add: $('rt-add'), remove: $('rt-remove'), reset: $('rt-reset'),
    status: $('rt-status'), error: $('rt-error'), legs: $('rt-legs').querySelector('tbody'),
    stat: { verdict: $('rt-stat-verdict'), clearance: $('rt-stat-clearance'), ms: $('rt-stat-ms') },
  };

  // The pane over the canvas takes the pointer: waypoint drags first, orbiting otherwise.
  const pane = document.createElement('div');
  pane.className = 'pane';
  pane.dataset.for = 'route';
  pane.hidden = true;
  Object.assign(pane.style, { left: 0, top: 0, right: 0, bottom: 0 });
  viewport.append(pane);

  const scene = new THREE.Scene();
  const camera = zUpCamera(scene, { near: 0.05, far: 500 });

  const mat = {
    obstacle: new THREE.MeshStandardMaterial({ color: COLORS.obstacle, roughness: 0.8, metalness: 0, side: THREE.DoubleSide, transparent: true, opacity: 0.8, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }),
    obstacleEdge: new THREE.LineBasicMaterial({ color: COLORS.obstacleEdge, transparent: true, opacity: 0.7 }),
    traverse: new THREE.MeshStandardMaterial({ color: COLORS.traverse, roughness: 0.5, metalness: 0, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }),
    traverseEdge: new THREE.LineBasicMaterial({ color: 0xa6eef8 }),
    waypointEdge: new THREE.LineBasicMaterial({ color: COLORS.traverse, transparent: true, opacity: 0.45 }),
    clear: new THREE.MeshStandardMaterial({ color: COLORS.clear, transparent: true, opacity: 0.2, depthWrite: false, side: THREE.DoubleSide, roughness: 0.6 }),
    hit: new THREE.MeshStandardMaterial({ color: COLORS.hit, transparent: true, opacity: 0.24, depthWrite: false, side: THREE.DoubleSide, roughness: 0.6 }),
    clearEdge: new THREE.LineBasicMaterial({ color: COLORS.clear, transparent: true, opacity: 0.55 }),
    hitEdge: new THREE.LineBasicMaterial({ color: COLORS.hit, transparent: true, opacity: 0.65 }),
    ghost: new THREE.MeshStandardMaterial({ color: COLORS.ghost, transparent: true, opacity: 0.5, depthWrite: false, roughness: 0.5 }),
    ghostEdge: new THREE.LineBasicMaterial({ color: COLORS.ghost }),
    sample: new THREE.LineBasicMaterial({ color: COLORS.sample, transparent: true, opacity: 0.5 }),
    sampleHit: new THREE.LineBasicMaterial({ color: COLORS.hit }),
    route: new THREE.LineDashedMaterial({ color: COLORS.route, dashSize: 0.25, gapSize: 0.15, transparent: true, opacity: 0.8 }),
    handle: new THREE.MeshStandardMaterial({ color: COLORS.handle, roughness: 0.35, emissive: 0x222222 }),
    selected: new THREE.MeshStandardMaterial({ color: COLORS.selected, roughness: 0.35, emissive: 0x553300 }),
    contact: new THREE.MeshBasicMaterial({ color: COLORS.hit, depthTest: false }),
  };

  const groups = {
    static: new THREE.Group(), // grid, obstacles
    sweeps: new THREE.Group(),
    poses: new THREE.Group(), // traverse at the waypoints
    ghost: new THREE.Group(),
    samples: new THREE.Group(),
    handles: new THREE.Group(),
  };
  for (const g of Object.values(groups)) scene.add(g);

  const controls = new OrbitControls(camera, pane);
  controls.enableDamping = true;
  controls.dampingFactor = 0.12;
  controls.enabled = false;

  // ------------------------------------------------------------ state

  let active = false;
  let preset = 'doorway';
  let sceneJson = presetScene(preset);
  let route = sceneJson.route.map((p) => [...p]);
  let selected = -1;
  let anchor = [0, 0, 0]; // the traverse's box centre: waypoint handles sit at offset + anchor
  let traverseGeoms = []; // per part: {mesh: BufferGeometry, edges: EdgesGeometry, vertices}
  let report = null;
  let sweeps = [];
  let runCount = 0;
  let inFlight = false;
  let dirty = false;
  let framed = false;

  function requestRender() {
    if (active) stage.requestRender();
  }
  controls.addEventListener('change', requestRender);

  function render(r) {
    controls.update();
    r.setScissorTest(false);
    r.setViewport(0, 0, stage.size.width, stage.size.height);
    r.render(scene, camera);
  }

  function resize(w, h) {
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    if (!framed) {
      frame();
      framed = true;
    }
  }

  // ------------------------------------------------------------ geometry

  function meshGeometry(part) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(partVertices(part), 3));
    g.setIndex(partTriangles(part));
    g.computeVertexNormals();
    return g;
  }

  function add(group, obj, order = 0) {
    obj.renderOrder = order;
    group.add(obj);
    return obj;
  }

  /** Grid, obstacles and the traverse's geometry for the current scene (once per preset). */
  function buildStatic() {
    clearGroup(groups.static);
    for (const g of traverseGeoms) { g.mesh.dispose(); g.edges.dispose(); }
    const bounds = new THREE.Box3();
    for (const obstacle of sceneJson.obstacles) {
      const g = meshGeometry(obstacle);
      g.computeBoundingBox();
      bounds.union(g.boundingBox);
      add(groups.static, new THREE.Mesh(g, mat.obstacle), 1).name = obstacle.name;
      add(groups.static, new THREE.LineSegments(new THREE.EdgesGeometry(g, 1), mat.obstacleEdge), 2);
    }
    traverseGeoms = sceneJson.traverse.parts.map((part) => {
      const mesh = meshGeometry(part);
      return { mesh, edges: new THREE.EdgesGeometry(mesh, 1), vertices: partVertices(part) };
    });
    const tb = new THREE.Box3();
    for (const g of traverseGeoms) { g.mesh.computeBoundingBox(); tb.union(g.mesh.boundingBox); }
    anchor = tb.getCenter(new THREE.Vector3()).toArray();
    for (const p of route) bounds.union(tb.clone().translate(new THREE.Vector3(...p)));
    const size = bounds.getSize(new THREE.Vector3());
    const centre = bounds.getCenter(new THREE.Vector3());
    const span = Math.ceil(Math.max(size.x, size.y) + 4);
    const grid = new THREE.GridHelper(span, span, COLORS.grid, COLORS.grid);
    grid.rotation.x = Math.PI / 2;
    grid.position.set(Math.round(centre.x), Math.round(centre.y), 0);
    add(groups.static, grid, 0);
    sceneBounds = bounds;
  }
  let sceneBounds = new THREE.Box3(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));

  function frame() {
    const centre = sceneBounds.getCenter(new THREE.Vector3());
    const r = sceneBounds.getSize(new THREE.Vector3()).length() / 2;
    const dir = new THREE.Vector3(-0.55, -1.25, 1.0).normalize();
    const fov = THREE.MathUtils.degToRad(camera.fov);
    const hfov = 2 * Math.atan(Math.tan(fov / 2) * camera.aspect);
    const dist = (r / Math.sin(Math.min(fov, hfov) / 2)) * 0.95;
    controls.target.copy(centre);
    camera.position.copy(centre).addScaledVector(dir, dist);
    camera.near = dist / 100;
    camera.far = dist * 10;
    camera.updateProjectionMatrix();
    controls.update();
  }

  /** The traverse (all parts) at `offset`, as faces and/or edges with the given materials. */
  function traverseAt(group, offset, faceMat, edgeMat, order) {
    for (const g of traverseGeoms) {
      if (faceMat) add(group, new THREE.Mesh(g.mesh, faceMat), order).position.set(...offset);
      if (edgeMat) add(group, new THREE.LineSegments(g.edges, edgeMat), order + 1).position.set(...offset);
    }
  }

  /** Waypoint handles, the route line and the traverse at each waypoint. */
  function drawRoute() {
    for (const g of [groups.poses, groups.handles]) {
      for (const obj of [...g.children]) {
        // Shared traverse geometries stay; only the line and spheres are owned here.
        if (obj.userData.owned) obj.geometry.dispose();
      }
      g.clear();
    }
    const pts = route.map((p) => new THREE.Vector3(p[0] + anchor[0], p[1] + anchor[1], p[2] + anchor[2]));
    const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts), mat.route);
    line.computeLineDistances();
    line.userData.owned = true;
    add(groups.handles, line, 6);
    const radius = Math.max(0.12, sceneBounds.getSize(new THREE.Vector3()).length() / 90);
    route.forEach((p, i) => {
      const sphere = new THREE.Mesh(new THREE.SphereGeometry(radius, 20, 14), i === selected ? mat.selected : mat.handle);
      sphere.position.copy(pts[i]);
      sphere.userData = { owned: true, waypoint: i };
      add(groups.handles, sphere, 7);
      traverseAt(groups.poses, p, i === 0 ? mat.traverse : null, i === 0 ? mat.traverseEdge : mat.waypointEdge, 3);
    });
    ui.remove.disabled = selected < 0 || route.length <= 2;
  }

  function drawReport() {
    clearGroup(groups.sweeps);
    clearGroup(groups.ghost);
    groups.samples.clear();
    if (!report) return;
    // Swept hulls, per leg and part, coloured by the leg's status.
    for (const { leg, part, triangles } of sweeps) {
      const status = report.legs[leg]?.status;
      if (!status) continue;
      const a = route[leg], b = route[leg + 1];
      const v = traverseGeoms[part].vertices;
      const m = v.length / 3;
      const pos = new Float32Array(6 * m);
      for (let i = 0; i < m; i++) {
        for (let k = 0; k < 3; k++) {
          pos[3 * i + k] = v[3 * i + k] + a[k];
          pos[3 * (m + i) + k] = v[3 * i + k] + b[k];
        }
      }
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
      g.setIndex(new THREE.BufferAttribute(triangles, 1));
      g.computeVertexNormals();
      const isClear = status === 'clear';
      add(groups.sweeps, new THREE.Mesh(g, isClear ? mat.clear : mat.hit), 4);
      add(groups.sweeps, new THREE.LineSegments(new THREE.EdgesGeometry(g, 1), isClear ? mat.clearEdge : mat.hitEdge), 5);
    }
    // The traverse at its first contact.
    for (const leg of report.legs) {
      if (leg.status !== 'clear' && leg.position) traverseAt(groups.ghost, leg.position, mat.ghost, mat.ghostEdge, 8);
    }
    // N-step sampling: the traverse at N + 1 fractions of every leg, red where a pose hits.
    if (ui.showSamples.checked) {
      const n = currentSamples();
      report.legs.forEach((leg, i) => {
        const a = route[i], b = route[i + 1];
        const hitAt = leg.sampled?.hit ? leg.sampled.fraction : null;
        for (let k = 0; k <= n; k++) {
          const f = k / n;
          const p = a.map((x, c) => x + f * (b[c] - x));
          const isHit = hitAt !== null && Math.abs(f - hitAt) < 1e-9;
          traverseAt(groups.samples, p, null, isHit ? mat.sampleHit : mat.sample, 9);
        }
      });
    }
  }

  // ------------------------------------------------------------ checking

  const currentSamples = () => {
    const v = Math.round(Number(ui.samples.value));
    return Number.isFinite(v) ? Math.max(1, Math.min(SAMPLES_MAX, v)) : 20;
  };
  const currentMargin = () => {
    const v = Number(ui.margin.value);
    return Number.isFinite(v) && v >= 0 ? v : 0;
  };

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
    const sent = route.map((p) => [...p]);
    const scene = { ...sceneJson, route: sent, margin: currentMargin() };
    const t0 = performance.now();
    if (!report) setState('computing');
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

  const fmtFraction = (f) => (Array.isArray(f) ? f[0] : f)?.toFixed(4) ?? '—';
  const fmtLength = (d) => (Number.isFinite(d) ? (Math.abs(d) >= 1e-3 || d === 0 ? d.toFixed(3) : d.toExponential(2)) : '—');

  function show(msg, samples, roundTripMs) {
    report = msg.report;
    sweeps = msg.sweeps;
    ui.error.hidden = true;
    drawReport();
    runCount++;
    const rows = report.legs.map((leg, i) => {
      const tr = document.createElement('tr');
      tr.dataset.status = leg.status;
      const sampled = leg.sampled ? (leg.sampled.hit ? `hit ${leg.sampled.fraction.toFixed(2)}` : 'clear') : '—';
      const missed = leg.sampled && !leg.sampled.hit && leg.status !== 'clear';
      const cells = [
        String(i + 1), leg.status,
        leg.status === 'clear' ? (leg.fraction !== undefined ? fmtFraction(leg.fraction) : '—') : fmtFraction(leg.fraction),
        leg.obstacle ?? '—',
        leg.status === 'clear' ? fmtLength(leg.clearance) : '0',
        missed ? 'missed' : sampled,
      ];
      for (const [k, text] of cells.entries()) {
        const td = document.createElement('td');
        td.textContent = text;
        if (k === 1) td.className = `status-${leg.status}`;
        if (k === 5 && missed) td.className = 'missed';
        tr.append(td);
      }
      if (leg.status !== 'clear' && Array.isArray(leg.fraction)) {
        tr.title = `first contact in [${leg.fraction[0]}, ${leg.fraction[1]}] with ${leg.obstacle}` +
          `${leg.triangle !== undefined ? ` (triangle ${leg.triangle})` : ''}${leg.part ? `, by ${leg.part}` : ''}`;
      }
      return tr;
    });
    ui.legs.replaceChildren(...rows);
    const hits = report.legs.filter((l) => l.status !== 'clear').length;
    const sampledHits = report.legs.filter((l) => l.sampled?.hit).length;
    ui.stat.verdict.textContent = report.clear ? 'clear' : `${hits} hit${hits === 1 ? '' : 's'}`;
    ui.stat.verdict.className = report.clear ? 'status-clear' : 'status-hit';
    ui.stat.clearance.textContent = fmtLength(report.min_clearance);
    ui.stat.ms.textContent = fmtMs(1000 * report.seconds);
    ui.stat.ms.title = `all legs checked in ${fmtMs(1000 * report.seconds)} inside the worker; scene prepared in ${fmtMs(1000 * (report.build_seconds ?? 0))}; round trip ${fmtMs(roundTripMs)}`;
    const missed = hits - report.legs.filter((l) => l.status !== 'clear' && l.sampled?.hit).length;
    let status = `${fileNote}${PRESETS[preset].note} ${report.legs.length} legs: ${hits ? `${hits} hit${hits === 1 ? '' : 's'}` : 'all clear'}` +
      ` (margin ${currentMargin()}).`;
    status += ` ${samples}-step sampling finds ${sampledHits} of ${hits}${missed > 0 ? `: it misses ${missed}` : ''}.`;
    ui.status.textContent = status;
    exportButtons.report.disabled = false;
    window.hullkitRoute = {
      obstacles: sceneJson.obstacles.length, parts: sceneJson.traverse.parts.length,
      preset, clear: report.clear, samples, overlay: ui.showSamples.checked, waypoints: route.length, run: runCount,
      legs: report.legs.map((l) => ({ status: l.status, fraction: l.fraction ?? null, obstacle: l.obstacle ?? null, clearance: l.clearance ?? null, sampledHit: l.sampled ? l.sampled.hit : null })),
    };
    setState('ready');
    requestRender();
  }

  function fail(message, logged = true) {
    exportButtons.report.disabled = true;
    showError(ui.error, message, logged);
    setState('error');
  }

  // ------------------------------------------------------------ waypoints: drag, add, remove

  const raycaster = new THREE.Raycaster();
  let drag = null; // {index, plane, offset}

  function ndcOf(event) {
    const rect = pane.getBoundingClientRect();
    return new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1, -((event.clientY - rect.top) / rect.height) * 2 + 1);
  }

  function handleUnder(event) {
    raycaster.setFromCamera(ndcOf(event), camera);
    const hits = raycaster.intersectObjects(groups.handles.children.filter((o) => o.userData.waypoint !== undefined), false);
    return hits.length ? hits[0].object.userData.waypoint : -1;
  }

  // Registered before OrbitControls sees the event (capture): a handle under the pointer is dragged instead.
  pane.addEventListener('pointerdown', (event) => {
    if (event.button !== 0) return;
    const i = handleUnder(event);
    if (i < 0) return;
    controls.enabled = false;
    selected = i;
    const p = route[i];
    const z = p[2] + anchor[2];
    const plane = new THREE.Plane(new THREE.Vector3(0, 0, 1), -z);
    raycaster.setFromCamera(ndcOf(event), camera);
    const at = raycaster.ray.intersectPlane(plane, new THREE.Vector3());
    drag = { index: i, plane, dx: at ? p[0] - at.x : 0, dy: at ? p[1] - at.y : 0 };
    pane.setPointerCapture(event.pointerId);
    drawRoute();
    requestRender();
  }, { capture: true });

  pane.addEventListener('pointermove', (event) => {
    if (!drag) {
      pane.style.cursor = handleUnder(event) >= 0 ? 'grab' : '';
      return;
    }
    raycaster.setFromCamera(ndcOf(event), camera);
    const at = raycaster.ray.intersectPlane(drag.plane, new THREE.Vector3());
    if (!at) return;
    const p = route[drag.index];
    p[0] = Number((at.x + drag.dx).toFixed(3));
    p[1] = Number((at.y + drag.dy).toFixed(3));
    drawRoute();
    check();
    requestRender();
  });

  const endDrag = () => {
    if (!drag) return;
    drag = null;
    controls.enabled = active;
    writeUrl('route', urlParams(), { push: true });
  };
  pane.addEventListener('pointerup', endDrag);
  pane.addEventListener('pointercancel', endDrag);

  function addWaypoint() {
    const i = selected >= 0 ? selected : route.length - 1;
    let p;
    if (i + 1 < route.length) {
      p = route[i].map((x, k) => (x + route[i + 1][k]) / 2);
    } else {
      const prev = route[i - 1] ?? route[i].map((x, k) => x - (k === 0 ? 1 : 0));
      p = route[i].map((x, k) => x + 0.5 * (x - prev[k]));
    }
    route.splice(i + 1, 0, p.map((x) => Number(x.toFixed(3))));
    selected = i + 1;
    routeChanged();
  }

  function removeWaypoint() {
    if (selected < 0 || route.length <= 2) return;
    route.splice(selected, 1);
    selected = Math.min(selected, route.length - 1);
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
    route = sceneJson.route.map((p) => [...p]);
    selected = -1;
    routeChanged();
  });
  document.addEventListener('keydown', (event) => {
    if (!active || (event.key !== 'Delete' && event.key !== 'Backspace')) return;
    if (event.target instanceof HTMLElement && event.target.closest('input, select, textarea')) return;
    removeWaypoint();
  });

  // ------------------------------------------------------------ presets, options, URL

  function loadPreset(name, waypoints = null) {
    preset = PRESETS[name] ? name : 'doorway';
    ui.preset.value = preset;
    sceneJson = presetScene(preset);
    fileNote = '';
    ui.margin.value = String(sceneJson.margin);
    route = waypoints ?? sceneJson.route.map((p) => [...p]);
    selected = -1;
    report = null;
    buildStatic();
    drawRoute();
    drawReport();
    framed = false;
    if (active) {
      frame();
      framed = true;
    }
  }

  function urlParams() {
    const presetRoute = JSON.stringify(sceneJson.route);
    return {
      preset,
      margin: currentMargin() !== sceneJson.margin ? currentMargin() : undefined,
      samples: currentSamples() !== 20 ? currentSamples() : undefined,
      overlay: ui.showSamples.checked ? 1 : undefined,
      route: JSON.stringify(route) !== presetRoute ? route.map((p) => p.join(',')).join(';') : undefined,
    };
  }

  function parseRoute(text) {
    if (!text) return null;
    const pts = text.split(';').map((s) => s.split(',').map(Number));
    return pts.length >= 2 && pts.length <= 200 && pts.every((p) => p.length === 3 && p.every(Number.isFinite)) ? pts : null;
  }

  function applyUrl(q) {
    const name = PRESETS[q.get('preset')] ? q.get('preset') : 'doorway';
    loadPreset(name, parseRoute(q.get('route')));
    ui.margin.value = String(q.has('margin') && Number(q.get('margin')) >= 0 ? Number(q.get('margin')) : sceneJson.margin);
    ui.samples.value = String(q.has('samples') ? Math.max(1, Math.min(SAMPLES_MAX, Math.round(Number(q.get('samples'))) || 20)) : 20);
    ui.showSamples.checked = q.get('overlay') === '1';
    if (active) check();
  }

  ui.form.addEventListener('submit', (event) => event.preventDefault());
  ui.preset.addEventListener('change', () => {
    loadPreset(ui.preset.value);
    writeUrl('route', urlParams(), { push: true });
    check();
  });
  for (const input of [ui.margin, ui.samples]) {
    input.addEventListener('change', () => {
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

  /** Test hook: where waypoint `i`'s handle is on the screen (client pixels). */
  window.hullkitRouteHandle = (i) => {
    const h = groups.handles.children.find((o) => o.userData.waypoint === i);
    if (!h) return null;
    const v = h.position.clone().project(camera);
    const rect = pane.getBoundingClientRect();
    return { x: rect.left + ((v.x + 1) / 2) * rect.width, y: rect.top + ((1 - v.y) / 2) * rect.height };
  };

  // ------------------------------------------------------------ files in and out

  let fileNote = ''; // what opened files changed in the preset, for the status line
  let cancelled = false; // Cancel restarted the worker: do not re-run the check when it is ready
  const exportButtons = {
    report: document.querySelector('[data-rt-export="report"]'),
    scene: document.querySelector('[data-rt-export="scene"]'),
  };
  exportButtons.report.addEventListener('click', () => {
    if (report) download(`route-report-${preset}.json`, `${JSON.stringify(report, null, 2)}\n`, 'application/json');
  });
  exportButtons.scene.addEventListener('click', () => {
    const out = { ...sceneJson, route: route.map((p) => [...p]), margin: currentMargin() };
    download(`route-scene-${preset}.json`, `${JSON.stringify(out)}\n`, 'application/json');
  });

  /** Reads a mesh file with the C++ mesh readers (in the worker): an obstacle or the traverse. */
  async function openFile(file) {
    ui.error.hidden = true;
    ui.status.textContent = `Reading ${file.name}…`;
    const msg = await readInWorker(worker, file, 'mesh');
    if (msg.cancelled) return;
    if (msg.error) {
      fail(msg.error, false);
      return;
    }
    const vertices = [];
    for (let i = 0; i < msg.vertices.length; i += 3) vertices.push([msg.vertices[i], msg.vertices[i + 1], msg.vertices[i + 2]]);
    const triangles = [];
    for (let t = 0; t < msg.triangles.length; t += 3) triangles.push([msg.triangles[t], msg.triangles[t + 1], msg.triangles[t + 2]]);
    if (!triangles.length) {
      fail(`Cannot use ${file.name}: it has no triangles (a traverse or an obstacle is a triangle mesh).`, false);
      return;
    }
    const part = { name: file.name, vertices, triangles };
    const role = ui.fileRole.value;
    if (role === 'traverse') {
      sceneJson = { ...sceneJson, traverse: { parts: [part] } };
      fileNote += `Traverse: ${file.name} (${triangles.length} triangles). `;
    } else {
      sceneJson = { ...sceneJson, obstacles: [...sceneJson.obstacles, part] };
      fileNote += `Obstacle added: ${file.name} (${triangles.length} triangles). `;
    }
    report = null;
    buildStatic();
    drawRoute();
    drawReport();
    frame();
    check();
  }

  function cancel() {
    if (!inFlight) return;
    worker.restart(); // a wasm call cannot be interrupted
    inFlight = false;
    dirty = false;
    cancelled = true;
    ui.status.textContent = 'Cancelled; the worker was restarted. Move a waypoint to check again.';
    setState('cancelled');
  }

  worker.on('ready', () => { if (active && !cancelled) check(); });
  loadPreset('doorway');
  worker.on('load-error', () => { if (active) check(); });

  return {
    name: 'route',
    render,
    resize,
    activate() {
      active = true;
      controls.enabled = true;
      check();
      requestRender();
    },
    deactivate() {
      active = false;
      controls.enabled = false;
    },
    applyUrl,
    urlParams,
    openFile,
    cancel,
    fileHint: 'a mesh (OBJ, OFF, PLY, STL, glTF) as an obstacle or the traverse',
    busyLabel: () => 'Checking the route',
  };
}
