// hullkit: Delaunay triangulation of 2D points by lifting to the paraboloid z = x^2 + y^2.
//
// The Delaunay triangulation is the projection of the lower convex hull of the lifted points
// (the seed document's last section). "Is point d below the lifted plane of triangle a, b, c" is
// exactly the 2D in-circle test, so every decision here is made by the exact predicates
// orient2d and incircle on the original coordinates; no rounded lifted z decides anything.
//
// Output is compatible with delaunator (npm): `triangles` as index triples, `halfedges` with -1 on
// the hull, `hull` as a cycle of indices; orientation as delaunator's, see Delaunay below.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace hullkit {

/// A read-only view of `count` 2D points stored as 2*count doubles: x0 y0 x1 y1 ...
/// The caller keeps the storage alive while the view is in use; nothing is copied.
struct PointSpan2 {
    const double* xy = nullptr;
    std::size_t count = 0;

    PointSpan2() = default;
    PointSpan2(const double* xy_, std::size_t count_) : xy(xy_), count(count_) {}
    /// View of a flat vector; a trailing odd coordinate is ignored (callers that accept user data
    /// check the size first).
    PointSpan2(const std::vector<double>& flat) : xy(flat.data()), count(flat.size() / 2) {}

    const double* operator[](std::size_t i) const { return xy + 2 * i; }
};

enum class DelaunayAlgorithm {
    Incremental,  ///< dedicated incremental insertion in a space-filling-curve order (default)
    Giftwrap,     ///< the seed's gift wrapping on the lifted points: O(n^2), for teaching and checking
};

struct DelaunayOptions {
    DelaunayAlgorithm algorithm = DelaunayAlgorithm::Incremental;
    /// Also report the Delaunay polygons (Delaunay::polygon_offsets / polygon_vertices): the lower
    /// faces of the lifted hull before triangulation (a square grid gives squares).
    bool merge_cocircular = false;
    /// Threads for the output stage of inputs of 50 000 points or more: 1 keeps everything on the
    /// calling thread; any other value (0, the default) lets a second thread share the output
    /// stage where the platform has threads (the WebAssembly build has not). The result is the
    /// same either way.
    unsigned threads = 0;
    /// Called on the calling thread as the incremental algorithm inserts the distinct points:
    /// points_done of total, every 65 536 points and once at the end (points_done == total).
    /// Not called by gift wrapping, nor for fewer than 3 distinct points or collinear ones.
    /// Leave empty for none.
    std::function<void(std::size_t points_done, std::size_t total)> progress;
};

/// A Delaunay triangulation. On failure `error` says what is wrong and, where one point is to
/// blame, `error_point` is its index; the other fields are then empty.
///
/// Orientation (as delaunator): every triangle a, b, c is CLOCKWISE with the y axis pointing up,
/// i.e. counter-clockwise on a screen whose y axis points down (orient2d(a, b, c) < 0).
/// Half-edge e = 3t + k goes from triangles[e] to triangles[next(e)], next(e) = e % 3 == 2 ? e - 2 : e + 1;
/// halfedges[e] is the opposite half-edge in the neighbouring triangle, or -1 on the hull.
///
/// Cocircular points (square grids, regular polygons): the Delaunay polygons are unique; each is
/// triangulated by one rule that every algorithm shares, so every algorithm returns identical
/// arrays, and no triangle has zero area. The canonical rule:
///  * each Delaunay polygon (a triangle in general position) is fanned from its LOWEST index c0:
///    with its corners c0, c1, ..., c(m-1) in order, the triangles are c0, c(k+1), c(k) (clockwise);
///  * each triangle starts at its lowest index;
///  * triangles are sorted by the position of their first corner, then of their second, along a
///    Hilbert curve over the bounding box of the input (points with equal curve keys by index).
///    This depends only on the input; it keeps neighbouring triangles near each other in memory;
///  * `hull` starts at its lowest index and follows the boundary half-edges (clockwise, y up).
///
/// `dimension`: 2 when the distinct points span the plane; 1 when they are all collinear (no
/// triangles; `hull` holds the distinct points in order along the line); 0 one distinct point;
/// -1 no points.
struct Delaunay {
    int dimension = -1;
    std::vector<std::uint32_t> triangles;  ///< 3 indices per triangle into the input points
    std::vector<std::int32_t> halfedges;   ///< one per entry of `triangles`; -1 on the hull
    std::vector<std::uint32_t> hull;       ///< the convex hull as a cycle, in delaunator's orientation,
                                           ///< including points that lie on hull edges
    /// For each input point, the index of the point that represents it: itself, or the lowest index
    /// with exactly the same coordinates (duplicates are merged, never dropped silently).
    std::vector<std::uint32_t> representative;
    std::size_t duplicate_count = 0;  ///< points whose representative is not themselves

