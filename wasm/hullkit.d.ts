/**
 * hullkit: exact convex hulls of 3D point sets, computed by the hullkit C++ core compiled to
 * WebAssembly. Every function takes typed arrays and returns typed arrays the caller owns
 * (copied out of the WebAssembly heap), so results stay valid across later calls.
 */

/**
 * One 3D point as callers hold them: `[x, y, z]` (an array or typed array of 3 numbers), or an
 * object with numeric `x`, `y`, `z` (three.js `Vector3`, `{x, y, z}`; other properties ignored).
 */
export type Point3 = ArrayLike<number> | { readonly x: number; readonly y: number; readonly z: number };
/** One 2D point: `[x, y]`, or an object with numeric `x`, `y` (three.js `Vector2`, `{x, y}`). */
export type Point2 = ArrayLike<number> | { readonly x: number; readonly y: number };
/**
 * 3D points: flat, x0 y0 z0 x1 y1 z1 ... (a Float64Array is used as it is, without a copy: the fast
 * path; other array-likes of numbers are copied into one), or an array of {@link Point3} (as
 * quickhull3d and three.js take them), flattened into a Float64Array. Anything else (a ragged
 * array, a string) is an error saying what to pass: "points[3] has 2 coordinates, expected 3".
 */
export type Points3 = Float64Array | ArrayLike<number> | ArrayLike<Point3>;
/** 2D points: flat x0 y0 x1 y1 ..., or an array of {@link Point2} (as delaunator's `Delaunator.from` takes them). */
export type Points2 = Float64Array | ArrayLike<number> | ArrayLike<Point2>;

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
  /**
   * `true` (default): `equations` holds each triangle's plane. `false`: `equations` is empty, for
   * large hulls whose planes are not needed (32 bytes per triangle; on 10⁶ points on a sphere the
   * planes add about a tenth to the hull's time).
   */
  equations?: boolean;
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
  /**
   * The plane of each triangle, 4 numbers per triangle as scipy's `ConvexHull.equations` and
   * qconvex's `n` give them: `nx ny nz offset`, the outward unit normal and the offset with
   * n·x + offset ≤ 0 for every point of the hull (= 0 on the triangle's plane). Computed in the
   * C++ core from the exact triangles, rounded: each normal within about 1e-14 of the exact one.
   * Dimension 2: every triangle's plane is the polygon's, on the side of `normal`. Empty below
   * dimension 2, and with `{ equations: false }`.
   */
  equations: Float64Array;
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
   * The convex hull of an array of points, `[[x, y, z], ...]` or `[{x, y, z}, ...]` (three.js
   * `Vector3`s; as quickhull3d and three.js's `ConvexHull` take them), flattened into a Float64Array
   * first (pass a Float64Array to skip that copy). Indices in the result are positions in the array.
   *
   * @throws {HullkitError} for an entry that is not a point of 3 numbers ("points[3] has 2
   *   coordinates, expected 3"; `pointIndex` names it), and as the flat overload.
   */
  hull(points: ArrayLike<Point3>, options?: HullOptions): HullResult;
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
    xyz: Points3,
    result: { triangles: Uint32Array | ArrayLike<number>; vertices?: Uint32Array | ArrayLike<number>; dimension?: number },
  ): VerifyReport;
  /** The algorithm names `hull` accepts, the default first. */
  readonly algorithms: readonly HullAlgorithm[];
  /**
   * The seed's 3D gift wrapping of `xyz` (exact side tests), recorded step by step by the C++ core
   * while it wraps: the same wrap as `hull(xyz, {algorithm: 'giftwrap'})`. Replaying the events
   * (see {@link GiftwrapTrace}) gives exactly that hull's `triangles`, in the same order.
   * Deterministic. Input without volume (coplanar, collinear, identical or no points) is not
   * wrapped: the trace is the single event `done 0 t`, with `triangles` and `dimension` as `hull`
   * gives them.
   *
   * @throws {HullkitError} for more points than {@link Hullkit.traceLimits} allows for the scan
   *   (5000 single pass, 1000 restart), an unknown option or scan, a coordinate count that is not a
   *   multiple of 3, a non-finite coordinate (`pointIndex`), or coordinates out of the exact range.
   */
  giftwrapTrace(xyz: Points3, options?: GiftwrapTraceOptions): GiftwrapTrace;
  /** The most points {@link Hullkit.giftwrapTrace} takes per scan, and {@link Hullkit.delaunayGiftwrapTrace} (`delaunay`). */
  readonly traceLimits: Readonly<Record<GiftwrapScan | 'delaunay', number>>;
  /**
   * The 3D points in a file, read by the C++ readers `hullkit hull` uses: "x y z" text, qhull/rbox
   * text, OBJ and OFF (their vertices, faces not needed), and PLY, STL (ASCII or binary) and glTF
   * (.glb, .gltf with data: URIs) as {@link Hullkit.readMesh} reads them (the mesh's vertices; a PLY
   * point cloud without faces too; STL corners with equal coordinates merged). A
   * ".ply"/".stl"/".gltf"/".glb" name picks the mesh
   * reader, ".obj"/".off" the point reader; otherwise the content decides (PLY, STL, else text).
   * Returns x0 y0 z0 x1 y1 z1 ...
   *
   * @param bytes the file's contents
   * @param name the file name: picks the format and starts every error message (default "<bytes>")
   * Records an OBJ file should not hold (FCL's "648 1292" count line, a misspelt keyword) are
   * skipped, and said so in the result's `warnings`; so is a CSV header row of column names
   * (`x,y,z`: "skipped header line 1: x,y,z"). A UTF-8 byte-order mark is skipped. A file without
   * points (empty, only comments) gives an empty array, not an error.
   *
   * @throws {HullkitError} with the reader's message, "name:LINE: what is wrong" (then `line` is
   *   set; a non-finite coordinate: 'p.xyz:5: coordinate "nan" of point 3 is not a finite number')
   *   or "name: what is wrong" (truncated binary STL, ...).
   */
  readPoints(bytes: Uint8Array | ArrayBuffer | ArrayBufferView, name?: string): PointsRead;
  /**
   * 2D points from a file, x0 y0 x1 y1 ...: text as `hullkit delaunay` reads it ("x y" or
   * "x y z" lines, z ignored, whitespace or a comma between the numbers, a CSV header row skipped;
   * qhull/rbox text of dimension 2 or 3); a mesh file (OBJ, OFF, PLY,
   * STL, by name or content) gives the x and y of the points {@link Hullkit.readPoints} reads.
   *
   * @throws {HullkitError} as {@link Hullkit.readPoints}.
   */
  readPoints2d(bytes: Uint8Array | ArrayBuffer | ArrayBufferView, name?: string): PointsRead;
  /**
   * A triangle mesh from OBJ, OFF, PLY (ascii or binary), STL (ASCII or binary) or glTF 2.0 (.glb,
   * or .gltf with its buffers embedded as data: URIs; a .gltf naming external .bin files is refused
   * here — use a .glb), read as the route checker reads obstacle and traverse meshes (format from
   * the content, then the name's extension). Faces with more than 3 corners are fanned; a glTF
   * gives the triangle primitives of its default scene with the node transforms applied.
   *
   * @throws {HullkitError} with the reader's message naming the line (`line`) or binary record, or
   *   the problem (no triangles, truncated binary STL, not a mesh format).
   */
  readMesh(bytes: Uint8Array | ArrayBuffer | ArrayBufferView, name?: string): MeshData;
  /**
   * The hull as binary glTF 2.0 (.glb) bytes, as `hullkit hull -o hull.glb` writes them: one mesh,
   * the hull's vertices (in the order of `result.vertices`) as float32 positions — rounded to the
   * nearest float, so not exact, unlike OBJ/OFF text — and its triangles as uint32 indices into
   * them. {@link Hullkit.readMesh} reads it back.
   *
   * @param xyz the points the hull was computed from
   * @param result what {@link Hullkit.hull} returned for them (its `vertices` and `triangles`)
   * @throws {HullkitError} for a coordinate beyond float32's range (about 3.4e38), or a result that
   *   does not fit the points.
   */
  writeGlb(xyz: Points3, result: { vertices: Uint32Array | ArrayLike<number>; triangles: Uint32Array | ArrayLike<number> }): Uint8Array;
  /**
   * The Delaunay triangulation of the 2D points `xy`, a flat array x0 y0 x1 y1 ... (a Float64Array
   * is used as it is; other array-likes of numbers are converted): the lower convex hull of the
   * points lifted to the paraboloid z = x² + y², projected back. Every decision is exact.
   * Degenerate input is a value, not an error: duplicates are merged (`representative`), collinear
   * points or fewer than three distinct points give no triangles (`dimension` 1, 0 or -1).
   * The arrays are laid out as delaunator's, so code written for delaunator works on the result.
   *
   * @throws {HullkitError} for a coordinate count that is not even, a non-finite coordinate
   *   (`pointIndex` names the point), magnitudes the exact predicates cannot take after rescaling
   *   (`pointIndex` too), or an unknown option or option value.
   */
  delaunay(xy: Float64Array | ArrayLike<number>, options?: DelaunayOptions): DelaunayResult;
  /**
   * The Delaunay triangulation of an array of points, `[[x, y], ...]` (as delaunator's
   * `Delaunator.from` takes them) or `[{x, y}, ...]` (three.js `Vector2`s), flattened into a
   * Float64Array first (pass a Float64Array to skip that copy).
   *
   * @throws {HullkitError} for an entry that is not a point of 2 numbers ("points[3] has 3
   *   coordinates, expected 2"; `pointIndex` names it), and as the flat overload.
   */
  delaunay(points: ArrayLike<Point2>, options?: DelaunayOptions): DelaunayResult;
  /**
   * The triangles inside polygons with holes, exactly — earcut's arguments and a constrained
   * Delaunay triangulation: `coords` flat (x y per vertex, or `dim` numbers per vertex of which the
   * first two are used), `holeIndices` the vertex index at which each hole (each ring after the
   * first) starts. Or a GeoJSON Polygon, MultiPolygon or a Feature holding one (no holeIndices).
   * Rings may be open or closed, in any orientation, order and nesting; they may touch, overlap
   * and cross: the inside is decided by `fill` ('evenodd', the default, or 'nonzero'). Every ring
   * edge is an edge of the result (split where a vertex lies on it; where two ring edges cross,
   * the crossing is computed exactly, rounded to the nearest double and added to `coords`), and
   * every other edge is as Delaunay as the rings allow. Every decision is an exact orient2d or
   * incircle: no overlapping or zero-area triangle, nothing dropped, for any input.
   *
   * With `minAngle` / `maxArea` the inside becomes a quality mesh (Delaunay refinement, Triangle's
   * -q and -a): points are added (`steinerCount`, after the crossings in `coords`) until every
   * angle is at least `minAngle` degrees and no triangle is larger than `maxArea`; `conforming`
   * makes every triangle Delaunay (Triangle's -D).
   *
   * @example
   * // earcut(coords, holeIndices) becomes:
   * const { triangles } = hullkit.triangulatePolygon(coords, holeIndices);
   * // a quality mesh of the same polygon:
   * const mesh = hullkit.triangulatePolygon(coords, holeIndices, { minAngle: 25, maxArea: 10 });
   *
   * @throws {HullkitError} for a non-finite coordinate (`pointIndex`), holeIndices that decrease or
   *   pass the vertex count, a GeoJSON value that is not a (Multi)Polygon, or an unknown option.
   */
  triangulatePolygon(
    coords: Float64Array | ArrayLike<number> | GeoJSONPolygonLike,
    holeIndices?: Uint32Array | ArrayLike<number> | null,
    options?: PolygonOptions,
  ): ConstrainedResult;
  /**
   * The constrained Delaunay triangulation of points `coords` (x y per point) with segments
   * `edges` (index pairs, flat): every segment is an edge of the result (split at points that lie
   * on it; crossing segments meet at their exactly computed crossing rounded to the nearest double,
   * added to `coords`), and the triangulation covers the convex hull, as Delaunay as the segments
   * allow. Delaunator + Constrainautor's job in one call, without "constraining edge intersects
   * point" errors. Repeated points are merged (`representative`), zero-length and repeated
   * segments are harmless.
   *
   * Triangle's .poly domain and quality options: `removeExterior` drops what lies outside the
   * segments, `holes` (x y per hole point) the regions around the hole points; `minAngle`,
   * `maxArea`, `conforming` refine what is left (see triangulatePolygon).
   *
   * @throws {HullkitError} for a non-finite coordinate (`pointIndex`), an edge index past the points
   *   (`segmentIndex`), an odd number of edge indices, a bad option.
   */
  constrainedDelaunay(coords: Float64Array | ArrayLike<number>, edges: Uint32Array | ArrayLike<number>, options?: GraphOptions): ConstrainedResult;
  /**
   * Triangle's -r: refines a triangulation, `triangles` (index triples into `coords`, either
   * orientation: an earlier result's `triangles` will do). The domain is their union: its boundary
   * (edges of one triangle only) and `edges` (index pairs) are kept, the inside is triangulated anew
   * (constrained Delaunay) and refined by `minAngle`, `maxArea`, `conforming`, `unsuitable`. With
   * `triangleMaxArea` (one bound per triangle, 0 or less: none) every edge of the mesh is kept so
   * that each bound holds over its own triangle, and `sourceTriangle` says which input triangle each
   * output triangle lies in. Vertices no triangle or edge uses stay in `coords`, in no triangle.
   *
   * @example
   * const first = hullkit.triangulatePolygon(coords, holeIndices);
   * const finer = hullkit.refineMesh(first.coords, first.triangles, { minAngle: 30, maxArea: 0.5 });
   *
   * @throws {HullkitError} for a triangle with an index past the points, no area, or an edge on the
   *   same side as another's (overlap) (`triangleIndex`), a non-finite coordinate (`pointIndex`), a
   *   triangleMaxArea of the wrong length, a bad option.
   */
  refineMesh(
    coords: Float64Array | ArrayLike<number>,
    triangles: Uint32Array | ArrayLike<number>,
    options?: MeshRefineOptions,
  ): ConstrainedResult & { sourceTriangle?: Int32Array };
  /**
   * The index of the input point nearest to (x, y) (exact ties: the lowest index; a duplicate is
   * never returned, its representative is), found by walking `triangulation` from point `start`
   * (default 0; the previous answer is a good start for a moving query). -1 when there are no points.
   * `xy` and `triangulation` are copied into the WebAssembly heap on each call (O(n)).
   *
   * @throws {HullkitError} for a non-finite x or y, a `start` that is not a point index, or a
   *   triangulation whose arrays do not fit `xy` (an index out of range, mismatched lengths,
   *   half-edges that do not pair up).
   */
  find(xy: Points2, triangulation: DelaunayTriangulation, x: number, y: number, start?: number): number;
  /**
   * Exact point location in a triangulation: for each query point (x y per query), the triangle of
   * `triangulation` holding it (an index into `triangles` / 3), or -1 outside the convex hull; with
   * `{barycentric: true}` its barycentric coordinates there, with `{nearest: true}` the nearest
   * input point. A point on an edge or a vertex is held by every triangle around it: the one with
   * the lowest index is reported, so the answer depends only on the point. Every decision is made
   * by exact predicates (orient2d, and an exact comparison of squared distances), never by a
   * rounded area. Queries are sorted along a Hilbert curve and each walk starts where the previous
   * one ended, so many queries cost little more than one walk each: pass them in one call.
   *
   * `triangulation` is what {@link Hullkit.delaunay} returned for the same `xy` (or a delaunator
   * object, as {@link Hullkit.find} takes): its arrays go back into the core, which answers from
   * them (nothing is triangulated again). They are checked for consistency (indices in range,
   * half-edges paired with their reverse), not for geometry: answers for a triangulation of other
   * points are meaningless. Collinear points have no triangles (`triangle` is all -1) but a
   * nearest point. The 2D counterpart of {@link Hullkit.locate3}.
   *
   * @example
   * const t = hullkit.delaunay(xy);
   * const { triangle, barycentric } = hullkit.locate(xy, t, [0.1, 0.2], { barycentric: true });
   * // triangle[0] >= 0: the point 0.1 0.2 is Σ barycentric[k] · corner k, the corners being
   * // t.triangles[3 * triangle[0] + k]; exactly 1 and two 0s when it is one of the corners
   *
   * @throws {HullkitError} for a non-finite query coordinate or one too far from the points' scale
   *   to be decided exactly ("locate: query 1 has a non-finite y coordinate (nan)", `queryIndex`
   *   1), an odd number of query coordinates, a triangulation whose arrays do not fit the points
   *   (the message says which entry; a `representative` of another length: a triangulation of
   *   other points), an unknown option or a non-boolean flag.
   * @throws {TypeError} for queries that are not a Float64Array or an array of numbers (an array of
   *   [x, y] points is refused: flatten it), or a triangulation that is not an object.
   */
  locate(
    xy: Points2,
    triangulation: DelaunayTriangulation,
    queries: Float64Array | ArrayLike<number>,
    options?: LocateOptions,
  ): LocateResult;
  /**
   * The Voronoi cells of the points, clipped to the rectangle `bounds` = [xmin, ymin, xmax, ymax],
   * built from the circumcentres of `triangulation`'s triangles.
   *
   * @throws {HullkitError} for bounds that are not four finite numbers with xmin < xmax and
   *   ymin < ymax, or a triangulation whose arrays do not fit `xy`.
   */
  voronoi(xy: Points2, triangulation: DelaunayTriangulation, bounds: ArrayLike<number>): VoronoiCells;
  /**
   * The whole Voronoi diagram of the points, unbounded cells included, as scipy.spatial.Voronoi
   * lays it out: a vertex per Delaunay polygon (triangles whose corners are exactly cocircular
   * share one: a square grid has one per square), a ridge per Delaunay edge, a cell per distinct
   * point with its area. Which vertices, ridges and cells exist is decided exactly; coordinates
   * and areas are rounded.
   *
   * @example
   * const xy = [0, 0, 1, 0, 0, 1, 1, 1, 0.5, 2];
   * const v = hullkit.voronoiDiagram(xy, hullkit.delaunay(xy));
   * // v.vertices: [0.5, 0.5, 0.5, 1.375]: the unit square's centre and one more
   * // v.cells.subarray(v.cellOffsets[v.pointCell[0]], v.cellOffsets[v.pointCell[0] + 1]): [0, -1]
   *
   * @throws {HullkitError} for a triangulation whose arrays do not fit `xy`.
   */
  voronoiDiagram(xy: Points2, triangulation: DelaunayTriangulation): VoronoiDiagram;
  /** The algorithm names `delaunay` accepts, the default first. */
  readonly delaunayAlgorithms: readonly DelaunayAlgorithm[];
  /** The fill rules triangulatePolygon accepts, the default first: ['evenodd', 'nonzero']. */
  readonly fillRules: readonly ('evenodd' | 'nonzero')[];
  /**
   * The Delaunay view's gift wrap, recorded by the C++ core: the wrap of
   * `delaunay(xy, {algorithm: 'giftwrap'})` on the points lifted to z = x² + y² (same code, the
   * distinct points in input order), events with input indices as in {@link GiftwrapTrace}:
   * `first_point` (the lowest point in (x, y) order), `first_edge` (the convex hull edge leaving
   * it) and its `push_edge`, then per popped edge `pop_edge`, `candidate`, `replace` (p strictly
   * inside the circle through a, b and the candidate = below its lifted plane), `coplanar` (p on the
   * final circle), the projected `accept`s (clockwise with y up, as `delaunay` reports them) and
   * `push_edge`s; a `pop_edge` with no `candidate` is a convex hull edge. The accepts, as a set, are
   * `delaunay(xy).triangles` (which is `triangles` here, in delaunay's order). Collinear or fewer
   * than three distinct points: the single event `done`.
   *
   * @throws {HullkitError} for more than 2000 points (`traceLimits.delaunay`), and as {@link Hullkit.delaunay}.
   */
  delaunayGiftwrapTrace(xy: Points2): GiftwrapTrace;
  /**
   * The Delaunay tetrahedralization of the 3D points `xyz`, a flat array x0 y0 z0 x1 y1 z1 ... (a
   * Float64Array is used as it is; an array of numbers is converted; an array of [x, y, z] or
   * {x, y, z} points is refused with a TypeError saying to flatten it): tetrahedra whose
   * circumspheres hold no input point, filling the convex hull. Every decision is made by exact
   * orient3d and insphere tests on the input coordinates. Cospherical points (grids, lattices,
   * points on a sphere) are tetrahedralized by one rule that depends only on the points (Devillers
   * and Teillaud's symbolic perturbation, each point's lift raised by an infinitesimal that grows
   * with its place in (x, y, z) order; CGAL's default), so no tetrahedron is flat and the same
   * points give the same tetrahedra in any order, natively and in WebAssembly. Degenerate input is a value, not an error: duplicates
   * are merged (`representative`); coplanar points give `triangles`, collinear points or a single
   * distinct point give `vertices` (see {@link Delaunay3Result.dimension}).
   * The WebAssembly build runs on the calling thread (the native library's `threads` gives the same
   * arrays); about 250 bytes of WebAssembly memory per point at the peak.
   *
   * @example
   * const { tetrahedra, neighbors, hull } = hullkit.delaunay3(xyz);
   * for (let t = 0; t < tetrahedra.length / 4; t++) {
   *   const [a, b, c, d] = tetrahedra.subarray(4 * t, 4 * t + 4); // orient3d(a, b, c, d) > 0
   *   const across = neighbors[4 * t + 3]; // the tetrahedron sharing face (a, b, c), or -1
   * }
   *
   * @throws {HullkitError} for a coordinate count that is not a multiple of 3, a non-finite
   *   coordinate ("delaunay3: point 3 has a non-finite y coordinate (nan)", `pointIndex` 3),
   *   magnitudes the exact predicates cannot take after rescaling (the message names the smallest
   *   and largest point), an unknown option or a `progress` that is not a function. An exception
   *   thrown by `progress` is rethrown once the tetrahedralization has finished.
   * @throws {TypeError} for points that are not a Float64Array or an array of numbers.
   */
  delaunay3(xyz: Float64Array | ArrayLike<number>, options?: Delaunay3Options): Delaunay3Result;
  /**
   * Checks exactly that `tetrahedra` (4 indices each, as {@link Delaunay3Result.tetrahedra}, from
   * hullkit or elsewhere, e.g. a TetGen .ele's rows with 1 subtracted) is the Delaunay tetrahedralization of the
   * distinct points of `xyz`: indices in range, every tetrahedron positively oriented (none flat),
   * each face shared by at most two tetrahedra lying on opposite sides, the boundary faces a closed
   * convex surface (the convex hull's), every distinct point a vertex, Euler's V - E + F - T = 1,
   * and every interior face locally Delaunay by the exact in-sphere test; with `perturbed` (the
   * default) ties must also go as {@link Hullkit.delaunay3}'s rule decides, which makes the answer
   * unique. Only for points that span 3D: coplanar points have no tetrahedra to check.
   * Problems are reported in the returned value, not thrown.
   *
   * @throws {HullkitError} only for malformed arguments (a coordinate count that is not a multiple
   *   of 3, an index count that is not a multiple of 4, an entry that is not a non-negative
   *   integer, an unknown option); TypeError for arguments that are not arrays.
   */
  verifyDelaunay3(
    xyz: Float64Array | ArrayLike<number>,
    tetrahedra: Uint32Array | ArrayLike<number>,
    options?: VerifyDelaunay3Options,
  ): Delaunay3VerifyReport;
  /**
   * Exact point location in a tetrahedralization: for each query point (x y z per query), the
   * tetrahedron of `triangulation` holding it, or -1 outside the convex hull; with
   * `{barycentric: true}` its barycentric coordinates there, with `{nearest: true}` the nearest
   * input point. A point on a face, edge or vertex is held by every tetrahedron around it: the one
   * with the lowest index is reported, so the answer depends only on the point. Every decision is
   * made by exact predicates (orient3d, and an exact comparison of squared distances), never by a
   * rounded volume. Queries are sorted along a Hilbert curve and each walk starts where the
   * previous one ended, so many queries cost little more than one walk each.
   *
   * `triangulation` is what {@link Hullkit.delaunay3} returned for the same `xyz`: its arrays go
   * back into the core, which answers from them (nothing is tetrahedralized again). They are
   * checked for consistency (indices in range, neighbours that share their faces back), not for
   * geometry: check arrays from elsewhere with {@link Hullkit.verifyDelaunay3} first. Coplanar and
   * collinear points have no tetrahedra (`tetrahedron` is all -1) but a nearest point. A
   * furthest-site tetrahedralization (`furthestSite: true`) locates queries but finds no nearest
   * points (`nearest: true` throws: the points inside the hull are in it nowhere).
   *
   * @example
   * const t = hullkit.delaunay3(xyz);
   * const { tetrahedron, barycentric } = hullkit.locate3(xyz, t, [0.1, 0.2, 0.3], { barycentric: true });
   * // tetrahedron[0] >= 0: the point is 0.1 0.2 0.3 = Σ barycentric[k] · corner k of that tetrahedron
   *
   * @throws {HullkitError} for a non-finite query coordinate or one too far from the points' scale
   *   to be decided exactly (`queryIndex` names the query), a triangulation whose arrays do not fit
   *   the points (the message says which entry), an unknown option or a non-boolean flag.
   * @throws {TypeError} for points or queries that are not a Float64Array or an array of numbers.
   */
  locate3(
    xyz: Float64Array | ArrayLike<number>,
    triangulation: Delaunay3Triangulation,
    queries: Float64Array | ArrayLike<number>,
    options?: Locate3Options,
  ): Locate3Result;
  /**
   * The Voronoi diagram of `xyz`, dual to its tetrahedralization `triangulation` (what
   * {@link Hullkit.delaunay3} returned for the same points, checked as {@link Hullkit.locate3}
   * checks it): a vertex at the circumcentre of each Delaunay cell, a face between each pair of
   * points joined by a Delaunay edge, and each point's cell with its volume. Which vertices and
   * faces exist is decided exactly (cospherical tetrahedra, as in a grid's cubes, share one
   * vertex by the exact in-sphere test); coordinates and volumes are rounded. Points on the convex
   * hull have unbounded cells (volume `Infinity`). Below dimension 3 every cell is unbounded: no
   * vertices or faces.
   *
   * @example
   * const v = hullkit.voronoi3(xyz, hullkit.delaunay3(xyz));
   * for (let f = v.cellOffsets[i]; f < v.cellOffsets[i + 1]; f++) {
   *   const face = v.cellFaces[f];
   *   const corners = v.faceVertices.subarray(v.faceOffsets[face], v.faceOffsets[face + 1]);
   *   // corners index v.vertices (x y z each); v.faceBounded[face] === 0 on an unbounded face
   * }
   *
   * @throws {HullkitError} for a triangulation whose arrays do not fit the points.
   * @throws {TypeError} for points that are not a Float64Array or an array of numbers.
   */
  voronoi3(xyz: Float64Array | ArrayLike<number>, triangulation: Delaunay3Triangulation): Voronoi3Result;
  /**
   * The exact convex hull of points in `dimension` dimensions (2 to 10; `hull` is faster in 3D):
   * quickhull on simplicial facets, every side test exact. Points in a facet's hyperplane that see
   * no facet are not vertices.
   *
   * @example
   * const h = hullkit.hullNd([[0, 0, 0, 0], [1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], 4);
   * h.facets.length / 4; // 5 facets of 4 corners
   *
   * @throws {HullkitError} for points that span fewer dimensions ("lie in a flat of k dimensions"),
   *   fewer than dimension + 1 points, a non-finite coordinate (with `pointIndex`) or a dimension out of range.
   * @throws {TypeError} for points that are not numbers.
   */
  hullNd(points: Float64Array | ArrayLike<number> | ArrayLike<ArrayLike<number>>, dimension: number): HullNdResult;
  /**
   * The exact Delaunay triangulation of points in `dimension` dimensions (1 to 9; `delaunay` and
   * `delaunay3` are faster in 2D and 3D): the lower facets of the points lifted to the paraboloid
   * (`furthestSite`: the upper ones). Every distinct point is a corner; cospherical points (cube
   * corners, grids) get one of their triangulations, no simplex flat.
   *
   * @throws {HullkitError} as hullNd, and for fewer than dimension + 1 distinct points.
   */
  delaunayNd(
    points: Float64Array | ArrayLike<number> | ArrayLike<ArrayLike<number>>,
    dimension: number,
    options?: { furthestSite?: boolean },
  ): DelaunayNdResult;
  /**
   * The simplex of `triangulation` (delaunayNd's result for `points`) holding each query, exactly:
   * on a shared face the lowest-indexed simplex holding it; -1 outside the hull (and for a query
   * with a non-finite coordinate).
   *
   * @throws {HullkitError} for a triangulation whose arrays do not fit the points.
   */
  locateNd(
    points: Float64Array | ArrayLike<number> | ArrayLike<ArrayLike<number>>,
    triangulation: DelaunayNdResult,
    queries: Float64Array | ArrayLike<number> | ArrayLike<ArrayLike<number>>,
  ): Int32Array;
  /**
   * Checks a traverse moved along the scene's route against its obstacles, one check per leg. A
   * straight translation: the convex hull of each part at both ends of a leg contains all it
   * sweeps (no contact missed), and an exact narrow phase on the swept triangles where that hull
   * hits (no contact invented for non-convex parts). A leg that turns: the same hulls grown by the
   * interpolation bound over adaptive sub-intervals, a hit only at a pose found in contact.
   * Returns the same report as `hullkit route`.
   * Meshes may be inline, bytes (`mesh: Uint8Array`), or file names looked up in `options.files`.
   *
   * @throws {HullkitError} for a malformed scene or mesh (the message names the field, e.g.
   *   "checkRoute: scene: obstacles[2].box.min: expected 3 numbers [x, y, z], got 2 values", or
   *   the mesh and its line), fewer than two waypoints, a non-finite number, a malformed rotation
   *   (not a unit quaternion, a zero axis, a rotation key outside a waypoint), or an unknown option.
   */
  checkRoute(scene: RouteScene, options?: RouteCheckOptions & RouteSceneOptions): RouteReport;
  /**
   * A scene prepared once (the parts' hulls and the obstacles' bounding-volume hierarchy) for
   * many {@link RouteChecker.check} calls, e.g. while waypoints are dragged. The scene's `route`
   * may be left out. Free it with `delete()` (or `using checker = new hullkit.RouteChecker(...)`).
   */
  RouteChecker: new (scene: RouteScene, options?: RouteSceneOptions) => RouteChecker;
}

