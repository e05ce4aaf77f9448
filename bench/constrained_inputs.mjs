// Writes the constrained Delaunay benchmark's inputs (issue 31) to bench/out/constrained/ (gitignored
// with bench/out): polygons with holes that look like real data, and a planar straight-line graph.
// Every input comes from its own fixed seed (mulberry32 seeded with a hash of its name), so the files
// are the same on every machine.
//
//   node bench/constrained_inputs.mjs [--quick] [--out DIR]
//
// Polygons, one JSON file each (NAME.json): {"kind": "polygon", "name", "description", "coords":
// [x0, y0, x1, y1, ...], "holeIndices": [vertex index where each hole starts], "vertices", "rings",
// "area"} — earcut's arguments; ring 0 is the outer ring (counter-clockwise, y up), the holes
// clockwise; "area" is the outer ring's shoelace area minus the holes'. None self-intersects, and no
// two rings touch, by construction, and the generator checks it exactly (below):
//   lake-1e3, lake-1e4, lake-1e5  a lake shore: a star-shaped ring around a centre whose radius is a
//         periodic midpoint-displacement fractal (roughness 0.62, radius between 0.4 R and R), with
//         islands (holes: smaller fractal rings, each inside its own disc, the discs disjoint and well
//         inside 0.4 R); UTM-like coordinates (metres, centre near 452 km E, 5213 km N), so the
//         coordinates are large next to the details. 4, 9 and 16 islands holding a tenth of the vertices.
//   footprint-1e3, footprint-1e4  a building footprint: a rectilinear "skyline" ring (a flat
//         bottom, columns of random width and height, a third of the neighbours the same height) with
//         rectangular courtyards as holes; every edge split into collinear runs of extra vertices (as
//         digitised outlines have), coordinates multiples of 0.25 m with an offset: exact collinearity.
//   repeated-1e4  a lake with 3 islands whose rings repeat vertices: about one vertex in ten twice in a
//         row, one in fifty three times, and every ring closed by repeating its first vertex (GeoJSON).
//   star-1e4      a star of 4968 sharp spikes (tips between 0.5 and 1, valleys near 0.12) around a
//         64-vertex round hole: long thin triangles.
//   grid-holes-1e3, grid-holes-1e4  a square with a 16 x 16 / 50 x 50 grid of square holes on integer
//         coordinates: four cocircular points everywhere.
// Graph (graph-1e6; graph-1e4 with --quick): NAME.json describes it ({"kind": "graph", "points",
// "segments", "pointsFile", "segmentsFile", "hullArea"}); NAME.xy.bin holds the points (raw
// little-endian float64 x y, uniform in [-1, 1]^2), NAME.seg.bin the segments (uint32 index pairs):
// 1e5 (quick: 1e3) edges of the Delaunay triangulation (delaunator) of every 10th point, every k-th
// edge in delaunator's order. Edges of one triangulation never cross, and each is about three times as
// long as the full set's edges, so it crosses several triangles of the points' own triangulation
// (edges of the full set's triangulation would be there already, and would test nothing).
//
// Quick mode (--quick): every polygon but lake-1e5, and graph-1e4. The list of inputs written goes
// to inputs.json (inputs-quick.json with --quick): [{name, kind, file, vertices|points, ...}].
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { orient2d } from 'robust-predicates';
import Delaunator from 'delaunator';

import { hullArea, mulberry32, polygonArea, ringArea2, seedOf, uniform53 } from './constrained_common.mjs';

const VERSION = 1; // bump when a generator changes: the graph files are kept while the version matches
const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const quick = args.includes('--quick');
const outArg = args.indexOf('--out');
const outDir = outArg >= 0 ? args[outArg + 1] : join(here, 'out', 'constrained');
mkdirSync(outDir, { recursive: true });

