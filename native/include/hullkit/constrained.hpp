// hullkit: constrained Delaunay triangulation of planar straight-line graphs and of polygons with
// holes, exact.
//
// A constrained Delaunay triangulation (CDT) keeps given segments as edges and is otherwise as
// Delaunay as the segments allow: no triangle's circumcircle holds a point that is visible from the
// triangle's inside (visibility is blocked by segments). Built here in three steps, every decision
// an exact orient2d or incircle (predicates.hpp) on the coordinates scaled by one power of two as
// delaunay() scales them:
//  1. The points are triangulated as delaunay() does it (duplicates merged: the representative map;
//     Bowyer-Watson insertion in Hilbert order), its working mesh taken over as it is.
//  2. Each segment is inserted by walking from one end to the other over the triangles it crosses.
//     A point lying exactly on the segment splits it there (the pieces are inserted in turn). When
//     nothing blocks the way, the crossed triangles are removed and the two polygons either side are
//     re-triangulated by the recursive empty-circle rule for pseudo-polygons (Anglada, "An improved
//     incremental algorithm for constructing restricted Delaunay triangulations", Computers &
//     Graphics 21, 1997): the result is again a CDT.
//  3. A segment that crosses an earlier segment (self-intersecting rings, overlapping outlines):
//     the crossing point is computed exactly (rational, from the exact orientations) and rounded to
//     the nearest double in each coordinate (ties to even), and is inserted as a new point (a point
//     of a CDT inserted by Bowyer-Watson, whose cavity never crosses a segment). Both segments
//     become chains through it, and the pieces are inserted again, so a piece that now crosses
//     another segment is split the same way; this repeats until no piece crosses another (iterated
//     rounding of crossings; a simpler rule than Hobby's snap rounding, with the same aim: an exact
//     CDT of the rounded graph). A rounded point that lands exactly on another segment splits it;
//     one that lands on an existing point is that point. Every added point is within half a unit in
//     the last place (per coordinate) of an exact crossing of two pieces; where that coordinate is
//     subnormal (inputs near 1e-310), within one unit of the subnormal spacing: added points, like
//     the refinement's, are rounded to values the output holds exactly.
// The triangulation is therefore a valid, exact CDT of the rounded graph: no triangle has zero area,
// no segment is crossed, every edge that is not on a segment is locally Delaunay.
//
// Output in delaunator's form, like delaunay(): triangles clockwise with y up, `halfedges` with -1
// where no returned triangle is across, and per half-edge a flag saying it lies on a segment.
// The same input gives the same arrays every time, for any thread count (the steps are one fixed
// sequence on the calling thread).
//
// Memory: about 60 bytes per point (the working mesh: 2 triangles per point, a vertex, a twin and a
// segment index per half-edge) plus the output arrays; 10^6 points and 10^5 segments peak near
// 200 MB including the input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "hullkit/delaunay.hpp"

