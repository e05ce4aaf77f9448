// hullkit for JavaScript: the WebAssembly build of the C++ core behind plain functions that take
// typed arrays and return typed arrays the caller owns. Runs in Node (>= 20), browsers and workers.
import createHullkitCore from '../build/wasm/hullkit_core.mjs';
import { HullkitError, bytesOf, checkOptions, copyIn, isBytes, takeTrace, toFloat64, toUint32 } from './internal.js';
import { delaunay, delaunayFind, delaunayLocate, delaunayVoronoi, delaunayVoronoiDiagram, delaunayGiftwrapTrace, DELAUNAY_ALGORITHMS, DELAUNAY_TRACE_MAX_POINTS } from './delaunay.js';
import { delaunay3, verifyDelaunay3, locate3, voronoi3 } from './delaunay3.js';
import { constrainedDelaunay, refineMesh, triangulatePolygon, FILL_RULES } from './constrained.js';
import { checkRoute, RouteChecker } from './route.js';
import { delaunayNd, hullNd, locateNd } from './nd.js';

export { HullkitError };

const ALGORITHMS = ['quickhull', 'giftwrap'];
const EPSILONS = ['exact', 'seed'];
const HULL_OPTIONS = ['algorithm', 'epsilon', 'mergeCoplanar', 'equations'];
const SCANS = ['single-pass', 'restart'];
/** giftwrapTrace refuses more points than this (single pass) / TRACE_MAX_RESTART (restart scan). */
const TRACE_MAX_POINTS = 5000;
const TRACE_MAX_RESTART = 1000;

const isNode = typeof process === 'object' && typeof process.versions?.node === 'string';

/**
 * Loads the WebAssembly module once and resolves to the hullkit API.
 * @returns {Promise<import('./hullkit.d.ts').Hullkit>}
 */
export default async function createHullkit() {
  const moduleOptions = {};
  if (isNode) {
    // Emscripten's web build would fetch() a file path under Node: hand it the bytes instead.
    const { readFile } = await import('node:fs/promises');
    moduleOptions.wasmBinary = await readFile(new URL('../build/wasm/hullkit_core.wasm', import.meta.url));
  }
  const core = await createHullkitCore(moduleOptions);
  await warmUp(core);
  return Object.freeze({
    hull: (xyz, options) => hull(core, xyz, options),
    verify: (xyz, result) => verify(core, xyz, result),
    giftwrapTrace: (xyz, options) => giftwrapTrace(core, xyz, options),
    readPoints: (bytes, name) => readPoints(core, bytes, name),
    readPoints2d: (bytes, name) => readPoints2d(core, bytes, name),
    readMesh: (bytes, name) => readMesh(core, bytes, name),
    writeGlb: (xyz, result) => writeGlb(core, xyz, result),
    delaunay: (xy, options) => delaunay(core, xy, options),
    find: (xy, triangulation, x, y, start) => delaunayFind(core, xy, triangulation, x, y, start),
    locate: (xy, triangulation, queries, options) => delaunayLocate(core, xy, triangulation, queries, options),
    voronoi: (xy, triangulation, bounds) => delaunayVoronoi(core, xy, triangulation, bounds),
    voronoiDiagram: (xy, triangulation) => delaunayVoronoiDiagram(core, xy, triangulation),
    delaunayGiftwrapTrace: (xy) => delaunayGiftwrapTrace(core, xy),
    triangulatePolygon: (coords, holeIndices, options) => triangulatePolygon(core, coords, holeIndices, options),
    constrainedDelaunay: (coords, edges, options) => constrainedDelaunay(core, coords, edges, options),
    refineMesh: (coords, triangles, options) => refineMesh(core, coords, triangles, options),
    delaunay3: (xyz, options) => delaunay3(core, xyz, options),
    verifyDelaunay3: (xyz, tetrahedra, options) => verifyDelaunay3(core, xyz, tetrahedra, options),
    locate3: (xyz, triangulation, queries, options) => locate3(core, xyz, triangulation, queries, options),
    voronoi3: (xyz, triangulation) => voronoi3(core, xyz, triangulation),
    hullNd: (points, dimension) => hullNd(core, points, dimension),
    delaunayNd: (points, dimension, options) => delaunayNd(core, points, dimension, options),
    locateNd: (points, triangulation, queries) => locateNd(core, points, triangulation, queries),
    checkRoute: (scene, options) => checkRoute(core, scene, options),
    RouteChecker: class extends RouteChecker {
      constructor(scene, options) {
        super(core, scene, options);
      }
    },
    algorithms: Object.freeze([...ALGORITHMS]),
    traceLimits: Object.freeze({ 'single-pass': TRACE_MAX_POINTS, restart: TRACE_MAX_RESTART, delaunay: DELAUNAY_TRACE_MAX_POINTS }),
    delaunayAlgorithms: Object.freeze([...DELAUNAY_ALGORITHMS]),
    fillRules: Object.freeze([...FILL_RULES]),
  });
}