/** How gift wrapping searches for the face across an edge. */
export type GiftwrapScan = 'single-pass' | 'restart';

export interface GiftwrapTraceOptions {
  /**
   * `'single-pass'` (default): one pass over the points per edge; a point above the candidate's
   * plane replaces it (`replace` events). `'restart'`: the seed's literal step 4; a point above the
   * candidate's plane rejects it and the next candidate is tested from the start (`restart` events).
   */
  scan?: GiftwrapScan;
}

/**
 * The name of a recorded gift-wrap event; each event has three arguments a, b, c (point indices,
 * unused ones 0). "Above" a plane means outside the would-be face.
 *  - `first_point` a: step 1, the point with the largest x (then y, z).
 *  - `first_edge` a b: step 2, the edge a→b of the flattened points' hull leaving a.
 *  - `vertical_face` a b c: the vertical plane through the first edge holds a face (a, b, c span
 *    it); its `accept` events follow directly.
 *  - `wrap_first` a b: the vertical plane touches the hull along the segment a–b: the first face is
 *    searched across a→b (not taken from the stack).
 *  - `push_edge` a b: a→b goes onto the edge stack (the face on its left is still unknown).
 *  - `pop_edge` a b: a→b taken off the stack to be wrapped: the edge being wrapped.
 *  - `skip_edge` a b: a→b taken off the stack, but both its faces are known: discarded.
 *  - `candidate` a b c: candidate triangle a, b, c for the edge being wrapped.
 *  - `replace` a b p: (single pass) p lies above the candidate's plane: new candidate a, b, p.
 *  - `restart` a b p: (restart) p lies above the candidate's plane: the candidate is rejected and
 *    the next `candidate` is tested against all points again.
 *  - `coplanar` a b p: p lies exactly on the candidate's plane; it joins the face if the candidate
 *    stands (a later `replace` forgets it).
 *  - `accept` a b c: a hull triangle, counter-clockwise from outside (a face with more corners gives
 *    consecutive accepts fanned from its lowest index), followed by its `push_edge`s.
 *  - `done` f t: the hull closed with f faces and t triangles (the last event).
 */
