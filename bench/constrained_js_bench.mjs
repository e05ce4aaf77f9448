// Times one JavaScript polygon / constrained triangulation implementation on one input of
// bench/constrained_inputs.mjs in a fresh Node process, checks what it returned, and prints one JSON line.
//
//   node --expose-gc bench/constrained_js_bench.mjs --impl IMPL --input bench/out/constrained/NAME.json [--runs 5] [--budget 60] [--no-check]
//
// IMPL, on a polygon (flat coordinates + hole start indices, earcut's arguments):
//   hullkit        hullkit's WebAssembly build through its public API (wasm/hullkit.js):
//                  triangulatePolygon(coords: Float64Array, holeIndices) — the whole call, copies in
//                  and out included. "not available" while the module has no triangulatePolygon.
//   earcut         earcut(coords, holeIndices) on the same Float64Array (ear clipping: not a CDT).
//   constrainautor new Delaunator(coords), then new Constrainautor(delaunator) and constrainAll(ring
//                  edges), then the triangles inside: a flood fill from the convex hull that crosses
//                  constrained edges with even-odd parity (the triangulation covers the convex hull;
//                  the caller must pick the inside). All three steps timed.
//   cdt2d          cdt2d(points, edges, {exterior: false}) (its own even-odd rule drops the outside).
//   poly2tri       new SweepContext(outer).addHoles(holes).triangulate(), getTriangles().
// on a graph (points + segments):
//   hullkit        constrainedDelaunay(coords: Float64Array, edges: Uint32Array).
//   constrainautor new Delaunator(coords), new Constrainautor(delaunator, edges) (edges as [a, b] pairs).
//   cdt2d          cdt2d(points, edges) (the whole convex hull).
//   earcut and poly2tri triangulate polygons only: "not applicable".
// Each library gets its input in the form it takes, made before the clock starts (cdt2d and poly2tri:
// arrays of points; poly2tri's point objects anew for every run, as it writes into them); hullkit and
// earcut take the flat Float64Array itself. Loading (imports, createHullkit) and reading the file are
// not timed. The first call after loading is reported on its own ("first": what a user meets) and the
// median of the later calls as "warm"; a full garbage collection runs between calls under --expose-gc.
// No further call starts once the calls add up to more than --budget seconds.
//
// After the timed calls, untimed: the first call's triangles are checked (bench/constrained_common.mjs:
// a triangulation of exactly the polygon, or of the graph's hull keeping every segment) and the line
// gets "verdict": "ok" | "wrong" (with "reason") | "exception" (a call threw; "error" has the message)
// | "not available" | "not applicable". --no-check skips the check ("verdict": "unchecked"): the extra
// fresh processes bench/constrained_run.sh runs for a median of first calls, whose result the
// first process checked.
// Output: {"impl", "input", "kind", "n", "first", "runs", "warm", "triangles", "verdict", "reason",
// "area_error", "t_junctions" (polygons: places where a vertex lies on another triangle's edge; the
// verdict stays ok, the report marks them), "peak_rss_mb", "detail"}.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { basename } from 'node:path';
import { parseArgs } from 'node:util';

import { checkGraph, checkPolygon, median, readInput, ringRanges } from './constrained_common.mjs';

const require = createRequire(import.meta.url);
const IMPLS = ['hullkit', 'earcut', 'constrainautor', 'cdt2d', 'poly2tri'];

function usage(message) {
  console.error(`constrained_js_bench: ${message}`);
  console.error(`usage: node bench/constrained_js_bench.mjs --impl ${IMPLS.join('|')} --input FILE.json [--runs 5] [--budget 60] [--no-check]`);
  process.exit(2);
}

let values;
try {
  ({ values } = parseArgs({
    args: process.argv.slice(2),
    options: {
      impl: { type: 'string' }, input: { type: 'string' }, runs: { type: 'string', default: '5' }, budget: { type: 'string', default: '60' },
      'no-check': { type: 'boolean', default: false },
    },
  }));
} catch (error) {
  usage(error.message);
}
const impl = values.impl;
const runs = Number(values.runs);
const budget = Number(values.budget);
if (!impl || !values.input) usage('--impl and --input are required');
if (!IMPLS.includes(impl)) usage(`unknown implementation ${impl}`);
if (!(runs >= 1)) usage('--runs must be at least 1');

const input = readInput(values.input);
const name = input.name ?? basename(values.input).replace(/\.json$/, '');
const isPolygon = input.kind === 'polygon';
const n = input.coords.length / 2;
// A package's version from its package.json (some packages' "exports" do not expose that file).
const version = (pkg) => JSON.parse(readFileSync(new URL(`../node_modules/${pkg}/package.json`, import.meta.url), 'utf8')).version;

