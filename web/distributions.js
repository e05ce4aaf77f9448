// Deterministic point generators for the demo page (used inside the worker).

/** mulberry32: a tiny 32-bit seeded PRNG; returns floats in [0, 1). */
export function mulberry32(seed) {
  let a = seed >>> 0;
  return function next() {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

export const DISTRIBUTIONS = {
  cube: { label: 'in a cube', boundingRadius: Math.sqrt(3) },
  ball: { label: 'in a ball', boundingRadius: 1 },
  sphere: { label: 'on a sphere', boundingRadius: 1 },
  plane: { label: 'in a square (coplanar)', boundingRadius: Math.SQRT2 },
};
// 'custom' (pasted coordinates) is handled by parsePoints().

/**
 * n points as a flat Float64Array [x0, y0, z0, x1, ...].
 *   cube:   uniform in [-1, 1]^3
 *   ball:   uniform in the unit ball (rejection sampling)
 *   sphere: uniform on the unit sphere (normalised Gaussian vectors)
 *   plane:  uniform in the square [-1, 1]^2 at z = 0 (degenerate on purpose)
 */
export function generatePoints(distribution, n, seed) {
  if (!(distribution in DISTRIBUTIONS)) throw new Error(`unknown distribution "${distribution}"`);
  const rand = mulberry32(seed);
  const u = () => 2 * rand() - 1;
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    let x, y, z;
    switch (distribution) {
      case 'cube':
        x = u(); y = u(); z = u();
        break;
      case 'ball':
        do { x = u(); y = u(); z = u(); } while (x * x + y * y + z * z > 1);
        break;
      case 'sphere': {
        let r2;
        do {
          x = gaussian(rand); y = gaussian(rand); z = gaussian(rand);
          r2 = x * x + y * y + z * z;
        } while (r2 < 1e-12);
        const inv = 1 / Math.sqrt(r2);
        x *= inv; y *= inv; z *= inv;
        break;
      }
      case 'plane':
        x = u(); y = u(); z = 0;
        break;
    }
    xyz[3 * i] = x;
    xyz[3 * i + 1] = y;
    xyz[3 * i + 2] = z;
  }
  return xyz;
}

const MAX_CUSTOM_POINTS = 100_000;
const SPECIAL = { nan: NaN, inf: Infinity, '+inf': Infinity, '-inf': -Infinity, infinity: Infinity, '+infinity': Infinity, '-infinity': -Infinity };

/**
 * Parse pasted coordinates: numbers separated by white space, commas or
 * semicolons, read as x y z triples; '#' starts a comment. "nan" and "inf"
 * are accepted as numbers so that the hull library itself reports them.
 * The coordinate count is not checked here either (the library does).
 */
export function parsePoints(text) {
  const values = [];
  const lines = String(text).split(/\r?\n/);
  for (let li = 0; li < lines.length; li++) {
    const line = lines[li].replace(/#.*/, '');
    for (const token of line.split(/[\s,;]+/)) {
      if (token === '') continue;
      const special = SPECIAL[token.toLowerCase()];
      const v = special !== undefined ? special : Number(token);
      if (special === undefined && (Number.isNaN(v) || !/^[+-]?(\d|\.\d)/.test(token))) {
        throw new Error(`custom points, line ${li + 1}: "${token.length > 24 ? token.slice(0, 24) + '…' : token}" is not a number`);
      }
      values.push(v);
      if (values.length > 3 * MAX_CUSTOM_POINTS + 2) {
        throw new Error(`custom points: more than ${MAX_CUSTOM_POINTS.toLocaleString('en-US')} points`);
      }
    }
  }
  return Float64Array.from(values);
}

// Box–Muller (one value per call; simple and deterministic).
function gaussian(rand) {
  let s;
  do { s = rand(); } while (s === 0);
  return Math.sqrt(-2 * Math.log(s)) * Math.cos(2 * Math.PI * rand());
}