    /// With DelaunayOptions::merge_cocircular: polygon p is
    /// polygon_vertices[polygon_offsets[p]] ... polygon_vertices[polygon_offsets[p + 1] - 1], in the
    /// triangles' orientation, starting at its lowest index; the polygons sorted as sequences of
    /// indices (lexicographically, a prefix first), whichever path built them. Empty otherwise.
    std::vector<std::uint32_t> polygon_offsets;
    std::vector<std::uint32_t> polygon_vertices;

    std::string error;              ///< empty on success
    std::int64_t error_point = -1;  ///< index of the offending point, -1 if none

    bool ok() const { return error.empty(); }
    std::size_t triangle_count() const { return triangles.size() / 3; }
};

/// Triangulates `points` exactly. Fails only on a non-finite coordinate (naming the point), more
/// than 357913941 points (6n half-edge slots must fit int32), or coordinates whose nonzero
/// magnitudes span more than a factor of 2^410 (incircle's exact range after a power-of-two
/// rescaling, see predicates.hpp; the error names the smallest and largest point).
Delaunay delaunay(PointSpan2 points, const DelaunayOptions& options = {});

/// "incremental", "giftwrap"
const char* delaunay_algorithm_name(DelaunayAlgorithm algorithm);
/// Parses an algorithm name; returns false (and leaves *out alone) for an unknown name.
bool parse_delaunay_algorithm(const std::string& name, DelaunayAlgorithm* out);

/// The input point nearest to (x, y) (exact ties: the lowest index), found by walking the
/// triangulation from `start` (any point index; a good guess makes it fast). Returns -1 when the
/// triangulation has no points. Distances are compared exactly (compare_distance). Each call first
/// indexes the triangulation, O(n); for many queries use DelaunayLocator.
std::int64_t delaunay_find(PointSpan2 points, const Delaunay& triangulation, double x, double y,
                           std::uint32_t start = 0);

/// delaunay_find for many queries: indexes the triangulation once (one half-edge per point), then
/// each find walks from `start` (or from the previous answer when start is omitted) over Delaunay
/// neighbours to the nearest point. Keeps references to `points` and `triangulation`.
class DelaunayLocator {
public:
    DelaunayLocator(PointSpan2 points, const Delaunay& triangulation);
    std::int64_t find(double x, double y, std::int64_t start = -1);

private:
    PointSpan2 points_;
    const Delaunay& triangulation_;
    std::vector<std::int32_t> outgoing_;  ///< per point: a half-edge leaving it, -1 if none
    int exponent_ = 0;  ///< the power of two delaunay() scaled the points by (distances compared so)
    std::int64_t last_ = -1;
};

