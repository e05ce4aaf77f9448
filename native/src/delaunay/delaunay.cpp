// hullkit::delaunay: input checks, exact duplicates, dimension, then one algorithm's Delaunay faces
// turned into delaunator-style output by one rule shared by every algorithm.
//
// The canonical rule (documented in delaunay.hpp and the README):
//  * every Delaunay face (a maximal set of cocircular points with an empty circle; a triangle for
//    points in general position) is fanned from its LOWEST index: corners v0 < others, in order
//    around the face, give triangles (v0, v_k, v_k+1). Corners of a face lie on one circle, so they
//    are in strictly convex position and no fan triangle has zero area;
//  * each triangle is written clockwise with y up (delaunator's orientation), starting at its
//    lowest index; triangles are sorted by (first, second) index;
//  * `hull` starts at its lowest index and follows the boundary half-edges' direction.
// The faces are unique, so every algorithm returns identical arrays.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "delaunay_internal.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit {
namespace {

using delaunay_detail::Faces;

Delaunay failure(std::string message, std::int64_t point = -1) {
    Delaunay d;
    d.error = std::move(message);
    d.error_point = point;
    return d;
}

/// Rejects non-finite coordinates and too many points; sets *exponent to the power of two that
/// brings the coordinates into incircle's exact range.
Delaunay check_input(PointSpan2 points, int* exponent) {
    if (points.count > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
        return failure("too many points: " + std::to_string(points.count) +
                       " (at most 2147483647 fit the 32-bit half-edge indices)");
    }
    double largest = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
    std::size_t largest_at = 0, smallest_at = 0;
    for (std::size_t i = 0; i < points.count; ++i) {
        for (int axis = 0; axis < 2; ++axis) {
            const double value = points[i][axis];
            const double magnitude = std::fabs(value);
            if (!(magnitude <= std::numeric_limits<double>::max())) {  // inf or nan
                const char* what = std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
                return failure("point " + std::to_string(i) + " has a non-finite " +
                                   (axis == 0 ? "x" : "y") + " coordinate (" + what + ")",
                               static_cast<std::int64_t>(i));
            }
            if (magnitude > largest) largest = magnitude, largest_at = i;
            if (magnitude != 0.0 && magnitude < smallest) smallest = magnitude, smallest_at = i;
        }
    }
    *exponent = 0;
    if (!incircle_range_ok(largest, smallest) &&
        !incircle_scale_exponent(largest, smallest, exponent)) {
        return failure("coordinates span too many orders of magnitude for exact in-circle tests: point " +
                           std::to_string(smallest_at) + " (smallest nonzero |coordinate|) and point " +
                           std::to_string(largest_at) +
                           " (largest) must be within a factor of 2^410 (about 1e123)",
                       static_cast<std::int64_t>(smallest_at));
    }
    return Delaunay{};
}

inline bool lex_less(PointSpan2 p, std::uint32_t a, std::uint32_t b) {
    const double* u = p[a];
    const double* v = p[b];
    return u[0] < v[0] || (u[0] == v[0] && (u[1] < v[1] || (u[1] == v[1] && a < b)));
}

/// Sorts the indices by (x, y, index), fills `representative` / `duplicate_count` and returns the
/// distinct points (the lowest index of each group), still sorted by (x, y).
std::vector<std::uint32_t> merge_duplicates(PointSpan2 p, Delaunay& out) {
    std::vector<std::uint32_t> order(p.count);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return lex_less(p, a, b); });
    out.representative.resize(p.count);
    std::vector<std::uint32_t> distinct;
    distinct.reserve(p.count);
    for (std::size_t k = 0; k < order.size(); ++k) {
        const std::uint32_t i = order[k];
        if (k > 0 && p[i][0] == p[distinct.back()][0] && p[i][1] == p[distinct.back()][1]) {
            out.representative[i] = distinct.back();  // lowest index comes first in the sort
            ++out.duplicate_count;
        } else {
            out.representative[i] = i;
            distinct.push_back(i);
        }
    }
    return distinct;
}

