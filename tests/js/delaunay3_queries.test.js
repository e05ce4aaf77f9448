// hullkit.locate3 and voronoi3 through the WebAssembly build, checked independently: which
// tetrahedra hold each query and the nearest point by brute force with exact BigInt arithmetic
// (tests/js/exact.js), ties included; the Voronoi cells of a grid are unit cubes, each bounded cell
// of random points has the volume of the convex hull of its vertices (hullkit.hull), its faces lie
// on the bisectors of their two points, turn the documented way and pair up with the Delaunay edges.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import createHullkit, { HullkitError } from '../../wasm/hullkit.js';
import { exactPoints, orient3d, randomBall, seededRandom } from './exact.js';

const hullkit = await createHullkit();

function uniform(n, seed, half = 1) {
  const random = seededRandom(seed);
  return Float64Array.from({ length: 3 * n }, () => half * (2 * random() - 1));
}

/** The integer grid {0..k-1}^3, point (x, y, z) at index x + k y + k² z. */
function grid(k) {
  const xyz = [];
  for (let z = 0; z < k; z++) for (let y = 0; y < k; y++) for (let x = 0; x < k; x++) xyz.push(x, y, z);
  return Float64Array.from(xyz);
}

const corners = (tetrahedra, t) => Array.from(tetrahedra.subarray(4 * t, 4 * t + 4));

/**
 * By brute force, exactly: the lowest-index tetrahedron holding each query (-1 if none), the
 * orientations with each corner replaced by the query (for the barycentric zeros), and the
 * nearest point (lowest index among the nearest).
 */
function bruteForce(xyz, tetrahedra, queries) {
  const n = xyz.length / 3;
  const all = exactPoints(Float64Array.from([...xyz, ...queries]));
  const p = all.slice(0, n);
  const q = all.slice(n);
  const boxes = [];
  for (let t = 0; t < tetrahedra.length / 4; t++) {
    const v = corners(tetrahedra, t);
    boxes.push([0, 1, 2].map((k) => [Math.min(...v.map((i) => xyz[3 * i + k])), Math.max(...v.map((i) => xyz[3 * i + k]))]));
  }
  return q.map((point, j) => {
    let holding = -1;
    let signs = null;
    for (let t = 0; t < boxes.length && holding < 0; t++) {
      // Comparing doubles is exact: a query outside the box of a tetrahedron is not in it.
      if (boxes[t].some(([lo, hi], k) => queries[3 * j + k] < lo || queries[3 * j + k] > hi)) continue;
      const v = corners(tetrahedra, t).map((i) => p[i]);
      const s = [0, 1, 2, 3].map((k) => orient3d(...v.map((w, i) => (i === k ? point : w))));
      if (s.every((x) => x >= 0)) [holding, signs] = [t, s];
    }
    let nearest = -1;
    let best = null;
    p.forEach((w, i) => {
      const d = (w[0] - point[0]) ** 2n + (w[1] - point[1]) ** 2n + (w[2] - point[2]) ** 2n;
      if (best === null || d < best) [best, nearest] = [d, i];
    });
    return { holding, signs, nearest };
  });
}

