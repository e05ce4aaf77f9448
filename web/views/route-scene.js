// The Route view's three.js scene: camera and orbit controls on the pane over the canvas, the
// materials, and the drawing of the scene (grid, obstacles), of the route (the traverse at each
// waypoint, the handles with their yaw rings, the path of the handles) and of a report (each leg's
// swept hulls per sub-interval, the traverse ghosted at first contact, the sampled poses).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { clearGroup, zUpCamera } from '../app/stage.js';
import { partVertices, partTriangles } from '../route-scenes.js';
import { IDENTITY, legMotion, poseAt, poseOf, placePoint, rotate, subintervalCount, yawOf } from '../route-poses.js';

const COLORS = {
  obstacle: 0x8796b0,
  obstacleEdge: 0xc4cede,
  traverse: 0x5fd3e3,
  clear: 0x4ade80,
  hit: 0xff5f5f,
  ghost: 0xffb547,
  sample: 0xb8c3d6,
  handle: 0xffffff,
  selected: 0xffb547,
  route: 0xdbe3ee,
  grid: 0x243040,
};
const RING_SEGMENTS = 64;

/** The traverse's pivot (its own coordinates; the library's default is the origin). */
export const pivotOf = (sceneJson) => sceneJson.traverse.pivot ?? [0, 0, 0];

/**
 * The scene drawn on the `stage`'s renderer and orbited on a pane over the canvas (appended to
 * `viewport`); it draws while `state.active`. Reads state.sceneJson, state.route, state.selected,
 * state.report and state.sweeps.
 */