/** m samples of a periodic midpoint-displacement fractal, normalised to [lo, hi]. */
function periodicFractal(m, rand, roughness, lo, hi) {
  let v = Array.from({ length: 8 }, () => 2 * rand() - 1);
  let amplitude = 1;
  while (v.length < 2 * m) {
    amplitude *= roughness;
    const w = new Array(2 * v.length);
    for (let i = 0; i < v.length; i++) {
      w[2 * i] = v[i];
      w[2 * i + 1] = (v[i] + v[(i + 1) % v.length]) / 2 + amplitude * (2 * rand() - 1);
    }
    v = w;
  }
  const out = new Float64Array(m);
  for (let i = 0; i < m; i++) {
    const t = (i * v.length) / m;
    const k = Math.floor(t);
    const f = t - k;
    out[i] = v[k] * (1 - f) + v[(k + 1) % v.length] * f;
  }
  let min = Infinity, max = -Infinity;
  for (const x of out) { min = Math.min(min, x); max = Math.max(max, x); }
  for (let i = 0; i < m; i++) out[i] = lo + ((out[i] - min) / (max - min)) * (hi - lo);
  return out;
}

/**
 * A ring star-shaped around (cx, cy): m vertices at increasing angles (jittered), radius r(i);
 * counter-clockwise, or clockwise with `clockwise`. Returns flat coordinates.
 */
function starRing(cx, cy, radii, rand, clockwise) {
  const m = radii.length;
  const out = new Array(2 * m);
  for (let i = 0; i < m; i++) {
    const a = (2 * Math.PI * (i + 0.45 * rand())) / m;
    out[2 * i] = cx + radii[i] * Math.cos(a);
    out[2 * i + 1] = cy + radii[i] * Math.sin(a);
  }
  if (clockwise) {
    const r = [];
    for (let i = m - 1; i >= 0; i--) r.push(out[2 * i], out[2 * i + 1]);
    return r;
  }
  return out;
}

/**
 * Exact check that a ring is simple because star-shaped around (cx, cy): every edge turns the same
 * way strictly around the centre (exact orient2d), and the turns add up to one full turn.
 */
function assertStarShaped(ring, cx, cy, what) {
  const m = ring.length / 2;
  let sign = 0;
  let total = 0;
  for (let i = 0; i < m; i++) {
    const j = (i + 1) % m;
    const o = orient2d(cx, cy, ring[2 * i], ring[2 * i + 1], ring[2 * j], ring[2 * j + 1]);
    const s = Math.sign(o);
    if (s === 0 || (sign !== 0 && s !== sign)) throw new Error(`${what}: edge ${i} does not turn around the centre`);
    sign = s;
    const a = Math.atan2(ring[2 * i + 1] - cy, ring[2 * i] - cx);
    const b = Math.atan2(ring[2 * j + 1] - cy, ring[2 * j] - cx);
    let d = Math.abs(b - a);
    if (d > Math.PI) d = 2 * Math.PI - d;
    total += d;
  }
  if (Math.abs(total - 2 * Math.PI) > 1e-6) throw new Error(`${what}: the ring turns ${total} radians around its centre`);
}

/** Exact check that a ring stays within distance `limit` of (cx, cy) (vertices; edges are chords). */
function maxDistance(ring, cx, cy) {
  let d = 0;
  for (let i = 0; i < ring.length; i += 2) d = Math.max(d, Math.hypot(ring[i] - cx, ring[i + 1] - cy));
  return d;
}

/** Lake: a fractal outer ring with `islands` fractal holes; n vertices in all. */
function lake(name, n, islands, roughness = 0.62) {
  const rand = mulberry32(seedOf(name));
  const cx = 452000 + Math.round(1000 * rand()), cy = 5213000 + Math.round(1000 * rand());
  const R = 2500;
  const holeShare = Math.max(8 * islands, Math.round(0.1 * n));
  const perHole = Math.floor(holeShare / islands);
  const outerCount = n - perHole * islands;
  const outer = starRing(cx, cy, periodicFractal(outerCount, rand, roughness, 0.4 * R, R), rand, false);
  assertStarShaped(outer, cx, cy, `${name} outer ring`);
  // The outer ring's nearest point to the centre: every vertex is at least 0.4 R away and the angle
  // steps are tiny, so every edge stays outside 0.39 R; the islands stay within 0.3 R (checked).
  const rings = [outer];
  const g = Math.ceil(Math.sqrt(islands));
  const side = 0.3 * R * Math.SQRT2 * 0.95; // the square of islands, corners within 0.285 R
  const cell = side / g;
  for (let k = 0; k < islands; k++) {
    const hx = cx - side / 2 + cell * ((k % g) + 0.5);
    const hy = cy - side / 2 + cell * (Math.floor(k / g) + 0.5);
    const rho = 0.42 * cell;
    const ring = starRing(hx, hy, periodicFractal(perHole, rand, roughness, 0.5 * rho, 0.95 * rho), rand, true);
    assertStarShaped(ring, hx, hy, `${name} island ${k}`);
    if (maxDistance(ring, hx, hy) >= 0.96 * rho) throw new Error(`${name}: island ${k} leaves its disc`);
    if (maxDistance(ring, cx, cy) >= 0.3 * R) throw new Error(`${name}: island ${k} too far out`);
    rings.push(ring);
  }
  let nearest = Infinity;
  for (let i = 0; i < outer.length; i += 2) nearest = Math.min(nearest, Math.hypot(outer[i] - cx, outer[i + 1] - cy));
  if (nearest < 0.399 * R) throw new Error(`${name}: outer ring too close to the centre`);
  return rings;
}

