// Scene builders shared by the route tests.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hullkit/route.hpp"

namespace route_test {

/// A closed axis-aligned box, 12 triangles, counter-clockwise seen from outside.
inline hullkit::TriangleMesh box_mesh(const std::string& name, double x0, double y0, double z0,
                                      double x1, double y1, double z1) {
    hullkit::TriangleMesh m;
    m.name = name;
    for (int i = 0; i < 8; ++i) {
        m.xyz.push_back(i & 1 ? x1 : x0);
        m.xyz.push_back(i & 2 ? y1 : y0);
        m.xyz.push_back(i & 4 ? z1 : z0);
    }
    // Faces as quads (outward), split into two triangles each.
    const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        m.triangles.insert(m.triangles.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    }
    return m;
}

/// A zero-thickness square plate in the plane x = x0: y, z in [lo, hi]; two triangles.
inline hullkit::TriangleMesh plate_x(const std::string& name, double x0, double lo, double hi) {
    hullkit::TriangleMesh m;
    m.name = name;
    m.xyz = {x0, lo, lo, x0, hi, lo, x0, hi, hi, x0, lo, hi};
    m.triangles = {0, 1, 2, 0, 2, 3};
    return m;
}

/// A closed prism over a simple polygon (counter-clockwise in xy), z in [z0, z1]; the caps are
/// fanned from `fan` vertex, which must see the whole polygon (true for the L below from its
/// inner corner).
inline hullkit::TriangleMesh prism_mesh(const std::string& name,
                                        const std::vector<double>& polygon_xy, std::uint32_t fan,
                                        double z0, double z1) {
    hullkit::TriangleMesh m;
    m.name = name;
    const auto n = static_cast<std::uint32_t>(polygon_xy.size() / 2);
    for (double z : {z0, z1}) {
        for (std::uint32_t i = 0; i < n; ++i) {
            m.xyz.insert(m.xyz.end(), {polygon_xy[2 * i], polygon_xy[2 * i + 1], z});
        }
    }
    for (std::uint32_t k = 1; k + 1 < n; ++k) {
        const std::uint32_t i = (fan + k) % n, j = (fan + k + 1) % n;
        m.triangles.insert(m.triangles.end(), {fan, j, i});              // bottom, facing -z
        m.triangles.insert(m.triangles.end(), {n + fan, n + i, n + j});  // top, facing +z
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t j = (i + 1) % n;
        m.triangles.insert(m.triangles.end(), {i, j, n + j, i, n + j, n + i});
    }
    return m;
}

/// The L: [0,3]x[0,1] u [0,1]x[0,3], z in [0,1]; its inner corner (1,1) sees every vertex.
inline hullkit::TriangleMesh l_part() {
    return prism_mesh("L", {0, 0, 3, 0, 3, 1, 1, 1, 1, 3, 0, 3}, 3, 0.0, 1.0);
}

/// Adds (dx, dy, dz) to every point of the mesh.
inline void shift(hullkit::TriangleMesh& m, double dx, double dy, double dz) {
    for (std::size_t i = 0; i < m.xyz.size(); i += 3) {
        m.xyz[i] += dx;
        m.xyz[i + 1] += dy;
        m.xyz[i + 2] += dz;
    }
}

/// Shifts the obstacles and the waypoints by (s, s, s): the parts move with the route.
inline hullkit::Scene offset_scene(hullkit::Scene scene, double s) {
    for (auto& o : scene.obstacles) shift(o, s, s, s);
    for (double& x : scene.route) x += s;
    return scene;
}

}  // namespace route_test
