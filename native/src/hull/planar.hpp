// The convex polygon of coplanar points, shared by gift wrapping (its faces), the 2D result of
// coplanar input, and the merging of coplanar triangles.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "hullkit/hull.hpp"
#include "sides.hpp"

namespace hullkit::detail {

/// Chooses the axis-aligned projection for the plane of a, b, c: fills the kept axes (i, j) and
/// returns the orientation of a, b, c in them (+1: counter-clockwise in (i, j) means
/// counter-clockwise seen from where (b-a) x (c-a) points; -1: the reverse; 0: a, b, c collinear).
template <class Sides>
int plane_projection(const Sides& sides, const double* a, const double* b, const double* c, int* i, int* j) {
    // Drop the axis along which the normal is largest (rounded); the exact test confirms it.
    const glm::dvec3 normal = glm::abs(glm::cross(vec3(b) - vec3(a), vec3(c) - vec3(a)));
    int order[3] = {0, 1, 2};
    std::stable_sort(order, order + 3, [&](int p, int q) { return normal[p] > normal[q]; });  // ties: x, y, z
    for (int dropped : order) {
        *i = (dropped + 1) % 3;
        *j = (dropped + 2) % 3;
        if (int orientation = sides.orient_in_plane(a, b, c, *i, *j); orientation != 0) return orientation;
    }
    return 0;
}

/// The corners of the convex polygon of the coplanar points `members` (indices into `points`),
/// counter-clockwise seen from where (b-a) x (c-a) points, a, b, c being three non-collinear
/// points of the plane. Points on the polygon's edges or inside it are left out; of identical
/// points the lowest index is kept. Returns false when a, b, c are collinear or fewer than three
/// corners remain (possible only with inexact sides).
template <class Sides>
bool convex_polygon(PointSpan points, const Sides& sides, std::vector<std::uint32_t> members, std::uint32_t a,
                    std::uint32_t b, std::uint32_t c, std::vector<std::uint32_t>& polygon) {
    int i = 0, j = 0;
    const int orientation = plane_projection(sides, points[a], points[b], points[c], &i, &j);
    polygon.clear();
    if (orientation == 0) return false;

    auto at = [&](std::uint32_t p) { return points[p]; };
    std::sort(members.begin(), members.end(), [&](std::uint32_t p, std::uint32_t q) {
        if (at(p)[i] != at(q)[i]) return at(p)[i] < at(q)[i];
        if (at(p)[j] != at(q)[j]) return at(p)[j] < at(q)[j];
        return p < q;
    });
    // Coplanar points with the same projection are the same point: keep the lowest index.
    members.erase(std::unique(members.begin(), members.end(),
                              [&](std::uint32_t p, std::uint32_t q) { return at(p)[i] == at(q)[i] && at(p)[j] == at(q)[j]; }),
                  members.end());
    // Andrew's monotone chain with strict turns only.
    auto chain = [&](auto first, auto last) {
        const std::size_t floor = polygon.size();
        for (auto it = first; it != last; ++it) {
            while (polygon.size() >= floor + 2 &&
                   sides.orient_in_plane(at(polygon[polygon.size() - 2]), at(polygon.back()), at(*it), i, j) <= 0)
                polygon.pop_back();
            polygon.push_back(*it);
        }
        polygon.pop_back();  // the chain's last point starts the other chain
    };
    chain(members.begin(), members.end());
    chain(members.rbegin(), members.rend());
    if (polygon.size() < 3) return false;
    if (orientation < 0) std::reverse(polygon.begin(), polygon.end());
    return true;
}

}  // namespace hullkit::detail
