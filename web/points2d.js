// Seeded 2D point sets for the Delaunay view, flat x0 y0 x1 y1 ... inside [-1, 1]².
import { mulberry32 } from './distributions.js';

export const POINT_SETS = ['uniform', 'gaussian', 'grid', 'rotated-grid', 'circle', 'figure1'];

/** Side of the square grid used for about n points. */
export const gridSide2 = (n) => Math.max(1, Math.round(Math.sqrt(n)));

/** The number of points set `name` gives for the requested n (grids round to a square). */
export function pointCount2(name, n) {
  if (name === 'grid' || name === 'rotated-grid') return gridSide2(n) ** 2;
  return n;
}

/** The points of set `name`: n of them (grids: the nearest square), from `seed`. */
export function generatePoints2(name, n, seed) {
  const random = mulberry32(seed);
  switch (name) {
    case 'gaussian': {
      const xy = new Float64Array(2 * n);
      for (let i = 0; i < n; i++) {
        // Box–Muller, σ = 0.33: nearly all points land inside the unit square.
        const r = 0.33 * Math.sqrt(-2 * Math.log(1 - random()));
        const t = 2 * Math.PI * random();
        xy[2 * i] = r * Math.cos(t);
        xy[2 * i + 1] = r * Math.sin(t);
      }
      return xy;
    }
    case 'grid':
    case 'rotated-grid': {
      const k = gridSide2(n);
      // A power-of-two spacing keeps the coordinates (and x² + y²) exact in binary.
      const step = 2 ** -Math.floor(Math.log2(Math.max(1, (k - 1) / 2)));
      const angle = name === 'rotated-grid' ? Math.PI / 6 : 0;
      const c = Math.cos(angle), s = Math.sin(angle);
      const xy = new Float64Array(2 * k * k);
      for (let i = 0; i < k; i++) {
        for (let j = 0; j < k; j++) {
          const x = (i - (k - 1) / 2) * step, y = (j - (k - 1) / 2) * step;
          const o = 2 * (i * k + j);
          xy[o] = angle ? c * x - s * y : x;
          xy[o + 1] = angle ? s * x + c * y : y;
        }
      }
      return xy;
    }
    case 'circle': {
      const xy = new Float64Array(2 * n);
      for (let i = 0; i < n; i++) {
        xy[2 * i] = Math.cos((2 * Math.PI * i) / n);
        xy[2 * i + 1] = Math.sin((2 * Math.PI * i) / n);
      }
      return xy;
    }
    case 'figure1': {
      // The seed's Figure 1: random points on the unit sphere, flattened onto the x–y plane.
      const xy = new Float64Array(2 * n);
      for (let i = 0; i < n; i++) {
        const z = 2 * random() - 1;
        const t = 2 * Math.PI * random();
        const r = Math.sqrt(1 - z * z);
        xy[2 * i] = r * Math.cos(t);
        xy[2 * i + 1] = r * Math.sin(t);
      }
      return xy;
    }
    default: { // uniform
      const xy = new Float64Array(2 * n);
      for (let i = 0; i < 2 * n; i++) xy[i] = 2 * random() - 1;
      return xy;
    }
  }
}
