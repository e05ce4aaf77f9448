// hullkit.delaunay, find and voronoi through the WebAssembly build: checked exactly (BigInt
// empty-circle tests), against delaunator (npm) on ordinary input, against the native CLI, and by
// brute force for find and voronoi.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, writeFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

import Delaunator from 'delaunator';
import createHullkit, { HullkitError } from '../../wasm/hullkit.js';
import { exactPoints, seededRandom } from './exact.js';

const root = fileURLToPath(new URL('../..', import.meta.url));
const cli = process.env.HULLKIT_CLI ?? join(root, 'build/native/hullkit');
const hullkit = await createHullkit();

// ---------------------------------------------------------------- inputs

function uniform(n, seed) {
  const random = seededRandom(seed);
  return Float64Array.from({ length: 2 * n }, () => 2 * random() - 1);
}

function gaussian(n, seed) {
  const random = seededRandom(seed);
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < 2 * n; i += 2) {
    const r = Math.sqrt(-2 * Math.log(1 - random()));
    const a = 2 * Math.PI * random();
    xy[i] = r * Math.cos(a);
    xy[i + 1] = r * Math.sin(a);
  }
  return xy;
}

/** The integer grid {0..k-1}^2: every unit square's corners are cocircular. */
function grid(k) {
  const xy = [];
  for (let i = 0; i < k; i++) for (let j = 0; j < k; j++) xy.push(j, i);
  return Float64Array.from(xy);
}

// ---------------------------------------------------------------- exact checks

/** Exact integer (BigInt) coordinates of the 2D points, all scaled by one power of two. */
function exact2d(xy) {
  const xyz = new Float64Array((xy.length / 2) * 3);
  for (let i = 0; i < xy.length / 2; i++) xyz.set([xy[2 * i], xy[2 * i + 1], 0], 3 * i);
  return exactPoints(xyz);
}

const sign = (v) => (v > 0n ? 1 : v < 0n ? -1 : 0);
const orient2d = (a, b, c) => sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
/** > 0 when d is inside the circle through a, b, c given counter-clockwise. */
function incircle(a, b, c, d) {
  const [ax, ay, bx, by, cx, cy] = [a[0] - d[0], a[1] - d[1], b[0] - d[0], b[1] - d[1], c[0] - d[0], c[1] - d[1]];
  const [aw, bw, cw] = [ax * ax + ay * ay, bx * bx + by * by, cx * cx + cy * cy];
  return sign(ax * (by * cw - bw * cy) - ay * (bx * cw - bw * cx) + aw * (bx * cy - by * cx));
}

const next = (e) => (e % 3 === 2 ? e - 2 : e + 1);

/**
 * Problems with `result` as the Delaunay triangulation of `xy`, exactly: triangles clockwise (y up)
 * and not degenerate, halfedges symmetric between the same two points, the hull the cycle of the
 * boundary half-edges, the triangle count 2n - h - 2, and the empty-circle test across every
 * interior edge (which, for a triangulation, makes it Delaunay).
 */