export type GiftwrapEventName =
  | 'first_point' | 'first_edge' | 'vertical_face' | 'wrap_first' | 'push_edge' | 'pop_edge' | 'skip_edge'
  | 'candidate' | 'replace' | 'restart' | 'coplanar' | 'accept' | 'done';

/**
 * A recorded gift wrap. Event e is `kindNames[kinds[e]]` with arguments `args[3e]`, `args[3e + 1]`,
 * `args[3e + 2]`. Replay: the edge stack is the `push_edge` events, each `pop_edge` / `skip_edge`
 * removing its top (the edge it names); the `accept` events in order are `triangles`.
 */
export interface GiftwrapTrace {
  kinds: Uint8Array;
  args: Uint32Array;
  /** Index = kind: the {@link GiftwrapEventName}s in the order above. */
  kindNames: GiftwrapEventName[];
  /** The hull's triangles, as `hull(xyz, {algorithm: 'giftwrap'}).triangles`. */
  triangles: Uint32Array;
  /** As `hull` (or for delaunayGiftwrapTrace, `delaunay`) gives it. */
  dimension: 3 | 2 | 1 | 0 | -1;
}

/**
 * Points read from a file (x y z, or x y for readPoints2d), with what the reader skipped and read
 * on past: one line per kind, without the file name, e.g.
 * `skipped 1 unknown OBJ record "648" (first at line 1)`; empty when nothing was skipped.
 */
