// The Delaunay view under the pointer: hovering a triangle shows its empty circumcircle in the
// plane and its lift on the paraboloid (it lies in the plane of the lifted face); a click in the
// plane adds a point there. In the constrained modes the rings' editor (constrained/rings.js)
// takes the pointer instead.
//
// Test hook: window.hullkitDelaunayHover = {triangle, corners, x, y, r} for the triangle
// highlighted (null when none).
import * as THREE from 'three';
import { clearGroup } from '../app/stage.js';
import { LIFT, PLANE_Z } from './delaunay-scene.js';

const orient = (ax, ay, bx, by, cx, cy) => (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);

/**
 * Hover and clicks on the panes of `scene`, over `state.tri` and `state.xy`; a click adds to
 * `state.added` and calls `compute`.
 */
export function createDelaunayHover({ state, scene, compute }) {
  const { materials, hover3d, hover2d, hoverPlane3d, pane3d, pane2d, camera3d, camera2d, panes, requestRender } = scene;

  /** The triangle containing (x, y), by walking from the last one found; -1 outside the hull. */
  function locate(x, y) {
    const { xy, tri } = state;
    if (!tri || tri.triangles.length === 0) return -1;
    const T = tri.triangles, H = tri.halfedges;
    let t = Math.min(state.lastTriangle, T.length / 3 - 1);
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
      if (!crossed) return (state.lastTriangle = t);
    }
    return -1; // a cycle (rounding on near-degenerate input): no highlight
  }

  function circumcircle(t) {
    const { xy, tri } = state;
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
          const px = state.xy[2 * i], py = state.xy[2 * i + 1];
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
      const width = state.extent.r * 0.005;
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

  const pointsMode = () => state.mode === undefined || state.mode === 'unconstrained';
  for (const pane of [pane2d, pane3d]) {
    let down = null;
    pane.addEventListener('pointerdown', (event) => { down = pointsMode() ? { x: event.clientX, y: event.clientY, t: performance.now() } : null; });
    pane.addEventListener('pointermove', (event) => {
      if (event.buttons || !pointsMode()) return;
      const p = planePoint(event, pane);
      showHover(p ? locate(p[0], p[1]) : -1);
    });
    pane.addEventListener('pointerleave', () => { if (pointsMode()) showHover(-1); });
    pane.addEventListener('pointerup', (event) => {
      if (!down || !pointsMode() || Math.hypot(event.clientX - down.x, event.clientY - down.y) > 5 || performance.now() - down.t > 600) return;
      const p = planePoint(event, pane);
      if (!p || Math.abs(p[0] - state.extent.cx) > 4 * state.extent.r || Math.abs(p[1] - state.extent.cy) > 4 * state.extent.r) return;
      state.added.push([Number(p[0].toFixed(4)), Number(p[1].toFixed(4))]);
      compute({ push: true });
    });
  }

  return { showHover };
}
