// hullkit.delaunay3, verifyDelaunay3, locate3 and voronoi3: the JS side of
// native/include/hullkit/delaunay3.hpp. Points go in as a Float64Array x0 y0 z0 x1 y1 z1 ...; every
// result array is a fresh typed array the caller owns (copied out of the WebAssembly heap after the
// call). The queries take the object delaunay3() returned back: its arrays are checked and copied
// into the heap, and the core answers from them (nothing is tetrahedralized again).
import {
  HullkitError, checkCorners, checkOptions, checkRepresentative, copyIn, flatCoordinates, locateInHeap, locateOptions, toInt32, toUint32,
} from './internal.js';

const DELAUNAY3_OPTIONS = ['progress', 'furthestSite'];
const VERIFY_OPTIONS = ['perturbed'];

/** The points as a Float64Array, x y z per point (see flatCoordinates: a flat layout only). */
const points3 = (xyz, where) => flatCoordinates(xyz, where, 3);

/**
 * The caller's progress callback made safe to call from C++: its first exception is kept (and
 * later calls skipped) to be thrown once the core has returned, since an exception thrown through
 * the WebAssembly frames would skip the C++ destructors and leak the working mesh.
 */
function guardedProgress(progress) {
  const guard = { failure: null, call: null };
  if (progress === undefined) return guard;
  if (typeof progress !== 'function') {
    throw new HullkitError(`delaunay3: progress must be a function (pointsDone, total) => void, got ${String(progress)}`);
  }
  guard.call = (done, total) => {
    if (guard.failure) return;
    try {
      progress(done, total);
    } catch (error) {
      guard.failure = { error };
    }
  };
  return guard;
}

/**
 * The Delaunay tetrahedralization of `xyz` (see hullkit.d.ts for the result).
 * @param core the loaded WebAssembly module
 */
export function delaunay3(core, xyz, options = {}) {
  const points = points3(xyz, 'delaunay3');
  const checked = checkOptions(options, DELAUNAY3_OPTIONS, 'delaunay3');
  const progress = guardedProgress(checked.progress);
  const furthestSite = checked.furthestSite ?? false;
  if (typeof furthestSite !== 'boolean') throw new HullkitError(`delaunay3: furthestSite must be true or false, got ${String(furthestSite)}`);
  const address = copyIn(core, points, 'delaunay3');
  let result;
  try {
    result = core.delaunay3FromHeap(address, points.length / 3, progress.call, furthestSite);
  } finally {
    core._free(address);
  }
  try {
    if (progress.failure) throw progress.failure.error;
    if (!result.ok()) throw new HullkitError(`delaunay3: ${result.error}`, { pointIndex: result.errorPoint() });
    // The views are taken now, after the call: memory growth during it replaced the heap's buffer.
    return {
      dimension: result.dimension,
      tetrahedra: result.tetrahedraView().slice(),
      neighbors: result.neighborsView().slice(),
      hull: result.hullView().slice(),
      triangles: result.trianglesView().slice(),
      vertices: result.verticesView().slice(),
      normal: result.normalView().slice(),
      representative: result.representativeView().slice(),
      duplicateCount: result.duplicateCount(),
      furthestSite: result.furthestSite,
    };
  } finally {
    result.delete();
  }
}

/** The exact check of a tetrahedralization of `xyz` (see hullkit.d.ts). */
export function verifyDelaunay3(core, xyz, tetrahedra, options = {}) {
  const points = points3(xyz, 'verifyDelaunay3');
  if (tetrahedra !== null && typeof tetrahedra === 'object' && !ArrayBuffer.isView(tetrahedra) && 'tetrahedra' in tetrahedra) {
    throw new TypeError('verifyDelaunay3: pass the tetrahedra array (result.tetrahedra), not the whole result');
  }
  const corners = toUint32(tetrahedra, 'verifyDelaunay3: tetrahedra');
  if (corners.length % 4 !== 0) {
    throw new HullkitError(`verifyDelaunay3: ${corners.length} indices is not a whole number of tetrahedra (4 per tetrahedron)`);
  }
  const { perturbed = true } = checkOptions(options, VERIFY_OPTIONS, 'verifyDelaunay3');
  if (typeof perturbed !== 'boolean') {
    throw new HullkitError(`verifyDelaunay3: perturbed must be true or false, got ${String(perturbed)}`);
  }
  const addresses = [];
  try {
    addresses.push(copyIn(core, points, 'verifyDelaunay3'), copyIn(core, corners, 'verifyDelaunay3'));
    return core.verifyDelaunay3FromHeap(addresses[0], points.length / 3, addresses[1], corners.length / 4, perturbed);
  } finally {
    for (const address of addresses) core._free(address);
  }
}

