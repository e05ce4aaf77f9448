// hullkit.hullNd, delaunayNd and locateNd through the WebAssembly build: every facet and simplex
// checked exactly in JS (BigInt determinants by Bareiss' elimination, independent of hullkit), and
// in 2D and 3D against hullkit's own hull, delaunay and delaunay3 (other algorithms).
import { test } from 'node:test';
import assert from 'node:assert/strict';

import createHullkit, { HullkitError } from '../../wasm/hullkit.js';
import { seededRandom } from './exact.js';

const hullkit = await createHullkit();

/** x * 2^1074 as a BigInt: exact for every finite double. */
function scaled(x) {
  if (x === 0) return 0n;
  const buffer = new DataView(new ArrayBuffer(8));
  buffer.setFloat64(0, x);
  const bits = buffer.getBigUint64(0);
  const exponent = Number((bits >> 52n) & 0x7ffn);
  const fraction = bits & ((1n << 52n) - 1n);
  const mantissa = exponent === 0 ? fraction : fraction | (1n << 52n);
  const shift = BigInt(Math.max(exponent, 1) - 1);  // value = mantissa * 2^(exponent - 1075)
  const value = mantissa << shift;
  return x < 0 ? -value : value;
}

/** The sign of the determinant of a square BigInt matrix (Bareiss: every division exact). */
function signOfDet(matrix) {
  const a = matrix.map((row) => row.slice());
  const n = a.length;
  let sign = 1;
  let previous = 1n;
  for (let k = 0; k < n - 1; k++) {
    if (a[k][k] === 0n) {
      const swap = a.findIndex((row, r) => r > k && row[k] !== 0n);
      if (swap < 0) return 0;
      [a[k], a[swap]] = [a[swap], a[k]];
      sign = -sign;
    }
    for (let i = k + 1; i < n; i++) {
      for (let j = k + 1; j < n; j++) a[i][j] = (a[i][j] * a[k][k] - a[i][k] * a[k][j]) / previous;
    }
    previous = a[k][k];
  }
  const det = a[n - 1][n - 1];
  return det === 0n ? 0 : (det > 0n ? sign : -sign);
}

const row = (p, d, i) => [...Array.from(p.subarray(i * d, i * d + d), scaled), 1n];
function liftedRow(p, d, i) {
  const x = Array.from(p.subarray(i * d, i * d + d), scaled);
  return [...x, x.reduce((s, v) => s + v * v, 0n), 1n];
}

function uniform(n, d, seed) {
  const random = seededRandom(seed);
  return Float64Array.from({ length: n * d }, () => 2 * random() - 1);
}

const sortedRows = (flat, width) => {
  const rows = [];
  for (let k = 0; k < flat.length; k += width) rows.push(Array.from(flat.subarray(k, k + width)).sort((a, b) => a - b).join(' '));
  return rows.sort();
};

test('hullNd in 4 and 5 dimensions: every point on the inner side of every facet, exactly', () => {
  for (const d of [4, 5]) {
    const p = uniform(d === 4 ? 40 : 24, d, d);
    const n = p.length / d;
    const h = hullkit.hullNd(p, d);
    const corners = new Set();
    for (let f = 0; f < h.facets.length / d; f++) {
      const base = Array.from(h.facets.subarray(f * d, f * d + d), (c) => { corners.add(c); return row(p, d, c); });
      let strict = false;
      for (let q = 0; q < n; q++) {
        const s = signOfDet([...base, row(p, d, q)]);
        assert.ok(s <= 0, `point ${q} outside facet ${f}`);
        strict ||= s < 0;
      }
      assert.ok(strict, `facet ${f} is flat`);
    }
    assert.deepEqual(Array.from(h.vertices), [...corners].sort((a, b) => a - b));
  }
});

test('hullNd and delaunayNd in 2D and 3D agree with hull, delaunay and delaunay3', () => {
  const xyz = uniform(200, 3, 7);
  const h3 = hullkit.hullNd(xyz, 3);
  const reference = hullkit.hull(xyz);
  assert.deepEqual(Array.from(h3.vertices), Array.from(reference.vertices).sort((a, b) => a - b));
  assert.deepEqual(sortedRows(h3.facets, 3), sortedRows(reference.triangles, 3));
  const t3 = hullkit.delaunayNd(xyz, 3);
  assert.deepEqual(sortedRows(t3.simplices, 4), sortedRows(hullkit.delaunay3(xyz).tetrahedra, 4));
  const xy = uniform(300, 2, 8);
  const t2 = hullkit.delaunayNd(Array.from(xy), 2);  // an array of numbers as well
  assert.deepEqual(sortedRows(t2.simplices, 3), sortedRows(hullkit.delaunay(xy).triangles, 3));
});