function emit(fields) {
  console.log(JSON.stringify({ impl, input: name, kind: input.kind, n, ...fields }));
}

/** The ring edges of a polygon as [a, b] pairs (consecutive vertices and the closing one). */
function ringEdges() {
  const edges = [];
  for (const [s, e] of ringRanges(n, input.holeIndices)) {
    for (let i = s; i < e; i++) edges.push([i, i + 1 < e ? i + 1 : s]);
  }
  return edges;
}

/**
 * The triangles of a delaunator triangulation constrained by Constrainautor that are inside the
 * polygon: breadth-first from the hull triangles (outside, parity 0), flipping the parity across
 * constrained edges; inside is odd. Returns a Uint32Array of vertex triples.
 */
function insideTriangles(d, con) {
  const { triangles, halfedges } = d;
  const t = triangles.length / 3;
  const parity = new Int8Array(t).fill(-1);
  const queue = new Int32Array(t);
  let head = 0, tail = 0;
  // Seeds: triangles with a hull edge; outside unless that hull edge is constrained.
  for (let e = 0; e < halfedges.length; e++) {
    if (halfedges[e] !== -1) continue;
    const f = Math.floor(e / 3);
    const p = con.isConstrained(e) ? 1 : 0;
    if (parity[f] === -1) {
      parity[f] = p;
      queue[tail++] = f;
    }
  }
  while (head < tail) {
    const f = queue[head++];
    for (let k = 0; k < 3; k++) {
      const e = 3 * f + k;
      const o = halfedges[e];
      if (o === -1) continue;
      const g = Math.floor(o / 3);
      if (parity[g] !== -1) continue;
      parity[g] = con.isConstrained(e) ? 1 - parity[f] : parity[f];
      queue[tail++] = g;
    }
  }
  let count = 0;
  for (let f = 0; f < t; f++) if (parity[f] === 1) count++;
  const out = new Uint32Array(3 * count);
  let w = 0;
  for (let f = 0; f < t; f++) {
    if (parity[f] !== 1) continue;
    out[w++] = triangles[3 * f];
    out[w++] = triangles[3 * f + 1];
    out[w++] = triangles[3 * f + 2];
  }
  return out;
}

const flatten = (cells) => {
  const out = new Uint32Array(3 * cells.length);
  cells.forEach((c, k) => out.set(c, 3 * k));
  return out;
};

// Each implementation: prepare() (untimed) returns the call's arguments, run(args) is timed,
// triangles(result) (untimed) gives flat vertex triples (and coords when the result has its own).
let impls;
try {
  impls = await setUp();
} catch (error) {
  emit({ verdict: 'exception', error: `loading: ${String(error.message ?? error)}` });
  process.exit(0);
}
if (impls.unavailable || impls.inapplicable) {
  emit({ verdict: impls.unavailable ? 'not available' : 'not applicable', error: impls.unavailable ?? impls.inapplicable });
  process.exit(0);
}

