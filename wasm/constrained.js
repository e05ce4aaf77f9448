// hullkit.triangulatePolygon and hullkit.constrainedDelaunay: the JS side of
// native/include/hullkit/constrained.hpp. triangulatePolygon takes earcut's arguments (flat
// coordinates, the vertex index where each hole starts, `dim`) or a GeoJSON Polygon/MultiPolygon;
// constrainedDelaunay takes points and index pairs. Results are fresh typed arrays laid out as
// delaunator's (clockwise triangles with y up, halfedges), plus a flag per half-edge on a segment.
import { HullkitError, checkOptions, copyIn, flatCoordinates, toUint32 } from './internal.js';

/** The fill rules triangulatePolygon accepts, the default first. */
export const FILL_RULES = ['evenodd', 'nonzero'];
const QUALITY_OPTIONS = ['minAngle', 'maxArea', 'conforming', 'maxSteinerPoints', 'keepSegments', 'unsuitable'];
const KEEP_SEGMENTS = { none: 0, boundary: 1, all: 2 };
const POLYGON_OPTIONS = ['dim', 'fill', ...QUALITY_OPTIONS];
const GRAPH_OPTIONS = ['holes', 'removeExterior', ...QUALITY_OPTIONS];
const MESH_OPTIONS = ['edges', 'triangleMaxArea', ...QUALITY_OPTIONS];

/** The refinement options checked (the core checks the ranges again and names them). */
function qualityOf(options, where) {
  const { minAngle = 0, maxArea = 0, conforming = false, maxSteinerPoints = 0, keepSegments = 'none' } = options;
  if (typeof minAngle !== 'number' || !(minAngle >= 0 && minAngle <= 34)) {
    throw new HullkitError(`${where}: minAngle must be a number of degrees from 0 to 34, got ${String(minAngle)}`);
  }
  if (typeof maxArea !== 'number' || !(maxArea >= 0 && Number.isFinite(maxArea))) {
    throw new HullkitError(`${where}: maxArea must be a positive number (0 or absent: none), got ${String(maxArea)}`);
  }
  if (typeof conforming !== 'boolean') throw new HullkitError(`${where}: conforming must be true or false, got ${String(conforming)}`);
  if (!Number.isSafeInteger(maxSteinerPoints) || maxSteinerPoints < 0) {
    throw new HullkitError(`${where}: maxSteinerPoints must be a whole number (0: no cap), got ${String(maxSteinerPoints)}`);
  }
  if (!Object.hasOwn(KEEP_SEGMENTS, keepSegments)) {
    throw new HullkitError(`${where}: keepSegments must be 'none', 'boundary' or 'all', got ${String(keepSegments)}`);
  }
  const test = userTest(options.unsuitable, where);
  return { args: [minAngle, maxArea, conforming, maxSteinerPoints, KEEP_SEGMENTS[keepSegments], test.call], test };
}

/**
 * Triangle's -u: the caller's `unsuitable([ax, ay], [bx, by], [cx, cy], area)` as the core calls
 * it (seven numbers). What it throws, or an answer that is not a boolean, is kept in `error` (the
 * later calls answer false at once) and thrown once the core has returned: an exception must not
 * unwind through the WebAssembly frames.
 */
function userTest(unsuitable, where) {
  const test = { call: null, error: null };
  if (unsuitable === undefined || unsuitable === null) return test;
  if (typeof unsuitable !== 'function') {
    throw new HullkitError(`${where}: unsuitable must be a function ([ax, ay], [bx, by], [cx, cy], area) => boolean, got ${typeof unsuitable}`);
  }
  test.call = (ax, ay, bx, by, cx, cy, area) => {
    if (test.error !== null) return false;
    try {
      const answer = unsuitable([ax, ay], [bx, by], [cx, cy], area);
      if (typeof answer !== 'boolean') throw new HullkitError(`${where}: unsuitable must return true or false, got ${String(answer)}`);
      return answer;
    } catch (error) {
      test.error = error;
      return false;
    }
  };
  return test;
}

/**
 * Copies the core's result out (or throws its error naming the point or segment, or what the
 * caller's unsuitable test threw) and frees it.
 */
