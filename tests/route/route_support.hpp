// Scene builders shared by the route tests.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
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

// ---- the hand-worked scenes (tests/route/scenes.cpp works out their answers; threads.cpp
// checks that every thread count gives the same report for them)

/// The traverse of most hand-worked scenes: the unit cube [0,1]^3; no obstacles, no route.
inline hullkit::Scene unit_cube_scene() {
    hullkit::Scene s;
    s.parts.push_back(box_mesh("cube", 0, 0, 0, 1, 1, 1));
    return s;
}

/// The unit cube moving along `route` past `obstacle`.
inline hullkit::Scene cube_past(hullkit::TriangleMesh obstacle, std::vector<double> route, double margin = 0.0) {
    hullkit::Scene s = unit_cube_scene();
    s.obstacles.push_back(std::move(obstacle));
    s.route = std::move(route);
    s.margin = margin;
    return s;
}

/// The unit cube moving 10 along x towards the wall "high" (x in [5, 6], y from `high_bottom`
/// up to 10, z in [-10, 10]).
inline hullkit::Scene wall_scene(double high_bottom, double margin) {
    return cube_past(box_mesh("high", 5, high_bottom, -10, 6, 10, 10), {0, 0, 0, 10, 0, 0}, margin);
}

/// The same through a slot: the wall "low" (y from -10 up to `low_top`) comes first, then "high".
inline hullkit::Scene slot_scene(double low_top, double high_bottom, double margin) {
    hullkit::Scene s = wall_scene(high_bottom, margin);
    s.obstacles.insert(s.obstacles.begin(), box_mesh("low", 5, -10, -10, 6, low_top, 10));
    return s;
}

/// A cube of side 2^-10 moving 1 along x through the zero-thickness plate x = 0.5 + 2^-8.
inline hullkit::Scene thin_plate_scene() {
    hullkit::Scene s;
    const double side = std::ldexp(1.0, -10);
    s.parts.push_back(box_mesh("cube", 0, 0, 0, side, side, side));
    s.obstacles.push_back(plate_x("plate", 0.50390625, -1, 1));
    s.route = {0, 0, 0, 1, 0, 0};
    return s;
}

/// The unit cube starting against a box sharing its face x = 1, then moving down and away.
inline hullkit::Scene touching_start_scene() {
    return cube_past(box_mesh("touching", 1, 0.5, 0.5, 2, 2, 2), {0, 0, 0, 0, 0, -5, 5, 0, -5});
}

/// The unit cube moving 10 along x over a small closed box ("bead") at x in [5, 5.1].
inline hullkit::Scene bead_scene() {
    return cube_past(box_mesh("bead", 5, 0.4, 0.4, 5.1, 0.6, 0.6), {0, 0, 0, 10, 0, 0});
}

/// The unit cube moving 10 along x over a lone triangle ("chip") near x = 7.
inline hullkit::Scene chip_scene() {
    hullkit::TriangleMesh chip;
    chip.name = "chip";
    chip.xyz = {7, 0.2, 0.2, 7.05, 0.8, 0.3, 7.02, 0.5, 0.9};
    chip.triangles = {0, 1, 2};
    return cube_past(chip, {0, 0, 0, 10, 0, 0});
}

/// The unit cube inside the vessel [-5, 6]^3, moving by (1, 1, 1); without its top (the last
/// two triangles) the vessel is an open surface.
inline hullkit::Scene vessel_scene(bool closed) {
    hullkit::TriangleMesh vessel = box_mesh("vessel", -5, -5, -5, 6, 6, 6);
    if (!closed) vessel.triangles.resize(vessel.triangles.size() - 6);
    return cube_past(vessel, {0, 0, 0, 1, 1, 1});
}

/// The unit cube around the box [0.25, 0.75]^3, moving 0.1 along z.
inline hullkit::Scene obstacle_inside_part_scene() {
    return cube_past(box_mesh("inside", 0.25, 0.25, 0.25, 0.75, 0.75, 0.75), {0, 0, 0, 0, 0, 0.1});
}

/// The L (l_part) around the post [1.5, 1.7]^2 x [-5, 5], moving from 0 to `end`.
inline hullkit::Scene l_post_scene(double ex, double ey, double ez) {
    hullkit::Scene s;
    s.parts.push_back(l_part());
    s.obstacles.push_back(box_mesh("post", 1.5, 1.5, -5, 1.7, 1.7, 5));
    s.route = {0, 0, 0, ex, ey, ez};
    return s;
}

struct NamedScene {
    std::string name;
    hullkit::Scene scene;
};

/// Every hand-worked scene of scenes.cpp with its route, as given (not offset).
inline std::vector<NamedScene> hand_worked_scenes() {
    const double g = std::ldexp(1.0, -40);
    return {
        {"wide slot", slot_scene(-0.25, 1.25, 0.125)},
        {"narrow slot, margin 0", slot_scene(-0.25, 0.75, 0.0)},
        {"narrow slot, margin 0.5", slot_scene(-0.25, 0.75, 0.5)},
        {"grazing a wall at the margin", wall_scene(1.25, 0.25)},
        {"slot exactly as wide as the cube", slot_scene(0.0, 1.0, 0.0)},
        {"slot wider by 2^-40", slot_scene(-g, 1 + g, 0.0)},
        {"thin plate", thin_plate_scene()},
        {"touching start", touching_start_scene()},
        {"bead", bead_scene()},
        {"chip", chip_scene()},
        {"closed vessel", vessel_scene(true)},
        {"open vessel", vessel_scene(false)},
        {"obstacle inside the part", obstacle_inside_part_scene()},
        {"L around a post, clear", l_post_scene(0.25, 0.25, 2)},
        {"L around a post, hit", l_post_scene(0.75, 0.75, 0)},
    };
}

}  // namespace route_test