/** Building footprint: rectilinear skyline ring with courtyards, collinear runs everywhere. */
function footprint(name, n) {
  const rand = mulberry32(seedOf(name));
  const q = (x) => Math.round(x * 4) / 4; // multiples of 0.25 m
  const ox = 31000, oy = 17000;
  const int = (lo, hi) => lo + Math.floor(rand() * (hi - lo + 1));
  // Columns: widths in [1, 6] m, heights in [20, 40] m, a third equal to the previous one.
  const xs = [0], hs = [];
  let estimate = 8;
  while (estimate < 0.75 * n) {
    xs.push(xs[xs.length - 1] + q(1 + 5 * rand()));
    hs.push(hs.length && rand() < 0.33 ? hs[hs.length - 1] : q(20 + 20 * rand()));
    estimate += 4.5;
  }
  const W = xs[xs.length - 1];
  const outer = [];
  const put = (ring, x, y) => ring.push(ox + x, oy + y);
  /** Points strictly between a and b on a horizontal or vertical edge, k of them, at 0.25 m steps. */
  const between = (a, b, k) => {
    const lo = Math.min(a, b), hi = Math.max(a, b);
    const slots = Math.round((hi - lo) * 4) - 1;
    const chosen = new Set();
    for (let t = 0; t < Math.min(k, slots) * 3 && chosen.size < Math.min(k, slots); t++) chosen.add(1 + Math.floor(rand() * slots));
    const list = [...chosen].sort((u, v) => u - v).map((s) => lo + s / 4);
    return a < b ? list : list.reverse();
  };
  // Bottom: (0,0) to (W,0), a collinear vertex about every 3 m.
  put(outer, 0, 0);
  for (const x of between(0, W, Math.floor(W / 3))) put(outer, x, 0);
  put(outer, W, 0);
  // Right side up.
  const last = hs.length - 1;
  for (const y of between(0, hs[last], int(0, 3))) put(outer, W, y);
  // The skyline, right to left.
  for (let j = last; j >= 0; j--) {
    put(outer, xs[j + 1], hs[j]);
    for (const x of between(xs[j + 1], xs[j], int(0, 2))) put(outer, x, hs[j]);
    if (j > 0 && hs[j - 1] !== hs[j]) {
      put(outer, xs[j], hs[j]);
      for (const y of between(hs[j], hs[j - 1], int(0, 1))) put(outer, xs[j], y);
    }
  }
  put(outer, 0, hs[0]);
  for (const y of between(hs[0], 0, int(0, 3))) put(outer, 0, y);
  // Drop a vertex equal to the one before (a skipped vertical leaves (x_j, h_j) twice): none expected,
  // but the footprint must have no repeats.
  const rings = [dedupe(outer)];
  // Courtyards in the band 4 m < y < 16 m (every column is at least 20 m tall), left to right.
  let x = 2;
  let vertices = rings[0].length / 2;
  while (vertices < n && x < W - 6) {
    const w = q(2 + 6 * rand());
    if (x + w > W - 2) break;
    const y0 = q(4 + 4 * rand()), y1 = q(12 + 4 * rand());
    const ring = [];
    // Clockwise: up the left side, right along the top, down the right side, left along the bottom.
    put(ring, x, y0);
    for (const y of between(y0, y1, int(0, 3))) put(ring, x, y);
    put(ring, x, y1);
    for (const xx of between(x, x + w, int(0, 3))) put(ring, xx, y1);
    put(ring, x + w, y1);
    for (const y of between(y1, y0, int(0, 3))) put(ring, x + w, y);
    put(ring, x + w, y0);
    for (const xx of between(x + w, x, int(0, 3))) put(ring, xx, y0);
    rings.push(ring);
    vertices += ring.length / 2;
    x += w + q(1 + 3 * rand());
  }
  return rings;
}

