// hullkit: convex hulls of 3D point sets.
//
// The one-shot entry point. Points come in as a flat array x0 y0 z0 x1 y1 z1 ...;
// the hull goes out as uint32 index triples into that array.
#pragma once

#include <cstddef>
#include <cstdint>
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

/// "quickhull", "giftwrap"
const char* algorithm_name(Algorithm algorithm);
/// Parses an algorithm name; returns false (and leaves *out alone) for an unknown name.
bool parse_algorithm(const std::string& name, Algorithm* out);

}  // namespace hullkit
