// Web Worker: generates (or parses) the points and computes their convex hull
// with the hullkit WebAssembly module, so that the page stays responsive.
//
// Shared by every view: each request carries an id, answered by one 'result' or 'error' with it.
//
// worker -> main  {type: 'ready', algorithms, delaunay}   once the module is loaded
//                 (delaunay: {algorithms}, the names hullkit.delaunay accepts)
//                 {type: 'load-error', message}                if it cannot be loaded
// main -> worker  {type: 'compute', id, distribution, n, seed, algorithm?, epsilon?,
//                  mergeCoplanar?, text?, xyz?}   (xyz: the points of distribution 'file')
// worker -> main  {type: 'result', id, n, dimension, xyz, triangles, vertices, edges,
//                  faces, faceSizes?, volume, area, extent, comparison?,
//                  hullMs, genMs, workerMs}                     (buffers transferred)
//                 {type: 'error', id, kind, message, n, xyz?, comparison?}
//                                                               (xyz transferred when available)
// main -> worker  {type: 'delaunay', id, xy, algorithm?, voronoi?: [xmin, ymin, xmax, ymax]}
// worker -> main  {type: 'result', id, dimension, triangles, halfedges, hull, representative,
//                  duplicateCount, cells?: {cellOffsets, cellXY}, ms, voronoiMs}
// main -> worker  {type: 'constrained', id, coords, rings, segments?, holes?, regions?, options?}
//                 (coords: Float64Array x y; rings: closed rings as arrays of point indices;
//                 segments: Uint32Array index pairs; holes: Float64Array x y; options: minAngle,
//                 maxArea, conforming, maxSteinerPoints). Rings alone: hullkit.triangulatePolygon
//                 (even-odd). With segments or `regions`: hullkit.constrainedDelaunay of the
//                 points, rings and segments, with `regions` as Triangle's -p (removeExterior and
//                 the hole points), or of the whole hull when that leaves nothing (`wholeHull`).
// worker -> main  {type: 'result', id, graph, triangles, halfedges, constrained, coords, inputCount,
//                  addedCount, crossingCount, duplicateCount, steinerCount, unrefinedCount,
//                  polygonEdges, notDelaunay, wholeHull, ms, delaunayMs}
//                 (coords: hullkit's, its first inputCount the vertices it was given; notDelaunay:
//                 how many of the polygonEdges the unconstrained hullkit.delaunay of the same
//                 points lacks)
//                 {type: 'error', id, kind, message, pointIndex?, segmentIndex?} (pointIndex into
//                 the request's coords)
// main -> worker  {type: 'read', id, bytes (ArrayBuffer), name, as: 'points' | 'points2d' | 'mesh' | 'polygon'}
// worker -> main  {type: 'result', id, xyz | xy | {vertices, triangles}, ms}: the file read by the
//                 C++ readers the CLI uses (hullkit.readPoints / readPoints2d / readMesh);
//                 'polygon': {type: 'result', id, polygon, warnings, ms}, GeoJSON or Triangle's
//                 .poly read by polygons.js (readPolygonFile)
// main -> worker  {type: 'trace', id, xyz, scan?} / {type: 'trace', id, xy, lifted: true}
// worker -> main  {type: 'result', id, kinds, args, kindNames, triangles, dimension, ms}: the
//                 events of the real gift wrapping (hullkit.giftwrapTrace / delaunayGiftwrapTrace)
// main -> worker  {type: 'delaunay3', id, distribution, n, seed, text?, xyz?, furthestSite?}   (the Hull view's points)
// worker -> main  {type: 'progress', id, done, total}   while the points are inserted, then
//                 {type: 'result', id, key, n, xyz, dimension, tetrahedra, neighbors, hull, triangles,
//                  vertices, representative, duplicateCount, ms, genMs, drawing, drawingMs}
//                 (drawing: what the page draws, from positions.js tetrahedraDrawing; buffers transferred)
// main -> worker  {type: 'delaunay3-voronoi', id, key, points?: {xyz, dimension, tetrahedra, neighbors,
//                  triangles, vertices, representative}}
// worker -> main  {type: 'result', id, key, volume, tetrahedronVertex, vertexCount, faceCount, ms}: the
//                 Voronoi diagram (hullkit.voronoi3) of the tetrahedralization `key` (the id of its
//                 'delaunay3' request), which the worker keeps for cell requests; {type: 'error',
//                 kind: 'stale'} when it no longer has it and `points` are not given
// main -> worker  {type: 'delaunay3-cell', id, key, point}
// worker -> main  {type: 'result', id, key, point, volume, bounded, vertices (Float64Array x y z),
//                  faceOffsets, faceCorners (into vertices), faceBounded, neighbours}: one cell of
//                 that diagram; 'stale' as above
// main -> worker  {type: 'route', id, scene, route, samples}
// worker -> main  {type: 'result', id, report, sweeps: [{leg, sub, of, part, points, triangles}], ms}
//                 (sweeps: each part's swept hull per sub-interval `sub` of `of` of a leg (one
//                 for a leg that does not turn), from hullkit.hull of the part's hull vertices
//                 placed at both ends of the sub-interval: `points` (Float32Array x y z ...) and
//                 `triangles` indexing them; buffers transferred)
//   kind: 'input'    the input was rejected (by the library or the text parser)
//         'stale'    (Delaunay 3D) the tetrahedralization asked about is no longer in the worker
//         'load'     the hullkit module could not be loaded / instantiated
//         'internal' anything else (wasm trap, malformed result, bug)
//   faces:      polygons with mergeCoplanar (faceSizes: {corners: count}), else triangles
//   edges:      pairs of point indices to draw: the polygon edges with mergeCoplanar, all
//               triangle edges without; the outline of a flat result; a segment's two ends
//   comparison: with epsilon 'seed' only, what exact predicates make of the same points:
//               {epsilon, outcome: 'same' | 'different' | 'failed', exact: {dimension, vertices,
//               faces, volume, area}, dropped (Uint32Array: exact hull vertices the seed's hull
//               lacks), added (count of seed hull vertices that are not extreme)}
import { generatePoints, parsePoints } from './distributions.js';
import { partVertices } from './route-scenes.js';
import { legMotion, poseAt, subintervalCount, placeVertices } from './route-poses.js';
import { tetrahedraDrawing } from './positions.js';
import { readPolygonFile, edgesMissingFrom } from './polygons.js';