function takeResult(result, where, test, extra = () => ({})) {
  try {
    if (test.error !== null) throw test.error;
    if (!result.ok()) {
      const error = new HullkitError(`${where}: ${result.error}`, { pointIndex: result.errorPoint() });
      const segment = result.errorSegment();
      if (segment >= 0) error.segmentIndex = segment;
      const triangle = result.errorTriangle();
      if (triangle >= 0) error.triangleIndex = triangle;
      throw error;
    }
    const coords = result.coordsView().slice();
    const representative = result.representativeView().slice();
    return {
      dimension: result.dimension,
      triangles: result.trianglesView().slice(),
      halfedges: result.halfedgesView().slice(),
      constrained: result.constrainedView().slice(),
      coords,
      inputCount: representative.length,
      addedCount: coords.length / 2 - representative.length,
      representative,
      duplicateCount: result.duplicateCount(),
      crossingCount: result.crossingCount(),
      steinerCount: result.steinerCount(),
      unrefinedCount: result.unrefinedCount(),
      ...extra(result),
    };
  } finally {
    result.delete();
  }
}

/** Flat index tuples (pairs, triples) as a Uint32Array; `what` names them in the errors. */
function indexTuples(values, arity, what, where) {
  const flat = toUint32(values ?? [], `${where}: ${what}`);
  if (flat.length % arity !== 0) {
    throw new HullkitError(`${where}: ${flat.length} ${what.replace(/s$/, '')} indices is not a whole number of ${arity === 2 ? 'pairs' : 'triples'}`);
  }
  return flat;
}

/** Runs `call(addresses...)` with each typed array copied into the heap, freeing them afterwards. */
function withHeap(core, arrays, where, call) {
  const addresses = [];
  try {
    for (const array of arrays) addresses.push(copyIn(core, array, where));
    return call(...addresses);
  } finally {
    for (const address of addresses) core._free(address);
  }
}

/** A GeoJSON Polygon, MultiPolygon or a Feature holding one, as flat x y coordinates and ring starts. */
function fromGeoJSON(value, where) {
  const geometry = value.type === 'Feature' ? value.geometry : value;
  if (geometry === null || typeof geometry !== 'object') throw new HullkitError(`${where}: the Feature has no geometry`);
  let polygons;
  if (geometry.type === 'Polygon') polygons = [geometry.coordinates];
  else if (geometry.type === 'MultiPolygon') polygons = geometry.coordinates;
  else throw new HullkitError(`${where}: GeoJSON ${String(geometry.type)} is not a Polygon or MultiPolygon`);
  if (!Array.isArray(polygons)) throw new HullkitError(`${where}: GeoJSON coordinates must be an array`);
  const xy = [];
  const starts = [];
  polygons.forEach((rings, p) => {
    if (!Array.isArray(rings)) throw new HullkitError(`${where}: polygon ${p} is not an array of rings`);
    rings.forEach((ring, r) => {
      if (!Array.isArray(ring)) throw new HullkitError(`${where}: polygon ${p} ring ${r} is not an array of positions`);
      if (xy.length > 0) starts.push(xy.length / 2);
      ring.forEach((position, i) => {
        if (!Array.isArray(position) || position.length < 2 || typeof position[0] !== 'number' || typeof position[1] !== 'number') {
          throw new HullkitError(`${where}: polygon ${p} ring ${r} position ${i} is not [x, y]`);
        }
        xy.push(position[0], position[1]);
      });
    });
  });
  return { xy: Float64Array.from(xy), starts: Uint32Array.from(starts) };
}

/**
 * The triangles inside polygons with holes (see hullkit.d.ts).
 * @param core the loaded WebAssembly module
 */
