// hullkit.checkRoute and RouteChecker (wasm/route.js): the same reports as `hullkit route` on the
// same scenes, meshes as bytes and through options.files, checker reuse and delete, errors, and
// an informal timing of a 20-leg re-check against a ~1e5-triangle scene.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

import createHullkit, { HullkitError } from '../../wasm/hullkit.js';

const root = fileURLToPath(new URL('../..', import.meta.url));
const cli = process.env.HULLKIT_CLI ?? join(root, 'build/native/hullkit');
const data = join(root, 'tests/data/route');
const hullkit = await createHullkit();

/** A unit cube "cube" moved along `route`, a wall slab x in [3, 4] and a thin plate at x = 2.2. */
function cubeScene(route, margin = 0) {
  return {
    traverse: { parts: [{ name: 'cube', box: { min: [0, 0, 0], max: [1, 1, 1] } }] },
    route,
    obstacles: [
      { name: 'wall', box: { min: [3, -10, -10], max: [4, 10, 10] } },
      { name: 'plate', vertices: [[2.2, -5, -5], [2.2, 5, -5], [2.2, 0, 5]], triangles: [[0, 1, 2]] },
    ],
    margin,
  };
}

/** The CLI's report on `scene` (written to a scratch directory with `files` beside it). */
function cliReport(scene, args = [], files = {}) {
  assert.ok(existsSync(cli), `native CLI missing at ${cli}: run npm run build`);
  const dir = mkdtempSync(join(tmpdir(), 'hullkit-route-js-'));
  try {
    writeFileSync(join(dir, 'scene.json'), JSON.stringify(scene));
    for (const [name, bytes] of Object.entries(files)) writeFileSync(join(dir, name), bytes);
    const run = spawnSync(cli, ['route', join(dir, 'scene.json'), ...args], { encoding: 'utf8' });
    assert.ok(run.status === 0 || run.status === 1, `hullkit route failed (${run.status}): ${run.stderr}`);
    return JSON.parse(run.stdout);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

/**
 * Asserts two reports agree: the same verdicts, names, indices and flags, and numbers within
 * 1e-8 (relative above 1). The native CLI and the wasm module are compiled by different compilers
 * and standard libraries; first-contact brackets (width <= 1e-9) may then differ in their last
 * digits while both bracket the same contact. A start overlap may also name a different one of
 * the triangles already in contact (the core does not fix which one when several are).
 */
function assertSameReport(actual, expected, what = '') {
  const walk = (a, b, path) => {
    if (typeof b === 'number' && typeof a === 'number') {
      assert.ok(Math.abs(a - b) <= 1e-8 * Math.max(1, Math.abs(b)), `${what} ${path}: ${a} vs ${b}`);
      return;
    }
    if (b === null || typeof b !== 'object') {
      assert.equal(a, b, `${what} ${path}`);
      return;
    }
    assert.ok(a !== null && typeof a === 'object', `${what} ${path}: ${JSON.stringify(a)} vs ${JSON.stringify(b)}`);
    assert.deepEqual(Object.keys(a), Object.keys(b), `${what} ${path}: keys`);
    for (const key of Object.keys(b)) {
      if (key === 'triangle' && b.status === 'start-overlap') continue;
      walk(a[key], b[key], `${path}.${key}`);
    }
  };
  walk(verdicts(actual), verdicts(expected), 'report');
}

/** A report without its timings, which differ from run to run. */
const verdicts = ({ build_seconds, seconds, ...rest }) => {
  assert.equal(typeof build_seconds, 'number');
  assert.equal(typeof seconds, 'number');
  return rest;
};

/** Binary STL bytes of a box (12 triangles, as the scene's "box" would give). */
function binaryStlBox(min, max) {
  const corner = (c) => [0, 1, 2].map((axis) => ((c >> axis) & 1 ? max[axis] : min[axis]));
  const triangles = [0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6];
  const bytes = new Uint8Array(84 + 50 * 12);
  const view = new DataView(bytes.buffer);
  view.setUint32(80, 12, true);
  for (let t = 0; t < 12; t++) {
    for (let c = 0; c < 3; c++) {
      corner(triangles[3 * t + c]).forEach((x, axis) => view.setFloat32(84 + 50 * t + 12 + 12 * c + 4 * axis, x, true));
    }
  }
  return bytes;
}

test('checkRoute: the same report as hullkit route, on hand-worked scenes', () => {
  for (const [route, margin, args] of [
    [[[0, 0, 0], [5, 0, 0]], 0, []],
    [[[0, 0, 0], [0.5, 5, 0], [-1, 5, 3]], 0.25, []], // minima at the end of leg 0, the start of leg 1
    [[[0, 0, 0], [10, 0, 0], [10, 4, 0]], 0.1, ['--samples', '4']],
    [[[2.5, 0, 0], [2.5, 0, 5]], 0, ['--no-clearance']],
  ]) {
    const scene = cubeScene(route, margin);
    const options = {};
    if (args[0] === '--samples') options.samples = Number(args[1]);
    if (args[0] === '--no-clearance') options.clearance = false;
    assertSameReport(hullkit.checkRoute(scene, options), cliReport(scene, args), JSON.stringify(route));
  }
  // The thin plate: a hit at 1.2 of 10 that 4-step sampling misses (it only sees the wall).
  const report = hullkit.checkRoute(cubeScene([[0, 0, 0], [10, 0, 0]]), { samples: 4 });
  const [leg] = report.legs;
  assert.equal(leg.status, 'hit');
  assert.equal(leg.obstacle, 'plate');
  assert.ok(leg.fraction[0] <= 0.12 && 0.12 <= leg.fraction[1] && leg.fraction[1] - leg.fraction[0] <= 1e-9);
  assert.deepEqual(leg.sampled, { hit: true, fraction: 0.25 });
});

test('checkRoute: the crane scene with its meshes from options.files and as bytes', () => {
  const scene = JSON.parse(readFileSync(join(data, 'crane.json'), 'utf8'));
  const files = Object.fromEntries(['load.stl', 'vessel.obj', 'post.off'].map((name) => [name, new Uint8Array(readFileSync(join(data, name)))]));
  const expected = cliReport(scene, ['--samples', '20'], files);
  assertSameReport(hullkit.checkRoute(scene, { files, samples: 20 }), expected);
  // The same meshes handed in as bytes (an ArrayBuffer for one of them), and a Map of files.
  const inline = structuredClone(scene);
  inline.traverse.parts[0].mesh = files['load.stl'];
  inline.obstacles[2].mesh = files['vessel.obj'].slice().buffer;
  assertSameReport(hullkit.checkRoute(inline, { files: new Map([['post.off', files['post.off']]]), samples: 20 }), expected);
});

test('checkRoute: a binary STL part gives the same report as the box it encodes', () => {
  const box = cubeScene([[0, 0, 0], [5, 0, 0], [5, 6, 0]], 0.1);
  const stl = structuredClone(box);
  stl.traverse.parts[0] = { name: 'cube', mesh: binaryStlBox([0, 0, 0], [1, 1, 1]) };
  const a = verdicts(hullkit.checkRoute(box));
  const b = verdicts(hullkit.checkRoute(stl));
  assert.deepEqual(b, a);
  // Flat typed arrays for vertices, triangles and route are the same scene as nested arrays.
  const flat = structuredClone(box);
  flat.route = new Float64Array(box.route.flat());
  flat.obstacles[1].vertices = new Float64Array(box.obstacles[1].vertices.flat());
  flat.obstacles[1].triangles = new Uint32Array([0, 1, 2]);
  assert.deepEqual(verdicts(hullkit.checkRoute(flat)), a);
});

test('RouteChecker: one scene, many routes; delete and dispose', () => {
  const scene = cubeScene(undefined, 0.05);
  delete scene.route;
  const checker = new hullkit.RouteChecker(scene);
  assert.ok(checker.buildSeconds >= 0);
  const routes = [
    [[0, 0, 0], [5, 0, 0]],
    [[0, 0, 0], [0, 5, 0], [-3, 5, 2]],
    [[-4, 0, 0], [1, 0, 0], [1, 8, 0], [10, 8, 0]],
  ];
  for (let round = 0; round < 2; round++) {
    for (const route of routes) {
      const expected = verdicts(hullkit.checkRoute({ ...scene, route }, { samples: 8 }));
      assert.deepEqual(verdicts(checker.check(route, { samples: 8 })), expected);
      assert.deepEqual(verdicts(checker.check(new Float64Array(route.flat()), { samples: 8 })), expected);
    }
  }
  assert.throws(() => checker.check(), /RouteChecker.check: no route given and the scene has none/);
  assert.equal(checker.deleted, false);
  checker.delete();
  assert.equal(checker.deleted, true);
  assert.throws(() => checker.check(routes[0]), (e) => e instanceof HullkitError && /the checker was deleted/.test(e.message));
  assert.throws(() => checker.buildSeconds, /the checker was deleted/);
  checker.delete(); // harmless

  const disposable = new hullkit.RouteChecker(cubeScene([[0, 0, 0], [1, 0, 0]]));
  assert.equal(disposable.check().legs[0].status, 'clear'); // the scene's own route
  const dispose = typeof Symbol.dispose === 'symbol' ? Symbol.dispose : Symbol.for('nodejs.dispose');
  disposable[dispose]();
  assert.throws(() => disposable.check(), /the checker was deleted/);
});

test('checkRoute and RouteChecker: legs that turn, as hullkit route reports them', () => {
  // A bar 3 long along y, turned towards x while it passes a slot 1 wide at x in [5, 6].
  const slot = {
    traverse: { parts: [{ name: 'bar', box: { min: [-0.2, -1.5, -0.2], max: [0.2, 1.5, 0.2] } }], pivot: [0, 0, 0] },
    obstacles: [
      { name: 'low', box: { min: [5, -10, -1], max: [6, -0.5, 1] } },
      { name: 'high', box: { min: [5, 0.5, -1], max: [6, 10, 1] } },
    ],
  };
  const turnedFirst = [
    [0, 0, 0],
    { position: [0, 0, 0], rotation: { axis: [0, 0, 1], degrees: 90 } },
    { position: [12, 0, 0], rotation: { yaw_pitch_roll_degrees: [90, 0, 0] } },
  ];
  const turnedWhilePassing = [[0, 0, 0], { position: [12, 0, 0], rotation: { quaternion: [Math.SQRT1_2, 0, 0, Math.SQRT1_2] } }];
  for (const route of [turnedFirst, turnedWhilePassing]) {
    const scene = { ...slot, route };
    const expected = cliReport(scene, ['--samples', '8']);
    assertSameReport(hullkit.checkRoute(scene, { samples: 8 }), expected, JSON.stringify(route));
    const checker = new hullkit.RouteChecker(slot);
    assertSameReport(checker.check(route, { samples: 8 }), expected, 'RouteChecker');
    checker.delete();
  }
  const first = hullkit.checkRoute({ ...slot, route: turnedFirst });
  assert.equal(first.clear, true);
  const [leg] = hullkit.checkRoute({ ...slot, route: turnedWhilePassing }).legs;
  assert.equal(leg.status, 'hit');
  assert.ok(leg.fraction[1] - leg.fraction[0] <= 1e-7);
  assert.equal(leg.rotation.length, 4);
  assert.equal(leg.grazing, undefined);
  // Rotation errors name the waypoint's field, from checkRoute and from RouteChecker.check.
  const checker = new hullkit.RouteChecker(slot);
  assert.throws(() => checker.check([[0, 0, 0], { position: [1, 0, 0], rotation: { axis: [0, 0, 0], degrees: 5 } }]),
    (e) => e instanceof HullkitError && e.message === 'RouteChecker.check: route[1].rotation.axis: a zero axis has no direction');
  assert.throws(() => checker.check([[0, 0, 0], { position: [1, 0, NaN] }]),
    (e) => e instanceof HullkitError && e.message === 'RouteChecker.check: route[1].position[2]: expected a finite number');
  checker.delete();
  assert.throws(() => hullkit.checkRoute({ ...slot, route: [[0, 0, 0], { position: [1, 0, 0], rotation: { quaternion: [1, 0, 0, 0.1] } }] }),
    (e) => e instanceof HullkitError && /^checkRoute: scene: route\[1\]\.rotation\.quaternion: not a unit quaternion/.test(e.message));
});

test('checkRoute and RouteChecker: bad scenes and arguments throw one clear message', () => {
  const good = cubeScene([[0, 0, 0], [1, 0, 0]]);
  const cases = [
    [{ ...good, route: [[0, 0, 0]] }, {}, 'checkRoute: scene: route: needs at least 2 waypoints, got 1'],
    [{ ...good, route: undefined }, {}, 'checkRoute: scene: missing "route"'],
    [{ ...good, route: [[0, 0, 0], [1, NaN, 0]] }, {}, 'checkRoute: scene: route[1][1]: expected a finite number, got NaN'],
    [{ ...good, margin: Infinity }, {}, 'checkRoute: scene: margin: expected a finite number, got Infinity'],
    [{ ...good, route: [[0, 0, 0], [1, 0, 0, 0, 0, 90]] }, {},
      'checkRoute: scene: route[1]: expected 3 numbers [x, y, z] or {"position": [x, y, z], "rotation": ...}, got 6 values'],
    [{ ...good, rotation: [0, 0, 1] }, {},
      'checkRoute: scene: rotation: a rotation belongs to a waypoint: {"position": [x, y, z], "rotation": {"quaternion": [w, x, y, z]}} (or "axis" with "degrees", or "yaw_pitch_roll_degrees")'],
    [{ ...good, obstacles: [{ box: { min: [0, 0], max: [1, 1, 1] } }] }, {},
      'checkRoute: scene: obstacles[0].box.min: expected 3 numbers [x, y, z], got 2 values'],
    [{ ...good, obstacles: [{ mesh: new TextEncoder().encode('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 7\n') }] }, {},
      'checkRoute: scene: obstacles[0].mesh:5: face index 7 out of range (3 vertices)'],
    [{ ...good, obstacles: [{ mesh: 'vessel.obj' }] }, {}, 'checkRoute: scene: obstacles[0].mesh: "vessel.obj" is not in options.files'],
    [{ ...good, obstacles: [{ mesh: 'short.stl' }] }, { files: { 'short.stl': new Uint8Array(100) } },
      'checkRoute: scene: obstacles[0].mesh: short.stl: binary STL is too long: 84 + 50*N bytes expected (N = 0 triangles: 84 bytes), got 100'],
    [good, { sample: 3 }, 'checkRoute: unknown option "sample" (known: samples, clearance, files)'],
    [good, { samples: -1 }, 'checkRoute: samples must be an integer from 0 to 1000000, got -1'],
  ];
  for (const [scene, options, message] of cases) {
    assert.throws(() => hullkit.checkRoute(scene, options), (e) => {
      assert.ok(e instanceof HullkitError, `${message}: got ${e}`);
      assert.equal(e.message, message);
      return true;
    });
  }
  assert.throws(() => hullkit.checkRoute('scene.json'), TypeError);
  assert.throws(() => new hullkit.RouteChecker({ ...good, traverse: { parts: [] } }),
    /^HullkitError: RouteChecker: scene: traverse.parts: no parts/);
  const checker = new hullkit.RouteChecker(good);
  try {
    assert.throws(() => checker.check([[0, 0, 0]]), /RouteChecker.check: route: needs at least 2 waypoints, got 1/);
    assert.throws(() => checker.check([[0, 0, 0], [1, 2]]), /RouteChecker.check: route\[1\]: expected 3 numbers/);
    assert.throws(() => checker.check(new Float64Array([0, 0, 0, 1, Infinity, 0])), /route\[1\]\[1\]: expected a finite number, got Infinity/);
    assert.throws(() => checker.check(good.route, { files: {} }), /unknown option "files"/);
  } finally {
    checker.delete();
  }
});

test('RouteChecker: a 20-leg re-check against a ~1e5-triangle scene (timed informally)', (t) => {
  // 27 bunnies' worth of triangles, as 8 300 small boxes in a grid; a traverse box weaving through.
  const obstacles = [];
  for (let i = 0; i < 8300; i++) {
    const x = (i % 25) * 2, y = Math.floor(i / 25) % 20 * 2, z = Math.floor(i / 500) * 2;
    obstacles.push({ box: { min: [x, y, z], max: [x + 0.5, y + 0.5, z + 0.5] } });
  }
  const scene = { traverse: { parts: [{ box: { min: [0, 0, 0], max: [0.6, 0.6, 0.6] } }] }, obstacles, margin: 0.01 };
  const route = [];
  for (let k = 0; k <= 20; k++) route.push([0.9 + (k % 2) * 1.1, 0.8 + 2 * k * 0.9, 0.8 + (k % 3) * 2]);
  let start = performance.now();
  const checker = new hullkit.RouteChecker(scene);
  const build = performance.now() - start;
  try {
    start = performance.now();
    const first = checker.check(route);
    const firstMs = performance.now() - start;
    const times = [];
    for (let i = 0; i < 5; i++) {
      start = performance.now();
      assert.deepEqual(verdicts(checker.check(route)), verdicts(first));
      times.push(performance.now() - start);
    }
    times.sort((a, b) => a - b);
    assert.equal(first.legs.length, 20);
    t.diagnostic(`${12 * obstacles.length} triangles: build ${build.toFixed(0)} ms (incl. JSON), ` +
      `20-leg re-check ${firstMs.toFixed(1)} ms first, ${times[2].toFixed(1)} ms median of 5`);
  } finally {
    checker.delete();
  }
});