const HULLKIT_URL = new URL('../wasm/hullkit.js', import.meta.url).href;

let hullkitPromise = null;
let HullkitError = null; // the library's error class for rejected input, when exported
function loadHullkit() {
  if (!hullkitPromise) {
    hullkitPromise = import(HULLKIT_URL).then((mod) => {
      if (typeof mod.default !== 'function') {
        throw new Error(`${HULLKIT_URL} has no default export createHullkit()`);
      }
      if (typeof mod.HullkitError === 'function') HullkitError = mod.HullkitError;
      return mod.default();
    });
  }
  return hullkitPromise;
}

// Start loading right away and tell the page what the module offers.
loadHullkit().then(
  (hullkit) => {
    const algorithms = Array.isArray(hullkit.algorithms) ? [...hullkit.algorithms].map(String) : null;
    const delaunay = { algorithms: [...hullkit.delaunayAlgorithms].map(String) };
    self.postMessage({ type: 'ready', algorithms, delaunay });
  },
  (err) => {
    self.postMessage({ type: 'load-error', message: loadErrorMessage(err) });
  },
);

function loadErrorMessage(err) {
  return `could not load the hullkit WebAssembly module (${HULLKIT_URL}): ${describe(err)}`;
}

// Input rejected by the library (shown to the user) vs. a real failure.
function isInputError(err) {
  if (err instanceof WebAssembly.RuntimeError) return false; // trap / abort
  if (HullkitError) return err instanceof HullkitError || err instanceof TypeError;
  return err instanceof Error;
}

self.onmessage = (event) => {
  const msg = event.data;
  const run = msg && {
    compute, delaunay: delaunayJob, constrained: constrainedJob, route: routeJob, read: readJob, trace: traceJob,
    delaunay3: delaunay3Job, 'delaunay3-voronoi': voronoi3Job, 'delaunay3-cell': cell3Job,
  }[msg.type];
  if (run) {
    run(msg).catch((err) => {
      // Should not happen (compute catches everything), but never drop it.
      self.postMessage({ type: 'error', id: msg.id, kind: 'internal', message: describe(err), n: msg.n });
    });
  }
};

/**
 * The points a request names (the Hull and Delaunay 3D views): a file's (`xyz`, given), pasted
 * text, or a generated distribution. Throws what is wrong with them.
 */
function requestedPoints({ distribution, n, seed, text, xyz }) {
  if (distribution === 'file') {
    if (!(xyz instanceof Float64Array)) throw new Error('no points from a file');
    return xyz;
  }
  return distribution === 'custom' ? parsePoints(text ?? '') : generatePoints(distribution, n, seed);
}

