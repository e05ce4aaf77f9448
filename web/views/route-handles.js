// The Route view's waypoint handles under the pointer: a handle (sphere) is dragged over the
// ground at its height; the ring around it is turned to set the waypoint's yaw (its turn about z,
// shown next to the ring while turning); pressing either selects the waypoint. Rings are picked in
// screen space, with a finger's tolerance on touch screens.
//
// Test hooks: window.hullkitRouteHandle(i) and window.hullkitRouteRing(i, degrees): where waypoint
// i's handle, and the point of its ring at `degrees` about z, are on the screen (client pixels).
import * as THREE from 'three';
import { positionOf, yawOf, withYaw, wrapDegrees } from '../route-poses.js';

const RING_SAMPLES = 48;

const tolerance = (event) => (event.pointerType === 'mouse' ? 8 : 20); // pixels
const round = (x, digits) => Number(x.toFixed(digits));

/**
 * Listens on `view3d.pane` (created by createRouteScene): `onSelect()` after a press selected a
 * waypoint (state.selected), `onMove()` after a drag changed state.route, `onEnd()` when a drag
 * that changed it ends.
 */
export function createRouteHandles({ view3d, state, onSelect, onMove, onEnd }) {
  const { pane, camera, controls, groups } = view3d;
  const raycaster = new THREE.Raycaster();
  let drag = null; // {kind: 'move', index, plane, dx, dy} | {kind: 'yaw', index, plane, centre, last, yaw}

  const label = document.createElement('div');
  label.className = 'rt-yaw-label';
  label.hidden = true;
  pane.append(label);

  function ndcOf(event) {
    const rect = pane.getBoundingClientRect();
    return new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1, -((event.clientY - rect.top) / rect.height) * 2 + 1);
  }

  function handleUnder(event) {
    raycaster.setFromCamera(ndcOf(event), camera);
    const hits = raycaster.intersectObjects(groups.handles.children.filter((o) => o.userData.waypoint !== undefined), false);
    return hits.length ? hits[0].object.userData.waypoint : -1;
  }

  /** The waypoint whose ring passes nearest the pointer, within the tolerance (-1 if none). */
  function ringUnder(event) {
    let best = -1, bestDistance = tolerance(event);
    state.route.forEach((_, i) => {
      const pts = Array.from({ length: RING_SAMPLES + 1 }, (_, k) => view3d.toScreen(view3d.ringPoint(i, (360 * k) / RING_SAMPLES)));
      for (let k = 0; k < RING_SAMPLES; k++) {
        const d = segmentDistance(event.clientX, event.clientY, pts[k], pts[k + 1]);
        if (d < bestDistance) [best, bestDistance] = [i, d];
      }
    });
    return best;
  }

  /** The pointer on `plane` (world), or null when the ray misses it. */
  function onPlane(event, plane) {
    raycaster.setFromCamera(ndcOf(event), camera);
    return raycaster.ray.intersectPlane(plane, new THREE.Vector3());
  }

  /** The pointer's angle about the ring's centre in degrees (in the ring's plane; on the screen when edge-on). */
  function angleAbout(event, centre, plane) {
    const at = onPlane(event, plane);
    if (at) return THREE.MathUtils.radToDeg(Math.atan2(at.y - centre.y, at.x - centre.x));
    const c = view3d.toScreen(centre);
    return THREE.MathUtils.radToDeg(Math.atan2(c.y - event.clientY, event.clientX - c.x));
  }

  function showLabel(i) {
    const c = view3d.toScreen(view3d.handleOf(i));
    const rect = pane.getBoundingClientRect();
    label.textContent = `waypoint ${i + 1}: yaw ${round(yawOf(state.route[i]), 1)}°`;
    Object.assign(label.style, { left: `${c.x - rect.left + 14}px`, top: `${c.y - rect.top - 30}px` });
    label.hidden = false;
  }

  // Registered before OrbitControls sees the event (capture): a handle or ring under the pointer
  // is dragged instead.
  pane.addEventListener('pointerdown', (event) => {
    if (event.button !== 0) return;
    let index = handleUnder(event);
    const kind = index >= 0 ? 'move' : 'yaw';
    if (index < 0) index = ringUnder(event);
    if (index < 0) return;
    controls.enabled = false;
    state.selected = index;
    const centre = view3d.handleOf(index);
    const plane = new THREE.Plane(new THREE.Vector3(0, 0, 1), -centre.z);
    if (kind === 'move') {
      const p = positionOf(state.route[index]);
      const at = onPlane(event, plane);
      drag = { kind, index, plane, dx: at ? p[0] - at.x : 0, dy: at ? p[1] - at.y : 0, moved: false };
    } else {
      drag = { kind, index, plane, centre, last: angleAbout(event, centre, plane), yaw: yawOf(state.route[index]), moved: false };
      showLabel(index);
    }
    pane.setPointerCapture(event.pointerId);
    onSelect();
  }, { capture: true });

  pane.addEventListener('pointermove', (event) => {
    if (!drag) {
      pane.style.cursor = handleUnder(event) >= 0 || ringUnder(event) >= 0 ? 'grab' : '';
      return;
    }
    const i = drag.index;
    if (drag.kind === 'move') {
      const at = onPlane(event, drag.plane);
      if (!at) return;
      const p = positionOf(state.route[i]);
      p[0] = round(at.x + drag.dx, 3);
      p[1] = round(at.y + drag.dy, 3);
    } else {
      const angle = angleAbout(event, drag.centre, drag.plane);
      drag.yaw += wrapDegrees(angle - drag.last);
      drag.last = angle;
      state.route[i] = withYaw(state.route[i], round(drag.yaw, 1));
      showLabel(i);
    }
    drag.moved = true;
    onMove();
  });

  const endDrag = () => {
    if (!drag) return;
    const { moved } = drag;
    drag = null;
    label.hidden = true;
    controls.enabled = state.active;
    if (moved) onEnd();
  };
  pane.addEventListener('pointerup', endDrag);
  pane.addEventListener('pointercancel', endDrag);

  window.hullkitRouteHandle = (i) => (i >= 0 && i < state.route.length ? view3d.toScreen(view3d.handleOf(i)) : null);
  window.hullkitRouteRing = (i, degrees) => (i >= 0 && i < state.route.length ? view3d.toScreen(view3d.ringPoint(i, degrees)) : null);
}

/** Distance from (x, y) to the segment a–b (client pixels). */
function segmentDistance(x, y, a, b) {
  const dx = b.x - a.x, dy = b.y - a.y;
  const len2 = dx * dx + dy * dy;
  const t = len2 > 0 ? Math.max(0, Math.min(1, ((x - a.x) * dx + (y - a.y) * dy) / len2)) : 0;
  return Math.hypot(x - a.x - t * dx, y - a.y - t * dy);
}
