#include "convex_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace hullkit::route_detail {

std::vector<Vec> distinct_directions(const std::vector<Vec>& directions) {
    std::vector<Vec> out;
    for (const Vec& d : directions) {
        if (out.size() == kConvexAxes) break;
        const double len = glm::length(d);
        if (!(len > 0.0) || !std::isfinite(len)) continue;
        const Vec u = d / len;
        bool repeated = false;
        for (const Vec& v : out) repeated = repeated || std::fabs(glm::dot(u, v)) > 1.0 - 1e-9;
        if (!repeated) out.push_back(u);
    }
    return out;
}

void ConvexSweep::place(const std::vector<Vec>& hull_points, const std::vector<Vec>& normals,
                        const std::vector<Vec>& edges, const Pose* poses, int count, const Vec& pivot, double turned) {
    const std::size_t h = hull_points.size();
    points.resize(count * h);
    box = Box{};
    axes.clear();
    for (int i = 0; i < count; ++i) {
        const Pose& pose = poses[i];
        for (std::size_t k = 0; k < h; ++k) {
            points[i * h + k] = route_detail::place(pose, pivot, hull_points[k]);
            box.add(points[i * h + k]);
        }
        // The second pose's normals only when it has turned noticeably from the first.
        if (i == 0 || turned > 1e-3) {
            for (const Vec& n : normals) axes.push_back(pose.rotation.identity ? n : pose.rotation.apply(n));
        }
    }
    if (count == 2) {
        // The sides of the sweep: planes along the motion through an edge of the part.
        Vec moved(0.0);
        for (std::size_t k = 0; k < h; ++k) moved += points[h + k] - points[k];
        for (const Vec& e : edges) {
            const Vec n = glm::cross(moved, poses[0].rotation.identity ? e : poses[0].rotation.apply(e));
            const double len = glm::length(n);
            if (len > 0.0 && std::isfinite(len)) axes.push_back(n / len);
        }
    }
    lo.resize(axes.size());
    hi.resize(axes.size());
    for (std::size_t j = 0; j < axes.size(); ++j) std::tie(lo[j], hi[j]) = extent_along(axes[j], points);
}

double ConvexSweep::box_gap(const Box& b, double enough) const {
    double best = box.distance(b);
    if (best > enough) return best;
    const Vec c = (b.lo + b.hi) * 0.5, half = (b.hi - b.lo) * 0.5;
    for (std::size_t j = 0; j < axes.size(); ++j) {
        const double mid = glm::dot(axes[j], c), reach = glm::dot(glm::abs(axes[j]), half);
        best = std::max({best, lo[j] - (mid + reach), (mid - reach) - hi[j]});
        if (best > enough) return best;
    }
    return best;
}

double ConvexSweep::axes_gap(const Vec* q, double enough) const {
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < axes.size(); ++j) {
        const Vec& n = axes[j];
        const double q0 = glm::dot(n, q[0]), q1 = glm::dot(n, q[1]), q2 = glm::dot(n, q[2]);
        best = std::max({best, std::min({q0, q1, q2}) - hi[j], lo[j] - std::max({q0, q1, q2})});
        if (best > enough) return best;
    }
    return best;
}

double ConvexSweep::gap(const Vec* q, double enough, Vec* direction, bool known) const {
    double best = axes_gap(q, enough);
    if (best > enough) return best;
    best = std::max(best, points_gap_along(glm::cross(q[1] - q[0], q[2] - q[0]), points.data(), points.size(), q));
    if (best > enough) return best;
    if (known) {
        best = std::max(best, points_gap_along(*direction, points.data(), points.size(), q));
        if (best > enough) return best;
    }
    *direction = hull_closest_direction(points.data(), static_cast<int>(points.size()), q);
    return std::max(best, points_gap_along(*direction, points.data(), points.size(), q));
}

}  // namespace hullkit::route_detail
