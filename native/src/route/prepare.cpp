// RouteChecker's scene preparation: the meshes' validation, their closedness and connected
// components, each part's hull (broad-phase axes; a convex closed part's hull triangles as its
// surface) and BVH, and the obstacles' triangles in one BVH.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "checker_internal.hpp"
#include "hullkit/hull.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit {

namespace {

struct Topology {
    bool closed = false;
    std::vector<Component> components;
};

Vec point_of(const TriangleMesh& m, std::uint32_t i) {
    return {m.xyz[3 * i], m.xyz[3 * i + 1], m.xyz[3 * i + 2]};
}

/// Closedness (every directed edge used once and its reverse once, vertices merged by exact
/// coordinates) and connected components of a validated mesh.
Topology analyze(const TriangleMesh& m) {
    // Merge points with identical coordinates: sort (x, y, z, index) records.
    const std::size_t n = m.xyz.size() / 3;
    struct Keyed {
        double x, y, z;
        std::uint32_t index;
    };
    std::vector<Keyed> keyed(n);
    for (std::size_t i = 0; i < n; ++i) {
        keyed[i] = {m.xyz[3 * i], m.xyz[3 * i + 1], m.xyz[3 * i + 2], static_cast<std::uint32_t>(i)};
    }
    std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
        return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
    });
    std::vector<std::uint32_t> id(n);
    for (std::size_t k = 0; k < n; ++k) {
        const bool same = k > 0 && keyed[k].x == keyed[k - 1].x && keyed[k].y == keyed[k - 1].y &&
                          keyed[k].z == keyed[k - 1].z;
        id[keyed[k].index] = same ? id[keyed[k - 1].index] : keyed[k].index;
    }
    // Directed edges bucketed by their first point (counting sort), so that "used once, and its
    // reverse once" is a scan of small buckets.
    const std::size_t t = m.triangles.size() / 3;
    std::vector<std::uint32_t> start(n + 1, 0), targets(3 * t);
    std::vector<std::uint32_t> parent(n);
    for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<std::uint32_t>(i);
    auto find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::size_t edge_count = 0;
    for (std::size_t f = 0; f < t; ++f) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t u = id[m.triangles[3 * f + k]];
            const std::uint32_t v = id[m.triangles[3 * f + (k + 1) % 3]];
            if (u != v) ++start[u + 1], ++edge_count;
            parent[find(u)] = find(v);
        }
    }
    for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < t; ++f) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t u = id[m.triangles[3 * f + k]];
            const std::uint32_t v = id[m.triangles[3 * f + (k + 1) % 3]];
            if (u != v) targets[fill[u]++] = v;
        }
    }
    auto count = [&](std::uint32_t u, std::uint32_t v) {
        int c = 0;
        for (std::uint32_t e = start[u]; e < start[u + 1]; ++e) c += targets[e] == v;
        return c;
    };
    Topology topo;
    topo.closed = edge_count > 0;
    for (std::uint32_t u = 0; u < n && topo.closed; ++u) {
        for (std::uint32_t e = start[u]; e < start[u + 1] && topo.closed; ++e) {
            const std::uint32_t v = targets[e];
            topo.closed = count(u, v) == 1 && count(v, u) == 1;
        }
    }
    std::vector<std::int64_t> component_of(n, -1);
    for (std::size_t f = 0; f < t; ++f) {
        const std::uint32_t root = find(id[m.triangles[3 * f]]);
        if (component_of[root] < 0) {
            component_of[root] = static_cast<std::int64_t>(topo.components.size());
            Component c;
            c.rep = point_of(m, m.triangles[3 * f]);
            c.triangle = static_cast<std::uint32_t>(f);
            topo.components.push_back(c);
        }
        Component& c = topo.components[component_of[root]];
        for (int k = 0; k < 3; ++k) c.box.add(point_of(m, m.triangles[3 * f + k]));
    }
    return topo;
}

std::string label(const char* kind, std::size_t index, const std::string& name) {
    std::string s = std::string(kind) + " " + std::to_string(index);
    if (!name.empty()) s += " ('" + name + "')";
    return s;
}

