// The Delaunay 3D view's three.js scene: the tetrahedra drawn shrunk towards their centroids and
// cut by a plane, the points, the cutting plane with its handle, the circumsphere of the
// tetrahedron under the pointer with the points on it, and the Voronoi cell of a picked point.
//
// The tetrahedra are one mesh of four vertices each, built in the worker (positions.js), each
// vertex with its tetrahedron's centroid: the vertex shader moves each corner towards the centroid
// by the shrink factor and, when whole tetrahedra are cut, collapses those whose centroid lies on
// the removed side of the plane. Shrink and cut are uniforms, so dragging their sliders or the
// plane redraws without touching the geometry (about 670 000 tetrahedra for 100 000 points).
// "Clipped" cuts through the tetrahedra with a three.js clipping plane instead; the points are
// always clipped by it. (One mesh rather than instances of a tetrahedron: four-vertex instances
// drew at half the speed in Chromium's software renderer.)
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { discTexture, clearGroup, zUpCamera, fitCamera } from '../app/stage.js';
import { TETRAHEDRON_FACES, TETRAHEDRA_PER_MESH } from '../positions.js';

export const CUT_MODES = ['whole', 'clip', 'off'];

const COLORS = {
  tetrahedron: 0x3fb8c9,
  point: 0xffb547,
  plane: 0xdbe3ee,
  sphere: 0xff6fa5,
  onSphere: 0xffffff,
  hovered: 0xff6fa5,
  cell: 0xc58cff,
  picked: 0xffffff,
};

/** Each corner moves towards its tetrahedron's centroid; whole tetrahedra may be cut away. */
function tetrahedronMaterial(uniforms) {
  const material = new THREE.MeshStandardMaterial({
    color: COLORS.tetrahedron, flatShading: true, roughness: 0.55, metalness: 0,
  });
  material.onBeforeCompile = (shader) => {
    Object.assign(shader.uniforms, uniforms);
    shader.vertexShader = shader.vertexShader
      .replace('#include <common>', `#include <common>
        attribute vec3 middle; // the tetrahedron's centroid
        uniform float shrink;
        uniform vec4 cutPlane;
        uniform float cutWhole;
        varying float vShade;`)
      .replace('#include <begin_vertex>', `
        vec3 transformed = middle + shrink * (position - middle);
        // Kept where cutPlane.xyz . p + cutPlane.w >= 0 (three.js clipping planes keep that side too).
        if (cutWhole > 0.5 && dot(cutPlane.xyz, middle) + cutPlane.w < 0.0) transformed = middle;
        float h = fract(sin(dot(middle, vec3(12.9898, 78.233, 37.719))) * 43758.5453); // a shade per tetrahedron
        vShade = 0.72 + 0.36 * h;`);
    shader.fragmentShader = shader.fragmentShader
      .replace('#include <common>', '#include <common>\nvarying float vShade;')
      .replace('#include <color_fragment>', '#include <color_fragment>\ndiffuseColor.rgb *= vShade;');
  };
  material.customProgramCacheKey = () => 'hullkit-shrunk-tetrahedra';
  return material;
}

/**
 * The scene drawn on the `stage`'s renderer, orbited on `pane` (the view's layer over the canvas);
 * it draws while `state.active`.
 */
