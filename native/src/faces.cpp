// Planar faces from the triangles of a convex surface.
#include <algorithm>
#include <numeric>

#include "hull_internal.hpp"
#include "hullkit/predicates.hpp"
#include "planar.hpp"
#include "sides.hpp"

namespace hullkit::detail {
namespace {

class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
    std::uint32_t find(std::uint32_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }

private:
    std::vector<std::uint32_t> parent_;
};

}  // namespace

Polygons merge_coplanar_triangles(PointSpan points, const std::vector<std::uint32_t>& triangles,
                                  const std::vector<std::uint32_t>& twins) {
    const std::size_t count = triangles.size() / 3;
    auto corner = [&](std::size_t t, std::size_t k) { return points[triangles[3 * t + k]]; };

    // Pairs of edge-adjacent triangles whose planes coincide exactly.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> coplanar;
    for (std::size_t t = 0; t < count; ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t opposite = twins[3 * t + k];
            const std::uint32_t u = opposite / 3;
            if (u <= t) continue;  // each pair once
            const double* apex = corner(u, (opposite % 3 + 2) % 3);  // u's corner off the shared edge
            if (orient3d(corner(t, 0), corner(t, 1), corner(t, 2), apex) == 0)
                coplanar.emplace_back(static_cast<std::uint32_t>(t), u);
        }
    }

    Polygons faces;
    faces.vertices.reserve(triangles.size());
    faces.offsets.reserve(count + 1);
    if (coplanar.empty()) {  // every triangle is a face of its own: the common case
        for (std::size_t t = 0; t < count; ++t) faces.add(&triangles[3 * t], &triangles[3 * t] + 3);
        return faces;
    }

    DisjointSets sets(count);
    for (const auto& [t, u] : coplanar) sets.unite(t, u);
    // Triangles grouped by face (the group's lowest triangle index names it), in triangle order.
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    std::vector<std::uint32_t> root(count);
    for (std::uint32_t t = 0; t < count; ++t) root[t] = sets.find(t);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return root[a] < root[b]; });

    const ExactSides sides;
    std::vector<std::uint32_t> members, polygon;
    for (std::size_t begin = 0; begin < count;) {
        std::size_t end = begin + 1;
        while (end < count && root[order[end]] == root[order[begin]]) ++end;
        const std::uint32_t first = order[begin];
        if (end - begin == 1) {
            faces.add(&triangles[3 * first], &triangles[3 * first] + 3);
        } else {
            members.clear();
            for (std::size_t g = begin; g < end; ++g)
                members.insert(members.end(), &triangles[3 * order[g]], &triangles[3 * order[g]] + 3);
            std::sort(members.begin(), members.end());
            members.erase(std::unique(members.begin(), members.end()), members.end());
            const std::uint32_t* abc = &triangles[3 * first];
            convex_polygon(points, sides, members, abc[0], abc[1], abc[2], polygon);
            faces.add(polygon.begin(), polygon.end());
        }
        begin = end;
    }
    return faces;
}

}  // namespace hullkit::detail