/// Point location in a triangulation (dimension 2), exact: which triangle holds each query, its
/// barycentric coordinates there, and the nearest input point.
///
/// A query on an edge or a vertex is held by every triangle around it: the one with the lowest
/// index is reported, so the answer depends only on the query (not on where a walk began, nor on
/// the threads). Every decision is an exact orient2d or compare_distance on the coordinates scaled
/// as delaunay() scales them; a query coordinate that is not finite, or that leaves the predicates'
/// exact range after that scaling, is an error naming the query.
struct DelaunayQueryOptions {
    bool barycentric = false;  ///< also the barycentric coordinates (3 per query)
    bool nearest = false;      ///< also the nearest input point
    /// Threads: 0 every hardware thread, 1 the calling thread; the answers are the same.
    unsigned threads = 0;
};
struct DelaunayQueries {
    /// Per query: the triangle holding it (an index into triangles / 3), -1 outside the hull (and
    /// for every query when the points span less than a plane).
    std::vector<std::int32_t> triangle;
    /// With `barycentric`: 3 per query, the weights of the triangle's corners (in its corner order)
    /// that give the query point; they sum to 1 up to rounding, are exactly 0 for a corner whose
    /// opposite edge holds the query and exactly 1 at a corner; NaN outside the hull.
    std::vector<double> barycentric;
    /// With `nearest`: per query, the nearest input point (exact distances; ties: the lowest index).
    std::vector<std::int32_t> nearest;
    std::string error;  ///< empty on success; on failure the arrays are empty
    std::int64_t error_query = -1;

    bool ok() const { return error.empty(); }
};
/// Locates every query (a flat x y array) in `triangulation`, the delaunay() result for `points`.
/// Queries are sorted along a Hilbert curve and each walk starts where the previous one ended, so
/// many queries cost little more than one short walk each; they are spread over the threads.
DelaunayQueries delaunay_locate(PointSpan2 points, const Delaunay& triangulation, PointSpan2 queries,
                                const DelaunayQueryOptions& options = {});

/// Gradients at the points that make a smooth surface through their values over a triangulation
/// (for Clough-Tocher interpolation): the gradients that minimise the total squared second
/// derivative of the cubics along the Delaunay edges (each edge's cubic fixed by the values and
/// the gradients' components along it, its curvature weighted by 1 / length^3). Found by
/// Gauss-Seidel sweeps over the points in index order, each point's gradient solved exactly from
/// its neighbours' (a 2 x 2 system), starting from zero, until no gradient moves in a sweep by
/// more than `tolerance` times the larger of 1 and its largest component (an absolute tolerance
/// for small gradients, a relative one for large; or `max_iterations` sweeps). Linear
/// values give their exact gradient (up to rounding). Plain floating point: no decision depends on
/// it. The same bits every time (one thread, a fixed order).
struct GradientOptions {
    double tolerance = 1e-6;
    unsigned max_iterations = 400;
};
struct DelaunayGradients {
    /// Per point, per column: d/dx, d/dy (point count x columns x 2). A repeated point gets its
    /// representative's; every gradient is 0 when the points span less than a plane.
    std::vector<double> gradients;
    unsigned iterations = 0;  ///< the most sweeps any column took
    bool converged = true;    ///< false when a column reached max_iterations first
    std::string error;
    bool ok() const { return error.empty(); }
};
/// `values`: point count x `columns`, row-major (the value of a repeated point is not used: its
/// representative's is). Fails (error set) when the triangulation is not of these points or a
/// value of a distinct point is not finite.
DelaunayGradients delaunay_gradients(PointSpan2 points, const Delaunay& triangulation, const double* values,
                                     std::size_t columns, const GradientOptions& options = {});

/// Voronoi cells clipped to the rectangle [xmin, xmax] x [ymin, ymax]: cell i is the polygon
/// cell_xy[2*cell_offsets[i]] ... (x y pairs) up to cell_offsets[i + 1], counter-clockwise with y
/// up; empty for duplicates and for points whose cell misses the rectangle. Each cell is the
/// rectangle clipped by the perpendicular bisectors to the point's Delaunay neighbours, so its
/// corners are the triangles' circumcentres where they lie inside the rectangle, and hull cells
/// (unbounded rays) end on the rectangle's sides. Coordinates are rounded (floating point);
/// collinear input gives slabs, one distinct point the whole rectangle.
struct VoronoiCells {
    std::vector<std::uint32_t> cell_offsets;  ///< point count + 1 entries
    std::vector<double> cell_xy;
};
VoronoiCells delaunay_voronoi(PointSpan2 points, const Delaunay& triangulation, double xmin,
                              double ymin, double xmax, double ymax);

