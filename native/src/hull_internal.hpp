// Private helpers shared by the hull algorithms.
#pragma once

#include <cstdint>
#include <vector>

#include "hullkit/hull.hpp"

namespace hullkit::detail {

/// Checks what every algorithm requires of its input: at least 4 points, fewer than 2^32,
/// finite coordinates. Returns a failed Hull describing the first problem, or an ok() one.
Hull validate_input(PointSpan points);

/// Fills `vertices`, `volume` and `area` of a hull whose `triangles` are set.
void finish_hull(PointSpan points, Hull& hull);

/// A failed Hull carrying `message` (and the index of the point to blame, if any).
Hull failure(std::string message, std::int64_t point = -1);

/// Indices of the distinct points (exact coordinate equality), the lowest index of each group of
/// identical points, in ascending order.
std::vector<std::uint32_t> distinct_points(PointSpan points);

}  // namespace hullkit::detail
