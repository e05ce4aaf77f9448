import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync, rmSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

import createHullkit, { HullkitError } from '../../wasm/hullkit.js';
import { hullProblems, randomBall, seededRandom } from './exact.js';

const root = fileURLToPath(new URL('../..', import.meta.url));
const cli = process.env.HULLKIT_CLI ?? join(root, 'build/native/hullkit');
const hullkit = await createHullkit();

function cubeCorners(half = 1) {
  const xyz = [];
  for (let i = 0; i < 8; i++) xyz.push(i & 1 ? half : -half, i & 2 ? half : -half, i & 4 ? half : -half);
  return new Float64Array(xyz);
}

test('hull: tetrahedron gives 4 outward triangles, volume and area', () => {
  const result = hullkit.hull(new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]));
  assert.ok(result.triangles instanceof Uint32Array);
  assert.ok(result.vertices instanceof Uint32Array);
  assert.equal(result.triangles.length, 12);
  assert.deepEqual([...result.vertices], [0, 1, 2, 3]);
  assert.ok(Math.abs(result.volume - 1 / 6) < 1e-15);
  assert.ok(Math.abs(result.area - (1.5 + Math.sqrt(3) / 2)) < 1e-15);
  assert.deepEqual(hullProblems(new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]), result), []);
});

test('hull: cube corners give 12 triangles of volume 8', () => {
  const xyz = cubeCorners();
  const result = hullkit.hull(xyz, { algorithm: 'giftwrap' });
  assert.equal(result.triangles.length / 3, 12);
  assert.equal(result.volume, 8);
  assert.equal(result.area, 24);
  assert.deepEqual(hullProblems(xyz, result), []);
});

test('hull: random ball, exact containment checked with BigInt arithmetic', () => {
  for (const seed of [1, 2, 3]) {
    const xyz = randomBall(1500, seed);
    const result = hullkit.hull(xyz);
    assert.deepEqual(hullProblems(xyz, result), [], `seed ${seed}`);
    assert.equal(result.triangles.length / 3, 2 * result.vertices.length - 4);
    assert.ok(result.volume > 0.85 * (4 / 3) * Math.PI && result.volume < (4 / 3) * Math.PI);
  }
});

test('hull: results are owned by the caller, not views into wasm memory', () => {
  const first = hullkit.hull(randomBall(500, 4));
  const copy = first.triangles.slice();
  // Later calls (with heap growth) must not change an earlier result.
  for (let i = 0; i < 3; i++) hullkit.hull(randomBall(20000, 10 + i));
  assert.deepEqual(first.triangles, copy);
  assert.notEqual(first.triangles.buffer.byteLength, 0);
});

test('hull: plain arrays are accepted', () => {
  const fromArray = hullkit.hull([...cubeCorners()]);
  assert.deepEqual(fromArray, hullkit.hull(cubeCorners()));
});

test('hull: degenerate input gets a lower-dimensional answer, not an error', () => {
  const none = hullkit.hull(new Float64Array(0));
  assert.equal(none.dimension, -1);
  assert.equal(none.vertices.length, 0);
  const point = hullkit.hull(new Float64Array(12).fill(1));
  assert.equal(point.dimension, 0);
  assert.deepEqual([...point.vertices], [0]);
  const segment = hullkit.hull([0, 0, 0, 3, 3, 3, 1, 1, 1, -2, -2, -2]);
  assert.equal(segment.dimension, 1);
  assert.deepEqual([...segment.vertices], [1, 3]);
  // A unit square with its centre, in the plane z = 0.
  const square = hullkit.hull([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0]);
  assert.equal(square.dimension, 2);
  assert.equal(square.vertices.length, 4);
  assert.equal(square.area, 1);
  assert.equal(square.volume, 0);
  assert.deepEqual([...square.normal].map(Math.abs), [0, 0, 1]);
  assert.equal(square.triangles.length, 6);
});

