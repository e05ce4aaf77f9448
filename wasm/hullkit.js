// hullkit for JavaScript: the WebAssembly build of the C++ core behind plain functions that take
// typed arrays and return typed arrays the caller owns. Runs in Node (>= 20), browsers and workers.
import createHullkitCore from '../build/wasm/hullkit_core.mjs';

const ALGORITHMS = ['quickhull', 'giftwrap'];
const EPSILONS = ['exact', 'seed'];
const HULL_OPTIONS = ['algorithm', 'epsilon', 'mergeCoplanar'];

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
  return Object.freeze({
    hull: (xyz, options) => hull(core, xyz, options),
    verify: (xyz, result) => verify(core, xyz, result),
    algorithms: Object.freeze([...ALGORITHMS]),
  });
}

export class HullkitError extends Error {
  constructor(message, { pointIndex } = {}) {
    super(message);
    this.name = 'HullkitError';
    if (pointIndex !== undefined && pointIndex >= 0) this.pointIndex = pointIndex;
  }
}

function hull(core, xyz, options = {}) {
  const points = toFloat64(xyz, 'hull');
  const { algorithm = 'quickhull', epsilon = 'exact', mergeCoplanar = false } = checkOptions(options, HULL_OPTIONS, 'hull');
  if (!ALGORITHMS.includes(algorithm)) {
    throw new HullkitError(`hull: unknown algorithm "${algorithm}" (known: ${ALGORITHMS.join(', ')})`);
  }
  if (!EPSILONS.includes(epsilon)) {
    throw new HullkitError(`hull: unknown epsilon "${epsilon}" (known: ${EPSILONS.join(', ')})`);
  }
  if (typeof mergeCoplanar !== 'boolean') {
    throw new HullkitError(`hull: mergeCoplanar must be true or false, got ${String(mergeCoplanar)}`);
  }

  const count = points.length / 3;
  const address = copyIn(core, points, 'hull');
  let result;
  try {
    result = core.hullFromHeap(address, count, algorithm, epsilon === 'seed', mergeCoplanar);
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

/** Copies `array` (a typed array) into a fresh malloc'ed block; returns its address. */
function copyIn(core, array, where) {
  const bytes = Math.max(array.byteLength, 8);
  const address = core._malloc(bytes);
  if (!address) throw new HullkitError(`${where}: cannot allocate ${bytes} bytes`);
  // HEAP views are re-read after malloc: memory growth replaces the buffer behind old views.
  new array.constructor(core.HEAPU8.buffer, address, array.length).set(array);
  return address;
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

function toUint32(values, where) {
  if (values instanceof Uint32Array) return values;
  if (values == null || typeof values.length !== 'number' || typeof values === 'string') {
    throw new TypeError(`${where} must be a Uint32Array or an array of indices`);
  }
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    if (!Number.isInteger(v) || v < 0 || v > 0xffffffff) throw new HullkitError(`${where}: entry ${i} (${v}) is not a valid index`);
  }
  return Uint32Array.from(values);
}

function toFloat64(xyz, where) {
  let points = xyz;
  if (!(xyz instanceof Float64Array)) {
    if (xyz == null || typeof xyz.length !== 'number' || typeof xyz === 'string') {
      throw new TypeError(`${where}: points must be a Float64Array (or an array of numbers) x0 y0 z0 x1 y1 z1 ...`);
    }
    points = Float64Array.from(xyz);
  }
  if (points.length % 3 !== 0) {
    throw new HullkitError(`${where}: ${points.length} coordinates is not a whole number of 3D points`);
  }
  if (points.length / 3 > 0xffffffff) {
    throw new HullkitError(`${where}: too many points (${points.length / 3}), at most 4294967295`);
  }
  return points;
}

function checkOptions(options, known, where) {
  if (options === undefined || options === null) return {};
  if (typeof options !== 'object') throw new TypeError(`${where}: options must be an object`);
  for (const key of Object.keys(options)) {
    if (!known.includes(key)) {
      throw new HullkitError(`${where}: unknown option "${key}" (known: ${known.join(', ')})`);
    }
  }
  return options;
}