export type PointsRead = Float64Array & { readonly warnings: string[] };

/** A triangle mesh read from a file. */
export interface MeshData {
  /** What the reader skipped (as {@link PointsRead.warnings}); empty when nothing was. */
  warnings?: string[];
  /** x0 y0 z0 x1 y1 z1 ... */
  vertices: Float64Array;
  /** 3 vertex indices per triangle, in the file's orientation. */
  triangles: Uint32Array;
}

/** Algorithms available to {@link Hullkit.delaunay}; every one returns identical triangles. */
export type DelaunayAlgorithm = 'incremental' | 'giftwrap';

export interface DelaunayOptions {
  /**
   * `'incremental'` (default): insertion in a space-filling-curve order with a walking locate,
   * exact. `'giftwrap'`: the seed document's gift wrapping on the lifted points, O(n²), for
   * teaching and checking.
   */
  algorithm?: DelaunayAlgorithm;
  /**
   * Also return the Delaunay polygons (`polygonOffsets`, `polygonVertices`): the lower faces of the
   * lifted hull before they are cut into triangles (a square grid gives its squares).
   */
  mergeCocircular?: boolean;
}

/**
 * What {@link Hullkit.find}, {@link Hullkit.locate} and {@link Hullkit.voronoi} need of a
 * triangulation: a {@link DelaunayResult}, or a delaunator object (then no duplicates are assumed).
 */