test('hull: quickhull and gift wrapping agree; mergeCoplanar gives a cube six quads', () => {
  const grid = [];
  for (let x = -1; x <= 1; x++) for (let y = -1; y <= 1; y++) for (let z = -1; z <= 1; z++) grid.push(x, y, z);
  const xyz = new Float64Array(grid);
  for (const algorithm of hullkit.algorithms) {
    const result = hullkit.hull(xyz, { algorithm, mergeCoplanar: true });
    assert.equal(result.dimension, 3);
    assert.deepEqual([...result.vertices], [0, 2, 6, 8, 18, 20, 24, 26], algorithm);
    assert.equal(result.faceOffsets.length, 7);
    for (let f = 0; f < 6; f++) assert.equal(result.faceOffsets[f + 1] - result.faceOffsets[f], 4);
    assert.deepEqual(hullProblems(xyz, result), []);
    assert.equal(result.volume, 8);
  }
  assert.equal(hullkit.hull(xyz).faceOffsets, undefined);
  const ball = randomBall(2000, 8);
  assert.deepEqual(hullkit.hull(ball, { algorithm: 'quickhull' }).vertices, hullkit.hull(ball, { algorithm: 'giftwrap' }).vertices);
  assert.deepEqual(hullkit.algorithms, ['quickhull', 'giftwrap']);
});

test("hull: epsilon 'seed' is the seed's behaviour, for gift wrapping", () => {
  const ball = randomBall(1000, 12);
  const seed = hullkit.hull(ball, { algorithm: 'giftwrap', epsilon: 'seed' });
  assert.deepEqual(seed.vertices, hullkit.hull(ball).vertices);
  assert.throws(() => hullkit.hull([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0], { algorithm: 'giftwrap', epsilon: 'seed' }), {
    name: 'HullkitError', message: /coplanar within the seed's epsilon/,
  });
  assert.throws(() => hullkit.hull(ball, { epsilon: 'seed' }), { message: /gift wrapping only/ });
});

test('hull: bad input throws HullkitError with a clear message', () => {
  assert.throws(() => hullkit.hull(new Float64Array(10)), { name: 'HullkitError', message: /10 coordinates is not a whole number/ });
  const withNaN = cubeCorners();
  withNaN[3 * 6 + 2] = NaN;
  assert.throws(() => hullkit.hull(withNaN), (error) => {
    assert.ok(error instanceof HullkitError);
    assert.match(error.message, /point 6 has a non-finite z coordinate \(nan\)/);
    assert.equal(error.pointIndex, 6);
    return true;
  });
  assert.throws(() => hullkit.hull([1e300, 0, 0, 0, 1e-300, 0, 0, 0, 1, 1, 1, 1]), { message: /orders of magnitude/ });
  assert.throws(() => hullkit.hull(cubeCorners(), { algorithm: 'qhull' }), { message: /unknown algorithm "qhull" \(known: quickhull, giftwrap\)/ });
  assert.throws(() => hullkit.hull(cubeCorners(), { algoritm: 'giftwrap' }), { message: /unknown option "algoritm"/ });
  assert.throws(() => hullkit.hull(cubeCorners(), { epsilon: 1e-9 }), { message: /unknown epsilon "1e-9"/ });
  assert.throws(() => hullkit.hull(cubeCorners(), { mergeCoplanar: 'yes' }), { message: /mergeCoplanar must be true or false/ });
  assert.throws(() => hullkit.hull(cubeCorners(), { equations: 1 }), { message: /equations must be true or false/ });
  assert.throws(() => hullkit.hull('1 2 3'), TypeError);
  assert.throws(() => hullkit.hull(null), TypeError);
  // The module keeps working after errors.
  assert.equal(hullkit.hull(cubeCorners()).volume, 8);
});