export function triangulatePolygon(core, coords, holeIndices, options = {}) {
  const where = 'triangulatePolygon';
  const checked = checkOptions(options, POLYGON_OPTIONS, where);
  const { dim = 2, fill = FILL_RULES[0] } = checked;
  const quality = qualityOf(checked, where);
  if (!FILL_RULES.includes(fill)) throw new HullkitError(`${where}: unknown fill "${fill}" (known: ${FILL_RULES.join(', ')})`);
  if (!Number.isInteger(dim) || dim < 2) throw new HullkitError(`${where}: dim must be an integer of at least 2, got ${String(dim)}`);
  let xy;
  let starts;
  if (coords !== null && typeof coords === 'object' && !Array.isArray(coords) && !ArrayBuffer.isView(coords) && 'type' in coords) {
    if (holeIndices != null && holeIndices.length > 0) {
      throw new HullkitError(`${where}: pass holeIndices with flat coordinates, not with GeoJSON (its rings say where holes start)`);
    }
    ({ xy, starts } = fromGeoJSON(coords, where));
  } else {
    const flat = flatCoordinates(coords, where, dim);
    xy = flat;
    if (dim !== 2) {
      xy = new Float64Array((flat.length / dim) * 2);
      for (let i = 0, j = 0; i < flat.length; i += dim, j += 2) {
        xy[j] = flat[i];
        xy[j + 1] = flat[i + 1];
      }
    }
    starts = toUint32(holeIndices ?? [], `${where}: holeIndices`);
  }
  const count = xy.length / 2;
  for (let k = 0; k < starts.length; k++) {
    if (starts[k] > count || (k > 0 && starts[k] < starts[k - 1])) {
      throw new HullkitError(`${where}: holeIndices[${k}] = ${starts[k]} is ${starts[k] > count ? `past the ${count} vertices` : 'before the hole before it'}`);
    }
  }
  return takeResult(
    withHeap(core, [xy, starts], where, (p, s) => core.triangulatePolygonFromHeap(p, count, s, starts.length, fill, ...quality.args)),
    where, quality.test);
}

/**
 * The constrained Delaunay triangulation of points and segments (see hullkit.d.ts).
 * @param core the loaded WebAssembly module
 */
export function constrainedDelaunay(core, coords, edges, options = {}) {
  const where = 'constrainedDelaunay';
  const checked = checkOptions(options, GRAPH_OPTIONS, where);
  const quality = qualityOf(checked, where);
  const { removeExterior = false } = checked;
  if (typeof removeExterior !== 'boolean') throw new HullkitError(`${where}: removeExterior must be true or false, got ${String(removeExterior)}`);
  const holes = checked.holes === undefined ? new Float64Array(0) : flatCoordinates(checked.holes, `${where}: holes`, 2);
  const xy = flatCoordinates(coords, where, 2);
  const segments = indexTuples(edges, 2, 'edges', where);
  const count = xy.length / 2;
  return takeResult(
    withHeap(core, [xy, segments, holes], where, (p, s, h) =>
      core.constrainedDelaunayFromHeap(p, count, s, segments.length / 2, h, holes.length / 2, removeExterior, ...quality.args),
    ),
    where,
    quality.test,
  );
}

/**
 * Triangle's -r: a triangulation refined (see hullkit.d.ts).
 * @param core the loaded WebAssembly module
 */
export function refineMesh(core, coords, triangles, options = {}) {
  const where = 'refineMesh';
  const checked = checkOptions(options, MESH_OPTIONS, where);
  const quality = qualityOf(checked, where);
  const xy = flatCoordinates(coords, where, 2);
  const corners = indexTuples(triangles, 3, 'triangles', where);
  const segments = indexTuples(checked.edges, 2, 'edges', where);
  const perTriangle = checked.triangleMaxArea !== undefined;
  let areas = new Float64Array(0);
  if (perTriangle) {
    if (checked.triangleMaxArea === null || typeof checked.triangleMaxArea !== 'object' || typeof checked.triangleMaxArea.length !== 'number') {
      throw new HullkitError(`${where}: triangleMaxArea must be an array of numbers, one per triangle`);
    }
    areas = Float64Array.from(checked.triangleMaxArea);
    if (areas.length !== corners.length / 3) {
      throw new HullkitError(`${where}: triangleMaxArea holds ${areas.length} numbers for ${corners.length / 3} triangles`);
    }
  }
  const count = xy.length / 2;
  return takeResult(
    withHeap(core, [xy, corners, segments, areas], where, (p, t, s, a) =>
      core.refineMeshFromHeap(p, count, t, corners.length / 3, s, segments.length / 2, perTriangle ? a : 0, ...quality.args),
    ),
    where,
    quality.test,
    (result) => (perTriangle ? { sourceTriangle: result.triangleRegionView().slice() } : {}),
  );
}
