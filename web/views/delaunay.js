// The Delaunay view: 2D points lifted onto the paraboloid z = x² + y²; the lower faces of their
// convex hull (shaded) project to the Delaunay triangulation of the plane. Side by side (the
// paraboloid in 3D | the plane seen from above) or blended (the paraboloid over the plane in one
// 3D view). Clicks add points, hovering a triangle shows its empty circumcircle (and its lift,
// which lies in the plane of the lifted face), Voronoi cells on request.
//
// Test hook: window.hullkitDelaunay = {n, distinct, duplicates, triangles, hull, dimension,
// ms, set, seed, added, run} after each triangulation drawn.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { discTexture, clearGroup, zUpCamera } from '../app/stage.js';
import { fmtInt, fmtMs } from '../app/format.js';
import { writeUrl } from '../app/url-state.js';
import { showError, readInWorker } from '../app/panel.js';
import { compact, offText, triangulationSvg, download } from '../app/export.js';
import { createGiftwrapStepper } from './giftwrap-stepper.js';
import { POINT_SETS, generatePoints2, gridSide2 } from '../points2d.js';

const N_MAX = 50_000;
const FILE_MAX = 200_000; // points of an opened file the page draws (the CLI takes any number)
const DEFAULTS = { set: 'uniform', n: 300, seed: 1, layout: 'side', voronoi: false, algorithm: '' };
const FIGURE1_N = 1024;
const GIFTWRAP_MAX = 5000;
const LIFT = 0.75; // drawn height of the paraboloid per unit of x² + y²
const PLANE_Z = -0.55; // where the blended layout draws the plane under the paraboloid
const COLORS = {
  face: 0x3fb8c9,
  edge: 0xa6eef8,
  plane: 0x7fd6e3,
  hull: 0xffffff,
  point: 0xffb547,
  voronoi: 0xc58cff,
  circle: 0xff6fa5,
  guide: 0x2a3442,
  drop: 0x56657a,
};

