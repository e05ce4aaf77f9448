// hullkit: convex hulls of 3D point sets.
//
// The one-shot entry point. Points come in as a flat array x0 y0 z0 x1 y1 z1 ...;
// the hull goes out as uint32 index triples into that array.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace hullkit {

/// A read-only view of `count` points stored as 3*count doubles: x0 y0 z0 x1 y1 z1 ...
/// The caller keeps the storage alive while the view is in use; nothing is copied.
struct PointSpan {
    const double* xyz = nullptr;
    std::size_t count = 0;

    PointSpan() = default;
    PointSpan(const double* xyz_, std::size_t count_) : xyz(xyz_), count(count_) {}
    /// View of a flat vector; a trailing partial point (size not a multiple of 3) is ignored,
    /// callers that accept user data check the size first (see the CLI and the JS layer).
    PointSpan(const std::vector<double>& flat) : xyz(flat.data()), count(flat.size() / 3) {}

    const double* operator[](std::size_t i) const { return xyz + 3 * i; }
};

enum class Algorithm {
    Quickhull,  ///< Barber, Dobkin & Huhdanpaa's quickhull on a flat half-edge structure (default)
    Giftwrap,   ///< the seed document's 3D gift wrapping, one pass per hull edge: O(n*h)
};

/// How side-of-plane and side-of-line questions are decided.
enum class SideTest {
    Exact,  ///< adaptive exact predicates (hullkit/predicates.hpp): every decision is exact (default)
    Seed,   ///< the seed document's epsilon, DBL_EPSILON times the taxicab extent of the cloud;
            ///< gift wrapping only, for comparison: near-degenerate input can then fail or be wrong
};

/// How gift wrapping searches for the face across an edge.
enum class GiftwrapScan {
    SinglePass,  ///< when a point lies above the current candidate plane it becomes the candidate
    Restart,     ///< the seed's literal step 4: test every candidate against all points, O(n^2) per edge
};

struct HullOptions {
    Algorithm algorithm = Algorithm::Quickhull;
    SideTest side_test = SideTest::Exact;
    GiftwrapScan giftwrap_scan = GiftwrapScan::SinglePass;
    /// Also report the faces as planar convex polygons (Hull::face_offsets / face_vertices):
    /// a cube gives 6 quads. The triangles are reported either way.
    bool merge_coplanar = false;
    /// Threads for quickhull: 0 (the default) uses every hardware thread once the input is large
    /// enough to gain from them (tens of thousands of points); 1 keeps all work on the calling
    /// thread. The result is the same bits for every value, because the answer depends only on
    /// the points (see Hull's canonical order): a cloud with few hull vertices whose interior
    /// culling keeps many points (a ball) is cut into chunks hulled on the threads, then the hull
    /// of the chunks' vertices is taken; a cloud mostly on its hull (a sphere) is split in halves
    /// hulled on their own threads and joined along the seam; otherwise one quickhull runs, its
    /// passes over all points split in blocks. Gift wrapping runs on the calling thread; so does
    /// the WebAssembly build, which has no threads.
    unsigned threads = 0;
};

/// The result of a hull computation. On failure `error` says what is wrong and, where one point
/// is to blame, `error_point` is its index; the other fields are then empty.
///
/// What the fields hold depends on `dimension`, the dimension of the points' affine hull:
///   3   a polytope: `triangles` cover its boundary, counter-clockwise seen from outside;
///       `vertices` are its extreme points, ascending.
///   2   a convex polygon: `vertices` are its corners in counter-clockwise order seen from the side
///       `normal` points to (the side where the normal's largest component, x before y before z
///       on ties, is positive);
///       `triangles` fan it in the same orientation; volume 0, area its area.
///   1   a segment: `vertices` are its two end points; no triangles.
///   0   a single point (possibly repeated): `vertices` holds it; no triangles.
///  -1   no points at all.
/// Among identical points the lowest index represents them all. A point strictly inside a face or
/// an edge is never a vertex, and no triangle has zero area.
///
/// Quickhull's results are in one canonical order that depends only on the points: each face
/// (polygon, before it is fanned into triangles) starts at its lowest index, and the faces are
/// sorted by their first two corners; volume and area are summed in that order. So the thread
/// count, and hulling a cloud whole or streamed in chunks (HullBuilder), give the same arrays
/// and the same volume and area bits. Gift wrapping reports its faces in the order it wraps them
/// (the order giftwrap_trace records).
struct Hull {
    int dimension = -1;
    /// 3 indices per triangle into the input points, counter-clockwise seen from outside.
    std::vector<std::uint32_t> triangles;
    /// Indices of the input points that are hull vertices (see above for their order).
    std::vector<std::uint32_t> vertices;
    /// With HullOptions::merge_coplanar: face f is the convex polygon
    /// face_vertices[face_offsets[f]] ... face_vertices[face_offsets[f + 1] - 1], counter-clockwise
    /// seen from outside, starting at its lowest index. Empty otherwise.
    std::vector<std::uint32_t> face_offsets;
    std::vector<std::uint32_t> face_vertices;
    /// dimension 2: unit normal of the polygon's plane (rounded); zero otherwise.
    double normal[3] = {0.0, 0.0, 0.0};
    double volume = 0.0;  ///< enclosed volume
    double area = 0.0;    ///< surface area (dimension 2: the polygon's area)

