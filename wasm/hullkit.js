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
  const bytes = Math.max(points.byteLength, 8);
  const address = core._malloc(bytes);
  if (!address) throw new HullkitError(`hull: cannot allocate ${bytes} bytes for ${count} points`);
  let result;
  try {
    // HEAPF64 is re-read after malloc: memory growth replaces the buffer behind old views.
    new Float64Array(core.HEAPF64.buffer, address, points.length).set(points);
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
