// Shared by the hullkit JS modules: the error class, argument checks and copies into the wasm heap.
// Not part of the public API (hullkit.js re-exports HullkitError).

export class HullkitError extends Error {
  constructor(message, { pointIndex, queryIndex } = {}) {
    super(message);
    this.name = 'HullkitError';
    if (pointIndex !== undefined && pointIndex >= 0) this.pointIndex = pointIndex;
    if (queryIndex !== undefined && queryIndex >= 0) this.queryIndex = queryIndex;
  }
}

/** Copies `array` (a typed array) into a fresh malloc'ed block; returns its address. */
export function copyIn(core, array, where) {
  const bytes = Math.max(array.byteLength, 8);
  const address = core._malloc(bytes);
  if (!address) throw new HullkitError(`${where}: cannot allocate ${bytes} bytes`);
  // HEAP views are re-read after malloc: memory growth replaces the buffer behind old views.
  new array.constructor(core.HEAPU8.buffer, address, array.length).set(array);
  return address;
}

export function toUint32(values, where) {
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

/**
 * Points as a Float64Array of `dimension` coordinates per point (a plain array of numbers is
 * copied into one); checks the length is a whole number of points and the count fits uint32.
 */
export function toFloat64(coordinates, where, dimension = 3) {
  const layout = dimension === 2 ? 'x0 y0 x1 y1 ...' : 'x0 y0 z0 x1 y1 z1 ...';
  let points = coordinates;
  if (!(coordinates instanceof Float64Array)) {
    if (coordinates == null || typeof coordinates.length !== 'number' || typeof coordinates === 'string') {
      throw new TypeError(`${where}: points must be a Float64Array (or an array of numbers) ${layout}`);
    }
    points = Float64Array.from(coordinates);
  }
  if (points.length % dimension !== 0) {
    throw new HullkitError(`${where}: ${points.length} coordinates is not a whole number of ${dimension}D points`);
  }
  if (points.length / dimension > 0xffffffff) {
    throw new HullkitError(`${where}: too many points (${points.length / dimension}), at most 4294967295`);
  }
  return points;
}

export function checkOptions(options, known, where) {
  if (options === undefined || options === null) return {};
  if (typeof options !== 'object') throw new TypeError(`${where}: options must be an object`);
  for (const key of Object.keys(options)) {
    if (!known.includes(key)) {
      throw new HullkitError(`${where}: unknown option "${key}" (known: ${known.join(', ')})`);
    }
  }
  return options;
}

/** Whether `value` is an ArrayBuffer or a view on one (typed array, DataView): bytes for a reader. */
export const isBytes = (value) => value instanceof ArrayBuffer || ArrayBuffer.isView(value);

/** The bytes of a Uint8Array, any other typed array or DataView, or an ArrayBuffer (no copy). */
export function bytesOf(value) {
  if (value instanceof Uint8Array) return value;
  if (value instanceof ArrayBuffer) return new Uint8Array(value);
  return new Uint8Array(value.buffer, value.byteOffset, value.byteLength);
}

/**
 * A recorded gift wrap copied out of wasm memory and deleted (hullkit.giftwrapTrace and
 * delaunayGiftwrapTrace): {kinds, args, kindNames, triangles, dimension}, or its error thrown.
 */
export function takeTrace(trace, kindNames, where) {
  try {
    if (!trace.ok()) throw new HullkitError(`${where}: ${trace.error}`, { pointIndex: trace.errorPoint() });
    return {
      kinds: trace.kindsView().slice(),
      args: trace.argsView().slice(),
      kindNames,
      triangles: trace.trianglesView().slice(),
      dimension: trace.dimension,
    };
  } finally {
    trace.delete();
  }
}