export interface DelaunayTriangulation {
  triangles: Uint32Array | ArrayLike<number>;
  halfedges: Int32Array | ArrayLike<number>;
  hull: Uint32Array | ArrayLike<number>;
  representative?: Uint32Array | ArrayLike<number>;
  dimension?: number;
}

export interface DelaunayResult {
  /**
   * 2 when the distinct points span the plane; 1 when they are all collinear (no triangles, `hull`
   * lists the distinct points in order along the line); 0 one distinct point; -1 no points.
   */
  dimension: 2 | 1 | 0 | -1;
  /**
   * Three indices per triangle into the input points. Orientation as delaunator's: clockwise with
   * the y axis pointing up, i.e. counter-clockwise on a screen whose y axis points down.
   * Cocircular points (grids, regular polygons) are triangulated by one documented rule that every
   * algorithm shares; no triangle has zero area.
   */
  triangles: Uint32Array;
  /**
   * One entry per entry of `triangles`: half-edge e goes from `triangles[e]` to
   * `triangles[next(e)]` with next(e) = e % 3 === 2 ? e - 2 : e + 1; `halfedges[e]` is the opposite
   * half-edge in the neighbouring triangle, or -1 on the hull (as delaunator's).
   */
  halfedges: Int32Array;
  /** The convex hull as a cycle of point indices in the triangles' orientation, including points on hull edges. */
  hull: Uint32Array;
  /**
   * For each input point, the index that stands for it: itself, or the lowest index with exactly
   * the same coordinates (duplicates are merged, never dropped silently).
   */
  representative: Uint32Array;
  /** How many points are duplicates (`representative[i] !== i`). */
  duplicateCount: number;
  /**
   * With `mergeCocircular`: polygon p is `polygonVertices.subarray(polygonOffsets[p], polygonOffsets[p + 1])`,
   * in the triangles' orientation, starting at its lowest index.
   */
  polygonOffsets?: Uint32Array;
  polygonVertices?: Uint32Array;
}

/** A GeoJSON Polygon or MultiPolygon, or a Feature holding one (positions [x, y, ...]). */
export type GeoJSONPolygonLike =
  | { type: 'Polygon'; coordinates: number[][][] }
  | { type: 'MultiPolygon'; coordinates: number[][][][] }
  | { type: 'Feature'; geometry: { type: 'Polygon'; coordinates: number[][][] } | { type: 'MultiPolygon'; coordinates: number[][][][] } };

