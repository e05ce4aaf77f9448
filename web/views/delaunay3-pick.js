// The Delaunay 3D view under the pointer: the drawn tetrahedron the pointer is over, its
// circumsphere and the points on it; the point a click (or tap) picks; the cutting plane's handle
// dragged along the plane's normal.
//
// The tetrahedron under the pointer is found by a ray walk, not by testing every tetrahedron: the
// ray through the pointer enters the convex hull through a hull face (the faces without a
// neighbour) and goes from tetrahedron to neighbour across the face it leaves by, until it meets a
// drawn one (shrunk, on the kept side of the cut). About n^(1/3) steps, so 100 000 points stay
// responsive. The points on the circumsphere are the corners of the tetrahedra sharing its Voronoi
// vertex, which the core decides exactly (cospherical points, as in a grid, all light up).
//
// Test hooks: window.hullkitDelaunay3Hover = {tetrahedron, corners, centre, radius, onSphere} for
// the tetrahedron shown (null when none); window.hullkitDelaunay3Screen(i) = {x, y, kept} where
// point i is on the screen; window.hullkitDelaunay3Handle() where the plane's handle is (null
// when the plane is not shown).
import * as THREE from 'three';
import { TETRAHEDRON_FACES } from '../positions.js';

const MAX_STEPS = 100_000;
const tolerance = (event) => (event.pointerType === 'mouse' ? 8 : 20); // pixels

/** Outward normal and offset of each face of tetrahedron t (face k opposite corner k), from `p` (centred). */
function facePlanes(p, tetrahedra, t, out) {
  for (let k = 0; k < 4; k++) {
    const [a, b, c] = TETRAHEDRON_FACES[k].map((j) => 3 * tetrahedra[4 * t + j]);
    const ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
    const vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
    const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    out[4 * k] = nx;
    out[4 * k + 1] = ny;
    out[4 * k + 2] = nz;
    out[4 * k + 3] = nx * p[a] + ny * p[a + 1] + nz * p[a + 2];
  }
  return out;
}

/** The ray parameter where it meets triangle a, b, c (positions in `p`), or Infinity. */
function rayTriangle(o, d, p, a, b, c) {
  const e1x = p[b] - p[a], e1y = p[b + 1] - p[a + 1], e1z = p[b + 2] - p[a + 2];
  const e2x = p[c] - p[a], e2y = p[c + 1] - p[a + 1], e2z = p[c + 2] - p[a + 2];
  const hx = d.y * e2z - d.z * e2y, hy = d.z * e2x - d.x * e2z, hz = d.x * e2y - d.y * e2x;
  const det = e1x * hx + e1y * hy + e1z * hz;
  if (Math.abs(det) < 1e-30) return Infinity;
  const sx = o.x - p[a], sy = o.y - p[a + 1], sz = o.z - p[a + 2];
  const u = (sx * hx + sy * hy + sz * hz) / det;
  if (u < 0 || u > 1) return Infinity;
  const qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
  const v = (d.x * qx + d.y * qy + d.z * qz) / det;
  if (v < 0 || u + v > 1) return Infinity;
  const s = (e2x * qx + e2y * qy + e2z * qz) / det;
  return s > 0 ? s : Infinity;
}

/** Centre and radius of the sphere through four points (rounded; for drawing). */
export function circumsphere(a, b, c, d) {
  const [bx, by, bz] = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const [cx, cy, cz] = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  const [dx, dy, dz] = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
  const b2 = bx * bx + by * by + bz * bz, c2 = cx * cx + cy * cy + cz * cz, d2 = dx * dx + dy * dy + dz * dz;
  const cd = [cy * dz - cz * dy, cz * dx - cx * dz, cx * dy - cy * dx];
  const db = [dy * bz - dz * by, dz * bx - dx * bz, dx * by - dy * bx];
  const bc = [by * cz - bz * cy, bz * cx - bx * cz, bx * cy - by * cx];
  const den = 2 * (bx * cd[0] + by * cd[1] + bz * cd[2]);
  const u = [0, 1, 2].map((k) => (b2 * cd[k] + c2 * db[k] + d2 * bc[k]) / den);
  return { centre: [a[0] + u[0], a[1] + u[1], a[2] + u[2]], radius: Math.hypot(...u) };
}

/**
 * Pointer handling on `pane` over `scene` (delaunay3-scene.js) and `state.drawn` (the last
 * tetrahedralization drawn: {dimension, positions, tetrahedra, neighbors, representative,
 * boundary, distinct}) and `state.voronoi` ({tetrahedronVertex} once it came). Calls
 * `onHover(hover | null)`, `onPick(point | -1)`, `onPlaneDrag(offset)` while the handle is
 * dragged and `onPlaneDragEnd()`.
 */
