// hullkit.hullNd, delaunayNd and locateNd: the JS side of native/include/hullkit/hull_nd.hpp, hulls
// and Delaunay triangulations in any dimension (hulls 2 to 10, triangulations 1 to 9), exact. Points
// go in flat (a Float64Array or an array of numbers, `dimension` coordinates per point) or as an
// array of points (arrays of `dimension` numbers); every result array is a fresh typed array the
// caller owns (copied out of the WebAssembly heap after the call).
import { HullkitError, checkOptions, copyIn, toFloat64, toInt32, toUint32 } from './internal.js';

const DELAUNAY_ND_OPTIONS = ['furthestSite'];

/** The points as a Float64Array of `dimension` coordinates each (toFloat64), or an error naming the problem. */
function pointsNd(values, dimension, where, what = 'points') {
  if (!Number.isInteger(dimension) || dimension < 1) {
    throw new HullkitError(`${where}: dimension must be a positive integer, got ${String(dimension)}`);
  }
  const flat = toFloat64(values, what === 'queries' ? `${where}: queries` : where, dimension);
  if (flat.length / dimension > 0x7fffffff) throw new HullkitError(`${where}: too many ${what}, at most 2147483647`);
  return flat;
}

/**
 * Copies `flat` into the heap, calls `call(address)` for a core result, frees the block, and returns
 * `read(result)` (or throws the result's error) before deleting the result.
 */
function onHeap(core, flat, where, call, read) {
  const address = copyIn(core, flat, where);
  let result;
  try {
    result = call(address);
  } finally {
    core._free(address);
  }
  try {
    if (!result.ok()) throw new HullkitError(`${where}: ${result.error}`, { pointIndex: result.errorPoint() });
    return read(result);
  } finally {
    result.delete();
  }
}

/** The convex hull of points in `dimension` (2 to 10) dimensions (see hullkit.d.ts). */
export function hullNd(core, points, dimension) {
  const flat = pointsNd(points, dimension, 'hullNd');
  return onHeap(core, flat, 'hullNd', (address) => core.hullNdFromHeap(address, flat.length / dimension, dimension), (result) => ({
    dimension,
    facets: result.facetsView().slice(),
    neighbors: result.neighborsView().slice(),
    vertices: result.verticesView().slice(),
    group: result.groupView().slice(),
  }));
}

/** The Delaunay triangulation of points in `dimension` (1 to 9) dimensions (see hullkit.d.ts). */
export function delaunayNd(core, points, dimension, options = {}) {
  const flat = pointsNd(points, dimension, 'delaunayNd');
  const checked = checkOptions(options, DELAUNAY_ND_OPTIONS, 'delaunayNd');
  const furthestSite = checked.furthestSite ?? false;
  if (typeof furthestSite !== 'boolean') throw new HullkitError(`delaunayNd: furthestSite must be true or false, got ${String(furthestSite)}`);
  const count = flat.length / dimension;
  return onHeap(core, flat, 'delaunayNd', (address) => core.delaunayNdFromHeap(address, count, dimension, furthestSite), (result) => ({
    dimension,
    simplices: result.simplicesView().slice(),
    neighbors: result.neighborsView().slice(),
    group: result.groupView().slice(),
    representative: result.representativeView().slice(),
    duplicateCount: result.duplicateCount(),
    furthestSite,
  }));
}

/** The simplex of `triangulation` (delaunayNd's result for `points`) holding each query, -1 outside. */
export function locateNd(core, points, triangulation, queries) {
  if (triangulation === null || typeof triangulation !== 'object' || !('simplices' in triangulation)) {
    throw new TypeError('locateNd: triangulation must be the object delaunayNd returned');
  }
  const { dimension } = triangulation;
  const flat = pointsNd(points, dimension, 'locateNd');
  const q = pointsNd(queries, dimension, 'locateNd', 'queries');
  const simplices = toUint32(triangulation.simplices, 'locateNd: triangulation.simplices');
  const neighbors = toInt32(triangulation.neighbors, 'locateNd: triangulation.neighbors');
  const representative = toUint32(triangulation.representative, 'locateNd: triangulation.representative');
  const count = flat.length / dimension;
  const corners = dimension + 1;
  if (simplices.length % corners !== 0 || neighbors.length !== simplices.length || representative.length !== count) {
    throw new HullkitError(`locateNd: the triangulation does not fit these points (${simplices.length} corners, ` +
      `${neighbors.length} neighbours, ${representative.length} representatives for ${count} points in ${dimension}D)`);
  }
  const blocks = [];
  try {
    for (const [array, name] of [[flat, 'points'], [simplices, 'simplices'], [neighbors, 'neighbors'], [representative, 'representative'], [q, 'queries']]) {
      blocks.push(copyIn(core, array, `locateNd: ${name}`));
    }
    const [pointsAt, simplicesAt, neighborsAt, representativeAt, queriesAt] = blocks;
    const found = core.locateNdFromHeap(pointsAt, count, dimension, simplicesAt, simplices.length / corners, neighborsAt,
      representativeAt, queriesAt, q.length / dimension);
    if (typeof found === 'string') throw new HullkitError(`locateNd: ${found}`);
    return found;
  } finally {
    for (const address of blocks) core._free(address);
  }
}
