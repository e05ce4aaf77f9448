// hullkit.locate through the WebAssembly build, checked independently: which triangles hold each
// query and the nearest point by brute force with exact BigInt arithmetic (tests/js/exact.js),
// ties included (the lowest index); the barycentric weights rebuild the query, are exactly 0 on
// the edges through it and exactly 1 at a corner. Grids give cocircular ties, integer and
// half-integer coordinates exact midpoints on the edges.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import Delaunator from 'delaunator';
import createHullkit, { HullkitError } from '../../wasm/hullkit.js';
import { exactPoints, orient2d, seededRandom } from './exact.js';

const hullkit = await createHullkit();

function uniform(n, seed, half = 1) {
  const random = seededRandom(seed);
  return Float64Array.from({ length: 2 * n }, () => half * (2 * random() - 1));
}

/** `n` points with integer coordinates in [0, size): their edge midpoints are exact doubles. */
function integers(n, seed, size) {
  const random = seededRandom(seed);
  return Float64Array.from({ length: 2 * n }, () => Math.floor(size * random()));
}

/** The integer grid {0..k-1}^2, point (x, y) at index x + k y: every square's corners are cocircular. */
function grid(k) {
  const xy = [];
  for (let y = 0; y < k; y++) for (let x = 0; x < k; x++) xy.push(x, y);
  return Float64Array.from(xy);
}

const corners = (triangles, t) => [triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]];

/** The midpoint of every triangle edge, x y flat (each edge once per triangle using it). */
function edgeMidpoints(xy, triangles) {
  const out = [];
  for (let e = 0; e < triangles.length; e++) {
    const a = triangles[e], b = triangles[e % 3 === 2 ? e - 2 : e + 1];
    out.push((xy[2 * a] + xy[2 * b]) / 2, (xy[2 * a + 1] + xy[2 * b + 1]) / 2);
  }
  return out;
}

/**
 * By brute force over every triangle, exactly: the lowest-index triangle holding each query (-1 if
 * none), how many triangles hold it, the orientation of each edge with the query (edge k runs from
 * corner k to corner k + 1; 0 on its line), and the nearest point (the lowest index among the
 * nearest). hullkit's triangles are clockwise with y up, so a triangle holds q when no edge turns
 * counter-clockwise to it.
 */
function bruteForce(xy, triangles, queries) {
  const n = xy.length / 2;
  const all = exactPoints(Float64Array.from([...xy, ...queries]), 2);
  const p = all.slice(0, n);
  const boxes = [];
  for (let t = 0; t < triangles.length / 3; t++) {
    const v = corners(triangles, t);
    assert.equal(orient2d(p[v[0]], p[v[1]], p[v[2]]), -1, `triangle ${t} is clockwise and not flat`);
    boxes.push([0, 1].map((k) => [Math.min(...v.map((i) => xy[2 * i + k])), Math.max(...v.map((i) => xy[2 * i + k]))]));
  }
  return all.slice(n).map((q, j) => {
    let holding = -1, holders = 0, sides = null;
    for (let t = 0; t < boxes.length; t++) {
      // Comparing doubles is exact: a query outside the box of a triangle is not in it.
      if (boxes[t].some(([lo, hi], k) => queries[2 * j + k] < lo || queries[2 * j + k] > hi)) continue;
      const v = corners(triangles, t).map((i) => p[i]);
      const s = [0, 1, 2].map((k) => orient2d(v[k], v[(k + 1) % 3], q));
      if (s.some((x) => x > 0)) continue;
      holders++;
      if (holding < 0) [holding, sides] = [t, s];
    }
    let nearest = -1, best = null;
    p.forEach((w, i) => {
      const d = (w[0] - q[0]) ** 2n + (w[1] - q[1]) ** 2n;
      if (best === null || d < best) [best, nearest] = [d, i];
    });
    return { holding, holders, sides, nearest };
  });
}

/**
 * Locates `queries` in hullkit's triangulation of `xy` (or in `triangulation` when given) and
 * compares every answer with the brute force. Returns counts of what the queries exercised.
 */
