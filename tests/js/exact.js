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

/** Exact integer coordinates (BigInt triples), all scaled by one power of two, for flat x y z data. */
export function exactPoints(xyz) {
  const parts = Array.from(xyz, decompose);
  const lowest = Math.min(...parts.filter((p) => p.mantissa !== 0n).map((p) => p.exponent), 0);
  const scaled = parts.map(({ negative, mantissa, exponent }) => {
    const value = mantissa << BigInt(exponent - lowest);
    return negative ? -value : value;
  });
  const points = [];
  for (let i = 0; i < scaled.length; i += 3) points.push(scaled.slice(i, i + 3));
  return points;
}

/** Sign of ((b-a) x (c-a)) . (d-a) for BigInt points. */
export function orient3d(a, b, c, d) {
  const [bx, by, bz] = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const [cx, cy, cz] = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  const [dx, dy, dz] = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
  const det = dx * (by * cz - bz * cy) + dy * (bz * cx - bx * cz) + dz * (bx * cy - by * cx);
  return det > 0n ? 1 : det < 0n ? -1 : 0;
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