// ---------------------------------------------------------------- queries on a tetrahedralization

/**
 * The arrays of `triangulation` (what delaunay3() returned for `count` points) checked so that no
 * index sends the core outside its arrays or round a ring of faces forever: indices in range,
 * duplicates never used, four distinct corners per tetrahedron, and each neighbour sharing its
 * face back. O(n). The geometry is not checked (verifyDelaunay3 does that): answers for a
 * tetrahedralization of other points are meaningless.
 */
function checkTetrahedralization(triangulation, count, where) {
  if (triangulation === null || typeof triangulation !== 'object' || ArrayBuffer.isView(triangulation)) {
    throw new TypeError(`${where}: the triangulation must be the object delaunay3() returned`);
  }
  const { dimension } = triangulation;
  if (![3, 2, 1, 0, -1].includes(dimension)) {
    throw new HullkitError(`${where}: dimension ${String(dimension)} is not one of 3, 2, 1, 0, -1 (pass the object delaunay3() returned)`);
  }
  const representative = checkRepresentative(triangulation.representative ?? [], count, where);
  const empty = new Uint32Array(0);
  const furthestSite = triangulation.furthestSite ?? false;
  if (typeof furthestSite !== 'boolean') throw new HullkitError(`${where}: furthestSite must be true or false, got ${String(furthestSite)}`);
  const out = { dimension, tetrahedra: empty, neighbors: new Int32Array(0), triangles: empty, vertices: empty, representative, furthestSite };
  const corners = (array, name) => checkCorners(array, representative, name, where);
  if (dimension === 3) {
    const tetrahedra = corners(toUint32(triangulation.tetrahedra ?? [], `${where}: tetrahedra`), 'tetrahedra');
    const neighbors = toInt32(triangulation.neighbors ?? [], `${where}: neighbors`);
    if (tetrahedra.length % 4 !== 0) throw new HullkitError(`${where}: ${tetrahedra.length} tetrahedron indices is not a whole number of tetrahedra`);
    if (neighbors.length !== tetrahedra.length) throw new HullkitError(`${where}: ${neighbors.length} neighbours for ${tetrahedra.length / 4} tetrahedra (4 each)`);
    checkNeighbours(tetrahedra, neighbors, where);
    Object.assign(out, { tetrahedra, neighbors });
  } else if (dimension === 2) {
    const triangles = corners(toUint32(triangulation.triangles ?? [], `${where}: triangles`), 'triangles');
    if (triangles.length % 3 !== 0) throw new HullkitError(`${where}: ${triangles.length} triangle indices is not a whole number of triangles`);
    const neighbors = toInt32(triangulation.neighbors ?? [], `${where}: neighbors`);
    if (neighbors.length !== triangles.length) throw new HullkitError(`${where}: ${neighbors.length} neighbours for ${triangles.length / 3} triangles (3 each)`);
    for (let i = 0; i < neighbors.length; i++) {
      if (neighbors[i] < -1 || neighbors[i] >= triangles.length / 3) throw new HullkitError(`${where}: neighbors[${i}] = ${neighbors[i]} is out of range`);
    }
    Object.assign(out, { triangles, neighbors });
  } else {
    out.vertices = corners(toUint32(triangulation.vertices ?? [], `${where}: vertices`), 'vertices');
  }
  return out;
}