function checkLocate(xy, queries, name, triangulation = hullkit.delaunay(xy)) {
  queries = Float64Array.from(queries);
  const result = hullkit.locate(xy, triangulation, queries, { barycentric: true, nearest: true });
  const m = queries.length / 2;
  assert.ok(result.triangle instanceof Int32Array && result.triangle.length === m, name);
  assert.ok(result.barycentric instanceof Float64Array && result.barycentric.length === 3 * m, name);
  assert.ok(result.nearest instanceof Int32Array && result.nearest.length === m, name);
  const { triangles } = triangulation;
  const counts = { inside: 0, onEdge: 0, atCorner: 0, shared: 0, outside: 0 };
  bruteForce(xy, triangles, queries).forEach(({ holding, holders, sides, nearest }, j) => {
    const q = [queries[2 * j], queries[2 * j + 1]];
    const at = `${name}: query ${j} (${q})`;
    assert.equal(result.triangle[j], holding, `${at}: triangle (${holders} hold it)`);
    assert.equal(result.nearest[j], nearest, `${at}: nearest`);
    const b = Array.from(result.barycentric.subarray(3 * j, 3 * j + 3));
    if (holding < 0) {
      counts.outside++;
      assert.ok(b.every(Number.isNaN), `${at}: barycentric outside ${b}`);
      return;
    }
    counts.inside++;
    if (holders > 1) counts.shared++;
    // Corner k's weight is 0 exactly when the edge opposite it (corner k + 1 to k + 2) holds q.
    sides.forEach((s, edge) => {
      const k = (edge + 2) % 3;
      assert.equal(b[k] === 0, s === 0, `${at}: barycentric ${k} is ${b[k]}, orientation of its opposite edge ${s}`);
    });
    const zeros = sides.filter((s) => s === 0).length;
    if (zeros === 1) counts.onEdge++;
    if (zeros === 2) {
      counts.atCorner++;
      assert.deepEqual([...b].sort(), [0, 0, 1], `${at}: exactly 1 at a corner`);
    }
    assert.ok(Math.abs(b[0] + b[1] + b[2] - 1) < 1e-12, `${at}: weights sum to 1: ${b}`);
    const v = corners(triangles, holding);
    const scale = Math.max(...v.flatMap((i) => [Math.abs(xy[2 * i]), Math.abs(xy[2 * i + 1])]), 1e-300);
    for (let k = 0; k < 2; k++) {
      const rebuilt = v.reduce((sum, i, c) => sum + b[c] * xy[2 * i + k], 0);
      assert.ok(Math.abs(rebuilt - q[k]) <= 1e-12 * scale, `${at}: Σ b·corner = ${rebuilt}`);
    }
  });
  return counts;
}

test('locate: a grid, queried at its vertices, edge midpoints, square centres, on its hull and outside (ties: the lowest index)', (t) => {
  const k = 6;
  const xy = grid(k);
  const queries = [];
  for (let y = -0.5; y <= k - 0.5; y += 0.5) for (let x = -0.5; x <= k - 0.5; x += 0.5) queries.push(x, y);
  queries.push(2.25, 1.75, 0.125, 0, 5, 2.5, -1e-9, 3, 5 + 1e-9, 3, 2, -3, 7, 7, 1, 2 ** -40, 1, -(2 ** -40));
  const counts = checkLocate(xy, queries, 'grid');
  t.diagnostic(JSON.stringify(counts));
  // Every vertex and midpoint of the grid lies on several triangles: the rule is exercised.
  assert.ok(counts.atCorner >= k * k && counts.onEdge > 50 && counts.shared > 80 && counts.outside > 40, JSON.stringify(counts));
  // The centre of the square [1, 2]^2: its four corners are equally near, the lowest index wins;
  // a point on the segment between points 0 and 1, halfway: 0.
  const { nearest } = hullkit.locate(xy, hullkit.delaunay(xy), [1.5, 1.5, 0.5, 0], { nearest: true });
  assert.deepEqual([...nearest], [1 + k, 0]);
});

test('locate: random integer points, queried at their vertices, every edge midpoint and random points inside and outside', (t) => {
  const xy = integers(150, 1, 64);
  const triangulation = hullkit.delaunay(xy);
  const random = seededRandom(2);
  const inBox = Array.from({ length: 2 * 300 }, () => Math.floor(80 * 8 * random()) / 8 - 8);
  const queries = [...xy.subarray(0, 2 * 60), ...edgeMidpoints(xy, triangulation.triangles), ...inBox];
  const counts = checkLocate(xy, queries, 'integers', triangulation);
  t.diagnostic(JSON.stringify(counts));
  assert.ok(counts.atCorner >= 60 && counts.onEdge > 300 && counts.outside > 30, JSON.stringify(counts));
});

test('locate: random doubles, random doubles as queries (exact brute force on the rationals), and the input points', (t) => {
  const xy = uniform(200, 3);
  const queries = [...uniform(400, 4, 1.2), ...xy.subarray(0, 2 * 50)];
  const counts = checkLocate(xy, queries, 'uniform');
  t.diagnostic(JSON.stringify(counts));
  assert.ok(counts.inside > 250 && counts.outside > 40 && counts.atCorner >= 50, JSON.stringify(counts));
});

