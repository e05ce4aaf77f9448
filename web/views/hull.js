// The Hull view: points in 3D (generated or pasted), their convex hull computed in the shared
// worker, drawn translucent with its edges and vertices; gift wrapping's seed epsilon compared
// with exact predicates.
//
// Test hooks: document.body.dataset.state is 'loading' | 'computing' | 'ready' | 'error' |
// 'cancelled' while this view is shown, window.hullkitStats describes the last hull drawn,
// window.hullkitError holds the message of the last failed run (else null) and
// window.hullkitEpsilon compares the last run with the seed's epsilon to exact predicates:
// {outcome: 'same' | 'different' | 'failed', epsilon, seed, exact} (null after an exact run).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { gridSide, pointCount } from '../distributions.js';
import { discTexture, clearGroup } from '../app/stage.js';
import { fmtInt, fmtReal, fmtMs, fmtDuration } from '../app/format.js';
import { writeUrl } from '../app/url-state.js';
import { readInWorker } from '../app/panel.js';
import { compact, objText, offText, stlBytes, glbBytes, download } from '../app/export.js';
import { createGiftwrapStepper, STEP_MAX } from './giftwrap-stepper.js';

const N_MIN = 4;
const N_MAX = 1_000_000;
// Interior points beyond this many are drawn sparsely (every k-th): they only give the hull its
// context, and a million points would make orbiting stutter on a software renderer.
const MAX_INTERIOR_DRAWN = 150_000;
const DENSE_TRIANGLES = 60_000; // more hull triangles than this: front faces only, no wireframe
const N_DEFAULT = 2000;
const SEED_DEFAULT = 1;
const DIST_DEFAULT = 'ball';
const SPHERE_WARN_N = 5000; // gift wrapping points on a sphere is O(n²): every point is a hull vertex
const WARN_MS = 10_000; // a gift wrapping run estimated longer than this asks for confirmation
const DEFAULT_ALGORITHM = 'quickhull'; // the library's default (it lists it first)
const DISTRIBUTIONS = ['cube', 'ball', 'sphere', 'plane', 'near-coplanar', 'grid', 'rotated-grid', 'custom', 'file'];
const GRIDS = ['grid', 'rotated-grid'];
const CUSTOM_SAMPLE = `# x y z per point; '#' comments
# unit cube + centre
0 0 0
1 0 0
0 1 0
1 1 0
0 0 1
1 0 1
0 1 1
1 1 1
0.5 0.5 0.5
`;

const COLORS = {
  background: 0x0d1117,
  face: 0x3fb8c9,
  faceBack: 0x2a7f8c,
  edge: 0xa6eef8,
  edgeBack: 0x5fd3e3,
  vertex: 0xffb547,
  point: 0x8a96ab,
  dropped: 0xff4f8b,
};

/**
 * Creates the view over the shared `stage` (renderer) and `worker` (WorkerClient); `setState`
 * publishes its state on <body data-state> while it is the view shown.
 */