std::string validate_mesh(const TriangleMesh& m, const char* kind, std::size_t index) {
    const std::string who = label(kind, index, m.name);
    if (m.xyz.size() % 3 != 0) {
        return who + ": " + std::to_string(m.xyz.size()) + " coordinates are not whole points";
    }
    if (m.triangles.size() % 3 != 0) {
        return who + ": " + std::to_string(m.triangles.size()) +
               " triangle indices are not whole triangles";
    }
    for (std::size_t i = 0; i < m.xyz.size(); ++i) {
        const double x = m.xyz[i];
        if (!std::isfinite(x)) {
            return who + ": point " + std::to_string(i / 3) + " has a non-finite coordinate";
        }
        if (std::fabs(x) > kMaxCoordinate || (x != 0.0 && std::fabs(x) < kMinCoordinate)) {
            return who + ": point " + std::to_string(i / 3) +
                   " has a coordinate outside the supported range (0 or 2^-200..2^300 in "
                   "magnitude)";
        }
    }
    const std::size_t points = m.xyz.size() / 3;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        if (m.triangles[i] >= points) {
            return who + ": triangle " + std::to_string(i / 3) + " refers to point " +
                   std::to_string(m.triangles[i]) + ", but there are only " +
                   std::to_string(points) + " points";
        }
    }
    return {};
}

}  // namespace

void RouteChecker::Impl::build_part(const TriangleMesh& mesh, Part& part) const {
    const Topology topo = analyze(mesh);
    part.closed = topo.closed;
    part.components = topo.components;

    // The hull of the referenced points (unreferenced points are not part of the geometry).
    std::vector<char> used(mesh.xyz.size() / 3, 0);
    for (std::uint32_t i : mesh.triangles) used[i] = 1;
    std::vector<double> pts;
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (used[i]) pts.insert(pts.end(), &mesh.xyz[3 * i], &mesh.xyz[3 * i + 3]);
    }
    for (std::size_t i = 0; i < pts.size(); i += 3) part.box.add(Vec(pts[i], pts[i + 1], pts[i + 2]));
    HullOptions options;
    options.merge_coplanar = true;
    const Hull h = hull(PointSpan(pts), options);
    auto hp = [&](std::uint32_t i) { return Vec(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]); };
    for (std::uint32_t v : h.vertices) part.hull_points.push_back(hp(v));
    // Edges of the hull (of its polygon faces when it is a polytope) and the fixed axes: the
    // faces' normals and the coordinate axes.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    if (h.dimension == 3) {
        for (std::size_t f = 0; f + 1 < h.face_offsets.size(); ++f) {
            const std::uint32_t* v = &h.face_vertices[h.face_offsets[f]];
            const std::uint32_t count = h.face_offsets[f + 1] - h.face_offsets[f];
            for (std::uint32_t k = 0; k < count; ++k) {
                const std::uint32_t u = v[k], w = v[(k + 1) % count];
                if (u < w) edges.emplace_back(u, w);
            }
            const Vec n = glm::cross(hp(v[1]) - hp(v[0]), hp(v[2]) - hp(v[0]));
            part.axes.push_back(glm::normalize(n));
        }
    } else {
        for (std::size_t k = 0; k < h.vertices.size(); ++k) {
            for (std::size_t j = k + 1; j < h.vertices.size() && j < k + 2 + (h.dimension == 2); ++j) {
                edges.emplace_back(h.vertices[k], h.vertices[j]);
            }
        }
        if (h.dimension == 2 && h.vertices.size() > 2) {
            edges.emplace_back(h.vertices.back(), h.vertices.front());
            part.axes.push_back(Vec(h.normal[0], h.normal[1], h.normal[2]));
        }
    }
    for (const auto& e : edges) part.hull_edges.push_back(hp(e.second) - hp(e.first));
    // The separating axes of the hull's sweep (convex_sweep.hpp): before the coordinate axes join.
    part.face_normals = distinct_directions(part.axes);
    part.edge_directions = distinct_directions(part.hull_edges);
    part.axes.push_back(Vec(1, 0, 0));
    part.axes.push_back(Vec(0, 1, 0));
    part.axes.push_back(Vec(0, 0, 1));
    for (const Vec& n : part.axes) {
        const auto [lo, hi] = extent_along(n, part.hull_points);
        part.axis_lo.push_back(lo);
        part.axis_hi.push_back(hi);
    }

    // A closed part whose every triangle lies in a supporting plane of its hull (all with the same
    // orientation) and which does not cover the hull twice is its hull: its solid is the hull's,
    // so the hull's (usually far fewer) triangles stand for its surface.
    if (part.closed && h.dimension == 3) {
        int orientation = 0;
        bool convex = true;
        double area = 0.0;
        for (std::size_t f = 0; convex && f < mesh.triangles.size() / 3; ++f) {
            const Vec a = point_of(mesh, mesh.triangles[3 * f]);
            const Vec b = point_of(mesh, mesh.triangles[3 * f + 1]);
            const Vec c = point_of(mesh, mesh.triangles[3 * f + 2]);
            area += 0.5 * glm::length(glm::cross(b - a, c - a));
            for (const Vec& p : part.hull_points) {
                const int s = orient3d(ptr(a), ptr(b), ptr(c), ptr(p));
                if (s == 0) continue;
                if (orientation == 0) orientation = s;
                if (s != orientation) {
                    convex = false;
                    break;
                }
            }
        }
        if (convex && area <= 1.5 * h.area) {
            part.hull_surface = true;
            for (std::uint32_t v : h.triangles) part.tris.push_back(hp(v));
            Component c;
            c.rep = part.hull_points.front();
            c.box = part.box;
            part.components.assign(1, c);
        }
    }
    if (!part.hull_surface) {
        for (std::uint32_t v : mesh.triangles) part.tris.push_back(point_of(mesh, v));
    }
    part.bvh.build(part.tris);
    std::vector<Vec> ordered(part.tris.size());
    for (std::size_t s = 0; s < part.bvh.order.size(); ++s) {
        for (int k = 0; k < 3; ++k) ordered[3 * s + k] = part.tris[3 * part.bvh.order[s] + k];
    }
    part.tris.swap(ordered);
}

