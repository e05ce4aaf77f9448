// hullkit::verify, the shared machinery: VerifyReport::lines, the preparation of the input (finite
// coordinates, exact power-of-two scaling into the predicates' range) and the check that the lowest
// index represents identical points.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hullkit/predicates.hpp"
#include "hullkit/verify.hpp"
#include "verify_internal.hpp"

namespace hullkit {

std::vector<std::string> VerifyReport::lines() const {
    std::vector<std::string> out = problems;
    if (problem_count > problems.size()) {
        out.push_back("... and " + std::to_string(problem_count - problems.size()) + " more problems (" +
                      std::to_string(problem_count) + " in all)");
    }
    return out;
}

namespace verify_detail {

bool prepare(PointSpan input, Problems& out, Prepared& prepared) {
    prepared.points = input;
    prepared.original = input;
    if (input.count > std::numeric_limits<Index>::max()) {
        out.add("too many points: " + num(input.count) + " (32-bit indices reach 4294967295 points)");
        return false;
    }
    double largest = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
    bool finite = true;
    for (std::size_t i = 0; i < input.count; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            const double value = input[i][axis];
            if (!std::isfinite(value)) {
                static const char* const kAxis[] = {"x", "y", "z"};
                out.add("point " + num(i) + " has a non-finite " + kAxis[axis] + " coordinate");
                finite = false;
                break;
            }
            const double magnitude = std::fabs(value);
            largest = std::max(largest, magnitude);
            if (magnitude != 0.0) smallest = std::min(smallest, magnitude);
        }
    }
    if (!finite) return false;
    int exponent = 0;
    if (!predicates_range_ok(largest, smallest) && !predicates_scale_exponent(largest, smallest, &exponent)) {
        out.add("the nonzero |coordinates| span more than a factor of 2^585: no common power-of-two scale "
                "brings them into the exact predicates' range");
        return false;
    }
    if (exponent != 0) {
        prepared.storage.resize(3 * input.count);
        for (std::size_t i = 0; i < prepared.storage.size(); ++i)
            prepared.storage[i] = std::ldexp(input.xyz[i], exponent);
        prepared.points = PointSpan(prepared.storage.data(), input.count);
    }
    return true;
}

// ---- identical points ----

void check_representatives(PointSpan points, PointSpan original, const std::vector<Index>& vertices,
                           Problems& out) {
    std::unordered_map<PointKey, Index, PointKeyHash> by_point;
    by_point.reserve(vertices.size() * 2 + 1);
    for (Index v : vertices) {
        auto [it, inserted] = by_point.emplace(key_of(points[v]), v);
        if (!inserted && it->second != v) {
            out.add("vertices " + num(std::min(it->second, v)) + " and " + num(std::max(it->second, v)) +
                    " are the same point " + coordinates(original[v]));
        }
    }
    for (std::size_t i = 0; i < points.count && !by_point.empty(); ++i) {
        auto it = by_point.find(key_of(points[i]));
        if (it == by_point.end()) continue;
        if (it->second > i) {
            out.add("vertex " + num(it->second) + " repeats point " + num(i) + " " + coordinates(original[i]) +
                    ": the lowest index must represent identical points");
        }
        by_point.erase(it);  // each vertex is judged by the first point equal to it
    }
}

}  // namespace verify_detail
}  // namespace hullkit
