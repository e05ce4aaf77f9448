// The one WebGL canvas every view draws on: the renderer, its size, and frames on demand.
//
// A view plugs in with {render(renderer), resize(width, height)}; the stage renders the active
// view only, at most once per animation frame, when something asked for it.
import * as THREE from 'three';

export const BACKGROUND = 0x0d1117;

/**
 * Creates the renderer on `canvas`, sized to `container` (followed with a ResizeObserver).
 * Throws when WebGL is unavailable (the caller shows the message).
 */
export function createStage(canvas, container) {
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, powerPreference: 'high-performance' });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  renderer.setClearColor(BACKGROUND, 1);

  let active = null;
  let queued = false;
  const size = { width: 1, height: 1 };

  function renderNow() {
    if (active) active.render(renderer);
  }

  /** Renders the active view on the next animation frame (coalesced). */
  function requestRender() {
    if (queued) return;
    queued = true;
    requestAnimationFrame(() => {
      queued = false;
      renderNow();
    });
  }

  function resize() {
    size.width = Math.max(1, container.clientWidth);
    size.height = Math.max(1, container.clientHeight);
    renderer.setSize(size.width, size.height, false);
    if (active) active.resize(size.width, size.height);
    requestRender();
  }
  new ResizeObserver(resize).observe(container);

  return {
    renderer,
    canvas,
    size,
    requestRender,
    renderNow,
    /** Draws `scene` through `camera` over the whole canvas (a view with one pane). */
    drawWhole(scene, camera) {
      renderer.setScissorTest(false);
      renderer.setViewport(0, 0, size.width, size.height);
      renderer.render(scene, camera);
    },
    /** Makes `view` the one drawn (and told about the size). */
    setActive(view) {
      active = view;
      resize();
    },
  };
}

/** A round point sprite, so that THREE.Points draw discs instead of squares. */
export function discTexture() {
  const size = 64;
  const c = document.createElement('canvas');
  c.width = c.height = size;
  const g = c.getContext('2d');
  g.fillStyle = '#fff';
  g.beginPath();
  g.arc(size / 2, size / 2, size / 2 - 1, 0, 2 * Math.PI);
  g.fill();
  const tex = new THREE.CanvasTexture(c);
  tex.colorSpace = THREE.SRGBColorSpace;
  return tex;
}

/** Disposes every geometry under `group` and empties it. */
export function clearGroup(group) {
  const geometries = new Set();
  group.traverse((obj) => { if (obj.geometry) geometries.add(obj.geometry); });
  for (const g of geometries) g.dispose();
  group.clear();
}

/**
 * Fits a sphere of `radius` about the origin into the view of `camera` (orbited by `controls`,
 * whose target becomes the origin), seen along `direction` (from the origin towards the camera),
 * with `margin` to spare; near and far planes follow the distance.
 */
export function fitCamera(camera, controls, radius, direction, margin = 1.15) {
  const dir = direction.clone().normalize();
  const vFov = THREE.MathUtils.degToRad(camera.fov);
  const hFov = 2 * Math.atan(Math.tan(vFov / 2) * camera.aspect);
  const dist = (radius / Math.sin(Math.min(vFov, hFov) / 2)) * margin;
  controls.target.set(0, 0, 0);
  camera.position.copy(dir).multiplyScalar(dist);
  camera.near = dist / 1000;
  camera.far = dist * 20;
  camera.updateProjectionMatrix();
  controls.update();
}

/**
 * A perspective camera with z up, added to `scene`, carrying a key light (so the lighting follows
 * the view) over a hemisphere light: the rig of the Delaunay and Route views.
 */
export function zUpCamera(scene, { near = 0.01, far = 100, fov = 40 } = {}) {
  const camera = new THREE.PerspectiveCamera(fov, 1, near, far);
  camera.up.set(0, 0, 1);
  scene.add(camera);
  scene.add(new THREE.HemisphereLight(0xd6ecff, 0x1b2230, 1.25));
  const key = new THREE.DirectionalLight(0xffffff, 2.5);
  key.position.set(-1, 1.5, 1);
  key.target.position.set(0, 0, -1);
  camera.add(key, key.target);
  return camera;
}
