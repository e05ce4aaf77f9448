// Shared pieces of the constrained Delaunay benchmark (issue 31): the seeded generator, reading the
// inputs written by bench/constrained_inputs.mjs, medians, and the independent check of a
// triangulation's output against its input (used by bench/constrained_js_bench.mjs in-process and by
// bench/constrained_check.mjs for the native programs' dumps).
//
// The check, for a polygon with holes (rings earcut's way: flat coords, hole start indices):
//   - every index in range, every triangle with nonzero area (robust-predicates' exact orient2d),
//     all triangles wound the same way;
//   - no directed edge used twice once the triangles are wound counter-clockwise (two triangles
//     overlapping across an edge, or a triangle used twice);
//   - the triangles' boundary equals the rings (the outer ring counter-clockwise, the holes
//     clockwise) as 1-chains: the edges with no reverse edge minus the ring edges must cancel, by
//     coordinates, exactly collinear pieces line by line. So a triangulator may drop collinear and
//     repeated ring vertices (one edge along several ring edges); a T-junction (a vertex on another
//     triangle's edge) still covers the polygon once and passes, counted in `t_junctions` (not a
//     conforming triangulation: the report marks it);
//   - the triangles' total area equals the polygon's (shoelace of the outer ring minus the holes',
//     in doubles, relative to the outer ring's first vertex) within a relative 1e-9.
// Consistently wound triangles whose boundary chain is the polygon's boundary cover every point
// of the polygon exactly once, so these tests together mean "a triangulation of this polygon".
// For a planar straight-line graph (points + segments): the same orientation and edge tests, the
// boundary edges on the convex hull's supporting lines and the total area the hull's, every distinct
// input point used, and every segment an edge (or a chain of edges through exactly collinear points).
// A failed test makes the verdict "wrong" with the first reason; the area error is always reported.
// Quality meshes (points added inside and on the rings, rounded to doubles) get checkMesh instead:
// see there.
import { readFileSync } from 'node:fs';
import { orient2d } from 'robust-predicates';

/** mulberry32, the page's seeded generator (floats in [0, 1)): the inputs use it too. */
export { mulberry32 } from '../web/distributions.js';

/** A 32-bit FNV-1a hash of a string: each input's seed comes from its name. */
export function seedOf(name) {
  let h = 0x811c9dc5;
  for (let i = 0; i < name.length; i++) h = Math.imul(h ^ name.charCodeAt(i), 0x01000193) >>> 0;
  return h;
}

/** Uniform doubles in [0, 1) with 53 random bits from two 32-bit draws. */
export function uniform53(rand) {
  const high = Math.floor(rand() * 2 ** 27);
  const low = Math.floor(rand() * 2 ** 26);
  return (high * 2 ** 26 + low) / 2 ** 53;
}

export function median(values) {
  if (values.length === 0) return null;
  const s = [...values].sort((a, b) => a - b);
  const m = s.length;
  return m % 2 ? s[(m - 1) / 2] : (s[m / 2 - 1] + s[m / 2]) / 2;
}

/** Counter-clockwise (y up) is positive here: robust-predicates' orient2d is positive clockwise. */
const ccw = (ax, ay, bx, by, cx, cy) => -orient2d(ax, ay, bx, by, cx, cy);

/**
 * Reads one input. A polygon: {kind: 'polygon', name, coords: Float64Array, holeIndices: number[],
 * area, ...}. A graph: {kind: 'graph', name, coords: Float64Array, segments: Uint32Array, hullArea,
 * ...} (its descriptor names the binary files next to it).
 */
export function readInput(file) {
  const input = JSON.parse(readFileSync(file, 'utf8'));
  if (input.kind === 'polygon') {
    input.coords = Float64Array.from(input.coords);
    return input;
  }
  const dir = file.replace(/[^/]*$/, '');
  const xy = readFileSync(dir + input.pointsFile);
  const seg = readFileSync(dir + input.segmentsFile);
  input.coords = new Float64Array(xy.buffer.slice(xy.byteOffset, xy.byteOffset + xy.byteLength));
  input.segments = new Uint32Array(seg.buffer.slice(seg.byteOffset, seg.byteOffset + seg.byteLength));
  return input;
}

