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

Polygons merge_coplanar_triangles(PointSpan points, std::vector<std::uint32_t> triangles,
                                  const std::vector<CoplanarPair>& coplanar) {
    const std::size_t count = triangles.size() / 3;
    Polygons faces;
    faces.offsets.resize(count + 1);
    for (std::size_t t = 0; t <= count; ++t) faces.offsets[t] = static_cast<std::uint32_t>(3 * t);
    if (coplanar.empty()) {  // every triangle is a face of its own: the common case
        faces.vertices = std::move(triangles);
        return faces;
    }
    faces.offsets.assign(1, 0);
    faces.vertices.reserve(triangles.size());

    DisjointSets sets(count);
    for (const CoplanarPair& pair : coplanar) sets.unite(pair.first, pair.second);
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

void measure(PointSpan points, const Polygons& faces, double* volume, double* area) {
    // Tetrahedra from one corner to every fan triangle: faces through that corner add zero, and by
    // convexity no tetrahedron has a negative volume, so a rounded one below zero counts as zero.
    const glm::dvec3 origin = faces.vertices.empty() ? glm::dvec3(0.0) : vec3(points[faces.vertices.front()]);
    double six_volume = 0.0;
    double twice_area = 0.0;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const std::uint32_t* corners = &faces.vertices[faces.offsets[f]];
        const std::size_t m = faces.offsets[f + 1] - faces.offsets[f];
        const glm::dvec3 a = vec3(points[corners[0]]) - origin;
        for (std::size_t k = 1; k + 1 < m; ++k) {
            const glm::dvec3 b = vec3(points[corners[k]]) - origin;
            const glm::dvec3 c = vec3(points[corners[k + 1]]) - origin;
            six_volume += std::max(0.0, glm::dot(a, glm::cross(b, c)));
            twice_area += glm::length(glm::cross(b - a, c - a));
        }
    }
    *volume = six_volume / 6.0;
    *area = twice_area / 2.0;
}

}  // namespace hullkit::detail