function dedupe(ring) {
  const out = [];
  for (let i = 0; i < ring.length; i += 2) {
    if (out.length && out[out.length - 2] === ring[i] && out[out.length - 1] === ring[i + 1]) continue;
    out.push(ring[i], ring[i + 1]);
  }
  return out;
}

/** A lake whose rings repeat vertices and are closed GeoJSON-style. */
function repeated(name, n) {
  const rand = mulberry32(seedOf(`${name}/repeats`));
  const base = lake(name, Math.round(n / 1.16), 3);
  return base.map((ring) => {
    const out = [];
    for (let i = 0; i < ring.length; i += 2) {
      const u = rand();
      const times = u < 0.02 ? 3 : u < 0.12 ? 2 : 1;
      for (let t = 0; t < times; t++) out.push(ring[i], ring[i + 1]);
    }
    out.push(ring[0], ring[1]);
    return out;
  });
}

/** A star of sharp spikes around a round hole. */
function star(name, n) {
  const rand = mulberry32(seedOf(name));
  const holeCount = 64;
  const spikes = Math.floor((n - holeCount) / 2);
  const radii = new Float64Array(2 * spikes);
  for (let i = 0; i < spikes; i++) {
    radii[2 * i] = 0.5 + 0.5 * rand();
    radii[2 * i + 1] = 0.12 * (0.8 + 0.2 * rand());
  }
  const outer = starRing(0, 0, radii, () => 0.5, false);
  assertStarShaped(outer, 0, 0, `${name} outer ring`);
  const hole = starRing(0, 0, new Float64Array(holeCount).fill(0.05), () => 0, true);
  assertStarShaped(hole, 0, 0, `${name} hole`);
  return [outer, hole];
}

/** A square with a g x g grid of square holes, integer coordinates. */
function gridHoles(g) {
  const side = 4 * g;
  const rings = [[0, 0, side, 0, side, side, 0, side]];
  for (let i = 0; i < g; i++) {
    for (let j = 0; j < g; j++) {
      const x = 4 * i + 1, y = 4 * j + 1;
      rings.push([x, y, x, y + 2, x + 2, y + 2, x + 2, y]); // clockwise
    }
  }
  return rings;
}

const polygons = [
  { name: 'lake-1e3', make: () => lake('lake-1e3', 1e3, 4), description: 'fractal lake shore, 4 islands, UTM-like coordinates' },
  { name: 'lake-1e4', make: () => lake('lake-1e4', 1e4, 9), description: 'fractal lake shore, 9 islands, UTM-like coordinates' },
  { name: 'lake-1e5', make: () => lake('lake-1e5', 1e5, 16), description: 'fractal lake shore, 16 islands, UTM-like coordinates', full: true },
  { name: 'footprint-1e3', make: () => footprint('footprint-1e3', 1e3), description: 'rectilinear building footprint with courtyards, collinear runs' },
  { name: 'footprint-1e4', make: () => footprint('footprint-1e4', 1e4), description: 'rectilinear building footprint with courtyards, collinear runs' },
  { name: 'repeated-1e4', make: () => repeated('repeated-1e4', 1e4), description: 'lake with 3 islands, repeated consecutive vertices, closed rings' },
  { name: 'star-1e4', make: () => star('star-1e4', 1e4), description: '4968 sharp spikes around a round hole' },
  { name: 'grid-holes-1e3', make: () => gridHoles(16), description: 'square with a 16 x 16 grid of square holes (integers)' },
  { name: 'grid-holes-1e4', make: () => gridHoles(50), description: 'square with a 50 x 50 grid of square holes (integers)' },
].filter((p) => !(quick && p.full));

