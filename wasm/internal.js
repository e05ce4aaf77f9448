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

/** An Int32Array (used as it is) from an array-like of integers, or a TypeError. */
export function toInt32(values, where) {
  if (values instanceof Int32Array) return values;
  if (values == null || typeof values.length !== 'number' || typeof values === 'string') {
    throw new TypeError(`${where} must be an Int32Array or an array of integers`);
  }
  return Int32Array.from(values);
}

/** A value as it may appear in a message: its type, and short values themselves. */
function described(value) {
  if (value === null) return 'null';
  if (Array.isArray(value)) return `an array of ${value.length}`;
  if (typeof value === 'string') return `the string ${JSON.stringify(value.length > 20 ? `${value.slice(0, 20)}...` : value)}`;
  if (typeof value === 'object') return 'an object';
  return `${typeof value} ${String(value)}`;
}

/**
 * Points as a Float64Array of `dimension` (2 or 3) coordinates per point, from what callers have:
 *  - a flat Float64Array x0 y0 z0 x1 y1 z1 ... (x0 y0 x1 y1 ... in 2D): used as it is, no copy (the
 *    fast path);
 *  - a flat array (or other typed array) of numbers: copied into one;
 *  - an array of points, as quickhull3d, three.js and delaunator's `Delaunator.from` take them:
 *    [x, y, z] arrays (or typed arrays), or objects with numeric x, y (and z) properties, such as
 *    three.js's Vector3 (Vector2 in 2D; other properties are ignored): flattened into one.
 * Anything else is a TypeError or a HullkitError saying what was found where and what to pass; the
 * count must fit uint32. Non-finite numbers are passed on (the core names their point).
 */
export function toFloat64(coordinates, where, dimension = 3) {
  // Above 3 dimensions points are arrays of `dimension` numbers (no named axes for objects).
  const axes = dimension === 2 ? ['x', 'y'] : dimension === 3 ? ['x', 'y', 'z'] : null;
  const flatLayout = dimension === 2 ? 'x0 y0 x1 y1 ...' : dimension === 3 ? 'x0 y0 z0 x1 y1 z1 ...' : `${dimension} numbers per point`;
  const pointLayout = axes ? `[${axes.join(', ')}] or {${axes.join(', ')}}` : `[${dimension} numbers]`;
  const what = `pass a flat Float64Array (or array of numbers) ${flatLayout}, or an array of points ${pointLayout}`;
  let points = coordinates;
  if (!(coordinates instanceof Float64Array)) {
    if (coordinates == null || typeof coordinates.length !== 'number' || typeof coordinates === 'string') {
      throw new TypeError(`${where}: points must be a Float64Array (or an array of numbers) ${flatLayout}, or an array of points ${pointLayout}`);
    }
    const first = coordinates[0];
    points = coordinates.length > 0 && first !== null && typeof first === 'object' && !ArrayBuffer.isView(coordinates)
      ? flattenPoints(coordinates, where, axes, what, dimension)
      : flatNumbers(coordinates, where, what);
  }
  if (points.length % dimension !== 0) {
    throw new HullkitError(`${where}: ${points.length} coordinates is not a whole number of ${dimension}D points (${flatLayout}); ` +
      `or pass an array of points ${pointLayout}`);
  }
  if (points.length / dimension > 0xffffffff) {
    throw new HullkitError(`${where}: too many points (${points.length / dimension}), at most 4294967295`);
  }
  return points;
}

/** A flat array-like of numbers (a typed array, or an array whose entries must all be numbers) copied. */
function flatNumbers(values, where, what) {
  if (!ArrayBuffer.isView(values)) {
    for (let i = 0; i < values.length; i++) {
      if (typeof values[i] !== 'number') {
        throw new HullkitError(`${where}: entry ${i} of the flat coordinate array is ${described(values[i])}, not a number; ${what}`);
      }
    }
  }
  return Float64Array.from(values);
}

/** An array of points ([x, y, z] arrays or typed arrays, or {x, y, z} objects when `axes` names them) flattened, d per point. */
function flattenPoints(points, where, axes, what, d = axes.length) {
  const out = new Float64Array(d * points.length);
  const fail = (i, problem) => new HullkitError(`${where}: points[${i}]${problem}; ${what}`, { pointIndex: i });
  for (let i = 0; i < points.length; i++) {
    const p = points[i];
    if (Array.isArray(p) || ArrayBuffer.isView(p)) {
      if (p.length !== d) {
        throw new HullkitError(`${where}: points[${i}] has ${p.length} coordinate${p.length === 1 ? '' : 's'}, expected ${d}`, { pointIndex: i });
      }
      for (let k = 0; k < d; k++) {
        const v = p[k];
        if (typeof v !== 'number') throw fail(i, `[${k}] is ${described(v)}, not a number`);
        out[d * i + k] = v;
      }
    } else if (axes && p !== null && typeof p === 'object') {
      for (let k = 0; k < d; k++) {
        const v = p[axes[k]];
        if (typeof v !== 'number') throw fail(i, ` has no numeric ${axes[k]} (${axes[k]} is ${v === undefined ? 'missing' : described(v)})`);
        out[d * i + k] = v;
      }
    } else {
      throw fail(i, ` is ${described(p)}, not a point`);
    }
  }
  return out;
}

