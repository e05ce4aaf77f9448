// The Delaunay view's scenes and panes: the 3D scene of the paraboloid (orbited) and the 2D scene
// of the plane (orthographic, seen from above), their materials and groups, the two panes over
// the canvas side by side or one blended pane, the framing of both cameras and the render.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { discTexture, zUpCamera } from '../app/stage.js';

export const LIFT = 0.75; // drawn height of the paraboloid per unit of x² + y²
export const PLANE_Z = -0.55; // where the blended layout draws the plane under the paraboloid
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

/**
 * The scenes drawn on the `stage`'s renderer, with their panes in `viewport`; `ui.layout` picks
 * the layout. It draws while `state.active`, fits the cameras to `state.extent` and frames the 3D
 * view once (`state.framed`).
 */
export function createDelaunayScene({ stage, ui, state, viewport }) {
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
  // The rings being edited in the constrained modes (constrained/draw.js), kept apart from the
  // triangulation's groups, which are redrawn with each result.
  const edit2d = new THREE.Group();
  const edit3d = new THREE.Group();
  edit3d.position.z = PLANE_Z;
  scene3d.add(lifted, planeIn3d, hover3d, hoverPlane3d, edit3d, paraboloidGuide());
  scene2d.add(plane, hover2d, edit2d);

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

  function requestRender() {
    if (state.active) stage.requestRender();
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
    const constrained = state.mode !== undefined && state.mode !== 'unconstrained';
    if (constrained) {
      label3d.textContent = panes.b ? 'lifted: the constrained triangles on z = x² + y²' : 'lifted over the plane: click the plane to draw rings';
      label2d.textContent = state.mode === 'quality' ? 'projected: quality mesh' : 'projected: constrained Delaunay triangulation';
    } else {
      label3d.textContent = panes.b ? 'lifted: z = x² + y², lower hull shaded' : 'lifted paraboloid over the plane: click the plane to add points';
      label2d.textContent = 'projected: Delaunay triangulation';
    }
    planeIn3d.visible = hoverPlane3d.visible = edit3d.visible = !panes.b;
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
    const half = state.extent.r * 1.12;
    const aspect = w / h;
    const hx = aspect >= 1 ? half * aspect : half;
    const hy = aspect >= 1 ? half : half / aspect;
    Object.assign(camera2d, { left: state.extent.cx - hx, right: state.extent.cx + hx, top: state.extent.cy + hy, bottom: state.extent.cy - hy });
    camera2d.position.set(0, 0, 5);
    camera2d.updateProjectionMatrix();
  }

  function frame3d() {
    const dir = new THREE.Vector3(0.9, -1.7, 0.95).normalize();
    const R = Math.max(state.extent.r, 0.5);
    // The lifted points' bounding sphere (blended: the plane below too), with a little room.
    const r = 1.05 * Math.hypot(R, R, (LIFT * R * R - (panes.b ? 0 : PLANE_Z)) / 2);
    const vfov = THREE.MathUtils.degToRad(camera3d.fov);
    const hfov = 2 * Math.atan(Math.tan(vfov / 2) * camera3d.aspect);
    const dist = r / Math.sin(Math.min(vfov, hfov) / 2);
    controls.target.set(state.extent.cx, state.extent.cy, panes.b ? (LIFT * R * R) / 2 : (LIFT * R * R + PLANE_Z) / 2);
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
    if (!state.framed) frame3d();
  }

  return {
    pane3d, pane2d, materials, scene3d, camera3d, controls, scene2d, camera2d,
    lifted, planeIn3d, plane, hover3d, hover2d, hoverPlane3d, edit2d, edit3d,
    panes, requestRender, layoutPanes, frame3d, render, resize,
  };
}
