// Private to native/src/delaunay: what the algorithms share with the driver in delaunay.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "hullkit/delaunay.hpp"

namespace hullkit {
namespace delaunay_detail {

/// Convex polygons given as index cycles, COUNTER-clockwise with y up (the algorithms' internal
/// orientation; the driver turns them round for the output).
struct Faces {
    std::vector<std::uint32_t> offsets{0};
    std::vector<std::uint32_t> vertices;
    std::size_t size() const { return offsets.size() - 1; }
};

/// The input of an algorithm: `points` already in the predicates' exact range, and the distinct
/// points (lowest index of each set of exact duplicates) sorted by (x, y), at least 3 of them and
/// not all collinear.
struct Input {
    PointSpan2 points;
    std::vector<std::uint32_t> distinct;
};

/// Both algorithms return the Delaunay faces: the lower faces of the lifted hull, each a maximal set
/// of cocircular points whose circle is empty, as a counter-clockwise cycle.
Faces incremental_faces(const Input& input);
Faces giftwrap_faces(const Input& input);

/// Merges a Delaunay triangulation (counter-clockwise triangles, `twin[e]` the opposite half-edge or
/// -1) into its Delaunay faces: triangles joined across every edge whose in-circle test is exactly 0.
Faces merge_cocircular_triangles(PointSpan2 points, const std::vector<std::uint32_t>& triangles,
                                 const std::vector<std::int32_t>& twin);

}  // namespace delaunay_detail
}  // namespace hullkit
