// The Delaunay view's drawing of a triangulation: on the paraboloid the lower hull faces, their
// edges, the lifted points and the lines dropped from them; in the plane (and again under the
// paraboloid when blended) the triangles, edges, hull outline, points and the Voronoi cells.
import * as THREE from 'three';
import { clearGroup } from '../app/stage.js';
import { LIFT, PLANE_Z } from './delaunay-scene.js';

/** The points as drawn: lifted onto the paraboloid (z = LIFT (x² + y²)) and in the plane (z = 0). */
export function liftedAndPlanePositions(coords) {
  const n = coords.length / 2;
  const liftedPos = new Float32Array(3 * n);
  const planePos = new Float32Array(3 * n);
  for (let i = 0; i < n; i++) {
    const x = coords[2 * i], y = coords[2 * i + 1];
    liftedPos.set([x, y, LIFT * (x * x + y * y)], 3 * i);
    planePos.set([x, y, 0], 3 * i);
  }
  return { liftedPos, planePos };
}

/** Every edge once: the halfedge with the larger twin index, or a hull halfedge. */
function triangleEdges(triangles, halfedges) {
  const out = [];
  for (let e = 0; e < triangles.length; e++) {
    if (halfedges[e] > e) continue;
    out.push(triangles[e], triangles[e % 3 === 2 ? e - 2 : e + 1]);
  }
  return Uint32Array.from(out);
}

/**
 * Draws `state.tri` over the points `state.xy` (and `state.cells`) into the groups of `scene`;
 * the display options are read from `ui`.
 */
export function createDelaunayDrawing({ ui, state, scene }) {
  const { materials, lifted, plane, planeIn3d, panes } = scene;

  function drawTriangulation() {
    const { xy, tri } = state;
    clearGroup(lifted);
    clearGroup(plane);
    clearGroup(planeIn3d);
    const n = xy.length / 2;
    const { liftedPos, planePos } = liftedAndPlanePositions(xy);
    const liftedAttr = new THREE.BufferAttribute(liftedPos, 3);
    const planeAttr = new THREE.BufferAttribute(planePos, 3);
    const edges = triangleEdges(tri.triangles, tri.halfedges);
    const size = n <= 400 ? 6 : n <= 3000 ? 4 : n <= 20000 ? 2.5 : 1.5;
    materials.point.size = size;

    const add = (group, obj, order) => {
      obj.renderOrder = order;
      obj.frustumCulled = false;
      group.add(obj);
      return obj;
    };
    const geometry = (attr, index) => {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', attr);
      if (index) g.setIndex(new THREE.BufferAttribute(index, 1));
      return g;
    };

    // The paraboloid: lower hull faces, their edges, the lifted points, and lift lines.
    const faces = add(lifted, new THREE.Mesh(geometry(liftedAttr, tri.triangles), materials.face), 1);
    faces.name = 'faces';
    add(lifted, new THREE.LineSegments(geometry(liftedAttr, edges), materials.liftedEdge), 2);
    add(lifted, new THREE.Points(geometry(liftedAttr), materials.point), 3);
    if (n <= 600) {
      const drops = new Float32Array(6 * n);
      for (let i = 0; i < n; i++) drops.set([xy[2 * i], xy[2 * i + 1], PLANE_Z, xy[2 * i], xy[2 * i + 1], liftedPos[3 * i + 2]], 6 * i);
      const dropLines = add(lifted, new THREE.LineSegments(geometry(new THREE.BufferAttribute(drops, 3)), materials.drop), 0);
      dropLines.name = 'drops';
    }

    // The plane: triangles, edges, hull outline, points; the same objects again under the paraboloid.
    const hullLoop = new Uint32Array(2 * tri.hull.length);
    for (let i = 0; i < tri.hull.length; i++) hullLoop.set([tri.hull[i], tri.hull[(i + 1) % tri.hull.length]], 2 * i);
    const planeGeoms = [
      [geometry(planeAttr, tri.triangles), (g) => new THREE.Mesh(g, materials.planeFill), 0],
      [geometry(planeAttr, edges), (g) => new THREE.LineSegments(g, materials.planeEdge), 1],
      [geometry(planeAttr, hullLoop), (g) => new THREE.LineSegments(g, materials.hull), 2],
      [geometry(planeAttr), (g) => new THREE.Points(g, materials.point), 4],
    ];
    for (const [g, make, order] of planeGeoms) {
      add(plane, make(g), order);
      add(planeIn3d, make(g), order);
    }
    drawVoronoi();
    applyVisibility();
  }

  function drawVoronoi() {
    for (const group of [plane, planeIn3d]) {
      const old = group.getObjectByName('voronoi');
      if (old) {
        group.remove(old);
        old.geometry.dispose();
      }
    }
    if (!state.cells || !ui.showVoronoi.checked) return;
    const { cellOffsets, cellXY } = state.cells;
    const pos = [];
    for (let c = 0; c + 1 < cellOffsets.length; c++) {
      const a = cellOffsets[c], b = cellOffsets[c + 1];
      for (let k = a; k < b; k++) {
        const l = k + 1 < b ? k + 1 : a;
        pos.push(cellXY[2 * k], cellXY[2 * k + 1], 0.001, cellXY[2 * l], cellXY[2 * l + 1], 0.001);
      }
    }
    const geom = new THREE.BufferGeometry();
    geom.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
    for (const group of [plane, planeIn3d]) {
      const lines = new THREE.LineSegments(geom, materials.voronoi);
      lines.name = 'voronoi';
      lines.renderOrder = 3;
      lines.frustumCulled = false;
      group.add(lines);
    }
  }

  function applyVisibility() {
    const faces = lifted.getObjectByName('faces');
    if (faces) faces.visible = ui.showLifted.checked;
    const drops = lifted.getObjectByName('drops');
    if (drops) drops.visible = ui.showDrops.checked && !panes.b;
  }

  return { drawTriangulation, drawVoronoi, applyVisibility };
}