/**
 * Flat coordinates, `dimension` per point, as a Float64Array (see toFloat64), refusing a plain
 * array whose entries are not numbers: Float64Array.from would turn [x, y, z] or {x, y, z} entries
 * into NaN, and the core would then blame "point 0" (or "query 0") for a non-finite coordinate
 * instead of the layout. `what` is 'points' (the argument named xyz or xy) or 'queries'.
 */
export function flatCoordinates(values, where, dimension, what = 'points') {
  const axes = dimension === 2 ? ['x', 'y'] : ['x', 'y', 'z'];
  const name = what === 'queries' ? 'queries' : axes.join('');
  if (Array.isArray(values)) {
    for (let i = 0; i < values.length; i++) {
      const v = values[i];
      if (typeof v === 'number') continue;
      const got = Array.isArray(v) || ArrayBuffer.isView(v)
        ? `an array of arrays — flatten it (${name}.flat())`
        : v !== null && typeof v === 'object'
          ? `an array of objects — flatten it (points.flatMap((p) => [${axes.map((a) => `p.${a}`).join(', ')}]))`
          : `entry ${i} is ${v === null ? 'null' : typeof v} (${String(v)})`;
      throw new TypeError(`${where}: ${name} must be a Float64Array or an array of numbers ` +
        `(${axes.join(' ')} per ${what === 'queries' ? 'query' : 'point'}); got ${got}`);
    }
  }
  return toFloat64(values, what === 'queries' ? `${where}: queries` : where, dimension);
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

// ---------------------------------------------------------------- triangulations handed back

/**
 * A triangulation's `representative` checked against `count` points: one entry per point, each
 * the point itself or a lower one that stands for itself. Another length means a triangulation of
 * other points.
 */
export function checkRepresentative(values, count, where) {
  const representative = toUint32(values, `${where}: representative`);
  if (representative.length !== count) {
    throw new HullkitError(`${where}: representative has ${representative.length} entries for ${count} points (the triangulation is of other points)`);
  }
  for (let i = 0; i < count; i++) {
    const r = representative[i];
    if (r > i || representative[r] !== r) throw new HullkitError(`${where}: representative[${i}] = ${r} is not a lower point that stands for itself`);
  }
  return representative;
}

/** `corners` (point indices, the array called `name`) in range and never a duplicate point. */
export function checkCorners(corners, representative, name, where) {
  const count = representative.length;
  for (let i = 0; i < corners.length; i++) {
    const v = corners[i];
    if (v >= count) throw new HullkitError(`${where}: ${name}[${i}] = ${v} but there are ${count} points`);
    if (representative[v] !== v) throw new HullkitError(`${where}: ${name}[${i}] = ${v} is a duplicate of point ${representative[v]}`);
  }
  return corners;
}

// ---------------------------------------------------------------- point location (locate, locate3)

const LOCATE_OPTIONS = ['barycentric', 'nearest'];

/** The options of locate and locate3: {barycentric, nearest}, each true or false (default false). */
export function locateOptions(options, where) {
  const checked = checkOptions(options, LOCATE_OPTIONS, where);
  const flags = {};
  for (const name of LOCATE_OPTIONS) {
    const value = checked[name] ?? false;
    if (typeof value !== 'boolean') throw new HullkitError(`${where}: ${name} must be true or false, got ${String(value)}`);
    flags[name] = value;
  }
  return flags;
}

/**
 * The part locate and locate3 share once their arguments are checked. `inHeap(run)` returns
 * `run(...heap)` called with the points and the triangulation in the WebAssembly heap (and frees
 * them after); the queries (a flat Float64Array, `dimension` per query) join them for the core's
 * `locateFromHeap(...heap, queriesAddress, queryCount, barycentric, nearest)`. Its result is
 * deleted once taken: an error is thrown as a HullkitError with the query to blame in `queryIndex`;
 * otherwise the arrays are copied out as {[cell]: Int32Array, barycentric?, nearest?}.
 */
export function locateInHeap(core, { where, cell, dimension, queries, flags }, inHeap, locateFromHeap) {
  const result = inHeap((...heap) => {
    const address = copyIn(core, queries, where);
    try {
      return locateFromHeap(...heap, address, queries.length / dimension, flags.barycentric, flags.nearest);
    } finally {
      core._free(address);
    }
  });
  try {
    if (result.error) throw new HullkitError(`${where}: ${result.error}`, { queryIndex: result.errorQuery() });
    const out = { [cell]: result[`${cell}View`]().slice() };
    if (flags.barycentric) out.barycentric = result.barycentricView().slice();
    if (flags.nearest) out.nearest = result.nearestView().slice();
    return out;
  } finally {
    result.delete();
  }
}
