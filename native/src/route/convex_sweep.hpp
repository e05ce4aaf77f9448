// Private to the route module: a traverse part's hull placed at one pose, or at the two end
// poses of a sub-interval of a turning leg, as the hull's points there and a few separating axes
// with the points' extents along them. For a convex part (Part::hull_surface) the hull is its
// solid; for any other part it holds the part, so the bounds below hold for it too.
//
// Over a sub-interval every point of the part stays within delta (motion.hpp) of the convex
// hull of its hull's points at the two end poses: the part's "sweep". The sweep's distance from an
// obstacle box or triangle is bounded from below by the gap along any direction; the directions
// tried are the part's face normals turned to each pose, the sides of the sweep (the motion
// crossed with the part's edge directions), the triangle's normal, and the direction between
// closest points (GJK). Every gap is floating point: callers compare it with bounds that carry the
// route checker's tolerance, and never decide a contact with it.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "bvh.hpp"
#include "motion.hpp"

namespace hullkit::route_detail {

/// The interval {lo, hi} the points a[0..count) cover along n (lo = inf, hi = -inf without
/// points).
inline std::pair<double, double> extent_along(const Vec& n, const Vec* a, std::size_t count) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t k = 0; k < count; ++k) {
        lo = std::min(lo, glm::dot(n, a[k]));
        hi = std::max(hi, glm::dot(n, a[k]));
    }
    return {lo, hi};
}

inline std::pair<double, double> extent_along(const Vec& n, const std::vector<Vec>& points) {
    return extent_along(n, points.data(), points.size());
}

/// The gap along direction n between the points a[0..count) and triangle q: their distance along
/// the unit direction, negative when they overlap along it, -inf for a zero or non-finite n.
inline double points_gap_along(const Vec& n, const Vec* a, std::size_t count, const Vec* q) {
    const double len = glm::length(n);
    if (!(len > 0.0) || !std::isfinite(len)) return -std::numeric_limits<double>::infinity();
    const auto [lo, hi] = extent_along(n, a, count);
    const auto [qlo, qhi] = extent_along(n, q, 3);
    return std::max(qlo - hi, lo - qhi) / len;
}

/// At most this many face normals and edge directions of a part's hull serve as axes.
constexpr std::size_t kConvexAxes = 8;

/// The unit directions of `directions` (part coordinates) one per line through the origin, at most
/// kConvexAxes of them: a hull's face normals or edge directions for its axes.
std::vector<Vec> distinct_directions(const std::vector<Vec>& directions);

struct ConvexSweep {
    std::vector<Vec> points;  ///< the hull's points at each pose, pose by pose
    std::vector<Vec> axes;    ///< unit separating axes
    std::vector<double> lo, hi;  ///< the points' extent along each axis
    Box box;                  ///< of the points

    /// The hull points placed at poses[0..count) (count 1 or 2) about `pivot`; `normals` and
    /// `edges` are the part's face normals and edge directions (distinct_directions); `turned`,
    /// the angle between two poses (the second pose's normals are left out below 1e-3 radians:
    /// fewer axes only make the bounds weaker).
    void place(const std::vector<Vec>& hull_points, const std::vector<Vec>& normals, const std::vector<Vec>& edges,
               const Pose* poses, int count, const Vec& pivot, double turned = 0.0);
    /// A lower bound of the distance between the sweep and `b`: the boxes' distance and the gaps
    /// along the axes; stops once above `enough`.
    double box_gap(const Box& b, double enough) const;
    /// The largest gap between the sweep and triangle q along the axes; stops once above `enough`.
    double axes_gap(const Vec* q, double enough) const;
    /// The largest gap between the sweep and triangle q found along the axes, q's normal,
    /// *direction (when `known`) and the closest-points direction (then written to *direction);
    /// stops once above `enough`.
    double gap(const Vec* q, double enough, Vec* direction, bool known) const;
};

}  // namespace hullkit::route_detail