/** The rings of a polygon as [start, end) vertex ranges. */
export function ringRanges(vertexCount, holeIndices) {
  const starts = [0, ...holeIndices];
  return starts.map((start, k) => [start, k + 1 < starts.length ? starts[k + 1] : vertexCount]);
}

/** Twice the signed area of ring [start, end) (shoelace relative to (ox, oy)), counter-clockwise positive. */
export function ringArea2(coords, start, end, ox, oy) {
  let sum = 0;
  for (let i = start; i < end; i++) {
    const j = i + 1 < end ? i + 1 : start;
    const ax = coords[2 * i] - ox, ay = coords[2 * i + 1] - oy;
    const bx = coords[2 * j] - ox, by = coords[2 * j + 1] - oy;
    sum += ax * by - bx * ay;
  }
  return sum;
}

/** The polygon's area: |outer| minus the holes' |area|, in doubles. */
export function polygonArea(coords, holeIndices) {
  const ox = coords[0], oy = coords[1];
  const rings = ringRanges(coords.length / 2, holeIndices);
  let area = 0;
  rings.forEach(([s, e], k) => {
    const a = Math.abs(ringArea2(coords, s, e, ox, oy)) / 2;
    area += k === 0 ? a : -a;
  });
  return area;
}

/** Convex hull (Andrew's monotone chain, exact turns), counter-clockwise, no collinear points. */
export function convexHull(coords) {
  const n = coords.length / 2;
  const order = Array.from({ length: n }, (_, i) => i).sort((a, b) => coords[2 * a] - coords[2 * b] || coords[2 * a + 1] - coords[2 * b + 1]);
  const turn = (o, a, b) => ccw(coords[2 * o], coords[2 * o + 1], coords[2 * a], coords[2 * a + 1], coords[2 * b], coords[2 * b + 1]);
  const lower = [];
  for (const p of order) {
    while (lower.length >= 2 && turn(lower[lower.length - 2], lower[lower.length - 1], p) <= 0) lower.pop();
    lower.push(p);
  }
  const upper = [];
  for (let k = order.length - 1; k >= 0; k--) {
    const p = order[k];
    while (upper.length >= 2 && turn(upper[upper.length - 2], upper[upper.length - 1], p) <= 0) upper.pop();
    upper.push(p);
  }
  lower.pop();
  upper.pop();
  return lower.concat(upper);
}

export function hullArea(coords) {
  const hull = convexHull(coords);
  const ox = coords[2 * hull[0]], oy = coords[2 * hull[0] + 1];
  let sum = 0;
  for (let k = 0; k < hull.length; k++) {
    const i = hull[k], j = hull[(k + 1) % hull.length];
    sum += (coords[2 * i] - ox) * (coords[2 * j + 1] - oy) - (coords[2 * j] - ox) * (coords[2 * i + 1] - oy);
  }
  return sum / 2;
}

/** Lower bound in a sorted Float64Array. */
function lowerBound(sorted, key) {
  let lo = 0, hi = sorted.length;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if (sorted[mid] < key) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}
const contains = (sorted, key) => {
  const i = lowerBound(sorted, key);
  return i < sorted.length && sorted[i] === key;
};

/**
 * The tests common to both kinds: indices, orientation, directed edges. Returns {reason} on the first
 * failure, else the counter-clockwise triangles, the sorted directed-edge keys (a * n + b), the
 * boundary edges (pairs) and the total area relative to (ox, oy).
 */
