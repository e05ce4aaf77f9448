// Polygons for the Delaunay view's constrained modes, with no DOM (the worker imports this too):
// the sample polygon, the readers of GeoJSON and Triangle's .poly files, and the measures the
// page shows of a constrained triangulation (its smallest angle, its edges, which polygon edges
// the unconstrained Delaunay triangulation lacks).
//
// Triangles come as hullkit returns them: three point indices per triangle, clockwise with y up,
// with delaunator's half-edges (half-edge e of triangle t = floor(e / 3) runs from
// triangles[e] to triangles[next(e)]; halfedges[e] is its twin or -1).

/**
 * The polygon the constrained modes start with: an outline with a notch and a bay, and two holes.
 * Every corner of the filled area is 60° or more, so a quality mesh meets any angle bound up to
 * about 20.7° everywhere (small input angles are where refinement has to stop).
 */
export const SAMPLE_RINGS = Object.freeze([
  // The outline (counter-clockwise): a notch cut from the top, a bay on the right.
  [[-1, -0.8], [0.15, -0.8], [0.95, -0.55], [0.95, 0.05], [0.55, 0.2], [0.95, 0.4], [0.85, 0.85],
    [0.12, 0.85], [0.12, 0.2], [-0.18, 0.2], [-0.18, 0.85], [-1, 0.85]],
  // A hole in the left arm, so near the notch that the notch's wall is no Delaunay edge, and a
  // hexagonal hole in the lower right.
  [[-0.8, -0.1], [-0.3, -0.1], [-0.3, 0.5], [-0.8, 0.5]],
  [[0.2, -0.55], [0.42, -0.55], [0.53, -0.36], [0.42, -0.17], [0.2, -0.17], [0.09, -0.36]],
].map((ring) => Object.freeze(ring.map((p) => Object.freeze(p)))));

const next = (e) => (e % 3 === 2 ? e - 2 : e + 1);

// ------------------------------------------------------------------ measures

/**
 * The smallest angle of the triangles in degrees ({degrees: Infinity, triangle: -1} with none),
 * and how many triangles have an angle below `bound` degrees (when given).
 */
export function smallestAngle(coords, triangles, bound = null) {
  let degrees = Infinity;
  let triangle = -1;
  let below = 0;
  for (let t = 0; t < triangles.length; t += 3) {
    let least = Infinity;
    for (let k = 0; k < 3; k++) {
      const a = triangles[t + k], b = triangles[t + ((k + 1) % 3)], c = triangles[t + ((k + 2) % 3)];
      const ux = coords[2 * b] - coords[2 * a], uy = coords[2 * b + 1] - coords[2 * a + 1];
      const vx = coords[2 * c] - coords[2 * a], vy = coords[2 * c + 1] - coords[2 * a + 1];
      // The angle at corner a from its sine and cosine (robust for angles near 0° and 180°).
      least = Math.min(least, Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy));
    }
    const d = (least * 180) / Math.PI;
    if (d < degrees) [degrees, triangle] = [d, t / 3];
    if (bound !== null && d < bound) below++;
  }
  return { degrees, triangle, below };
}

/** Every edge once: its count, and how many of them are constrained (hullkit's `constrained` flags). */
export function countEdges(halfedges, constrained) {
  let edges = 0;
  let constrainedEdges = 0;
  for (let e = 0; e < halfedges.length; e++) {
    if (halfedges[e] > e) continue; // the twin with the larger index counts it
    edges++;
    if (constrained[e]) constrainedEdges++;
  }
  return { edges, constrainedEdges };
}

/**
 * The polygon edges (flat index pairs into the points) that are not edges of the unconstrained
 * Delaunay triangulation of the same points (`triangles` from hullkit.delaunay, `representative`
 * naming the first of repeated points): {edges: the non-degenerate polygon edges counted once,
 * missing: how many of them it lacks}.
 */
export function edgesMissingFrom(triangles, representative, pairs) {
  const n = representative.length;
  const key = (a, b) => (a < b ? a * n + b : b * n + a);
  const present = new Set();
  for (let e = 0; e < triangles.length; e++) present.add(key(triangles[e], triangles[next(e)]));
  const seen = new Set();
  let missing = 0;
  for (let i = 0; i + 1 < pairs.length; i += 2) {
    const a = representative[pairs[i]], b = representative[pairs[i + 1]];
    if (a === b) continue;
    const k = key(a, b);
    if (seen.has(k)) continue;
    seen.add(k);
    if (!present.has(k)) missing++;
  }
  return { edges: seen.size, missing };
}

