// hullkit.checkRoute and RouteChecker: the JS side of native/include/hullkit/route.hpp.
//
// The scene is the same object as the JSON that `hullkit route` reads. It crosses into wasm as
// JSON text; meshes given as bytes (Uint8Array / ArrayBuffer) or through options.files go in as
// named blobs; routes to re-check go in as a Float64Array, or as JSON text when their waypoints
// carry rotations ({position, rotation}, parsed by the scene reader's rules). The report is the
// CLI's JSON, parsed.
import { HullkitError, bytesOf, checkOptions, copyIn, isBytes, toFloat64 } from './internal.js';

const CHECK_OPTIONS = ['samples', 'clearance'];
const SCENE_OPTIONS = ['files'];
const ONE_SHOT_OPTIONS = [...CHECK_OPTIONS, ...SCENE_OPTIONS];

/** [[x0, y0, z0], ...] from a flat typed array of triples (vertices, triangles, route). */
function triples(flat, path, where) {
  if (flat instanceof ArrayBuffer || flat instanceof DataView) {
    throw new HullkitError(`${where}: scene: ${path}: expected numbers, got ${flat.constructor.name}`);
  }
  if (flat.length % 3 !== 0) throw new HullkitError(`${where}: scene: ${path}: ${flat.length} numbers is not a whole number of triples`);
  const out = new Array(flat.length / 3);
  for (let i = 0; i < out.length; i++) out[i] = [flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]];
  return out;
}

/** A shallow copy of a part or obstacle: mesh bytes set aside in `blobs` (named by their path), typed arrays nested. */
function plainShape(shape, path, blobs, where) {
  if (shape === null || typeof shape !== 'object' || Array.isArray(shape)) return shape;
  const out = { ...shape };
  if (isBytes(shape.mesh)) {
    blobs.set(`${path}.mesh`, bytesOf(shape.mesh));
    out.mesh = `${path}.mesh`;
  }
  for (const key of ['vertices', 'triangles']) {
    if (isBytes(shape[key])) out[key] = triples(shape[key], `${path}.${key}`, where);
  }
  return out;
}

/**
 * The path of the first non-finite number in `value` ("" if none). JSON would silently turn it
 * into null, so the scene is searched (only when its JSON text has a null at all) to name it.
 */
function nonFinitePath(value, path) {
  if (typeof value === 'number') return Number.isFinite(value) ? '' : path;
  if (value === null || typeof value !== 'object' || value instanceof ArrayBuffer || value instanceof DataView) return '';
  const isList = Array.isArray(value) || ArrayBuffer.isView(value);
  for (const [key, entry] of isList ? Array.from(value).entries() : Object.entries(value)) {
    const found = nonFinitePath(entry, isList ? `${path}[${key}]` : path ? `${path}.${key}` : key);
    if (found) return found;
  }
  return '';
}

/**
 * The scene as JSON text for the C++ parser (the same format as the CLI's scene files), with mesh
 * bytes set aside in `blobs`. Only the shape lists are copied (shallowly): a scene of 1e5
 * triangles costs one JSON.stringify, not a walk over every number.
 */
