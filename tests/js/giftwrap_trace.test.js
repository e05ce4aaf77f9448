// hullkit.giftwrapTrace: the recorded events of the C++ gift wrap replay to the one-shot hull.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import createHullkit, { HullkitError } from '../../wasm/hullkit.js';
import { randomBall } from './exact.js';
import bunny from 'bunny';

const hullkit = await createHullkit();

/**
 * Replays a trace: the edge stack from push_edge, each pop_edge / skip_edge taking its top (checked
 * to be the edge it names), the accepted triangles in order. Returns {triangles, counts}.
 */
function replay(trace) {
  const stack = [];
  const triangles = [];
  const counts = {};
  for (let e = 0; e < trace.kinds.length; e++) {
    const kind = trace.kindNames[trace.kinds[e]];
    const [a, b, c] = trace.args.subarray(3 * e, 3 * e + 3);
    counts[kind] = (counts[kind] ?? 0) + 1;
    switch (kind) {
      case 'push_edge':
        stack.push([a, b]);
        break;
      case 'pop_edge':
      case 'skip_edge':
        assert.ok(stack.length > 0, `event ${e}: ${kind} on an empty stack`);
        assert.deepEqual(stack.pop(), [a, b], `event ${e}: ${kind} ${a} ${b} is not the top of the stack`);
        break;
      case 'accept':
        triangles.push(a, b, c);
        break;
      case 'done':
        assert.equal(e, trace.kinds.length - 1, 'done is the last event');
        assert.equal(stack.length, 0, 'the stack is empty at done');
        assert.equal(b, triangles.length / 3);
        break;
      default:
        assert.ok(kind !== undefined, `event ${e}: unknown kind ${trace.kinds[e]}`);
    }
  }
  return { triangles: Uint32Array.from(triangles), counts };
}

function cubeWithInterior() {
  const xyz = [];
  for (let i = 0; i < 8; i++) xyz.push(i & 1 ? 2 : -2, i & 2 ? 2 : -2, i & 4 ? 2 : -2);
  const inside = randomBall(30, 5);
  xyz.push(...inside, 2, 0, 0, 0, -2, 0, 0, 0, 2, 2, 2, 0, -2, 0, -2);
  return new Float64Array(xyz);
}

function grid(k) {
  const xyz = [];
  for (let x = 0; x < k; x++) for (let y = 0; y < k; y++) for (let z = 0; z < k; z++) xyz.push(x, y, z);
  return new Float64Array(xyz);
}

/** A bumpy, non-convex closed surface with points inside, like a scanned figurine. */
function lumpy(n) {
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    const t = Math.acos(1 - (2 * (i + 0.5)) / n);
    const f = 2.399963229728653 * i;
    let r = 1 + 0.25 * Math.sin(3 * t) * Math.cos(2 * f) + 0.1 * Math.cos(5 * f);
    if (i % 5 === 0) r *= 0.6;
    xyz.set([r * Math.sin(t) * Math.cos(f), 0.8 * r * Math.sin(t) * Math.sin(f), 1.2 * r * Math.cos(t)], 3 * i);
  }
  return xyz;
}

const inputs = {
  'random ball': randomBall(300, 21),
  'cube corners with interior, face and edge points': cubeWithInterior(),
  'grid with coplanar points': grid(4),
  'lumpy figurine': lumpy(400),
};
const bunnyXyz = Float64Array.from(bunny.positions.flat());

for (const scan of ['single-pass', 'restart']) {
  for (const [name, xyz] of Object.entries(inputs)) {
    test(`giftwrapTrace (${scan}): ${name} replays to the one-shot hull`, () => {
      const trace = hullkit.giftwrapTrace(xyz, { scan });
      assert.ok(trace.kinds instanceof Uint8Array);
      assert.ok(trace.args instanceof Uint32Array);
      assert.equal(trace.args.length, 3 * trace.kinds.length);
      assert.equal(trace.dimension, 3);
      const { triangles, counts } = replay(trace);
      const oneShot = hullkit.hull(xyz, { algorithm: 'giftwrap' });
      assert.deepEqual(triangles, oneShot.triangles);
      assert.deepEqual(trace.triangles, oneShot.triangles);
      assert.equal(counts.first_point, 1);
      assert.equal(counts.first_edge, 1);
      if (scan === 'single-pass') assert.equal(counts.restart, undefined);
      else assert.equal(counts.replace, undefined);
      // Deterministic.
      const again = hullkit.giftwrapTrace(xyz, { scan });
      assert.deepEqual(again.kinds, trace.kinds);
      assert.deepEqual(again.args, trace.args);
    });
  }
}

test('giftwrapTrace: the Stanford bunny (single pass, all points; restart, the first 600)', () => {
  for (const [scan, xyz] of [['single-pass', bunnyXyz], ['restart', bunnyXyz.subarray(0, 1800)]]) {
    const trace = hullkit.giftwrapTrace(xyz, { scan });
    assert.deepEqual(replay(trace).triangles, hullkit.hull(xyz, { algorithm: 'giftwrap' }).triangles);
  }
});