function checkLocate(xyz, queries, name) {
  const triangulation = hullkit.delaunay3(xyz);
  const result = hullkit.locate3(xyz, triangulation, queries, { barycentric: true, nearest: true });
  const m = queries.length / 3;
  assert.ok(result.tetrahedron instanceof Int32Array && result.tetrahedron.length === m, name);
  assert.ok(result.barycentric instanceof Float64Array && result.barycentric.length === 4 * m, name);
  assert.ok(result.nearest instanceof Int32Array && result.nearest.length === m, name);
  const expected = bruteForce(xyz, triangulation.tetrahedra, queries);
  let inside = 0, onBoundary = 0;
  expected.forEach(({ holding, signs, nearest }, j) => {
    const at = `${name}: query ${j} (${Array.from(queries.subarray(3 * j, 3 * j + 3))})`;
    assert.equal(result.tetrahedron[j], holding, `${at}: tetrahedron`);
    assert.equal(result.nearest[j], nearest, `${at}: nearest`);
    const b = Array.from(result.barycentric.subarray(4 * j, 4 * j + 4));
    if (holding < 0) {
      assert.ok(b.every(Number.isNaN), `${at}: barycentric outside ${b}`);
      return;
    }
    inside++;
    if (signs.includes(0)) onBoundary++;
    signs.forEach((s, k) => assert.equal(b[k] === 0, s === 0, `${at}: barycentric ${k} is ${b[k]}, orientation ${s}`));
    assert.ok(Math.abs(b.reduce((a, x) => a + x, 0) - 1) < 1e-12, `${at}: weights sum to 1: ${b}`);
    const v = corners(triangulation.tetrahedra, holding);
    for (let k = 0; k < 3; k++) {
      const rebuilt = v.reduce((sum, i, c) => sum + b[c] * xyz[3 * i + k], 0);
      assert.ok(Math.abs(rebuilt - queries[3 * j + k]) < 1e-12 * (1 + Math.abs(queries[3 * j + k])), `${at}: Σ b·corner = ${rebuilt}`);
    }
    if (signs.filter((s) => s === 0).length === 3) assert.deepEqual(b.map((x) => (x === 1 ? 1 : x === 0 ? 0 : x)).sort(), [0, 0, 0, 1], `${at}: at a corner`);
  });
  return { inside, onBoundary, outside: m - inside };
}

// ---------------------------------------------------------------- locate3

test('locate3: random points, random queries inside and outside: the lowest tetrahedron holding each, barycentric, nearest (exact brute force)', (t) => {
  const xyz = uniform(120, 1);
  const queries = Float64Array.from([...uniform(250, 2, 1.25), ...xyz.subarray(0, 3 * 60)]);
  const counts = checkLocate(xyz, queries, 'uniform');
  t.diagnostic(JSON.stringify(counts));
  assert.ok(counts.inside > 100 && counts.outside > 30, JSON.stringify(counts));
  assert.ok(counts.onBoundary >= 60, `the input points themselves lie on faces: ${JSON.stringify(counts)}`);
});

test('locate3: a grid, queried at its vertices, edge midpoints, face and cube centres, on its hull and outside (ties: the lowest index)', (t) => {
  const k = 4;
  const xyz = grid(k);
  const queries = [];
  for (let z = 0; z < k; z += 0.5) for (let y = 0; y < k; y += 0.5) for (let x = 0; x < k; x += 0.5) queries.push(x, y, z);
  queries.push(-0.5, 1, 1, 1, 1, 3.5, 1.25, 0, 2.75, 3, 3, 3, 0, 0, 0, 1.5, 1.5, -1e-9);
  const counts = checkLocate(xyz, Float64Array.from(queries), 'grid');
  t.diagnostic(JSON.stringify(counts));
  assert.ok(counts.onBoundary > 100, JSON.stringify(counts));
  // The centre of the cube [1, 2]^3: its 8 corners are equally near; the lowest index wins.
  const { nearest } = hullkit.locate3(xyz, hullkit.delaunay3(xyz), [1.5, 1.5, 1.5], { nearest: true });
  assert.deepEqual([...nearest], [1 + k + k * k]);
});

test('locate3: a ball with duplicates (never the nearest), one query, options off', () => {
  const base = randomBall(80, 3);
  const xyz = Float64Array.from([...base, ...base.subarray(0, 3), ...base.subarray(30, 33)]);
  const queries = Float64Array.from([...base.subarray(30, 33), ...uniform(40, 4)]);
  checkLocate(xyz, queries, 'ball with duplicates');
  const t = hullkit.delaunay3(xyz);
  const { nearest } = hullkit.locate3(xyz, t, base.subarray(30, 33), { nearest: true });
  assert.deepEqual([...nearest], [10]);
  const plain = hullkit.locate3(xyz, t, [0, 0, 0]);
  assert.deepEqual(Object.keys(plain), ['tetrahedron']);
  assert.equal(plain.tetrahedron.length, 1);
  assert.ok(plain.tetrahedron[0] >= 0);
  assert.deepEqual(hullkit.locate3(xyz, t, [], { nearest: true, barycentric: true }),
    { tetrahedron: new Int32Array(0), barycentric: new Float64Array(0), nearest: new Int32Array(0) });
});

