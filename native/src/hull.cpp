#include "hullkit/hull.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/glm.hpp>

#include "hull_internal.hpp"
#include "hullkit/giftwrap.hpp"

namespace hullkit {

namespace detail {

Hull failure(std::string message, std::int64_t point) {
    Hull result;
    result.error = std::move(message);
    result.error_point = point;
    return result;
}

Hull validate_input(PointSpan points) {
    if (points.count > std::numeric_limits<std::uint32_t>::max()) {
        return failure("too many points: " + std::to_string(points.count) +
                       " (at most 4294967295 fit 32-bit indices)");
    }
    for (std::size_t i = 0; i < points.count; ++i) {
        const double* p = points[i];
        for (int axis = 0; axis < 3; ++axis) {
            if (!std::isfinite(p[axis])) {
                static const char* const kAxis[] = {"x", "y", "z"};
                const char* what = std::isnan(p[axis]) ? "nan" : (p[axis] > 0 ? "inf" : "-inf");
                return failure("point " + std::to_string(i) + " has a non-finite " + kAxis[axis] +
                                   " coordinate (" + what + ")",
                               static_cast<std::int64_t>(i));
            }
        }
    }
    if (points.count < 4) {
        return failure("a 3D hull needs at least 4 points, got " + std::to_string(points.count));
    }
    return Hull{};
}

std::vector<std::uint32_t> distinct_points(PointSpan points) {
    std::vector<std::uint32_t> order(points.count);
    std::iota(order.begin(), order.end(), 0u);
    auto less = [&](std::uint32_t a, std::uint32_t b) {
        const double* p = points[a];
        const double* q = points[b];
        if (p[0] != q[0]) return p[0] < q[0];
        if (p[1] != q[1]) return p[1] < q[1];
        if (p[2] != q[2]) return p[2] < q[2];
        return a < b;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<std::uint32_t> kept;
    kept.reserve(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        if (k > 0) {
            const double* p = points[order[k - 1]];
            const double* q = points[order[k]];
            if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) continue;  // same point, higher index
        }
        kept.push_back(order[k]);
    }
    std::sort(kept.begin(), kept.end());
    return kept;
}

void finish_hull(PointSpan points, Hull& hull) {
    hull.vertices.assign(hull.triangles.begin(), hull.triangles.end());
    std::sort(hull.vertices.begin(), hull.vertices.end());
    hull.vertices.erase(std::unique(hull.vertices.begin(), hull.vertices.end()), hull.vertices.end());

    auto at = [&](std::uint32_t i) { return glm::dvec3(points[i][0], points[i][1], points[i][2]); };
    // Tetrahedra from one hull vertex to every face: the reference point's own faces add zero.
    const glm::dvec3 origin = hull.vertices.empty() ? glm::dvec3(0.0) : at(hull.vertices.front());
    double six_volume = 0.0;
    double twice_area = 0.0;
    for (std::size_t t = 0; t + 2 < hull.triangles.size(); t += 3) {
        const glm::dvec3 a = at(hull.triangles[t]) - origin;
        const glm::dvec3 b = at(hull.triangles[t + 1]) - origin;
        const glm::dvec3 c = at(hull.triangles[t + 2]) - origin;
        six_volume += glm::dot(a, glm::cross(b, c));
        twice_area += glm::length(glm::cross(b - a, c - a));
    }
    hull.volume = six_volume / 6.0;
    hull.area = twice_area / 2.0;
}

}  // namespace detail

Hull hull(PointSpan points, const HullOptions& options) {
    switch (options.algorithm) {
        case Algorithm::Giftwrap:
            return giftwrap(points, options.giftwrap_scan);
    }
    return detail::failure("unknown algorithm");
}

const char* algorithm_name(Algorithm algorithm) {
    switch (algorithm) {
        case Algorithm::Giftwrap:
            return "giftwrap";
    }
    return "unknown";
}

bool parse_algorithm(const std::string& name, Algorithm* out) {
    if (name == "giftwrap") {
        *out = Algorithm::Giftwrap;
        return true;
    }
    return false;
}

}  // namespace hullkit