test('giftwrapTrace: event names and the first steps', () => {
  const xyz = randomBall(40, 3);
  const trace = hullkit.giftwrapTrace(xyz);
  assert.deepEqual(trace.kindNames, ['first_point', 'first_edge', 'vertical_face', 'wrap_first', 'push_edge', 'pop_edge',
    'skip_edge', 'candidate', 'replace', 'restart', 'coplanar', 'accept', 'done']);
  assert.equal(trace.kindNames[trace.kinds[0]], 'first_point');
  assert.equal(trace.kindNames[trace.kinds[1]], 'first_edge');
  const first = trace.args[0];
  for (let i = 0; i < 40; i++) assert.ok(xyz[3 * i] <= xyz[3 * first]);
  // Results are the caller's: a second call leaves the first intact.
  const copy = trace.args.slice();
  hullkit.giftwrapTrace(randomBall(200, 4));
  assert.deepEqual(trace.args, copy);
});

test('giftwrapTrace: input without volume is a single done event', () => {
  const square = new Float64Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0]);
  const trace = hullkit.giftwrapTrace(square);
  assert.equal(trace.dimension, 2);
  assert.deepEqual([...trace.kinds].map((k) => trace.kindNames[k]), ['done']);
  assert.deepEqual(trace.triangles, hullkit.hull(square, { algorithm: 'giftwrap' }).triangles);
  const empty = hullkit.giftwrapTrace(new Float64Array(0));
  assert.equal(empty.dimension, -1);
  assert.equal(empty.triangles.length, 0);
});

test('giftwrapTrace: bad input and too many points throw HullkitError', () => {
  assert.throws(() => hullkit.giftwrapTrace(new Float64Array([0, 0, 0, 1, 0, 0, NaN, 1, 0, 0, 0, 1])),
    (error) => error instanceof HullkitError && error.pointIndex === 2 && /non-finite/.test(error.message));
  assert.throws(() => hullkit.giftwrapTrace(new Float64Array(5)), HullkitError);
  assert.throws(() => hullkit.giftwrapTrace(randomBall(10, 1), { scan: 'twice' }), /unknown scan "twice"/);
  assert.throws(() => hullkit.giftwrapTrace(randomBall(10, 1), { algorithm: 'quickhull' }), /unknown option "algorithm"/);
  assert.equal(hullkit.traceLimits['single-pass'], 5000);
  assert.throws(() => hullkit.giftwrapTrace(randomBall(5001, 1)),
    (error) => error instanceof HullkitError && /5001 points is too many to trace .* \(at most 5000\)/.test(error.message));
  assert.throws(() => hullkit.giftwrapTrace(randomBall(1001, 1), { scan: 'restart' }), /at most 1000/);
});

// ---- the Delaunay view's lifting: the wrap on the lifted points, projected

function sortedTriangles(flat) {
  const out = [];
  for (let i = 0; i < flat.length; i += 3) out.push(`${flat[i]},${flat[i + 1]},${flat[i + 2]}`);
  return out.sort();
}

test('delaunayGiftwrapTrace: replay gives delaunay(xy, {algorithm: giftwrap})', () => {
  const random = new Float64Array(400);
  let state = 9;
  for (let i = 0; i < random.length; i++) random[i] = (state = (state * 16807) % 2147483647) / 2147483647;
  const grid = [];
  for (let x = 0; x < 5; x++) for (let y = 0; y < 4; y++) grid.push(x, y);
  grid.push(1, 1, 4, 3); // duplicates
  for (const xy of [random, new Float64Array(grid)]) {
    const trace = hullkit.delaunayGiftwrapTrace(xy);
    const oneShot = hullkit.delaunay(xy, { algorithm: 'giftwrap' });
    assert.equal(trace.dimension, 2);
    assert.deepEqual(trace.triangles, oneShot.triangles);
    const { triangles, counts } = replay(trace);
    assert.deepEqual(sortedTriangles(triangles), sortedTriangles(oneShot.triangles));
    assert.equal(counts.first_point, 1);
    assert.equal(counts.restart, undefined);
    const again = hullkit.delaunayGiftwrapTrace(xy);
    assert.deepEqual(again.args, trace.args);
  }
});

test('delaunayGiftwrapTrace: degenerate and bad input', () => {
  const line = hullkit.delaunayGiftwrapTrace(new Float64Array([0, 0, 1, 1, 2, 2]));
  assert.equal(line.dimension, 1);
  assert.deepEqual([...line.kinds].map((k) => line.kindNames[k]), ['done']);
  assert.throws(() => hullkit.delaunayGiftwrapTrace(new Float64Array([0, 0, 1, Infinity, 0, 1])),
    (error) => error instanceof HullkitError && error.pointIndex === 1);
  assert.throws(() => hullkit.delaunayGiftwrapTrace(new Float64Array(2 * 2001)), /at most 2000/);
});