test('locate: duplicates are never a corner nor the nearest; a delaunator object; plain arrays', () => {
  const base = integers(60, 5, 32);
  const xy = Float64Array.from([...base, ...base.subarray(0, 2), ...base.subarray(20, 22)]);
  const random = seededRandom(6);
  const queries = [...base.subarray(20, 22), ...Array.from({ length: 200 }, () => 40 * random() - 4)];
  checkLocate(xy, queries, 'with duplicates');
  const t = hullkit.delaunay(xy);
  assert.deepEqual([...hullkit.locate(xy, t, base.subarray(20, 22), { nearest: true }).nearest], [10]);
  // A delaunator object (no representative): its own triangles, the same rules.
  const distinct = uniform(100, 7);
  checkLocate(distinct, uniform(150, 8, 1.1), 'delaunator', new Delaunator(distinct));
  // Plain arrays work as typed ones do.
  const plain = { dimension: t.dimension, triangles: [...t.triangles], halfedges: [...t.halfedges], hull: [...t.hull], representative: [...t.representative] };
  const options = { barycentric: true, nearest: true };
  assert.deepEqual(hullkit.locate([...xy], plain, queries, options), hullkit.locate(xy, t, Float64Array.from(queries), options));
});

test('locate: the same answers in one call, one query at a time and in any order (what the core splits over threads)', () => {
  // More queries than one chunk of the core's work (4096), so the batch is split.
  const xy = uniform(500, 9);
  const t = hullkit.delaunay(xy);
  const m = 10000;
  const queries = uniform(m, 10, 1.1);
  const options = { barycentric: true, nearest: true };
  const all = hullkit.locate(xy, t, queries, options);
  const order = Array.from({ length: m }, (_, i) => i).reverse();
  const reversed = hullkit.locate(xy, t, Float64Array.from(order.flatMap((i) => [queries[2 * i], queries[2 * i + 1]])), options);
  order.forEach((i, j) => {
    assert.equal(reversed.triangle[j], all.triangle[i]);
    assert.equal(reversed.nearest[j], all.nearest[i]);
    assert.deepEqual(reversed.barycentric.subarray(3 * j, 3 * j + 3), all.barycentric.subarray(3 * i, 3 * i + 3));
  });
  for (let i = 0; i < m; i += 97) {
    const one = hullkit.locate(xy, t, queries.subarray(2 * i, 2 * i + 2), options);
    assert.deepEqual([one.triangle[0], one.nearest[0]], [all.triangle[i], all.nearest[i]], `query ${i}`);
    assert.deepEqual(one.barycentric, all.barycentric.slice(3 * i, 3 * i + 3), `query ${i}`);
  }
});

test('locate: points that do not span the plane: no triangle, the nearest point still exact; arrays typed and owned', () => {
  const cases = {
    collinear: Float64Array.from([0, 0, 2, 2, 1, 1, 3, 3, 1, 1, -1, -1]),
    'one point': Float64Array.from([1, 2, 1, 2]),
  };
  const queries = uniform(60, 11, 4);
  for (const [name, xy] of Object.entries(cases)) {
    const t = hullkit.delaunay(xy);
    assert.ok(t.dimension < 2, name);
    const result = hullkit.locate(xy, t, queries, { nearest: true, barycentric: true });
    assert.ok(result.triangle.every((x) => x === -1), name);
    assert.ok(result.barycentric.every(Number.isNaN), name);
    assert.deepEqual([...result.nearest], bruteForce(xy, new Uint32Array(0), queries).map((e) => e.nearest), name);
  }
  const none = hullkit.locate([], hullkit.delaunay([]), [0, 0], { nearest: true });
  assert.deepEqual([...none.triangle, ...none.nearest], [-1, -1]);
  const xy = grid(3);
  const t = hullkit.delaunay(xy);
  const plain = hullkit.locate(xy, t, [0.5, 0.5]);
  assert.deepEqual(Object.keys(plain), ['triangle']);
  assert.equal(plain.triangle.buffer.byteLength, plain.triangle.byteLength, 'its own buffer');
  assert.deepEqual(hullkit.locate(xy, t, [], { nearest: true, barycentric: true }),
    { triangle: new Int32Array(0), barycentric: new Float64Array(0), nearest: new Int32Array(0) });
});

