// The Delaunay view's constrained modes, drawn over what delaunay-draw.js draws of the
// triangulation (its triangles, edges and points, on the paraboloid and in the plane):
// constrained edges thick and orange, the points hullkit added (crossings, Steiner points)
// violet; and, in groups of their own that follow every edit at once, the rings being edited:
// closed rings, the open ring, the vertices, a ring around the open ring's first vertex (click it
// to close the ring), Triangle's hole points and a red ring around a vertex an error names.
import * as THREE from 'three';
import { clearGroup } from '../../app/stage.js';
import { LIFT } from '../delaunay-scene.js';

const COLORS = { constraint: 0xff6a3d, added: 0xd66bff, ring: 0xff6a3d, open: 0xffffff, first: 0xffffff, bad: 0xff3b3b, hole: 0x9aa6b8 };
const EDGE_PX = 3.5; // constrained edges, in pixels of the plane pane
const RING_PX = 2; // the rings being edited
const Z = { ring: 0.0008, constraint: 0.001, added: 0.002, vertex: 0.0025, marker: 0.003 };

/**
 * Draws into the groups of `scene` (delaunay-scene.js): `drawResult(result)` after
 * drawing.drawTriangulation() of the same result, `drawEditing(model, {badPoint})` after each edit,
 * `clearResult()` when there is no triangulation to show.
 */