/** Each tetrahedron has four distinct corners; neighbours are in range and share their face back. */
function checkNeighbours(tetrahedra, neighbors, where) {
  const count = tetrahedra.length / 4;
  for (let t = 0; t < count; t++) {
    const a = tetrahedra[4 * t], b = tetrahedra[4 * t + 1], c = tetrahedra[4 * t + 2], d = tetrahedra[4 * t + 3];
    if (a === b || a === c || a === d || b === c || b === d || c === d) {
      throw new HullkitError(`${where}: tetrahedron ${t} (${a} ${b} ${c} ${d}) repeats a corner`);
    }
    for (let k = 0; k < 4; k++) {
      const u = neighbors[4 * t + k];
      if (u === -1) continue;
      if (!Number.isInteger(u) || u < -1 || u >= count || u === t) {
        throw new HullkitError(`${where}: neighbors[${4 * t + k}] = ${u} is out of range (${count} tetrahedra)`);
      }
      // u holds the three corners of t other than corner k, and its fourth corner's face leads back to t.
      const far = tetrahedra[4 * t + k];
      let shared = 0, back = -1;
      for (let j = 0; j < 4; j++) {
        const w = tetrahedra[4 * u + j];
        if (w !== far && (w === a || w === b || w === c || w === d)) shared++;
        else back = j;
      }
      if (shared !== 3 || neighbors[4 * u + back] !== t) {
        throw new HullkitError(`${where}: tetrahedra ${t} and ${u} are neighbours (neighbors[${4 * t + k}]) but do not share that face back`);
      }
    }
  }
}

/**
 * With the points and the checked tetrahedralization copied into the heap, runs
 * `call(pointsAddress, count, heapTetrahedralization)` and frees the blocks.
 */
function withTetrahedralizationInHeap(core, points, t, where, call) {
  const blocks = [];
  const put = (array) => {
    const address = copyIn(core, array, where);
    blocks.push(address);
    return address;
  };
  try {
    const heap = {
      dimension: t.dimension,
      tetrahedra: put(t.tetrahedra),
      tetrahedronCount: t.tetrahedra.length / 4,
      neighbors: put(t.neighbors),
      triangles: put(t.triangles),
      triangleCount: t.triangles.length / 3,
      vertices: put(t.vertices),
      vertexCount: t.vertices.length,
      representative: put(t.representative),
      furthestSite: t.furthestSite,
    };
    return call(put(points), points.length / 3, heap);
  } finally {
    for (const address of blocks) core._free(address);
  }
}

/**
 * Locates each query point (x y z per query) in the tetrahedralization of `xyz` (see hullkit.d.ts).
 * @param core the loaded WebAssembly module
 */
export function locate3(core, xyz, triangulation, queries, options = {}) {
  const where = 'locate3';
  const points = points3(xyz, where);
  const at = flatCoordinates(queries, where, 3, 'queries');
  const flags = locateOptions(options, where);
  const t = checkTetrahedralization(triangulation, points.length / 3, where);
  return locateInHeap(core, { where, cell: 'tetrahedron', dimension: 3, queries: at, flags },
    (run) => withTetrahedralizationInHeap(core, points, t, where, run), (...args) => core.delaunay3LocateFromHeap(...args));
}

/**
 * The Voronoi diagram of `xyz` from its tetrahedralization (see hullkit.d.ts).
 * @param core the loaded WebAssembly module
 */
export function voronoi3(core, xyz, triangulation) {
  const where = 'voronoi3';
  const points = points3(xyz, where);
  const t = checkTetrahedralization(triangulation, points.length / 3, where);
  const v = withTetrahedralizationInHeap(core, points, t, where, (address, count, heap) => core.delaunay3VoronoiFromHeap(address, count, heap));
  try {
    return {
      vertices: v.verticesView().slice(),
      tetrahedronVertex: v.tetrahedronVertexView().slice(),
      facePoints: v.facePointsView().slice(),
      faceOffsets: v.faceOffsetsView().slice(),
      faceVertices: v.faceVerticesView().slice(),
      faceBounded: v.faceBoundedView().slice(),
      cellOffsets: v.cellOffsetsView().slice(),
      cellFaces: v.cellFacesView().slice(),
      volume: v.volumeView().slice(),
    };
  } finally {
    v.delete();
  }
}
