// hullkit.delaunay, find and voronoi: the JS side of native/include/hullkit/delaunay.hpp.
// Points go in as a Float64Array x0 y0 x1 y1 ...; every result array is a fresh typed array the
// caller owns (copied out of the WebAssembly heap), laid out as delaunator's.
import { HullkitError, checkOptions, copyIn, takeTrace, toFloat64, toUint32 } from './internal.js';

/** The algorithm names `delaunay` accepts, the default first. */
export const DELAUNAY_ALGORITHMS = ['incremental', 'giftwrap'];
const DELAUNAY_OPTIONS = ['algorithm', 'mergeCocircular'];

/**
 * The Delaunay triangulation of `xy` (see hullkit.d.ts for the result).
 * @param core the loaded WebAssembly module
 */
export function delaunay(core, xy, options = {}) {
  const points = toFloat64(xy, 'delaunay', 2);
  const { algorithm = DELAUNAY_ALGORITHMS[0], mergeCocircular = false } = checkOptions(options, DELAUNAY_OPTIONS, 'delaunay');
  if (!DELAUNAY_ALGORITHMS.includes(algorithm)) {
    throw new HullkitError(`delaunay: unknown algorithm "${algorithm}" (known: ${DELAUNAY_ALGORITHMS.join(', ')})`);
  }
  if (typeof mergeCocircular !== 'boolean') {
    throw new HullkitError(`delaunay: mergeCocircular must be true or false, got ${String(mergeCocircular)}`);
  }
  const address = copyIn(core, points, 'delaunay');
  let result;
  try {
    result = core.delaunayFromHeap(address, points.length / 2, algorithm, mergeCocircular);
  } finally {
    core._free(address);
  }
  try {
    if (!result.ok()) throw new HullkitError(`delaunay: ${result.error}`, { pointIndex: result.errorPoint() });
    const out = {
      dimension: result.dimension,
      triangles: result.trianglesView().slice(),
      halfedges: result.halfedgesView().slice(),
      hull: result.hullView().slice(),
      representative: result.representativeView().slice(),
      duplicateCount: result.duplicateCount(),
    };
    if (mergeCocircular) {
      out.polygonOffsets = result.polygonOffsetsView().slice();
      out.polygonVertices = result.polygonVerticesView().slice();
    }
    return out;
  } finally {
    result.delete();
  }
}

/**
 * Checks a triangulation a caller hands back (from `delaunay`, possibly edited or rebuilt) against
 * `count` points, so that no index sends the C++ walk outside its arrays. O(n); returns the arrays
 * as typed arrays.
 */
function checkTriangulation(triangulation, count, where) {
  if (triangulation === null || typeof triangulation !== 'object') {
    throw new TypeError(`${where}: the triangulation must be the object delaunay() returned`);
  }
  const triangles = toUint32(triangulation.triangles ?? [], `${where}: triangles`);
  const hull = toUint32(triangulation.hull ?? [], `${where}: hull`);
  let halfedges = triangulation.halfedges ?? [];
  if (!(halfedges instanceof Int32Array)) {
    if (typeof halfedges.length !== 'number') throw new TypeError(`${where}: halfedges must be an Int32Array`);
    halfedges = Int32Array.from(halfedges);
  }
  if (triangles.length % 3 !== 0) {
    throw new HullkitError(`${where}: ${triangles.length} triangle indices is not a whole number of triangles`);
  }
  if (halfedges.length !== triangles.length) {
    throw new HullkitError(`${where}: ${halfedges.length} halfedges for ${triangles.length} triangle indices`);
  }
  for (let i = 0; i < triangles.length; i++) {
    if (triangles[i] >= count) throw new HullkitError(`${where}: triangles[${i}] = ${triangles[i]} but there are ${count} points`);
    const h = halfedges[i];
    if (h < -1 || h >= halfedges.length) throw new HullkitError(`${where}: halfedges[${i}] = ${h} is out of range`);
  }
  for (let i = 0; i < hull.length; i++) {
    if (hull[i] >= count) throw new HullkitError(`${where}: hull[${i}] = ${hull[i]} but there are ${count} points`);
  }
  let representative;
  if (triangulation.representative === undefined) {
    // A delaunator-style object: no duplicates known, every point stands for itself.
    representative = new Uint32Array(count);
    for (let i = 0; i < count; i++) representative[i] = i;
  } else {
    representative = toUint32(triangulation.representative, `${where}: representative`);
    if (representative.length !== count) {
      throw new HullkitError(`${where}: representative has ${representative.length} entries for ${count} points`);
    }
    for (let i = 0; i < count; i++) {
      if (representative[i] > i) throw new HullkitError(`${where}: representative[${i}] = ${representative[i]} is not a lower index`);
    }
  }
  const dimension = triangulation.dimension ?? (triangles.length ? 2 : 1);
  if (![2, 1, 0, -1].includes(dimension)) throw new HullkitError(`${where}: dimension ${dimension} is not one of 2, 1, 0, -1`);
  return { dimension, triangles, halfedges, hull, representative };
}