function delaunayProblems(xy, result) {
  const problems = [];
  const { triangles, halfedges, hull } = result;
  const p = exact2d(xy);
  for (let t = 0; t < triangles.length; t += 3) {
    if (orient2d(p[triangles[t]], p[triangles[t + 1]], p[triangles[t + 2]]) >= 0) problems.push(`triangle ${t / 3} is not clockwise`);
  }
  const hullNext = new Map();
  for (let e = 0; e < halfedges.length; e++) {
    const o = halfedges[e];
    if (o === -1) {
      hullNext.set(triangles[e], triangles[next(e)]);
      continue;
    }
    if (halfedges[o] !== e || triangles[o] !== triangles[next(e)] || triangles[next(o)] !== triangles[e]) {
      problems.push(`halfedges ${e} and ${o} do not match`);
      continue;
    }
    // The point opposite o, tested against the circle of e's triangle (clockwise: inside < 0).
    const t = e - (e % 3);
    const d = triangles[next(next(o))];
    if (incircle(p[triangles[t]], p[triangles[t + 1]], p[triangles[t + 2]], p[d]) < 0) {
      problems.push(`point ${d} is inside the circumcircle of triangle ${t / 3}`);
    }
  }
  if (hullNext.size !== hull.length) problems.push(`hull has ${hull.length} points, the boundary ${hullNext.size}`);
  for (let k = 0; k < hull.length; k++) {
    if (hullNext.get(hull[k]) !== hull[(k + 1) % hull.length]) problems.push(`hull[${k}] is not followed by the boundary's next point`);
  }
  const distinct = new Set();
  for (let i = 0; i < xy.length / 2; i++) distinct.add(`${xy[2 * i]},${xy[2 * i + 1]}`);
  if (triangles.length && triangles.length / 3 !== 2 * distinct.size - hull.length - 2) {
    problems.push(`${triangles.length / 3} triangles, expected 2n - h - 2 = ${2 * distinct.size - hull.length - 2}`);
  }
  return problems.slice(0, 10);
}

/** The triangles as strings of their rotation starting at the smallest index, sorted. */
function canonicalTriangles(triangles) {
  const out = [];
  for (let t = 0; t < triangles.length; t += 3) {
    const tri = [triangles[t], triangles[t + 1], triangles[t + 2]];
    const k = tri.indexOf(Math.min(...tri));
    out.push(`${tri[k]},${tri[(k + 1) % 3]},${tri[(k + 2) % 3]}`);
  }
  return out.sort();
}

/** Directed edge "a,b" -> the directed edge across it ("b,a") or "hull", for comparing halfedges. */
function adjacency(triangles, halfedges) {
  const map = new Map();
  for (let e = 0; e < triangles.length; e++) {
    const o = halfedges[e];
    map.set(`${triangles[e]},${triangles[next(e)]}`, o === -1 ? 'hull' : `${triangles[o]},${triangles[next(o)]}`);
  }
  return map;
}

/** The cycle rotated to start at its smallest entry. */
function canonicalCycle(cycle) {
  const list = [...cycle];
  const k = list.indexOf(Math.min(...list));
  return [...list.slice(k), ...list.slice(0, k)];
}

// ---------------------------------------------------------------- delaunay

test('delaunay: the same triangulation as delaunator on ordinary input', () => {
  for (const [name, xy] of [['uniform', uniform(3000, 1)], ['gaussian', gaussian(3000, 2)], ['small uniform', uniform(7, 3)]]) {
    const ours = hullkit.delaunay(xy);
    const theirs = new Delaunator(xy);
    assert.equal(ours.triangles.length, theirs.triangles.length, name);
    assert.deepEqual(canonicalTriangles(ours.triangles), canonicalTriangles(theirs.triangles), name);
    assert.deepEqual(adjacency(ours.triangles, ours.halfedges), adjacency(theirs.triangles, theirs.halfedges), name);
    assert.deepEqual(canonicalCycle(ours.hull), canonicalCycle(theirs.hull), name);
    assert.deepEqual(delaunayProblems(xy, ours), [], name);
  }
});

test('delaunay: code written for delaunator runs unchanged on the result (edges, triangles around a point)', () => {
  const xy = uniform(500, 7);
  // delaunator's documented idioms: every edge once via e > halfedges[e]; the triangles around a
  // point by following halfedges from an incoming half-edge.
  const walk = (t) => {
    let edges = 0;
    for (let e = 0; e < t.triangles.length; e++) if (e > t.halfedges[e]) edges++;
    const degrees = [];
    for (let point = 0; point < 20; point++) {
      if (t.hull.includes(point)) continue;
      const start = t.triangles.findIndex((_, e) => t.triangles[next(e)] === point);
      let incoming = start;
      let count = 0;
      do {
        count++;
        incoming = t.halfedges[next(incoming)];
      } while (incoming !== -1 && incoming !== start);
      degrees.push(count);
    }
    return { edges, degrees };
  };
  assert.deepEqual(walk(hullkit.delaunay(xy)), walk(new Delaunator(xy)));
});