/// Triangles (clockwise, rotated, sorted as in the rule above) from counter-clockwise faces.
std::vector<std::uint32_t> canonical_triangles(std::size_t point_count, const Faces& faces) {
    std::size_t triangle_count = 0;
    for (std::size_t f = 0; f < faces.size(); ++f) triangle_count += faces.offsets[f + 1] - faces.offsets[f] - 2;
    // Counting sort by the first (lowest) index, then each small bucket by the second index.
    std::vector<std::uint32_t> start(point_count + 1, 0);
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const std::uint32_t* c = &faces.vertices[faces.offsets[f]];
        const std::size_t m = faces.offsets[f + 1] - faces.offsets[f];
        const std::uint32_t low = *std::min_element(c, c + m);
        start[low + 1] += static_cast<std::uint32_t>(m - 2);
    }
    for (std::size_t i = 0; i < point_count; ++i) start[i + 1] += start[i];
    std::vector<std::uint32_t> triangles(3 * triangle_count);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const std::uint32_t* c = &faces.vertices[faces.offsets[f]];
        const std::size_t m = faces.offsets[f + 1] - faces.offsets[f];
        const std::size_t low = static_cast<std::size_t>(std::min_element(c, c + m) - c);
        const std::uint32_t v0 = c[low];
        for (std::size_t k = 1; k + 1 < m; ++k) {
            // Counter-clockwise fan triangle (v0, c_k, c_k+1) written clockwise: (v0, c_k+1, c_k).
            const std::uint32_t t = fill[v0]++;
            triangles[3 * t] = v0;
            triangles[3 * t + 1] = c[(low + k + 1) % m];
            triangles[3 * t + 2] = c[(low + k) % m];
        }
    }
    for (std::size_t i = 0; i < point_count; ++i) {
        // Buckets hold about two triangles: insertion sort by the second index.
        for (std::uint32_t t = start[i] + 1; t < start[i + 1]; ++t) {
            const std::uint32_t b = triangles[3 * t + 1], c = triangles[3 * t + 2];
            std::uint32_t s = t;
            while (s > start[i] && triangles[3 * (s - 1) + 1] > b) {
                triangles[3 * s + 1] = triangles[3 * (s - 1) + 1];
                triangles[3 * s + 2] = triangles[3 * (s - 1) + 2];
                --s;
            }
            triangles[3 * s + 1] = b;
            triangles[3 * s + 2] = c;
        }
    }
    return triangles;
}

/// delaunator's half-edges for `triangles`: each half-edge is matched with its reverse, found among
/// the half-edges leaving its end vertex (grouped by start vertex with a counting sort).
std::vector<std::int32_t> match_halfedges(std::size_t point_count, const std::vector<std::uint32_t>& triangles) {
    const std::size_t edges = triangles.size();
    std::vector<std::uint32_t> start(point_count + 1, 0);
    for (std::size_t e = 0; e < edges; ++e) ++start[triangles[e] + 1];
    for (std::size_t i = 0; i < point_count; ++i) start[i + 1] += start[i];
    std::vector<std::uint32_t> by_start(edges);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t e = 0; e < edges; ++e) by_start[fill[triangles[e]]++] = static_cast<std::uint32_t>(e);
    auto next = [](std::size_t e) { return e % 3 == 2 ? e - 2 : e + 1; };
    std::vector<std::int32_t> halfedges(edges, -1);
    for (std::size_t e = 0; e < edges; ++e) {
        if (halfedges[e] != -1) continue;
        const std::uint32_t from = triangles[e], to = triangles[next(e)];
        for (std::uint32_t k = start[to]; k < start[to + 1]; ++k) {
            const std::uint32_t f = by_start[k];
            if (triangles[next(f)] == from) {
                halfedges[e] = static_cast<std::int32_t>(f);
                halfedges[f] = static_cast<std::int32_t>(e);
                break;
            }
        }
    }
    return halfedges;
}

/// The hull cycle: from the lowest hull index along the boundary half-edges.
std::vector<std::uint32_t> hull_cycle(std::size_t point_count, const std::vector<std::uint32_t>& triangles,
                                      const std::vector<std::int32_t>& halfedges) {
    std::vector<std::uint32_t> successor(point_count, std::numeric_limits<std::uint32_t>::max());
    std::uint32_t first = std::numeric_limits<std::uint32_t>::max();
    std::size_t count = 0;
    for (std::size_t e = 0; e < triangles.size(); ++e) {
        if (halfedges[e] != -1) continue;
        const std::uint32_t from = triangles[e];
        successor[from] = triangles[e % 3 == 2 ? e - 2 : e + 1];
        first = std::min(first, from);
        ++count;
    }
    std::vector<std::uint32_t> hull;
    hull.reserve(count);
    for (std::uint32_t v = first; hull.size() < count; v = successor[v]) hull.push_back(v);
    return hull;
}

/// merge_cocircular: the faces turned clockwise, each from its lowest index, sorted like triangles.
void fill_polygons(const Faces& faces, Delaunay& out) {
    std::vector<std::vector<std::uint32_t>> polygons(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const std::uint32_t* c = &faces.vertices[faces.offsets[f]];
        const std::size_t m = faces.offsets[f + 1] - faces.offsets[f];
        const std::size_t low = static_cast<std::size_t>(std::min_element(c, c + m) - c);
        auto& polygon = polygons[f];
        for (std::size_t k = 0; k < m; ++k) polygon.push_back(c[(low + m - k) % m]);
    }
    std::sort(polygons.begin(), polygons.end());
    out.polygon_offsets.assign(1, 0);
    for (const auto& polygon : polygons) {
        out.polygon_vertices.insert(out.polygon_vertices.end(), polygon.begin(), polygon.end());
        out.polygon_offsets.push_back(static_cast<std::uint32_t>(out.polygon_vertices.size()));
    }
}

}  // namespace

