/**
 * hullkit: exact convex hulls of 3D point sets, computed by the hullkit C++ core compiled to
 * WebAssembly. Every function takes typed arrays and returns typed arrays the caller owns
 * (copied out of the WebAssembly heap), so results stay valid across later calls.
 */

/** Algorithms available to {@link Hullkit.hull}. */
export type HullAlgorithm = 'quickhull' | 'giftwrap';

export interface HullOptions {
  /**
   * `'quickhull'` (default): Barber, Dobkin & Huhdanpaa's quickhull, exact.
   * `'giftwrap'`: 3D gift wrapping as in the seed document, one pass over the points per hull
   * edge, O(n·h) for n points and h hull vertices.
   */
  algorithm?: HullAlgorithm;
  /**
   * `'exact'` (default): every side-of-plane decision is made by exact predicates.
   * `'seed'`: the seed document's epsilon (DBL_EPSILON times the taxicab extent of the cloud),
   * gift wrapping only, to show the difference: near-degenerate input may then be rejected.
   */
  epsilon?: 'exact' | 'seed';
  /** Also return the faces as planar convex polygons (`faceOffsets`, `faceVertices`). */
  mergeCoplanar?: boolean;
}

export interface HullResult {
  /**
   * Dimension of the points' affine hull: 3 a polytope, 2 a convex polygon (`vertices` in
   * counter-clockwise order seen from `normal`), 1 a segment (`vertices` its two ends), 0 a single
   * point, -1 no points.
   */
  dimension: 3 | 2 | 1 | 0 | -1;
  /**
   * Three indices per triangle into the input points, counter-clockwise seen from outside
   * (dimension 2: a fan of the polygon, counter-clockwise seen from `normal`).
   */
  triangles: Uint32Array;
  /**
   * Indices of the hull's vertices: its extreme points only (no point inside a face or an edge),
   * ascending for dimension 3; of identical points the lowest index stands for all.
   */
  vertices: Uint32Array;
  /** Enclosed volume (0 below dimension 3). */
  volume: number;
  /** Surface area (dimension 2: the polygon's area). */
  area: number;
  /** Dimension 2 only: unit normal of the polygon's plane. */
  normal?: Float64Array;
  /**
   * With `mergeCoplanar`: face f is the convex polygon
   * `faceVertices.subarray(faceOffsets[f], faceOffsets[f + 1])`, counter-clockwise seen from outside.
   */
  faceOffsets?: Uint32Array;
  faceVertices?: Uint32Array;
}

export interface Hullkit {
  /**
   * The convex hull of `xyz`, a flat array x0 y0 z0 x1 y1 z1 ... (a Float64Array is used as it is;
   * other array-likes of numbers are converted). Every input gets an answer: coplanar, collinear,
   * repeated and too few points give results of lower `dimension`, not errors.
   *
   * @throws {HullkitError} for a coordinate count that is not a multiple of 3, a non-finite
   *   coordinate (`pointIndex` names the point), coordinates spanning more than about 1e176 between
   *   the smallest and largest nonzero magnitude, an unknown option or option value, or a
   *   near-degenerate input that the seed's epsilon cannot decide.
   */
  hull(xyz: Float64Array | ArrayLike<number>, options?: HullOptions): HullResult;
  /**
   * Checks exactly (with exact predicates) that `result` is the convex hull of `xyz`: indices in
   * range, no zero-area triangle, closed and consistently oriented (every directed edge once and
   * its reverse once), convex, containing every point, with only extreme points as vertices.
   * `result` may come from {@link Hullkit.hull} (then `vertices` and `dimension` are checked too)
   * or be any `{triangles}` from elsewhere (dimension 3 is assumed).
   * Problems are reported in the returned value, not thrown.
   *
   * @throws {HullkitError} only for malformed arguments (not a whole number of points or
   *   triangles, an index that is not a non-negative integer).
   */
  verify(
    xyz: Float64Array | ArrayLike<number>,
    result: { triangles: Uint32Array | ArrayLike<number>; vertices?: Uint32Array | ArrayLike<number>; dimension?: number },
  ): VerifyReport;
  /** The algorithm names `hull` accepts, the default first. */
  readonly algorithms: readonly HullAlgorithm[];
}

export interface VerifyReport {
  /** True when nothing is wrong. */
  ok: boolean;
  /** Up to 20 problems, one line each naming what and where, then "... and N more problems". */
  problems: string[];
  /** How many problems were found in all. */
  problemCount: number;
  /** Remarks that are not problems (for example checks skipped because earlier ones failed). */
  notes: string[];
  dimension: number;
  /** Input points shown to lie in the hull. */
  checkedPoints: number;
  triangleCount: number;
  vertexCount: number;
  /** Planar faces (edge-connected coplanar triangles merged). */
  faceCount: number;
}

/** What hullkit throws for bad input: the message says what is wrong and where. */
export class HullkitError extends Error {
  name: 'HullkitError';
  /** Index of the point to blame, when there is one. */
  pointIndex?: number;
}

/** Loads the WebAssembly module (once per call) and resolves to the API. */
export default function createHullkit(): Promise<Hullkit>;