async function compute({ id, distribution, n, seed, algorithm, epsilon, mergeCoplanar = false, text, xyz: given }) {
  const w0 = performance.now();
  let xyz;
  try {
    xyz = requestedPoints({ distribution, n, seed, text, xyz: given });
  } catch (err) {
    self.postMessage({ type: 'error', id, kind: 'input', message: describe(err), n });
    return;
  }
  const genMs = performance.now() - w0;
  const count = Math.floor(xyz.length / 3);

  let hullkit;
  try {
    hullkit = await loadHullkit();
  } catch (err) {
    postError(id, 'load', loadErrorMessage(err), xyz);
    return;
  }

  const options = { mergeCoplanar: Boolean(mergeCoplanar) };
  if (algorithm) options.algorithm = algorithm;
  const seedEpsilon = epsilon === 'seed';
  if (seedEpsilon) options.epsilon = 'seed';

  let result;
  const h0 = performance.now();
  try {
    result = hullkit.hull(xyz, options);
  } catch (err) {
    const kind = isInputError(err) ? 'input' : 'internal';
    // The seed's epsilon may give up on near-degenerate input: say what exact predicates find.
    const comparison = seedEpsilon && kind === 'input' && xyz.length % 3 === 0
      ? compareWithExact(hullkit, xyz, options.mergeCoplanar, null) : undefined;
    postError(id, kind, describe(err), xyz, comparison);
    return;
  }
  const hullMs = performance.now() - h0;

  let triangles, vertices, edges, faces, faceSizes, dimension;
  try {
    dimension = result.dimension;
    if (![3, 2, 1, 0, -1].includes(dimension)) throw new Error(`dimension ${dimension}`);
    triangles = ownedCopy(result.triangles, Uint32Array, 'triangles');
    vertices = ownedCopy(result.vertices, Uint32Array, 'vertices');
    validate(triangles, vertices, count);
    if (options.mergeCoplanar && dimension >= 2) {
      const polygons = checkPolygons(result.faceOffsets, result.faceVertices, count);
      faces = polygons.length;
      faceSizes = polygonSizes(polygons);
      edges = dimension === 3 ? polygonEdges(polygons, count) : outline(vertices);
    } else {
      faces = triangles.length / 3;
      edges = dimension === 3 ? triangleEdges(triangles, count) : dimension === 2 ? outline(vertices) : segment(vertices, dimension);
    }
  } catch (err) {
    postError(id, 'internal', `unexpected hull result: ${describe(err)}`, xyz);
    return;
  }

  const comparison = seedEpsilon ? compareWithExact(hullkit, xyz, options.mergeCoplanar, { result, faces }) : undefined;
  const workerMs = performance.now() - w0;
  const transfer = [xyz.buffer, triangles.buffer, vertices.buffer, edges.buffer];
  if (comparison?.dropped) transfer.push(comparison.dropped.buffer);
  self.postMessage(
    {
      type: 'result', id, n: count, dimension, xyz, triangles, vertices, edges, faces, faceSizes,
      volume: Number(result.volume), area: Number(result.area), extent: taxicabExtent(xyz), comparison,
      hullMs, genMs, workerMs,
    },
    transfer,
  );
}

function postError(id, kind, message, xyz, comparison) {
  self.postMessage({ type: 'error', id, kind, message, n: Math.floor(xyz.length / 3), xyz, comparison }, [xyz.buffer]);
}

function describe(err) {
  if (err instanceof Error) return err.message || String(err);
  return String(err);
}

/**
 * The same points with exact predicates (quickhull, the fast default) next to the seed's
 * epsilon run: `seed` is {result, faces} of that run, or null when it failed.
 */
function compareWithExact(hullkit, xyz, mergeCoplanar, seed) {
  const extent = taxicabExtent(xyz);
  const comparison = { epsilon: Number.EPSILON * extent, outcome: seed ? 'same' : 'failed', exact: null, dropped: null, added: 0 };
  let exact;
  try {
    exact = hullkit.hull(xyz, { mergeCoplanar });
  } catch (err) {
    comparison.exactError = describe(err);
    return comparison;
  }
  comparison.exact = {
    dimension: exact.dimension,
    vertices: exact.vertices.length,
    faces: mergeCoplanar && exact.faceOffsets ? Math.max(0, exact.faceOffsets.length - 1) : exact.triangles.length / 3,
    volume: Number(exact.volume),
    area: Number(exact.area),
  };
  if (seed) {
    const inSeed = new Set(seed.result.vertices);
    const inExact = new Set(exact.vertices);
    comparison.dropped = Uint32Array.from(exact.vertices.filter((v) => !inSeed.has(v)));
    for (const v of seed.result.vertices) if (!inExact.has(v)) comparison.added++;
    const same = comparison.dropped.length === 0 && comparison.added === 0 && exact.dimension === seed.result.dimension &&
      comparison.exact.faces === seed.faces;
    comparison.outcome = same ? 'same' : 'different';
  }
  return comparison;
}

