// Web Worker: generates (or parses) the points and computes their convex hull
// with the hullkit WebAssembly module, so that the page stays responsive.
//
// worker -> main  {type: 'ready', algorithms}                  once the module is loaded
//                 {type: 'load-error', message}                if it cannot be loaded
// main -> worker  {type: 'compute', id, distribution, n, seed, algorithm?, text?}
// worker -> main  {type: 'result', id, n, dimension, xyz, triangles, vertices, edges,
//                  volume, area, hullMs, genMs, workerMs}        (buffers transferred)
//                 {type: 'error', id, kind, message, n, xyz?}   (xyz transferred when available)
//   kind: 'input'    the input was rejected (by the library or the text parser)
//         'load'     the hullkit module could not be loaded / instantiated
//         'internal' anything else (wasm trap, malformed result, bug)
import { generatePoints, parsePoints } from './distributions.js';

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
    self.postMessage({ type: 'ready', algorithms });
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
  if (msg && msg.type === 'compute') {
    compute(msg).catch((err) => {
      // Should not happen (compute catches everything), but never drop it.
      self.postMessage({ type: 'error', id: msg.id, kind: 'internal', message: describe(err), n: msg.n });
    });
  }
};

async function compute({ id, distribution, n, seed, algorithm, text }) {
  const w0 = performance.now();
  let xyz;
  try {
    xyz = distribution === 'custom' ? parsePoints(text ?? '') : generatePoints(distribution, n, seed);
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

  let result;
  const h0 = performance.now();
  try {
    result = hullkit.hull(xyz, algorithm ? { algorithm } : undefined);
  } catch (err) {
    postError(id, isInputError(err) ? 'input' : 'internal', describe(err), xyz);
    return;
  }
  const hullMs = performance.now() - h0;

  let triangles, vertices, edges, dimension;
  try {
    triangles = ownedCopy(result.triangles, Uint32Array, 'triangles');
    vertices = ownedCopy(result.vertices, Uint32Array, 'vertices');
    validate(triangles, vertices, count);
    ({ edges, dimension } = hullEdges(triangles, vertices, count, result.dimension));
  } catch (err) {
    postError(id, 'internal', `unexpected hull result: ${describe(err)}`, xyz);
    return;
  }

  const workerMs = performance.now() - w0;
  self.postMessage(
    {
      type: 'result', id, n: count, dimension, xyz, triangles, vertices, edges,
      volume: Number(result.volume), area: Number(result.area),
      hullMs, genMs, workerMs,
    },
    [xyz.buffer, triangles.buffer, vertices.buffer, edges.buffer],
  );
}

function postError(id, kind, message, xyz) {
  self.postMessage({ type: 'error', id, kind, message, n: Math.floor(xyz.length / 3), xyz }, [xyz.buffer]);
}

function describe(err) {
  if (err instanceof Error) return err.message || String(err);
  return String(err);
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

/**
 * The edges to draw, as a flat Uint32Array [a0, b0, a1, b1, ...], and the
 * dimension of the hull (taken from the result when the API reports it):
 *   3  closed surface: every edge is shared by two triangles; all edges
 *   2  flat polygon (coplanar input): the boundary, i.e. edges used once
 *   1  segment between the two vertices;  0 / -1  none
 */
function hullEdges(triangles, vertices, n, reportedDimension) {
  const m = triangles.length;
  const keys = new Float64Array(m); // lo * n + hi < 2^53 for n <= 2^26
  for (let t = 0; t < m; t += 3) {
    for (let k = 0; k < 3; k++) {
      const a = triangles[t + k];
      const b = triangles[t + (k === 2 ? 0 : k + 1)];
      keys[t + k] = a < b ? a * n + b : b * n + a;
    }
  }
  keys.sort();
  const unique = [];
  const boundary = [];
  for (let i = 0; i < m; ) {
    let j = i + 1;
    while (j < m && keys[j] === keys[i]) j++;
    unique.push(keys[i]);
    if (j - i === 1) boundary.push(keys[i]);
    i = j;
  }
  let dimension;
  if (Number.isInteger(reportedDimension)) dimension = reportedDimension;
  else if (m > 0) dimension = boundary.length === 0 ? 3 : 2;
  else dimension = vertices.length >= 2 ? 1 : vertices.length - 1;

  let chosen = [];
  if (dimension === 3) chosen = unique;
  else if (dimension === 2) chosen = boundary;
  const segment = dimension === 1 && vertices.length >= 2;
  const edges = new Uint32Array(segment ? 2 : 2 * chosen.length);
  if (segment) {
    edges[0] = vertices[0];
    edges[1] = vertices[vertices.length - 1];
  } else {
    for (let i = 0; i < chosen.length; i++) {
      const lo = Math.floor(chosen[i] / n);
      edges[2 * i] = lo;
      edges[2 * i + 1] = chosen[i] - lo * n;
    }
  }
  return { edges, dimension };
}
