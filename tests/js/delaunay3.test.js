// hullkit.delaunay3 and verifyDelaunay3 through the WebAssembly build: every tetrahedralization
// checked exactly in JS (BigInt orient3d and insphere, independent of hullkit), compared with the
// native CLI (identical arrays), on grids, degenerate input and bad input.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, writeFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

import createHullkit, { HullkitError } from '../../wasm/hullkit.js';
import { exactPoints, hullProblems, insphere, orient3d, orient3dDeterminant, randomBall, seededRandom } from './exact.js';

const root = fileURLToPath(new URL('../..', import.meta.url));
const cli = process.env.HULLKIT_CLI ?? join(root, 'build/native/hullkit');
const hullkit = await createHullkit();

// ---------------------------------------------------------------- inputs

function uniform(n, seed) {
  const random = seededRandom(seed);
  return Float64Array.from({ length: 3 * n }, () => 2 * random() - 1);
}

/** The integer grid {0..k-1}^3: every unit cube's corners are cospherical. */
function grid(k) {
  const xyz = [];
  for (let i = 0; i < k; i++) for (let j = 0; j < k; j++) for (let l = 0; l < k; l++) xyz.push(l, j, i);
  return Float64Array.from(xyz);
}

/** n points on the plane z = 0.25 x - 0.5 y + 3 (exactly: dyadic coordinates). */
function tiltedPlane(n, seed) {
  const random = seededRandom(seed);
  const xyz = [];
  for (let i = 0; i < n; i++) {
    const x = Math.floor(64 * random()) / 8;
    const y = Math.floor(64 * random()) / 8;
    xyz.push(x, y, 0.25 * x - 0.5 * y + 3);
  }
  return Float64Array.from(xyz);
}

// ---------------------------------------------------------------- exact checks

const tetrahedron = (tetrahedra, t) => Array.from(tetrahedra.subarray(4 * t, 4 * t + 4));
/** The face opposite corner k as its sorted corners ("a,b,c"), to match faces between tetrahedra. */
const faceKey = (corners, k) => corners.filter((_, i) => i !== k).sort((a, b) => a - b).join(',');

/**
 * Problems with `result` as the Delaunay tetrahedralization of `xyz`, exactly: every tetrahedron
 * positively oriented (none flat) and starting at its lowest index, no duplicate used and every
 * distinct point a vertex, neighbours symmetric across the same face, the far corner of each
 * interior face not inside the circumsphere, the faces without neighbours exactly `hull` (a closed
 * convex hull, outward), and the tetrahedra's volumes summing exactly to the hull's. Together these
 * make the tetrahedra a triangulation of the convex hull that is locally, hence globally, Delaunay.
 */
function tetrahedralizationProblems(xyz, result) {
  const problems = [];
  const { tetrahedra, neighbors, hull, representative } = result;
  const p = exactPoints(xyz);
  const count = tetrahedra.length / 4;
  if (neighbors.length !== tetrahedra.length) problems.push(`${neighbors.length} neighbours for ${count} tetrahedra`);
  const used = new Set();
  let volume = 0n;
  for (let t = 0; t < count; t++) {
    const v = tetrahedron(tetrahedra, t);
    v.forEach((i) => used.add(i));
    const det = orient3dDeterminant(...v.map((i) => p[i]));
    if (det <= 0n) problems.push(`tetrahedron ${t} (${v}) is ${det === 0n ? 'flat' : 'negatively oriented'}`);
    volume += det;
    if (!(v[0] < v[1] && v[1] < v[2] && v[1] < v[3])) problems.push(`tetrahedron ${t} (${v}) does not start at its two lowest indices`);
  }
  for (let i = 0; i < p.length; i++) {
    if (representative[i] === i && !used.has(i)) problems.push(`point ${i} is in no tetrahedron`);
    if (representative[i] !== i && used.has(i)) problems.push(`duplicate point ${i} is used`);
  }
  const boundary = new Set();
  for (let t = 0; t < count; t++) {
    const v = tetrahedron(tetrahedra, t);
    for (let k = 0; k < 4; k++) {
      const key = faceKey(v, k);
      const u = neighbors[4 * t + k];
      if (u === -1) {
        boundary.add(key);
        continue;
      }
      const w = u >= 0 && u < count ? tetrahedron(tetrahedra, u) : [];
      const back = w.findIndex((_, j) => faceKey(w, j) === key);
      if (back === -1 || neighbors[4 * u + back] !== t) {
        problems.push(`tetrahedron ${t} face ${k}: neighbour ${u} does not share the face ${key} back`);
        continue;
      }
      if (insphere(...v.map((i) => p[i]), p[w[back]]) > 0) {
        problems.push(`point ${w[back]} is inside the circumsphere of tetrahedron ${t} (${v})`);
      }
    }
  }
  // The hull: the faces without a neighbour, each outward (the tetrahedron's far corner behind it).
  const hullKeys = new Set();
  let hullVolume = 0n;
  for (let h = 0; h < hull.length; h += 3) {
    const [a, b, c] = hull.subarray(h, h + 3);
    hullKeys.add([a, b, c].sort((x, y) => x - y).join(','));
    if (!(a < b && a < c)) problems.push(`hull triangle ${h / 3} does not start at its lowest index`);
    hullVolume += orient3dDeterminant(p[0], p[a], p[b], p[c]);
  }
  const sorted = [...boundary].sort().join(' ');
  if ([...hullKeys].sort().join(' ') !== sorted || hullKeys.size !== hull.length / 3) {
    problems.push(`hull has ${hull.length / 3} triangles, ${boundary.size} faces have no neighbour, not the same`);
  }
  problems.push(...hullProblems(xyz, { triangles: hull }));
  if (volume !== hullVolume) problems.push(`the tetrahedra's volume ${volume}/6 is not the hull's ${hullVolume}/6`);
  return problems.slice(0, 10);
}

