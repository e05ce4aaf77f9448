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
    Giftwrap,  ///< the seed document's 3D gift wrapping, one pass per hull edge: O(n*h)
};

/// How gift wrapping searches for the face across an edge.
enum class GiftwrapScan {
    SinglePass,  ///< when a point lies above the current candidate plane it becomes the candidate
    Restart,     ///< the seed's literal step 4: test every candidate against all points, O(n^2) per edge
};

struct HullOptions {
    Algorithm algorithm = Algorithm::Giftwrap;
    GiftwrapScan giftwrap_scan = GiftwrapScan::SinglePass;
};

/// The result of a hull computation. On failure `error` says what is wrong and, where one point
/// is to blame, `error_point` is its index; the other fields are then empty.
struct Hull {
    /// 3 indices per triangle into the input points, counter-clockwise seen from outside.
    std::vector<std::uint32_t> triangles;
    /// Indices of the input points that are hull vertices, ascending.
    std::vector<std::uint32_t> vertices;
    double volume = 0.0;  ///< enclosed volume
    double area = 0.0;    ///< surface area

    std::string error;               ///< empty on success
    std::int64_t error_point = -1;   ///< index of the offending point, -1 if none

    bool ok() const { return error.empty(); }
    std::size_t face_count() const { return triangles.size() / 3; }
};

/// Computes the convex hull of `points`.
/// Fails (Hull::ok() == false) on fewer than 4 points, a non-finite coordinate, more than 2^32-1
/// points, or a point set with no volume (all identical, collinear or coplanar).
Hull hull(PointSpan points, const HullOptions& options = {});

/// "giftwrap", ...
const char* algorithm_name(Algorithm algorithm);
/// Parses an algorithm name; returns false (and leaves *out alone) for an unknown name.
bool parse_algorithm(const std::string& name, Algorithm* out);

}  // namespace hullkit