export function createHullView({ stage, worker, setState }) {
  const $ = (id) => document.getElementById(id);
  const ui = {
    form: $('controls'),
    distribution: $('distribution'),
    algorithmField: $('algorithm-field'),
    algorithm: $('algorithm'),
    epsilonField: $('epsilon-field'),
    epsilon: $('epsilon'),
    epsilonNote: $('epsilon-note'),
    merge: $('merge'),
    nHint: $('n-hint'),
    generatedFields: $('generated-fields'),
    customField: $('custom-field'),
    customPoints: $('custom-points'),
    nSlider: $('n-slider'),
    n: $('n'),
    seed: $('seed'),
    reseed: $('reseed'),
    compute: $('compute'),
    cancel: $('cancel'),
    status: $('status'),
    error: $('error'),
    warning: $('warning'),
    warningText: $('warning-text'),
    useCap: $('use-cap'),
    useQuickhull: $('use-quickhull'),
    compare: $('compare'),
    compareText: $('compare-text'),
    compareSeed: $('compare-seed'),
    compareExact: $('compare-exact'),
    facesLabel: $('stat-faces-label'),
    legendDropped: $('legend-dropped'),
    showFaces: $('show-faces'),
    showEdges: $('show-edges'),
    showPoints: $('show-points'),
    resetView: $('reset-view'),
    viewport: $('viewport'),
    canvas: $('canvas'),
    stat: {
      n: $('stat-n'),
      vertices: $('stat-vertices'),
      faces: $('stat-faces'),
      edges: $('stat-edges'),
      volume: $('stat-volume'),
      area: $('stat-area'),
      ms: $('stat-ms'),
      rtt: $('stat-rtt'),
      draw: $('stat-draw'),
    },
  };

  // ---------------------------------------------------------------- inputs

  const LOG_RANGE = Math.log(N_MAX / N_MIN);
  const sliderToN = (s) => Math.round(N_MIN * Math.exp((s / 1000) * LOG_RANGE));
  const nToSlider = (n) => Math.round((1000 * Math.log(Math.max(N_MIN, Math.min(N_MAX, n)) / N_MIN)) / LOG_RANGE);

  function parseN(text) {
    const v = Math.round(Number(text));
    if (!Number.isFinite(v) || String(text).trim() === '') return N_DEFAULT;
    // Fewer than 4 points are passed on: the library decides what their hull is.
    return Math.max(0, Math.min(N_MAX, v));
  }
  function parseSeed(text) {
    const v = Math.floor(Number(text));
    return Number.isFinite(v) ? v >>> 0 : SEED_DEFAULT;
  }

  // Cheap count of the coordinates in the pasted text (for the cost estimate only).
  function roughCustomCount(text) {
    const tokens = text.replace(/#.*$/gm, '').split(/[\s,;]+/).filter(Boolean).length;
    return Math.floor(tokens / 3);
  }

  /** The algorithm that will run: the selected one, else the library's default. */
  const chosenAlgorithm = () => ui.algorithm.value || DEFAULT_ALGORITHM;
  /** The seed's epsilon exists for gift wrapping only; quickhull always decides exactly. */
  const epsilonApplies = () => chosenAlgorithm() === 'giftwrap';

  function readParams() {
    const distribution = DISTRIBUTIONS.includes(ui.distribution.value) ? ui.distribution.value : DIST_DEFAULT;
    const algorithm = ui.algorithm.value || undefined;
    const epsilon = epsilonApplies() && ui.epsilon.value === 'seed' ? 'seed' : 'exact';
    const mergeCoplanar = ui.merge.checked;
    if (distribution === 'file' && fileInput) {
      return { distribution, n: fileInput.xyz.length / 3, seed: 0, algorithm, epsilon, mergeCoplanar, file: fileInput.name };
    }
    if (distribution === 'custom') {
      const text = ui.customPoints.value;
      return { distribution, n: roughCustomCount(text), seed: 0, algorithm, epsilon, mergeCoplanar, text };
    }
    return { distribution, n: parseN(ui.n.value), seed: parseSeed(ui.seed.value), algorithm, epsilon, mergeCoplanar };
  }

  function writeParams({ distribution, n, seed }) {
    ui.distribution.value = distribution === 'file' && !fileInput ? DIST_DEFAULT : distribution;
    if (distribution !== 'custom' && distribution !== 'file') {
      ui.n.value = String(n);
      ui.nSlider.value = String(nToSlider(n));
      ui.seed.value = String(seed);
    }
    updateSourceFields();
  }

  function updateSourceFields() {
    const custom = ui.distribution.value === 'custom';
    ui.customField.hidden = !custom;
    ui.generatedFields.hidden = custom || ui.distribution.value === 'file';
    updateNHint();
  }

  /** Grids round n to a cube number: say which. */
  function updateNHint() {
    const distribution = ui.distribution.value;
    if (GRIDS.includes(distribution)) {
      const k = gridSide(parseN(ui.n.value));
      ui.nHint.textContent = `n → ${k}×${k}×${k} = ${fmtInt(k ** 3)}`;
    } else {
      ui.nHint.textContent = 'n';
    }
  }

  function updateEpsilonField() {
    const applies = epsilonApplies();
    ui.epsilon.disabled = !applies;
    ui.epsilonField.classList.toggle('inactive', !applies);
    ui.epsilonNote.textContent = applies
      ? (ui.epsilon.value === 'seed'
        ? 'Within ε = DBL_EPSILON × (x + y + z extent) of a plane counts as on it; each run is compared with exact predicates.'
        : 'Every side test is exact. Pick the seed\'s epsilon to compare (try “near-coplanar”).')
      : 'Quickhull is always exact; the seed\'s epsilon is a gift wrapping option.';
  }

  let preferredAlgorithm = null; // from the URL, applied once the worker lists the algorithms

  function paramsFromUrl(q) {
    // A file's points cannot be put in a link: such URLs show the default points.
    const distribution = DISTRIBUTIONS.includes(q.get('dist')) && q.get('dist') !== 'file' ? q.get('dist') : DIST_DEFAULT;
    const n = q.has('n') ? parseN(q.get('n')) : N_DEFAULT;
    const seed = q.has('seed') ? parseSeed(q.get('seed')) : SEED_DEFAULT;
    preferredAlgorithm = q.get('algo');
    ui.epsilon.value = q.get('eps') === 'seed' ? 'seed' : 'exact';
    ui.merge.checked = q.get('merge') === '1';
    return { distribution, n, seed };
  }

  /** The URL parameters that reproduce `params`. */
  function urlParamsOf({ distribution, n, seed, algorithm, epsilon, mergeCoplanar }) {
    const q = { dist: distribution };
    if (distribution === 'file') return { dist: DIST_DEFAULT }; // not reproducible by a link
    if (distribution !== 'custom') {
      q.n = n;
      q.seed = seed;
    }
    if (algorithm) q.algo = algorithm;
    if (epsilon === 'seed') q.eps = 'seed';
    if (mergeCoplanar) q.merge = 1;
    return q;
  }

  /** A new history entry for each run after the first (back/forward step through them). */
  function paramsToUrl(params) {
    if (params.distribution === 'file') return; // the URL keeps the last reproducible state
    if (active) writeUrl('hull', urlParamsOf(params), { push: runCount > 0 || lastFailed });
  }

  const paramsKey = (p) => `${p.distribution}|${p.n}|${p.seed}|${p.algorithm}|${p.epsilon}|${p.mergeCoplanar}|${p.text ?? ''}|${p.file ?? ''}`;

  // ---------------------------------------------------------------- cost estimate

  // Rough running time model, refined from every sufficiently long run:
  //   giftwrap   ms ≈ k · n · h              (one pass over the points per hull edge)
  //   quickhull  ms ≈ k · n · log2(h)        (expected; 10^6 points on a sphere in about a second)
  // Only gift wrapping ever asks for confirmation: quickhull is fast up to the page's 100 000 points.
  const DEFAULT_MS_PER_UNIT = { giftwrap: 1.5e-5, quickhull: 5e-5 };
  const msPerUnit = new Map();

  const costKey = (algorithm) => (algorithm === 'giftwrap' ? 'giftwrap' : 'quickhull'); // quickhull: the default

  function expectedHullVertices(distribution, n) {
    switch (distribution) {
      case 'ball': return Math.min(n, 4.4 * Math.sqrt(n)); // Θ(n^(1/2))
      case 'cube': { const l = Math.log(Math.max(n, 2)); return Math.min(n, 1.6 * l * l); } // Θ(log² n)
      case 'plane': // 2D hull of a square: Θ(log n), generous
      case 'near-coplanar': return Math.min(n, 4 * Math.cbrt(Math.max(n, 1)));
      case 'grid': return Math.min(n, 8);
      case 'rotated-grid': return Math.min(n, 6 * Math.cbrt(Math.max(n, 1))); // face points rounded off their planes
      default: return n; // sphere: every point is extreme; custom: assume the worst
    }
  }

  function workUnits(algorithm, n, h) {
    return costKey(algorithm) === 'giftwrap' ? n * h : n * Math.log2(Math.max(h, 2));
  }

  /** Points the run will hash (grids round n to a cube number). */
  const inputSize = ({ distribution, n }) => (distribution === 'custom' || distribution === 'file' ? n : pointCount(distribution, n));

  function estimateMs(params) {
    const key = costKey(params.algorithm);
    const n = inputSize(params);
    return (msPerUnit.get(key) ?? DEFAULT_MS_PER_UNIT[key]) * workUnits(params.algorithm, n, expectedHullVertices(params.distribution, n));
  }

  function calibrate(algorithm, n, h, hullMs) {
    if (hullMs > 50 && n > 0 && h > 0) msPerUnit.set(costKey(algorithm), hullMs / workUnits(algorithm, n, h));
  }

  function needsConfirmation(params, estMs) {
    if (costKey(params.algorithm) !== 'giftwrap') return false;
    return (params.distribution === 'sphere' && params.n > SPHERE_WARN_N) || estMs > WARN_MS;
  }

  // ---------------------------------------------------------------- three.js scene

  const renderer = stage.renderer;

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(38, 1, 0.01, 100);
  const DEFAULT_VIEW_DIR = new THREE.Vector3(1.15, 0.8, 1.55).normalize();
  camera.position.copy(DEFAULT_VIEW_DIR).multiplyScalar(4);
  scene.add(camera);

  scene.add(new THREE.HemisphereLight(0xd6ecff, 0x1b2230, 1.1));
  const keyLight = new THREE.DirectionalLight(0xffffff, 3.2);
  keyLight.position.set(-1.2, 1.6, 1.0); // relative to the camera: follows the view
  keyLight.target.position.set(0, 0, -1);
  camera.add(keyLight, keyLight.target);

  const controls = new OrbitControls(camera, ui.canvas);
  controls.enableDamping = true;
  controls.dampingFactor = 0.12;
  controls.rotateSpeed = 0.8;

  const disc = discTexture();

  // Translucent convex surface, drawn back faces first, then front faces; edges
  // and hull vertices twice (dim through the surface, bright in front).
  const materials = {
    faceBack: new THREE.MeshStandardMaterial({
      color: COLORS.faceBack, transparent: true, opacity: 0.22, side: THREE.BackSide,
      flatShading: true, depthWrite: false, roughness: 0.7, metalness: 0,
    }),
    faceFront: new THREE.MeshStandardMaterial({
      color: COLORS.face, transparent: true, opacity: 0.34, side: THREE.FrontSide,
      flatShading: true, depthWrite: true, roughness: 0.42, metalness: 0,
      polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
    }),
    edgeBack: new THREE.LineBasicMaterial({ color: COLORS.edgeBack, transparent: true, opacity: 0.3, depthWrite: false }),
    edgeFront: new THREE.LineBasicMaterial({ color: COLORS.edge, transparent: true, opacity: 0.8, depthWrite: false }),
    point: new THREE.PointsMaterial({ color: COLORS.point, size: 3, sizeAttenuation: false, map: disc, alphaTest: 0.5 }),
    vertex: new THREE.PointsMaterial({ color: COLORS.vertex, size: 6, sizeAttenuation: false, map: disc, alphaTest: 0.5 }),
    vertexFront: new THREE.PointsMaterial({
      color: COLORS.vertex, size: 6, sizeAttenuation: false, map: disc, alphaTest: 0.5,
      transparent: true, depthWrite: false,
    }),
    // Extreme points that the seed's epsilon left out of its hull: on top of everything.
    dropped: new THREE.PointsMaterial({
      color: COLORS.dropped, size: 7, sizeAttenuation: false, map: disc, alphaTest: 0.5,
      transparent: true, depthTest: false, depthWrite: false,
    }),
  };

  const content = new THREE.Group();
  scene.add(content);
  const layers = { faces: [], edges: [], points: [] };
  let viewRadius = 1;
  let framedOnce = false;
  let interiorStride = 1; // the last drawing shows every interiorStride-th interior point
  let dense = false; // the last hull was drawn without back faces and wireframe
  let interiorTotal = 0;
  let fileInput = null; // {name, xyz}: the points of the last file opened
  let lastHull = null; // {xyz, triangles, dimension, name}: what the export buttons write

  function clearContent() {
    clearGroup(content);
    layers.faces = [];
    layers.edges = [];
    layers.points = [];
  }

  function addObject(obj, layer, renderOrder) {
    obj.renderOrder = renderOrder;
    obj.frustumCulled = false;
    content.add(obj);
    layers[layer].push(obj);
  }

  /**
   * Float32 positions relative to the centre of the finite points' bounding box
   * (so that data far from the origin keeps its precision on the GPU), and the
   * radius of the sphere around that centre containing them all.
   */
  function centredPositions(xyz) {
    const n = Math.floor(xyz.length / 3);
    const lo = [Infinity, Infinity, Infinity];
    const hi = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < n; i++) {
      const x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
      if (!Number.isFinite(x) || !Number.isFinite(y) || !Number.isFinite(z)) continue;
      if (x < lo[0]) lo[0] = x; if (x > hi[0]) hi[0] = x;
      if (y < lo[1]) lo[1] = y; if (y > hi[1]) hi[1] = y;
      if (z < lo[2]) lo[2] = z; if (z > hi[2]) hi[2] = z;
    }
    const centre = lo[0] <= hi[0] ? lo.map((l, k) => (l + hi[k]) / 2) : [0, 0, 0];
    const positions = new Float32Array(3 * n);
    let r2 = 0;
    for (let i = 0; i < n; i++) {
      const x = xyz[3 * i] - centre[0], y = xyz[3 * i + 1] - centre[1], z = xyz[3 * i + 2] - centre[2];
      positions[3 * i] = x;
      positions[3 * i + 1] = y;
      positions[3 * i + 2] = z;
      const d = x * x + y * y + z * z;
      if (d > r2 && Number.isFinite(d)) r2 = d;
    }
    const radius = Math.sqrt(r2);
    return { positions, radius: radius > 0 ? radius : 1 };
  }

  function pointsGeometry(positions, indices) {
    const pos = new Float32Array(3 * indices.length);
    for (let i = 0; i < indices.length; i++) {
      const j = 3 * indices[i];
      pos[3 * i] = positions[j];
      pos[3 * i + 1] = positions[j + 1];
      pos[3 * i + 2] = positions[j + 2];
    }
    const geom = new THREE.BufferGeometry();
    geom.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    return geom;
  }

  /**
   * Draw a hull (triangles/edges/vertices) or, for failed runs, only the points;
   * `dropped` (point indices) are highlighted on top.
   */
  function drawScene({ xyz, triangles = null, edges = null, vertices = null, dropped = null }) {
    clearContent();
    const { positions, radius } = centredPositions(xyz);
    const n = positions.length / 3;

    const isHull = new Uint8Array(n);
    if (vertices) for (let i = 0; i < vertices.length; i++) isHull[vertices[i]] = 1;
    if (dropped) for (let i = 0; i < dropped.length; i++) isHull[dropped[i]] = 1;
    let interior = new Uint32Array(n);
    let interiorCount = 0;
    for (let i = 0; i < n; i++) {
      // Rejected input may hold NaN / infinite coordinates: leave those out.
      if (!isHull[i] && Number.isFinite(positions[3 * i] + positions[3 * i + 1] + positions[3 * i + 2])) interior[interiorCount++] = i;
    }
    interiorStride = Math.max(1, Math.ceil(interiorCount / MAX_INTERIOR_DRAWN));
    interiorTotal = interiorCount;
    if (interiorStride > 1) {
      const kept = new Uint32Array(Math.ceil(interiorCount / interiorStride));
      for (let k = 0; k < kept.length; k++) kept[k] = interior[k * interiorStride];
      interior = kept;
    } else {
      interior = interior.subarray(0, interiorCount);
    }

    materials.point.size = n <= 200 ? 5 : n <= 5000 ? 3 : n <= 30000 ? 2 : 1.5;
    if (interior.length) addObject(new THREE.Points(pointsGeometry(positions, interior), materials.point), 'points', 0);

    if (vertices && vertices.length) {
      const h = vertices.length;
      materials.vertex.size = materials.vertexFront.size = h <= 600 ? 6 : h <= 6000 ? 4 : h <= 30000 ? 2.5 : 1.5;
      // Dense hulls (points on a sphere) would drown in their own wireframe.
      materials.edgeFront.opacity = h <= 1000 ? 0.8 : h <= 10000 ? 0.6 : 0.4;
      materials.edgeBack.opacity = h <= 1000 ? 0.3 : h <= 10000 ? 0.18 : 0.1;

      const shared = new THREE.BufferAttribute(positions, 3);
      const vertGeom = pointsGeometry(positions, vertices);
      addObject(new THREE.Points(vertGeom, materials.vertex), 'points', 0);
      // A very dense hull (points on a sphere) is drawn lighter so that orbiting stays smooth: its
      // front faces only, no wireframe (it would be a solid sheet of lines anyway).
      dense = triangles !== null && triangles.length / 3 > DENSE_TRIANGLES;
      if (triangles && triangles.length) {
        const faceGeom = new THREE.BufferGeometry();
        faceGeom.setAttribute('position', shared);
        faceGeom.setIndex(new THREE.BufferAttribute(triangles, 1));
        if (!dense) addObject(new THREE.Mesh(faceGeom, materials.faceBack), 'faces', 1);
        addObject(new THREE.Mesh(faceGeom, materials.faceFront), 'faces', 3);
      }
      if (edges && edges.length && !dense) {
        const edgeGeom = new THREE.BufferGeometry();
        edgeGeom.setAttribute('position', shared);
        edgeGeom.setIndex(new THREE.BufferAttribute(edges, 1));
        // Back edges add nothing but cost to a dense wireframe.
        if (edges.length / 2 <= 30000) addObject(new THREE.LineSegments(edgeGeom, materials.edgeBack), 'edges', 2);
        addObject(new THREE.LineSegments(edgeGeom, materials.edgeFront), 'edges', 4);
      }
      addObject(new THREE.Points(vertGeom, materials.vertexFront), 'points', 5);
    }
    ui.legendDropped.hidden = !(dropped && dropped.length);
    if (dropped && dropped.length) addObject(new THREE.Points(pointsGeometry(positions, dropped), materials.dropped), 'points', 6);

    viewRadius = radius;
    applyVisibility();
    frameView(framedOnce);
    framedOnce = true;
    renderNow();
  }

  function applyVisibility() {
    for (const o of layers.faces) o.visible = ui.showFaces.checked;
    for (const o of layers.edges) o.visible = ui.showEdges.checked;
    for (const o of layers.points) o.visible = ui.showPoints.checked;
  }

  /** Fit the drawing (centred at the origin) into the view; keep the viewing direction if asked. */
  function frameView(keepDirection) {
    const dir = camera.position.clone().sub(controls.target);
    if (!keepDirection || dir.lengthSq() < 1e-30) dir.copy(DEFAULT_VIEW_DIR);
    dir.normalize();
    const vFov = THREE.MathUtils.degToRad(camera.fov);
    const hFov = 2 * Math.atan(Math.tan(vFov / 2) * camera.aspect);
    const fov = Math.min(vFov, hFov);
    const dist = (viewRadius / Math.sin(fov / 2)) * 1.15;
    controls.target.set(0, 0, 0);
    camera.position.copy(dir).multiplyScalar(dist);
    camera.near = dist / 1000;
    camera.far = dist * 20;
    camera.updateProjectionMatrix();
    controls.update();
  }

  let active = false;
  function requestRender() {
    if (active) stage.requestRender();
  }
  function renderNow() {
    if (active) stage.renderNow();
  }
  controls.addEventListener('change', requestRender);

  /** Draws this view (called by the stage while it is active). */
  function render(r) {
    controls.update(); // emits 'change' (→ another frame) while damping
    r.setScissorTest(false);
    r.setViewport(0, 0, stage.size.width, stage.size.height);
    r.render(scene, camera);
  }

  function resize(w, h) {
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  }

  // ---------------------------------------------------------------- worker

  let job = null; // { params, t0, estMs, timer, freshWorker }
  let runCount = 0;
  let lastFailed = false; // the last run failed (its URL is still worth a history entry)
  let pendingConfirmKey = null;
  let started = false; // the first computation has been requested

  function startJob(params, estMs) {
    hideWarning();
    hideError();
    ui.compare.hidden = true;
    const current = { params, t0: performance.now(), estMs, timer: 0, freshWorker: !worker.warm };
    job = current;
    setState('computing');
    ui.compute.disabled = true;
    ui.cancel.disabled = false;
    updateProgress();
    job.timer = setInterval(updateProgress, 200);
    paramsToUrl(params);
    const request = { type: 'compute', ...params };
    if (params.distribution === 'file') request.xyz = fileInput.xyz.slice();
    worker.request(request).then(
      (msg) => { if (job === current) onAnswer(msg); },
      (err) => {
        if (job !== current || err.cancelled) return; // cancelJob has said so already
        finishJob();
        showFailure(err.message, null);
      },
    );
  }

  function describeInput({ distribution, n, file }) {
    if (distribution === 'custom') return 'the pasted points';
    if (distribution === 'file') return `${fmtInt(n)} points from ${file}`;
    if (GRIDS.includes(distribution)) {
      const k = gridSide(n);
      return `${fmtInt(k ** 3)} points: ${labelOf(distribution)} ${k}×${k}×${k}`;
    }
    return `${fmtInt(n)} points ${labelOf(distribution)}`;
  }

  function updateProgress() {
    if (!job) return;
    const elapsed = performance.now() - job.t0;
    let text = `Computing the hull of ${describeInput(job.params)}… ${(elapsed / 1000).toFixed(1)} s`;
    if (job.estMs > 2000) text += ` (estimate ≈ ${fmtDuration(job.estMs)})`;
    ui.status.textContent = text;
  }

  function finishJob() {
    if (!job) return null;
    clearInterval(job.timer);
    const done = job;
    job = null;
    ui.compute.disabled = false;
    ui.cancel.disabled = true;
    return done;
  }

  function onAnswer(msg) {
    const done = finishJob();
    const roundTripMs = performance.now() - done.t0;
    if (msg.type === 'result') {
      try {
        showResult(msg, done.params, roundTripMs, done.freshWorker);
      } catch (err) {
        const message = `Drawing the hull failed: ${err.message}`;
        console.error(`[hullkit] ${message}`, err);
        showFailure(message, null);
      }
    } else if (msg.type === 'error') {
      const prefix = msg.kind === 'input' ? 'Cannot compute the hull' : 'Hull computation failed';
      const message = `${prefix}: ${String(msg.message).replace(/^hull:\s*/, '')}`;
      if (msg.kind !== 'input') console.error(`[hullkit] ${message}`);
      showFailure(message, msg, done.params);
    }
  }

  const ALGORITHM_LABELS = { giftwrap: 'gift wrapping · O(n·h)', quickhull: 'quickhull · O(n log n)' };

  function setAlgorithms(algorithms) {
    if (!Array.isArray(algorithms) || algorithms.length === 0) return;
    const current = ui.algorithm.value || preferredAlgorithm;
    ui.algorithm.replaceChildren(...algorithms.map((name) => {
      const option = document.createElement('option');
      option.value = name;
      option.textContent = ALGORITHM_LABELS[name] ?? name;
      return option;
    }));
    // The library lists its default first.
    ui.algorithm.value = algorithms.includes(current) ? current : algorithms[0];
    ui.algorithmField.hidden = false;
    ui.epsilonField.hidden = !algorithms.includes('giftwrap');
    updateEpsilonField();
  }

  /** The first hull, once the view is shown and the module has loaded (or failed to). */
  function startOnce() {
    if (started || !active) return;
    if (worker.loadError) {
      started = true;
      const message = `Hull computation failed: ${worker.loadError}`;
      console.error(`[hullkit] ${message}`);
      showFailure(message, null);
      return;
    }
    if (!worker.ready) return;
    started = true;
    requestCompute();
  }

  const DIMENSION_NOTES = {
    2: (r) => `The points are coplanar: their hull is a flat convex polygon with ${fmtInt(r.vertices.length)} corners (volume 0).`,
    1: () => 'The points are collinear: their hull is a segment.',
    0: () => 'All points coincide: their hull is a single point.',
    [-1]: () => 'There are no points.',
  };

  const POLYGON_NAMES = { 3: 'triangle', 4: 'quadrilateral', 5: 'pentagon', 6: 'hexagon', 7: 'heptagon', 8: 'octagon' };

  /** "6 quadrilaterals", "80 triangles, 3 quadrilaterals and 1 pentagon", … (largest groups first). */
  function describeFaceSizes(sizes) {
    const groups = Object.entries(sizes).map(([k, count]) => [Number(k), count]).sort((a, b) => b[1] - a[1] || a[0] - b[0]);
    const parts = groups.slice(0, 4).map(([k, count]) => {
      const name = POLYGON_NAMES[k] ?? `${k}-gon`;
      return `${fmtInt(count)} ${name}${count === 1 ? '' : 's'}`;
    });
    if (groups.length > 4) parts.push(`${groups.length - 4} other sizes`);
    return parts.length > 1 ? `${parts.slice(0, -1).join(', ')} and ${parts.at(-1)}` : parts[0] ?? 'none';
  }

  /** A very thin 3D hull (near-coplanar points): its thickness, about 2 · volume / area. */
  function slabNote(msg, radius) {
    if (msg.dimension !== 3 || !(msg.area > 0) || !(radius > 0)) return '';
    const thickness = (2 * msg.volume) / msg.area;
    if (thickness > 1e-6 * radius) return '';
    return ` The hull is a slab about ${thickness.toExponential(1)} thick: a polytope for exact predicates, drawn flat at this scale.`;
  }

  const EXACT_NAME = 'exact predicates';

  function showResult(msg, params, roundTripMs, freshWorker) {
    const merged = Boolean(params.mergeCoplanar) && msg.dimension >= 2;
    const faces = msg.faces ?? msg.triangles.length / 3;
    const vertices = msg.vertices.length;
    const edges = msg.edges.length / 2;
    const comparison = msg.comparison ?? null;
    const d0 = performance.now();
    drawScene({ ...msg, dropped: comparison?.dropped ?? null });
    const drawMs = performance.now() - d0;

    runCount++;
    if (msg.dimension === 3) calibrate(params.algorithm, msg.n, vertices, msg.hullMs);

    setStats({
      n: fmtInt(msg.n), vertices: fmtInt(vertices), faces: fmtInt(faces), edges: fmtInt(edges),
      volume: fmtReal(msg.volume), area: fmtReal(msg.area), ms: fmtMs(msg.hullMs), rtt: fmtMs(roundTripMs),
      draw: fmtMs(drawMs),
    });
    ui.facesLabel.textContent = merged ? 'polygons' : 'triangles';
    ui.stat.faces.title = merged
      ? `${fmtInt(faces)} planar faces (${describeFaceSizes(msg.faceSizes ?? {})}), drawn as ${fmtInt(msg.triangles.length / 3)} triangles`
      : 'triangles of the hull surface';
    ui.stat.edges.title = merged ? 'sides of the polygon faces (no triangulation diagonals)' : 'edges of the triangles';
    ui.stat.volume.title = String(msg.volume);
    ui.stat.area.title = String(msg.area);
    ui.stat.ms.title = `hullkit.hull() inside the worker; points generated in ${fmtMs(msg.genMs)}, worker total ${fmtMs(msg.workerMs)}`;
    ui.stat.rtt.title = 'from posting the request to receiving the result (generation, hull, edges, transfer)';
    ui.stat.draw.title = 'building the three.js geometry and the first render on the main thread';
    const seedNote = ['custom', 'grid', 'file'].includes(params.distribution) ? '' : ` (seed ${params.seed})`;
    const fromFile = params.distribution === 'file';
    let status = `Hull of ${params.distribution === 'custom' ? `${fmtInt(msg.n)} pasted points` : describeInput(params)}${fromFile ? '' : seedNote}.`;
    if (interiorStride > 1) status += ` Drawing every ${fmtInt(interiorStride)}th of the ${fmtInt(interiorTotal)} interior points.`;
    if (dense) status += ' So many faces: drawn without the wireframe and back faces, so that orbiting stays smooth.';
    if (DIMENSION_NOTES[msg.dimension]) status += ` ${DIMENSION_NOTES[msg.dimension](msg)}`;
    if (merged && msg.dimension === 3) {
      const sizes = msg.faceSizes ?? {};
      status += Object.keys(sizes).every((k) => k === '3')
        ? ` No coplanar triangles to merge: ${fmtInt(faces)} triangular faces.`
        : ` Coplanar triangles merged into ${fmtInt(faces)} faces: ${describeFaceSizes(sizes)}.`;
    }
    status += slabNote(msg, viewRadius);
    if (comparison) status += ` ${epsilonSentence(comparison, { vertices, faces, volume: msg.volume })}`;
    if (freshWorker) status += ' The round trip includes starting the worker and loading the WebAssembly module.';
    ui.status.textContent = status;
    showComparison(comparison, { vertices, faces, volume: msg.volume }, merged);

    lastHull = { xyz: msg.xyz, triangles: msg.triangles, dimension: msg.dimension, name: exportName(params) };
    setExportEnabled(msg.triangles.length > 0);
    stepper.offer({
      coords: msg.xyz, n: msg.n, eligible: msg.dimension === 3,
      why: msg.dimension === 3 ? `Available for at most ${STEP_MAX} points (set n to ${STEP_MAX} or fewer).` : 'Available for three-dimensional hulls.',
    });
    window.hullkitStats = {
      n: msg.n, vertices, faces, edges, triangles: msg.triangles.length / 3, merged,
      interiorStride,
      volume: msg.volume, area: msg.area, dimension: msg.dimension,
      ms: msg.hullMs, roundTripMs, distribution: params.distribution, seed: params.seed,
      algorithm: params.algorithm ?? null, epsilon: params.epsilon ?? 'exact', run: runCount,
    };
    // The triangles too, on demand (non-enumerable: JSON of the hook stays short).
    const drawnTriangles = msg.triangles;
    Object.defineProperty(window.hullkitStats, 'triangleList', { get: () => Array.from(drawnTriangles) });
    window.hullkitEpsilon = comparison ? publicComparison(comparison, { vertices, faces, volume: msg.volume }) : null;
    window.hullkitError = null;
    lastFailed = false;
    setState('ready');
  }

  const fmtEps = (c) => `ε = ${c.epsilon.toExponential(1)}`;
  const hullSummary = (h) => `${fmtInt(h.vertices)} vertices, ${fmtInt(h.faces)} faces, volume ${fmtReal(h.volume)}`;

  /** What the seed's epsilon did, as one or two sentences for the status line. */
  function epsilonSentence(c, seed) {
    const exact = c.exact;
    if (!exact) return `Exact predicates could not be compared: ${c.exactError ?? 'unknown error'}.`;
    if (c.outcome === 'failed') {
      const exactHull = {
        3: () => `is a polytope with ${hullSummary(exact)}`,
        2: () => `is a flat polygon with ${fmtInt(exact.vertices)} corners`,
        1: () => 'is a segment',
        0: () => 'is a single point',
      }[exact.dimension]?.() ?? 'is empty';
      return `The seed's epsilon (${fmtEps(c)}) could not decide these points, so gift wrapping gave up; ` +
        `with ${EXACT_NAME} the hull ${exactHull}.`;
    }
    if (c.outcome === 'same') {
      return `The seed's epsilon (${fmtEps(c)}) made no difference here: ${EXACT_NAME} give the same ${fmtInt(exact.vertices)} vertices.`;
    }
    const parts = [];
    const dropped = c.dropped?.length ?? 0;
    if (dropped) parts.push(`left out ${fmtInt(dropped)} extreme point${dropped === 1 ? '' : 's'} (pink) that it took to lie on a face plane`);
    if (c.added) parts.push(`kept ${fmtInt(c.added)} point${c.added === 1 ? '' : 's'} that ${c.added === 1 ? 'is' : 'are'} not extreme`);
    if (!parts.length) parts.push('split the faces differently');
    return `The seed's epsilon (${fmtEps(c)}) changed the hull: it ${parts.join(' and ')}; ` +
      `${fmtInt(seed.vertices)} vertices instead of the exact ${fmtInt(exact.vertices)}.`;
  }

  function showComparison(c, seed, merged) {
    if (!c) {
      ui.compare.hidden = true;
      return;
    }
    const cells = (row, values) => row.querySelectorAll('td').forEach((td, i) => { td.textContent = values[i] ?? ''; });
    const facesWord = merged ? 'polygons' : 'triangles';
    ui.compare.dataset.outcome = c.outcome;
    ui.compareText.textContent = `The seed's ${fmtEps(c)} ` + {
      same: 'gives the exact hull',
      different: `gives a different hull from ${EXACT_NAME}`,
      failed: `fails; ${EXACT_NAME} succeed`,
    }[c.outcome];
    if (seed) cells(ui.compareSeed, [fmtInt(seed.vertices), fmtInt(seed.faces), fmtReal(seed.volume)]);
    else cells(ui.compareSeed, ['error', '—', '—']);
    if (c.exact) cells(ui.compareExact, [fmtInt(c.exact.vertices), fmtInt(c.exact.faces), fmtReal(c.exact.volume)]);
    else cells(ui.compareExact, ['error', '—', '—']);
    ui.compare.querySelector('thead th:nth-child(3)').textContent = facesWord;
    ui.compare.hidden = false;
  }

  function publicComparison(c, seed) {
    return {
      outcome: c.outcome, epsilon: c.epsilon, seed, exact: c.exact,
      dropped: c.dropped ? c.dropped.length : 0, added: c.added ?? 0,
    };
  }

  function showFailure(message, msg, params = null) {
    const comparison = msg?.comparison ?? null;
    lastHull = null;
    setExportEnabled(false);
    stepper.offer({ why: 'Compute a hull first.' });
    if (msg && msg.xyz && msg.xyz.length % 3 === 0) {
      drawScene({ xyz: msg.xyz }); // show the offending input
      setStats({ n: fmtInt(msg.n) });
    } else {
      clearContent();
      requestRender();
      setStats({});
    }
    ui.facesLabel.textContent = 'faces';
    ui.error.textContent = message;
    ui.error.hidden = false;
    ui.status.textContent = comparison ? epsilonSentence(comparison, null) : '';
    showComparison(comparison, null, Boolean(params?.mergeCoplanar));
    window.hullkitError = message;
    lastFailed = true;
    window.hullkitEpsilon = comparison ? publicComparison(comparison, null) : null;
    setState('error');
  }

  function hideError() {
    ui.error.hidden = true;
    ui.error.textContent = '';
  }

  function setStats(values) {
    for (const [key, el] of Object.entries(ui.stat)) {
      el.textContent = values[key] ?? '—';
      el.title = '';
    }
  }

  function labelOf(distribution) {
    return ui.distribution.querySelector(`option[value="${distribution}"]`)?.textContent ?? distribution;
  }

  // ---------------------------------------------------------------- actions

  function requestCompute({ force = false } = {}) {
    if (job) return;
    const params = readParams();
    if (params.distribution !== 'custom') writeParams(params); // normalise what the user typed
    const estMs = estimateMs(params);
    if (!force && pendingConfirmKey !== paramsKey(params) && needsConfirmation(params, estMs)) {
      showWarning(params, estMs);
      return;
    }
    startJob(params, estMs);
  }

  function showWarning(params, estMs) {
    pendingConfirmKey = paramsKey(params);
    // Only gift wrapping asks (see needsConfirmation).
    const why = params.distribution === 'sphere'
      ? `All ${fmtInt(params.n)} points on a sphere are hull vertices, and gift wrapping costs O(n·h) = O(n²) here.`
      : `Gift wrapping costs O(n·h) for ${describeInput(params)}.`;
    ui.warningText.textContent = `${why} Estimated time ≈ ${fmtDuration(estMs)}. ` +
      'Click “Run anyway” to start; the page stays responsive and the run can be cancelled. ' +
      'Quickhull computes the same hull in well under a second.';
    ui.useCap.hidden = params.distribution === 'custom' || params.n <= SPHERE_WARN_N;
    ui.useQuickhull.hidden = ![...ui.algorithm.options].some((o) => o.value === 'quickhull');
    ui.warning.hidden = false;
    ui.compute.textContent = 'Run anyway';
    ui.compute.classList.add('warn');
    ui.status.textContent = 'Expensive run: confirm or reduce n.';
  }

  function hideWarning() {
    pendingConfirmKey = null;
    ui.warning.hidden = true;
    ui.compute.textContent = 'Compute';
    ui.compute.classList.remove('warn');
  }

  function cancelJob() {
    if (!job) return;
    worker.restart(); // the wasm call cannot be interrupted: drop the whole worker
    const done = finishJob();
    ui.status.textContent = `Cancelled after ${((performance.now() - done.t0) / 1000).toFixed(1)} s; worker restarted.`;
    setState('cancelled');
  }

  ui.form.addEventListener('submit', (event) => {
    event.preventDefault();
    requestCompute();
  });
  ui.useCap.addEventListener('click', () => {
    ui.n.value = String(SPHERE_WARN_N);
    ui.nSlider.value = String(nToSlider(SPHERE_WARN_N));
    requestCompute({ force: true });
  });
  ui.useQuickhull.addEventListener('click', () => {
    ui.algorithm.value = 'quickhull';
    updateEpsilonField();
    requestCompute({ force: true });
  });
  ui.cancel.addEventListener('click', cancelJob);

  // ---------------------------------------------------------------- files in and out

  const fileOption = ui.distribution.querySelector('option[value="file"]');

  /** Reads `file` with the C++ point readers (in the worker) and hulls its points. */
  async function openFile(file) {
    if (job) cancelJob();
    hideWarning();
    hideError();
    ui.status.textContent = `Reading ${file.name}…`;
    const msg = await readInWorker(worker, file, 'points');
    if (msg.cancelled) return;
    if (msg.error) {
      showFileError(msg.error);
      return;
    }
    fileInput = { name: file.name, xyz: msg.xyz };
    fileOption.hidden = false;
    fileOption.textContent = `from ${file.name}`;
    ui.distribution.value = 'file';
    updateSourceFields();
    requestCompute();
  }

  /** A file that cannot be read: say why; the drawing and the inputs stay as they were. */
  function showFileError(message) {
    ui.error.textContent = message;
    ui.error.hidden = false;
    ui.status.textContent = '';
    window.hullkitError = message;
    setState('error');
  }

  const exportButtons = [...document.querySelectorAll('[data-export]')];
  function setExportEnabled(on) {
    for (const b of exportButtons) b.disabled = !on;
  }
  function exportName(params) {
    if (params.distribution === 'file') return `${params.file.replace(/\.[^.]*$/, '')}-hull`;
    if (params.distribution === 'custom') return 'pasted-hull';
    return `hull-${params.distribution}-${params.n}-seed${params.seed}`;
  }
  for (const button of exportButtons) {
    button.addEventListener('click', () => {
      if (!lastHull) return;
      const mesh = compact(lastHull.xyz, lastHull.triangles, 3);
      const note = `convex hull by hullkit: ${mesh.positions.length / 3} vertices, ${mesh.triangles.length / 3} triangles, outward`;
      const format = button.dataset.export;
      if (format === 'obj') download(`${lastHull.name}.obj`, objText(mesh, note), 'model/obj');
      else if (format === 'off') download(`${lastHull.name}.off`, offText(mesh, note), 'text/plain');
      else if (format === 'glb') download(`${lastHull.name}.glb`, glbBytes(mesh), 'model/gltf-binary');
      else download(`${lastHull.name}.stl`, stlBytes(mesh, note), 'model/stl');
    });
  }

  // ---------------------------------------------------------------- gift wrapping, step by step

  const stepper = createGiftwrapStepper({
    worker, requestRender,
    targets: (xyz) => [{ scene, positions: centredPositions(xyz).positions }],
    request: (xyz, scan) => ({ type: 'trace', xyz, scan }),
    hideResult: (hidden) => { content.visible = !hidden; requestRender(); },
  });
  ui.nSlider.addEventListener('input', () => {
    ui.n.value = String(sliderToN(Number(ui.nSlider.value)));
    onParamsEdited();
  });
  ui.n.addEventListener('input', () => {
    const v = Number(ui.n.value);
    if (Number.isFinite(v)) ui.nSlider.value = String(nToSlider(v));
    onParamsEdited();
  });
  ui.seed.addEventListener('input', onParamsEdited);
  ui.customPoints.addEventListener('input', onParamsEdited);
  ui.algorithm.addEventListener('change', () => {
    updateEpsilonField();
    onParamsEdited();
  });
  ui.epsilon.addEventListener('change', () => {
    updateEpsilonField();
    onParamsEdited();
  });
  ui.merge.addEventListener('change', onParamsEdited);
  ui.distribution.addEventListener('change', () => {
    updateSourceFields();
    onParamsEdited();
  });
  ui.reseed.addEventListener('click', () => {
    ui.seed.value = String((Math.random() * 0x100000000) >>> 0);
    onParamsEdited();
  });
  function onParamsEdited() {
    updateNHint();
    if (pendingConfirmKey !== null && pendingConfirmKey !== paramsKey(readParams())) {
      hideWarning();
      if (!job) ui.status.textContent = '';
    }
  }
  // Ctrl/Cmd+Enter in the text area computes (Enter alone inserts a line).
  ui.customPoints.addEventListener('keydown', (event) => {
    if (event.key === 'Enter' && (event.ctrlKey || event.metaKey)) {
      event.preventDefault();
      requestCompute();
    }
  });

  for (const box of [ui.showFaces, ui.showEdges, ui.showPoints]) {
    box.addEventListener('change', () => { applyVisibility(); requestRender(); });
  }
  ui.resetView.addEventListener('click', () => { frameView(false); requestRender(); });

  // ---------------------------------------------------------------- start

  /**
   * Compile and link every shader program up front, while the worker loads the
   * wasm module: one draw of each material with the geometry placed behind the
   * camera (drivers defer the real work of compile() to the first draw).
   */
  function warmUpShaders() {
    const geom = new THREE.BufferGeometry();
    geom.setAttribute('position', new THREE.BufferAttribute(new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]), 3));
    geom.setIndex([0, 1, 2]);
    const group = new THREE.Group();
    group.add(
      new THREE.Mesh(geom, materials.faceBack), new THREE.Mesh(geom, materials.faceFront),
      new THREE.LineSegments(geom, materials.edgeBack), new THREE.LineSegments(geom, materials.edgeFront),
      new THREE.Points(geom, materials.point), new THREE.Points(geom, materials.vertex),
      new THREE.Points(geom, materials.vertexFront), new THREE.Points(geom, materials.dropped),
    );
    group.position.copy(camera.position).multiplyScalar(3); // on the view axis, behind the camera
    for (const obj of group.children) obj.frustumCulled = false;
    scene.add(group);
    try {
      renderer.render(scene, camera);
    } finally {
      scene.remove(group);
      geom.dispose();
    }
  }

  ui.customPoints.value = CUSTOM_SAMPLE;
  writeParams(paramsFromUrl(new URLSearchParams(location.search)));
  updateEpsilonField();
  worker.on('ready', (info) => { setAlgorithms(info.algorithms); startOnce(); });
  worker.on('load-error', () => startOnce());
  if (worker.info) setAlgorithms(worker.info.algorithms);
  warmUpShaders();

  return {
    name: 'hull',
    render,
    resize,
    /** Shown: take the controls and draw; the first hull starts here. */
    activate() {
      active = true;
      controls.enabled = true;
      startOnce();
      requestRender();
    },
    deactivate() {
      active = false;
      controls.enabled = false;
    },
    /** The URL changed (back/forward): show its parameters and recompute when they differ. */
    applyUrl(q) {
      const before = paramsKey(readParams());
      writeParams(paramsFromUrl(q));
      updateEpsilonField();
      if (preferredAlgorithm && [...ui.algorithm.options].some((o) => o.value === preferredAlgorithm)) {
        ui.algorithm.value = preferredAlgorithm;
        updateEpsilonField();
      }
      if (started && paramsKey(readParams()) !== before && !job) startJob(readParams(), 0);
    },
    /** The view's options for the URL when it is switched to. */
    urlParams() {
      return urlParamsOf(readParams());
    },
    openFile,
    fileHint: 'points from OBJ, OFF, PLY, STL, glTF or x y z text',
    busyLabel: () => (job ? `Computing the hull of ${describeInput(job.params)}` : 'Working'),
    cancel() {
      if (job) cancelJob();
      else stepper.cancel();
    },
  };
}