function triangleBasics(coords, triangles, ox, oy) {
  const n = coords.length / 2;
  const t = triangles.length / 3;
  if (!Number.isInteger(t)) return { reason: `${triangles.length} indices: not a multiple of 3` };
  const tri = new Uint32Array(triangles.length);
  let sign = 0;
  let area2 = 0;
  for (let k = 0; k < t; k++) {
    let a = triangles[3 * k], b = triangles[3 * k + 1], c = triangles[3 * k + 2];
    if (!(a < n && b < n && c < n && a >= 0 && b >= 0 && c >= 0)) return { reason: `triangle ${k} has an index out of range` };
    const o = ccw(coords[2 * a], coords[2 * a + 1], coords[2 * b], coords[2 * b + 1], coords[2 * c], coords[2 * c + 1]);
    if (o === 0) return { reason: `triangle ${k} (${a} ${b} ${c}) has zero area` };
    const s = o > 0 ? 1 : -1;
    if (sign === 0) sign = s;
    else if (s !== sign) return { reason: `triangle ${k} is wound the other way from triangle 0 (overlap)` };
    if (s < 0) [b, c] = [c, b];
    tri[3 * k] = a; tri[3 * k + 1] = b; tri[3 * k + 2] = c;
    const ax = coords[2 * a] - ox, ay = coords[2 * a + 1] - oy;
    const bx = coords[2 * b] - ox, by = coords[2 * b + 1] - oy;
    const cx = coords[2 * c] - ox, cy = coords[2 * c + 1] - oy;
    area2 += (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
  }
  const keys = new Float64Array(3 * t);
  for (let k = 0; k < t; k++) {
    for (let e = 0; e < 3; e++) keys[3 * k + e] = tri[3 * k + e] * n + tri[3 * k + ((e + 1) % 3)];
  }
  keys.sort();
  for (let i = 1; i < keys.length; i++) {
    if (keys[i] === keys[i - 1]) {
      const a = Math.floor(keys[i] / n);
      return { reason: `directed edge ${a}->${keys[i] - a * n} used twice (overlapping triangles)` };
    }
  }
  const boundary = [];
  for (let i = 0; i < keys.length; i++) {
    const a = Math.floor(keys[i] / n), b = keys[i] - a * n;
    if (!contains(keys, b * n + a)) boundary.push(a, b);
  }
  return { tri, keys, boundary, area: area2 / 2, n };
}

/** Exactly collinear with a-b and strictly between them (coordinates as pairs). */
function strictlyBetween(ax, ay, bx, by, qx, qy) {
  if (ccw(ax, ay, bx, by, qx, qy) !== 0) return false;
  if (ax !== bx) return ax < bx ? ax < qx && qx < bx : bx < qx && qx < ax;
  return ay < by ? ay < qy && qy < by : by < qy && qy < ay;
}

/**
 * Checks a polygon triangulation. `coords` may extend the input's (points a triangulator added);
 * the polygon itself comes from `input`. Returns {verdict: 'ok'|'wrong', reason?, triangles, area,
 * area_error (relative), t_junctions}.
 *
 * The boundary test compares 1-chains: the triangles' edges that have no reverse edge (their
 * boundary, plus the two sides of any T-junction) minus the rings' edges must cancel. Edges equal
 * by coordinates cancel directly; what is left must cancel line by line: the leftover edges are
 * grouped by exact collinearity through shared end points and each group's signed cover along its
 * line must be zero everywhere. That accepts dropped collinear or repeated ring vertices (one edge
 * along several ring edges) and T-junctions (a vertex on another triangle's edge: covered once, but
 * not a conforming triangulation: counted in t_junctions, the groups where triangle edges run both
 * ways), and nothing else.
 */
export function checkPolygon(input, triangles, coords = input.coords) {
  const pc = input.coords;
  const ox = pc[0], oy = pc[1];
  const expected = polygonArea(pc, input.holeIndices);
  const count = triangles.length / 3;
  const basics = triangleBasics(coords, triangles, ox, oy);
  if (basics.reason) return { verdict: 'wrong', reason: basics.reason, triangles: count, area: null, area_error: null, t_junctions: null };
  const areaError = Math.abs(basics.area - expected) / Math.abs(expected);
  let tJunctions = 0;
  const result = (reason) => ({ verdict: reason ? 'wrong' : 'ok', ...(reason ? { reason } : {}), triangles: count, area: basics.area, area_error: areaError, t_junctions: tJunctions });

  // chain: "ax,ay,bx,by" -> {ax, ay, bx, by, count}; triangle boundary edges +1, ring edges -1.
  const chain = new Map();
  // Keyed by the undirected edge (end points in lexicographic order), the count signed by direction:
  // two triangle edges a->b and b->a cancel even when they name repeated vertices by different indices.
  const add = (ax, ay, bx, by, c, label) => {
    if (ax === bx && ay === by) return;
    if (bx < ax || (bx === ax && by < ay)) {
      [ax, ay, bx, by] = [bx, by, ax, ay];
      c = -c;
    }
    const key = `${ax},${ay},${bx},${by}`;
    const e = chain.get(key);
    const fromTriangle = label.startsWith('triangle') ? c : 0;
    if (e) {
      e.count += c;
      e.triangle += fromTriangle;
      if (fromTriangle) e.label = label;
    } else chain.set(key, { ax, ay, bx, by, count: c, triangle: fromTriangle, label });
  };
  const { boundary } = basics;
  for (let k = 0; k < boundary.length; k += 2) {
    const a = boundary[k], b = boundary[k + 1];
    add(coords[2 * a], coords[2 * a + 1], coords[2 * b], coords[2 * b + 1], 1, `triangle edge ${a}->${b}`);
  }
  ringRanges(pc.length / 2, input.holeIndices).forEach(([s, e], r) => {
    // Outer ring counter-clockwise, holes clockwise: the inside on the left.
    const flip = (r === 0) !== (ringArea2(pc, s, e, ox, oy) > 0);
    for (let i = s; i < e; i++) {
      const j = i + 1 < e ? i + 1 : s;
      const [u, v] = flip ? [j, i] : [i, j];
      add(pc[2 * u], pc[2 * u + 1], pc[2 * v], pc[2 * v + 1], -1, `ring ${r} edge ${u}->${v}`);
    }
  });
  const left = [...chain.values()].filter((e) => e.count !== 0);
  if (left.length > 200000) return result(`${left.length} boundary edges match no ring edge`);
  // Group the leftover edges: union edges that share an end point and are collinear.
  const parent = left.map((_, i) => i);
  const find = (i) => {
    while (parent[i] !== i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const byPoint = new Map();
  left.forEach((e, i) => {
    for (const key of [`${e.ax},${e.ay}`, `${e.bx},${e.by}`]) {
      const list = byPoint.get(key);
      if (!list) { byPoint.set(key, [i]); continue; }
      for (const j of list) {
        const f = left[j];
        if (ccw(e.ax, e.ay, e.bx, e.by, f.ax, f.ay) === 0 && ccw(e.ax, e.ay, e.bx, e.by, f.bx, f.by) === 0) parent[find(i)] = find(j);
      }
      list.push(i);
    }
  });
  const groups = new Map();
  left.forEach((e, i) => {
    const g = find(i);
    if (!groups.has(g)) groups.set(g, []);
    groups.get(g).push(e);
  });
  for (const group of groups.values()) {
    // Exactly collinear: order along the dominant axis of the first edge is exact.
    const e0 = group[0];
    const useX = Math.abs(e0.bx - e0.ax) >= Math.abs(e0.by - e0.ay);
    const events = [];
    let forward = false, backward = false;
    for (const e of group) {
      const s = useX ? e.ax : e.ay, t = useX ? e.bx : e.by;
      if (e.triangle) (s < t) === (e.triangle > 0) ? (forward = true) : (backward = true);
      // A directed edge from s to t adds count on [s, t) going up the axis, -count going down.
      if (s < t) events.push([s, e.count], [t, -e.count]);
      else events.push([t, -e.count], [s, e.count]);
    }
    events.sort((p, q) => p[0] - q[0]);
    let cover = 0;
    for (let i = 0; i < events.length; i++) {
      cover += events[i][1];
      if (cover !== 0 && i + 1 < events.length && events[i + 1][0] > events[i][0]) {
        const culprit = group.find((e) => e.triangle !== 0) ?? group[0];
        return result(`${culprit.label} does not match the polygon's boundary ` +
          '(a filled hole, a missing, extra or overlapping triangle)');
      }
    }
    if (forward && backward) tJunctions++;
  }
  if (!(areaError <= 1e-9)) return result(`total area ${basics.area} differs from the polygon's ${expected} by ${areaError.toExponential(2)} (relative)`);
  return result(null);
}

/** Checks a triangulation of a planar straight-line graph (see the file's header). */
export function checkGraph(input, triangles, coords = input.coords) {
  const pc = input.coords;
  const n0 = pc.length / 2;
  const hull = convexHull(pc);
  const ox = pc[2 * hull[0]], oy = pc[2 * hull[0] + 1];
  const expected = input.hullArea ?? hullArea(pc);
  const count = triangles.length / 3;
  const basics = triangleBasics(coords, triangles, ox, oy);
  if (basics.reason) return { verdict: 'wrong', reason: basics.reason, triangles: count, area: null, area_error: null };
  const areaError = Math.abs(basics.area - expected) / Math.abs(expected);
  const result = (reason) => ({ verdict: reason ? 'wrong' : 'ok', ...(reason ? { reason } : {}), triangles: count, area: basics.area, area_error: areaError });
  const { boundary, keys, n } = basics;
  // Boundary edges on supporting lines of the hull: no hull vertex strictly to the right.
  for (let k = 0; k < boundary.length; k += 2) {
    const a = boundary[k], b = boundary[k + 1];
    for (const h of hull) {
      if (ccw(coords[2 * a], coords[2 * a + 1], coords[2 * b], coords[2 * b + 1], pc[2 * h], pc[2 * h + 1]) < 0) {
        return result(`boundary edge ${a}->${b} is not on the convex hull (a hole or a missing triangle)`);
      }
    }
  }
  if (!(areaError <= 1e-9)) return result(`total area ${basics.area} differs from the hull's ${expected} by ${areaError.toExponential(2)} (relative)`);
  // Every distinct input point used.
  const used = new Uint8Array(n);
  for (const v of basics.tri) used[v] = 1;
  let usedAt = null; // "x,y" of the used points: built only when an input point is unused
  for (let i = 0; i < n0; i++) {
    if (used[i]) continue;
    if (!usedAt) {
      usedAt = new Set();
      for (let j = 0; j < n; j++) if (used[j]) usedAt.add(`${coords[2 * j]},${coords[2 * j + 1]}`);
    }
    // A repeat of a used point is fine.
    if (!usedAt.has(`${pc[2 * i]},${pc[2 * i + 1]}`)) return result(`input point ${i} is in no triangle`);
  }
  // Every segment an edge, or a chain of edges through exactly collinear points between its ends.
  const hasEdge = (a, b) => contains(keys, a * n + b) || contains(keys, b * n + a);
  let both = null; // both directions of every edge, sorted: built only when a segment is not one edge
  const neighbours = (a) => {
    const out = [];
    for (let i = lowerBound(both, a * n); i < both.length && both[i] < (a + 1) * n; i++) out.push(both[i] - a * n);
    return out;
  };
  const segs = input.segments;
  let missing = 0;
  let firstMissing = -1;
  for (let s = 0; s < segs.length; s += 2) {
    const a = segs[s], b = segs[s + 1];
    const ax = coords[2 * a], ay = coords[2 * a + 1], bx = coords[2 * b], by = coords[2 * b + 1];
    if ((ax === bx && ay === by) || hasEdge(a, b)) continue;
    if (!both) {
      both = new Float64Array(2 * keys.length);
      for (let i = 0; i < keys.length; i++) {
        const u = Math.floor(keys[i] / n), v = keys[i] - u * n;
        both[2 * i] = keys[i];
        both[2 * i + 1] = v * n + u;
      }
      both.sort();
    }
    let at = a, ok = false;
    for (let steps = 0; steps < 10000 && !ok; steps++) {
      let next = -1;
      for (const c of neighbours(at)) {
        const cx = coords[2 * c], cy = coords[2 * c + 1];
        if (cx === bx && cy === by) { ok = true; break; }
        if (strictlyBetween(coords[2 * at], coords[2 * at + 1], bx, by, cx, cy)) next = c;
      }
      if (next < 0) break;
      at = next;
    }
    if (!ok) {
      missing++;
      if (firstMissing < 0) firstMissing = s / 2;
    }
  }
  if (missing) return result(`${missing} of ${segs.length / 2} segments are no edge (first: segment ${firstMissing})`);
  return result(null);
}

/**
 * Ring edges of a polygon with the inside on their left (outer ring counter-clockwise, holes
 * clockwise), zero-length edges (repeated vertices) left out: [{ux, uy, vx, vy}].
 */
function ringEdges(input) {
  const pc = input.coords;
  const ox = pc[0], oy = pc[1];
  const edges = [];
  ringRanges(pc.length / 2, input.holeIndices).forEach(([s, e], r) => {
    const flip = (r === 0) !== (ringArea2(pc, s, e, ox, oy) > 0);
    for (let i = s; i < e; i++) {
      const j = i + 1 < e ? i + 1 : s;
      const [u, v] = flip ? [j, i] : [i, j];
      const ux = pc[2 * u], uy = pc[2 * u + 1], vx = pc[2 * v], vy = pc[2 * v + 1];
      if (ux !== vx || uy !== vy) edges.push({ ux, uy, vx, vy });
    }
  });
  return edges;
}

/** Distance from (px, py) to the segment u-v, relative to u (large coordinates, short edges). */
function segmentDistance(e, px, py) {
  const dx = e.vx - e.ux, dy = e.vy - e.uy;
  const qx = px - e.ux, qy = py - e.uy;
  const t = Math.max(0, Math.min(1, (qx * dx + qy * dy) / (dx * dx + dy * dy)));
  return Math.hypot(qx - t * dx, qy - t * dy);
}

/**
 * A uniform grid over the ring edges answering "which ring edges pass within `tol` of this point".
 * Long edges go in piece by piece, so that each piece covers a few cells only.
 */
function ringEdgeGrid(edges, tol) {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (const e of edges) {
    minX = Math.min(minX, e.ux, e.vx); maxX = Math.max(maxX, e.ux, e.vx);
    minY = Math.min(minY, e.uy, e.vy); maxY = Math.max(maxY, e.uy, e.vy);
  }
  const width = Math.max(maxX - minX, tol), height = Math.max(maxY - minY, tol);
  const cell = Math.sqrt((width * height) / Math.max(edges.length, 1)) * 2;
  const cols = Math.max(1, Math.min(4096, Math.ceil(width / cell)));
  const rows = Math.max(1, Math.min(4096, Math.ceil(height / cell)));
  const cw = width / cols, ch = height / rows;
  const col = (x) => Math.max(0, Math.min(cols - 1, Math.floor((x - minX) / cw)));
  const row = (y) => Math.max(0, Math.min(rows - 1, Math.floor((y - minY) / ch)));
  const cells = new Map();
  edges.forEach((e, k) => {
    const pieces = Math.max(1, Math.ceil(Math.max(Math.abs(e.vx - e.ux) / cw, Math.abs(e.vy - e.uy) / ch)));
    for (let p = 0; p < pieces; p++) {
      const ax = e.ux + ((e.vx - e.ux) * p) / pieces, ay = e.uy + ((e.vy - e.uy) * p) / pieces;
      const bx = e.ux + ((e.vx - e.ux) * (p + 1)) / pieces, by = e.uy + ((e.vy - e.uy) * (p + 1)) / pieces;
      for (let r = row(Math.min(ay, by) - 2 * tol); r <= row(Math.max(ay, by) + 2 * tol); r++) {
        for (let c = col(Math.min(ax, bx) - 2 * tol); c <= col(Math.max(ax, bx) + 2 * tol); c++) {
          const key = r * cols + c;
          const list = cells.get(key);
          // Edges go in in order: edge k is already in a cell's list only as its last entry.
          if (!list) cells.set(key, [k]);
          else if (list[list.length - 1] !== k) list.push(k);
        }
      }
    }
  });
  return (px, py) => (cells.get(row(py) * cols + col(px)) ?? []).filter((k) => segmentDistance(edges[k], px, py) <= tol);
}

/** The angle at corner a of triangle a b c, in radians. */
function cornerAngle(ax, ay, bx, by, cx, cy) {
  const ux = bx - ax, uy = by - ay, vx = cx - ax, vy = cy - ay;
  return Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy);
}

/**
 * Checks a quality mesh of a polygon (a triangulation with points added inside and on the rings),
 * e.g. hullkit's triangulate_polygon with quality.min_angle. The points added on a ring edge are the
 * nearest doubles to points of the edge, so the mesh's boundary follows the rings only up to that
 * rounding, and the exact boundary test of checkPolygon does not apply. Instead:
 *   - every index in range, every triangle clockwise (y up; exact orient2d, nonzero), no directed
 *     edge twice (overlap);
 *   - every boundary edge (no reverse edge) on one ring edge, both ends within a few ulps of the
 *     input's largest coordinate, running the ring's way round (inside on the same side); the
 *     boundary's total length the rings' perimeter and the total area the polygon's (even-odd:
 *     outer minus holes; the generator's rings neither cross nor touch), both within a relative 1e-9;
 *   - every angle at least minAngle − 1e-9 degrees (angles in doubles), except in triangles that
 *     small input angles excuse: a corner at an input vertex inside a wedge between two ring edges
 *     narrower than the bound (the input angle itself, and the fan of triangles in it), or, as in
 *     Shewchuk's rule, a smallest angle facing an edge whose ends lie on two ring edges with a common
 *     end at equal distances from it, within 0.05% (the concentric shells' triangles). Those are
 *     counted.
 * Whether the mesh is (constrained) Delaunay is not checked: the dump does not say which edges are
 * constrained. Returns {verdict, reason?, triangles, area_error, length_error, min_angle_deg,
 * below_bound, excused_input_angle, excused_shells}.
 */
export function checkMesh(input, triangles, coords, { minAngle }) {
  const pc = input.coords;
  const ox = pc[0], oy = pc[1];
  const count = triangles.length / 3;
  const fields = { triangles: count, area_error: null, length_error: null, min_angle_deg: null, below_bound: null, excused_input_angle: null, excused_shells: null };
  const wrong = (reason) => ({ verdict: 'wrong', reason, ...fields });
  const basics = triangleBasics(coords, triangles, ox, oy);
  if (basics.reason) return wrong(basics.reason);
  if (count && ccw(...[0, 1, 2].flatMap((e) => [coords[2 * triangles[e]], coords[2 * triangles[e] + 1]])) > 0) {
    return wrong('the triangles are counter-clockwise (y up), not clockwise');
  }
  const expected = polygonArea(pc, input.holeIndices);
  fields.area_error = Math.abs(basics.area - expected) / Math.abs(expected);

  let maxAbs = 0;
  for (const v of pc) maxAbs = Math.max(maxAbs, Math.abs(v));
  const tol = 8 * Number.EPSILON * maxAbs;
  const edges = ringEdges(input);
  const near = ringEdgeGrid(edges, tol);
  let perimeter = 0;
  for (const e of edges) perimeter += Math.hypot(e.vx - e.ux, e.vy - e.uy);
  let length = 0;
  const { boundary } = basics;
  for (let k = 0; k < boundary.length; k += 2) {
    const a = boundary[k], b = boundary[k + 1];
    const ax = coords[2 * a], ay = coords[2 * a + 1], bx = coords[2 * b], by = coords[2 * b + 1];
    const onB = near(bx, by);
    const along = near(ax, ay).some((i) => onB.includes(i) && (bx - ax) * (edges[i].vx - edges[i].ux) + (by - ay) * (edges[i].vy - edges[i].uy) > 0);
    if (!along) return wrong(`boundary edge ${a}->${b} lies on no ring edge (or runs against it): a filled hole, a missing or extra triangle`);
    length += Math.hypot(bx - ax, by - ay);
  }
  fields.length_error = Math.abs(length - perimeter) / perimeter;
  if (!(fields.length_error <= 1e-9)) return wrong(`the boundary's length ${length} differs from the rings' ${perimeter} by ${fields.length_error.toExponential(2)} (relative)`);
  if (!(fields.area_error <= 1e-9)) return wrong(`total area ${basics.area} differs from the polygon's by ${fields.area_error.toExponential(2)} (relative)`);

  // The directions of the ring edges at each input vertex (by coordinates), sorted: the wedges.
  const directions = new Map();
  const addDirection = (x, y, tx, ty) => {
    const key = `${x},${y}`;
    const angle = Math.atan2(ty - y, tx - x);
    const list = directions.get(key);
    if (list) list.push(angle);
    else directions.set(key, [angle]);
  };
  for (const e of edges) {
    addDirection(e.ux, e.uy, e.vx, e.vy);
    addDirection(e.vx, e.vy, e.ux, e.uy);
  }
  for (const list of directions.values()) list.sort((p, q) => p - q);
  const bound = (minAngle * Math.PI) / 180;
  const slack = (1e-9 * Math.PI) / 180;
  // The wedge between ring edges at input vertex (px, py) holding the corner towards b and c.
  const narrowWedge = (px, py, bx, by, cx, cy) => {
    const list = directions.get(`${px},${py}`);
    if (!list || list.length < 2) return false;
    const ub = Math.hypot(bx - px, by - py), uc = Math.hypot(cx - px, cy - py);
    const mid = Math.atan2((by - py) / ub + (cy - py) / uc, (bx - px) / ub + (cx - px) / uc);
    let i = list.findIndex((d) => d > mid);
    if (i < 0) i = 0;
    const from = list[(i + list.length - 1) % list.length], to = list[i];
    const wedge = to > from ? to - from : to - from + 2 * Math.PI;
    return wedge < bound + slack;
  };
  // Ends of an edge on two ring edges with a common end, at equal distances from it.
  const shellEdge = (px, py, qx, qy) => {
    for (const i of near(px, py)) {
      for (const j of near(qx, qy)) {
        if (i === j) continue;
        for (const [ax, ay] of [[edges[i].ux, edges[i].uy], [edges[i].vx, edges[i].vy]]) {
          if (!((ax === edges[j].ux && ay === edges[j].uy) || (ax === edges[j].vx && ay === edges[j].vy))) continue;
          // "Equal" as hullkit's refinement takes it: squared distances within 0.1% (a segment split at
          // its middle lands near a shell, not on it, when its length is near a power of two).
          const dp = Math.hypot(px - ax, py - ay), dq = Math.hypot(qx - ax, qy - ay);
          if (Math.abs(dp - dq) <= 4 * tol + 5e-4 * Math.max(dp, dq)) return true;
        }
      }
    }
    return false;
  };
  const inputVertex = (x, y) => directions.has(`${x},${y}`);
  let smallest = Math.PI, below = 0, excusedInput = 0, excusedShells = 0, first = -1, firstAngle = 0;
  const t = basics.tri;
  for (let k = 0; k < count; k++) {
    const v = [t[3 * k], t[3 * k + 1], t[3 * k + 2]];
    const xy = v.map((i) => [coords[2 * i], coords[2 * i + 1]]);
    let low = Math.PI, at = 0;
    for (let c = 0; c < 3; c++) {
      const [a, b, d] = [xy[c], xy[(c + 1) % 3], xy[(c + 2) % 3]];
      const angle = cornerAngle(a[0], a[1], b[0], b[1], d[0], d[1]);
      if (angle < low) [low, at] = [angle, c];
    }
    smallest = Math.min(smallest, low);
    if (low >= bound - slack) continue;
    below++;
    let excused = false;
    for (let c = 0; c < 3 && !excused; c++) {
      const [a, b, d] = [xy[c], xy[(c + 1) % 3], xy[(c + 2) % 3]];
      excused = inputVertex(a[0], a[1]) && narrowWedge(a[0], a[1], b[0], b[1], d[0], d[1]);
    }
    if (excused) { excusedInput++; continue; }
    const [p, q] = [xy[(at + 1) % 3], xy[(at + 2) % 3]];
    if (shellEdge(p[0], p[1], q[0], q[1])) { excusedShells++; continue; }
    if (first < 0) [first, firstAngle] = [k, low];
  }
  Object.assign(fields, { min_angle_deg: (smallest * 180) / Math.PI, below_bound: below, excused_input_angle: excusedInput, excused_shells: excusedShells });
  const unexcused = below - excusedInput - excusedShells;
  if (unexcused) {
    return wrong(`${unexcused} triangle(s) below the ${minAngle.toFixed(4)}° bound that no small input angle excuses ` +
      `(first: triangle ${first}, ${((firstAngle * 180) / Math.PI).toFixed(4)}°)`);
  }
  return { verdict: 'ok', ...fields };
}
