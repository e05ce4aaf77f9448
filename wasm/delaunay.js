// hullkit.delaunay, find, locate, voronoi and voronoiDiagram: the JS side of native/include/hullkit/delaunay.hpp.
// Points go in as a Float64Array x0 y0 x1 y1 ...; every result array is a fresh typed array the
// caller owns (copied out of the WebAssembly heap), laid out as delaunator's. The queries take the
// triangulation back: its arrays are checked and copied into the heap, and the core answers from
// them (nothing is triangulated again).
import {
  HullkitError, checkCorners, checkOptions, checkRepresentative, copyIn, flatCoordinates, locateInHeap, locateOptions, takeTrace, toFloat64,
  toInt32, toUint32,
} from './internal.js';

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
 * Checks a triangulation a caller hands back (from `delaunay`, possibly edited or rebuilt, or a
 * delaunator object) against `count` points, so that no index sends the C++ walks outside their
 * arrays or round a ring of triangles forever: indices in range, duplicates never used, three
 * distinct corners per triangle, and each half-edge paired with its reverse. O(n); returns the
 * arrays as typed arrays. The geometry is not checked: answers for a triangulation of other points
 * are meaningless.
 */
function checkTriangulation(triangulation, count, where) {
  if (triangulation === null || typeof triangulation !== 'object' || ArrayBuffer.isView(triangulation)) {
    throw new TypeError(`${where}: the triangulation must be the object delaunay() returned`);
  }
  let representative;
  if (triangulation.representative === undefined) {
    // A delaunator-style object: no duplicates known, every point stands for itself.
    representative = new Uint32Array(count);
    for (let i = 0; i < count; i++) representative[i] = i;
  } else {
    representative = checkRepresentative(triangulation.representative, count, where);
  }
  const triangles = checkCorners(toUint32(triangulation.triangles ?? [], `${where}: triangles`), representative, 'triangles', where);
  const hull = checkCorners(toUint32(triangulation.hull ?? [], `${where}: hull`), representative, 'hull', where);
  const halfedges = toInt32(triangulation.halfedges ?? [], `${where}: halfedges`);
  if (triangles.length % 3 !== 0) {
    throw new HullkitError(`${where}: ${triangles.length} triangle indices is not a whole number of triangles`);
  }
  if (halfedges.length !== triangles.length) {
    throw new HullkitError(`${where}: ${halfedges.length} halfedges for ${triangles.length} triangle indices`);
  }
  checkHalfedges(triangles, halfedges, where);
  const dimension = triangulation.dimension ?? (triangles.length ? 2 : 1);
  if (![2, 1, 0, -1].includes(dimension)) throw new HullkitError(`${where}: dimension ${dimension} is not one of 2, 1, 0, -1`);
  return { dimension, triangles, halfedges, hull, representative };
}

const next = (e) => (e % 3 === 2 ? e - 2 : e + 1);

/** Each triangle has three distinct corners; each half-edge's opposite runs the same edge back and names it in return. */
function checkHalfedges(triangles, halfedges, where) {
  for (let e = 0; e < triangles.length; e += 3) {
    const a = triangles[e], b = triangles[e + 1], c = triangles[e + 2];
    if (a === b || b === c || a === c) throw new HullkitError(`${where}: triangle ${e / 3} (${a} ${b} ${c}) repeats a corner`);
  }
  for (let e = 0; e < halfedges.length; e++) {
    const h = halfedges[e];
    if (h === -1) continue;
    if (h < -1 || h >= halfedges.length || h === e) throw new HullkitError(`${where}: halfedges[${e}] = ${h} is out of range`);
    if (halfedges[h] !== e || triangles[h] !== triangles[next(e)] || triangles[next(h)] !== triangles[e]) {
      throw new HullkitError(`${where}: halfedges[${e}] = ${h}, but half-edges ${e} (${triangles[e]} → ${triangles[next(e)]}) and ${h} ` +
        'are not one edge run both ways, each naming the other');
    }
  }
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

/**
 * Locates each query point (x y per query) in the triangulation of `xy` (see hullkit.d.ts):
 * locate3's counterpart in the plane.
 * @param core the loaded WebAssembly module
 */
export function delaunayLocate(core, xy, triangulation, queries, options = {}) {
  const where = 'locate';
  const points = toFloat64(xy, where, 2);
  const at = flatCoordinates(queries, where, 2, 'queries');
  const flags = locateOptions(options, where);
  return locateInHeap(core, { where, cell: 'triangle', dimension: 2, queries: at, flags },
    (run) => withTriangulationInHeap(core, points, triangulation, where, run), (...args) => core.delaunayLocateFromHeap(...args));
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

/** The whole Voronoi diagram, unclipped, in scipy's layout (see hullkit.d.ts). */
export function delaunayVoronoiDiagram(core, xy, triangulation) {
  const where = 'voronoiDiagram';
  const diagram = withTriangulationInHeap(core, toFloat64(xy, where, 2), triangulation, where, (...heap) =>
    core.delaunayVoronoiDiagramFromHeap(...heap));
  try {
    if (!diagram.ok()) throw new HullkitError(`${where}: ${diagram.error()}`);
    return {
      vertices: diagram.verticesView().slice(),
      triangleVertex: diagram.triangleVertexView().slice(),
      ridgePoints: diagram.ridgePointsView().slice(),
      ridgeVertices: diagram.ridgeVerticesView().slice(),
      cells: diagram.cellsView().slice(),
      cellOffsets: diagram.cellOffsetsView().slice(),
      cellPoint: diagram.cellPointView().slice(),
      pointCell: diagram.pointCellView().slice(),
      areas: diagram.areasView().slice(),
    };
  } finally {
    diagram.delete();
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