test('locate3: points that do not span 3D: no tetrahedron, the nearest point still exact', () => {
  const random = seededRandom(5);
  const plane = [];
  for (let i = 0; i < 60; i++) {
    const x = Math.floor(16 * random()) / 4, y = Math.floor(16 * random()) / 4;
    plane.push(x, y, 0.5 * x - y);
  }
  const cases = {
    coplanar: Float64Array.from(plane),
    collinear: Float64Array.from([0, 0, 0, 1, 1, 1, 3, 3, 3, 2, 2, 2, 1, 1, 1]),
    'one point': Float64Array.from([1, 2, 3, 1, 2, 3]),
  };
  for (const [name, xyz] of Object.entries(cases)) {
    const t = hullkit.delaunay3(xyz);
    assert.ok(t.dimension < 3, name);
    const queries = uniform(50, 6, 4);
    const result = hullkit.locate3(xyz, t, queries, { nearest: true, barycentric: true });
    assert.ok(result.tetrahedron.every((x) => x === -1), name);
    assert.ok(result.barycentric.every(Number.isNaN), name);
    const expected = bruteForce(xyz, new Uint32Array(0), queries);
    assert.deepEqual([...result.nearest], expected.map((e) => e.nearest), name);
  }
  const none = hullkit.locate3([], hullkit.delaunay3([]), [0, 0, 0], { nearest: true });
  assert.deepEqual([...none.tetrahedron, ...none.nearest], [-1, -1]);
});