test('delaunayNd in 4D: positively oriented simplices with empty circumspheres, exactly; cube corners', () => {
  const d = 4;
  const p = uniform(30, d, 11);
  const n = p.length / d;
  const t = hullkit.delaunayNd(p, d);
  for (let s = 0; s < t.simplices.length / (d + 1); s++) {
    const corners = Array.from(t.simplices.subarray(s * (d + 1), (s + 1) * (d + 1)));
    assert.equal(signOfDet(corners.map((c) => row(p, d, c))), 1);
    const lifted = corners.map((c) => liftedRow(p, d, c));
    for (let q = 0; q < n; q++) {
      if (!corners.includes(q)) assert.equal(signOfDet([...lifted, liftedRow(p, d, q)]), -1, `point ${q} in the sphere of ${s}`);
    }
  }
  // The 16 corners of the 4-cube lie on one sphere: a full triangulation all the same.
  const cube = [];
  for (let m = 0; m < 16; m++) cube.push([0, 1, 2, 3].map((j) => (m >> j) & 1));
  const c = hullkit.delaunayNd(cube, 4);
  assert.ok(c.group.every((g) => g === 0));
  const volume = (s) => {
    const rows = Array.from(c.simplices.subarray(s * 5, s * 5 + 5), (k) => [...cube[k].map(BigInt), 1n]);
    assert.equal(signOfDet(rows), 1);
    return s;
  };
  for (let s = 0; s < c.simplices.length / 5; s++) volume(s);
  assert.equal(hullkit.delaunayNd(cube, 4, { furthestSite: true }).simplices.length, c.simplices.length);
});

test('locateNd: each query in a simplex that holds it, -1 only outside every simplex', () => {
  const d = 4;
  const p = uniform(25, d, 12);
  const t = hullkit.delaunayNd(p, d);
  const queries = uniform(40, d, 13);
  const found = hullkit.locateNd(p, t, queries);
  const m = t.simplices.length / (d + 1);
  const holds = (s, q) => {
    const corners = Array.from(t.simplices.subarray(s * (d + 1), (s + 1) * (d + 1)));
    return corners.every((_, k) => signOfDet(corners.map((c, j) => (j === k ? row(queries, d, q) : row(p, d, c)))) >= 0);
  };
  for (let q = 0; q < found.length; q++) {
    if (found[q] >= 0) assert.ok(holds(found[q], q), `query ${q}`);
    else for (let s = 0; s < m; s++) assert.ok(!holds(s, q), `query ${q} is in simplex ${s}`);
  }
  assert.ok(found.some((s) => s >= 0) && found.some((s) => s < 0));
});

test('hullNd, delaunayNd and locateNd: errors say what is wrong', () => {
  const flat = [];
  for (let i = 0; i < 10; i++) flat.push([i % 3, (i * 7) % 5, i % 2, i % 3]);  // x_3 = x_0: a hyperplane
  assert.throws(() => hullkit.hullNd(flat, 4), { name: 'HullkitError', message: /lie in a flat of 3 dimensions/ });
  const bad = uniform(10, 4, 14);
  bad[4 * 6 + 1] = NaN;
  assert.throws(() => hullkit.delaunayNd(bad, 4), (e) => e instanceof HullkitError && e.pointIndex === 6 && /point 6 has a non-finite coordinate 1/.test(e.message));
  assert.throws(() => hullkit.hullNd(uniform(12, 11, 1), 11), /2 to 10 dimensions, not 11/);
  assert.throws(() => hullkit.hullNd([[0, 0, 0, 0], [1, 0, 0]], 4), (e) => e instanceof HullkitError && e.pointIndex === 1 && /hullNd: points\[1\] has 3 coordinates, expected 4/.test(e.message));
  assert.throws(() => hullkit.delaunayNd(uniform(10, 4, 1), 4, { furthest: true }), /unknown option "furthest"/);
  const p = uniform(20, 4, 15);
  const t = hullkit.delaunayNd(p, 4);
  const broken = { ...t, simplices: t.simplices.slice() };
  broken.simplices[3] = 99;
  assert.throws(() => hullkit.locateNd(p, broken, [0, 0, 0, 0]), /simplex 0 has a corner past the points/);
  assert.throws(() => hullkit.locateNd(p.subarray(0, 40), t, [0, 0, 0, 0]), /does not fit these points/);
});