void RouteChecker::Impl::build() {
    if (scene.parts.empty()) {
        error = "the traverse has no parts";
        return;
    }
    if (!std::isfinite(scene.margin) || scene.margin < 0.0 || scene.margin > kMaxCoordinate) {
        error = "margin must be a finite number >= 0 (got " + std::to_string(scene.margin) + ")";
        return;
    }
    margin = scene.margin;
    for (int k = 0; k < 3; ++k) {
        const double c = scene.pivot[k];
        if (!std::isfinite(c) || std::fabs(c) > kMaxCoordinate || (c != 0.0 && std::fabs(c) < kMinCoordinate)) {
            error = "the traverse's pivot has a coordinate that is not finite or outside the supported range (0 or "
                    "2^-200..2^300 in magnitude)";
            return;
        }
    }
    pivot = Vec(scene.pivot[0], scene.pivot[1], scene.pivot[2]);
    for (std::size_t i = 0; i < scene.parts.size(); ++i) {
        error = validate_mesh(scene.parts[i], "part", i);
        if (!error.empty()) return;
        if (scene.parts[i].triangles.empty()) {
            error = label("part", i, scene.parts[i].name) + ": no triangles";
            return;
        }
    }
    for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
        error = validate_mesh(scene.obstacles[i], "obstacle", i);
        if (!error.empty()) return;
    }
    for (const auto* meshes : {&scene.parts, &scene.obstacles}) {
        for (const TriangleMesh& m : *meshes) {
            for (double x : m.xyz) scale = std::max(scale, std::fabs(x));
        }
    }

    parts.resize(scene.parts.size());
    for (std::size_t i = 0; i < parts.size(); ++i) {
        build_part(scene.parts[i], parts[i]);
        world.add(parts[i].box);
    }

    // Every obstacle triangle in one BVH; first[o] numbers obstacle o's triangles globally.
    std::vector<std::size_t> first(scene.obstacles.size() + 1, 0);
    for (std::size_t o = 0; o < scene.obstacles.size(); ++o) {
        const TriangleMesh& m = scene.obstacles[o];
        first[o + 1] = first[o] + m.triangles.size() / 3;
        Topology topo = analyze(m);
        obstacle_closed.push_back(topo.closed);
        Box box;
        for (Component& c : topo.components) {
            c.mesh = static_cast<std::uint32_t>(o);
            box.add(c.box);
            obstacle_components.push_back(c);
        }
        obstacle_box.push_back(box);
        world.add(box);
    }
    const std::size_t n = first.back();
    std::vector<std::uint32_t> owner(n);
    for (std::size_t o = 0; o < scene.obstacles.size(); ++o) {
        std::fill(owner.begin() + first[o], owner.begin() + first[o + 1], static_cast<std::uint32_t>(o));
    }
    auto corner = [&](std::size_t t, int k) {
        const TriangleMesh& m = scene.obstacles[owner[t]];
        return point_of(m, m.triangles[3 * (t - first[owner[t]]) + k]);
    };
    bvh.build(n, [&](std::size_t t) {
        Box b;
        for (int k = 0; k < 3; ++k) b.add(corner(t, k));
        return b;
    });
    tris.resize(3 * n);
    tri_obstacle.resize(n);
    tri_index.resize(n);
    for (std::size_t s = 0; s < n; ++s) {
        const std::uint32_t t = bvh.order[s];
        for (int k = 0; k < 3; ++k) tris[3 * s + k] = corner(t, k);
        tri_obstacle[s] = owner[t];
        tri_index[s] = static_cast<std::uint32_t>(t - first[owner[t]]);
    }
}

}  // namespace hullkit