test('locate3: bad queries, options and triangulations throw, naming what is wrong', () => {
  const xyz = uniform(30, 7);
  const t = hullkit.delaunay3(xyz);
  const query = (pattern, index) => (e) => e instanceof HullkitError && pattern.test(e.message) && e.queryIndex === index;
  assert.throws(() => hullkit.locate3(xyz, t, [0, 0, 0, 0, NaN, 0]), query(/^locate3: query 1 has a non-finite y coordinate \(nan\)/, 1));
  assert.throws(() => hullkit.locate3(xyz, t, [1e300, 0, 0]), query(/query 0: its x coordinate is too far from the points' scale/, 0));
  assert.throws(() => hullkit.locate3(xyz, t, [0, 0]), /locate3: queries: 2 coordinates is not a whole number of 3D points/);
  assert.throws(() => hullkit.locate3(xyz, t, [[0, 0, 0]]), (e) => e instanceof TypeError && /array of arrays/.test(e.message));
  assert.throws(() => hullkit.locate3(xyz, t, [0, 0, 0], { exact: true }), /unknown option "exact" \(known: barycentric, nearest\)/);
  assert.throws(() => hullkit.locate3(xyz, t, [0, 0, 0], { nearest: 1 }), /nearest must be true or false/);
  assert.throws(() => hullkit.locate3(xyz, t.tetrahedra, [0, 0, 0]), (e) => e instanceof TypeError && /the object delaunay3\(\) returned/.test(e.message));
  assert.throws(() => hullkit.locate3(xyz.subarray(3), t, [0, 0, 0]), /representative has 30 entries for 29 points/);
  const tampered = (change) => {
    const copy = { ...t, tetrahedra: t.tetrahedra.slice(), neighbors: t.neighbors.slice() };
    change(copy);
    return copy;
  };
  assert.throws(() => hullkit.locate3(xyz, tampered((c) => { c.tetrahedra[5] = 30; }), [0, 0, 0]), /tetrahedra\[5\] = 30 but there are 30 points/);
  assert.throws(() => hullkit.locate3(xyz, tampered((c) => { c.tetrahedra[1] = c.tetrahedra[0]; }), [0, 0, 0]), /tetrahedron 0 .* repeats a corner/);
  assert.throws(() => hullkit.locate3(xyz, tampered((c) => { c.neighbors[c.neighbors.indexOf(-1)] = 0; }), [0, 0, 0]), /are neighbours .* but do not share that face back|out of range/);
  const interior = t.neighbors.findIndex((u) => u >= 0);
  assert.throws(() => hullkit.locate3(xyz, tampered((c) => { c.neighbors[interior] = -1; }), [0, 0, 0]), /do not share that face back/);
  assert.throws(() => hullkit.locate3(xyz, tampered((c) => { c.neighbors[interior] = 1e6; }), [0, 0, 0]), /out of range/);
  assert.throws(() => hullkit.locate3(xyz, { ...t, dimension: 4 }, [0, 0, 0]), /dimension 4 is not one of/);
  assert.throws(() => hullkit.locate3(xyz, { ...t, neighbors: t.neighbors.subarray(4) }, [0, 0, 0]), /neighbours for/);
  const dup = Float64Array.from([...xyz, ...xyz.subarray(0, 3)]);
  const td = hullkit.delaunay3(dup);
  const usesDuplicate = { ...td, tetrahedra: td.tetrahedra.map((v) => (v === 0 ? 30 : v)) };
  assert.throws(() => hullkit.locate3(dup, usesDuplicate, [0, 0, 0]), /= 30 is a duplicate of point 0/);
  // Plain arrays work as well as typed ones.
  const plain = { dimension: 3, tetrahedra: [...t.tetrahedra], neighbors: [...t.neighbors], representative: [...t.representative] };
  assert.deepEqual(hullkit.locate3([...xyz], plain, [0.1, 0.2, 0.3]), hullkit.locate3(xyz, t, [0.1, 0.2, 0.3]));
});

// ---------------------------------------------------------------- voronoi3

/** The distinct Voronoi vertices of point i's cell, flat x y z. */
function cellVertices(v, i) {
  const seen = new Set();
  for (let f = v.cellOffsets[i]; f < v.cellOffsets[i + 1]; f++) {
    const face = v.cellFaces[f];
    for (let c = v.faceOffsets[face]; c < v.faceOffsets[face + 1]; c++) seen.add(v.faceVertices[c]);
  }
  return Float64Array.from([...seen].flatMap((w) => [v.vertices[3 * w], v.vertices[3 * w + 1], v.vertices[3 * w + 2]]));
}

const point = (xyz, i) => [xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]];

test('voronoi3: the inner cells of a 5x5x5 grid are unit cubes around their points; hull points have unbounded cells', () => {
  const k = 5;
  const xyz = grid(k);
  const t = hullkit.delaunay3(xyz);
  const v = hullkit.voronoi3(xyz, t);
  assert.equal(v.vertices.length / 3, (k - 1) ** 3, 'one vertex per unit cube (its cospherical tetrahedra share it)');
  assert.equal(v.tetrahedronVertex.length, t.tetrahedra.length / 4);
  assert.equal(v.cellOffsets.length, k ** 3 + 1);
  let inner = 0;
  for (let i = 0; i < k ** 3; i++) {
    const [x, y, z] = point(xyz, i);
    const interior = [x, y, z].every((c) => c > 0 && c < k - 1);
    if (!interior) {
      assert.equal(v.volume[i], Infinity, `hull point ${i}`);
      continue;
    }
    inner++;
    assert.ok(Math.abs(v.volume[i] - 1) < 1e-12, `point ${i}: volume ${v.volume[i]}`);
    const faces = v.cellFaces.subarray(v.cellOffsets[i], v.cellOffsets[i + 1]);
    assert.equal(faces.length, 6, `point ${i}: a cube has 6 faces`);
    for (const f of faces) {
      assert.equal(v.faceBounded[f], 1);
      assert.equal(v.faceOffsets[f + 1] - v.faceOffsets[f], 4, 'square faces');
    }
    const corners = cellVertices(v, i);
    assert.equal(corners.length, 24, 'eight corners');
    for (let c = 0; c < 8; c++) {
      const offsets = [0, 1, 2].map((a) => corners[3 * c + a] - [x, y, z][a]);
      assert.ok(offsets.every((d) => Math.abs(Math.abs(d) - 0.5) < 1e-12), `point ${i}: corner ${offsets}`);
    }
  }
  assert.equal(inner, (k - 2) ** 3);
});

test('voronoi3: random points: each bounded cell has the volume of the hull of its vertices; faces on bisectors, oriented, dual to the Delaunay edges', () => {
  const xyz = uniform(300, 8);
  const t = hullkit.delaunay3(xyz);
  const v = hullkit.voronoi3(xyz, t);
  const n = xyz.length / 3;
  const onHull = new Set(t.hull);
  let bounded = 0;
  for (let i = 0; i < n; i++) {
    if (onHull.has(i)) {
      assert.equal(v.volume[i], Infinity, `hull point ${i}`);
      continue;
    }
    bounded++;
    const hull = hullkit.hull(cellVertices(v, i));
    assert.equal(hull.dimension, 3);
    assert.ok(Math.abs(hull.volume - v.volume[i]) <= 1e-9 * hull.volume, `point ${i}: ${v.volume[i]} vs the hull's ${hull.volume}`);
  }
  assert.ok(bounded > 100, `${bounded} bounded cells`);
  // The faces are the Delaunay edges (random points: no cospherical cells), each in both cells.
  const edges = new Set();
  for (let s = 0; s < t.tetrahedra.length; s += 4) {
    for (let a = 0; a < 4; a++) for (let b = a + 1; b < 4; b++) {
      const [p, q] = [t.tetrahedra[s + a], t.tetrahedra[s + b]].sort((x, y) => x - y);
      edges.add(`${p},${q}`);
    }
  }
  const faces = v.facePoints.length / 2;
  assert.equal(faces, edges.size);
  assert.equal(v.faceOffsets.length, faces + 1);
  for (let f = 0; f < faces; f++) {
    const [p, q] = [v.facePoints[2 * f], v.facePoints[2 * f + 1]];
    assert.ok(p < q && edges.has(`${p},${q}`), `face ${f}: ${p} ${q}`);
    for (const i of [p, q]) assert.ok(v.cellFaces.subarray(v.cellOffsets[i], v.cellOffsets[i + 1]).includes(f), `face ${f} in the cell of ${i}`);
    if (!v.faceBounded[f]) assert.ok(onHull.has(p) && onHull.has(q), `face ${f}: only faces dual to hull edges are unbounded`);
    const ring = Array.from(v.faceVertices.subarray(v.faceOffsets[f], v.faceOffsets[f + 1]), (w) => [0, 1, 2].map((k) => v.vertices[3 * w + k]));
    const P = point(xyz, p), Q = point(xyz, q);
    const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
    for (const c of ring) assert.ok(Math.abs(dist(c, P) - dist(c, Q)) < 1e-9 * (1 + dist(c, P)), `face ${f}: a vertex off the bisector of ${p} and ${q}`);
    if (v.faceBounded[f] && ring.length >= 3) {
      // Newell's normal: counter-clockwise seen from q, so it points from p to q.
      const normal = [0, 0, 0];
      ring.forEach((a, j) => {
        const b = ring[(j + 1) % ring.length];
        normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
        normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
        normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
      });
      const along = normal[0] * (Q[0] - P[0]) + normal[1] * (Q[1] - P[1]) + normal[2] * (Q[2] - P[2]);
      assert.ok(along > 0, `face ${f} (${p} → ${q}) is not counter-clockwise seen from ${q}`);
    }
  }
});

test('voronoi3: duplicates get NaN, lower dimensions unbounded cells only; arrays typed and owned', () => {
  const base = uniform(40, 9);
  const xyz = Float64Array.from([...base, ...base.subarray(6, 9)]);
  const v = hullkit.voronoi3(xyz, hullkit.delaunay3(xyz));
  assert.ok(Number.isNaN(v.volume[40]) && !Number.isNaN(v.volume[2]));
  assert.equal(v.cellOffsets[41] - v.cellOffsets[40], 0, 'the duplicate has no faces');
  const types = { vertices: Float64Array, tetrahedronVertex: Uint32Array, facePoints: Uint32Array, faceOffsets: Uint32Array, faceVertices: Uint32Array, faceBounded: Uint8Array, cellOffsets: Uint32Array, cellFaces: Uint32Array, volume: Float64Array };
  for (const [key, type] of Object.entries(types)) {
    assert.ok(v[key] instanceof type, `${key} is a ${type.name}`);
    assert.equal(v[key].buffer.byteLength, v[key].byteLength, `${key} has its own buffer`);
  }
  const flat = Float64Array.from([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.25, 0]);
  const planar = hullkit.voronoi3(flat, hullkit.delaunay3(flat));
  assert.deepEqual([...planar.volume], [Infinity, Infinity, Infinity, Infinity, Infinity]);
  assert.equal(planar.vertices.length + planar.facePoints.length + planar.cellFaces.length, 0);
  assert.throws(() => hullkit.voronoi3(xyz, { dimension: 3, representative: [] }), /voronoi3: representative has 0 entries for 41 points/);
});