/**
 * Runs a few small hulls and triangulations before the caller's first call. V8 first runs
 * WebAssembly in its baseline tier and compiles a function with the optimising tier only once it
 * has run a while, in the background, for its next call; a user's single big hull() or delaunay()
 * would otherwise run entirely in the baseline tier (about 1.5 to 2 times as slow). The inputs take
 * every hot path: 10,000 points in a cube (interior culling, repeats), 10,000 on a sphere (every
 * point a vertex; over 4,096 candidates take the Morton-order path as large inputs do), 4,000
 * points in a square for Delaunay and a ring of 2,000 vertices with a hole for triangulatePolygon. About 100-200 ms of loading time; the results are discarded. The
 * points are deterministic (a fixed generator); only the number of rounds depends on timing.
 */
async function warmUp(core) {
  const cubeCount = 10000;
  const sphereCount = 10000;
  const xyz = new Float64Array(3 * (cubeCount + sphereCount));
  let state = 12345;
  const next = () => (state = (state * 16807) % 2147483647) / 2147483647 - 0.5;
  for (let i = 0; i < cubeCount + sphereCount; i++) {
    const x = next();
    const y = next();
    const z = next();
    const scale = i < cubeCount ? 1 : 1 / Math.hypot(x, y, z);
    xyz[3 * i] = x * scale;
    xyz[3 * i + 1] = y * scale;
    xyz[3 * i + 2] = z * scale;
  }
  // The optimised code is compiled in the background (tens of ms for the largest function on a
  // busy machine) and used from the next call on: repeat, yielding to the event loop in between,
  // until a round is no faster than the one before (the code is in place), 3 to 6 rounds.
  // Delaunay's code likewise: a first 1e6-point triangulation took about 2.2 s in the baseline
  // tier against 1.4 s once the code is optimised. 4,000 points in a square are enough.
  const xy = new Float64Array(2 * 4000);
  for (let i = 0; i < xy.length; i++) xy[i] = next();
  // triangulatePolygon's own code (segment insertion, the inside flood): a 2,000-vertex star-shaped
  // ring with a hole, its vertices from the same generator.
  const ring = [];
  for (let k = 0; k < 2000; k++) {
    const angle = (2 * Math.PI * k) / 2000;
    const r = k < 1600 ? 2 + next() : 0.5 + 0.2 * next();
    ring.push(r * Math.cos(k < 1600 ? (angle * 2000) / 1600 : -(angle * 2000) / 400), r * Math.sin(k < 1600 ? (angle * 2000) / 1600 : -(angle * 2000) / 400));
  }
  const polygon = Float64Array.from(ring);
  let previous = Infinity;
  for (let round = 0; round < 6; round++) {
    const start = performance.now();
    hull(core, xyz.subarray(0, 3 * cubeCount));
    hull(core, xyz.subarray(3 * cubeCount));
    delaunay(core, xy);
    triangulatePolygon(core, polygon, [1600]);
    const seconds = performance.now() - start;
    await new Promise((resolve) => setTimeout(resolve, 0));
    if (round >= 2 && seconds > 0.85 * previous) break;
    previous = Math.min(previous, seconds);
  }
}