/** qconvex's `n` output for `xyz` (4, the facet count, then "nx ny nz offset" lines) as arrays of 4. */
function qconvexPlanes(xyz, dir) {
  const lines = [`3 ${xyz.length / 3}`];
  for (let i = 0; i < xyz.length; i += 3) lines.push(`${xyz[i]} ${xyz[i + 1]} ${xyz[i + 2]}`);
  const file = join(dir, 'qconvex-input.txt');
  writeFileSync(file, lines.join('\n') + '\n');
  const out = execFileSync('qconvex', ['n', 'TI', file], { encoding: 'utf8' }).trim().split('\n');
  assert.equal(out[0].trim(), '4');
  const planes = out.slice(2).map((line) => line.trim().split(/\s+/).map(Number));
  assert.equal(planes.length, Number(out[1]));
  return planes;
}

test('hull: equations are the outward facet planes qconvex n prints, to 1e-12', (t) => {
  const dir = mkdtempSync(join(tmpdir(), 'hullkit-js-'));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  const random = seededRandom(7);
  const sphere = Float64Array.from({ length: 3 * 400 }, () => random() - 0.5);
  for (let i = 0; i < sphere.length; i += 3) {
    const r = Math.hypot(sphere[i], sphere[i + 1], sphere[i + 2]);
    for (let k = 0; k < 3; k++) sphere[i + k] = 3 + sphere[i + k] / r;  // off the origin: offsets of every size
  }
  for (const [name, xyz] of [['ball', randomBall(3000, 21)], ['sphere', sphere]]) {
    const result = hullkit.hull(xyz);
    const triangles = result.triangles.length / 3;
    assert.equal(result.equations.length, 4 * triangles);
    // Random points: every facet is a triangle. Match them by their normals.
    const theirs = qconvexPlanes(xyz, dir);
    assert.equal(theirs.length, triangles, name);
    const key = (n) => n.slice(0, 3).map((v) => v.toFixed(6)).join(' ');
    const byNormal = new Map(theirs.map((plane) => [key(plane), plane]));
    let worst = 0;
    for (let t = 0; t < triangles; t++) {
      const ours = [...result.equations.subarray(4 * t, 4 * t + 4)];
      const plane = byNormal.get(key(ours));
      assert.ok(plane, `${name}: qconvex has no facet with normal ${key(ours)}`);
      for (let k = 0; k < 3; k++) worst = Math.max(worst, Math.abs(ours[k] - plane[k]));  // unit vectors
      worst = Math.max(worst, Math.abs(ours[3] - plane[3]) / Math.max(1, Math.abs(plane[3])));
      // Outward: every point on the inner side.
      for (let i = 0; i < xyz.length; i += 3) {
        assert.ok(ours[0] * xyz[i] + ours[1] * xyz[i + 1] + ours[2] * xyz[i + 2] + ours[3] <= 1e-14);
      }
    }
    assert.ok(worst <= 1e-12, `${name}: largest difference from qconvex ${worst}`);
  }
  // A polygon's planes are its own; fewer dimensions have none; { equations: false } leaves them out.
  const square = hullkit.hull([0, 0, 2, 1, 0, 2, 1, 1, 2, 0, 1, 2]);
  assert.deepEqual([...square.equations], [0, 0, 1, -2, 0, 0, 1, -2]);
  assert.equal(hullkit.hull([0, 0, 0, 1, 1, 1]).equations.length, 0);
  assert.equal(hullkit.hull(new Float64Array(0)).equations.length, 0);
  const without = hullkit.hull(randomBall(100, 3), { equations: false });
  assert.ok(without.equations instanceof Float64Array && without.equations.length === 0);
});