function sceneText(scene, blobs, where) {
  const plain = { ...scene };
  if (isBytes(scene.route)) plain.route = triples(scene.route, 'route', where);
  if (Array.isArray(scene.obstacles)) plain.obstacles = scene.obstacles.map((shape, i) => plainShape(shape, `obstacles[${i}]`, blobs, where));
  if (scene.traverse && typeof scene.traverse === 'object' && Array.isArray(scene.traverse.parts)) {
    plain.traverse = { ...scene.traverse, parts: scene.traverse.parts.map((shape, i) => plainShape(shape, `traverse.parts[${i}]`, blobs, where)) };
  }
  const text = JSON.stringify(plain);
  if (text.includes('null')) {
    const path = nonFinitePath(plain, '');
    if (path) {
      const value = path.split(/\.|\[/).reduce((v, k) => v?.[k.replace(']', '')], plain);
      throw new HullkitError(`${where}: scene: ${path}: expected a finite number, got ${value}`);
    }
  }
  return text;
}

/** Fresh handle with the scene loaded; throws HullkitError (and frees the handle) on a bad scene. */
function loadScene(core, scene, files, requireRoute, where) {
  if (scene === null || typeof scene !== 'object' || Array.isArray(scene)) {
    throw new TypeError(`${where}: the scene must be an object {traverse, route, obstacles, margin}`);
  }
  if (files != null && typeof files !== 'object') throw new TypeError(`${where}: options.files must be an object {name: Uint8Array}`);
  const blobs = new Map();
  const text = sceneText(scene, blobs, where);
  const entries = files instanceof Map ? [...files] : Object.entries(files ?? {});
  for (const [name, bytes] of entries) {
    if (!isBytes(bytes)) throw new TypeError(`${where}: options.files["${name}"] must be a Uint8Array or an ArrayBuffer`);
    if (!blobs.has(name)) blobs.set(name, bytesOf(bytes));
  }
  const handle = new core.RouteCheckerHandle();
  try {
    for (const [name, bytes] of blobs) handle.addFile(name, bytes);
    const error = handle.load(text, 'scene', requireRoute);
    if (error) throw new HullkitError(`${where}: ${error}`);
    return handle;
  } catch (error) {
    handle.delete();
    throw error;
  }
}

/** A waypoint with an orientation, {position, rotation}: such routes go to the C++ parser as JSON. */
function isPose(waypoint) {
  return waypoint !== null && typeof waypoint === 'object' && !Array.isArray(waypoint) && !ArrayBuffer.isView(waypoint);
}

/** Waypoints as a flat Float64Array from [[x, y, z], ...] or a flat array / Float64Array. */
function routeArray(route, where) {
  if (route == null || typeof route.length !== 'number' || typeof route === 'string') {
    throw new TypeError(`${where}: the route must be an array of waypoints [[x, y, z] or {position, rotation}, ...] or a Float64Array x0 y0 z0 x1 ...`);
  }
  let flat = route;
  if (!(route instanceof Float64Array) && route.length > 0 && typeof route[0] === 'object') {
    flat = new Float64Array(3 * route.length);
    for (let i = 0; i < route.length; i++) {
      const p = route[i];
      if (p == null || p.length !== 3) {
        throw new HullkitError(`${where}: route[${i}]: expected 3 numbers [x, y, z] or {"position": [x, y, z], "rotation": ...}`);
      }
      flat[3 * i] = p[0];
      flat[3 * i + 1] = p[1];
      flat[3 * i + 2] = p[2];
    }
  }
  const points = toFloat64(flat, where);
  for (let i = 0; i < points.length; i++) {
    if (!Number.isFinite(points[i])) {
      throw new HullkitError(`${where}: route[${Math.floor(i / 3)}][${i % 3}]: expected a finite number, got ${points[i]}`);
    }
  }
  if (points.length < 6) throw new HullkitError(`${where}: route: needs at least 2 waypoints, got ${points.length / 3}`);
  return points;
}

function checkValues({ samples = 0, clearance = true }, where) {
  if (!Number.isInteger(samples) || samples < 0 || samples > 1e6) {
    throw new HullkitError(`${where}: samples must be an integer from 0 to 1000000, got ${String(samples)}`);
  }
  if (typeof clearance !== 'boolean') throw new HullkitError(`${where}: clearance must be true or false, got ${String(clearance)}`);
  return { samples, clearance };
}

/** Runs one check on a loaded handle; `route` undefined means the scene's own route. */
function runCheck(core, handle, route, options, where) {
  const { samples, clearance } = checkValues(options, where);
  let text;
  if (route === undefined) {
    if (handle.routeWaypoints() === 0) throw new HullkitError(`${where}: no route given and the scene has none`);
    text = handle.check(0, 0, clearance, samples);
  } else if (Array.isArray(route) && route.some(isPose)) {
    const json = JSON.stringify(route);
    if (json.includes('null')) {
      const path = nonFinitePath(route, 'route');
      if (path) throw new HullkitError(`${where}: ${path}: expected a finite number`);
    }
    text = handle.checkJson(json, where, clearance, samples);
  } else {
    const points = routeArray(route, where);
    const address = copyIn(core, points, where);
    try {
      text = handle.check(address, points.length / 3, clearance, samples);
    } finally {
      core._free(address);
    }
  }
  if (!text) {
    const message = handle.error();  // the route parser's messages start with `where` already
    throw new HullkitError(message.startsWith(`${where}: `) ? message : `${where}: ${message}`);
  }
  return JSON.parse(text);
}

/**
 * Checks the scene's route once: the report object of `hullkit route` (see hullkit.d.ts).
 * options: {samples, clearance, files}.
 */
export function checkRoute(core, scene, options = {}) {
  const where = 'checkRoute';
  const { files, ...rest } = checkOptions(options, ONE_SHOT_OPTIONS, where);
  const handle = loadScene(core, scene, files, true, where);
  try {
    return runCheck(core, handle, undefined, rest, where);
  } finally {
    handle.delete();
  }
}

// A checker that is garbage-collected without delete() still frees its wasm memory.
const finalizer = typeof FinalizationRegistry === 'function' ? new FinalizationRegistry((handle) => handle.delete()) : null;
const disposeSymbol = typeof Symbol.dispose === 'symbol' ? Symbol.dispose : Symbol.for('nodejs.dispose');

/**
 * A scene prepared once (parts' hulls, the obstacles' BVH) for many checks of different routes.
 * Constructed as `new hullkit.RouteChecker(scene, options)`; free it with delete() or `using`.
 */
export class RouteChecker {
  #core;
  #handle;

  constructor(core, scene, options = {}) {
    const { files } = checkOptions(options, SCENE_OPTIONS, 'RouteChecker');
    this.#core = core;
    this.#handle = loadScene(core, scene, files, false, 'RouteChecker');
    finalizer?.register(this, this.#handle, this);
  }

  #live(where) {
    if (!this.#handle) throw new HullkitError(`RouteChecker.${where}: the checker was deleted`);
    return this.#handle;
  }

  /** Seconds spent preparing the scene (hulls, BVH). */
  get buildSeconds() {
    return this.#live('buildSeconds').buildSeconds();
  }

  /** Checks `route` (or the scene's own route when omitted): the report, as checkRoute returns it. */
  check(route, options = {}) {
    const handle = this.#live('check');
    return runCheck(this.#core, handle, route ?? undefined, checkOptions(options, CHECK_OPTIONS, 'RouteChecker.check'), 'RouteChecker.check');
  }

  /** Frees the wasm memory; later calls throw. Calling it twice is harmless. */
  delete() {
    if (!this.#handle) return;
    finalizer?.unregister(this);
    this.#handle.delete();
    this.#handle = null;
  }

  /** True once delete() was called. */
  get deleted() {
    return this.#handle === null;
  }

  [disposeSymbol]() {
    this.delete();
  }
}