async function setUp() {
  const coords = input.coords;
  if (impl === 'hullkit') {
    const { default: createHullkit } = await import('../wasm/hullkit.js');
    const hullkit = await createHullkit();
    const fn = isPolygon ? 'triangulatePolygon' : 'constrainedDelaunay';
    if (typeof hullkit[fn] !== 'function') return { unavailable: `wasm/hullkit.js has no ${fn} yet` };
    const result = (r) => ({ triangles: r.triangles, coords: r.coords && r.coords.length > coords.length ? r.coords : coords });
    return isPolygon
      ? { detail: 'hullkit wasm triangulatePolygon(Float64Array, holeIndices), copies in and out included', prepare: () => null,
          run: () => hullkit.triangulatePolygon(coords, input.holeIndices), triangles: result }
      : { detail: 'hullkit wasm constrainedDelaunay(Float64Array, Uint32Array), copies in and out included', prepare: () => null,
          run: () => hullkit.constrainedDelaunay(coords, input.segments), triangles: result };
  }
  if (impl === 'earcut') {
    if (!isPolygon) return { inapplicable: 'earcut triangulates polygons only' };
    const { default: earcut } = await import('earcut');
    return { detail: `earcut ${version('earcut')} earcut(Float64Array, holeIndices)`, prepare: () => null,
      run: () => earcut(coords, input.holeIndices), triangles: (r) => ({ triangles: r, coords }) };
  }
  if (impl === 'constrainautor') {
    const { default: Delaunator } = await import('delaunator');
    const { default: Constrainautor } = await import('@kninnug/constrainautor');
    const detail = `delaunator ${version('delaunator')} + @kninnug/constrainautor ${version('@kninnug/constrainautor')}`;
    if (isPolygon) {
      const edges = ringEdges();
      return { detail: `${detail}: new Delaunator(Float64Array), constrainAll(ring edges), inside by even-odd flood fill`, prepare: () => null,
        run: () => {
          const d = new Delaunator(coords);
          const con = new Constrainautor(d);
          con.constrainAll(edges);
          return insideTriangles(d, con);
        },
        triangles: (r) => ({ triangles: r, coords }) };
    }
    const edges = [];
    for (let s = 0; s < input.segments.length; s += 2) edges.push([input.segments[s], input.segments[s + 1]]);
    return { detail: `${detail}: new Delaunator(Float64Array), new Constrainautor(d, edges)`, prepare: () => null,
      run: () => {
        const d = new Delaunator(coords);
        new Constrainautor(d, edges);
        return d.triangles;
      },
      triangles: (r) => ({ triangles: r, coords }) };
  }
  if (impl === 'cdt2d') {
    const cdt2d = require('cdt2d');
    const points = [];
    for (let i = 0; i < n; i++) points.push([coords[2 * i], coords[2 * i + 1]]);
    const edges = [];
    if (isPolygon) edges.push(...ringEdges());
    else for (let s = 0; s < input.segments.length; s += 2) edges.push([input.segments[s], input.segments[s + 1]]);
    return isPolygon
      ? { detail: `cdt2d ${version('cdt2d')} cdt2d(points, ring edges, {exterior: false})`, prepare: () => null,
          run: () => cdt2d(points, edges, { exterior: false }), triangles: (r) => ({ triangles: flatten(r), coords }) }
      : { detail: `cdt2d ${version('cdt2d')} cdt2d(points, edges)`, prepare: () => null,
          run: () => cdt2d(points, edges), triangles: (r) => ({ triangles: flatten(r), coords }) };
  }
  if (impl === 'poly2tri') {
    if (!isPolygon) return { inapplicable: 'poly2tri triangulates polygons only' };
    const poly2tri = require('poly2tri');
    const rings = ringRanges(n, input.holeIndices);
    const prepare = () =>
      rings.map(([s, e]) => {
        const ring = [];
        for (let i = s; i < e; i++) ring.push({ x: coords[2 * i], y: coords[2 * i + 1], id: i });
        return ring;
      });
    return { detail: `poly2tri ${version('poly2tri')} new SweepContext(outer).addHoles(holes).triangulate()`, prepare,
      run: (points) => {
        const context = new poly2tri.SweepContext(points[0]);
        context.addHoles(points.slice(1));
        context.triangulate();
        return context.getTriangles();
      },
      triangles: (r) => {
        const out = new Uint32Array(3 * r.length);
        r.forEach((t, k) => {
          for (let j = 0; j < 3; j++) {
            const id = t.getPoint(j).id;
            out[3 * k + j] = id === undefined ? 0xffffffff : id; // a point poly2tri made itself: out of range
          }
        });
        return { triangles: out, coords };
      } };
  }
  throw new Error(`unknown implementation ${impl}`);
}

const times = [];
let firstResult = null;
let total = 0;
for (let k = 0; k < runs && (k === 0 || total < budget); k++) {
  if (k > 0 && globalThis.gc) globalThis.gc();
  const args = impls.prepare();
  let result;
  const start = performance.now();
  try {
    result = impls.run(args);
  } catch (error) {
    emit({ first: times[0] ?? null, runs: times, verdict: 'exception', error: String(error?.message ?? error).slice(0, 300),
      detail: impls.detail, peak_rss_mb: process.resourceUsage().maxRSS / 1024 });
    process.exit(0);
  }
  const seconds = (performance.now() - start) / 1000;
  times.push(seconds);
  total += seconds;
  if (k === 0) firstResult = result;
}
const peak = process.resourceUsage().maxRSS / 1024;
if (values['no-check']) {
  // One more fresh process for a median of first calls (bench/constrained_run.sh): the result was checked in the first.
  emit({ first: times[0], runs: times, warm: median(times.slice(1)), verdict: 'unchecked', peak_rss_mb: peak, detail: impls.detail });
  process.exit(0);
}
let check;
try {
  const { triangles, coords } = impls.triangles(firstResult);
  check = isPolygon ? checkPolygon(input, triangles, coords) : checkGraph(input, triangles, coords);
} catch (error) {
  check = { verdict: 'wrong', reason: `unreadable result: ${String(error?.message ?? error)}` };
}
emit({
  first: times[0],
  runs: times,
  warm: median(times.slice(1)),
  triangles: check.triangles ?? null,
  verdict: check.verdict,
  ...(check.reason ? { reason: check.reason } : {}),
  area_error: check.area_error ?? null,
  ...(check.t_junctions != null ? { t_junctions: check.t_junctions } : {}),
  peak_rss_mb: peak,
  detail: impls.detail,
});
