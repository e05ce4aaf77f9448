// The Hull view's cost estimate: a rough running time model for a run, refined from every
// sufficiently long run, and the rule for when a gift wrapping run asks for confirmation.
import { pointCount } from '../distributions.js';

export const SPHERE_WARN_N = 5000; // gift wrapping points on a sphere is O(n²): every point is a hull vertex
const WARN_MS = 10_000; // a gift wrapping run estimated longer than this asks for confirmation

// Rough running time model, refined from every sufficiently long run:
//   giftwrap   ms ≈ k · n · h              (one pass over the points per hull edge)
//   quickhull  ms ≈ k · n · log2(h)        (expected; 10^6 points on a sphere in about a second)
// Only gift wrapping ever asks for confirmation: quickhull is fast up to the page's 100 000 points.
const DEFAULT_MS_PER_UNIT = { giftwrap: 1.5e-5, quickhull: 5e-5 };

const costKey = (algorithm) => (algorithm === 'giftwrap' ? 'giftwrap' : 'quickhull'); // quickhull: the default

function expectedHullVertices(distribution, n) {
  switch (distribution) {
    case 'ball': return Math.min(n, 4.4 * Math.sqrt(n)); // Θ(n^(1/2))
    case 'cube': { const l = Math.log(Math.max(n, 2)); return Math.min(n, 1.6 * l * l); } // Θ(log² n)
    case 'plane': // 2D hull of a square: Θ(log n), generous
    case 'near-coplanar': return Math.min(n, 4 * Math.cbrt(Math.max(n, 1)));
    case 'grid': return Math.min(n, 8);
    case 'rotated-grid': return Math.min(n, 6 * Math.cbrt(Math.max(n, 1))); // face points rounded off their planes
    default: return n; // sphere: every point is extreme; custom: assume the worst
  }
}

function workUnits(algorithm, n, h) {
  return costKey(algorithm) === 'giftwrap' ? n * h : n * Math.log2(Math.max(h, 2));
}

/** Points the run will hash (grids round n to a cube number). */
const inputSize = ({ distribution, n }) => (distribution === 'custom' || distribution === 'file' ? n : pointCount(distribution, n));

export function needsConfirmation(params, estMs) {
  if (costKey(params.algorithm) !== 'giftwrap') return false;
  return (params.distribution === 'sphere' && params.n > SPHERE_WARN_N) || estMs > WARN_MS;
}

/** A cost model of its own: {estimateMs(params), calibrate(algorithm, n, h, hullMs)}. */
export function createCostModel() {
  const msPerUnit = new Map();

  function estimateMs(params) {
    const key = costKey(params.algorithm);
    const n = inputSize(params);
    return (msPerUnit.get(key) ?? DEFAULT_MS_PER_UNIT[key]) * workUnits(params.algorithm, n, expectedHullVertices(params.distribution, n));
  }

  function calibrate(algorithm, n, h, hullMs) {
    if (hullMs > 50 && n > 0 && h > 0) msPerUnit.set(costKey(algorithm), hullMs / workUnits(algorithm, n, h));
  }

  return { estimateMs, calibrate };
}