function hull(core, xyz, options = {}) {
  const points = toFloat64(xyz, 'hull');
  const { algorithm = 'quickhull', epsilon = 'exact', mergeCoplanar = false, equations = true } = checkOptions(options, HULL_OPTIONS, 'hull');
  if (!ALGORITHMS.includes(algorithm)) {
    throw new HullkitError(`hull: unknown algorithm "${algorithm}" (known: ${ALGORITHMS.join(', ')})`);
  }
  if (!EPSILONS.includes(epsilon)) {
    throw new HullkitError(`hull: unknown epsilon "${epsilon}" (known: ${EPSILONS.join(', ')})`);
  }
  for (const [name, value] of [['mergeCoplanar', mergeCoplanar], ['equations', equations]]) {
    if (typeof value !== 'boolean') throw new HullkitError(`hull: ${name} must be true or false, got ${String(value)}`);
  }

  const count = points.length / 3;
  const address = copyIn(core, points, 'hull');
  let result;
  let planes = new Float64Array(0);
  try {
    result = core.hullFromHeap(address, count, algorithm, epsilon === 'seed', mergeCoplanar);
    // The planes while the points are still in the heap.
    if (equations && result.ok()) planes = core.hullEquations(address, count, result);
  } catch (error) {
    result?.delete();
    throw error;
  } finally {
    core._free(address);
  }
  try {
    if (!result.ok()) {
      throw new HullkitError(`hull: ${result.error}`, { pointIndex: result.errorPoint() });
    }
    const out = {
      dimension: result.dimension,
      triangles: result.trianglesView().slice(),
      vertices: result.verticesView().slice(),
      equations: planes,
      volume: result.volume,
      area: result.area,
    };
    if (out.dimension === 2) out.normal = result.normalView().slice();
    if (mergeCoplanar) {
      out.faceOffsets = result.faceOffsetsView().slice();
      out.faceVertices = result.faceVerticesView().slice();
    }
    return out;
  } finally {
    result.delete();
  }
}


function verify(core, xyz, result) {
  const points = toFloat64(xyz, 'verify');
  if (result === null || typeof result !== 'object') {
    throw new TypeError('verify: the second argument must be a hull result {triangles, vertices?, dimension?}');
  }
  const triangles = toUint32(result.triangles ?? [], 'verify: triangles');
  if (triangles.length % 3 !== 0) {
    throw new HullkitError(`verify: ${triangles.length} triangle indices is not a whole number of triangles`);
  }
  const withHull = result.vertices !== undefined;
  const vertices = toUint32(result.vertices ?? [], 'verify: vertices');
  const dimension = result.dimension ?? 3;
  if (![3, 2, 1, 0, -1].includes(dimension)) throw new HullkitError(`verify: dimension ${dimension} is not one of 3, 2, 1, 0, -1`);
  const addresses = [];
  try {
    addresses.push(copyIn(core, points, 'verify'), copyIn(core, triangles, 'verify'), copyIn(core, vertices, 'verify'));
    return core.verifyFromHeap(addresses[0], points.length / 3, addresses[1], triangles.length / 3, addresses[2],
      vertices.length, dimension, withHull);
  } finally {
    for (const address of addresses) core._free(address);
  }
}

let eventNames = null; // the C++ core's event kind names, index = kind

/** The recorded gift wrap of `xyz` (exact sides): events, their names and the hull's triangles. */
function giftwrapTrace(core, xyz, options = {}) {
  const points = toFloat64(xyz, 'giftwrapTrace');
  const { scan = 'single-pass' } = checkOptions(options, ['scan'], 'giftwrapTrace');
  if (!SCANS.includes(scan)) {
    throw new HullkitError(`giftwrapTrace: unknown scan "${scan}" (known: ${SCANS.join(', ')})`);
  }
  const count = points.length / 3;
  const limit = scan === 'restart' ? TRACE_MAX_RESTART : TRACE_MAX_POINTS;
  if (count > limit) {
    throw new HullkitError(`giftwrapTrace: ${count} points is too many to trace with the ${scan} scan (at most ${limit}); ` +
      'use hull(xyz, {algorithm: "giftwrap"}) for the hull alone');
  }
  eventNames ??= Object.freeze(core.giftwrapEventNames());
  const address = copyIn(core, points, 'giftwrapTrace');
  let trace;
  try {
    trace = core.giftwrapTraceFromHeap(address, count, scan === 'restart');
  } finally {
    core._free(address);
  }
  return takeTrace(trace, [...eventNames], 'giftwrapTrace');
}