/// The centre of the circle through a, b, c (x y each) into out[0], out[1]: from the differences to
/// a, scaled by a power of two to about 1 (no overflow or underflow in the squares of tiny or huge
/// triangles; a grid's centres come out exactly); rounded; inf or NaN when the points are collinear.
void circumcentre(const double* a, const double* b, const double* c, double* out);

/// The whole Voronoi diagram of a triangulation's points, unbounded cells included, in
/// scipy.spatial.Voronoi's layout (flat arrays). Which vertices, ridges and cells exist is decided
/// exactly: two triangles that share an edge belong to one Delaunay polygon when their four corners
/// are exactly cocircular (incircle), and each polygon is one Voronoi vertex, as Qhull merges them
/// (a square grid has one vertex per square). Numbering depends only on the input:
///  * vertex v is polygon number v, the polygons numbered in the order of their first triangle in
///    `triangulation` (Hilbert order, so nearby vertices are near each other); its coordinates are the
///    circumcentre (rounded) of the polygon's corners c0, c(m/3), c(2m/3), with c0 its lowest index
///    and the corners in the triangles' orientation (a triangle's own three corners);
///  * a ridge per Delaunay edge (between two polygons or on the hull), in the order of the
///    half-edges that carry them (the lower of the two; hull half-edges where they are);
///  * a cell per distinct point: its polygons' vertices counter-clockwise (y up), a bounded cell
///    from its lowest vertex, an unbounded one (a hull point's) from the ray after its hull edge
///    that comes in, with -1 (the vertex at infinity) last; the cells numbered in the order of
///    their points' walks (along the triangles, so nearby cells are near each other), each
///    point's cell in `point_cell` (a repeated point: its representative's). Collinear points: a
///    ridge between each two neighbours along the line, with no vertex ({-1, -1}), and each cell
///    {-1}; one distinct point: one cell {-1}.
/// `threads` as elsewhere (0: every hardware thread); the arrays are the same for every count.
/// Memory: the result takes about 140 bytes per point (two vertices, three ridges and a cell of six
/// or so vertices each), and making it about 50 more for a while.
struct VoronoiDiagram {
    std::vector<double> vertices;               ///< 2 per vertex: x, y
    std::vector<std::uint32_t> triangle_vertex; ///< per triangle of the triangulation: its polygon's vertex
    std::vector<std::int32_t> ridge_points;     ///< 2 per ridge: the Delaunay edge's ends, lower first
    std::vector<std::int32_t> ridge_vertices;   ///< 2 per ridge: the vertex across and the vertex, or -1, v for a ray
    std::vector<std::int32_t> cells;            ///< every cell's vertices, flat
    std::vector<std::int64_t> cell_offsets;     ///< cell count + 1: cell c is cells[cell_offsets[c] ..< cell_offsets[c + 1]]
    std::vector<std::uint32_t> cell_point;      ///< per cell: its point (a distinct one)
    std::vector<std::int32_t> point_cell;       ///< per input point: its cell (-1 only for no points)
    std::vector<double> areas;                  ///< per cell: its area if bounded, +inf if not
    std::string error;                          ///< empty on success
    bool ok() const { return error.empty(); }
};
VoronoiDiagram delaunay_voronoi_diagram(PointSpan2 points, const Delaunay& triangulation, unsigned threads = 0);

/// An exact check that `triangles` (triangle_count index triples) is a Delaunay triangulation of
/// the distinct points of `points`: indices in range, every triangle clockwise (y up) and not
/// degenerate, each undirected edge in at most two triangles with opposite directions, the
/// boundary one convex cycle that is the convex hull, every distinct point used, the triangle count
/// 2n - h - 2, and the exact empty-circle test on every interior edge.
struct DelaunayVerifyReport {
    bool ok = true;
    std::vector<std::string> problems;  ///< one line each, at most a few dozen, then a count
    std::size_t problem_count = 0;
    std::size_t distinct_points = 0;
    std::size_t hull_points = 0;
};
DelaunayVerifyReport verify_delaunay(PointSpan2 points, const std::uint32_t* triangles,
                                     std::size_t triangle_count);

}  // namespace hullkit