namespace delaunay_detail {

Faces merge_cocircular_triangles(PointSpan2 p, const std::vector<std::uint32_t>& triangles,
                                 const std::vector<std::int32_t>& twin) {
    const std::size_t count = triangles.size() / 3;
    // Union-find over triangles joined across edges with an exactly cocircular neighbour.
    std::vector<std::uint32_t> parent;
    auto find = [&](std::uint32_t t) {
        while (parent[t] != t) t = parent[t] = parent[parent[t]];
        return t;
    };
    for (std::size_t e = 0; e < triangles.size(); ++e) {
        const std::int32_t f = twin[e];
        if (f < 0 || static_cast<std::size_t>(f) < e) continue;
        const std::size_t t = e / 3;
        const std::uint32_t opposite = triangles[f % 3 == 0 ? f + 2 : f - 1];  // vertex of f's triangle off the edge
        const double* a = p[triangles[3 * t]];
        const double* b = p[triangles[3 * t + 1]];
        const double* c = p[triangles[3 * t + 2]];
        const double* d = p[opposite];
        if (incircle(a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]) != 0) continue;
        if (parent.empty()) {
            parent.resize(count);
            std::iota(parent.begin(), parent.end(), 0u);
        }
        const std::uint32_t r1 = find(static_cast<std::uint32_t>(t)), r2 = find(static_cast<std::uint32_t>(f / 3));
        if (r1 != r2) parent[std::max(r1, r2)] = std::min(r1, r2);
    }
    Faces faces;
    if (parent.empty()) {  // general position: every triangle is a face
        faces.vertices = triangles;
        faces.offsets.resize(count + 1);
        for (std::size_t t = 0; t <= count; ++t) faces.offsets[t] = static_cast<std::uint32_t>(3 * t);
        return faces;
    }
    // Group the triangles by root; walk each group's boundary (a convex cycle on one circle).
    std::vector<std::vector<std::uint32_t>> members(count);
    for (std::uint32_t t = 0; t < count; ++t) members[find(t)].push_back(t);
    std::vector<std::uint32_t> successor;
    for (std::uint32_t root = 0; root < count; ++root) {
        const auto& group = members[root];
        if (group.empty()) continue;
        if (group.size() == 1) {
            faces.vertices.insert(faces.vertices.end(), &triangles[3 * root], &triangles[3 * root + 3]);
            faces.offsets.push_back(static_cast<std::uint32_t>(faces.vertices.size()));
            continue;
        }
        std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary;
        for (std::uint32_t t : group) {
            for (int k = 0; k < 3; ++k) {
                const std::size_t e = 3 * t + k;
                const std::int32_t f = twin[e];
                if (f >= 0 && find(static_cast<std::uint32_t>(f / 3)) == root) continue;
                boundary.emplace_back(triangles[e], triangles[k == 2 ? e - 2 : e + 1]);
            }
        }
        std::sort(boundary.begin(), boundary.end());
        auto next_of = [&](std::uint32_t v) {
            return std::lower_bound(boundary.begin(), boundary.end(), std::make_pair(v, 0u))->second;
        };
        std::uint32_t v = boundary.front().first;
        for (std::size_t k = 0; k < boundary.size(); ++k, v = next_of(v)) faces.vertices.push_back(v);
        faces.offsets.push_back(static_cast<std::uint32_t>(faces.vertices.size()));
    }
    return faces;
}

}  // namespace delaunay_detail

Delaunay delaunay(PointSpan2 input, const DelaunayOptions& options) {
    int exponent = 0;
    Delaunay out = check_input(input, &exponent);
    if (!out.ok()) return out;
    std::vector<double> scaled;
    PointSpan2 points = input;
    if (exponent != 0) {
        scaled.resize(2 * input.count);
        for (std::size_t i = 0; i < scaled.size(); ++i) scaled[i] = std::ldexp(input.xy[i], exponent);
        points = PointSpan2(scaled.data(), input.count);
    }
    delaunay_detail::Input in;
    in.points = points;
    in.distinct = merge_duplicates(points, out);
    const auto& d = in.distinct;
    if (d.empty()) {
        out.dimension = -1;
        return out;
    }
    if (d.size() == 1) {
        out.dimension = 0;
        out.hull = d;
        return out;
    }
    std::size_t k = 2;
    while (k < d.size() && orient2d(points[d[0]][0], points[d[0]][1], points[d[1]][0], points[d[1]][1],
                                     points[d[k]][0], points[d[k]][1]) == 0)
        ++k;
    if (k == d.size()) {  // all collinear: the (x, y) order is the order along the line
        out.dimension = 1;
        out.hull = d;
        return out;
    }
    out.dimension = 2;
    const Faces faces = options.algorithm == DelaunayAlgorithm::Giftwrap ? delaunay_detail::giftwrap_faces(in)
                                                                         : delaunay_detail::incremental_faces(in);
    out.triangles = canonical_triangles(input.count, faces);
    out.halfedges = match_halfedges(input.count, out.triangles);
    out.hull = hull_cycle(input.count, out.triangles, out.halfedges);
    if (options.merge_cocircular) fill_polygons(faces, out);
    return out;
}

}  // namespace hullkit