/** The file's bytes (see bytesOf); anything else is a TypeError. */
function fileBytes(bytes, where) {
  if (!isBytes(bytes)) throw new TypeError(`${where}: the file must be a Uint8Array or an ArrayBuffer`);
  return bytesOf(bytes);
}

/**
 * Runs one of the C++ readers on the file's bytes; `take(result)` copies the arrays out. A reader's
 * error ("name:LINE: what is wrong") is thrown as a HullkitError with that message and, when the
 * message names one, `line` (1-based).
 */
function readFile(core, bytes, name, where, read, take) {
  const data = fileBytes(bytes, where);
  if (name === undefined || name === null) name = '';
  if (typeof name !== 'string') throw new TypeError(`${where}: the name must be a string (the file name)`);
  if (data.length > 0xffffffff) throw new HullkitError(`${where}: ${name || 'the file'} is too large (4 GiB at most)`);
  const source = name || '<bytes>';
  const address = copyIn(core, data, where);
  let result;
  try {
    result = read(address, data.length, source);
  } finally {
    core._free(address);
  }
  try {
    const error = result.error();
    if (error) {
      const failure = new HullkitError(error);
      const match = error.startsWith(`${source}:`) ? /^(\d+): /.exec(error.slice(source.length + 1)) : null;
      if (match) failure.line = Number(match[1]);
      throw failure;
    }
    return take(result);
  } finally {
    result.delete();
  }
}

/**
 * The points a reader returned, as a Float64Array carrying the reader's `warnings` (what it skipped
 * and read on past: `skipped 1 unknown OBJ record "648" (first at line 1)`), an empty array if none.
 */
function pointsWithWarnings(r) {
  const points = r.view().slice();
  Object.defineProperty(points, 'warnings', { value: r.warnings(), enumerable: false });
  return points;
}

function readPoints(core, bytes, name) {
  return readFile(core, bytes, name, 'readPoints', (a, n, s) => core.readPointsFromHeap(a, n, s), pointsWithWarnings);
}

function readPoints2d(core, bytes, name) {
  return readFile(core, bytes, name, 'readPoints2d', (a, n, s) => core.readPoints2dFromHeap(a, n, s), pointsWithWarnings);
}

function readMesh(core, bytes, name) {
  return readFile(core, bytes, name, 'readMesh', (a, n, s) => core.readMeshFromHeap(a, n, s),
    (r) => ({ vertices: r.verticesView().slice(), triangles: r.trianglesView().slice(), warnings: r.warnings() }));
}

/**
 * The hull as binary glTF (.glb) bytes, as `hullkit hull -o hull.glb` writes them: the hull's
 * vertices as float32 positions (rounded to the nearest float) and its triangles as uint32 indices.
 */
function writeGlb(core, xyz, result) {
  const points = toFloat64(xyz, 'writeGlb');
  if (result === null || typeof result !== 'object') throw new TypeError('writeGlb: the hull must be the object hull() returned');
  const vertices = toUint32(result.vertices, 'writeGlb: hull.vertices');
  const triangles = toUint32(result.triangles, 'writeGlb: hull.triangles');
  const blocks = [];
  try {
    blocks.push(copyIn(core, points, 'writeGlb'));
    blocks.push(copyIn(core, vertices, 'writeGlb'));
    blocks.push(copyIn(core, triangles, 'writeGlb'));
    const out = core.writeGlbFromHeap(blocks[0], points.length / 3, blocks[1], vertices.length, blocks[2], triangles.length);
    if (out.error) throw new HullkitError(`writeGlb: ${out.error}`);
    return out.bytes;
  } finally {
    for (const address of blocks) core._free(address);
  }
}
