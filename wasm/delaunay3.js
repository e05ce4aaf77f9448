// hullkit.delaunay3 and verifyDelaunay3: the JS side of native/include/hullkit/delaunay3.hpp.
// Points go in as a Float64Array x0 y0 z0 x1 y1 z1 ...; every result array is a fresh typed array
// the caller owns (copied out of the WebAssembly heap after the call).
import { HullkitError, checkOptions, copyIn, toFloat64, toUint32 } from './internal.js';

const DELAUNAY3_OPTIONS = ['progress'];
const VERIFY_OPTIONS = ['perturbed'];

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