/**
 * With `points` a Float64Array from toFloat64, runs `call(pointsAddress, count, dimension, trianglesAddress, corners, halfedgesAddress,
 * hullAddress, hullCount, representativeAddress)` with everything copied into the heap, freeing
 * it all afterwards.
 */
function withTriangulationInHeap(core, points, triangulation, where, call) {
  const count = points.length / 2;
  const t = checkTriangulation(triangulation, count, where);
  const addresses = [];
  try {
    for (const array of [points, t.triangles, t.halfedges, t.hull, t.representative]) addresses.push(copyIn(core, array, where));
    const [p, triangles, halfedges, hull, representative] = addresses;
    return call(p, count, t.dimension, triangles, t.triangles.length, halfedges, hull, t.hull.length, representative);
  } finally {
    for (const address of addresses) core._free(address);
  }
}

function checkFinite(value, name, where) {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new HullkitError(`${where}: ${name} must be a finite number, got ${String(value)}`);
  }
}

/** The index of the input point nearest to (x, y), or -1 without points (see hullkit.d.ts). */
export function delaunayFind(core, xy, triangulation, x, y, start = 0) {
  checkFinite(x, 'x', 'find');
  checkFinite(y, 'y', 'find');
  const points = toFloat64(xy, 'find', 2);
  const count = points.length / 2;
  if (!Number.isInteger(start) || start < 0 || (count > 0 && start >= count)) {
    throw new HullkitError(`find: start must be a point index from 0 to ${count - 1}, got ${String(start)}`);
  }
  return withTriangulationInHeap(core, points, triangulation, 'find', (...heap) => core.delaunayFindFromHeap(...heap, x, y, start));
}

/** Voronoi cells clipped to bounds [xmin, ymin, xmax, ymax] (see hullkit.d.ts). */
export function delaunayVoronoi(core, xy, triangulation, bounds) {
  if (bounds == null || typeof bounds.length !== 'number' || bounds.length !== 4) {
    throw new TypeError('voronoi: bounds must be [xmin, ymin, xmax, ymax]');
  }
  const [xmin, ymin, xmax, ymax] = Array.from(bounds);
  ['xmin', 'ymin', 'xmax', 'ymax'].forEach((name, i) => checkFinite(bounds[i], `bounds ${name}`, 'voronoi'));
  if (!(xmin < xmax && ymin < ymax)) {
    throw new HullkitError(`voronoi: bounds [${xmin}, ${ymin}, ${xmax}, ${ymax}] are empty (need xmin < xmax and ymin < ymax)`);
  }
  const cells = withTriangulationInHeap(core, toFloat64(xy, 'voronoi', 2), triangulation, 'voronoi', (...heap) =>
    core.delaunayVoronoiFromHeap(...heap, xmin, ymin, xmax, ymax));
  try {
    return { cellOffsets: cells.cellOffsetsView().slice(), cellXY: cells.cellXYView().slice() };
  } finally {
    cells.delete();
  }
}

/** delaunayGiftwrapTrace refuses more points than this (the wrap is O(n²)). */
export const DELAUNAY_TRACE_MAX_POINTS = 2000;

/**
 * The recorded gift wrap on the lifted points (see hullkit.d.ts): events with input indices, the
 * event names, and delaunay(xy)'s triangles.
 * @param core the loaded WebAssembly module
 */
export function delaunayGiftwrapTrace(core, xy) {
  const points = toFloat64(xy, 'delaunayGiftwrapTrace', 2);
  const count = points.length / 2;
  if (count > DELAUNAY_TRACE_MAX_POINTS) {
    throw new HullkitError(`delaunayGiftwrapTrace: ${count} points is too many to trace (at most ${DELAUNAY_TRACE_MAX_POINTS}); ` +
      'use delaunay(xy, {algorithm: "giftwrap"}) for the triangulation alone');
  }
  const address = copyIn(core, points, 'delaunayGiftwrapTrace');
  let trace;
  try {
    trace = core.delaunayGiftwrapTraceFromHeap(address, count);
  } finally {
    core._free(address);
  }
  return takeTrace(trace, core.giftwrapEventNames(), 'delaunayGiftwrapTrace');
}