// ------------------------------------------------------------------ files

/**
 * A polygon file's text as what the page edits: GeoJSON (Polygon, MultiPolygon, Feature,
 * FeatureCollection or GeometryCollection of those) gives rings, Triangle's .poly (by its `name`)
 * a planar graph. Throws "NAME:LINE: what is wrong" (or "NAME: what") for a malformed file.
 *   {kind: 'rings', xy (Float64Array), starts (Uint32Array: where each ring starts, then the end), warnings}
 *   {kind: 'poly', xy, segments (Uint32Array pairs), holes (Float64Array x y), warnings}
 */
export function readPolygonFile(text, name) {
  return /\.poly$/i.test(name) ? parsePoly(text, name) : parseGeoJSON(text, name);
}

/** GeoJSON polygons as rings (the repeated closing position dropped). */
export function parseGeoJSON(text, name) {
  let value;
  try {
    value = JSON.parse(text);
  } catch (err) {
    throw new Error(`${name}: not GeoJSON (not valid JSON: ${err.message})`);
  }
  const polygons = [];
  let skipped = 0;
  const visit = (geometry, where, inCollection) => {
    if (geometry === null || typeof geometry !== 'object') {
      if (inCollection) {
        skipped++;
        return;
      }
      throw new Error(`${name}: ${where} has no geometry`);
    }
    switch (geometry.type) {
      case 'Polygon': polygons.push({ rings: geometry.coordinates, where }); break;
      case 'MultiPolygon':
        if (!Array.isArray(geometry.coordinates)) throw new Error(`${name}: ${where}: coordinates must be an array of polygons`);
        geometry.coordinates.forEach((rings, p) => polygons.push({ rings, where: `${where} polygon ${p}` }));
        break;
      case 'Feature': visit(geometry.geometry, where, inCollection); break;
      case 'FeatureCollection':
        if (!Array.isArray(geometry.features)) throw new Error(`${name}: a FeatureCollection needs a "features" array`);
        geometry.features.forEach((f, i) => visit(f, `feature ${i}`, true));
        break;
      case 'GeometryCollection':
        if (!Array.isArray(geometry.geometries)) throw new Error(`${name}: a GeometryCollection needs a "geometries" array`);
        geometry.geometries.forEach((g, i) => visit(g, `geometry ${i}`, true));
        break;
      default:
        if (inCollection) skipped++;
        else throw new Error(`${name}: GeoJSON ${geometry.type === undefined ? 'without a "type"' : `"${String(geometry.type)}"`} is not a Polygon or MultiPolygon`);
    }
  };
  visit(value, 'the file', false);
  const xy = [];
  const starts = [];
  for (const { rings, where } of polygons) {
    if (!Array.isArray(rings)) throw new Error(`${name}: ${where}: coordinates must be an array of rings`);
    rings.forEach((ring, r) => {
      const at = `${where} ring ${r}`;
      if (!Array.isArray(ring)) throw new Error(`${name}: ${at} is not an array of positions`);
      const ringXY = [];
      ring.forEach((position, i) => {
        if (!Array.isArray(position) || position.length < 2 || !Number.isFinite(position[0]) || !Number.isFinite(position[1])) {
          throw new Error(`${name}: ${at} position ${i} is not [x, y] with finite numbers`);
        }
        ringXY.push(position[0], position[1]);
      });
      const m = ringXY.length;
      if (m >= 4 && ringXY[0] === ringXY[m - 2] && ringXY[1] === ringXY[m - 1]) ringXY.length = m - 2; // closed as GeoJSON closes rings
      if (ringXY.length < 6) throw new Error(`${name}: ${at} has fewer than 3 positions`);
      starts.push(xy.length / 2);
      xy.push(...ringXY);
    });
  }
  if (starts.length === 0) throw new Error(`${name}: no Polygon or MultiPolygon in the file`);
  starts.push(xy.length / 2);
  const warnings = skipped ? [`skipped ${skipped} ${skipped === 1 ? 'geometry that is' : 'geometries that are'} not polygons`] : [];
  return { kind: 'rings', xy: Float64Array.from(xy), starts: Uint32Array.from(starts), warnings };
}

