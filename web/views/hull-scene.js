// The Hull view's three.js scene: camera, lights and orbit controls, the materials, and the
// drawing of a hull (translucent faces, edges, hull vertices, the interior points, the points the
// seed's epsilon dropped) or of the points alone, framed in the view.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { discTexture, clearGroup, fitCamera } from '../app/stage.js';
import { centredPositions } from '../positions.js';

// Interior points beyond this many are drawn sparsely (every k-th): they only give the hull its
// context, and a million points would make orbiting stutter on a software renderer.
const MAX_INTERIOR_DRAWN = 150_000;
const DENSE_TRIANGLES = 60_000; // more hull triangles than this: front faces only, no wireframe

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
 * The scene drawn on the `stage`'s renderer, orbited on `ui.canvas`; it draws while
 * `state.active` (the view is shown).
 */
export function createHullScene({ stage, ui, state }) {
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
    fitCamera(camera, controls, viewRadius, dir);
  }

  function requestRender() {
    if (state.active) stage.requestRender();
  }
  function renderNow() {
    if (state.active) stage.renderNow();
  }
  controls.addEventListener('change', requestRender);

  /** Draws this view (called by the stage while it is active). */
  function render() {
    controls.update(); // emits 'change' (→ another frame) while damping
    stage.drawWhole(scene, camera);
  }

  function resize(w, h) {
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  }

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

  return {
    scene, controls, content, requestRender, renderNow, render, resize, drawScene, clearContent, applyVisibility, frameView, warmUpShaders,
    get viewRadius() { return viewRadius; },
    get interiorStride() { return interiorStride; },
    get interiorTotal() { return interiorTotal; },
    get dense() { return dense; },
  };
}