/** The tetrahedra as sorted index lists, sorted: the set, whatever the order and rotation. */
function tetrahedronSet(tetrahedra, map = (i) => i) {
  const out = [];
  for (let t = 0; t < tetrahedra.length / 4; t++) out.push(tetrahedron(tetrahedra, t).map(map).sort((a, b) => a - b).join(','));
  return out.sort();
}

// ---------------------------------------------------------------- delaunay3

test('delaunay3: every tetrahedron positive, every interior face locally Delaunay, neighbours and hull consistent (exact)', () => {
  const cases = {
    'uniform cube': uniform(400, 1),
    ball: randomBall(300, 2),
    'offset 1e6': uniform(150, 3).map((v) => v + 1e6),
    'grid 5': grid(5),
    'five points': uniform(5, 4),
    'four points': Float64Array.from([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]),
  };
  for (const [name, xyz] of Object.entries(cases)) {
    const result = hullkit.delaunay3(xyz);
    assert.equal(result.dimension, 3, name);
    assert.equal(result.duplicateCount, 0, name);
    assert.ok(result.tetrahedra.length > 0, name);
    assert.deepEqual(tetrahedralizationProblems(xyz, result), [], name);
    const report = hullkit.verifyDelaunay3(xyz, result.tetrahedra);
    assert.deepEqual(report.problems, [], name);
    assert.equal(report.ok, true, name);
    assert.equal(report.distinctPoints, xyz.length / 3, name);
    assert.equal(report.hullTriangles, result.hull.length / 3, name);
  }
  // The JS insphere itself, on a sphere of radius sqrt(12) around (2, 2, 2).
  const [a, b, c, d] = [[0n, 0n, 0n], [4n, 0n, 0n], [0n, 4n, 0n], [0n, 0n, 4n]];
  assert.deepEqual([orient3d(a, b, c, d), insphere(a, b, c, d, [1n, 1n, 1n]), insphere(a, b, c, d, [4n, 4n, 4n]), insphere(a, b, c, d, [5n, 4n, 4n])], [1, 1, 0, -1]);
});

test('delaunay3: a 10x10x10 grid gives no flat tetrahedron and fills the cube exactly', () => {
  const xyz = grid(10);
  const result = hullkit.delaunay3(xyz);
  assert.deepEqual(tetrahedralizationProblems(xyz, result), []);
  const p = exactPoints(xyz);
  let volume = 0n;
  for (let t = 0; t < result.tetrahedra.length / 4; t++) {
    const det = orient3dDeterminant(...tetrahedron(result.tetrahedra, t).map((i) => p[i]));
    assert.ok(det > 0n, `tetrahedron ${t} is flat or negative`);
    volume += det;
  }
  const unit = orient3dDeterminant(p[0], p[1], p[10], p[100]); // the unit cube's corner tetrahedron, 1/6
  assert.equal(volume, 729n * 6n * unit);
  assert.equal(result.hull.length / 3, 6 * 81 * 2); // every square of every face cut in two
  assert.equal(hullkit.verifyDelaunay3(xyz, result.tetrahedra).ok, true);
});