/** |x extent| + |y extent| + |z extent| of the finite points (the seed's epsilon is DBL_EPSILON times this). */
function taxicabExtent(xyz) {
  let sum = 0;
  for (let k = 0; k < 3; k++) {
    let lo = Infinity, hi = -Infinity;
    for (let i = k; i < xyz.length; i += 3) {
      const v = xyz[i];
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
    if (hi >= lo && Number.isFinite(hi - lo)) sum += hi - lo;
  }
  return sum;
}

// The result arrays must own their whole (non-shared) buffer to be
// transferable; a view into wasm memory, for instance, is copied first.
function ownedCopy(arr, Type, name) {
  if (!(arr instanceof Type)) {
    if (arr && typeof arr.length === 'number') return Type.from(arr);
    throw new Error(`${name} is not a ${Type.name}`);
  }
  const whole = arr.byteOffset === 0 && arr.byteLength === arr.buffer.byteLength;
  return whole && arr.buffer instanceof ArrayBuffer ? arr : arr.slice();
}

function validate(triangles, vertices, n) {
  if (triangles.length % 3 !== 0) throw new Error(`triangles has length ${triangles.length}, not a multiple of 3`);
  for (let i = 0; i < triangles.length; i++) {
    if (triangles[i] >= n) throw new Error(`triangle index ${triangles[i]} out of range (n = ${n})`);
  }
  for (let i = 0; i < vertices.length; i++) {
    if (vertices[i] >= n) throw new Error(`vertex index ${vertices[i]} out of range (n = ${n})`);
  }
}

/** faceOffsets/faceVertices as an array of polygons (subarrays), checked. */
function checkPolygons(offsets, corners, n) {
  if (!offsets || !corners) throw new Error('mergeCoplanar was requested but faceOffsets/faceVertices are missing');
  if (offsets.length === 0 || offsets[0] !== 0 || offsets[offsets.length - 1] !== corners.length) {
    throw new Error('faceOffsets does not span faceVertices');
  }
  const polygons = [];
  for (let f = 0; f + 1 < offsets.length; f++) {
    if (offsets[f + 1] - offsets[f] < 3) throw new Error(`face ${f} has fewer than 3 corners`);
    polygons.push(corners.subarray(offsets[f], offsets[f + 1]));
  }
  for (let i = 0; i < corners.length; i++) {
    if (corners[i] >= n) throw new Error(`face vertex index ${corners[i]} out of range (n = ${n})`);
  }
  return polygons;
}

/** {corners: number of faces with that many corners}. */
function polygonSizes(polygons) {
  const sizes = {};
  for (const p of polygons) sizes[p.length] = (sizes[p.length] ?? 0) + 1;
  return sizes;
}

/** Closed loop through the vertices in order (a flat result's polygon). */
function outline(vertices) {
  const h = vertices.length;
  if (h < 3) return segment(vertices, h - 1);
  const edges = new Uint32Array(2 * h);
  for (let i = 0; i < h; i++) {
    edges[2 * i] = vertices[i];
    edges[2 * i + 1] = vertices[(i + 1) % h];
  }
  return edges;
}

function segment(vertices, dimension) {
  return dimension === 1 && vertices.length >= 2
    ? Uint32Array.of(vertices[0], vertices[vertices.length - 1]) : new Uint32Array(0);
}

/** Every edge of the triangles once (two triangles share each edge of a closed surface). */
function triangleEdges(triangles, n) {
  const keys = new Float64Array(triangles.length); // lo * n + hi < 2^53 for n <= 2^26
  for (let t = 0; t < triangles.length; t += 3) {
    for (let k = 0; k < 3; k++) keys[t + k] = edgeKey(triangles[t + k], triangles[t + (k === 2 ? 0 : k + 1)], n);
  }
  return uniqueEdges(keys, n);
}

/** The polygons' sides once each: no triangulation diagonals. */
function polygonEdges(polygons, n) {
  let m = 0;
  for (const p of polygons) m += p.length;
  const keys = new Float64Array(m);
  let o = 0;
  for (const p of polygons) {
    for (let i = 0; i < p.length; i++) keys[o++] = edgeKey(p[i], p[(i + 1) % p.length], n);
  }
  return uniqueEdges(keys, n);
}

const edgeKey = (a, b, n) => (a < b ? a * n + b : b * n + a);

function uniqueEdges(keys, n) {
  keys.sort();
  const out = [];
  for (let i = 0; i < keys.length; i++) {
    if (i > 0 && keys[i] === keys[i - 1]) continue;
    const lo = Math.floor(keys[i] / n);
    out.push(lo, keys[i] - lo * n);
  }
  return Uint32Array.from(out);
}

// ---------------------------------------------------------------- Delaunay and Route views

/**
 * Runs `job(hullkit)` for request `id` once the module is loaded; a load failure or a throw is
 * answered as an error message ('load', 'input' or 'internal').
 */
async function withHullkit(id, job) {
  let hullkit;
  try {
    hullkit = await loadHullkit();
  } catch (err) {
    self.postMessage({ type: 'error', id, kind: 'load', message: loadErrorMessage(err) });
    return;
  }
  try {
    job(hullkit);
  } catch (err) {
    self.postMessage({ type: 'error', id, kind: isInputError(err) ? 'input' : 'internal', message: describe(err) });
  }
}

function delaunayJob({ id, xy, algorithm, voronoi }) {
  return withHullkit(id, (hullkit) => {
    const t0 = performance.now();
    const options = algorithm ? { algorithm } : {};
    const result = hullkit.delaunay(xy, options);
    const ms = performance.now() - t0;
    let cells;
    let voronoiMs = 0;
    if (voronoi) {
      const v0 = performance.now();
      cells = hullkit.voronoi(xy, result, voronoi);
      voronoiMs = performance.now() - v0;
    }
    const out = {
      type: 'result', id, dimension: result.dimension,
      triangles: ownedCopy(result.triangles, Uint32Array, 'triangles'),
      halfedges: ownedCopy(result.halfedges, Int32Array, 'halfedges'),
      hull: ownedCopy(result.hull, Uint32Array, 'hull'),
      representative: ownedCopy(result.representative, Uint32Array, 'representative'),
      duplicateCount: result.duplicateCount,
      cells, ms, voronoiMs,
    };
    const transfer = [out.triangles.buffer, out.halfedges.buffer, out.hull.buffer, out.representative.buffer];
    if (cells) transfer.push(cells.cellOffsets.buffer, cells.cellXY.buffer);
    self.postMessage(out, transfer);
  });
}

// ---------------------------------------------------------------- Delaunay view, constrained modes

/**
 * A polygon with holes or a planar graph, triangulated with constraints (see the message list at
 * the top), next to the unconstrained Delaunay triangulation of the same points: how many of the
 * polygon's edges it lacks.
 */
function constrainedJob({ id, coords, rings = [], segments = new Uint32Array(0), holes = new Float64Array(0), regions = false, options = {} }) {
  return withHullkit(id, (hullkit) => {
    const graph = regions || segments.length > 0;
    // The polygon's edges as index pairs into coords, and what hullkit is given.
    const pairs = Array.from(segments);
    for (const ring of rings) ring.forEach((v, i) => pairs.push(v, ring[(i + 1) % ring.length]));
    let inputPoint; // input vertex of the hullkit call -> index into coords
    let call;
    let wholeHull = false;
    if (graph) {
      inputPoint = Uint32Array.from({ length: coords.length / 2 }, (_, i) => i);
      const edges = Uint32Array.from(pairs);
      call = () => {
        if (!regions) return hullkit.constrainedDelaunay(coords, edges, options);
        const domain = hullkit.constrainedDelaunay(coords, edges, { holes, removeExterior: true, ...options });
        if (domain.triangles.length > 0) return domain;
        wholeHull = true; // the segments enclose nothing: the convex hull, as triangle -pc
        return hullkit.constrainedDelaunay(coords, edges, options);
      };
    } else {
      inputPoint = Uint32Array.from(rings.flat());
      const flat = new Float64Array(2 * inputPoint.length);
      inputPoint.forEach((v, k) => flat.set([coords[2 * v], coords[2 * v + 1]], 2 * k));
      const holeIndices = [];
      let start = 0;
      rings.forEach((ring, r) => {
        if (r > 0) holeIndices.push(start);
        start += ring.length;
      });
      call = () => hullkit.triangulatePolygon(flat, Uint32Array.from(holeIndices), { fill: 'evenodd', ...options });
    }
    let result;
    const t0 = performance.now();
    try {
      result = call();
    } catch (err) {
      if (!isInputError(err)) throw err;
      const error = { type: 'error', id, kind: 'input', message: describe(err) };
      if (Number.isInteger(err.pointIndex) && err.pointIndex >= 0 && err.pointIndex < inputPoint.length) error.pointIndex = inputPoint[err.pointIndex];
      if (Number.isInteger(err.segmentIndex) && err.segmentIndex >= 0) error.segmentIndex = err.segmentIndex;
      self.postMessage(error);
      return;
    }
    const { triangles, halfedges, constrained } = result;
    const ms = performance.now() - t0;
    const d0 = performance.now();
    const unconstrained = hullkit.delaunay(coords);
    const { edges: polygonEdges, missing: notDelaunay } = edgesMissingFrom(unconstrained.triangles, unconstrained.representative, pairs);
    const delaunayMs = performance.now() - d0;
    const out = {
      type: 'result', id, graph,
      triangles: ownedCopy(triangles, Uint32Array, 'triangles'),
      halfedges: ownedCopy(halfedges, Int32Array, 'halfedges'),
      constrained: ownedCopy(constrained, Uint8Array, 'constrained'),
      coords: ownedCopy(result.coords, Float64Array, 'coords'),
      inputCount: result.inputCount, addedCount: result.addedCount,
      crossingCount: result.crossingCount ?? 0, duplicateCount: result.duplicateCount ?? 0,
      steinerCount: result.steinerCount ?? null, unrefinedCount: result.unrefinedCount ?? null,
      polygonEdges, notDelaunay, wholeHull, ms, delaunayMs,
    };
    self.postMessage(out, [out.triangles.buffer, out.halfedges.buffer, out.constrained.buffer, out.coords.buffer]);
  });
}

// ---------------------------------------------------------------- files and traces

const READERS = { points: 'readPoints', points2d: 'readPoints2d', mesh: 'readMesh' };

function readJob({ id, bytes, name, as }) {
  if (as === 'polygon') return readPolygonJob({ id, bytes, name });
  return withHullkit(id, (hullkit) => {
    const reader = READERS[as];
    if (!reader || typeof hullkit[reader] !== 'function') throw new Error(`this hullkit build cannot read ${as} files`);
    const t0 = performance.now();
    const result = hullkit[reader](new Uint8Array(bytes), String(name ?? ''));
    const ms = performance.now() - t0;
    // What the reader skipped (unknown OBJ records, ...): the page shows it in a note.
    const warnings = Array.isArray(result.warnings) ? result.warnings.map(String) : [];
    if (as === 'mesh') {
      const vertices = ownedCopy(result.vertices, Float64Array, 'vertices');
      const triangles = ownedCopy(result.triangles, Uint32Array, 'triangles');
      self.postMessage({ type: 'result', id, vertices, triangles, warnings, ms }, [vertices.buffer, triangles.buffer]);
    } else {
      const coords = ownedCopy(result, Float64Array, 'points');
      self.postMessage({ type: 'result', id, [as === 'points' ? 'xyz' : 'xy']: coords, warnings, ms }, [coords.buffer]);
    }
  });
}

/** A GeoJSON or .poly file, read in JavaScript (polygons.js); its errors are the input's. */
async function readPolygonJob({ id, bytes, name }) {
  const t0 = performance.now();
  let polygon;
  try {
    polygon = readPolygonFile(new TextDecoder().decode(bytes), String(name ?? ''));
  } catch (err) {
    self.postMessage({ type: 'error', id, kind: 'input', message: describe(err) });
    return;
  }
  const { warnings, ...rest } = polygon;
  const transfer = Object.values(rest).filter(ArrayBuffer.isView).map((a) => a.buffer);
  self.postMessage({ type: 'result', id, polygon: rest, warnings, ms: performance.now() - t0 }, transfer);
}

function traceJob({ id, xyz, xy, lifted = false, scan }) {
  return withHullkit(id, (hullkit) => {
    const t0 = performance.now();
    const trace = lifted ? hullkit.delaunayGiftwrapTrace(xy) : hullkit.giftwrapTrace(xyz, scan ? { scan } : {});
    const ms = performance.now() - t0;
    const kinds = ownedCopy(trace.kinds, Uint8Array, 'kinds');
    const args = ownedCopy(trace.args, Uint32Array, 'args');
    const triangles = ownedCopy(trace.triangles, Uint32Array, 'triangles');
    self.postMessage(
      { type: 'result', id, kinds, args, triangles, kindNames: [...trace.kindNames], dimension: trace.dimension, ms },
      [kinds.buffer, args.buffer, triangles.buffer],
    );
  });
}

// ---------------------------------------------------------------- Route view

// The last scene's RouteChecker, reused while dragging, and the vertices of its traverse parts'
// own hulls (what the swept hulls are made of): {key, instance, parts: [Float64Array]}.
let prepared = null;

function routeJob({ id, scene, route, samples }) {
  return withHullkit(id, (hullkit) => {
    const t0 = performance.now();
    const key = JSON.stringify({ ...scene, route: undefined });
    if (!prepared || prepared.key !== key) {
      prepared?.instance.delete();
      prepared = null;
      prepared = { key, instance: new hullkit.RouteChecker(scene), parts: scene.traverse.parts.map((part) => hullVertices(hullkit, part)) };
    }
    const report = prepared.instance.check(route, { samples, clearance: true });
    const ms = performance.now() - t0;
    const sweeps = sweptHulls(hullkit, prepared.parts, scene.traverse.pivot ?? [0, 0, 0], route);
    const transfer = sweeps.flatMap((s) => [s.points.buffer, s.triangles.buffer]);
    self.postMessage({ type: 'result', id, report, sweeps, ms }, transfer);
  });
}

/** A part's hull vertices (all its vertices when the hull has none to offer), flat. */
function hullVertices(hullkit, part) {
  const all = partVertices(part);
  let extreme;
  try {
    extreme = hullkit.hull(Float64Array.from(all)).vertices;
  } catch {
    return Float64Array.from(all);
  }
  if (!extreme?.length) return Float64Array.from(all);
  const out = new Float64Array(3 * extreme.length);
  extreme.forEach((v, i) => out.set(all.slice(3 * v, 3 * v + 3), 3 * i));
  return out;
}

/**
 * Each traverse part's swept hulls per leg: a leg is split into sub-intervals (one per
 * SUBINTERVAL_DEGREES turned, one for a leg that does not turn), each drawn as hullkit.hull of the
 * part's vertices placed at both of its ends.
 */
function sweptHulls(hullkit, parts, pivot, route) {
  const sweeps = [];
  for (let leg = 0; leg + 1 < route.length; leg++) {
    const motion = legMotion(route[leg], route[leg + 1]);
    const n = subintervalCount(motion);
    for (let sub = 0; sub < n; sub++) {
      const [from, to] = [poseAt(motion, sub / n), poseAt(motion, (sub + 1) / n)];
      parts.forEach((vertices, part) => {
        const both = new Float64Array(2 * vertices.length);
        placeVertices(vertices, pivot, from, both, 0);
        placeVertices(vertices, pivot, to, both, vertices.length);
        const hull = hullkit.hull(both);
        sweeps.push({ leg, sub, of: n, part, points: Float32Array.from(both), triangles: ownedCopy(hull.triangles, Uint32Array, 'triangles') });
      });
    }
  }
  return sweeps;
}

// ---------------------------------------------------------------- Delaunay 3D view

// The last tetrahedralization and (once asked for) its Voronoi diagram, for the cell requests:
// {key, xyz, triangulation, voronoi}.
let tetrahedralization = null;

function delaunay3Job({ id, distribution, n, seed, text, xyz: given, furthestSite = false }) {
  return withHullkit(id, (hullkit) => {
    const g0 = performance.now();
    const xyz = requestedPoints({ distribution, n, seed, text, xyz: given });
    const genMs = performance.now() - g0;
    tetrahedralization = null; // the memory of the last one first
    const t0 = performance.now();
    // Progress after each round of the insertion (rounds grow eightfold; the last holds 7/8 of the points).
    const result = hullkit.delaunay3(xyz, { furthestSite, progress: (done, total) => self.postMessage({ type: 'progress', id, done, total }) });
    const ms = performance.now() - t0;
    const owned = {
      tetrahedra: ownedCopy(result.tetrahedra, Uint32Array, 'tetrahedra'),
      neighbors: ownedCopy(result.neighbors, Int32Array, 'neighbors'),
      hull: ownedCopy(result.hull, Uint32Array, 'hull'),
      triangles: ownedCopy(result.triangles, Uint32Array, 'triangles'),
      vertices: ownedCopy(result.vertices, Uint32Array, 'vertices'),
      representative: ownedCopy(result.representative, Uint32Array, 'representative'),
    };
    // The worker keeps copies for the Voronoi diagram; the page gets the originals.
    tetrahedralization = {
      key: id, xyz: xyz.slice(), voronoi: null,
      triangulation: { dimension: result.dimension, furthestSite, ...Object.fromEntries(Object.entries(owned).map(([k, v]) => [k, v.slice()])) },
    };
    const d0 = performance.now();
    const drawing = tetrahedraDrawing(xyz, { dimension: result.dimension, ...owned });
    const drawingMs = performance.now() - d0;
    const drawingBuffers = Object.values(drawing).filter(ArrayBuffer.isView).map((a) => a.buffer);
    self.postMessage(
      { type: 'result', id, key: id, n: xyz.length / 3, xyz, dimension: result.dimension, furthestSite, ...owned, duplicateCount: result.duplicateCount, ms, genMs, drawing, drawingMs },
      [xyz.buffer, ...Object.values(owned).map((a) => a.buffer), ...drawingBuffers],
    );
  });
}

/** The tetrahedralization `key` kept here (or rebuilt from `points`), or null after a 'stale' answer. */
function keptTetrahedralization(id, key, points) {
  if (tetrahedralization?.key === key) return tetrahedralization;
  if (points) {
    const { xyz, ...triangulation } = points;
    tetrahedralization = { key, xyz, triangulation, voronoi: null };
    return tetrahedralization;
  }
  self.postMessage({ type: 'error', id, kind: 'stale', message: 'the worker no longer has this tetrahedralization' });
  return null;
}

function voronoi3Job({ id, key, points }) {
  return withHullkit(id, (hullkit) => {
    const kept = keptTetrahedralization(id, key, points);
    if (!kept) return;
    const t0 = performance.now();
    kept.voronoi ??= hullkit.voronoi3(kept.xyz, kept.triangulation);
    const ms = performance.now() - t0;
    const volume = kept.voronoi.volume.slice();
    const tetrahedronVertex = kept.voronoi.tetrahedronVertex.slice();
    self.postMessage(
      { type: 'result', id, key, volume, tetrahedronVertex, vertexCount: kept.voronoi.vertices.length / 3, faceCount: kept.voronoi.facePoints.length / 2, ms },
      [volume.buffer, tetrahedronVertex.buffer],
    );
  });
}

/**
 * One point's Voronoi cell: its distinct vertices (x y z), each face as a run of corners into them
 * (`faceOffsets`, `faceCorners`, counter-clockwise seen from outside the cell), which faces are
 * bounded, and the point across each face (its Delaunay neighbours).
 */
function cell3Job({ id, key, point }) {
  return withHullkit(id, () => {
    const kept = keptTetrahedralization(id, key, null);
    if (!kept) return;
    const v = kept.voronoi;
    if (!v) throw new Error('the Voronoi diagram has not been computed');
    if (!Number.isInteger(point) || point < 0 || point >= v.volume.length) throw new Error(`no point ${point}`);
    const local = new Map();
    const coords = [];
    const offsets = [0];
    const corners = [];
    const bounded = [];
    const neighbours = [];
    for (let f = v.cellOffsets[point]; f < v.cellOffsets[point + 1]; f++) {
      const face = v.cellFaces[f];
      const [p, q] = [v.facePoints[2 * face], v.facePoints[2 * face + 1]];
      const ring = [];
      for (let c = v.faceOffsets[face]; c < v.faceOffsets[face + 1]; c++) {
        const w = v.faceVertices[c];
        if (!local.has(w)) {
          local.set(w, coords.length / 3);
          coords.push(v.vertices[3 * w], v.vertices[3 * w + 1], v.vertices[3 * w + 2]);
        }
        ring.push(local.get(w));
      }
      // Counter-clockwise seen from q: from outside the cell of p, from inside the cell of q.
      if (point === q) ring.reverse();
      corners.push(...ring);
      offsets.push(corners.length);
      bounded.push(v.faceBounded[face]);
      neighbours.push(point === p ? q : p);
    }
    const out = {
      type: 'result', id, key, point, volume: v.volume[point], bounded: Number.isFinite(v.volume[point]),
      vertices: Float64Array.from(coords), faceOffsets: Uint32Array.from(offsets), faceCorners: Uint32Array.from(corners),
      faceBounded: Uint8Array.from(bounded), neighbours: Uint32Array.from(neighbours),
    };
    self.postMessage(out, [out.vertices.buffer, out.faceOffsets.buffer, out.faceCorners.buffer, out.faceBounded.buffer, out.neighbours.buffer]);
  });
}
