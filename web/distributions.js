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
  cube: { label: 'in a cube' },
  ball: { label: 'in a ball' },
  sphere: { label: 'on a sphere' },
  plane: { label: 'in a square (coplanar)' },
  'near-coplanar': { label: 'near-coplanar (square, z ± 1e-13)' },
  grid: { label: 'cube grid (integer points)' },
  'rotated-grid': { label: 'cube grid, rotated (seeded)' },
};
// 'custom' (pasted coordinates) is handled by parsePoints().

/** Half-thickness of the 'near-coplanar' slab: far above rounding, far below anything visible. */
export const NEAR_COPLANAR_Z = 1e-13;

const isGrid = (distribution) => distribution === 'grid' || distribution === 'rotated-grid';

/** Points per edge of the grids for a requested n: the cube number k³ nearest to n (k >= 2). */
export function gridSide(n) {
  return Math.max(2, Math.round(Math.cbrt(Math.max(0, n))));
}

/** How many points generatePoints(distribution, n, seed) returns. */
export function pointCount(distribution, n) {
  return isGrid(distribution) ? gridSide(n) ** 3 : n;
}

/**
 * n points as a flat Float64Array [x0, y0, z0, x1, ...].
 *   cube:          uniform in [-1, 1]^3
 *   ball:          uniform in the unit ball (rejection sampling)
 *   sphere:        uniform on the unit sphere (normalised Gaussian vectors)
 *   plane:         uniform in the square [-1, 1]^2 at z = 0 (degenerate on purpose)
 *   near-coplanar: the same square with z uniform in ±1e-13: a slab that exact predicates see as
 *                  3D, while the seed's epsilon (≈ 9e-16 here) cannot decide it consistently
 *   grid:          the integer points {0, ..., k-1}^3, k = gridSide(n): hull = 8 corners, 6 squares,
 *                  with many points on its faces and edges (the seed does not use n here)
 *   rotated-grid:  the same lattice, centred, turned by a random rotation drawn from the seed;
 *                  rounding moves the face points slightly off the face planes, so the exact hull
 *                  has many more than 8 vertices, while the seed's epsilon snaps them back
 */
export function generatePoints(distribution, n, seed) {
  if (!(distribution in DISTRIBUTIONS)) throw new Error(`unknown distribution "${distribution}"`);
  if (isGrid(distribution)) return gridPoints(gridSide(n), distribution === 'rotated-grid' ? seed : null);
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
      case 'near-coplanar':
        x = u(); y = u(); z = NEAR_COPLANAR_Z * u();
        break;
    }
    xyz[3 * i] = x;
    xyz[3 * i + 1] = y;
    xyz[3 * i + 2] = z;
  }
  return xyz;
}

/** The k³ lattice points: integers 0..k-1, or (with a seed) centred and rotated. */
function gridPoints(k, rotationSeed) {
  const xyz = new Float64Array(3 * k ** 3);
  const R = rotationSeed === null ? null : randomRotation(mulberry32(rotationSeed));
  const h = (k - 1) / 2;
  let o = 0;
  for (let a = 0; a < k; a++) {
    for (let b = 0; b < k; b++) {
      for (let c = 0; c < k; c++) {
        if (!R) {
          xyz[o++] = a; xyz[o++] = b; xyz[o++] = c;
        } else {
          const x = a - h, y = b - h, z = c - h;
          for (let r = 0; r < 3; r++) xyz[o++] = R[r][0] * x + R[r][1] * y + R[r][2] * z;
        }
      }
    }
  }
  return xyz;
}

/** A rotation matrix from a random unit quaternion (rejection sampling in the 4-ball). */
function randomRotation(rand) {
  let q, len2;
  do {
    q = [2 * rand() - 1, 2 * rand() - 1, 2 * rand() - 1, 2 * rand() - 1];
    len2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  } while (len2 > 1 || len2 < 0.01);
  const len = Math.sqrt(len2);
  const [w, x, y, z] = q.map((v) => v / len);
  return [
    [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
    [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
    [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
  ];
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