namespace hullkit {

/// Which points a set of rings encloses. Winding number w of a point: how many times the rings go
/// round it counter-clockwise (y up) minus clockwise.
enum class FillRule {
    EvenOdd,  ///< inside where w is odd: holes are holes whatever their orientation (earcut, SVG default)
    NonZero,  ///< inside where w is not 0: the rings' orientation matters (holes wound the other way)
};

/// Delaunay refinement of the triangulation's inside (the polygon's inside; for a graph, the convex
/// hull less the removed regions), as Triangle's -q, -a and -D switches ask for it (Ruppert;
/// Shewchuk, "Delaunay refinement algorithms for triangular mesh generation", 2002). Segments
/// encroached by a point (inside the circle with the segment as diameter) are split, at the middle
/// or, next to a segment's end, at a power-of-two distance from it (concentric shells, so that small
/// input angles do not cascade); a triangle with too small an angle or too large an area gets its
/// circumcentre, unless that would encroach a segment (then the segment is split instead). Every
/// edge of the region's boundary is kept as a segment. Points are computed in floating point and
/// every decision about the mesh is exact: the result is an exact constrained Delaunay triangulation
/// of its points (conforming: every triangle Delaunay). A point added on a segment is the nearest
/// double to the chosen point of the segment and may lie off its line by that rounding; the segment
/// is then the chain through it (the region's area changes by at most that rounding).
/// Triangles whose smallest angle is between two segments meeting at less than the bound, or lies
/// between two points on segments at the same distance (within 0.1%) from their common end
/// (Shewchuk's rule for small input angles), are left as they are and counted (unrefined_count).
/// So are triangles whose shortest edge is below 2^-40 of the points' extent or largest coordinate
/// (whichever is larger), and segments shorter than twice that are not split: features that small
/// (a point a few units in the last place from a segment) would otherwise ask for points at that
/// scale all along them, where rounding decides more than the geometry.
struct QualityOptions {
    /// Degrees, 0 to 34: refine until every angle is at least this (0: no angle bound). Up to 28.6
    /// termination is guaranteed (with exact arithmetic); above it refinement usually finishes, and
    /// unless max_steiner_points is set a cap of 16 points per input point plus 10^6 applies.
    double min_angle = 0;
    /// No triangle larger than this (in the input's units squared); 0: no area bound.
    double max_area = 0;
    /// Every triangle Delaunay, not only constrained Delaunay: segments are split until no point
    /// lies in the circle on any segment as diameter (Triangle's -D). Segments below the
    /// resolution (see above) stay whole; their triangles are counted in unrefined_count.
    bool conforming = false;
    /// Stop with an error once refinement has added this many points (0: no cap, see min_angle).
    std::size_t max_steiner_points = 0;
    /// Segments refinement leaves whole (no point is added on them), as Triangle's -Y and -YY:
    /// 0 none; 1 the boundary's (segments with the domain on one side only: a polygon's rings, a
    /// graph's outline and hole boundaries); 2 every segment. A point that would encroach such a
    /// segment is added anyway; where a triangle's circumcentre lies beyond one, a triangle above
    /// max_area gets its centroid instead and one with only a small angle is left (counted in
    /// unrefined_count). The angle bound is then not guaranteed near those segments, and
    /// termination is not either: unless max_steiner_points is set, the cap of min_angle > 28.6
    /// applies.
    unsigned keep_segments = 0;
    /// Triangle's -u (its triunsuitable()): also refine each triangle for which this returns true,
    /// given its corners (x y each, in the input's units, counter-clockwise with y up) and its area.
    /// It is called on the calling thread, for every triangle of the domain as it is made (so it
    /// must depend on the triangle alone), and refinement treats its triangles as too large (see
    /// keep_segments). Whether refinement ends is up to the function: unless max_steiner_points is
    /// set, the cap of min_angle > 28.6 applies. Empty: none.
    std::function<bool(const double* a, const double* b, const double* c, double area)> unsuitable;
    bool active() const { return min_angle > 0 || max_area > 0 || conforming || static_cast<bool>(unsuitable); }
};

/// A region of a planar straight-line graph (Triangle's .poly regions): the triangles reachable from
/// (x, y) without crossing a segment get the area bound max_area (0: only the global one); where a
/// global bound applies too, the smaller holds. A later seed in the same region wins.
struct RegionSeed {
    double x = 0, y = 0;
    double max_area = 0;
};

struct ConstrainedOptions {
    /// Accepted for symmetry with DelaunayOptions; every step runs on the calling thread (the
    /// result would be the same for any count).
    unsigned threads = 0;
    /// Stop with an error once this many points have been added at crossings (0: no overall cap).
    /// Independently, two input segments whose pieces have crossed 16 times are an error naming
    /// them: iterated rounding settles after one or two points per crossing pair on every input
    /// hullkit has met, and the guard turns a pathological one into an error instead of a long run.
    std::size_t max_added_points = 0;
    /// Triangle's .poly domain (its `-p` switch without `-c`): drop the exterior (the triangles
    /// reachable from the convex hull's edges that are not on a segment, without crossing one) and
    /// the region around each hole point (x y pairs; the triangles reachable from those holding it
    /// without crossing a segment: all around it on a corner, both on an edge; nothing outside the
    /// hull) before refining and returning. Every test is an exact orient2d.
    bool remove_exterior = false;
    std::vector<double> holes;
    std::vector<RegionSeed> regions;
    QualityOptions quality;
};

struct PolygonOptions {
    FillRule fill = FillRule::EvenOdd;
    unsigned threads = 0;
    std::size_t max_added_points = 0;  ///< as ConstrainedOptions::max_added_points
    QualityOptions quality;  ///< refinement of the inside
};

/// A constrained Delaunay triangulation. On failure `error` says what is wrong, naming the point
/// (`error_point`) or the segment (`error_segment`) where one is to blame, and the arrays are empty.
struct ConstrainedDelaunay {
    /// As Delaunay::dimension: 2 when the points span the plane; 1, 0, -1 for collinear, one, no
    /// distinct points (then there are no triangles; the segments lie on the line).
    int dimension = -1;
    /// The input points followed by the points added at crossings, x y each, in the input's units.
    /// Triangles index into this array.
    std::vector<double> coords;
    std::size_t input_count = 0;  ///< input points; coords holds input_count + added points
    std::vector<std::uint32_t> triangles;  ///< 3 indices per triangle, clockwise with y up
    std::vector<std::int32_t> halfedges;   ///< per half-edge: the opposite half-edge, -1 if none
    /// Per half-edge: 1 when it lies on a segment (a constraint, a ring edge, or a piece of one).
    std::vector<std::uint8_t> constrained;
    /// Per input point: itself, or the lowest index with exactly the same coordinates.
    std::vector<std::uint32_t> representative;
    std::size_t duplicate_count = 0;
    std::size_t crossing_count = 0;  ///< crossings of two segments resolved by adding or reusing a point
    std::size_t steiner_count = 0;   ///< points added by refinement (QualityOptions), after the crossings'
    /// Returned triangles that still miss the quality bounds (small input angles, see QualityOptions).
    std::size_t unrefined_count = 0;
    /// With ConstrainedOptions::regions: per triangle, the seed whose region holds it (the last of
    /// several seeds in one region), -1 where no seed's region does; triangles added by refinement
    /// are in the region of the triangle they split. Triangle's regional attributes (its -A switch)
    /// are the seeds' attributes looked up here. Empty without regions.
    std::vector<std::int32_t> triangle_region;