export function createDelaunayView({ stage, worker, setState, viewport }) {
  const $ = (id) => document.getElementById(id);
  const ui = {
    form: $('dl-controls'), set: $('dl-set'), n: $('dl-n'), nHint: $('dl-n-hint'), seed: $('dl-seed'),
    algorithm: $('dl-algorithm'), algorithmField: $('dl-algorithm-field'), clear: $('dl-clear'),
    status: $('dl-status'), error: $('dl-error'), layout: $('dl-layout'),
    showLifted: $('dl-show-lifted'), showVoronoi: $('dl-show-voronoi'), showDrops: $('dl-show-drops'),
    stat: { n: $('dl-stat-n'), triangles: $('dl-stat-triangles'), hull: $('dl-stat-hull'), ms: $('dl-stat-ms'), rtt: $('dl-stat-rtt'), dup: $('dl-stat-dup') },
  };

  // Two panes over the canvas: the 3D one orbits, the plane one takes hover and clicks.
  const pane3d = document.createElement('div');
  const pane2d = document.createElement('div');
  pane3d.className = 'pane pane-3d';
  pane2d.className = 'pane pane-2d';
  pane3d.dataset.for = pane2d.dataset.for = 'delaunay';
  pane3d.hidden = pane2d.hidden = true;
  const label3d = Object.assign(document.createElement('p'), { className: 'pane-label', textContent: 'lifted: z = x² + y², lower hull shaded' });
  const label2d = Object.assign(document.createElement('p'), { className: 'pane-label', textContent: 'projected: Delaunay triangulation' });
  pane3d.append(label3d);
  pane2d.append(label2d);
  viewport.append(pane3d, pane2d);

  // ------------------------------------------------------------ scenes

  const disc = discTexture();
  const materials = {
    face: new THREE.MeshStandardMaterial({
      color: COLORS.face, transparent: true, opacity: 0.55, side: THREE.DoubleSide, flatShading: true,
      roughness: 0.5, metalness: 0, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
    }),
    liftedEdge: new THREE.LineBasicMaterial({ color: COLORS.edge, transparent: true, opacity: 0.75 }),
    planeFill: new THREE.MeshBasicMaterial({ color: COLORS.face, transparent: true, opacity: 0.12, side: THREE.DoubleSide, depthWrite: false }),
    planeEdge: new THREE.LineBasicMaterial({ color: COLORS.plane, transparent: true, opacity: 0.85 }),
    hull: new THREE.LineBasicMaterial({ color: COLORS.hull }),
    point: new THREE.PointsMaterial({ color: COLORS.point, size: 6, sizeAttenuation: false, map: disc, alphaTest: 0.5 }),
    voronoi: new THREE.LineBasicMaterial({ color: COLORS.voronoi, transparent: true, opacity: 0.8 }),
    circle: new THREE.LineBasicMaterial({ color: COLORS.circle, depthTest: false }),
    ring: new THREE.MeshBasicMaterial({ color: COLORS.circle, side: THREE.DoubleSide, depthTest: false }),
    hoverFill: new THREE.MeshBasicMaterial({ color: COLORS.circle, transparent: true, opacity: 0.35, side: THREE.DoubleSide, depthTest: false }),
    guide: new THREE.LineBasicMaterial({ color: COLORS.guide }),
    drop: new THREE.LineBasicMaterial({ color: COLORS.drop, transparent: true, opacity: 0.45 }),
  };

  const scene3d = new THREE.Scene();
  const camera3d = zUpCamera(scene3d);
  const controls = new OrbitControls(camera3d, pane3d);
  controls.enableDamping = true;
  controls.dampingFactor = 0.12;
  controls.enabled = false;

  const scene2d = new THREE.Scene();
  const camera2d = new THREE.OrthographicCamera(-1, 1, 1, -1, -10, 10);

  const lifted = new THREE.Group(); // paraboloid content, in scene3d
  const planeIn3d = new THREE.Group(); // the plane drawing again, under the paraboloid (blended)
  planeIn3d.position.z = PLANE_Z;
  const plane = new THREE.Group(); // the plane drawing, in scene2d
  const hover3d = new THREE.Group();
  const hover2d = new THREE.Group();
  const hoverPlane3d = new THREE.Group();
  hoverPlane3d.position.z = PLANE_Z;
  scene3d.add(lifted, planeIn3d, hover3d, hoverPlane3d, paraboloidGuide());
  scene2d.add(plane, hover2d);

  /** Faint rings and meridians of the paraboloid, so that the lift reads as a surface. */
  function paraboloidGuide() {
    const pos = [];
    const r = 1.2;
    for (let ring = 1; ring <= 5; ring++) {
      const rr = (r * ring) / 5;
      for (let k = 0; k < 64; k++) {
        const a = (2 * Math.PI * k) / 64, b = (2 * Math.PI * (k + 1)) / 64;
        pos.push(rr * Math.cos(a), rr * Math.sin(a), LIFT * rr * rr, rr * Math.cos(b), rr * Math.sin(b), LIFT * rr * rr);
      }
    }
    for (let m = 0; m < 12; m++) {
      const a = (2 * Math.PI * m) / 12;
      for (let k = 0; k < 16; k++) {
        const r0 = (r * k) / 16, r1 = (r * (k + 1)) / 16;
        pos.push(r0 * Math.cos(a), r0 * Math.sin(a), LIFT * r0 * r0, r1 * Math.cos(a), r1 * Math.sin(a), LIFT * r1 * r1);
      }
    }
    const geom = new THREE.BufferGeometry();
    geom.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
    return new THREE.LineSegments(geom, materials.guide);
  }

  // ------------------------------------------------------------ state

  let active = false;
  let base = null; // {set, n, seed, xy}: the generated points
  let fileInput = null; // {name, xy}: the points of the last file opened
  let added = []; // clicked points [[x, y], ...]
  let xy = new Float64Array(0); // base + added
  let tri = null; // the last triangulation drawn
  let cells = null;
  let extent = { cx: 0, cy: 0, r: 1 };
  let lastTriangle = 0;
  let runCount = 0;
  let pendingKey = null; // what is being computed
  let drawnKey = null;
  let requestSeq = 0;
  let framed = false;

  function requestRender() {
    if (active) stage.requestRender();
  }
  controls.addEventListener('change', requestRender);

  // ------------------------------------------------------------ layout and rendering

  const panes = { a: null, b: null }; // {x, y, w, h} in CSS pixels, y from the top

  function layoutPanes() {
    const { width: w, height: h } = stage.size;
    if (ui.layout.value === 'blend') {
      panes.a = { x: 0, y: 0, w, h };
      panes.b = null;
    } else if (w >= h) {
      const half = Math.floor(w / 2);
      panes.a = { x: 0, y: 0, w: half, h };
      panes.b = { x: half, y: 0, w: w - half, h };
    } else {
      const half = Math.floor(h / 2);
      panes.a = { x: 0, y: 0, w, h: half };
      panes.b = { x: 0, y: half, w, h: h - half };
    }
    place(pane3d, panes.a);
    place(pane2d, panes.b);
    label3d.textContent = panes.b ? 'lifted: z = x² + y², lower hull shaded' : 'lifted paraboloid over the plane: click the plane to add points';
    planeIn3d.visible = hoverPlane3d.visible = !panes.b;
    camera3d.aspect = panes.a.w / panes.a.h;
    camera3d.updateProjectionMatrix();
    if (panes.b) fit2d();
  }

  function place(el, rect) {
    if (!rect) {
      el.style.display = 'none';
      return;
    }
    el.style.display = '';
    Object.assign(el.style, { left: `${rect.x}px`, top: `${rect.y}px`, width: `${rect.w}px`, height: `${rect.h}px` });
  }

  /** The orthographic camera shows the points' box with a margin, undistorted. */
  function fit2d() {
    const { w, h } = panes.b;
    const half = extent.r * 1.12;
    const aspect = w / h;
    const hx = aspect >= 1 ? half * aspect : half;
    const hy = aspect >= 1 ? half : half / aspect;
    Object.assign(camera2d, { left: extent.cx - hx, right: extent.cx + hx, top: extent.cy + hy, bottom: extent.cy - hy });
    camera2d.position.set(0, 0, 5);
    camera2d.updateProjectionMatrix();
  }

  function frame3d() {
    const dir = new THREE.Vector3(0.9, -1.7, 0.95).normalize();
    const R = Math.max(extent.r, 0.5);
    // The lifted points' bounding sphere (blended: the plane below too), with a little room.
    const r = 1.05 * Math.hypot(R, R, (LIFT * R * R - (panes.b ? 0 : PLANE_Z)) / 2);
    const vfov = THREE.MathUtils.degToRad(camera3d.fov);
    const hfov = 2 * Math.atan(Math.tan(vfov / 2) * camera3d.aspect);
    const dist = r / Math.sin(Math.min(vfov, hfov) / 2);
    controls.target.set(extent.cx, extent.cy, panes.b ? (LIFT * R * R) / 2 : (LIFT * R * R + PLANE_Z) / 2);
    camera3d.position.copy(controls.target).addScaledVector(dir, dist);
    camera3d.near = dist / 100;
    camera3d.far = dist * 10;
    camera3d.updateProjectionMatrix();
    controls.update();
  }

  function render(r) {
    controls.update();
    const H = stage.size.height;
    r.setScissorTest(true);
    const draw = (rect, scene, camera) => {
      r.setViewport(rect.x, H - rect.y - rect.h, rect.w, rect.h);
      r.setScissor(rect.x, H - rect.y - rect.h, rect.w, rect.h);
      r.render(scene, camera);
    };
    draw(panes.a, scene3d, camera3d);
    if (panes.b) draw(panes.b, scene2d, camera2d);
    r.setScissorTest(false);
  }

  function resize() {
    layoutPanes();
    if (!framed) frame3d();
  }

  // ------------------------------------------------------------ drawing

  /** The points as drawn: lifted onto the paraboloid (z = LIFT (x² + y²)) and in the plane (z = 0). */
  function liftedAndPlanePositions(coords) {
    const n = coords.length / 2;
    const liftedPos = new Float32Array(3 * n);
    const planePos = new Float32Array(3 * n);
    for (let i = 0; i < n; i++) {
      const x = coords[2 * i], y = coords[2 * i + 1];
      liftedPos.set([x, y, LIFT * (x * x + y * y)], 3 * i);
      planePos.set([x, y, 0], 3 * i);
    }
    return { liftedPos, planePos };
  }

  function drawTriangulation() {
    clearGroup(lifted);
    clearGroup(plane);
    clearGroup(planeIn3d);
    const n = xy.length / 2;
    const { liftedPos, planePos } = liftedAndPlanePositions(xy);
    const liftedAttr = new THREE.BufferAttribute(liftedPos, 3);
    const planeAttr = new THREE.BufferAttribute(planePos, 3);
    const edges = triangleEdges(tri.triangles, tri.halfedges);
    const size = n <= 400 ? 6 : n <= 3000 ? 4 : n <= 20000 ? 2.5 : 1.5;
    materials.point.size = size;

    const add = (group, obj, order) => {
      obj.renderOrder = order;
      obj.frustumCulled = false;
      group.add(obj);
      return obj;
    };
    const geometry = (attr, index) => {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', attr);
      if (index) g.setIndex(new THREE.BufferAttribute(index, 1));
      return g;
    };

    // The paraboloid: lower hull faces, their edges, the lifted points, and lift lines.
    const faces = add(lifted, new THREE.Mesh(geometry(liftedAttr, tri.triangles), materials.face), 1);
    faces.name = 'faces';
    add(lifted, new THREE.LineSegments(geometry(liftedAttr, edges), materials.liftedEdge), 2);
    add(lifted, new THREE.Points(geometry(liftedAttr), materials.point), 3);
    if (n <= 600) {
      const drops = new Float32Array(6 * n);
      for (let i = 0; i < n; i++) drops.set([xy[2 * i], xy[2 * i + 1], PLANE_Z, xy[2 * i], xy[2 * i + 1], liftedPos[3 * i + 2]], 6 * i);
      const dropLines = add(lifted, new THREE.LineSegments(geometry(new THREE.BufferAttribute(drops, 3)), materials.drop), 0);
      dropLines.name = 'drops';
    }

    // The plane: triangles, edges, hull outline, points; the same objects again under the paraboloid.
    const hullLoop = new Uint32Array(2 * tri.hull.length);
    for (let i = 0; i < tri.hull.length; i++) hullLoop.set([tri.hull[i], tri.hull[(i + 1) % tri.hull.length]], 2 * i);
    const planeGeoms = [
      [geometry(planeAttr, tri.triangles), (g) => new THREE.Mesh(g, materials.planeFill), 0],
      [geometry(planeAttr, edges), (g) => new THREE.LineSegments(g, materials.planeEdge), 1],
      [geometry(planeAttr, hullLoop), (g) => new THREE.LineSegments(g, materials.hull), 2],
      [geometry(planeAttr), (g) => new THREE.Points(g, materials.point), 4],
    ];
    for (const [g, make, order] of planeGeoms) {
      add(plane, make(g), order);
      add(planeIn3d, make(g), order);
    }
    drawVoronoi();
    applyVisibility();
  }

  function drawVoronoi() {
    for (const group of [plane, planeIn3d]) {
      const old = group.getObjectByName('voronoi');
      if (old) {
        group.remove(old);
        old.geometry.dispose();
      }
    }
    if (!cells || !ui.showVoronoi.checked) return;
    const { cellOffsets, cellXY } = cells;
    const pos = [];
    for (let c = 0; c + 1 < cellOffsets.length; c++) {
      const a = cellOffsets[c], b = cellOffsets[c + 1];
      for (let k = a; k < b; k++) {
        const l = k + 1 < b ? k + 1 : a;
        pos.push(cellXY[2 * k], cellXY[2 * k + 1], 0.001, cellXY[2 * l], cellXY[2 * l + 1], 0.001);
      }
    }
    const geom = new THREE.BufferGeometry();
    geom.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
    for (const group of [plane, planeIn3d]) {
      const lines = new THREE.LineSegments(geom, materials.voronoi);
      lines.name = 'voronoi';
      lines.renderOrder = 3;
      lines.frustumCulled = false;
      group.add(lines);
    }
  }

  function applyVisibility() {
    const faces = lifted.getObjectByName('faces');
    if (faces) faces.visible = ui.showLifted.checked;
    const drops = lifted.getObjectByName('drops');
    if (drops) drops.visible = ui.showDrops.checked && !panes.b;
  }

  /** Every edge once: the halfedge with the larger twin index, or a hull halfedge. */
  function triangleEdges(triangles, halfedges) {
    const out = [];
    for (let e = 0; e < triangles.length; e++) {
      if (halfedges[e] > e) continue;
      out.push(triangles[e], triangles[e % 3 === 2 ? e - 2 : e + 1]);
    }
    return Uint32Array.from(out);
  }

  // ------------------------------------------------------------ hover: the empty circumcircle

  const orient = (ax, ay, bx, by, cx, cy) => (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);

  /** The triangle containing (x, y), by walking from the last one found; -1 outside the hull. */
  function locate(x, y) {
    if (!tri || tri.triangles.length === 0) return -1;
    const T = tri.triangles, H = tri.halfedges;
    let t = Math.min(lastTriangle, T.length / 3 - 1);
    for (let steps = 0; steps < T.length; steps++) {
      let crossed = false;
      for (let k = 0; k < 3; k++) {
        const e = 3 * t + k;
        const a = T[e], b = T[k === 2 ? 3 * t : e + 1];
        // Clockwise triangles (y up): the inside lies to the right of every edge.
        if (orient(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1], x, y) > 0) {
          if (H[e] < 0) return -1;
          t = Math.floor(H[e] / 3);
          crossed = true;
          break;
        }
      }
      if (!crossed) return (lastTriangle = t);
    }
    return -1; // a cycle (rounding on near-degenerate input): no highlight
  }

  function circumcircle(t) {
    const [a, b, c] = [0, 1, 2].map((k) => tri.triangles[3 * t + k]);
    const ax = xy[2 * a], ay = xy[2 * a + 1];
    const bx = xy[2 * b] - ax, by = xy[2 * b + 1] - ay, cx = xy[2 * c] - ax, cy = xy[2 * c + 1] - ay;
    const d = 2 * (bx * cy - by * cx);
    const b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
    return { corners: [a, b, c], x: ax + ux, y: ay + uy, r: Math.hypot(ux, uy) };
  }

  function showHover(t) {
    for (const g of [hover3d, hover2d, hoverPlane3d]) clearGroup(g);
    if (t >= 0) {
      const { corners, x, y, r } = circumcircle(t);
      const liftedRing = [];
      for (let k = 0; k <= 96; k++) {
        const a = (2 * Math.PI * k) / 96;
        const px = x + r * Math.cos(a), py = y + r * Math.sin(a);
        liftedRing.push(px, py, LIFT * (px * px + py * py)); // the circle lifts into the face's plane
      }
      const line = (pos, group) => {
        const g = new THREE.BufferGeometry();
        g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
        const l = new THREE.Line(g, materials.circle);
        l.renderOrder = 10;
        l.frustumCulled = false;
        group.add(l);
      };
      const fill = (lift, group) => {
        const pos = corners.flatMap((i) => {
          const px = xy[2 * i], py = xy[2 * i + 1];
          return [px, py, lift ? LIFT * (px * px + py * py) : 0.002];
        });
        const g = new THREE.BufferGeometry();
        g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
        const m = new THREE.Mesh(g, materials.hoverFill);
        m.renderOrder = 9;
        m.frustumCulled = false;
        group.add(m);
      };
      // In the plane a ring a few pixels wide (WebGL lines are one pixel).
      const width = extent.r * 0.005;
      const ringGeom = new THREE.RingGeometry(Math.max(0, r - width), r + width, 96, 1);
      ringGeom.translate(x, y, 0.003);
      for (const group of [hover2d, hoverPlane3d]) {
        const m = new THREE.Mesh(ringGeom, materials.ring);
        m.renderOrder = 10;
        m.frustumCulled = false;
        group.add(m);
        fill(false, group);
      }
      line(liftedRing, hover3d);
      fill(true, hover3d);
    }
    window.hullkitDelaunayHover = t >= 0 ? { triangle: t, ...circumcircle(t) } : null;
    requestRender();
  }

  // ------------------------------------------------------------ pointer: hover and click to add

  const raycaster = new THREE.Raycaster();
  const planeZ = new THREE.Plane(new THREE.Vector3(0, 0, 1), -PLANE_Z);

  /** The plane point under the pointer, or null. */
  function planePoint(event, pane) {
    const rect = pane.getBoundingClientRect();
    const ndc = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1, -((event.clientY - rect.top) / rect.height) * 2 + 1);
    if (pane === pane2d) {
      const v = new THREE.Vector3(ndc.x, ndc.y, 0).unproject(camera2d);
      return [v.x, v.y];
    }
    if (panes.b) return null; // side by side: the 3D pane only orbits
    raycaster.setFromCamera(ndc, camera3d);
    const hit = raycaster.ray.intersectPlane(planeZ, new THREE.Vector3());
    return hit ? [hit.x, hit.y] : null;
  }

  for (const pane of [pane2d, pane3d]) {
    let down = null;
    pane.addEventListener('pointerdown', (event) => { down = { x: event.clientX, y: event.clientY, t: performance.now() }; });
    pane.addEventListener('pointermove', (event) => {
      if (event.buttons) return;
      const p = planePoint(event, pane);
      showHover(p ? locate(p[0], p[1]) : -1);
    });
    pane.addEventListener('pointerleave', () => showHover(-1));
    pane.addEventListener('pointerup', (event) => {
      if (!down || Math.hypot(event.clientX - down.x, event.clientY - down.y) > 5 || performance.now() - down.t > 600) return;
      const p = planePoint(event, pane);
      if (!p || Math.abs(p[0] - extent.cx) > 4 * extent.r || Math.abs(p[1] - extent.cy) > 4 * extent.r) return;
      added.push([Number(p[0].toFixed(4)), Number(p[1].toFixed(4))]);
      compute({ push: true });
    });
  }

  // ------------------------------------------------------------ parameters, URL, compute

  function readParams() {
    const set = POINT_SETS.includes(ui.set.value) || (ui.set.value === 'file' && fileInput) ? ui.set.value : DEFAULTS.set;
    let n = Math.round(Number(ui.n.value));
    if (!Number.isFinite(n) || ui.n.value.trim() === '') n = DEFAULTS.n;
    n = Math.max(0, Math.min(N_MAX, n));
    let seed = Math.floor(Number(ui.seed.value));
    seed = Number.isFinite(seed) ? seed >>> 0 : DEFAULTS.seed;
    return { set, n, seed, layout: ui.layout.value, voronoi: ui.showVoronoi.checked, algorithm: ui.algorithm.value };
  }

  function writeParams(p) {
    ui.set.value = p.set;
    ui.n.value = String(p.n);
    ui.seed.value = String(p.seed);
    ui.layout.value = p.layout;
    ui.showVoronoi.checked = p.voronoi;
    if (p.algorithm && [...ui.algorithm.options].some((o) => o.value === p.algorithm)) ui.algorithm.value = p.algorithm;
    updateHint();
  }

  function updateHint() {
    const set = ui.set.value;
    const n = Number(ui.n.value) || 0;
    if (set === 'grid' || set === 'rotated-grid') {
      const k = gridSide2(n);
      ui.nHint.textContent = `n → ${k}×${k} = ${fmtInt(k * k)}`;
    } else {
      ui.nHint.textContent = 'n';
    }
  }

  const encodeAdded = () => added.map(([x, y]) => `${x},${y}`).join(';');
  function decodeAdded(text) {
    if (!text) return [];
    return text.split(';').map((s) => s.split(',').map(Number)).filter((p) => p.length === 2 && p.every(Number.isFinite)).slice(0, 10_000);
  }

  function urlParams() {
    const p = readParams();
    if (p.set === 'file') return { set: DEFAULTS.set }; // a file's points cannot be put in a link
    return {
      set: p.set, n: p.n, seed: p.seed,
      layout: p.layout === 'side' ? undefined : p.layout,
      voronoi: p.voronoi ? 1 : undefined,
      algo: p.algorithm && p.algorithm !== ui.algorithm.options[0]?.value ? p.algorithm : undefined,
      add: added.length ? encodeAdded() : undefined,
    };
  }

  function applyUrl(q) {
    writeParams({
      set: POINT_SETS.includes(q.get('set')) ? q.get('set') : DEFAULTS.set,
      n: q.has('n') ? Math.max(0, Math.min(N_MAX, Math.round(Number(q.get('n'))) || 0)) : DEFAULTS.n,
      seed: q.has('seed') ? Number(q.get('seed')) >>> 0 : DEFAULTS.seed,
      layout: q.get('layout') === 'blend' ? 'blend' : 'side',
      voronoi: q.get('voronoi') === '1',
      algorithm: q.get('algo') ?? '',
    });
    added = decodeAdded(q.get('add'));
    layoutPanes();
    if (active) compute({ push: false });
  }

  function setAlgorithms(info) {
    const list = info?.delaunay?.algorithms ?? ['incremental'];
    const wanted = ui.algorithm.value;
    const labels = { incremental: 'incremental insertion', giftwrap: 'gift wrapping the lifted points' };
    ui.algorithm.replaceChildren(...list.map((name) => Object.assign(document.createElement('option'), { value: name, textContent: labels[name] ?? name })));
    ui.algorithm.value = list.includes(wanted) ? wanted : list[0];
    const q = new URLSearchParams(location.search);
    if (q.get('view') === 'delaunay' && list.includes(q.get('algo'))) ui.algorithm.value = q.get('algo');
  }

  const keyOf = (p) => `${p.set}|${p.n}|${p.seed}|${p.algorithm}|${p.voronoi}|${encodeAdded()}|${p.set === 'file' ? fileInput.name : ''}`;

  /** Generates the points, asks the worker for the triangulation (and cells) and draws it. */
  function compute({ push = false, force = false } = {}) {
    if (!worker.ready) {
      setState('loading');
      ui.status.textContent = worker.loadError ? '' : 'Loading the WebAssembly module…';
      if (worker.loadError) fail(`Cannot triangulate: ${worker.loadError}`);
      return;
    }
    const p = readParams();
    const key = keyOf(p);
    if (!force && (key === pendingKey || key === cancelledKey || (key === drawnKey && pendingKey === null))) return;
    cancelledKey = null;
    if (p.set === 'file') {
      if (!base || base.xy !== fileInput.xy) base = { set: 'file', n: p.n, seed: p.seed, xy: fileInput.xy };
    } else if (!base || base.set !== p.set || base.n !== p.n || base.seed !== p.seed) {
      base = { set: p.set, n: p.n, seed: p.seed, xy: generatePoints2(p.set, p.n, p.seed) };
    }
    xy = new Float64Array(base.xy.length + 2 * added.length);
    xy.set(base.xy);
    added.forEach(([x, y], i) => xy.set([x, y], base.xy.length + 2 * i));
    extent = boundsOf(xy);
    const bounds = [extent.cx - 1.3 * extent.r, extent.cy - 1.3 * extent.r, extent.cx + 1.3 * extent.r, extent.cy + 1.3 * extent.r];

    if (active && p.set !== 'file') writeUrl('delaunay', urlParams(), { push });
    if (p.algorithm === 'giftwrap' && xy.length / 2 > GIFTWRAP_MAX) {
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
    ui.status.textContent = `Triangulating ${fmtInt(xy.length / 2)} points…`;
    const points = xy;
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

  function boundsOf(points) {
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (let i = 0; i < points.length; i += 2) {
      x0 = Math.min(x0, points[i]); x1 = Math.max(x1, points[i]);
      y0 = Math.min(y0, points[i + 1]); y1 = Math.max(y1, points[i + 1]);
    }
    if (!(x0 <= x1)) return { cx: 0, cy: 0, r: 1 };
    return { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, r: Math.max(0.5, (x1 - x0) / 2, (y1 - y0) / 2) };
  }

  function show(msg, p, roundTripMs, points) {
    xy = points;
    tri = msg;
    cells = msg.cells ?? null;
    lastTriangle = 0;
    showHover(-1);
    layoutPanes();
    if (!framed) {
      frame3d();
      framed = true;
    }
    drawTriangulation();
    runCount++;
    const n = xy.length / 2;
    const triangles = tri.triangles.length / 3;
    const distinct = n - tri.duplicateCount;
    setStats({
      n: fmtInt(n), triangles: fmtInt(triangles), hull: fmtInt(tri.hull.length),
      ms: fmtMs(msg.ms), rtt: fmtMs(roundTripMs), dup: fmtInt(tri.duplicateCount),
    });
    ui.stat.ms.title = 'hullkit.delaunay() inside the worker';
    const setLabel = p.set === 'file' ? fileInput.name : ui.set.selectedOptions[0]?.textContent ?? p.set;
    lastExport = { xy: points, triangles: tri.triangles, hull: tri.hull, cells: msg.cells ?? null, name: p.set === 'file' ? `${fileInput.name.replace(/\.[^.]*$/, '')}-delaunay` : `delaunay-${p.set}-${p.n}-seed${p.seed}` };
    for (const b of exportButtons) b.disabled = tri.triangles.length === 0;
    let status = `${fmtInt(distinct)} points (${setLabel}${added.length ? `, ${added.length} clicked` : ''}): ` +
      `${fmtInt(triangles)} triangles = 2n − h − 2 with h = ${fmtInt(tri.hull.length)} hull points.`;
    if (tri.dimension < 2) status = `${fmtInt(distinct)} distinct points, all on one line: no triangles, the hull is the ordered line of points.`;
    if (tri.duplicateCount) status += ` ${fmtInt(tri.duplicateCount)} exact duplicates merged into their first copy.`;
    if (cells) status += ` Voronoi cells in ${fmtMs(msg.voronoiMs)}.`;
    ui.status.textContent = status;
    window.hullkitDelaunay = {
      n, distinct, duplicates: tri.duplicateCount, triangles, hull: tri.hull.length, dimension: tri.dimension,
      ms: msg.ms, set: p.set, seed: p.seed, added: added.length, voronoi: Boolean(cells), run: runCount,
    };
    liftStepper.offer({
      coords: xy, n: distinct, eligible: tri.dimension === 2 && tri.duplicateCount === 0,
      why: tri.dimension !== 2 ? 'Available when the points span the plane.'
        : tri.duplicateCount ? 'Available for points without duplicates.' : `Available for at most ${LIFT_STEP_MAX} points (set n to ${LIFT_STEP_MAX} or fewer).`,
    });
    // The coordinates too (non-enumerable: JSON of the hook stays short).
    Object.defineProperty(window.hullkitDelaunay, 'points', { value: Array.from(xy) });
    const drawn = tri.triangles;
    Object.defineProperty(window.hullkitDelaunay, 'triangleList', { get: () => Array.from(drawn) });
    setState('ready');
    requestRender();
  }

  function fail(message, logged = true) {
    liftStepper.offer({ why: 'Triangulate first.' });
    lastExport = null;
    for (const b of exportButtons) b.disabled = true;
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
      return [{ scene: scene3d, positions: liftedPos }, { scene: scene2d, positions: planePos }];
    },
    request: (coords) => ({ type: 'trace', xy: coords, lifted: true }),
    hideResult: (hidden) => {
      lifted.visible = plane.visible = planeIn3d.visible = !hidden;
      requestRender();
    },
  });

  // ------------------------------------------------------------ files in and out

  let lastExport = null;
  const exportButtons = [...document.querySelectorAll('[data-dl-export]')];
  for (const button of exportButtons) {
    button.addEventListener('click', () => {
      if (!lastExport) return;
      const { xy: pts, triangles, hull, cells: vcells, name } = lastExport;
      if (button.dataset.dlExport === 'off') {
        const mesh = compact(pts, triangles, 2);
        download(`${name}.off`, offText(mesh, `Delaunay triangulation by hullkit, z = 0, ${triangles.length / 3} triangles`), 'text/plain');
      } else {
        const svg = triangulationSvg({ xy: pts, triangles, hull, cells: vcells ? { offsets: vcells.cellOffsets, xy: vcells.cellXY } : null });
        download(`${name}.svg`, svg, 'image/svg+xml');
      }
    });
  }

  /** Reads `file` with the C++ 2D point reader (in the worker) and triangulates its points. */
  async function openFile(file) {
    ui.error.hidden = true;
    ui.status.textContent = `Reading ${file.name}…`;
    const msg = await readInWorker(worker, file, 'points2d');
    if (msg.cancelled) return;
    if (msg.error) {
      fileError(msg.error);
      return;
    }
    const count = msg.xy.length / 2;
    if (count > FILE_MAX) {
      fileError(`${file.name} has ${fmtInt(count)} points; this page draws at most ${fmtInt(FILE_MAX)} (the hullkit command and hullkit.delaunay take any number).`);
      return;
    }
    fileInput = { name: file.name, xy: msg.xy };
    const option = ui.set.querySelector('option[value="file"]');
    option.hidden = false;
    option.textContent = `from ${file.name}`;
    ui.set.value = 'file';
    ui.n.value = String(count);
    added = [];
    updateHint();
    framed = false;
    compute({ force: true });
  }

  /** A file that cannot be read: say why; the drawing stays as it was. */
  function fileError(message) {
    showError(ui.error, message, false);
    ui.status.textContent = '';
    setState('error');
  }

  function cancel() {
    if (pendingKey === null) return;
    worker.restart(); // a wasm call cannot be interrupted
    cancelledKey = pendingKey;
    pendingKey = null;
    requestSeq++;
    ui.status.textContent = 'Cancelled; the worker was restarted.';
    setState('cancelled');
  }
  let cancelledKey = null;

  ui.set.addEventListener('change', () => {
    if (ui.set.value === 'figure1') ui.n.value = String(FIGURE1_N);
    added = [];
    updateHint();
    compute({ push: true });
  });
  ui.n.addEventListener('input', updateHint);
  ui.n.addEventListener('change', () => compute({ push: true }));
  ui.seed.addEventListener('change', () => compute({ push: true }));
  ui.algorithm.addEventListener('change', () => compute({ push: true }));
  ui.clear.addEventListener('click', () => {
    added = [];
    compute({ push: true });
  });
  ui.showVoronoi.addEventListener('change', () => {
    if (ui.showVoronoi.checked && !cells) compute({ push: true });
    else {
      drawVoronoi();
      writeUrl('delaunay', urlParams(), { push: true });
      requestRender();
    }
  });
  ui.layout.addEventListener('change', () => {
    layoutPanes();
    frame3d();
    applyVisibility();
    writeUrl('delaunay', urlParams(), { push: true });
    requestRender();
  });
  for (const box of [ui.showLifted, ui.showDrops]) box.addEventListener('change', () => { applyVisibility(); requestRender(); });

  worker.on('ready', (info) => {
    setAlgorithms(info);
    if (active) compute();
  });
  worker.on('load-error', () => { if (active) compute(); });
  if (worker.info) setAlgorithms(worker.info);

  return {
    name: 'delaunay',
    render,
    resize,
    activate() {
      active = true;
      controls.enabled = true;
      layoutPanes();
      compute();
      requestRender();
    },
    deactivate() {
      active = false;
      controls.enabled = false;
      showHover(-1);
    },
    applyUrl,
    urlParams,
    openFile,
    cancel,
    fileHint: '2D points (x y per line, rbox "2 n", or OBJ/OFF/PLY/STL vertices: x and y)',
    busyLabel: () => 'Triangulating',
  };
}
