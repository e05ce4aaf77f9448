// The rings of the Delaunay view's constrained modes under the pointer and the keyboard: a click
// in the plane adds a vertex to the open ring, a click on its first vertex (or Enter) closes it,
// Backspace removes its last vertex, and a vertex is dragged to move it. The plane pane takes
// them; when blended, the 3D pane too (a press on a vertex there drags it instead of orbiting).
//
// Test hooks: window.hullkitPlaneToScreen(x, y) is where the plane point (x, y) is on the screen
// (client pixels), window.hullkitRingVertex(i) where point i of the rings is.
import * as THREE from 'three';
import { PLANE_Z } from '../delaunay-scene.js';

const tolerance = (event) => (event.pointerType === 'mouse' ? 9 : 20); // pixels
const CLICK_PX = 5;
const CLICK_MS = 600;
const round = (v) => Number(v.toFixed(4));

/**
 * Listens on the panes of `scene` while `editing()` is true; `model()` is the model being edited
 * ({points: [[x, y]], open: [i], ...}). The edits are the callbacks': onAdd(x, y), onClose(),
 * onUndo(), onMove(i, x, y) while a vertex is dragged, and onMoveEnd() when a drag that moved it ends.
 */
export function createRingEditor({ scene, state, editing, model, onAdd, onClose, onUndo, onMove, onMoveEnd }) {
  const { pane2d, pane3d, camera2d, camera3d, panes, controls } = scene;
  const raycaster = new THREE.Raycaster();
  const planeZ = new THREE.Plane(new THREE.Vector3(0, 0, 1), -PLANE_Z);

  /** The pane that shows the plane flat (side by side), or the 3D pane with the plane under it (blended). */
  const planePane = () => (panes.b ? pane2d : pane3d);

  function ndc(event, pane) {
    const rect = pane.getBoundingClientRect();
    return new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1, -((event.clientY - rect.top) / rect.height) * 2 + 1);
  }

  /** The plane point under the pointer, or null (the 3D pane side by side only orbits). */
  function planePoint(event, pane) {
    if (pane !== planePane()) return null;
    const p = ndc(event, pane);
    if (pane === pane2d) {
      const v = new THREE.Vector3(p.x, p.y, 0).unproject(camera2d);
      return [v.x, v.y];
    }
    raycaster.setFromCamera(p, camera3d);
    const hit = raycaster.ray.intersectPlane(planeZ, new THREE.Vector3());
    return hit ? [hit.x, hit.y] : null;
  }

  /** Where the plane point (x, y) is drawn, in client pixels. */
  function toScreen(x, y) {
    const pane = planePane();
    const v = pane === pane2d ? new THREE.Vector3(x, y, 0).project(camera2d) : new THREE.Vector3(x, y, PLANE_Z).project(camera3d);
    const rect = pane.getBoundingClientRect();
    return { x: rect.left + ((v.x + 1) / 2) * rect.width, y: rect.top + ((1 - v.y) / 2) * rect.height };
  }

  /** The vertex nearest the pointer within the tolerance, or -1. */
  function vertexUnder(event) {
    const points = model()?.points ?? [];
    let best = -1, bestDistance = tolerance(event);
    points.forEach(([x, y], i) => {
      const s = toScreen(x, y);
      const d = Math.hypot(s.x - event.clientX, s.y - event.clientY);
      if (d <= bestDistance) [best, bestDistance] = [i, d];
    });
    return best;
  }

  let drag = null; // {index, pane, pointerId, moved}
  let down = null; // a press away from the vertices: {x, y, t}

  for (const pane of [pane2d, pane3d]) {
    // Before OrbitControls sees the press (capture): a vertex under it is dragged instead.
    pane.addEventListener('pointerdown', (event) => {
      down = null;
      if (!editing() || event.button !== 0 || pane !== planePane()) return;
      const index = vertexUnder(event);
      if (index < 0) {
        down = { x: event.clientX, y: event.clientY, t: performance.now() };
        return;
      }
      drag = { index, pane, pointerId: event.pointerId, moved: false, x: event.clientX, y: event.clientY };
      controls.enabled = false;
      pane.setPointerCapture(event.pointerId);
    }, { capture: true });

    pane.addEventListener('pointermove', (event) => {
      if (!editing()) return;
      if (!drag) {
        if (!event.buttons && pane === planePane()) pane.style.cursor = vertexUnder(event) >= 0 ? 'grab' : '';
        return;
      }
      if (drag.pane !== pane) return;
      if (!drag.moved && Math.hypot(event.clientX - drag.x, event.clientY - drag.y) < 2) return;
      const p = planePoint(event, pane);
      if (!p) return;
      drag.moved = true;
      pane.style.cursor = 'grabbing';
      onMove(drag.index, round(p[0]), round(p[1]));
    });

    const release = (event, cancelled) => {
      if (drag && drag.pane === pane) {
        const { index, moved } = drag;
        drag = null;
        controls.enabled = state.active;
        pane.style.cursor = '';
        if (moved) onMoveEnd();
        else if (!cancelled) {
          const m = model();
          if (m.open.length >= 3 && index === m.open[0]) onClose(); // a click on the first vertex
        }
        return;
      }
      if (!down || cancelled || !editing()) return;
      const quick = Math.hypot(event.clientX - down.x, event.clientY - down.y) <= CLICK_PX && performance.now() - down.t <= CLICK_MS;
      down = null;
      if (!quick) return; // an orbit (blended) or a slip
      const p = planePoint(event, pane);
      if (!p || Math.abs(p[0] - state.extent.cx) > 4 * state.extent.r || Math.abs(p[1] - state.extent.cy) > 4 * state.extent.r) return;
      onAdd(round(p[0]), round(p[1]));
    };
    pane.addEventListener('pointerup', (event) => release(event, false));
    pane.addEventListener('pointercancel', (event) => release(event, true));
  }

  // Enter closes the open ring, Backspace takes back its last vertex (not while typing in a field).
  window.addEventListener('keydown', (event) => {
    if (!editing() || event.defaultPrevented || event.altKey || event.ctrlKey || event.metaKey) return;
    if (event.target.closest?.('input, select, textarea, button, dialog, [contenteditable]')) return;
    if (event.key === 'Enter') {
      event.preventDefault();
      onClose();
    } else if (event.key === 'Backspace') {
      event.preventDefault();
      onUndo();
    }
  });

  window.hullkitPlaneToScreen = (x, y) => toScreen(x, y);
  window.hullkitRingVertex = (i) => {
    const p = model()?.points[i];
    return p ? toScreen(p[0], p[1]) : null;
  };

  return { toScreen };
}