/** Delaunay refinement (Triangle's -q, -a, -D); without any of them nothing is refined. */
export interface QualityOptions {
  /**
   * Smallest angle in degrees, 0 to 34 (default 0: none). Up to 28.6 refinement always finishes;
   * triangles at input angles smaller than this are left as they are (`unrefinedCount`).
   */
  minAngle?: number;
  /** Largest triangle area, in the coordinates' units squared (default 0: none). */
  maxArea?: number;
  /** Every triangle Delaunay (segments split until no point is in a circle on one as diameter). */
  conforming?: boolean;
  /** Reject (throw) once refinement has added this many points (default 0: no cap). */
  maxSteinerPoints?: number;
  /**
   * Segments refinement adds no point on (Triangle's -Y and -YY): 'boundary' the boundary's (a
   * polygon's rings; a graph's outline and hole boundaries), 'all' every segment (default 'none').
   * Where a circumcentre lies beyond such a segment, a triangle above `maxArea` gets its centroid
   * and one with only a small angle is left (`unrefinedCount`).
   */
  keepSegments?: 'none' | 'boundary' | 'all';
  /**
   * Triangle's -u (its triunsuitable): also refine each triangle for which this returns true,
   * given its corners (counter-clockwise, y up) and area. It must depend on the triangle alone;
   * whether refinement ends is up to it (unless `maxSteinerPoints` is set, a cap of 16 points per
   * input point plus 10⁶ applies). What it throws is thrown by the call, once the core has stopped.
   */
  unsuitable?: (a: [number, number], b: [number, number], c: [number, number], area: number) => boolean;
}

export interface PolygonOptions extends QualityOptions {
  /** Numbers per vertex in flat `coords` (default 2; earcut's `dim`): the first two are x and y. */
  dim?: number;
  /** Which points the rings enclose: 'evenodd' (default; holes whatever their orientation) or 'nonzero'. */
  fill?: 'evenodd' | 'nonzero';
}

export interface GraphOptions extends QualityOptions {
  /** Drop the triangles outside the segments (reachable from the hull without crossing one). */
  removeExterior?: boolean;
  /** Hole points, x y each: the region around each (bounded by segments) is dropped. */
  holes?: Float64Array | ArrayLike<number>;
}

export interface MeshRefineOptions extends QualityOptions {
  /** Edges to keep inside the mesh, index pairs (flat). */
  edges?: Uint32Array | ArrayLike<number>;
  /** One area bound per triangle (0 or less: none); every edge of the mesh is then kept. */
  triangleMaxArea?: Float64Array | ArrayLike<number>;
}

/** What triangulatePolygon, constrainedDelaunay and refineMesh return. */
export interface ConstrainedResult {
  /** 2 when the points span the plane; 1, 0, -1 for collinear, one, no distinct points (no triangles). */
  dimension: 2 | 1 | 0 | -1;
  /**
   * Three indices per triangle into the vertices of `coords` (the input vertices, then the added
   * crossing points), clockwise with y up as delaunator's. A repeated vertex is named by its
   * representative (the first with the same coordinates).
   */
  triangles: Uint32Array;
  /** Per half-edge, the opposite half-edge, or -1 (on the hull, or on the boundary of a polygon's inside). */
  halfedges: Int32Array;
  /** Per half-edge, 1 when it lies on a segment or ring edge (or a piece of one), else 0. */
  constrained: Uint8Array;
  /** The input vertices (x y) followed by the points added at crossings and by refinement. */
  coords: Float64Array;
  /** The number of input vertices; `coords.length / 2 - inputCount` were added (`addedCount`). */
  inputCount: number;
  addedCount: number;
  /** Per input vertex, itself or the first vertex with the same coordinates. */
  representative: Uint32Array;
  duplicateCount: number;
  /** Crossings of two segments resolved by adding (or reusing) a point. */
  crossingCount: number;
  /** Points added by refinement (minAngle, maxArea, conforming); they follow the crossings in `coords`. */
  steinerCount: number;
  /** Triangles left below minAngle (at small input angles) or above maxArea (at the limit of doubles). */
  unrefinedCount: number;
}

export interface LocateOptions {
  /** Also the barycentric coordinates of each query in its triangle (default false). */
  barycentric?: boolean;
  /** Also the nearest input point to each query (default false). */
  nearest?: boolean;
}

export interface LocateResult {
  /**
   * Per query: the triangle holding it, an index into `triangles` / 3 (the lowest index when it
   * lies on a shared edge or vertex), or -1 outside the convex hull (and always -1 when the points
   * do not span the plane).
   */
  triangle: Int32Array;
  /**
   * With `barycentric`: 3 per query, the weights of the triangle's corners (in its corner order)
   * that give the query point: they sum to 1 up to rounding, are exactly 0 for a corner whose
   * opposite edge holds the point and exactly 1 at a corner; NaN outside the hull.
   */
  barycentric?: Float64Array;
  /**
   * With `nearest`: per query, the nearest input point (exact distances; ties go to the lowest
   * index, so never a duplicate); -1 only when there are no points.
   */
  nearest?: Int32Array;
}

export interface VoronoiCells {
  /**
   * One more entry than there are points: cell i is the polygon of points
   * `cellXY.subarray(2 * cellOffsets[i], 2 * cellOffsets[i + 1])` (x y pairs), counter-clockwise
   * with y up; empty for duplicates and for points whose cell misses the rectangle.
   */
  cellOffsets: Uint32Array;
  /** The cells' corners, x y pairs. */
  cellXY: Float64Array;
}

/** The result of {@link Hullkit.voronoiDiagram}. */
export interface VoronoiDiagram {
  /**
   * x y per Voronoi vertex: each Delaunay polygon's circumcentre (rounded), numbered in the order
   * of the polygons' first triangles.
   */
  vertices: Float64Array;
  /** Per triangle of the triangulation: its polygon's vertex. */
  triangleVertex: Uint32Array;
  /** 2 per ridge: the points p < q it separates (a Delaunay edge between two polygons or on the hull). */
  ridgePoints: Int32Array;
  /** 2 per ridge: the vertex across and the vertex, or -1 (infinity) and the vertex for a ray. */
  ridgeVertices: Int32Array;
  /**
   * Every cell's vertices: cell c is `cells.subarray(cellOffsets[c], cellOffsets[c + 1])`,
   * counter-clockwise (y up); a bounded cell from its lowest vertex, an unbounded one (a hull
   * point's) with -1 last. Collinear points: each cell is [-1] and each ridge [-1, -1].
   */
  cells: Int32Array;
  /** One more than there are cells (one per distinct point). */
  cellOffsets: Uint32Array;
  /** Per cell: its point. */
  cellPoint: Uint32Array;
  /** Per input point: its cell (a duplicate: its representative's). */
  pointCell: Int32Array;
  /** Per cell: its area, `Infinity` when unbounded. */
  areas: Float64Array;
}

export interface Delaunay3Options {
  /**
   * Called on the calling thread as points are inserted: `pointsDone` of `total` after each round
   * of the insertion (rounds grow eightfold; the last holds 7/8 of the points), the last call with
   * `pointsDone === total`. Not called when the points do not span 3D or the plane.
   */
  progress?: (pointsDone: number, total: number) => void;
  /**
   * The furthest-site tetrahedralization instead (scipy's and Qhull's furthest_site: the upper hull
   * of the lifted points): the tetrahedra whose circumspheres hold every point. Only the convex
   * hull's extreme points are corners (a point inside the hull, or inside one of its faces or
   * edges, is in no tetrahedron); ties as for the ordinary one (no flat tetrahedron). Coplanar
   * points: the furthest-site triangles of the polygon's corners; collinear: the two end points.
   * {@link Hullkit.locate3} and {@link Hullkit.voronoi3} take the result as they take the ordinary
   * one (the diagram's cells are then all unbounded). Default false.
   */
  furthestSite?: boolean;
}

