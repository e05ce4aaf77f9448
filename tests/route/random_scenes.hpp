// The route oracle's random scenes (tests/route/oracle.cpp), shared with tests/route/threads.cpp:
// convex blobs (hulls of 8 random points), closed star-shaped prisms (non-convex) and triangle
// soups, as traverse parts and obstacles, with a route of 3 random waypoints.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "hullkit/hull.hpp"
#include "hullkit/route.hpp"

namespace route_test {

using D3 = std::array<double, 3>;

/// The oracle's seed.
constexpr std::uint64_t kRandomSceneSeed = 20261129;

struct Mesh {
    std::vector<D3> points;
    std::vector<std::array<std::uint32_t, 3>> tris;
    bool closed = false;
};

/// The same mesh as hullkit sees it, named `name`.
inline hullkit::TriangleMesh to_mesh(const Mesh& m, const char* name) {
    hullkit::TriangleMesh t;
    t.name = name;
    for (const D3& p : m.points) t.xyz.insert(t.xyz.end(), p.begin(), p.end());
    for (const auto& f : m.tris) t.triangles.insert(t.triangles.end(), f.begin(), f.end());
    return t;
}

/// The hull of 8 random points within `size` of `center` (closed and convex).
inline Mesh convex_blob(std::mt19937_64& rng, const D3& center, double size) {
    std::uniform_real_distribution<double> u(-size, size);
    for (;;) {
        std::vector<double> xyz;
        for (int i = 0; i < 8; ++i) {
            for (int k = 0; k < 3; ++k) xyz.push_back(center[k] + u(rng));
        }
        const hullkit::Hull h = hullkit::hull(hullkit::PointSpan(xyz));
        if (h.dimension != 3) continue;
        Mesh m;
        m.closed = true;
        for (std::size_t i = 0; i < xyz.size(); i += 3) m.points.push_back({xyz[i], xyz[i + 1], xyz[i + 2]});
        for (std::size_t f = 0; f < h.triangles.size(); f += 3) {
            m.tris.push_back({h.triangles[f], h.triangles[f + 1], h.triangles[f + 2]});
        }
        return m;
    }
}

/// A closed prism over a star-shaped polygon around `center` (non-convex in general), caps fanned
/// from their centres.
inline Mesh star_prism(std::mt19937_64& rng, const D3& center, double size) {
    std::uniform_real_distribution<double> r(0.3 * size, size);
    const std::uint32_t n = 5 + static_cast<std::uint32_t>(rng() % 3);
    Mesh m;
    m.closed = true;
    const double h = r(rng);
    for (double z : {-h, h}) {
        for (std::uint32_t i = 0; i < n; ++i) {
            const double angle = 2 * M_PI * (i + 0.3 * std::uniform_real_distribution<double>(0, 1)(rng)) / n;
            const double radius = r(rng);
            m.points.push_back({center[0] + radius * std::cos(angle),
                                center[1] + radius * std::sin(angle), center[2] + z});
        }
    }
    m.points.push_back({center[0], center[1], center[2] - h});
    m.points.push_back({center[0], center[1], center[2] + h});
    const std::uint32_t cb = 2 * n, ct = 2 * n + 1;
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t j = (i + 1) % n;
        m.tris.push_back({cb, j, i});
        m.tris.push_back({ct, n + i, n + j});
        m.tris.push_back({i, j, n + j});
        m.tris.push_back({i, n + j, n + i});
    }
    return m;
}

/// `count` random triangles within `size` of `center` (an open soup: no inside).
inline Mesh soup(std::mt19937_64& rng, const D3& center, double size, int count) {
    std::uniform_real_distribution<double> u(-size, size);
    Mesh m;
    for (int t = 0; t < count; ++t) {
        for (int k = 0; k < 3; ++k) m.points.push_back({center[0] + u(rng), center[1] + u(rng), center[2] + u(rng)});
        const auto b = static_cast<std::uint32_t>(3 * t);
        m.tris.push_back({b, b + 1, b + 2});
    }
    return m;
}

/// One of the three kinds above, picked by `rng`.
inline Mesh random_mesh(std::mt19937_64& rng, const D3& center, double size) {
    switch (rng() % 3) {
        case 0: return convex_blob(rng, center, size);
        case 1: return star_prism(rng, center, size);
        default: return soup(rng, center, size, 1 + static_cast<int>(rng() % 3));
    }
}

struct RandomScene {
    std::vector<Mesh> parts, obstacles;
    std::vector<D3> waypoints;
    hullkit::Scene scene;  ///< the same parts, obstacles and waypoints; margin 0 for odd indices
};

/// The next random scene from `rng`: 1 or 2 parts (0.8 apart along x), 2 to 4 obstacles around the
/// origin, 3 waypoints in [-2, 2]^3 and, for an even `scene_index`, a margin up to 0.09.
inline RandomScene random_scene(std::mt19937_64& rng, int scene_index) {
    std::uniform_real_distribution<double> place(-2.0, 2.0), size(0.3, 0.9);
    RandomScene r;
    const int part_count = 1 + static_cast<int>(rng() % 2);
    for (int i = 0; i < part_count; ++i) {
        r.parts.push_back(random_mesh(rng, {0.8 * i, 0, 0}, size(rng) * 0.6));
    }
    const int obstacle_count = 2 + static_cast<int>(rng() % 3);
    for (int i = 0; i < obstacle_count; ++i) {
        r.obstacles.push_back(random_mesh(rng, {0.7 * place(rng), 0.7 * place(rng), 0.7 * place(rng)}, size(rng)));
    }
    for (const Mesh& m : r.parts) r.scene.parts.push_back(to_mesh(m, "part"));
    for (const Mesh& m : r.obstacles) r.scene.obstacles.push_back(to_mesh(m, "obstacle"));
    for (int i = 0; i < 3; ++i) {
        r.waypoints.push_back({place(rng), place(rng), place(rng)});
        r.scene.route.insert(r.scene.route.end(), r.waypoints.back().begin(), r.waypoints.back().end());
    }
    r.scene.margin = scene_index % 2 ? 0.0 : 0.1 * size(rng);
    return r;
}

}  // namespace route_test