/**
 * Triangle's .poly: a header (vertex count, 2, attribute count, marker count), the vertices
 * (number x y [attributes] [marker]), the segment header (count, marker count) and segments
 * (number a b [marker]), the hole count and holes (number x y); then optional regional
 * attributes, which the page ignores (said in a warning). Vertex numbers start at 0 or 1, as the
 * first vertex's number says. `#` starts a comment.
 */
export function parsePoly(text, name) {
  const lines = [];
  String(text).split(/\r\n|\r|\n/).forEach((raw, i) => {
    const tokens = raw.replace(/#.*/, '').trim().split(/\s+/).filter(Boolean);
    if (tokens.length) lines.push({ line: i + 1, tokens });
  });
  let at = 0;
  const fail = (line, message) => { throw new Error(`${name}:${line}: ${message}`); };
  const lastLine = lines.length ? lines[lines.length - 1].line : 1;
  const take = (what) => {
    if (at >= lines.length) fail(lastLine, `the file ends where ${what} should be`);
    return lines[at++];
  };
  const number = (entry, k, what) => {
    const token = entry.tokens[k];
    if (token === undefined) fail(entry.line, `missing ${what}`);
    const v = Number(token);
    if (!Number.isFinite(v)) fail(entry.line, `${what} "${token}" is not a finite number`);
    return v;
  };
  const count = (entry, k, what) => {
    const v = number(entry, k, what);
    if (!Number.isInteger(v) || v < 0) fail(entry.line, `${what} ${v} is not a count`);
    return v;
  };

  const header = take('the vertex count');
  const nv = count(header, 0, 'the vertex count');
  if (nv === 0) fail(header.line, 'the vertices are in a separate .node file; put them in the .poly file to open it here');
  const dim = header.tokens.length > 1 ? number(header, 1, 'the dimension') : 2;
  if (dim !== 2) fail(header.line, `dimension ${dim}: only 2D .poly files`);
  const attributes = header.tokens.length > 2 ? count(header, 2, 'the attribute count') : 0;
  const xy = new Float64Array(2 * nv);
  let base = 0;
  for (let i = 0; i < nv; i++) {
    const entry = take(`vertex ${i + 1} of ${nv}`);
    const id = number(entry, 0, 'the vertex number');
    if (i === 0) {
      if (id !== 0 && id !== 1) fail(entry.line, `the first vertex is numbered ${id}; .poly numbers start at 0 or 1`);
      base = id;
    }
    xy[2 * i] = number(entry, 1, 'x');
    xy[2 * i + 1] = number(entry, 2, 'y');
    if (entry.tokens.length < 3 + attributes) fail(entry.line, `vertex ${id} has fewer than ${attributes} attributes`);
  }
  const segHeader = take('the segment count');
  const ns = count(segHeader, 0, 'the segment count');
  const segments = new Uint32Array(2 * ns);
  for (let s = 0; s < ns; s++) {
    const entry = take(`segment ${s + 1} of ${ns}`);
    for (let k = 0; k < 2; k++) {
      const v = number(entry, 1 + k, 'a segment end');
      const index = v - base;
      if (!Number.isInteger(v) || index < 0 || index >= nv) fail(entry.line, `segment ${entry.tokens[0]} names vertex ${v}, not one of the ${nv} vertices (numbered from ${base})`);
      segments[2 * s + k] = index;
    }
  }
  let holes = new Float64Array(0);
  const warnings = [];
  if (at < lines.length) {
    const holeHeader = take('the hole count');
    const nh = count(holeHeader, 0, 'the hole count');
    holes = new Float64Array(2 * nh);
    for (let h = 0; h < nh; h++) {
      const entry = take(`hole ${h + 1} of ${nh}`);
      holes[2 * h] = number(entry, 1, 'the hole\'s x');
      holes[2 * h + 1] = number(entry, 2, 'the hole\'s y');
    }
  } else {
    warnings.push('no hole section (read as no holes)');
  }
  if (at < lines.length && count(lines[at], 0, 'the region count') > 0) warnings.push(`regional attributes and area constraints ignored (line ${lines[at].line})`);
  return { kind: 'poly', xy, segments, holes, warnings };
}