test('delaunay3: the same arrays as the native command line (uniform, ball, 10x10x10 grid, duplicates, lower dimensions)', () => {
  const dir = mkdtempSync(join(tmpdir(), 'hullkit-delaunay3-js-'));
  try {
    const cases = {
      uniform: uniform(3000, 5),
      ball: randomBall(1000, 6),
      grid: grid(10),
      duplicates: Float64Array.from([...uniform(200, 7), 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, ...uniform(1, 7)]),
      coplanar: tiltedPlane(200, 8),
      collinear: Float64Array.from([3, 3, 3, 0, 0, 0, 2, 2, 2, 1, 1, 1, 2, 2, 2]),
      'one point': Float64Array.from([1.5, -2, 7, 1.5, -2, 7]),
      none: new Float64Array(0),
    };
    for (const [name, xyz] of Object.entries(cases)) {
      const file = join(dir, `${name}.txt`);
      let text = '';
      for (let i = 0; i < xyz.length; i += 3) text += `${xyz[i]} ${xyz[i + 1]} ${xyz[i + 2]}\n`; // shortest round-trip form
      writeFileSync(file, text);
      const native = JSON.parse(execFileSync(cli, ['delaunay3', file, '--format', 'json', '--quiet'], { encoding: 'utf8' }));
      const wasm = hullkit.delaunay3(xyz);
      assert.equal(wasm.dimension, native.dimension, name);
      assert.deepEqual([...wasm.tetrahedra], (native.tetrahedra ?? []).flat(), `${name} tetrahedra`);
      assert.deepEqual([...wasm.neighbors], (native.neighbors ?? []).flat(), `${name} neighbors`);
      assert.deepEqual([...wasm.hull], (native.hull ?? []).flat(), `${name} hull`);
      assert.deepEqual([...wasm.triangles], (native.triangles ?? []).flat(), `${name} triangles`);
      assert.deepEqual([...wasm.vertices], (native.vertices ?? []).flat(), `${name} vertices`);
      assert.deepEqual([...wasm.normal], native.normal ?? [0, 0, 0], `${name} normal`);
      const duplicates = [];
      wasm.representative.forEach((r, i) => r !== i && duplicates.push([i, r]));
      assert.deepEqual(duplicates, native.duplicates, `${name} duplicates`);
      assert.equal(wasm.duplicateCount, native.duplicates.length, name);
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('delaunay3: the set of tetrahedra does not depend on the input order, ties included', () => {
  for (const [name, xyz] of [['uniform', uniform(300, 9)], ['grid', grid(4)]]) {
    const n = xyz.length / 3;
    const random = seededRandom(10);
    const order = Array.from({ length: n }, (_, i) => i);
    for (let i = n - 1; i > 0; i--) {
      const j = Math.floor(random() * (i + 1));
      [order[i], order[j]] = [order[j], order[i]];
    }
    const shuffled = new Float64Array(3 * n);
    order.forEach((from, to) => shuffled.set(xyz.subarray(3 * from, 3 * from + 3), 3 * to));
    const original = hullkit.delaunay3(xyz);
    const permuted = hullkit.delaunay3(shuffled);
    assert.deepEqual(tetrahedronSet(permuted.tetrahedra, (i) => order[i]), tetrahedronSet(original.tetrahedra), name);
  }
});

test('delaunay3: duplicates are merged into their lowest index and never used', () => {
  const base = uniform(100, 11);
  const xyz = Float64Array.from([...base, ...base.subarray(9, 12), ...base.subarray(21, 24), ...base.subarray(9, 12)]);
  const result = hullkit.delaunay3(xyz);
  assert.equal(result.duplicateCount, 3);
  assert.deepEqual([...result.representative.subarray(98)], [98, 99, 3, 7, 3]);
  assert.deepEqual(tetrahedralizationProblems(xyz, result), []);
  assert.deepEqual([...result.tetrahedra], [...hullkit.delaunay3(base).tetrahedra], 'the same tetrahedra as without the duplicates');
  assert.equal(hullkit.verifyDelaunay3(xyz, result.tetrahedra).distinctPoints, 100);
});

test('delaunay3: coplanar points give their planar Delaunay triangulation, oriented by the normal', () => {
  for (const [name, xyz] of [['tilted plane', tiltedPlane(150, 12)], ['square grid z = 2', Float64Array.from([...grid(3)].map((v, i) => (i % 3 === 2 ? 2 : v)))]]) {
    const result = hullkit.delaunay3(xyz);
    assert.equal(result.dimension, 2, name);
    assert.equal(result.tetrahedra.length, 0, name);
    assert.equal(result.hull.length, 0, name);
    assert.ok(result.normal instanceof Float64Array && result.normal.length === 3, name);
    assert.ok(Math.abs(Math.hypot(...result.normal) - 1) < 1e-15, name);
    const { triangles, neighbors, normal, representative } = result;
    assert.equal(neighbors.length, triangles.length, name);
    // Exact: the points and the normal scaled together; each triangle counter-clockwise seen from
    // the normal's side, and no far corner across an edge inside the triangle's circumcircle (a
    // coplanar point is inside the circle exactly when it is inside the sphere through the
    // triangle and the point lifted off the plane along the triangle's own normal).
    const p = exactPoints(Float64Array.from([...xyz, ...normal]));
    const n = p.pop();
    const used = new Set(triangles);
    const edgeKey = (t, k) => [0, 1, 2].filter((i) => i !== k).map((i) => triangles[3 * t + i]).sort((a, b) => a - b).join(',');
    for (let t = 0; t < triangles.length / 3; t++) {
      const [a, b, c] = [triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]].map((i) => p[i]);
      const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
      const v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
      const cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
      assert.ok(cross[0] * n[0] + cross[1] * n[1] + cross[2] * n[2] > 0n, `${name}: triangle ${t} is not counter-clockwise seen from the normal`);
      const lifted = [a[0] + cross[0], a[1] + cross[1], a[2] + cross[2]];
      for (let k = 0; k < 3; k++) {
        const across = neighbors[3 * t + k];
        if (across === -1) continue;
        const back = [0, 1, 2].find((j) => edgeKey(across, j) === edgeKey(t, k));
        assert.ok(back !== undefined && neighbors[3 * across + back] === t, `${name}: neighbours of triangle ${t}`);
        assert.ok(insphere(a, b, c, lifted, p[triangles[3 * across + back]]) <= 0, `${name}: triangle ${t} is not Delaunay`);
      }
    }
    for (let i = 0; i < xyz.length / 3; i++) assert.equal(used.has(i), representative[i] === i, `${name}: point ${i}`);
  }
});

test('delaunay3: collinear points, one point and no points', () => {
  const line = hullkit.delaunay3([3, 3, 3, 0, 0, 0, 2, 2, 2, 1, 1, 1, 2, 2, 2]);
  assert.equal(line.dimension, 1);
  assert.deepEqual([...line.vertices], [1, 3, 2, 0]); // in order along the line
  assert.deepEqual([...line.representative], [0, 1, 2, 3, 2]);
  assert.equal(line.duplicateCount, 1);
  for (const key of ['tetrahedra', 'neighbors', 'hull', 'triangles']) assert.equal(line[key].length, 0, key);
  const one = hullkit.delaunay3([1, 2, 3, 1, 2, 3, 1, 2, 3]);
  assert.equal(one.dimension, 0);
  assert.deepEqual([...one.vertices], [0]);
  assert.deepEqual([...one.representative], [0, 0, 0]);
  assert.equal(one.duplicateCount, 2);
  const none = hullkit.delaunay3(new Float64Array(0));
  assert.equal(none.dimension, -1);
  assert.deepEqual([...none.normal], [0, 0, 0]);
  for (const key of ['tetrahedra', 'neighbors', 'hull', 'triangles', 'vertices', 'representative']) assert.equal(none[key].length, 0, key);
  assert.equal(none.duplicateCount, 0);
  assert.deepEqual(hullkit.delaunay3([]), none);
});

test('delaunay3: results are independent copies the caller owns, typed as documented', () => {
  const xyz = uniform(2000, 13);
  const first = hullkit.delaunay3(xyz);
  const types = { tetrahedra: Uint32Array, neighbors: Int32Array, hull: Uint32Array, triangles: Uint32Array, vertices: Uint32Array, normal: Float64Array, representative: Uint32Array };
  for (const [key, type] of Object.entries(types)) {
    assert.ok(first[key] instanceof type, `${key} is a ${type.name}`);
    assert.equal(first[key].buffer.byteLength, first[key].byteLength, `${key} has its own buffer, not the WebAssembly heap`);
  }
  assert.equal(typeof first.duplicateCount, 'number');
  const copies = Object.fromEntries(Object.keys(types).map((key) => [key, first[key].slice()]));
  const second = hullkit.delaunay3(xyz);
  hullkit.delaunay3(uniform(150000, 14)); // grows the heap
  second.tetrahedra.fill(0);
  for (const key of Object.keys(types)) assert.deepEqual(first[key], copies[key], `${key} unchanged by later calls`);
  assert.notEqual(first.tetrahedra.buffer, second.tetrahedra.buffer);
  // A plain array of numbers gives the same as a Float64Array.
  const small = uniform(40, 15);
  assert.deepEqual(hullkit.delaunay3([...small]), hullkit.delaunay3(small));
});

test('delaunay3: progress reports each round, the last with every point; an exception in it is rethrown after the call', () => {
  const calls = [];
  const xyz = uniform(5000, 16);
  const result = hullkit.delaunay3(xyz, { progress: (done, total) => calls.push([done, total]) });
  assert.ok(calls.length >= 2, `${calls.length} calls`);
  for (let i = 1; i < calls.length; i++) assert.ok(calls[i][0] > calls[i - 1][0] && calls[i][1] === calls[0][1]);
  assert.deepEqual(calls.at(-1), [5000, 5000]);
  let seen = 0;
  assert.throws(() => hullkit.delaunay3(xyz, { progress: () => {
    seen++;
    throw new RangeError('stop here');
  } }), (e) => e instanceof RangeError && e.message === 'stop here');
  assert.equal(seen, 1, 'called once, then skipped');
  assert.deepEqual(hullkit.delaunay3(xyz), result, 'the module still works');
});

test('delaunay3: bad input throws, naming the point', () => {
  const isError = (pattern, pointIndex) => (e) => e instanceof HullkitError && pattern.test(e.message) && e.pointIndex === pointIndex;
  assert.throws(() => hullkit.delaunay3([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, NaN, 1]), isError(/^delaunay3: point 3 has a non-finite y coordinate \(nan\)/, 3));
  assert.throws(() => hullkit.delaunay3([0, 0, 0, 1, 0, Infinity]), isError(/point 1 has a non-finite z coordinate \(inf\)/, 1));
  assert.throws(() => hullkit.delaunay3(Float64Array.of(-Infinity, 0, 0)), isError(/point 0 has a non-finite x coordinate \(-inf\)/, 0));
  assert.throws(() => hullkit.delaunay3([0, 0, 0, 1, 0, 0, 1]), (e) => e instanceof HullkitError && /delaunay3: 7 coordinates is not a whole number of 3D points/.test(e.message));
  assert.throws(() => hullkit.delaunay3([0, 0, 0, 1e-300, 1, 1, 1e300, 1, 1, 2, 3, 4]),
    isError(/too many orders of magnitude .*: point 1 \(smallest nonzero \|coordinate\|\) and point 2 \(largest\)/, 1));
  assert.throws(() => hullkit.delaunay3([[0, 0, 0], [1, 0, 0]]), (e) => e instanceof TypeError && /xyz must be a Float64Array or an array of numbers \(x y z per point\); got an array of arrays — flatten it/.test(e.message));
  assert.throws(() => hullkit.delaunay3([{ x: 0, y: 0, z: 0 }]), (e) => e instanceof TypeError && /got an array of objects/.test(e.message));
  assert.throws(() => hullkit.delaunay3([0, 0, '1']), (e) => e instanceof TypeError && /entry 2 is string/.test(e.message));
  assert.throws(() => hullkit.delaunay3('0 0 0'), TypeError);
  assert.throws(() => hullkit.delaunay3([0, 0, 0], { threads: 2 }), /delaunay3: unknown option "threads" \(known: progress, furthestSite\)/);
  assert.throws(() => hullkit.delaunay3([0, 0, 0], { progress: 'yes' }), /progress must be a function/);
});

// ---------------------------------------------------------------- verifyDelaunay3

/** The cube {0, 1}^3, corner i = (i & 1, i >> 1 & 1, i >> 2 & 1), and some of its triangulations. */
const cube = Float64Array.from({ length: 24 }, (_, k) => (Math.floor(k / 3) >> k % 3) & 1);
function cubeTriangulations() {
  const p = exactPoints(cube);
  const positive = (t) => (orient3d(...t.map((i) => p[i])) > 0 ? t : [t[1], t[0], t[2], t[3]]);
  const out = [];
  // Six around each main diagonal (Kuhn's): 0 → corner c → ... → c ^ 7.
  for (const c of [0, 1, 2, 4]) {
    const tets = [];
    for (const [a, b] of [[1, 2], [2, 1], [1, 4], [4, 1], [2, 4], [4, 2]]) tets.push(positive([c, c ^ a, c ^ a ^ b, c ^ 7]));
    out.push(tets);
  }
  // Five: four corners cut off and the regular tetrahedron in the middle (two ways).
  for (const even of [[0, 3, 5, 6], [1, 2, 4, 7]]) {
    const tets = [positive([...even])];
    for (const corner of even) tets.push(positive([corner ^ 7, ...[1, 2, 4].map((bit) => corner ^ 7 ^ bit)]));
    out.push(tets);
  }
  return out.map((tets) => Uint32Array.from(tets.flat()));
}

test('verifyDelaunay3: accepts delaunay3, rejects tampered arrays; ties must follow the rule unless perturbed is false', () => {
  const xyz = uniform(300, 17);
  const { tetrahedra } = hullkit.delaunay3(xyz);
  assert.equal(hullkit.verifyDelaunay3(xyz, tetrahedra).ok, true);
  assert.equal(hullkit.verifyDelaunay3([...xyz], [...tetrahedra]).ok, true, 'plain arrays');
  const swapped = tetrahedra.slice();
  [swapped[0], swapped[1]] = [swapped[1], swapped[0]];
  const report = hullkit.verifyDelaunay3(xyz, swapped);
  assert.equal(report.ok, false);
  assert.ok(report.problemCount >= 1 && report.problems.some((line) => /negatively oriented/.test(line)), report.problems.join('\n'));
  const dropped = hullkit.verifyDelaunay3(xyz, tetrahedra.subarray(4));
  assert.equal(dropped.ok, false);
  const outOfRange = tetrahedra.slice();
  outOfRange[5] = 300;
  assert.match(hullkit.verifyDelaunay3(xyz, outOfRange).problems[0], /has index 300 but there are 300 points/);
  // Every triangulation of a cube is Delaunay (its corners are cospherical); only one follows the tie rule.
  const ours = tetrahedronSet(hullkit.delaunay3(cube).tetrahedra).join(' ');
  let rejected = 0;
  for (const candidate of cubeTriangulations()) {
    assert.equal(hullkit.verifyDelaunay3(cube, candidate, { perturbed: false }).ok, true, `${candidate}`);
    const strict = hullkit.verifyDelaunay3(cube, candidate);
    assert.equal(strict.ok, tetrahedronSet(candidate).join(' ') === ours, `${candidate}`);
    if (!strict.ok) {
      rejected++;
      assert.ok(strict.problems.every((line) => /is inside the circumsphere|break the tie rule/.test(line)), strict.problems.join('\n'));
    }
  }
  assert.ok(rejected >= 5);
});

test('verifyDelaunay3: malformed arguments throw', () => {
  const xyz = uniform(10, 18);
  const { tetrahedra } = hullkit.delaunay3(xyz);
  assert.throws(() => hullkit.verifyDelaunay3(xyz, tetrahedra.subarray(1)), /verifyDelaunay3: \d+ indices is not a whole number of tetrahedra/);
  assert.throws(() => hullkit.verifyDelaunay3(xyz, [0, 1, 2, -3]), (e) => e instanceof HullkitError && /entry 3 \(-3\) is not a valid index/.test(e.message));
  assert.throws(() => hullkit.verifyDelaunay3(xyz, hullkit.delaunay3(xyz)), /pass the tetrahedra array \(result.tetrahedra\)/);
  assert.throws(() => hullkit.verifyDelaunay3(xyz.subarray(1), tetrahedra), /not a whole number of 3D points/);
  assert.throws(() => hullkit.verifyDelaunay3(xyz, tetrahedra, { perturbed: 'no' }), /perturbed must be true or false/);
  assert.throws(() => hullkit.verifyDelaunay3(xyz, tetrahedra, { exact: true }), /unknown option "exact"/);
});

test('delaunay3 furthestSite: every circumsphere holds every point, the corners are the hull\'s extreme points (exact), the native arrays', () => {
  const dir = mkdtempSync(join(tmpdir(), 'hullkit-delaunay3-furthest-'));
  try {
    for (const [name, xyz] of [['uniform', uniform(300, 21)], ['ball', randomBall(200, 22)], ['grid', grid(3)]]) {
      const result = hullkit.delaunay3(xyz, { furthestSite: true });
      assert.equal(result.dimension, 3, name);
      assert.equal(result.furthestSite, true, name);
      const points = exactPoints(xyz);
      const corners = new Set();
      let volume = 0n;
      for (let t = 0; t < result.tetrahedra.length / 4; t++) {
        const [a, b, c, d] = tetrahedron(result.tetrahedra, t).map((i) => (corners.add(i), points[i]));
        assert.equal(orient3d(a, b, c, d), 1, `${name}: tetrahedron ${t} positive`);
        volume += orient3dDeterminant(a, b, c, d);
        for (let p = 0; p < points.length; p++) assert.ok(insphere(a, b, c, d, points[p]) >= 0, `${name}: point ${p} outside tetrahedron ${t}'s sphere`);
      }
      const hull = hullkit.hull(xyz);
      assert.deepEqual([...corners].sort((u, v) => u - v), [...hull.vertices].sort((u, v) => u - v), `${name}: corners`);
      // It fills the hull: the same volume as the ordinary tetrahedralization, exactly.
      const ordinary = hullkit.delaunay3(xyz);
      let expected = 0n;
      for (let t = 0; t < ordinary.tetrahedra.length / 4; t++) expected += orient3dDeterminant(...tetrahedron(ordinary.tetrahedra, t).map((i) => points[i]));
      assert.equal(volume, expected, `${name}: volume`);
      // The native command gives the same arrays.
      const file = join(dir, `${name}.txt`);
      let text = '';
      for (let i = 0; i < xyz.length; i += 3) text += `${xyz[i]} ${xyz[i + 1]} ${xyz[i + 2]}\n`;
      writeFileSync(file, text);
      const native = JSON.parse(execFileSync(cli, ['delaunay3', file, '--furthest-site', '--quiet'], { encoding: 'utf8' }));
      assert.deepEqual([...result.tetrahedra], native.tetrahedra.flat(), `${name} tetrahedra`);
      assert.deepEqual([...result.neighbors], native.neighbors.flat(), `${name} neighbors`);
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('delaunay3 furthestSite: locate3 finds the tetrahedron, refuses nearest points; voronoi3 cells are unbounded; bad flags throw', () => {
  const xyz = uniform(200, 23);
  const result = hullkit.delaunay3(xyz, { furthestSite: true });
  const centroid = [0, 1, 2].map((k) => [0, 1, 2, 3].reduce((s, i) => s + xyz[3 * result.tetrahedra[i] + k], 0) / 4);
  const { tetrahedron: found } = hullkit.locate3(xyz, result, centroid);
  assert.equal(found[0], 0, 'the first tetrahedron holds its own centroid');
  assert.throws(() => hullkit.locate3(xyz, result, centroid, { nearest: true }), (e) => e instanceof HullkitError && /nearest points need the ordinary tetrahedralization/.test(e.message));
  const cells = hullkit.voronoi3(xyz, result);
  const corner = new Set(result.tetrahedra);
  for (let i = 0; i < 200; i++) {
    const faces = cells.cellOffsets[i + 1] - cells.cellOffsets[i];
    assert.equal(faces > 0, corner.has(i), `point ${i}: faces only for corners`);
    assert.equal(cells.volume[i], corner.has(i) ? Infinity : 0, `point ${i}: volume`);
  }
  assert.throws(() => hullkit.delaunay3(xyz, { furthestSite: 1 }), (e) => e instanceof HullkitError && /furthestSite must be true or false/.test(e.message));
  assert.throws(() => hullkit.locate3(xyz, { ...result, furthestSite: 'yes' }, centroid), (e) => e instanceof HullkitError && /furthestSite must be true or false/.test(e.message));
});