test('hull: wasm and the native CLI return the same triangles', (t) => {
  assert.ok(existsSync(cli), `native CLI missing at ${cli}: run npm run build`);
  const dir = mkdtempSync(join(tmpdir(), 'hullkit-js-'));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  const random = seededRandom(99);
  const inputs = {
    ball: randomBall(3000, 5),
    cube: cubeCorners(3),
    gaussianish: Float64Array.from({ length: 3 * 800 }, () => random() + random() + random() - 1.5),
  };
  for (const [name, xyz] of Object.entries(inputs)) {
    const file = join(dir, `${name}.txt`);
    const lines = [];
    // %.17g-equivalent: JS prints the shortest string that reads back to the same double.
    for (let i = 0; i < xyz.length; i += 3) lines.push(`${xyz[i]} ${xyz[i + 1]} ${xyz[i + 2]}`);
    writeFileSync(file, lines.join('\n') + '\n');
    for (const algorithm of hullkit.algorithms) {
      const json = JSON.parse(execFileSync(cli, ['hull', file, '--format', 'json', '--algorithm', algorithm], { encoding: 'utf8' }));
      const wasm = hullkit.hull(xyz, { algorithm });
      // The JSON file is self-contained: its triangles index its points, whose input indices are
      // its vertices.
      assert.deepEqual([...wasm.triangles], json.triangles.flat().map((k) => json.vertices[k]), `${name} ${algorithm}`);
      assert.deepEqual([...wasm.vertices], json.vertices, `${name} ${algorithm}`);
      assert.deepEqual(json.points.flat(), [...wasm.vertices].flatMap((v) => [...xyz.subarray(3 * v, 3 * v + 3)]));
      assert.deepEqual([...wasm.equations], json.equations.flat(), `${name} ${algorithm}`);
      assert.equal(wasm.volume, json.volume, `${name} ${algorithm}`);
      assert.equal(wasm.area, json.area, `${name} ${algorithm}`);
    }
  }
  // The same error for the same bad file (its line and point), and for the same points in an array.
  const bad = join(dir, 'bad.txt');
  writeFileSync(bad, '0 0 0\n1 0 0\n0 1 0\n1 inf 0\n');
  const run = spawnSync(cli, ['hull', bad], { encoding: 'utf8' });
  assert.equal(run.status, 2);
  const message = `${bad}:4: coordinate "inf" of point 3 is not a finite number`;
  assert.equal(run.stderr, `hullkit: ${message}\n`);
  assert.throws(() => hullkit.readPoints(readFileSync(bad), bad), { message });
  assert.throws(() => hullkit.hull([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, Infinity, 0]), /point 3 has a non-finite y coordinate \(inf\)/);
});

test('verify: accepts hullkit results and pinpoints broken hulls', () => {
  const xyz = randomBall(3000, 21);
  const result = hullkit.hull(xyz);
  const report = hullkit.verify(xyz, result);
  assert.equal(report.ok, true, report.problems.join('\n'));
  assert.equal(report.checkedPoints, 3000);
  assert.equal(report.triangleCount, result.triangles.length / 3);
  assert.equal(report.vertexCount, result.vertices.length);
  // Triangles alone (as from another library) are checked too.
  assert.equal(hullkit.verify(xyz, { triangles: result.triangles }).ok, true);

  const flipped = result.triangles.slice();
  [flipped[0], flipped[1]] = [flipped[1], flipped[0]];
  const bad = hullkit.verify(xyz, { triangles: flipped });
  assert.equal(bad.ok, false);
  assert.ok(bad.problems.length > 0);
  assert.match(bad.problems.join('\n'), /edge/);

  // A point moved outside the hull is named.
  const moved = xyz.slice();
  const inner = [...Array(3000).keys()].find((i) => !result.vertices.includes(i));
  moved.set([5, 5, 5], 3 * inner);
  const outside = hullkit.verify(moved, result);
  assert.equal(outside.ok, false);
  assert.match(outside.problems.join('\n'), new RegExp(`point ${inner}\\b`));

  // Lower-dimensional results verify too.
  const square = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0];
  assert.equal(hullkit.verify(square, hullkit.hull(square)).ok, true);
  assert.throws(() => hullkit.verify(xyz, { triangles: [0, 1] }), { name: 'HullkitError', message: /whole number of triangles/ });
  assert.throws(() => hullkit.verify(xyz, { triangles: [0, 1, -2] }), { message: /entry 2 \(-2\) is not a valid index/ });
  assert.throws(() => hullkit.verify(xyz, null), TypeError);
});

