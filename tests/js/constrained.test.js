// hullkit.triangulatePolygon and hullkit.constrainedDelaunay through the WebAssembly build, checked
// exactly (BigInt orientation, area and empty-circle tests, independent of hullkit) and against
// earcut (npm) on simple polygons: both triangulate the same vertices, so the areas agree exactly.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import earcut from 'earcut';
import createHullkit, { HullkitError } from '../../wasm/hullkit.js';
import { exactPoints, orient2d, seededRandom } from './exact.js';

const hullkit = await createHullkit();
const next = (e) => (e % 3 === 2 ? e - 2 : e + 1);

/** Twice the total area of clockwise triangles over `coords`, exactly (in the common power-of-two units of exactPoints). */
function twiceArea(coords, triangles) {
  const p = exactPoints(coords, 2);
  let sum = 0n;
  for (let t = 0; t < triangles.length; t += 3) {
    const [a, b, c] = [p[triangles[t]], p[triangles[t + 1]], p[triangles[t + 2]]];
    sum -= (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }
  return sum;
}

/** twiceArea for small integer coordinates, in their own units (Number arithmetic is exact there). */
function twiceAreaOfIntegers(coords, triangles) {
  let sum = 0;
  for (let t = 0; t < triangles.length; t += 3) {
    const [a, b, c] = [0, 1, 2].map((k) => [coords[2 * triangles[t + k]], coords[2 * triangles[t + k] + 1]]);
    assert.ok([...a, ...b, ...c].every(Number.isInteger) && [...a, ...b, ...c].every((v) => Math.abs(v) < 2 ** 20));
    sum -= (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }
  return sum;
}

/** Sign of the in-circle determinant: > 0 when d is inside the circle of counter-clockwise a, b, c. */
function incircle(a, b, c, d) {
  const rows = [a, b, c].map((p) => [p[0] - d[0], p[1] - d[1]]);
  const lift = rows.map(([x, y]) => x * x + y * y);
  const det = lift[0] * (rows[1][0] * rows[2][1] - rows[2][0] * rows[1][1]) -
    lift[1] * (rows[0][0] * rows[2][1] - rows[2][0] * rows[0][1]) +
    lift[2] * (rows[0][0] * rows[1][1] - rows[1][0] * rows[0][1]);
  return det > 0n ? 1 : det < 0n ? -1 : 0;
}

/** Exact checks of a result: clockwise nonzero triangles, paired half-edges, flags symmetric, unflagged edges locally Delaunay. */
function checkValid(result, { boundaryConstrained }) {
  const { triangles, halfedges, constrained, coords } = result;
  const p = exactPoints(coords, 2);
  for (let t = 0; t < triangles.length; t += 3) {
    assert.equal(orient2d(p[triangles[t]], p[triangles[t + 1]], p[triangles[t + 2]]), -1, `triangle ${t / 3} is clockwise with area`);
  }
  for (let e = 0; e < triangles.length; e++) {
    const f = halfedges[e];
    if (f === -1) {
      if (boundaryConstrained) assert.equal(constrained[e], 1, `boundary half-edge ${e} lies on a ring`);
      continue;
    }
    assert.equal(halfedges[f], e);
    assert.equal(triangles[f], triangles[next(e)]);
    assert.equal(constrained[f], constrained[e]);
    if (constrained[e]) continue;
    const [a, b, c] = [triangles[e], triangles[next(e)], triangles[next(next(e))]];
    const d = triangles[next(next(f))];
    assert.notEqual(incircle(p[a], p[c], p[b], p[d]), 1, `edge ${a}-${b} is locally Delaunay`);
  }
}

/** A star-shaped ring around (cx, cy) with radii in [lo, hi] (counter-clockwise unless reversed). */
function starRing(n, cx, cy, lo, hi, random, reversed = false) {
  const out = [];
  for (let k = 0; k < n; k++) {
    const angle = (reversed ? -1 : 1) * 2 * Math.PI * (k + 0.5 * random()) / n;
    const r = lo + (hi - lo) * random();
    out.push(cx + r * Math.cos(angle), cy + r * Math.sin(angle));
  }
  return out;
}

test('triangulatePolygon: a square with a square hole, as earcut takes it', () => {
  const coords = [0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3];
  const result = hullkit.triangulatePolygon(coords, [4]);
  assert.equal(result.triangles.length, 24);
  assert.equal(result.addedCount, 0);
  assert.equal(result.inputCount, 8);
  checkValid(result, { boundaryConstrained: true });
  assert.equal(twiceAreaOfIntegers(result.coords, result.triangles), 24);
  assert.deepEqual(hullkit.fillRules, ['evenodd', 'nonzero']);
  // nonzero: a hole wound like the outer ring is filled.
  assert.equal(twiceAreaOfIntegers(coords, hullkit.triangulatePolygon(coords, [4], { fill: 'nonzero' }).triangles), 32);
  // dim 3 (earcut's third argument): the z coordinates are skipped.
  const xyz = [];
  for (let i = 0; i < coords.length; i += 2) xyz.push(coords[i], coords[i + 1], 7);
  assert.deepEqual(hullkit.triangulatePolygon(xyz, [4], { dim: 3 }).triangles, result.triangles);
});

test('triangulatePolygon: the same area as earcut on simple polygons with holes', () => {
  const random = seededRandom(31);
  for (let trial = 0; trial < 20; trial++) {
    const coords = starRing(200 + 50 * trial, 0, 0, 8, 10, random);
    const holes = [];
    for (const [cx, cy] of [[-3, 0], [3, 0], [0, 3], [0, -3]]) {
      holes.push(coords.length / 2);
      coords.push(...starRing(10 + trial, cx, cy, 0.5, 1.2, random, trial % 2 === 1));
    }
    const ours = hullkit.triangulatePolygon(coords, holes);
    checkValid(ours, { boundaryConstrained: true });
    const theirs = earcut(coords, holes);
    assert.equal(ours.triangles.length, theirs.length, `trial ${trial}: as many triangles as earcut`);
    assert.equal(twiceArea(coords, ours.triangles), -twiceArea(coords, theirs), `trial ${trial}: the same area`);
  }
});

test('triangulatePolygon: GeoJSON Polygon, MultiPolygon and Feature', () => {
  const square = [[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]];
  const hole = [[1, 1], [1, 3], [3, 3], [3, 1], [1, 1]];
  const polygon = { type: 'Polygon', coordinates: [square, hole] };
  const one = hullkit.triangulatePolygon(polygon);
  assert.equal(twiceAreaOfIntegers(one.coords, one.triangles), 24);
  const far = square.map(([x, y]) => [x + 10, y]);
  const multi = hullkit.triangulatePolygon({ type: 'Feature', geometry: { type: 'MultiPolygon', coordinates: [[square, hole], [far]] } });
  assert.equal(twiceAreaOfIntegers(multi.coords, multi.triangles), 24 + 32);
  checkValid(multi, { boundaryConstrained: true });
  assert.throws(() => hullkit.triangulatePolygon({ type: 'LineString', coordinates: [] }), /LineString is not a Polygon/);
  assert.throws(() => hullkit.triangulatePolygon(polygon, [3]), /not with GeoJSON/);
  assert.throws(() => hullkit.triangulatePolygon({ type: 'Polygon', coordinates: [[[0, 0], [1]]] }), /ring 0 position 1 is not \[x, y\]/);
});

test('triangulatePolygon: a self-crossing bow-tie gets its exact crossing point', () => {
  const result = hullkit.triangulatePolygon([0, 0, 2, 2, 2, 0, 0, 2]);
  assert.equal(result.crossingCount, 1);
  assert.equal(result.addedCount, 1);
  assert.deepEqual(Array.from(result.coords.subarray(8)), [1, 1]);
  assert.equal(twiceAreaOfIntegers(result.coords, result.triangles), 4);
  checkValid(result, { boundaryConstrained: true });
});

test('constrainedDelaunay: segments kept, crossings split, the hull covered', () => {
  const random = seededRandom(5);
  const coords = Float64Array.from({ length: 400 }, () => random());
  const edges = [];
  for (let k = 0; k < 20; k++) edges.push(Math.floor(random() * 200), Math.floor(random() * 200));
  const result = hullkit.constrainedDelaunay(coords, edges);
  checkValid(result, { boundaryConstrained: false });
  assert.ok(result.crossingCount > 0, 'random segments cross');
  // Every unshared half-edge is on the convex hull: all points on its inner side (exact).
  const p = exactPoints(result.coords, 2);
  for (let e = 0; e < result.triangles.length; e++) {
    if (result.halfedges[e] !== -1) continue;
    const a = p[result.triangles[e]], b = p[result.triangles[next(e)]];
    for (const q of p) assert.notEqual(orient2d(a, b, q), 1, 'hull edge with every point on its right');
  }
});

test('triangulatePolygon and constrainedDelaunay: clear errors', () => {
  assert.throws(() => hullkit.constrainedDelaunay([0, 0, 1, 0, 0, 1], [0, 5]), (error) =>
    error instanceof HullkitError && error.segmentIndex === 0 && /segment 0 joins points 0 and 5/.test(error.message));
  assert.throws(() => hullkit.constrainedDelaunay([0, 0, 1, 0, 0, 1], [0, 1, 2]), /not a whole number of pairs/);
  assert.throws(() => hullkit.triangulatePolygon([0, 0, 1, 0, NaN, 1]), (error) => error.pointIndex === 2);
  assert.throws(() => hullkit.triangulatePolygon([0, 0, 1, 0, 0, 1, 1, 1], [3, 2]), /holeIndices\[1\] = 2 is before the hole before it/);
  assert.throws(() => hullkit.triangulatePolygon([0, 0, 1, 0, 0, 1], [9]), /past the 3 vertices/);
  assert.throws(() => hullkit.triangulatePolygon([0, 0, 1, 0, 0, 1], [], { fill: 'winding' }), /unknown fill "winding"/);
  assert.throws(() => hullkit.triangulatePolygon([0, 0, 1, 0, 0, 1], [], { holes: [] }), /unknown option "holes"/);
  // Degenerate input is a value: collinear rings have no inside.
  assert.equal(hullkit.triangulatePolygon([0, 0, 1, 1, 2, 2]).triangles.length, 0);
  assert.equal(hullkit.triangulatePolygon([]).dimension, -1);
});

/** The smallest angle of a triangulation, in degrees (measured on the output). */
function smallestAngle(coords, triangles) {
  let best = 180;
  for (let t = 0; t < triangles.length; t += 3) {
    for (let k = 0; k < 3; k++) {
      const [w, u, x] = [0, 1, 2].map((j) => triangles[t + (k + j) % 3]);
      const ux = coords[2 * u] - coords[2 * w], uy = coords[2 * u + 1] - coords[2 * w + 1];
      const xx = coords[2 * x] - coords[2 * w], xy = coords[2 * x + 1] - coords[2 * w + 1];
      best = Math.min(best, Math.atan2(Math.abs(ux * xy - uy * xx), ux * xx + uy * xy) * 180 / Math.PI);
    }
  }
  return best;
}

test('triangulatePolygon: quality meshes (minAngle, maxArea, conforming) keep the area and the rings', () => {
  const coords = [0, 0, 10, 0, 10, 10, 0, 10, 3, 3, 7, 3, 7, 6, 3, 6];
  const plain = hullkit.triangulatePolygon(coords, [4]);
  assert.equal(plain.steinerCount, 0);
  for (const options of [{ minAngle: 20 }, { minAngle: 33 }, { maxArea: 0.5 }, { minAngle: 25, maxArea: 2, conforming: true }]) {
    const mesh = hullkit.triangulatePolygon(coords, [4], options);
    checkValid(mesh, { boundaryConstrained: true });
    assert.ok(mesh.steinerCount > 0, JSON.stringify(options));
    assert.equal(mesh.addedCount, mesh.steinerCount);
    assert.equal(mesh.unrefinedCount, 0);
    // Points on these axis-parallel rings are exact: the same area exactly.
    // (the input vertices come first in mesh.coords, so the plain triangles index it too)
    assert.equal(twiceArea(mesh.coords, mesh.triangles), twiceArea(mesh.coords, plain.triangles));
    if (options.minAngle) assert.ok(smallestAngle(mesh.coords, mesh.triangles) >= options.minAngle, JSON.stringify(options));
    if (options.maxArea) {
      for (let t = 0; t < mesh.triangles.length; t += 3) {
        const [a, b, c] = [0, 1, 2].map((k) => mesh.triangles[t + k]);
        const area = Math.abs((mesh.coords[2 * b] - mesh.coords[2 * a]) * (mesh.coords[2 * c + 1] - mesh.coords[2 * a + 1]) -
          (mesh.coords[2 * b + 1] - mesh.coords[2 * a + 1]) * (mesh.coords[2 * c] - mesh.coords[2 * a])) / 2;
        assert.ok(area <= options.maxArea);
      }
    }
  }
  // The same mesh every time.
  const again = hullkit.triangulatePolygon(coords, [4], { minAngle: 33 });
  assert.deepEqual(again.coords, hullkit.triangulatePolygon(coords, [4], { minAngle: 33 }).coords);
});

test('constrainedDelaunay: Triangle .poly domains (removeExterior, holes) and their quality meshes', () => {
  // An L-shaped outline with a square hole; the hull's notch is exterior.
  const coords = [0, 0, 6, 0, 6, 3, 3, 3, 3, 6, 0, 6, 1, 1, 2, 1, 2, 2, 1, 2];
  const edges = [0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 6, 7, 7, 8, 8, 9, 9, 6];
  const whole = hullkit.constrainedDelaunay(coords, edges);
  const domain = hullkit.constrainedDelaunay(coords, edges, { removeExterior: true, holes: [1.5, 1.5] });
  assert.equal(twiceAreaOfIntegers(coords, whole.triangles), 2 * (36 - 4.5));
  assert.equal(twiceAreaOfIntegers(coords, domain.triangles), 2 * (27 - 1));
  const mesh = hullkit.constrainedDelaunay(coords, edges, { removeExterior: true, holes: [1.5, 1.5], minAngle: 30, maxArea: 0.25 });
  checkValid(mesh, { boundaryConstrained: true });
  assert.equal(twiceArea(mesh.coords, mesh.triangles), twiceArea(mesh.coords, domain.triangles));
  assert.ok(smallestAngle(mesh.coords, mesh.triangles) >= 30);
  assert.throws(() => hullkit.triangulatePolygon(coords, [], { minAngle: 40 }), /minAngle must be a number of degrees from 0 to 34/);
  assert.throws(() => hullkit.triangulatePolygon(coords, [], { maxArea: -1 }), /maxArea must be a positive number/);
  assert.throws(() => hullkit.triangulatePolygon(coords, [], { conforming: 1 }), /conforming must be true or false/);
  assert.throws(() => hullkit.triangulatePolygon([0, 0, 1, 0, 1, 1, 0, 1], [], { maxArea: 1e-4, maxSteinerPoints: 50 }),
    (error) => error instanceof HullkitError && /max_steiner_points/.test(error.message));
  assert.throws(() => hullkit.constrainedDelaunay(coords, edges, { holes: [1] }), /holes/);
  assert.throws(() => hullkit.triangulatePolygon(coords, [], { keepSegments: 'inner' }), /keepSegments must be 'none', 'boundary' or 'all'/);
});

test('keepSegments (Triangle\'s -Y, -YY): no point added on the kept segments, the area bound still met', () => {
  // The square [0, 4]^2 halved by x = 2, as a graph: the outline is the boundary, x = 2 inside.
  const coords = [0, 0, 2, 0, 4, 0, 4, 4, 2, 4, 0, 4];
  const edges = [0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4];
  const pieces = (mesh, x) => { // segment edges (each once) along the line x
    let count = 0;
    for (let e = 0; e < mesh.triangles.length; e++) {
      if (!mesh.constrained[e] || (mesh.halfedges[e] >= 0 && mesh.halfedges[e] < e)) continue;
      const a = mesh.triangles[e], b = mesh.triangles[e % 3 === 2 ? e - 2 : e + 1];
      if (mesh.coords[2 * a] === x && mesh.coords[2 * b] === x) count++;
    }
    return count;
  };
  const plain = hullkit.constrainedDelaunay(coords, edges, { removeExterior: true });
  for (const [keepSegments, outlineWhole, middleWhole] of [['none', false, false], ['boundary', true, false], ['all', true, true]]) {
    const mesh = hullkit.constrainedDelaunay(coords, edges, { removeExterior: true, maxArea: 0.1, minAngle: 20, keepSegments });
    checkValid(mesh, { boundaryConstrained: true });
    assert.equal(twiceArea(mesh.coords, mesh.triangles), twiceArea(mesh.coords, plain.triangles));
    assert.equal(pieces(mesh, 0) === 1, outlineWhole, keepSegments);
    assert.equal(pieces(mesh, 2) === 1, middleWhole, keepSegments);
  }
  const ring = hullkit.triangulatePolygon([0, 0, 10, 0, 10, 10, 0, 10], [], { maxArea: 0.5, keepSegments: 'boundary' });
  assert.ok(ring.steinerCount > 0);
  for (let e = 0; e < ring.triangles.length; e++) if (ring.constrained[e]) assert.ok(ring.triangles[e] < 4, 'the sides stay whole');
});

test('unsuitable (Triangle\'s -u): the caller\'s test is met; what it throws is thrown after the core stops', () => {
  let calls = 0;
  const unsuitable = (a, b, c, area) => {
    calls++;
    assert.ok(Array.isArray(a) && a.length === 2 && area > 0);
    return area > ((a[0] + b[0] + c[0]) / 3 < 2 ? 0.02 : 0.5); // finer on the left
  };
  const mesh = hullkit.triangulatePolygon([0, 0, 4, 0, 4, 4, 0, 4], [], { unsuitable });
  checkValid(mesh, { boundaryConstrained: true });
  assert.ok(calls > 0 && mesh.steinerCount > 0);
  let left = 0, right = 0;
  for (let t = 0; t < mesh.triangles.length; t += 3) {
    const [a, b, c] = [0, 1, 2].map((k) => mesh.triangles[t + k]);
    const area = Math.abs((mesh.coords[2 * b] - mesh.coords[2 * a]) * (mesh.coords[2 * c + 1] - mesh.coords[2 * a + 1]) -
      (mesh.coords[2 * b + 1] - mesh.coords[2 * a + 1]) * (mesh.coords[2 * c] - mesh.coords[2 * a])) / 2;
    if ((mesh.coords[2 * a] + mesh.coords[2 * b] + mesh.coords[2 * c]) / 3 < 2) left = Math.max(left, area);
    else right = Math.max(right, area);
  }
  assert.ok(left <= 0.02 && right <= 0.5 && right > 0.02, `${left} ${right}`);
  const graph = hullkit.constrainedDelaunay([0, 0, 4, 0, 4, 4, 0, 4], [0, 1, 1, 2, 2, 3, 3, 0], { unsuitable: (a, b, c, area) => area > 1 });
  assert.ok(graph.steinerCount > 0);
  // The caller's exception, a non-boolean answer and a test that is not a function.
  assert.throws(() => hullkit.triangulatePolygon([0, 0, 4, 0, 4, 4], [], { unsuitable: () => { throw new RangeError('from the test'); } }),
    (error) => error instanceof RangeError && error.message === 'from the test');
  assert.throws(() => hullkit.triangulatePolygon([0, 0, 4, 0, 4, 4], [], { unsuitable: () => 1 }), /unsuitable must return true or false/);
  assert.throws(() => hullkit.triangulatePolygon([0, 0, 4, 0, 4, 4], [], { unsuitable: 3 }), /unsuitable must be a function/);
  // The module still works afterwards.
  assert.equal(hullkit.triangulatePolygon([0, 0, 4, 0, 4, 4], []).triangles.length, 3);
});

test('refineMesh (Triangle\'s -r): an earlier result refined keeps its hole and area; bounds per triangle; errors', () => {
  const coords = [0, 0, 10, 0, 10, 10, 0, 10, 3, 3, 7, 3, 7, 6, 3, 6];
  const plain = hullkit.triangulatePolygon(coords, [4]);
  const fine = hullkit.refineMesh(plain.coords, plain.triangles, { minAngle: 30, maxArea: 0.5 });
  checkValid(fine, { boundaryConstrained: true });
  assert.equal(twiceArea(fine.coords, fine.triangles), twiceArea(fine.coords, plain.triangles));  // the hole stays a hole
  assert.ok(smallestAngle(fine.coords, fine.triangles) >= 30);
  assert.ok(fine.steinerCount > 50);
  assert.deepEqual(fine.coords.slice(0, 16), Float64Array.from(coords));
  assert.equal(fine.sourceTriangle, undefined);
  // A bound on the first triangle alone: every output triangle lies in one input triangle (its
  // centroid strictly inside, exactly: points split off a slanted edge are within rounding of it),
  // and only the first's are small.
  const bounds = Array.from({ length: plain.triangles.length / 3 }, (_, t) => (t === 0 ? 0.05 : 0));
  const own = hullkit.refineMesh(plain.coords, plain.triangles, { triangleMaxArea: bounds });
  checkValid(own, { boundaryConstrained: true });
  assert.equal(own.sourceTriangle.length, own.triangles.length / 3);
  assert.equal(twiceArea(own.coords, own.triangles), twiceArea(own.coords, plain.triangles));
  let small = 0;
  for (let t = 0; t < own.triangles.length; t += 3) {
    const s = own.sourceTriangle[t / 3];
    const xy = [0, 1, 2].flatMap((k) => [coords[2 * plain.triangles[3 * s + k]], coords[2 * plain.triangles[3 * s + k] + 1]]);
    let cx = 0;
    let cy = 0;
    for (let k = 0; k < 3; k++) cx += own.coords[2 * own.triangles[t + k]] / 3, cy += own.coords[2 * own.triangles[t + k] + 1] / 3;
    const q = exactPoints([...xy, cx, cy], 2);
    for (let e = 0; e < 3; e++) assert.equal(orient2d(q[e], q[(e + 1) % 3], q[3]), -1, `triangle ${t / 3} lies in input triangle ${s}`);
    if (s === 0) {
      small++;
      const [a, b, c] = [0, 1, 2].map((k) => own.triangles[t + k]);
      const area = Math.abs((own.coords[2 * b] - own.coords[2 * a]) * (own.coords[2 * c + 1] - own.coords[2 * a + 1]) -
        (own.coords[2 * b + 1] - own.coords[2 * a + 1]) * (own.coords[2 * c] - own.coords[2 * a])) / 2;
      assert.ok(area <= 0.05);
    }
  }
  assert.ok(small > 20);
  // Errors name the triangle.
  assert.throws(() => hullkit.refineMesh(coords, [0, 1, 2, 0, 1, 2]), (e) => e instanceof HullkitError && e.triangleIndex === 1 && /overlap/.test(e.message));
  assert.throws(() => hullkit.refineMesh(coords, [0, 1, 9]), (e) => e instanceof HullkitError && e.triangleIndex === 0 && /has corner 9/.test(e.message));
  assert.throws(() => hullkit.refineMesh(coords, [0, 1, 2], { triangleMaxArea: [1, 2] }), /triangleMaxArea holds 2 numbers for 1 triangles/);
  assert.throws(() => hullkit.refineMesh(coords, [0, 1]), /not a whole number of triples/);
  assert.throws(() => hullkit.refineMesh(coords, []), /there are no triangles to refine/);
  assert.throws(() => hullkit.refineMesh(coords, [0, 1, 2], { holes: [1, 1] }), /holes/);
});
