import { mulberry32 } from '../../web/distributions.js';

// Exact geometry for the JS tests, independent of hullkit: every double is a rational with a
// power-of-two denominator, so scaling by a common power of two makes all coordinates BigInts.

const view = new DataView(new ArrayBuffer(8));

/** A finite double as sign * mantissa * 2^exponent with an integer (BigInt) mantissa. */
function decompose(value) {
  view.setFloat64(0, value);
  const bits = view.getBigUint64(0);
  const exponentBits = Number((bits >> 52n) & 0x7ffn);
  let mantissa = bits & ((1n << 52n) - 1n);
  if (exponentBits !== 0) mantissa |= 1n << 52n;
  const exponent = exponentBits === 0 ? -1074 : exponentBits - 1075;
  return { negative: bits >> 63n === 1n, mantissa, exponent };
}

/**
 * Exact integer coordinates (BigInt triples), all scaled by one power of two, for flat x y z data
 * (pairs for flat x y data with `dimension` 2).
 */
export function exactPoints(xyz, dimension = 3) {
  const parts = Array.from(xyz, decompose);
  const lowest = Math.min(...parts.filter((p) => p.mantissa !== 0n).map((p) => p.exponent), 0);
  const scaled = parts.map(({ negative, mantissa, exponent }) => {
    const value = mantissa << BigInt(exponent - lowest);
    return negative ? -value : value;
  });
  const points = [];
  for (let i = 0; i < scaled.length; i += dimension) points.push(scaled.slice(i, i + dimension));
  return points;
}

const sign = (value) => (value > 0n ? 1 : value < 0n ? -1 : 0);

/** Sign of (b-a) x (c-a) for BigInt points (x y): > 0 when a, b, c turn counter-clockwise (y up). */
export function orient2d(a, b, c) {
  return sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

/** ((b-a) x (c-a)) . (d-a) for BigInt points: six times the signed volume of a, b, c, d. */
export function orient3dDeterminant(a, b, c, d) {
  const [bx, by, bz] = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const [cx, cy, cz] = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  const [dx, dy, dz] = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
  return dx * (by * cz - bz * cy) + dy * (bz * cx - bx * cz) + dz * (bx * cy - by * cx);
}

/** Sign of ((b-a) x (c-a)) . (d-a) for BigInt points: > 0 when d is on the side the normal points to. */
export function orient3d(a, b, c, d) {
  return sign(orient3dDeterminant(a, b, c, d));
}

/**
 * For BigInt points with orient3d(a, b, c, d) > 0: 1 when e is strictly inside the sphere through
 * a, b, c and d, 0 on it, -1 outside (the 4x4 determinant of the points lifted to the paraboloid,
 * relative to e).
 */
export function insphere(a, b, c, d, e) {
  const rows = [a, b, c, d].map((p) => {
    const [x, y, z] = [p[0] - e[0], p[1] - e[1], p[2] - e[2]];
    return [x, y, z, x * x + y * y + z * z];
  });
  const det3 = ([p, q, r]) => p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) + p[2] * (q[0] * r[1] - q[1] * r[0]);
  let det = 0n;
  for (let i = 0; i < 4; i++) {
    const minor = rows.filter((_, j) => j !== i);
    det += (i % 2 === 0 ? -1n : 1n) * rows[i][3] * det3(minor);
  }
  // With this expansion a point inside a positively oriented tetrahedron's sphere gives det < 0.
  return sign(-det);
}

/** Problems with `hull` as the convex hull of `xyz` (closed, oriented, contains every point). */
export function hullProblems(xyz, hull) {
  const problems = [];
  const { triangles } = hull;
  const directed = new Map();
  for (let t = 0; t < triangles.length; t += 3) {
    for (let k = 0; k < 3; k++) {
      const key = `${triangles[t + k]},${triangles[t + ((k + 1) % 3)]}`;
      directed.set(key, (directed.get(key) ?? 0) + 1);
    }
  }
  for (const [key, count] of directed) {
    const [a, b] = key.split(',');
    if (count !== 1 || directed.get(`${b},${a}`) !== 1) problems.push(`edge ${key} not used once each way`);
  }
  const points = exactPoints(xyz);
  for (let t = 0; t < triangles.length && problems.length < 10; t += 3) {
    const [a, b, c] = [points[triangles[t]], points[triangles[t + 1]], points[triangles[t + 2]]];
    for (let p = 0; p < points.length; p++) {
      if (orient3d(a, b, c, points[p]) > 0) {
        problems.push(`point ${p} above triangle ${t / 3}`);
        break;
      }
    }
  }
  return problems;
}

/** Seeded uniform numbers in [0, 1): the page's generator. */
export { mulberry32 as seededRandom };

export function randomBall(n, seed) {
  const random = mulberry32(seed);
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; ) {
    const p = [random() * 2 - 1, random() * 2 - 1, random() * 2 - 1];
    if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > 1) continue;
    xyz.set(p, 3 * i++);
  }
  return xyz;
}