export function createDelaunay3Pick({ scene, state, pane, onHover, onPick, onPlaneDrag, onPlaneDragEnd }) {
  const { camera, controls } = scene;
  const raycaster = new THREE.Raycaster();

  function rayOf(event) {
    const rect = pane.getBoundingClientRect();
    const ndc = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1, -((event.clientY - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    return raycaster.ray;
  }

  /** The first drawn tetrahedron along `ray` and where the ray meets it, or null. */
  function tetrahedronAlong(ray) {
    const d = state.drawn;
    if (!d || d.dimension !== 3) return null;
    const { positions: p, tetrahedra, neighbors, boundary } = d;
    const o = ray.origin, dir = ray.direction;
    // Into the hull: the nearest hull face the ray meets.
    let t = -1, entry = Infinity;
    for (let i = 0; i < boundary.length; i++) {
      const face = boundary[i], tet = face >> 2;
      const [a, b, c] = TETRAHEDRON_FACES[face & 3].map((j) => 3 * tetrahedra[4 * tet + j]);
      const s = rayTriangle(o, dir, p, a, b, c);
      if (s < entry) [entry, t] = [s, tet];
    }
    if (t < 0) return null;
    const planes = new Float64Array(16);
    const shrink = scene.shrink;
    const cut = scene.cut;
    const R = scene.radius;
    for (let step = 0; step < MAX_STEPS; step++) {
      facePlanes(p, tetrahedra, t, planes);
      let cx = 0, cy = 0, cz = 0;
      for (let j = 0; j < 4; j++) {
        const v = 3 * tetrahedra[4 * t + j];
        cx += p[v] / 4; cy += p[v + 1] / 4; cz += p[v + 2] / 4;
      }
      if (cut.mode !== 'whole' || scene.kept(cx, cy, cz)) {
        // The ray inside the shrunk tetrahedron: its faces' planes moved towards the centroid.
        let lo = 0, hi = Infinity;
        for (let k = 0; k < 4 && lo <= hi; k++) {
          const nx = planes[4 * k], ny = planes[4 * k + 1], nz = planes[4 * k + 2];
          const nc = nx * cx + ny * cy + nz * cz;
          const h = nc + shrink * (planes[4 * k + 3] - nc);
          const den = nx * dir.x + ny * dir.y + nz * dir.z;
          const num = h - (nx * o.x + ny * o.y + nz * o.z);
          if (den > 0) hi = Math.min(hi, num / den);
          else if (den < 0) lo = Math.max(lo, num / den);
          else if (num < 0) hi = -Infinity;
        }
        if (cut.mode === 'clip') {
          // Kept: normal · p <= offset · R.
          const den = cut.normal.dot(dir);
          const num = cut.offset * R - cut.normal.dot(o);
          if (den > 0) hi = Math.min(hi, num / den);
          else if (den < 0) lo = Math.max(lo, num / den);
          else if (num < 0) hi = -Infinity;
        }
        if (lo <= hi) return { tetrahedron: t, at: lo };
      }
      // Leave by the face the ray crosses first.
      let exit = -1, best = Infinity;
      for (let k = 0; k < 4; k++) {
        const den = planes[4 * k] * dir.x + planes[4 * k + 1] * dir.y + planes[4 * k + 2] * dir.z;
        if (den <= 0) continue;
        const s = (planes[4 * k + 3] - (planes[4 * k] * o.x + planes[4 * k + 1] * o.y + planes[4 * k + 2] * o.z)) / den;
        if (s < best) [best, exit] = [s, k];
      }
      if (exit < 0) return null;
      t = neighbors[4 * t + exit];
      if (t < 0) return null;
    }
    return null;
  }

  /** Tetrahedron t's circumsphere and the points on it (exactly: those of its Delaunay cell). */
  function hoverOf(t) {
    const { positions: p, tetrahedra, neighbors } = state.drawn;
    const corner = (j) => Array.from(p.subarray(3 * tetrahedra[4 * t + j], 3 * tetrahedra[4 * t + j] + 3));
    const corners = [0, 1, 2, 3].map(corner);
    const { centre, radius } = circumsphere(...corners);
    const points = new Set(tetrahedra.subarray(4 * t, 4 * t + 4));
    const vertexOf = state.voronoi?.tetrahedronVertex;
    if (vertexOf) {
      // The tetrahedra of one Delaunay cell share its Voronoi vertex and are joined across faces.
      const seen = new Set([t]);
      const queue = [t];
      while (queue.length) {
        const u = queue.pop();
        for (let j = 0; j < 4; j++) points.add(tetrahedra[4 * u + j]);
        for (let k = 0; k < 4; k++) {
          const w = neighbors[4 * u + k];
          if (w >= 0 && !seen.has(w) && vertexOf[w] === vertexOf[t]) {
            seen.add(w);
            queue.push(w);
          }
        }
      }
    }
    const onSphere = [...points].sort((a, b) => a - b);
    return {
      tetrahedron: t,
      cornerIndices: Array.from(tetrahedra.subarray(4 * t, 4 * t + 4)),
      corners: corners.flat(),
      centre, radius, points: onSphere, exact: Boolean(vertexOf),
      onSphere: onSphere.flatMap((i) => Array.from(p.subarray(3 * i, 3 * i + 3))),
    };
  }

  function hoverAt(event) {
    const hit = tetrahedronAlong(rayOf(event));
    onHover(hit ? hoverOf(hit.tetrahedron) : null);
  }

  /** The point under the pointer: of the drawn points within the tolerance, the nearest to the camera. */
  function pointAt(event) {
    const d = state.drawn;
    if (!d) return -1;
    const rect = pane.getBoundingClientRect();
    const m = new THREE.Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse).elements;
    const px = event.clientX - rect.left, py = event.clientY - rect.top;
    const reach = Math.max(tolerance(event), scene.pointSize / 2 + 3);
    let best = -1, bestDepth = Infinity;
    const p = d.positions;
    for (const i of d.distinct) {
      const x = p[3 * i], y = p[3 * i + 1], z = p[3 * i + 2];
      const w = m[3] * x + m[7] * y + m[11] * z + m[15];
      if (w <= 0) continue;
      const sx = ((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) / 2 * rect.width;
      const sy = (1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) / 2 * rect.height;
      if (Math.abs(sx - px) > reach || Math.abs(sy - py) > reach || Math.hypot(sx - px, sy - py) > reach) continue;
      if (!scene.kept(x, y, z) || w >= bestDepth) continue;
      [best, bestDepth] = [i, w];
    }
    return best;
  }

  // ------------------------------------------------------------ the plane's handle

  function handleUnder(event) {
    if (!scene.planeShown || !state.drawn) return false;
    const c = scene.planeCentre();
    const at = scene.toScreen(c.x, c.y, c.z);
    return Math.hypot(at.x - event.clientX, at.y - event.clientY) <= tolerance(event) + 4;
  }

  /** The offset (in radii) of the point of the plane's normal line nearest the ray. */
  function offsetAlong(ray) {
    const n = scene.cut.normal;
    // Closest points of the line s·n and the ray o + u·d.
    const o = ray.origin, d = ray.direction;
    const b = n.dot(d), dn = n.dot(o), dd = d.dot(o);
    const den = 1 - b * b;
    if (den < 1e-6) return null; // looking along the normal: no drag
    const s = (dn - b * dd) / den;
    return s / scene.radius;
  }

  let drag = null; // {start offset, grabbed}
  let down = null;
  pane.addEventListener('pointerdown', (event) => {
    down = { x: event.clientX, y: event.clientY, t: performance.now() };
    if (event.button !== 0 || !handleUnder(event)) return;
    const grabbed = offsetAlong(rayOf(event));
    if (grabbed === null) return;
    drag = { from: scene.cut.offset, grabbed };
    controls.enabled = false;
    pane.setPointerCapture(event.pointerId);
    event.stopImmediatePropagation();
  }, { capture: true });

  let queued = null;
  pane.addEventListener('pointermove', (event) => {
    if (drag) {
      const at = offsetAlong(rayOf(event));
      if (at !== null) onPlaneDrag(Math.max(-1, Math.min(1, drag.from + at - drag.grabbed)));
      return;
    }
    pane.style.cursor = handleUnder(event) ? 'grab' : '';
    if (event.buttons || event.pointerType !== 'mouse') return;
    // At most one walk per 16 ms, not tied to frames (a slow GPU delays frames, not the answer).
    if (!queued) setTimeout(() => {
      const e = queued;
      queued = null;
      if (e) hoverAt(e);
    }, 16);
    queued = event;
  });
  pane.addEventListener('pointerleave', (event) => {
    queued = null;
    // A finger leaves when it is lifted: what its tap showed stays.
    if (!drag && event.pointerType === 'mouse') onHover(null);
  });
  const endDrag = () => {
    if (!drag) return false;
    drag = null;
    controls.enabled = state.active;
    onPlaneDragEnd();
    return true;
  };
  pane.addEventListener('pointerup', (event) => {
    if (endDrag()) return;
    if (!down || Math.hypot(event.clientX - down.x, event.clientY - down.y) > 5 || performance.now() - down.t > 600) return;
    if (event.pointerType !== 'mouse') hoverAt(event); // no hover on a touch screen: a tap shows it
    onPick(pointAt(event));
  });
  pane.addEventListener('pointercancel', endDrag);

  window.hullkitDelaunay3Screen = (i) => {
    const p = state.drawn?.positions;
    if (!p || i < 0 || 3 * i >= p.length) return null;
    const at = scene.toScreen(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    return { x: at.x, y: at.y, depth: at.depth, kept: scene.kept(p[3 * i], p[3 * i + 1], p[3 * i + 2]) };
  };
  window.hullkitDelaunay3Handle = () => {
    if (!scene.planeShown || !state.drawn) return null;
    const c = scene.planeCentre();
    return scene.toScreen(c.x, c.y, c.z);
  };

  return { hoverOf };
}