    std::string error;
    std::int64_t error_point = -1;
    std::int64_t error_segment = -1;
    std::int64_t error_triangle = -1;  ///< refine_mesh: the input triangle to blame, if one is

    bool ok() const { return error.empty(); }
    std::size_t triangle_count() const { return triangles.size() / 3; }
    std::size_t added_count() const { return coords.size() / 2 - input_count; }
};

/// The CDT of `points` and `segment_count` segments (index pairs, `segments[2k]`, `segments[2k+1]`)
/// covering the convex hull of the points. Segments between repeated points and repeated segments
/// are harmless (a segment given twice, either way round, is one segment counted twice); an index
/// past the points is an error naming the segment. Fails as delaunay() does on bad points.
ConstrainedDelaunay constrained_delaunay(PointSpan2 points, const std::uint32_t* segments, std::size_t segment_count,
                                         const ConstrainedOptions& options = {});

/// Triangulates the inside of polygons with holes given as rings, earcut's way: ring 0 is
/// points [0, ring_starts[0]), ring k is [ring_starts[k - 1], ring_starts[k]), the last runs to the
/// end (ring_starts are earcut's holeIndices; none means one ring). Rings may be given closed (last
/// point equal to the first) or open, in any orientation, order and nesting, may touch, overlap or
/// cross themselves and each other; the inside is decided by `fill`. Only the triangles inside are
/// returned; half-edges on the boundary of the inside have no opposite (-1) and are constrained.
/// ring_starts must be increasing and at most the point count (else an error naming the ring).
ConstrainedDelaunay triangulate_polygon(PointSpan2 points, const std::uint32_t* ring_starts, std::size_t ring_count,
                                        const PolygonOptions& options = {});

struct RefineMeshOptions {
    unsigned threads = 0;                ///< as ConstrainedOptions::threads
    std::size_t max_added_points = 0;    ///< as ConstrainedOptions::max_added_points (segments' crossings)
    /// Empty, or per triangle its own area bound (in the input's units squared; 0 or negative: only
    /// the global one, as in Triangle's .area files). When given, every edge of the triangulation is
    /// kept as a segment, so that each triangle's bound holds over exactly its area, and each output
    /// triangle's `triangle_region` is the input triangle it lies in.
    std::vector<double> triangle_max_area;
    QualityOptions quality;
};

/// Triangle's -r: refines a triangulation given as triangles (corner index triples into `points`,
/// either orientation), e.g. read from Triangle's .node and .ele files. The domain is the union of
/// the triangles: its boundary edges (those of one triangle only) and the optional `segments` (kept
/// edges inside, index pairs) become the segments of a constrained Delaunay triangulation of the
/// triangles' corners and the segments' ends, which `options.quality` then refines; points that no
/// triangle or segment uses are left out (they stay in `coords`, in no triangle). Without
/// triangle_max_area the inside is triangulated anew (constrained Delaunay) before refining, as
/// Triangle flips the edges of a mesh it refines. Errors name the triangle: no triangles, an index
/// past the points, a triangle with no area (exactly collinear corners), two triangles with an
/// edge on the same side (overlapping), a bad area; with triangle_max_area, a triangle that is not a
/// face of the mesh its edges make (a corner of another lying on its edge or inside it). Triangles
/// that overlap without sharing an edge are not detected: the domain is then the points covered an
/// odd number of times (even-odd), which is the triangles' union when they do not overlap.
ConstrainedDelaunay refine_mesh(PointSpan2 points, const std::uint32_t* triangles, std::size_t triangle_count,
                                const std::uint32_t* segments, std::size_t segment_count,
                                const RefineMeshOptions& options = {});

/// An exact check of a constrained triangulation, independent of how it was built: every triangle
/// clockwise with nonzero area (orient2d); no directed edge used twice; `halfedges` (when given,
/// may be null) pairing exactly the half-edges whose reverse is present; the flags symmetric; every
/// edge shared by two triangles that is not flagged passes the empty-circle test (incircle); with
/// `boundary_constrained` every unshared edge is flagged (the boundary of a polygon's inside);
/// otherwise the unshared edges must form the convex hull of the used points, winding once, with
/// T = 2n - h - 2 (a triangulation of the hull). Coordinates scaled by a power of two as
/// delaunay() does.
struct ConstrainedVerifyReport {
    bool ok = true;
    std::vector<std::string> problems;  ///< at most a few dozen, then counted
    std::size_t problem_count = 0;
};
ConstrainedVerifyReport verify_constrained(PointSpan2 coords, const std::uint32_t* triangles, std::size_t triangle_count,
                                           const std::int32_t* halfedges, const std::uint8_t* constrained,
                                           bool boundary_constrained);

const char* fill_rule_name(FillRule fill);
/// "evenodd" or "nonzero"; false (and *out left alone) for anything else.
bool parse_fill_rule(const std::string& name, FillRule* out);

}  // namespace hullkit