    std::string error;               ///< empty on success
    std::int64_t error_point = -1;   ///< index of the offending point, -1 if none

    bool ok() const { return error.empty(); }
    std::size_t face_count() const { return triangles.size() / 3; }
};

/// Computes the convex hull of `points`, exactly: every decision is made by exact predicates.
/// Coordinates far from unit scale are first multiplied by a power of two (exact).
/// Fails (Hull::ok() == false) only on a non-finite coordinate, more than 2^32-1 points, data whose
/// nonzero |coordinates| span more than 2^585 (no common power-of-two scale brings them into the
/// predicates' exact range, see predicates.hpp), or an option combination that does not exist.
Hull hull(PointSpan points, const HullOptions& options = {});

/// The plane of each of `triangle_count` triangles (3 indices each into `points`), 4 doubles per
/// triangle: nx ny nz offset, the unit normal on the side from which the triangle is seen
/// counter-clockwise and the offset with n . x + offset = 0 on the plane. For a hull's triangles the
/// normals point outwards and every point of the hull has n . x + offset <= 0: the facet equations
/// of qconvex's `n` and scipy's ConvexHull.equations (for a polygon, dimension 2, every triangle's
/// plane is the polygon's, on the side of Hull::normal). The triangles are exact, their planes are
/// rounded: each normal is within about 1e-14 of the exact unit normal (the exact cross product of
/// two edges, rounded once, for a nearly flat triangle), the offset within a few units in the last
/// place of the corners' coordinates. A triangle without area (never one of a hull) gets 0 0 0 0.
/// Throws std::invalid_argument for a corner out of range.
std::vector<double> plane_equations(PointSpan points, const std::uint32_t* triangles, std::size_t triangle_count);
/// plane_equations of hull.triangles.
std::vector<double> plane_equations(PointSpan points, const Hull& hull);

/// The hull of a cloud given in pieces (HullBuilder::finish). `hull` indexes `points`, the points
/// the builder kept (the hull's vertices and nothing else: points not on the hull are gone), and
/// `index` gives the caller's 64-bit index of each: the hull of the whole cloud has triangle
/// corners index[hull.triangles[k]], vertices index[hull.vertices[k]], and so on. These are the
/// same arrays, volume and area as hull() gives for the whole cloud where it fits in memory.
struct StreamedHull {
    Hull hull;
    std::vector<double> points;        ///< x y z of the kept points, in ascending `index`
    std::vector<std::uint64_t> index;  ///< the caller's index of each kept point
    std::uint64_t point_count = 0;     ///< points added in all

    bool ok() const { return hull.ok(); }
};

/// Streaming hull: add() the cloud in pieces of any size, in any order, then finish(). Holds only
/// the running hull's vertices between calls (plus, during add(), the candidates of the piece),
/// so clouds far larger than memory can be hulled one piece at a time; hulls compose, so the same
/// class merges the hulls of files hulled on other machines (add their vertices with their
/// indices). Quickhull with exact side tests only; HullOptions::threads applies to each add()
/// and to finish(). Indices must be distinct (a repeat among the kept points is an error).
class HullBuilder {
public:
    explicit HullBuilder(const HullOptions& options = {});

    /// Adds `points`, point i having the index first_index + i. Returns false, and finish()
    /// reports the error, on a non-finite coordinate ("point I has a non-finite x coordinate
    /// (nan)", I the global index), on magnitudes no power of two brings into the predicates'
    /// range, or once an earlier add() failed.
    bool add(PointSpan points, std::uint64_t first_index);
    /// Adds `points`, point i having the index indices[i] (e.g. hull vertices read back).
    bool add_indexed(PointSpan points, const std::uint64_t* indices);

    /// The hull of everything added so far (the builder can take more points afterwards).
    StreamedHull finish() const;

    std::uint64_t points_added() const { return added_; }
    /// How many points the builder holds now: the vertices of the hull so far.
    std::size_t points_kept() const { return ids_.size(); }
    const std::string& error() const { return error_; }

private:
    bool add_points(PointSpan points, std::uint64_t first_index, const std::uint64_t* indices);
    bool add_step(PointSpan points, std::uint64_t first_index, const std::uint64_t* indices, unsigned threads);

    HullOptions options_;
    std::vector<double> xyz_;           // the kept points, ascending global index
    std::vector<std::uint64_t> ids_;    // their global indices
    double largest_ = 0.0;              // magnitudes of every point added, kept or not
    double smallest_ = std::numeric_limits<double>::infinity();
    std::uint64_t added_ = 0;
    std::string error_;
    std::int64_t error_point_ = -1;
};

/// "quickhull", "giftwrap"
const char* algorithm_name(Algorithm algorithm);
/// Parses an algorithm name; returns false (and leaves *out alone) for an unknown name.
bool parse_algorithm(const std::string& name, Algorithm* out);

}  // namespace hullkit