const list = [];
for (const polygon of polygons) {
  const rings = polygon.make();
  const coords = [];
  const holeIndices = [];
  rings.forEach((ring, k) => {
    if (k > 0) holeIndices.push(coords.length / 2);
    for (const v of ring) coords.push(v);
  });
  const flat = Float64Array.from(coords);
  // Orientation as promised: outer counter-clockwise, holes clockwise.
  const ranges = [0, ...holeIndices, flat.length / 2];
  for (let k = 0; k + 1 < ranges.length; k++) {
    const a2 = ringArea2(flat, ranges[k], ranges[k + 1], flat[0], flat[1]);
    if ((k === 0) !== (a2 > 0)) throw new Error(`${polygon.name}: ring ${k} is wound the wrong way`);
  }
  const area = polygonArea(flat, holeIndices);
  const file = `${polygon.name}.json`;
  const record = { kind: 'polygon', name: polygon.name, version: VERSION, description: polygon.description, vertices: flat.length / 2, rings: rings.length, area };
  writeFileSync(join(outDir, file), JSON.stringify({ ...record, holeIndices, coords }));
  list.push({ ...record, file });
  console.error(`constrained inputs: ${polygon.name}: ${record.vertices} vertices, ${record.rings} rings, area ${area.toPrecision(6)}`);
}

// ---- the graph
const graphPoints = quick ? 1e4 : 1e6;
const graphSegments = quick ? 1e3 : 1e5;
const graphName = `graph-${quick ? '1e4' : '1e6'}`;
const graphFile = join(outDir, `${graphName}.json`);
let graph = null;
if (existsSync(graphFile)) {
  try {
    const old = JSON.parse(readFileSync(graphFile, 'utf8'));
    if (old.version === VERSION && old.points === graphPoints && old.segments === graphSegments &&
        existsSync(join(outDir, old.pointsFile)) && existsSync(join(outDir, old.segmentsFile))) graph = old;
  } catch {
    graph = null;
  }
}
if (!graph) {
  const rand = mulberry32(seedOf(graphName));
  const xy = new Float64Array(2 * graphPoints);
  for (let i = 0; i < xy.length; i++) xy[i] = 2 * uniform53(rand) - 1;
  const stride = 10;
  const coarse = new Float64Array(2 * Math.floor(graphPoints / stride));
  for (let i = 0; i < coarse.length / 2; i++) {
    coarse[2 * i] = xy[2 * stride * i];
    coarse[2 * i + 1] = xy[2 * stride * i + 1];
  }
  const d = new Delaunator(coarse);
  const edges = [];
  for (let e = 0; e < d.triangles.length; e++) {
    if (d.halfedges[e] < e) edges.push(e); // each undirected edge once (hull edges have -1)
  }
  if (edges.length < graphSegments) throw new Error(`${graphName}: only ${edges.length} coarse edges`);
  const k = Math.floor(edges.length / graphSegments);
  const segments = new Uint32Array(2 * graphSegments);
  for (let s = 0; s < graphSegments; s++) {
    const e = edges[s * k];
    const next = e % 3 === 2 ? e - 2 : e + 1;
    segments[2 * s] = stride * d.triangles[e];
    segments[2 * s + 1] = stride * d.triangles[next];
  }
  const pointsFile = `${graphName}.xy.bin`, segmentsFile = `${graphName}.seg.bin`;
  writeFileSync(join(outDir, pointsFile), Buffer.from(xy.buffer));
  writeFileSync(join(outDir, segmentsFile), Buffer.from(segments.buffer));
  graph = {
    kind: 'graph', name: graphName, version: VERSION,
    description: `${graphPoints} uniform points in [-1, 1]^2, ${graphSegments} edges of the Delaunay triangulation of every 10th point`,
    points: graphPoints, segments: graphSegments, pointsFile, segmentsFile, hullArea: hullArea(xy),
  };
  writeFileSync(graphFile, JSON.stringify(graph));
  console.error(`constrained inputs: ${graphName}: ${graphPoints} points, ${graphSegments} segments (every ${k}-th of ${edges.length} coarse edges)`);
} else {
  console.error(`constrained inputs: ${graphName}: kept`);
}
list.push({ ...graph, file: `${graphName}.json` });
writeFileSync(join(outDir, quick ? 'inputs-quick.json' : 'inputs.json'), JSON.stringify(list, null, 1) + '\n');