/** hullNd's result: `dimension` corners per facet, in flat arrays. */
export interface HullNdResult {
  dimension: number;
  /**
   * `dimension` point indices per facet, ordered so that a point q is strictly outside when the
   * determinant of the rows [corner, 1] ... and [q, 1] is positive.
   */
  facets: Uint32Array;
  /** `dimension` per facet: `neighbors[d * f + k]` shares every corner of facet f but its k-th. */
  neighbors: Int32Array;
  /** The hull's vertices, ascending. */
  vertices: Uint32Array;
  /** Per facet: the lowest facet of its flat piece of the boundary (exactly coplanar neighbours). */
  group: Int32Array;
}

/** delaunayNd's result: `dimension + 1` corners per simplex, in flat arrays. */
export interface DelaunayNdResult {
  dimension: number;
  /** `dimension + 1` point indices per simplex, positively oriented (det of the rows [corner, 1] > 0). */
  simplices: Uint32Array;
  /** `dimension + 1` per simplex: across from each corner, -1 on the hull. */
  neighbors: Int32Array;
  /** Per simplex: the lowest simplex with exactly the same circumsphere reachable through neighbours. */
  group: Int32Array;
  /** Per point: the lowest index of an equal point. */
  representative: Uint32Array;
  duplicateCount: number;
  furthestSite: boolean;
}

/**
 * A Delaunay tetrahedralization. Every field is always present; the arrays a `dimension` does not
 * use are empty. Indices are input indices; a duplicate point never appears, its
 * `representative` does.
 */
export interface Delaunay3Result {
  /**
   * The dimension of the points' affine hull: 3 tetrahedra; 2 all points on one plane
   * (`triangles`); 1 all on one line (`vertices`); 0 one distinct point (`vertices` holds it);
   * -1 no points.
   */
  dimension: 3 | 2 | 1 | 0 | -1;
  /**
   * Dimension 3: four indices per tetrahedron, positively oriented: orient3d(a, b, c, d) > 0, that
   * is d lies on the side the normal (b - a) × (c - a) points to (a, b, c counter-clockwise seen
   * from d). Each starts at its lowest index; no tetrahedron is flat.
   */
  tetrahedra: Uint32Array;
  /**
   * Dimension 3: four per tetrahedron, `neighbors[4 * t + k]` the tetrahedron sharing the face
   * opposite corner k of tetrahedron t, or -1 where that face is on the hull (scipy's convention).
   * Dimension 2: three per triangle, the triangle across the edge opposite corner k, -1 on the
   * boundary.
   */
  neighbors: Int32Array;
  /**
   * Dimension 3: the convex hull's triangles, three indices each, counter-clockwise seen from
   * outside: exactly the faces whose `neighbors` entry is -1 (coplanar hull faces triangulated by
   * the same tie rule), each starting at its lowest index, sorted.
   */
  hull: Uint32Array;
  /**
   * Dimension 2: the points' 2D Delaunay triangulation in their plane, three indices per triangle,
   * counter-clockwise seen from the side `normal` points to.
   */
  triangles: Uint32Array;
  /** Dimension 1: the distinct points in order along their line; dimension 0: the one point. */
  vertices: Uint32Array;
  /**
   * Dimension 2: the plane's unit normal (rounded), pointing to the side where its largest
   * component (x before y before z on ties) is positive; [0, 0, 0] otherwise.
   */
  normal: Float64Array;
  /**
   * For each input point, the index that stands for it: itself, or the lowest index with exactly
   * the same coordinates (duplicates are merged, never dropped silently).
   */
  representative: Uint32Array;
  /** How many points are duplicates (`representative[i] !== i`). */
  duplicateCount: number;
  /** Whether this is the furthest-site tetrahedralization ({@link Delaunay3Options.furthestSite}). */
  furthestSite: boolean;
}

export interface VerifyDelaunay3Options {
  /**
   * true (default): cospherical ties must be decided as {@link Hullkit.delaunay3} decides them, so
   * only hullkit's tetrahedralization passes. false: any Delaunay tetrahedralization passes (for
   * checking another library's output).
   */
  perturbed?: boolean;
}

/**
 * What {@link Hullkit.locate3} and {@link Hullkit.voronoi3} read of a tetrahedralization: a
 * {@link Delaunay3Result} (pass the whole object). `tetrahedra` and `neighbors` are read for
 * dimension 3, `triangles` and `neighbors` for dimension 2, `vertices` below.
 */
export interface Delaunay3Triangulation {
  dimension: number;
  /** true for a furthest-site tetrahedralization (default false): then no nearest points. */
  furthestSite?: boolean;
  tetrahedra?: Uint32Array | ArrayLike<number>;
  neighbors?: Int32Array | ArrayLike<number>;
  triangles?: Uint32Array | ArrayLike<number>;
  vertices?: Uint32Array | ArrayLike<number>;
  /** One per point: its own index, or the lower index of the point with its coordinates. */
  representative: Uint32Array | ArrayLike<number>;
}

export interface Locate3Options {
  /** Also the barycentric coordinates of each query in its tetrahedron (default false). */
  barycentric?: boolean;
  /** Also the nearest input point to each query (default false). */
  nearest?: boolean;
}

export interface Locate3Result {
  /**
   * Per query: the tetrahedron holding it (the lowest index when it lies on a shared face, edge or
   * vertex), or -1 outside the convex hull (and always -1 when the points do not span 3D).
   */
  tetrahedron: Int32Array;
  /**
   * With `barycentric`: 4 per query, the weights of the tetrahedron's corners (in its corner order)
   * that give the query point: they sum to 1 up to rounding, are exactly 0 for a corner whose
   * opposite face holds the point and exactly 1 at a corner; NaN outside the hull.
   */
  barycentric?: Float64Array;
  /**
   * With `nearest`: per query, the nearest input point (exact distances; ties go to the lowest
   * index, so never a duplicate); -1 only when there are no points.
   */
  nearest?: Int32Array;
}

/**
 * The Voronoi diagram of 3D points. Face f separates points `facePoints[2f] < facePoints[2f + 1]`
 * (p < q) and is the polygon of Voronoi vertices
 * `faceVertices.subarray(faceOffsets[f], faceOffsets[f + 1])`, counter-clockwise seen from q's side
 * (its normal points from p to q). Point i's cell is bounded by the faces
 * `cellFaces.subarray(cellOffsets[i], cellOffsets[i + 1])`.
 */
export interface Voronoi3Result {
  /** x y z per Voronoi vertex: the circumcentres of the Delaunay cells (rounded). */
  vertices: Float64Array;
  /** Per tetrahedron: its Voronoi vertex (cospherical tetrahedra share one). */
  tetrahedronVertex: Uint32Array;
  /** 2 per face: the points p < q it separates (a Delaunay edge). */
  facePoints: Uint32Array;
  /** One more than there are faces: where each face's vertices start in `faceVertices`. */
  faceOffsets: Uint32Array;
  faceVertices: Uint32Array;
  /**
   * Per face: 1 bounded (a convex polygon), 0 unbounded (dual to a hull edge: the chain of
   * vertices between its two rays, in the same orientation).
   */
  faceBounded: Uint8Array;
  /** One more than there are points: where each point's faces start in `cellFaces`. */
  cellOffsets: Uint32Array;
  cellFaces: Uint32Array;
  /**
   * Per point: the volume of its cell (rounded); `Infinity` for an unbounded cell (a point on the
   * convex hull), NaN for a duplicate (its representative has the cell).
   */
  volume: Float64Array;
}