export function createConstrainedDrawing({ scene, state }) {
  const { materials: base, plane, planeIn3d, lifted, edit2d, edit3d, panes, camera2d, requestRender } = scene;
  const materials = {
    constraint: new THREE.MeshBasicMaterial({ color: COLORS.constraint, side: THREE.DoubleSide }),
    constraintLine: new THREE.LineBasicMaterial({ color: COLORS.constraint }),
    added: new THREE.PointsMaterial({ color: COLORS.added, size: 9, sizeAttenuation: false, map: base.point.map, alphaTest: 0.5 }),
    ring: new THREE.MeshBasicMaterial({ color: COLORS.ring, side: THREE.DoubleSide }),
    open: new THREE.LineBasicMaterial({ color: COLORS.open }),
    vertex: new THREE.PointsMaterial({ color: base.point.color, size: 7, sizeAttenuation: false, map: base.point.map, alphaTest: 0.5 }),
    first: new THREE.MeshBasicMaterial({ color: COLORS.first, side: THREE.DoubleSide }),
    bad: new THREE.MeshBasicMaterial({ color: COLORS.bad, side: THREE.DoubleSide }),
    hole: new THREE.PointsMaterial({ color: COLORS.hole, size: 7, sizeAttenuation: false }),
  };

  /** World units per pixel of the plane as drawn (the plane pane; blended: roughly, from the extent). */
  function worldPerPixel() {
    if (panes.b) return (camera2d.right - camera2d.left) / Math.max(1, panes.b.w);
    return (2.6 * state.extent.r) / Math.max(1, Math.min(panes.a?.w ?? 1, panes.a?.h ?? 1));
  }

  const geometry = (positions, index) => {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    if (index) g.setIndex(new THREE.BufferAttribute(index, 1));
    return g;
  };
  const add = (group, obj, order, name) => {
    obj.renderOrder = order;
    obj.frustumCulled = false;
    if (name) obj.name = name;
    group.add(obj);
    return obj;
  };

  /** The constrained edges, each once, as flat index pairs. */
  function constrainedPairs({ triangles, halfedges, constrained }) {
    const out = [];
    for (let e = 0; e < triangles.length; e++) {
      if (!constrained[e] || halfedges[e] > e) continue;
      out.push(triangles[e], triangles[e % 3 === 2 ? e - 2 : e + 1]);
    }
    return Uint32Array.from(out);
  }

  /** Segments a–b as quads `width` wide at height z (two triangles each). */
  function thickSegments(coords, pairs, width, z) {
    const m = pairs.length / 2;
    const pos = new Float32Array(12 * m);
    const index = new Uint32Array(6 * m);
    for (let s = 0; s < m; s++) {
      const a = pairs[2 * s], b = pairs[2 * s + 1];
      const ax = coords[2 * a], ay = coords[2 * a + 1], bx = coords[2 * b], by = coords[2 * b + 1];
      const len = Math.hypot(bx - ax, by - ay) || 1;
      const nx = (-(by - ay) / len) * (width / 2), ny = ((bx - ax) / len) * (width / 2);
      pos.set([ax + nx, ay + ny, z, ax - nx, ay - ny, z, bx - nx, by - ny, z, bx + nx, by + ny, z], 12 * s);
      index.set([4 * s, 4 * s + 1, 4 * s + 2, 4 * s, 4 * s + 2, 4 * s + 3], 6 * s);
    }
    return geometry(pos, index);
  }

  /** Flat positions (x, y, z) of some points of `coords`. */
  function planePositions(coords, indices, z) {
    const pos = new Float32Array(3 * indices.length);
    indices.forEach((i, k) => pos.set([coords[2 * i], coords[2 * i + 1], z], 3 * k));
    return pos;
  }

  /** What sets the constrained result apart, over the triangulation drawn from it. */
  function drawResult(result) {
    const { coords, inputCount } = result;
    const pairs = constrainedPairs(result);
    const width = EDGE_PX * worldPerPixel();
    const added = Array.from({ length: coords.length / 2 - inputCount }, (_, k) => inputCount + k);
    for (const group of [plane, planeIn3d]) {
      add(group, new THREE.Mesh(thickSegments(coords, pairs, width, Z.constraint), materials.constraint), 3, 'constraints');
      if (added.length) add(group, new THREE.Points(geometry(planePositions(coords, added, Z.added)), materials.added), 5, 'added');
    }
    // On the paraboloid: the constrained edges and added points lifted.
    const liftedAt = (i) => [coords[2 * i], coords[2 * i + 1], LIFT * (coords[2 * i] ** 2 + coords[2 * i + 1] ** 2)];
    const liftedPos = new Float32Array(3 * pairs.length);
    pairs.forEach((v, k) => liftedPos.set(liftedAt(v), 3 * k));
    add(lifted, new THREE.LineSegments(geometry(liftedPos), materials.constraintLine), 3, 'constraints');
    if (added.length) {
      const addedPos = new Float32Array(3 * added.length);
      added.forEach((v, k) => addedPos.set(liftedAt(v), 3 * k));
      add(lifted, new THREE.Points(geometry(addedPos), materials.added), 5, 'added');
    }
    return { constrainedEdges: pairs.length / 2 };
  }

  /** No triangulation shown (an error, nothing to triangulate). */
  function clearResult() {
    for (const group of [plane, planeIn3d, lifted]) clearGroup(group);
  }

  /** A flat ring of `radius` pixels around (x, y). */
  function marker(x, y, radiusPx, material) {
    const px = worldPerPixel();
    const g = new THREE.RingGeometry(radiusPx * px, (radiusPx + 2.5) * px, 40, 1);
    g.translate(x, y, Z.marker);
    return new THREE.Mesh(g, material);
  }

  /**
   * The rings as edited: `model` = {points: [[x, y]], rings: [[i]], open: [i], segments (flat
   * pairs), holes (flat x y)}; `badPoint` (a point index) is ringed in red.
   */
  function drawEditing(model, { badPoint = -1 } = {}) {
    for (const group of [edit2d, edit3d]) {
      clearGroup(group);
      if (!model) continue;
      const { points, rings, open, segments, holes } = model;
      const at = (i, z) => [points[i][0], points[i][1], z];
      // The closed rings and segments as they are now (the result's constrained edges, drawn
      // wider over them, may lag a drag by a frame or be missing after an error).
      const pairs = [...segments];
      for (const ring of rings) ring.forEach((v, k) => pairs.push(v, ring[(k + 1) % ring.length]));
      if (pairs.length) {
        const flat = Float64Array.from(points.flat());
        add(group, new THREE.Mesh(thickSegments(flat, pairs, RING_PX * worldPerPixel(), Z.ring), materials.ring), 2, 'rings');
      }
      if (open.length >= 2) add(group, new THREE.Line(geometry(Float32Array.from(open.flatMap((v) => at(v, Z.ring)))), materials.open), 6, 'open-ring');
      if (points.length) add(group, new THREE.Points(geometry(Float32Array.from(points.flatMap(([x, y]) => [x, y, Z.vertex]))), materials.vertex), 7, 'vertices');
      if (holes.length) {
        const pos = [];
        for (let h = 0; h + 1 < holes.length; h += 2) pos.push(holes[h], holes[h + 1], Z.vertex);
        add(group, new THREE.Points(geometry(Float32Array.from(pos)), materials.hole), 7, 'hole-points');
      }
      if (open.length >= 3) add(group, marker(points[open[0]][0], points[open[0]][1], 7, materials.first), 8, 'first-vertex');
      if (badPoint >= 0 && badPoint < points.length) add(group, marker(points[badPoint][0], points[badPoint][1], 9, materials.bad), 8, 'bad-vertex');
    }
    requestRender();
  }

  return { drawResult, clearResult, drawEditing, worldPerPixel };
}
