/**
 * hullkit: convex hulls of 3D point sets, computed by the hullkit C++ core compiled to
 * WebAssembly. Every function takes typed arrays and returns typed arrays the caller owns
 * (copied out of the WebAssembly heap), so results stay valid across later calls.
 */

/** Algorithms available to {@link Hullkit.hull}. */
export type HullAlgorithm = 'giftwrap';

export interface HullOptions {
  /**
   * `'giftwrap'` (default): 3D gift wrapping as in the seed document, one pass over the points per
   * hull edge, O(n·h) for n points and h hull vertices.
   */
  algorithm?: HullAlgorithm;
}

export interface HullResult {
  /** Three indices per triangle into the input points, counter-clockwise seen from outside. */
  triangles: Uint32Array;
  /** Indices of the input points that are hull vertices, ascending. */
  vertices: Uint32Array;
  /** Enclosed volume. */
  volume: number;
  /** Surface area. */
  area: number;
}

export interface Hullkit {
  /**
   * The convex hull of `xyz`, a flat array x0 y0 z0 x1 y1 z1 ... (a Float64Array is used as it is;
   * other array-likes of numbers are converted).
   *
   * @throws {HullkitError} for fewer than 4 points, a coordinate count that is not a multiple of 3,
   *   a non-finite coordinate (`pointIndex` names the point), points without volume (all identical,
   *   collinear or coplanar), an unknown algorithm or an unknown option.
   */
  hull(xyz: Float64Array | ArrayLike<number>, options?: HullOptions): HullResult;
  /** The algorithm names `hull` accepts. */
  readonly algorithms: readonly HullAlgorithm[];
}

/** What hullkit throws for bad input: the message says what is wrong and where. */
export class HullkitError extends Error {
  name: 'HullkitError';
  /** Index of the point to blame, when there is one. */
  pointIndex?: number;
}

/** Loads the WebAssembly module (once per call) and resolves to the API. */
export default function createHullkit(): Promise<Hullkit>;