export interface Delaunay3VerifyReport {
  /** True when nothing is wrong. */
  ok: boolean;
  /**
   * Up to 40 problems, one line each naming what and where, e.g. "point 7 is inside the
   * circumsphere of tetrahedron 12 (0 3 5 9)".
   */
  problems: string[];
  /** How many problems were found in all. */
  problemCount: number;
  /** The distinct points (duplicates counted once). */
  distinctPoints: number;
  /** The boundary faces: the convex hull's triangles. */
  hullTriangles: number;
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

/** [x, y, z]. */
export type Vec3 = [number, number, number];

/**
 * A traverse part or an obstacle: exactly one of `box`, `vertices` + `triangles`, or `mesh`.
 * Triangle soups and open surfaces (a single plate) are allowed; a closed mesh also counts its
 * inside. Without `name`, a part is called "part K" and an obstacle "obstacle K" in reports.
 */
export interface RouteShape {
  name?: string;
  /** An axis-aligned box (12 triangles). */
  box?: { min: Vec3; max: Vec3 };
  /** Vertices as [[x, y, z], ...] or a flat Float64Array x0 y0 z0 x1 ... */
  vertices?: Vec3[] | Float64Array;
  /** Triangles as [[i, j, k], ...] (0-based vertex indices) or a flat Uint32Array. */
  triangles?: [number, number, number][] | Uint32Array;
  /**
   * A mesh file, OBJ, OFF, PLY (ascii or binary) or STL (ASCII or binary), detected from its
   * content: its bytes, or a name looked up in `options.files`.
   */
  mesh?: Uint8Array | ArrayBuffer | string;
}

/**
 * An orientation: a unit quaternion (length 1 within 1e-9), a turn of `degrees` about `axis`
 * (right-handed), or yaw about z, then pitch about the turned y, then roll about the turned x.
 */
export type RouteRotation =
  | { quaternion: [number, number, number, number] }
  | { axis: Vec3; degrees: number }
  | { yaw_pitch_roll_degrees: Vec3 };

/**
 * A waypoint: a translation offset, or an offset with an orientation (the traverse turned about
 * its pivot). Between waypoints the offset moves linearly and the orientation turns at constant
 * angular speed along the shorter arc.
 */
export type RouteWaypoint = Vec3 | { position: Vec3; rotation?: RouteRotation };

/** The scene: the same object as the JSON `hullkit route` reads. */
export interface RouteScene {
  /** `pivot`: the point the traverse turns about, in its own coordinates (default [0, 0, 0]). */
  traverse: { parts: RouteShape[]; pivot?: Vec3 };
  /**
   * Waypoints: offsets applied to every traverse vertex (and orientations); waypoint k to k + 1 is
   * leg k. At least two (optional for a RouteChecker, whose check() takes the route).
   */
  route?: RouteWaypoint[] | Float64Array;
  obstacles: RouteShape[];
  /** Required clearance (default 0): a leg is clear only when the traverse stays more than this away. */
  margin?: number;
}

export interface RouteSceneOptions {
  /** Mesh files by the names the scene's `mesh` fields use. */
  files?: Record<string, Uint8Array | ArrayBuffer> | Map<string, Uint8Array | ArrayBuffer>;
}

export interface RouteCheckOptions {
  /**
   * Also report per leg what checking N + 1 evenly spaced poses (fractions 0, 1/N, ..., 1) would
   * have found (`sampled`), for comparison. Default 0 (off).
   */
  samples?: number;
  /** Compute the clearance of clear legs (default true); false gives the verdicts alone, faster. */
  clearance?: boolean;
}

/** One leg's answer; `fraction` values are fractions of the leg, 0 at its start, 1 at its end. */
export type RouteLeg =
  | {
      /** The traverse comes within `margin` of an obstacle during the leg. */
      status: 'hit';
      obstacle: string;
      /** Index of the obstacle's triangle in contact. */
      triangle: number;
      part: string;
      /**
       * Brackets the first contact: hi - lo <= 1e-9 (1e-7 on a turning leg), lo never after the
       * true first contact.
       */
      fraction: [number, number];
      /** The traverse offset at fraction[0]. */
      position: Vec3;
      /** The orientation (w, x, y, z) at fraction[0]: present when the route has rotations. */
      rotation?: [number, number, number, number];
      /**
       * Present (true) when a turning leg passes closer than the bounds resolve without a pose
       * found in contact: not certified clear, so reported as a hit.
       */
      grazing?: true;
      sampled?: RouteSampled;
    }
  | {
      /** More than `margin` from every obstacle over the whole leg. */
      status: 'clear';
      /** Minimum distance over the leg, to 1e-9 relative; null when not computed or without obstacles. */
      clearance: number | null;
      /** The nearest obstacle and the fraction where the minimum occurs (null when not computed). */
      obstacle: string | null;
      fraction: number | null;
      sampled?: RouteSampled;
    }
  | {
      /** Already within `margin` of an obstacle at the leg's start. */
      status: 'start-overlap';
      obstacle: string;
      part: string;
      triangle: number;
      sampled?: RouteSampled;
    };

/** With `samples`: whether N-step sampling finds a contact, and the first sampled fraction that does. */
export interface RouteSampled {
  hit: boolean;
  fraction: number | null;
}

/** The report of `hullkit route`, and of checkRoute / RouteChecker.check. */
export interface RouteReport {
  /** Every leg clear. */
  clear: boolean;
  /** Smallest clearance over the legs (null when none was computed). */
  min_clearance: number | null;
  legs: RouteLeg[];
  /** Preparing the scene (hulls, BVH) after reading it. */
  build_seconds: number;
  /** Checking all legs. */
  seconds: number;
}

/**
 * `Symbol.dispose`'s type where the consumer's TypeScript `lib` declares it (esnext.disposable,
 * esnext, or @types/node), otherwise `never`: these types then compile with or without that lib,
 * and add nothing to the global `SymbolConstructor`.
 */
type DisposeSymbol = SymbolConstructor extends { readonly dispose: infer S extends symbol } ? S : never;

/**
 * `{ [Symbol.dispose](): void }` (the lib's `Disposable`, so `using` accepts the object) where the
 * lib declares `Symbol.dispose`; `{}` where it does not.
 */
type DisposableIfSupported = { [K in DisposeSymbol]: () => void };

// With an export list in the file, only declarations marked `export` are the module's: the two
// helpers above stay private (a .d.ts without one exports every top-level declaration).
export {};

/**
 * See {@link Hullkit.RouteChecker}. Where the TypeScript lib has `Symbol.dispose` (TypeScript 5.2 or
 * later with `lib` esnext or esnext.disposable), a checker is `Disposable`:
 * `using checker = new hullkit.RouteChecker(scene)` deletes it at the end of the block.
 */
export interface RouteChecker extends DisposableIfSupported {
  /**
   * Checks `route` ([[x, y, z], ...] or a flat Float64Array; the scene's own route when omitted)
   * against the prepared scene.
   * @throws {HullkitError} for fewer than two waypoints, a non-finite one, or after delete().
   */
  check(route?: RouteWaypoint[] | Float64Array, options?: RouteCheckOptions): RouteReport;
  /** Seconds spent preparing the scene. */
  readonly buildSeconds: number;
  /** True once delete() was called. */
  readonly deleted: boolean;
  /** Frees the WebAssembly memory; later calls throw. Harmless twice. */
  delete(): void;
}

/** What hullkit throws for bad input: the message says what is wrong and where. */
export class HullkitError extends Error {
  /** `pointIndex` and `queryIndex` are kept when they are 0 or more. */
  constructor(message: string, options?: { pointIndex?: number; queryIndex?: number });
  name: 'HullkitError';
  /** Index of the point to blame, when there is one. */
  pointIndex?: number;
  /** locate and locate3: index of the query to blame (a non-finite or out-of-range coordinate). */
  queryIndex?: number;
  /** constrainedDelaunay: index of the segment to blame (an index past the points). */
  segmentIndex?: number;
  /** refineMesh: index of the triangle to blame. */
  triangleIndex?: number;
  /** readPoints / readPoints2d / readMesh: the 1-based line the reader names, when it names one. */
  line?: number;
}

/** Loads the WebAssembly module (once per call) and resolves to the API. */
export default function createHullkit(): Promise<Hullkit>;