test('delaunay: results equal the native command line', () => {
  const dir = mkdtempSync(join(tmpdir(), 'hullkit-delaunay-js-'));
  try {
    for (const [name, xy] of [['gaussian', gaussian(2000, 4)], ['grid', grid(12)], ['duplicates', Float64Array.from([...uniform(50, 5), 0.5, 0.5, 0.5, 0.5])]]) {
      const file = join(dir, `${name}.txt`);
      let text = '';
      for (let i = 0; i < xy.length; i += 2) text += `${xy[i]} ${xy[i + 1]}\n`; // shortest round-trip form
      writeFileSync(file, text);
      for (const algorithm of hullkit.delaunayAlgorithms) {
        if (algorithm === 'giftwrap' && xy.length > 1000) continue; // O(n^2)
        const native = JSON.parse(execFileSync(cli, ['delaunay', file, '--format', 'json', '--algorithm', algorithm], { encoding: 'utf8' }));
        const wasm = hullkit.delaunay(xy, { algorithm });
        assert.equal(wasm.dimension, native.dimension, name);
        assert.deepEqual([...wasm.triangles], native.triangles.flat(), `${name} ${algorithm}`);
        assert.deepEqual([...wasm.halfedges], native.halfedges, `${name} ${algorithm}`);
        assert.deepEqual([...wasm.hull], native.hull, `${name} ${algorithm}`);
        const duplicates = [];
        wasm.representative.forEach((r, i) => r !== i && duplicates.push([i, r]));
        assert.deepEqual(duplicates, native.duplicates, name);
      }
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('delaunay: exact on cocircular and degenerate sets, and every algorithm agrees', () => {
  const circle = [];
  for (let k = 0; k < 64; k++) circle.push(Math.cos((2 * Math.PI * k) / 64), Math.sin((2 * Math.PI * k) / 64));
  const cases = {
    grid: grid(9),
    'circle with centre': Float64Array.from([...circle, 0, 0]),
    circle: Float64Array.from(circle),
    'offset 1e7': uniform(300, 9).map((v) => v + 1e7),
  };
  for (const [name, xy] of Object.entries(cases)) {
    const results = hullkit.delaunayAlgorithms.map((algorithm) => hullkit.delaunay(xy, { algorithm }));
    assert.deepEqual(delaunayProblems(xy, results[0]), [], name);
    for (const other of results.slice(1)) assert.deepEqual(canonicalTriangles(other.triangles), canonicalTriangles(results[0].triangles), name);
  }
});

test('delaunay: mergeCocircular returns the squares of a grid', () => {
  const result = hullkit.delaunay(grid(5), { mergeCocircular: true });
  assert.ok(result.polygonOffsets instanceof Uint32Array && result.polygonVertices instanceof Uint32Array);
  assert.equal(result.polygonOffsets.length, 16 + 1);
  for (let p = 0; p < 16; p++) assert.equal(result.polygonOffsets[p + 1] - result.polygonOffsets[p], 4);
  assert.equal(hullkit.delaunay(grid(5)).polygonOffsets, undefined);
});

test('delaunay: degenerate input is a value: none, one, duplicates, collinear', () => {
  const none = hullkit.delaunay(new Float64Array(0));
  assert.equal(none.dimension, -1);
  assert.equal(none.triangles.length, 0);
  const one = hullkit.delaunay([3, 4, 3, 4, 3, 4]);
  assert.equal(one.dimension, 0);
  assert.deepEqual([...one.representative], [0, 0, 0]);
  assert.equal(one.duplicateCount, 2);
  const line = hullkit.delaunay([2, 2, 0, 0, 3, 3, 1, 1, 1, 1]);
  assert.equal(line.dimension, 1);
  assert.equal(line.triangles.length, 0);
  assert.equal(line.halfedges.length, 0);
  assert.ok(['1,3,0,2', '2,0,3,1'].includes([...line.hull].join(',')), `collinear hull ${[...line.hull]}`);
  assert.equal(line.duplicateCount, 1);
  const square = hullkit.delaunay([0, 0, 1, 0, 1, 1, 0, 1, 1, 1]);
  assert.equal(square.dimension, 2);
  assert.equal(square.triangles.length, 6);
  assert.deepEqual([...square.representative], [0, 1, 2, 3, 2]);
  for (const index of square.triangles) assert.notEqual(index, 4); // the duplicate is never used
});

test('delaunay: results are owned by the caller and typed as documented', () => {
  const first = hullkit.delaunay(uniform(1000, 11));
  assert.ok(first.triangles instanceof Uint32Array);
  assert.ok(first.halfedges instanceof Int32Array);
  assert.ok(first.hull instanceof Uint32Array);
  assert.ok(first.representative instanceof Uint32Array);
  assert.equal(typeof first.duplicateCount, 'number');
  const copies = [first.triangles.slice(), first.halfedges.slice(), first.hull.slice()];
  for (let i = 0; i < 3; i++) hullkit.delaunay(uniform(100000, 20 + i)); // grows the heap
  assert.deepEqual([first.triangles, first.halfedges, first.hull], copies);
  assert.notEqual(first.triangles.buffer.byteLength, 0);
  // A plain array gives the same as a Float64Array.
  const xy = uniform(40, 12);
  assert.deepEqual(hullkit.delaunay([...xy]), hullkit.delaunay(xy));
});

test('delaunay: bad input and options throw HullkitError naming what is wrong', () => {
  assert.throws(() => hullkit.delaunay([0, 0, 1]), (e) => e instanceof HullkitError && /not a whole number of 2D points/.test(e.message));
  assert.throws(() => hullkit.delaunay([0, 0, 1, 0, 0, 1, NaN, 2]), (e) => e instanceof HullkitError && e.pointIndex === 3);
  assert.throws(() => hullkit.delaunay([0, 0, 1, Infinity, 0, 1]), (e) => e instanceof HullkitError && e.pointIndex === 1);
  assert.throws(() => hullkit.delaunay([0, 0, 1e-300, 1, 1e300, 1]), (e) => e instanceof HullkitError && e.pointIndex >= 1);
  assert.throws(() => hullkit.delaunay([0, 0], { algorithm: 'quickhull' }), /unknown algorithm "quickhull" \(known: incremental, giftwrap\)/);
  assert.throws(() => hullkit.delaunay([0, 0], { merge: true }), /unknown option "merge"/);
  assert.throws(() => hullkit.delaunay([0, 0], { mergeCocircular: 1 }), /mergeCocircular must be true or false/);
  assert.throws(() => hullkit.delaunay('0 0 1 1'), TypeError);
  assert.deepEqual([...hullkit.delaunayAlgorithms], ['incremental', 'giftwrap']);
});

// ---------------------------------------------------------------- find

/** The nearest point by brute force (exact ties: lowest index; squared distances exactly in BigInt). */
function nearest(xy, x, y) {
  const p = exact2d(Float64Array.from([...xy, x, y]));
  const q = p.pop();
  let best = -1;
  let bestDistance = 0n;
  for (let i = 0; i < p.length; i++) {
    const d = (p[i][0] - q[0]) ** 2n + (p[i][1] - q[1]) ** 2n;
    if (best === -1 || d < bestDistance) [best, bestDistance] = [i, d];
  }
  return best;
}

test('find: the nearest input point, from any start, as brute force says', () => {
  const xy = gaussian(400, 13);
  const triangulation = hullkit.delaunay(xy);
  const random = seededRandom(14);
  let previous = 0;
  for (let k = 0; k < 200; k++) {
    const [x, y] = [6 * random() - 3, 6 * random() - 3];
    const expected = nearest(xy, x, y);
    assert.equal(hullkit.find(xy, triangulation, x, y), expected, `query ${x} ${y}`);
    assert.equal(hullkit.find(xy, triangulation, x, y, previous), expected);
    previous = expected;
  }
  // Ties go to the lowest index; a duplicate's representative is returned.
  const square = [0, 0, 2, 0, 2, 2, 0, 2, 2, 2];
  const t = hullkit.delaunay(square);
  assert.equal(hullkit.find(square, t, 1, 1), 0);
  assert.equal(hullkit.find(square, t, 3, 3, 1), 2);
  // Also on a delaunator object, and with no points.
  assert.equal(hullkit.find(xy, new Delaunator(xy), 0.1, 0.2), nearest(xy, 0.1, 0.2));
  assert.equal(hullkit.find([], hullkit.delaunay([]), 0, 0), -1);
  // Collinear points: no triangles, still an answer.
  const line = [0, 0, 1, 1, 2, 2, 3, 3];
  assert.equal(hullkit.find(line, hullkit.delaunay(line), 2.2, 1.9), 2);
});

test('find: bad arguments throw', () => {
  const xy = uniform(20, 15);
  const t = hullkit.delaunay(xy);
  assert.throws(() => hullkit.find(xy, t, NaN, 0), /x must be a finite number/);
  assert.throws(() => hullkit.find(xy, t, 0, 0, 20), /start must be a point index from 0 to 19/);
  assert.throws(() => hullkit.find(xy, t, 0, 0, 1.5), /start must be a point index/);
  assert.throws(() => hullkit.find(xy.subarray(0, 10), t, 0, 0), /representative has 20 entries for 5 points \(the triangulation is of other points\)/);
  assert.throws(() => hullkit.find(xy.subarray(0, 10), { ...t, representative: undefined }, 0, 0), /triangles\[\d+\] = \d+ but there are 5 points/);
  assert.throws(() => hullkit.find(xy, { ...t, halfedges: t.halfedges.subarray(3) }, 0, 0), /halfedges for/);
  assert.throws(() => hullkit.find(xy, null, 0, 0), TypeError);
});

// ---------------------------------------------------------------- voronoi

function polygonArea(xy) {
  let area = 0;
  for (let i = 0; i < xy.length; i += 2) {
    const j = (i + 2) % xy.length;
    area += xy[i] * xy[j + 1] - xy[j] * xy[i + 1];
  }
  return area / 2;
}

/** True if (x, y) is inside the counter-clockwise convex polygon (boundary included, with slack). */
function insideConvex(cell, x, y) {
  for (let i = 0; i < cell.length; i += 2) {
    const j = (i + 2) % cell.length;
    const cross = (cell[j] - cell[i]) * (y - cell[i + 1]) - (cell[j + 1] - cell[i + 1]) * (x - cell[i]);
    if (cross < -1e-12) return false;
  }
  return true;
}

test('voronoi: the cells tile the rectangle and each holds the points nearest its site', () => {
  const xy = uniform(150, 16);
  xy.set([xy[0], xy[1]], 2 * 149); // point 149 duplicates point 0: it gets no cell
  const bounds = [-1.5, -1.2, 1.5, 1.3];
  const { cellOffsets, cellXY } = hullkit.voronoi(xy, hullkit.delaunay(xy), bounds);
  assert.ok(cellOffsets instanceof Uint32Array && cellXY instanceof Float64Array);
  assert.equal(cellOffsets.length, 151);
  const cells = [];
  let total = 0;
  for (let i = 0; i < 150; i++) {
    const cell = cellXY.subarray(2 * cellOffsets[i], 2 * cellOffsets[i + 1]);
    cells.push(cell);
    if (i === 149) {
      assert.equal(cell.length, 0, 'a duplicate has no cell');
      continue;
    }
    assert.ok(cell.length >= 6, `cell ${i} has ${cell.length / 2} corners`);
    const area = polygonArea(cell);
    assert.ok(area > 0, `cell ${i} is counter-clockwise`);
    assert.ok(insideConvex(cell, xy[2 * i], xy[2 * i + 1]), `cell ${i} holds its site`);
    total += area;
  }
  const rectangle = (bounds[2] - bounds[0]) * (bounds[3] - bounds[1]);
  assert.ok(Math.abs(total - rectangle) < 1e-9 * rectangle, `cells cover ${total} of ${rectangle}`);
  const random = seededRandom(17);
  for (let k = 0; k < 300; k++) {
    const x = bounds[0] + (bounds[2] - bounds[0]) * random();
    const y = bounds[1] + (bounds[3] - bounds[1]) * random();
    const owner = nearest(xy, x, y);
    assert.ok(insideConvex(cells[owner], x, y), `(${x}, ${y}) is nearest to ${owner} but outside its cell`);
  }
});

test('voronoi: bad bounds throw', () => {
  const xy = uniform(10, 18);
  const t = hullkit.delaunay(xy);
  assert.throws(() => hullkit.voronoi(xy, t, [0, 0, 1]), TypeError);
  assert.throws(() => hullkit.voronoi(xy, t, [0, 0, 0, 1]), /bounds .* are empty/);
  assert.throws(() => hullkit.voronoi(xy, t, [0, 0, NaN, 1]), /bounds xmax must be a finite number/);
  assert.throws(() => hullkit.voronoi(xy, t), TypeError);
});

test('voronoiDiagram: a vertex per cocircular group, each bounded cell the clipped cell, open cells on the hull', () => {
  const xy = uniform(300, 23);
  for (let j = 0; j < 6; j++) for (let i = 0; i < 6; i++) xy.set([2 + i / 4, j / 4], 2 * (240 + 6 * j + i)); // a grid
  xy.set([xy[2], xy[3]], 2 * 299); // point 299 repeats point 1
  const t = hullkit.delaunay(xy);
  const v = hullkit.voronoiDiagram(xy, t);
  for (const [name, type] of [['vertices', Float64Array], ['triangleVertex', Uint32Array], ['ridgePoints', Int32Array],
    ['ridgeVertices', Int32Array], ['cells', Int32Array], ['cellOffsets', Uint32Array], ['cellPoint', Uint32Array],
    ['pointCell', Int32Array], ['areas', Float64Array]]) assert.ok(v[name] instanceof type, name);
  assert.equal(v.pointCell[299], v.pointCell[1]);
  assert.equal(v.cellPoint.length, 299);
  // The grid's 25 squares are 25 vertices, each at its square's centre.
  const centres = new Set();
  for (let k = 0; k < v.vertices.length; k += 2) {
    const x = (v.vertices[k] - 2) * 4, y = v.vertices[k + 1] * 4;
    if (x > 0 && x < 5 && y > 0 && y < 5 && x % 1 === 0.5 && y % 1 === 0.5) centres.add(`${x},${y}`);
  }
  assert.equal(centres.size, 25);
  assert.equal(v.triangleVertex.length, t.triangles.length / 3);
  // Against the cells clipped to a rectangle holding every vertex.
  let [xmin, ymin, xmax, ymax] = [Infinity, Infinity, -Infinity, -Infinity];
  for (let k = 0; k < v.vertices.length; k += 2) {
    xmin = Math.min(xmin, v.vertices[k]); xmax = Math.max(xmax, v.vertices[k]);
    ymin = Math.min(ymin, v.vertices[k + 1]); ymax = Math.max(ymax, v.vertices[k + 1]);
  }
  const clipped = hullkit.voronoi(xy, t, [xmin - 5, ymin - 5, xmax + 5, ymax + 5]);
  const onHull = new Set(t.hull);
  for (let c = 0; c < v.cellPoint.length; c++) {
    const s = v.cellPoint[c];
    const cell = v.cells.subarray(v.cellOffsets[c], v.cellOffsets[c + 1]);
    assert.equal(v.pointCell[s], c);
    assert.equal(cell[cell.length - 1] === -1, onHull.has(s), `cell of ${s}: open exactly on the hull`);
    if (onHull.has(s)) {
      assert.equal(v.areas[c], Infinity);
      continue;
    }
    assert.equal(cell[0], Math.min(...cell), 'a bounded cell starts at its lowest vertex');
    const corners = Float64Array.from(Array.from(cell).flatMap((k) => [v.vertices[2 * k], v.vertices[2 * k + 1]]));
    const reference = clipped.cellXY.subarray(2 * clipped.cellOffsets[s], 2 * clipped.cellOffsets[s + 1]);
    assert.ok(Math.abs(polygonArea(corners) - v.areas[c]) <= 1e-12 * (1 + v.areas[c]));
    assert.ok(Math.abs(polygonArea(reference) - v.areas[c]) <= 1e-9 * (1 + v.areas[c]), `cell of ${s}`);
  }
  // Ridges: one per Delaunay edge between two groups: the edges less the grid squares' diagonals.
  const edges = new Set();
  for (let e = 0; e < t.triangles.length; e++) {
    const a = t.triangles[e], b = t.triangles[e % 3 === 2 ? e - 2 : e + 1];
    edges.add(`${Math.min(a, b)},${Math.max(a, b)}`);
  }
  assert.equal(v.ridgePoints.length / 2, edges.size - 25);
  for (let r = 0; r < v.ridgePoints.length; r += 2) assert.ok(edges.has(`${v.ridgePoints[r]},${v.ridgePoints[r + 1]}`));
});

test('voronoiDiagram: collinear points, a triangulation of other points', () => {
  const line = [0, 0, 2, 0, 1, 0];
  const l = hullkit.voronoiDiagram(line, hullkit.delaunay(line));
  assert.deepEqual(Array.from(l.cells), [-1, -1, -1]);
  assert.deepEqual(Array.from(l.ridgePoints), [0, 2, 1, 2]);
  assert.deepEqual(Array.from(l.ridgeVertices), [-1, -1, -1, -1]);
  assert.throws(() => hullkit.voronoiDiagram([0, 0, 1, 0, 0, 1, 1, 1], hullkit.delaunay(line)), HullkitError);
});

test('delaunay: arrays of points as Delaunator.from takes them ([x, y]) and {x, y} objects (three.js Vector2)', () => {
  const xy = uniform(500, 31);
  const expected = hullkit.delaunay(xy);
  const pairs = Array.from({ length: xy.length / 2 }, (_, i) => [xy[2 * i], xy[2 * i + 1]]);
  // The same points delaunator users hand to Delaunator.from, with the same triangles back.
  const theirs = Delaunator.from(pairs);
  assert.equal(theirs.triangles.length, expected.triangles.length);
  for (const points of [pairs, pairs.map(([x, y]) => ({ x, y })), pairs.map(([x, y]) => ({ x, y, z: 7, isVector3: true }))]) {
    const result = hullkit.delaunay(points);
    assert.deepEqual(result.triangles, expected.triangles);
    assert.deepEqual(result.halfedges, expected.halfedges);
    assert.deepEqual(result.hull, expected.hull);
    assert.equal(hullkit.find(points, result, 0.1, 0.2), hullkit.find(xy, expected, 0.1, 0.2));
    assert.deepEqual(hullkit.voronoi(points, result, [-1, -1, 1, 1]), hullkit.voronoi(xy, expected, [-1, -1, 1, 1]));
  }
  assert.throws(() => hullkit.delaunay([[0, 0], [1, 0], [0, 1, 2]]), (error) => error instanceof HullkitError &&
    error.pointIndex === 2 && error.message === 'delaunay: points[2] has 3 coordinates, expected 2');
  assert.throws(() => hullkit.delaunay([{ x: 0, y: 0 }, { x: 1 }]), { message: /^delaunay: points\[1\] has no numeric y \(y is missing\); pass a flat Float64Array \(or array of numbers\) x0 y0 x1 y1 \.\.\., or an array of points \[x, y\] or \{x, y\}$/ });
  assert.throws(() => hullkit.delaunay([0, 0, 1]), { message: /3 coordinates is not a whole number of 2D points \(x0 y0 x1 y1 \.\.\.\); or pass an array of points \[x, y\] or \{x, y\}/ });
});
