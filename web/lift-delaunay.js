// Delaunay triangulation by the seed's lifting argument, on top of hullkit.hull: the stand-in the
// page uses while the loaded wasm build has no hullkit.delaunay (it throws "not built yet").
// Lift (x, y) to (x, y, x² + y²), take the exact 3D hull, keep the faces seen from below, and
// return them in hullkit.delaunay's layout (delaunator's: triangles clockwise with y up,
// halfedges, hull). The lifted z is rounded, so near-cocircular points may be split differently
// from the exact in-circle test; hullkit.delaunay decides those exactly.

/**
 * {dimension, triangles, halfedges, hull, representative, duplicateCount} for the points
 * xy = x0 y0 x1 y1 ..., computed with `hullkit.hull`.
 */
export function liftDelaunay(hullkit, xy) {
  const n = xy.length >> 1;
  // Exact duplicates map to their lowest index; only representatives are lifted.
  const representative = new Uint32Array(n);
  const firstAt = new Map();
  const distinct = [];
  for (let i = 0; i < n; i++) {
    const key = `${xy[2 * i]},${xy[2 * i + 1]}`;
    const j = firstAt.get(key);
    if (j === undefined) {
      firstAt.set(key, i);
      representative[i] = i;
      distinct.push(i);
    } else {
      representative[i] = j;
    }
  }
  const m = distinct.length;
  const lifted = new Float64Array(3 * m);
  for (let k = 0; k < m; k++) {
    const x = xy[2 * distinct[k]];
    const y = xy[2 * distinct[k] + 1];
    lifted[3 * k] = x;
    lifted[3 * k + 1] = y;
    lifted[3 * k + 2] = x * x + y * y;
  }
  const result = m >= 4 ? hullkit.hull(lifted) : { dimension: m - 1, triangles: new Uint32Array(0) };

  // Faces seen from below are clockwise seen from above (outward normals point down).
  const kept = [];
  const h3 = result.dimension === 3 ? result.triangles : new Uint32Array(0);
  for (let t = 0; t < h3.length; t += 3) {
    const a = distinct[h3[t]], b = distinct[h3[t + 1]], c = distinct[h3[t + 2]];
    if (orient(xy, a, b, c) < 0) kept.push(a, b, c);
  }
  if (m === 3 && orient(xy, distinct[0], distinct[1], distinct[2]) !== 0) {
    const [a, b, c] = distinct;
    if (orient(xy, a, b, c) < 0) kept.push(a, b, c);
    else kept.push(a, c, b);
  }
  const triangles = Uint32Array.from(kept);
  const halfedges = new Int32Array(triangles.length).fill(-1);
  const edgeAt = new Map();
  for (let e = 0; e < triangles.length; e++) {
    const from = triangles[e];
    const to = triangles[e % 3 === 2 ? e - 2 : e + 1];
    const twin = edgeAt.get(to * n + from);
    if (twin !== undefined) {
      halfedges[e] = twin;
      halfedges[twin] = e;
    } else {
      edgeAt.set(from * n + to, e);
    }
  }

  let hull;
  if (triangles.length) {
    const next = new Map();
    for (let e = 0; e < triangles.length; e++) {
      if (halfedges[e] === -1) next.set(triangles[e], triangles[e % 3 === 2 ? e - 2 : e + 1]);
    }
    const start = next.keys().next().value;
    const loop = [start];
    for (let v = next.get(start); v !== start && loop.length <= next.size; v = next.get(v)) loop.push(v);
    hull = Uint32Array.from(loop);
  } else {
    hull = Uint32Array.from(distinct.sort((a, b) => xy[2 * a] - xy[2 * b] || xy[2 * a + 1] - xy[2 * b + 1]));
  }
  const dimension = triangles.length ? 2 : Math.min(1, m - 1);
  return { dimension, triangles, halfedges, hull, representative, duplicateCount: n - m };
}

function orient(xy, a, b, c) {
  return (xy[2 * b] - xy[2 * a]) * (xy[2 * c + 1] - xy[2 * a + 1]) - (xy[2 * b + 1] - xy[2 * a + 1]) * (xy[2 * c] - xy[2 * a]);
}

/**
 * Voronoi cells clipped to bounds [xmin, ymin, xmax, ymax], in hullkit.voronoi's layout
 * ({cellOffsets, cellXY}): each representative point's rectangle cut by the bisectors with its
 * Delaunay neighbours (duplicates get empty cells).
 */
export function voronoiCells(xy, triangulation, bounds) {
  const n = xy.length >> 1;
  const { triangles, representative } = triangulation;
  const neighbours = Array.from({ length: n }, () => []);
  for (let e = 0; e < triangles.length; e++) {
    const a = triangles[e];
    const b = triangles[e % 3 === 2 ? e - 2 : e + 1];
    neighbours[a].push(b); // interior edges come twice; hull edges once, so both ends here
    neighbours[b].push(a);
  }
  const [x0, y0, x1, y1] = bounds;
  const offsets = new Uint32Array(n + 1);
  const out = [];
  for (let i = 0; i < n; i++) {
    offsets[i] = out.length / 2;
    if (representative[i] !== i) continue;
    let poly = [x0, y0, x1, y0, x1, y1, x0, y1];
    const px = xy[2 * i], py = xy[2 * i + 1];
    const others = triangles.length ? neighbours[i] : triangulation.hull.filter((j) => j !== i);
    for (const j of others) {
      const dx = xy[2 * j] - px, dy = xy[2 * j + 1] - py;
      const mx = px + dx / 2, my = py + dy / 2;
      poly = clip(poly, (x, y) => (x - mx) * dx + (y - my) * dy);
      if (poly.length === 0) break;
    }
    out.push(...poly);
  }
  offsets[n] = out.length / 2;
  return { cellOffsets: offsets, cellXY: Float64Array.from(out) };
}

/** The part of convex polygon `poly` (flat xy) where side(x, y) <= 0. */
function clip(poly, side) {
  const out = [];
  const k = poly.length / 2;
  for (let i = 0; i < k; i++) {
    const ax = poly[2 * i], ay = poly[2 * i + 1];
    const bx = poly[(2 * i + 2) % poly.length], by = poly[(2 * i + 3) % poly.length];
    const sa = side(ax, ay), sb = side(bx, by);
    if (sa <= 0) out.push(ax, ay);
    if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) {
      const t = sa / (sa - sb);
      out.push(ax + t * (bx - ax), ay + t * (by - ay));
    }
  }
  return out;
}
