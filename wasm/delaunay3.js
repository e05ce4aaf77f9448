// hullkit.delaunay3, verifyDelaunay3, locate3 and voronoi3: the JS side of
// native/include/hullkit/delaunay3.hpp. Points go in as a Float64Array x0 y0 z0 x1 y1 z1 ...; every
// result array is a fresh typed array the caller owns (copied out of the WebAssembly heap after the
// call). The queries take the object delaunay3() returned back: its arrays are checked and copied
// into the heap, and the core answers from them (nothing is tetrahedralized again).
import { HullkitError, checkOptions, copyIn, toFloat64, toUint32 } from './internal.js';

const DELAUNAY3_OPTIONS = ['progress'];
const VERIFY_OPTIONS = ['perturbed'];
const LOCATE_OPTIONS = ['barycentric', 'nearest'];

/**
 * The points as a Float64Array (see toFloat64), refusing a plain array whose entries are not
 * numbers: Float64Array.from would turn [x, y, z] or {x, y, z} entries into NaN, and the core would
 * then blame "point 0" for a non-finite coordinate instead of the layout.
 */
function points3(xyz, where) {
  if (Array.isArray(xyz)) {
    for (let i = 0; i < xyz.length; i++) {
      const v = xyz[i];
      if (typeof v === 'number') continue;
      const got = Array.isArray(v) || ArrayBuffer.isView(v)
        ? 'an array of arrays — flatten it (xyz.flat())'
        : v !== null && typeof v === 'object'
          ? 'an array of objects — flatten it (points.flatMap((p) => [p.x, p.y, p.z]))'
          : `entry ${i} is ${v === null ? 'null' : typeof v} (${String(v)})`;
      throw new TypeError(`${where}: xyz must be a Float64Array or an array of numbers (x y z per point); got ${got}`);
    }
  }
  return toFloat64(xyz, where, 3);
}

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
  const progress = guardedProgress(checkOptions(options, DELAUNAY3_OPTIONS, 'delaunay3').progress);
  const address = copyIn(core, points, 'delaunay3');
  let result;
  try {
    result = core.delaunay3FromHeap(address, points.length / 3, progress.call);
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

/** A typed array of `Type` from `values` (used as it is when it already is one), or a TypeError. */
function typed(values, Type, where) {
  if (values instanceof Type) return values;
  if (values == null || typeof values.length !== 'number' || typeof values === 'string') {
    throw new TypeError(`${where} must be a ${Type.name} or an array of integers`);
  }
  return Type.from(values);
}

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
  const representative = toUint32(triangulation.representative ?? [], `${where}: representative`);
  if (representative.length !== count) {
    throw new HullkitError(`${where}: representative has ${representative.length} entries for ${count} points (the triangulation is of other points)`);
  }
  for (let i = 0; i < count; i++) {
    const r = representative[i];
    if (r > i || representative[r] !== r) throw new HullkitError(`${where}: representative[${i}] = ${r} is not a lower point that stands for itself`);
  }
  const empty = new Uint32Array(0);
  const out = { dimension, tetrahedra: empty, neighbors: new Int32Array(0), triangles: empty, vertices: empty, representative };
  const corners = (array, name) => {
    for (let i = 0; i < array.length; i++) {
      const v = array[i];
      if (v >= count) throw new HullkitError(`${where}: ${name}[${i}] = ${v} but there are ${count} points`);
      if (representative[v] !== v) throw new HullkitError(`${where}: ${name}[${i}] = ${v} is a duplicate of point ${representative[v]}`);
    }
    return array;
  };
  if (dimension === 3) {
    const tetrahedra = corners(toUint32(triangulation.tetrahedra ?? [], `${where}: tetrahedra`), 'tetrahedra');
    const neighbors = typed(triangulation.neighbors ?? [], Int32Array, `${where}: neighbors`);
    if (tetrahedra.length % 4 !== 0) throw new HullkitError(`${where}: ${tetrahedra.length} tetrahedron indices is not a whole number of tetrahedra`);
    if (neighbors.length !== tetrahedra.length) throw new HullkitError(`${where}: ${neighbors.length} neighbours for ${tetrahedra.length / 4} tetrahedra (4 each)`);
    checkNeighbours(tetrahedra, neighbors, where);
    Object.assign(out, { tetrahedra, neighbors });
  } else if (dimension === 2) {
    const triangles = corners(toUint32(triangulation.triangles ?? [], `${where}: triangles`), 'triangles');
    if (triangles.length % 3 !== 0) throw new HullkitError(`${where}: ${triangles.length} triangle indices is not a whole number of triangles`);
    const neighbors = typed(triangulation.neighbors ?? [], Int32Array, `${where}: neighbors`);
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
    };
    return call(put(points), points.length / 3, heap);
  } finally {
    for (const address of blocks) core._free(address);
  }
}

function flag(options, name, where) {
  const value = options[name] ?? false;
  if (typeof value !== 'boolean') throw new HullkitError(`${where}: ${name} must be true or false, got ${String(value)}`);
  return value;
}

/**
 * Locates each query point (x y z per query) in the tetrahedralization of `xyz` (see hullkit.d.ts).
 * @param core the loaded WebAssembly module
 */
export function locate3(core, xyz, triangulation, queries, options = {}) {
  const where = 'locate3';
  const points = points3(xyz, where);
  const at = points3(queries, `${where}: queries`);
  const checked = checkOptions(options, LOCATE_OPTIONS, where);
  const barycentric = flag(checked, 'barycentric', where);
  const nearest = flag(checked, 'nearest', where);
  const t = checkTetrahedralization(triangulation, points.length / 3, where);
  const result = withTetrahedralizationInHeap(core, points, t, where, (address, count, heap) => {
    const q = copyIn(core, at, where);
    try {
      return core.delaunay3LocateFromHeap(address, count, heap, q, at.length / 3, barycentric, nearest);
    } finally {
      core._free(q);
    }
  });
  try {
    if (result.error) throw new HullkitError(`${where}: ${result.error}`, { queryIndex: result.errorQuery() });
    const out = { tetrahedron: result.tetrahedronView().slice() };
    if (barycentric) out.barycentric = result.barycentricView().slice();
    if (nearest) out.nearest = result.nearestView().slice();
    return out;
  } finally {
    result.delete();
  }
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