export function createDelaunay3Scene({ stage, state, pane }) {
  stage.renderer.localClippingEnabled = true;
  const scene = new THREE.Scene();
  const camera = zUpCamera(scene, { fov: 38 });
  const DEFAULT_VIEW_DIR = new THREE.Vector3(1.2, -1.5, 0.9).normalize();
  camera.position.copy(DEFAULT_VIEW_DIR).multiplyScalar(4);
  const controls = new OrbitControls(camera, pane);
  controls.enableDamping = true;
  controls.dampingFactor = 0.12;
  controls.rotateSpeed = 0.8;
  controls.enabled = false;

  const uniforms = {
    shrink: { value: 0.75 },
    cutPlane: { value: new THREE.Vector4(0, 0, 1, 0) },
    cutWhole: { value: 1 },
  };
  const clipPlane = new THREE.Plane(new THREE.Vector3(0, 0, 1), 0); // kept: normal · p + constant >= 0
  const disc = discTexture();
  const materials = {
    tetrahedra: tetrahedronMaterial(uniforms),
    point: new THREE.PointsMaterial({ color: COLORS.point, size: 4, sizeAttenuation: false, map: disc, alphaTest: 0.5, clippingPlanes: [clipPlane] }),
    plane: new THREE.MeshBasicMaterial({ color: COLORS.plane, transparent: true, opacity: 0.07, side: THREE.DoubleSide, depthWrite: false }),
    planeEdge: new THREE.LineBasicMaterial({ color: COLORS.plane, transparent: true, opacity: 0.55 }),
    handle: new THREE.MeshBasicMaterial({ color: COLORS.point }),
    sphere: new THREE.MeshStandardMaterial({ color: COLORS.sphere, transparent: true, opacity: 0.2, depthWrite: false, roughness: 0.4, metalness: 0 }),
    sphereRing: new THREE.LineBasicMaterial({ color: COLORS.sphere, transparent: true, opacity: 0.85, depthTest: false }),
    hovered: new THREE.LineBasicMaterial({ color: COLORS.hovered, depthTest: false }),
    onSphere: new THREE.PointsMaterial({ color: COLORS.onSphere, size: 9, sizeAttenuation: false, map: disc, alphaTest: 0.5, depthTest: false, transparent: true }),
    cell: new THREE.MeshBasicMaterial({ color: COLORS.cell, transparent: true, opacity: 0.28, side: THREE.DoubleSide, depthTest: false, depthWrite: false }),
    cellEdge: new THREE.LineBasicMaterial({ color: COLORS.cell, depthTest: false }),
    picked: new THREE.PointsMaterial({ color: COLORS.picked, size: 10, sizeAttenuation: false, map: disc, alphaTest: 0.5, depthTest: false, transparent: true }),
  };

  const content = new THREE.Group(); // tetrahedra (or triangles) and points
  const planeGroup = new THREE.Group(); // the cutting plane and its handle
  const hoverGroup = new THREE.Group();
  const cellGroup = new THREE.Group();
  scene.add(content, planeGroup, hoverGroup, cellGroup);

  // The cutting plane: a translucent square with its outline, and a handle on its normal.
  const planeMesh = new THREE.Mesh(new THREE.PlaneGeometry(1, 1), materials.plane);
  const planeOutline = new THREE.LineLoop(
    new THREE.BufferGeometry().setAttribute('position', new THREE.Float32BufferAttribute([-0.5, -0.5, 0, 0.5, -0.5, 0, 0.5, 0.5, 0, -0.5, 0.5, 0], 3)),
    materials.planeEdge,
  );
  const handle = new THREE.Mesh(new THREE.SphereGeometry(1, 20, 14), materials.handle);
  const handleStem = new THREE.Line(new THREE.BufferGeometry().setAttribute('position', new THREE.Float32BufferAttribute([0, 0, 0, 0, 0, 1], 3)), materials.planeEdge);
  planeGroup.add(planeMesh, planeOutline, handle, handleStem);
  for (const o of [planeMesh, planeOutline, handle, handleStem]) o.renderOrder = 4;

  let radius = 1;
  const waiting = []; // meshes of tetrahedra still to add, one per frame
  let pointsObject = null;
  let framedOnce = false;
  const cut = { mode: 'whole', normal: new THREE.Vector3(0, 0, 1), offset: 0 }; // the plane normal · p = offset · radius
  const visible = { points: true, plane: true };

  /** Shows or hides the points and the plane ({points, plane}: booleans). */
  function setVisible(which) {
    Object.assign(visible, which);
    if (pointsObject) pointsObject.visible = visible.points;
    planeGroup.visible = cut.mode !== 'off' && visible.plane;
    requestRender();
  }

  function requestRender() {
    if (state.active) stage.requestRender();
  }
  controls.addEventListener('change', requestRender);

  /**
   * Draws a tetrahedralization as the worker prepared it (positions.js tetrahedraDrawing): the
   * tetrahedra's `corners`, `middles` and `faces` (coplanar points: their triangles, drawn flat),
   * `pointPositions` (the distinct points) and the `radius` of the points around their centre.
   */
  function draw({ corners, middles, faces, pointPositions, radius: r }) {
    clearGroup(content);
    clearHover();
    clearCell();
    radius = r;
    const solids = corners.length / 12;
    // One mesh per TETRAHEDRA_PER_MESH tetrahedra, added one per frame (see render).
    for (const mesh of waiting) mesh.geometry.dispose();
    waiting.length = 0;
    for (let first = 0; first < solids; first += TETRAHEDRA_PER_MESH) {
      const last = Math.min(solids, first + TETRAHEDRA_PER_MESH);
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(corners.subarray(12 * first, 12 * last), 3));
      geometry.setAttribute('middle', new THREE.BufferAttribute(middles.subarray(12 * first, 12 * last), 3));
      geometry.setIndex(new THREE.BufferAttribute(faces.subarray(12 * first, 12 * last), 1));
      const mesh = new THREE.Mesh(geometry, materials.tetrahedra);
      mesh.frustumCulled = false;
      if (first === 0) content.add(mesh);
      else waiting.push(mesh);
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(pointPositions, 3));
    const n = pointPositions.length / 3;
    materials.point.size = n <= 300 ? 7 : n <= 3000 ? 5 : n <= 30000 ? 3 : 2;
    pointsObject = new THREE.Points(geometry, materials.point);
    pointsObject.frustumCulled = false;
    pointsObject.renderOrder = 1;
    pointsObject.visible = visible.points;
    content.add(pointsObject);
    placePlane();
    frameView(framedOnce); // the new points in view, seen from where the camera was
    framedOnce = true;
    requestRender();
  }

  // ------------------------------------------------------------ shrink and cut

  function setShrink(value) {
    uniforms.shrink.value = value;
    requestRender();
  }

  /** The cut: mode ('whole' | 'clip' | 'off'), the plane's unit normal and its offset (in radii). */
  function setCut({ mode, normal, offset }) {
    cut.mode = mode;
    cut.normal.copy(normal).normalize();
    cut.offset = offset;
    placePlane();
    requestRender();
  }

  /** Whether a (centred) position is on the kept side of the cut. */
  function kept(x, y, z) {
    if (cut.mode === 'off') return true;
    return -(cut.normal.x * x + cut.normal.y * y + cut.normal.z * z) + cut.offset * radius >= 0;
  }

  function placePlane() {
    const on = cut.mode !== 'off';
    // Kept: normal · p <= offset · radius, i.e. (-normal) · p + offset · radius >= 0.
    clipPlane.normal.copy(cut.normal).negate();
    clipPlane.constant = cut.offset * radius;
    uniforms.cutPlane.value.set(clipPlane.normal.x, clipPlane.normal.y, clipPlane.normal.z, clipPlane.constant);
    uniforms.cutWhole.value = cut.mode === 'whole' ? 1 : 0;
    materials.tetrahedra.clippingPlanes = cut.mode === 'clip' ? [clipPlane] : [];
    // Closed tetrahedra show only their front faces; clipped ones are open at the plane.
    const side = cut.mode === 'clip' ? THREE.DoubleSide : THREE.FrontSide;
    if (materials.tetrahedra.side !== side) {
      materials.tetrahedra.side = side;
      materials.tetrahedra.needsUpdate = true;
    }
    materials.point.clippingPlanes = on ? [clipPlane] : [];
    planeGroup.visible = on && visible.plane;
    const centre = planeCentre();
    const size = 2.3 * radius;
    const orientation = new THREE.Quaternion().setFromUnitVectors(new THREE.Vector3(0, 0, 1), cut.normal);
    for (const o of [planeMesh, planeOutline]) {
      o.position.copy(centre);
      o.quaternion.copy(orientation);
      o.scale.setScalar(size);
    }
    handle.position.copy(centre);
    handle.scale.setScalar(0.025 * radius);
    handleStem.position.copy(centre);
    handleStem.quaternion.copy(orientation);
    handleStem.scale.setScalar(0.3 * radius);
  }

  /** The point of the plane nearest the centre of the points. */
  const planeCentre = () => cut.normal.clone().multiplyScalar(cut.offset * radius);

  // ------------------------------------------------------------ hover: the circumsphere

  const sphereGeometry = new THREE.SphereGeometry(1, 48, 32);

  function clearHover() {
    for (const child of [...hoverGroup.children]) if (child.geometry !== sphereGeometry) child.geometry.dispose();
    hoverGroup.clear();
  }

  /**
   * Shows the circumsphere (centre and radius in centred coordinates) of the tetrahedron with the
   * (centred) `corners` (12 floats), and the points on it (`onSphere`, centred x y z ...).
   */
  function showHover(hover) {
    clearHover();
    if (hover) {
      const sphere = new THREE.Mesh(sphereGeometry, materials.sphere);
      sphere.position.set(...hover.centre);
      sphere.scale.setScalar(hover.radius);
      sphere.renderOrder = 6;
      const ring = [];
      const [cx, cy, cz] = hover.centre;
      const view = camera.position.clone().sub(new THREE.Vector3(cx, cy, cz)).normalize();
      const u = new THREE.Vector3().crossVectors(view, Math.abs(view.z) < 0.9 ? new THREE.Vector3(0, 0, 1) : new THREE.Vector3(1, 0, 0)).normalize();
      const w = new THREE.Vector3().crossVectors(view, u);
      for (let k = 0; k <= 96; k++) {
        const a = (2 * Math.PI * k) / 96;
        ring.push(cx + hover.radius * (Math.cos(a) * u.x + Math.sin(a) * w.x), cy + hover.radius * (Math.cos(a) * u.y + Math.sin(a) * w.y), cz + hover.radius * (Math.cos(a) * u.z + Math.sin(a) * w.z));
      }
      const outline = new THREE.Line(new THREE.BufferGeometry().setAttribute('position', new THREE.Float32BufferAttribute(ring, 3)), materials.sphereRing);
      const edges = [];
      for (let a = 0; a < 4; a++) for (let b = a + 1; b < 4; b++) edges.push(...hover.corners.slice(3 * a, 3 * a + 3), ...hover.corners.slice(3 * b, 3 * b + 3));
      const tetra = new THREE.LineSegments(new THREE.BufferGeometry().setAttribute('position', new THREE.Float32BufferAttribute(edges, 3)), materials.hovered);
      const points = new THREE.Points(new THREE.BufferGeometry().setAttribute('position', new THREE.Float32BufferAttribute(hover.onSphere, 3)), materials.onSphere);
      outline.renderOrder = tetra.renderOrder = 7;
      points.renderOrder = 8;
      for (const o of [sphere, outline, tetra, points]) o.frustumCulled = false;
      hoverGroup.add(sphere, outline, tetra, points);
    }
    requestRender();
  }

  // ------------------------------------------------------------ the picked point's Voronoi cell

  function clearCell() {
    clearGroup(cellGroup);
  }

  /**
   * Draws a Voronoi cell: `vertices` (centred, x y z), faces as runs of corners (`faceOffsets`,
   * `faceCorners`), which are bounded (`faceBounded`), and the picked point (centred). Unbounded
   * faces give the chain of their vertices as lines; vertices farther than `reach` from the
   * centre of the points (circumcentres of flat hull tetrahedra) are left out.
   */
  function showCell(cell) {
    clearCell();
    if (cell) {
      const { vertices, faceOffsets, faceCorners, faceBounded, point } = cell;
      const reach = 4 * radius;
      const near = (c) => Math.hypot(vertices[3 * c], vertices[3 * c + 1], vertices[3 * c + 2]) <= reach;
      const triangles = [];
      const edges = [];
      for (let f = 0; f + 1 < faceOffsets.length; f++) {
        const ring = Array.from(faceCorners.subarray(faceOffsets[f], faceOffsets[f + 1]));
        const bounded = faceBounded[f] === 1;
        for (let k = 0; k + (bounded ? 0 : 1) < ring.length; k++) {
          const a = ring[k], b = ring[(k + 1) % ring.length];
          if (near(a) && near(b)) edges.push(a, b);
        }
        if (bounded && ring.every(near)) for (let k = 1; k + 1 < ring.length; k++) triangles.push(ring[0], ring[k], ring[k + 1]);
      }
      const positions = new THREE.BufferAttribute(Float32Array.from(vertices), 3);
      const faces = new THREE.BufferGeometry().setAttribute('position', positions);
      faces.setIndex(triangles);
      const lines = new THREE.BufferGeometry().setAttribute('position', positions);
      lines.setIndex(edges);
      const mesh = new THREE.Mesh(faces, materials.cell);
      const outline = new THREE.LineSegments(lines, materials.cellEdge);
      const dot = new THREE.Points(new THREE.BufferGeometry().setAttribute('position', new THREE.Float32BufferAttribute(point, 3)), materials.picked);
      mesh.renderOrder = 9;
      outline.renderOrder = 10;
      dot.renderOrder = 11;
      for (const o of [mesh, outline, dot]) o.frustumCulled = false;
      cellGroup.add(mesh, outline, dot);
    }
    requestRender();
  }

  // ------------------------------------------------------------ camera

  /** Fits the points into the view (keeping the viewing direction when asked). */
  function frameView(keepDirection = false) {
    const dir = camera.position.clone().sub(controls.target);
    if (!keepDirection || dir.lengthSq() < 1e-30) dir.copy(DEFAULT_VIEW_DIR);
    fitCamera(camera, controls, radius, dir);
  }

  /** A centred position on the screen: client pixels and its depth along the view (NDC z). */
  function toScreen(x, y, z) {
    const v = new THREE.Vector3(x, y, z).project(camera);
    const rect = pane.getBoundingClientRect();
    return { x: rect.left + ((v.x + 1) / 2) * rect.width, y: rect.top + ((1 - v.y) / 2) * rect.height, depth: v.z };
  }

  function render() {
    controls.update();
    stage.drawWhole(scene, camera);
    if (waiting.length) {
      content.add(waiting.shift()); // uploaded by the next frame
      stage.requestRender();
    }
  }

  /**
   * Compiles the shader programs of the tetrahedra, points and overlays while the worker loads
   * the module and computes (in parallel where the browser can: three.js compileAsync), so that
   * the first drawing does not wait for them on the main thread.
   */
  function warmUpShaders() {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(12), 3));
    geometry.setAttribute('middle', new THREE.BufferAttribute(new Float32Array(12), 3));
    geometry.setIndex(TETRAHEDRON_FACES.flat());
    const plain = new THREE.BufferGeometry().setAttribute('position', new THREE.BufferAttribute(new Float32Array(9), 3));
    const warm = new THREE.Group();
    warm.add(new THREE.Mesh(geometry, materials.tetrahedra), new THREE.Points(plain, materials.point), new THREE.Mesh(plain, materials.sphere),
      new THREE.Line(plain, materials.sphereRing), new THREE.Points(plain, materials.onSphere), new THREE.Mesh(plain, materials.cell));
    scene.add(warm);
    const done = () => {
      scene.remove(warm);
      geometry.dispose();
      plain.dispose();
    };
    stage.renderer.compileAsync(scene, camera).then(done, done);
  }

  function resize(w, h) {
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  }

  return {
    camera, controls, draw, setShrink, setCut, kept, planeCentre, showHover, showCell,
    frameView, toScreen, render, resize, requestRender, setVisible, warmUpShaders,
    get radius() { return radius; },
    /** Whether the plane and its handle are drawn (a cut, and the "plane" box ticked). */
    get planeShown() { return planeGroup.visible; },
    get pointSize() { return materials.point.size; },
    get shrink() { return uniforms.shrink.value; },
    get cut() { return cut; },
  };
}