export function createRouteScene({ stage, state, viewport }) {
  // The pane over the canvas takes the pointer: waypoint drags first, orbiting otherwise.
  const pane = document.createElement('div');
  pane.className = 'pane';
  pane.dataset.for = 'route';
  pane.hidden = true;
  Object.assign(pane.style, { left: 0, top: 0, right: 0, bottom: 0 });
  viewport.append(pane);

  const scene = new THREE.Scene();
  const camera = zUpCamera(scene, { near: 0.05, far: 500 });

  const mat = {
    obstacle: new THREE.MeshStandardMaterial({ color: COLORS.obstacle, roughness: 0.8, metalness: 0, side: THREE.DoubleSide, transparent: true, opacity: 0.8, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }),
    obstacleEdge: new THREE.LineBasicMaterial({ color: COLORS.obstacleEdge, transparent: true, opacity: 0.7 }),
    traverse: new THREE.MeshStandardMaterial({ color: COLORS.traverse, roughness: 0.5, metalness: 0, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }),
    traverseEdge: new THREE.LineBasicMaterial({ color: 0xa6eef8 }),
    waypointEdge: new THREE.LineBasicMaterial({ color: COLORS.traverse, transparent: true, opacity: 0.45 }),
    clear: new THREE.MeshStandardMaterial({ color: COLORS.clear, transparent: true, opacity: 0.2, depthWrite: false, side: THREE.DoubleSide, roughness: 0.6 }),
    hit: new THREE.MeshStandardMaterial({ color: COLORS.hit, transparent: true, opacity: 0.24, depthWrite: false, side: THREE.DoubleSide, roughness: 0.6 }),
    clearEdge: new THREE.LineBasicMaterial({ color: COLORS.clear, transparent: true, opacity: 0.55 }),
    hitEdge: new THREE.LineBasicMaterial({ color: COLORS.hit, transparent: true, opacity: 0.65 }),
    // The many sub-interval hulls of a turning leg: fainter edges.
    clearEdgeTurning: new THREE.LineBasicMaterial({ color: COLORS.clear, transparent: true, opacity: 0.22 }),
    hitEdgeTurning: new THREE.LineBasicMaterial({ color: COLORS.hit, transparent: true, opacity: 0.28 }),
    ghost: new THREE.MeshStandardMaterial({ color: COLORS.ghost, transparent: true, opacity: 0.5, depthWrite: false, roughness: 0.5 }),
    ghostEdge: new THREE.LineBasicMaterial({ color: COLORS.ghost }),
    sample: new THREE.LineBasicMaterial({ color: COLORS.sample, transparent: true, opacity: 0.5 }),
    sampleHit: new THREE.LineBasicMaterial({ color: COLORS.hit }),
    route: new THREE.LineDashedMaterial({ color: COLORS.route, dashSize: 0.25, gapSize: 0.15, transparent: true, opacity: 0.8 }),
    handle: new THREE.MeshStandardMaterial({ color: COLORS.handle, roughness: 0.35, emissive: 0x222222 }),
    selected: new THREE.MeshStandardMaterial({ color: COLORS.selected, roughness: 0.35, emissive: 0x553300 }),
    // Yaw rings: drawn over everything, like any gizmo.
    ring: new THREE.MeshBasicMaterial({ color: COLORS.route, transparent: true, opacity: 0.5, depthTest: false }),
    ringSelected: new THREE.MeshBasicMaterial({ color: COLORS.selected, transparent: true, opacity: 0.95, depthTest: false }),
  };

  const groups = {
    static: new THREE.Group(), // grid, obstacles
    sweeps: new THREE.Group(),
    poses: new THREE.Group(), // traverse at the waypoints
    ghost: new THREE.Group(),
    samples: new THREE.Group(),
    handles: new THREE.Group(),
  };
  for (const g of Object.values(groups)) scene.add(g);

  const controls = new OrbitControls(camera, pane);
  controls.enableDamping = true;
  controls.dampingFactor = 0.12;
  controls.enabled = false;

  let traverseGeoms = []; // per part: {mesh: BufferGeometry, edges: EdgesGeometry}
  let handleLocal = [0, 0, 0]; // the handles' point of the traverse: its pivot if it has one, else its box centre
  let sceneBounds = new THREE.Box3(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
  let framed = false;
  const sizes = { handle: 0.12, ring: 0.5 };

  function requestRender() {
    if (state.active) stage.requestRender();
  }
  controls.addEventListener('change', requestRender);

  function render() {
    controls.update();
    stage.drawWhole(scene, camera);
  }

  function resize(w, h) {
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    if (!framed) {
      frame();
      framed = true;
    }
  }

  // ------------------------------------------------------------ geometry

  function meshGeometry(part) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(partVertices(part), 3));
    g.setIndex(partTriangles(part));
    g.computeVertexNormals();
    return g;
  }

  function add(group, obj, order = 0) {
    obj.renderOrder = order;
    group.add(obj);
    return obj;
  }

  /** Puts `obj` (in the traverse's own coordinates) at `pose`: v -> pivot + R (v - pivot) + position. */
  function applyPose(obj, { position, quaternion }) {
    const pivot = pivotOf(state.sceneJson);
    const turned = rotate(quaternion, pivot);
    obj.position.set(...pivot.map((c, k) => c - turned[k] + position[k]));
    obj.quaternion.set(quaternion[1], quaternion[2], quaternion[3], quaternion[0]);
    return obj;
  }

  /** The poses a leg is drawn with: its ends and its sub-intervals' ends (steps per sub-interval). */
  function legPoses(leg, steps = 1) {
    const motion = legMotion(state.route[leg], state.route[leg + 1]);
    const n = steps * subintervalCount(motion);
    return Array.from({ length: n + 1 }, (_, k) => poseAt(motion, k / n));
  }

  /** Grid, obstacles and the traverse's geometry for the current scene (once per preset or file). */
  function buildStatic() {
    clearGroup(groups.static);
    for (const g of traverseGeoms) { g.mesh.dispose(); g.edges.dispose(); }
    const bounds = new THREE.Box3();
    for (const obstacle of state.sceneJson.obstacles) {
      const g = meshGeometry(obstacle);
      g.computeBoundingBox();
      bounds.union(g.boundingBox);
      add(groups.static, new THREE.Mesh(g, mat.obstacle), 1).name = obstacle.name;
      add(groups.static, new THREE.LineSegments(new THREE.EdgesGeometry(g, 1), mat.obstacleEdge), 2);
    }
    traverseGeoms = state.sceneJson.traverse.parts.map((part) => {
      const mesh = meshGeometry(part);
      return { mesh, edges: new THREE.EdgesGeometry(mesh, 1) };
    });
    const tb = new THREE.Box3();
    for (const g of traverseGeoms) { g.mesh.computeBoundingBox(); tb.union(g.mesh.boundingBox); }
    handleLocal = state.sceneJson.traverse.pivot ?? tb.getCenter(new THREE.Vector3()).toArray();
    // The traverse's box corners at every drawn pose of the route.
    const corners = [];
    for (const x of [tb.min.x, tb.max.x]) for (const y of [tb.min.y, tb.max.y]) for (const z of [tb.min.z, tb.max.z]) corners.push([x, y, z]);
    const pivot = pivotOf(state.sceneJson);
    for (let leg = 0; leg + 1 < state.route.length; leg++) {
      for (const pose of legPoses(leg)) for (const c of corners) bounds.expandByPoint(new THREE.Vector3(...placePoint(c, pivot, pose)));
    }
    const size = bounds.getSize(new THREE.Vector3());
    const centre = bounds.getCenter(new THREE.Vector3());
    const span = Math.ceil(Math.max(size.x, size.y) + 4);
    const grid = new THREE.GridHelper(span, span, COLORS.grid, COLORS.grid);
    grid.rotation.x = Math.PI / 2;
    grid.position.set(Math.round(centre.x), Math.round(centre.y), 0);
    add(groups.static, grid, 0);
    sceneBounds = bounds;
    sizes.handle = Math.max(0.12, size.length() / 90);
    sizes.ring = 4.5 * sizes.handle;
  }

  function frame() {
    const centre = sceneBounds.getCenter(new THREE.Vector3());
    const r = sceneBounds.getSize(new THREE.Vector3()).length() / 2;
    const dir = new THREE.Vector3(-0.55, -1.25, 1.0).normalize();
    const fov = THREE.MathUtils.degToRad(camera.fov);
    const hfov = 2 * Math.atan(Math.tan(fov / 2) * camera.aspect);
    const dist = (r / Math.sin(Math.min(fov, hfov) / 2)) * 0.95;
    controls.target.copy(centre);
    camera.position.copy(centre).addScaledVector(dir, dist);
    camera.near = dist / 100;
    camera.far = dist * 10;
    camera.updateProjectionMatrix();
    controls.update();
    framed = true;
  }

  /** The traverse (all parts) at `pose`, as faces and/or edges with the given materials. */
  function traverseAt(group, pose, faceMat, edgeMat, order) {
    for (const g of traverseGeoms) {
      if (faceMat) applyPose(add(group, new THREE.Mesh(g.mesh, faceMat), order), pose);
      if (edgeMat) applyPose(add(group, new THREE.LineSegments(g.edges, edgeMat), order + 1), pose);
    }
  }

  /** Where waypoint `i`'s handle is (world), or the handles' point at a pose. */
  const handleAt = (pose) => new THREE.Vector3(...placePoint(handleLocal, pivotOf(state.sceneJson), pose));
  const handleOf = (i) => handleAt(poseOf(state.route[i]));

  /** The point of waypoint `i`'s yaw ring at `degrees` about z (world). */
  function ringPoint(i, degrees) {
    const a = THREE.MathUtils.degToRad(degrees);
    return handleOf(i).add(new THREE.Vector3(sizes.ring * Math.cos(a), sizes.ring * Math.sin(a), 0));
  }

  function owned(obj) {
    obj.userData.owned = true;
    return obj;
  }

  /** Waypoint handles with their yaw rings, the handles' path and the traverse at each waypoint. */
  function drawRoute() {
    for (const g of [groups.poses, groups.handles]) {
      for (const obj of [...g.children]) {
        // Shared traverse geometries stay; only the line, spheres and rings are owned here.
        if (obj.userData.owned) obj.geometry.dispose();
      }
      g.clear();
    }
    const path = [handleOf(0)];
    for (let leg = 0; leg + 1 < state.route.length; leg++) path.push(...legPoses(leg, 2).slice(1).map(handleAt));
    const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(path), mat.route);
    line.computeLineDistances();
    add(groups.handles, owned(line), 6);
    state.route.forEach((w, i) => {
      const isSelected = i === state.selected;
      const centre = handleOf(i);
      const sphere = add(groups.handles, owned(new THREE.Mesh(new THREE.SphereGeometry(sizes.handle, 20, 14), isSelected ? mat.selected : mat.handle)), 7);
      sphere.position.copy(centre);
      sphere.userData.waypoint = i;
      const ringMat = isSelected ? mat.ringSelected : mat.ring;
      const ring = add(groups.handles, owned(new THREE.Mesh(new THREE.TorusGeometry(sizes.ring, sizes.ring * (isSelected ? 0.06 : 0.04), 6, RING_SEGMENTS), ringMat)), 10);
      ring.position.copy(centre);
      ring.userData.ring = i;
      // The knob on the ring points where the yaw turns the traverse's x axis.
      const knob = add(groups.handles, owned(new THREE.Mesh(new THREE.SphereGeometry(sizes.handle * 0.6, 12, 8), ringMat)), 11);
      knob.position.copy(ringPoint(i, yawOf(w)));
      traverseAt(groups.poses, poseOf(w), i === 0 ? mat.traverse : null, i === 0 ? mat.traverseEdge : mat.waypointEdge, 3);
    });
  }

  /** The swept hulls, the ghosts at first contact and (with `samples` > 0) the sampled poses. */
  function drawReport(samples) {
    clearGroup(groups.sweeps);
    groups.ghost.clear(); // the traverse's shared geometries
    groups.samples.clear();
    const { report, sweeps } = state;
    if (!report) return;
    // Swept hulls, per leg, sub-interval and part, coloured by the leg's status.
    for (const { leg, of, points, triangles } of sweeps) {
      const status = report.legs[leg]?.status;
      if (!status) continue;
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(points, 3));
      g.setIndex(new THREE.BufferAttribute(triangles, 1));
      g.computeVertexNormals();
      const isClear = status === 'clear';
      add(groups.sweeps, new THREE.Mesh(g, isClear ? mat.clear : mat.hit), 4);
      const edgeMat = of > 1 ? (isClear ? mat.clearEdgeTurning : mat.hitEdgeTurning) : isClear ? mat.clearEdge : mat.hitEdge;
      add(groups.sweeps, new THREE.LineSegments(new THREE.EdgesGeometry(g, 1), edgeMat), 5);
    }
    // The traverse at its first contact: offset and orientation at fraction[0].
    for (const leg of report.legs) {
      if (leg.status !== 'clear' && leg.position) {
        traverseAt(groups.ghost, { position: leg.position, quaternion: leg.rotation ?? IDENTITY }, mat.ghost, mat.ghostEdge, 8);
      }
    }
    // N-step sampling: the traverse at N + 1 fractions of every leg, red where a pose hits.
    if (samples > 0) {
      report.legs.forEach((leg, i) => {
        const motion = legMotion(state.route[i], state.route[i + 1]);
        const hitAt = leg.sampled?.hit ? leg.sampled.fraction : null;
        for (let k = 0; k <= samples; k++) {
          const f = k / samples;
          const isHit = hitAt !== null && Math.abs(f - hitAt) < 1e-9;
          traverseAt(groups.samples, poseAt(motion, f), null, isHit ? mat.sampleHit : mat.sample, 9);
        }
      });
    }
  }

  /** `v` (world) in client pixels. */
  function toScreen(v) {
    const p = v.clone().project(camera);
    const rect = pane.getBoundingClientRect();
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }

  return {
    pane, camera, controls, groups, sizes,
    render, resize, requestRender, buildStatic, frame, drawRoute, drawReport,
    handleOf, ringPoint, toScreen,
    /** Frames the scene now when shown, else on the next resize. */
    reframe() {
      framed = false;
      if (state.active) frame();
    },
  };
}