test('hull: arrays of points ([x, y, z], {x, y, z}, three.js Vector3-like) as quickhull3d and three.js users pass them', () => {
  const flat = randomBall(300, 17);
  const expected = hullkit.hull(flat);
  const nested = Array.from({ length: flat.length / 3 }, (_, i) => [flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]]);
  // A class like three.js's Vector3: x, y, z own properties, methods on the prototype.
  class Vector3 {
    constructor(x, y, z) { this.x = x; this.y = y; this.z = z; this.isVector3 = true; }
    length() { return Math.hypot(this.x, this.y, this.z); }
  }
  const inputs = {
    arrays: nested,
    typed: nested.map((p) => Float64Array.from(p)),
    objects: nested.map(([x, y, z]) => ({ x, y, z })),
    vectors: nested.map(([x, y, z]) => new Vector3(x, y, z)),
    mixed: nested.map((p, i) => (i % 2 ? p : { x: p[0], y: p[1], z: p[2] })),
  };
  for (const [name, points] of Object.entries(inputs)) {
    const result = hullkit.hull(points);
    assert.deepEqual(result.triangles, expected.triangles, name);
    assert.deepEqual(result.vertices, expected.vertices, name);
    assert.deepEqual(result.equations, expected.equations, name);
    assert.equal(hullkit.verify(points, result).ok, true, name);
  }
  assert.equal(hullkit.hull([]).dimension, -1);
  assert.equal(hullkit.giftwrapTrace(nested.slice(0, 50)).dimension, 3);
  assert.ok(hullkit.writeGlb(inputs.vectors, expected) instanceof Uint8Array);
});

test('hull: what is not points gets a message saying what to pass', () => {
  const points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0]];
  assert.throws(() => hullkit.hull(points), (error) => error instanceof HullkitError && error.pointIndex === 3 &&
    error.message === 'hull: points[3] has 2 coordinates, expected 3');
  assert.throws(() => hullkit.hull([[0, 0, 0], [1, 0, 0, 5]]), { message: 'hull: points[1] has 4 coordinates, expected 3' });
  assert.throws(() => hullkit.hull([{ x: 0, y: 0, z: 0 }, { x: 1, y: 2 }]),
    { message: /^hull: points\[1\] has no numeric z \(z is missing\); pass a flat Float64Array .* or an array of points \[x, y, z\] or \{x, y, z\}$/ });
  assert.throws(() => hullkit.hull([[0, 0, 0], ['1', 0, 0]]), { message: /^hull: points\[1\]\[0\] is the string "1", not a number;/ });
  assert.throws(() => hullkit.hull([[0, 0, 0], null]), { message: /^hull: points\[1\] is null, not a point;/ });
  assert.throws(() => hullkit.hull([0, 0, 0, [1, 0, 0]]), { message: /^hull: entry 3 of the flat coordinate array is an array of 3, not a number;/ });
  assert.throws(() => hullkit.hull([0, 0, '0']), { message: /entry 2 of the flat coordinate array is the string "0", not a number/ });
  assert.throws(() => hullkit.hull([0, 0, 0, 1]), { message: /4 coordinates is not a whole number of 3D points \(x0 y0 z0 x1 y1 z1 \.\.\.\); or pass an array of points/ });
  assert.throws(() => hullkit.hull('0 0 0'), TypeError);
  assert.throws(() => hullkit.hull(42), TypeError);
  // Non-finite numbers reach the core, which names the point, in any layout.
  assert.throws(() => hullkit.hull([[0, 0, 0], [1, NaN, 0]]), (error) => error.pointIndex === 1 && /non-finite y/.test(error.message));
});