test('locate: bad queries, options and triangulations throw, naming what is wrong', () => {
  const xy = uniform(40, 12);
  const t = hullkit.delaunay(xy);
  const query = (pattern, index) => (e) => e instanceof HullkitError && pattern.test(e.message) && e.queryIndex === index;
  assert.throws(() => hullkit.locate(xy, t, [0, 0, 0, NaN]), query(/^locate: query 1 has a non-finite y coordinate \(nan\)$/, 1));
  assert.throws(() => hullkit.locate(xy, t, [0, 0, 0, 0, -Infinity, 0]), query(/^locate: query 2 has a non-finite x coordinate \(-inf\)$/, 2));
  assert.throws(() => hullkit.locate(xy, t, [1e300, 0]), query(/query 0: its x coordinate is too far from the points' scale/, 0));
  assert.throws(() => hullkit.locate(xy, t, [0, 0, 0.5, 1e-80]), query(/query 1: its y coordinate is too far from the points' scale/, 1));
  assert.throws(() => hullkit.locate(xy, t, [0, 0, 0]), (e) => e instanceof HullkitError && /^locate: queries: 3 coordinates is not a whole number of 2D points/.test(e.message));
  assert.throws(() => hullkit.locate(xy.subarray(1), t, [0, 0]), /locate: 79 coordinates is not a whole number of 2D points/);
  assert.throws(() => hullkit.locate(xy, t, [[0, 0]]), (e) => e instanceof TypeError && /locate: queries must be .* got an array of arrays — flatten it \(queries\.flat\(\)\)/.test(e.message));
  assert.throws(() => hullkit.locate(xy, t, [0, '1']), (e) => e instanceof TypeError && /entry 1 is string/.test(e.message));
  assert.throws(() => hullkit.locate(xy, t, '0 0'), TypeError);
  assert.throws(() => hullkit.locate(xy, t, [0, 0], { exact: true }), /locate: unknown option "exact" \(known: barycentric, nearest\)/);
  assert.throws(() => hullkit.locate(xy, t, [0, 0], { threads: 1 }), /unknown option "threads"/, 'the WebAssembly build has one thread');
  assert.throws(() => hullkit.locate(xy, t, [0, 0], { nearest: 1 }), /nearest must be true or false, got 1/);
  assert.throws(() => hullkit.locate(xy, t.triangles, [0, 0]), (e) => e instanceof TypeError && /the object delaunay\(\) returned/.test(e.message));
  assert.throws(() => hullkit.locate(xy, null, [0, 0]), TypeError);
  assert.throws(() => hullkit.locate(xy.subarray(2), t, [0, 0]), /representative has 40 entries for 39 points \(the triangulation is of other points\)/);
  const tampered = (change) => {
    const copy = { ...t, triangles: t.triangles.slice(), halfedges: t.halfedges.slice(), representative: t.representative.slice() };
    change(copy);
    return copy;
  };
  assert.throws(() => hullkit.locate(xy, tampered((c) => { c.triangles[5] = 40; }), [0, 0]), /triangles\[5\] = 40 but there are 40 points/);
  assert.throws(() => hullkit.locate(xy, tampered((c) => { c.triangles[1] = c.triangles[0]; }), [0, 0]), /triangle 0 \(.*\) repeats a corner/);
  const boundary = t.halfedges.indexOf(-1);
  const interior = t.halfedges.findIndex((h) => h >= 0);
  assert.throws(() => hullkit.locate(xy, tampered((c) => { c.halfedges[boundary] = interior; }), [0, 0]), /are not one edge run both ways/);
  assert.throws(() => hullkit.locate(xy, tampered((c) => { c.halfedges[interior] = -1; }), [0, 0]), /are not one edge run both ways/);
  assert.throws(() => hullkit.locate(xy, tampered((c) => { c.halfedges[interior] = 1e6; }), [0, 0]), /halfedges\[\d+\] = 1000000 is out of range/);
  assert.throws(() => hullkit.locate(xy, { ...t, halfedges: t.halfedges.subarray(3) }, [0, 0]), /halfedges for/);
  assert.throws(() => hullkit.locate(xy, { ...t, dimension: 3 }, [0, 0]), /dimension 3 is not one of 2, 1, 0, -1/);
  assert.throws(() => hullkit.locate(xy, tampered((c) => { c.representative[3] = 7; }), [0, 0]), /representative\[3\] = 7 is not a lower point/);
  const dup = Float64Array.from([...xy, ...xy.subarray(0, 2)]);
  const td = hullkit.delaunay(dup);
  const usesDuplicate = { ...td, triangles: td.triangles.map((v) => (v === 0 ? 40 : v)) };
  assert.throws(() => hullkit.locate(dup, usesDuplicate, [0, 0]), /triangles\[\d+\] = 40 is a duplicate of point 0/);
});
