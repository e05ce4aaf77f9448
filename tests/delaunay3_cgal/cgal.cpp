// hullkit::delaunay3 against an independent implementation: CGAL's Delaunay_triangulation_3 (exact
// predicates, its own symbolic perturbation for ties). In general position the Delaunay
// tetrahedralization is unique, so the two must agree; hullkit's tie rule is CGAL's, so they agree
// on cospherical input too (grids, lattices, points on a sphere). Built only where CGAL is
// installed (libcgal-dev).
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "hullkit/delaunay3.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using Cgal = CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<VertexBase>>;
using Tet = std::array<std::uint32_t, 4>;

std::set<Tet> cgal_tetrahedra(const std::vector<double>& xyz) {
    std::vector<std::pair<Kernel::Point_3, std::uint32_t>> points;
    for (std::size_t i = 0; i < xyz.size() / 3; ++i)
        points.push_back({Kernel::Point_3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), static_cast<std::uint32_t>(i)});
    const Cgal dt(points.begin(), points.end());
    std::set<Tet> out;
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
        Tet v;
        for (int k = 0; k < 4; ++k) v[k] = c->vertex(k)->info();
        std::sort(v.begin(), v.end());
        out.insert(v);
    }
    return out;
}

std::set<Tet> hullkit_tetrahedra(const std::vector<double>& xyz) {
    const hullkit::Delaunay3 d = hullkit::delaunay3(hullkit::PointSpan(xyz.data(), xyz.size() / 3));
    REQUIRE(d.ok());
    REQUIRE(d.dimension == 3);
    std::set<Tet> out;
    for (std::size_t t = 0; t < d.tetrahedron_count(); ++t) {
        Tet v = {d.tetrahedra[4 * t], d.tetrahedra[4 * t + 1], d.tetrahedra[4 * t + 2], d.tetrahedra[4 * t + 3]};
        std::sort(v.begin(), v.end());
        out.insert(v);
    }
    REQUIRE(out.size() == d.tetrahedron_count());
    return out;
}

void same_as_cgal(const std::vector<double>& xyz) {
    const std::set<Tet> ours = hullkit_tetrahedra(xyz), theirs = cgal_tetrahedra(xyz);
    std::size_t common = 0;
    for (const Tet& t : ours) common += theirs.count(t);
    INFO("hullkit " << ours.size() << ", CGAL " << theirs.size() << ", in both " << common);
    REQUIRE(ours == theirs);
}

}  // namespace

TEST_CASE("delaunay3 vs CGAL: uniform and clustered points (general position)", "[delaunay3][cgal]") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    std::normal_distribution<double> g(0, 0.01);
    std::vector<double> uniform(3 * 20000), clusters;
    for (double& v : uniform) v = u(rng);
    same_as_cgal(uniform);
    for (int c = 0; c < 20; ++c) {
        const double cx = u(rng), cy = u(rng), cz = u(rng);
        for (int i = 0; i < 500; ++i) clusters.insert(clusters.end(), {cx + g(rng), cy + g(rng), cz + g(rng)});
    }
    same_as_cgal(clusters);
}

TEST_CASE("delaunay3 vs CGAL: cospherical ties (grids, lattices, spheres) broken the same way", "[delaunay3][cgal]") {
    std::vector<double> grid, sphere, bcc, box;
    for (int x = 0; x < 9; ++x)
        for (int y = 0; y < 7; ++y)
            for (int z = 0; z < 5; ++z) grid.insert(grid.end(), {double(x), double(y), double(z)});
    same_as_cgal(grid);
    for (int x = -19; x <= 19; ++x)
        for (int y = -19; y <= 19; ++y)
            for (int z = -19; z <= 19; ++z)
                if (x * x + y * y + z * z == 325 || x * x + y * y + z * z == 50) sphere.insert(sphere.end(), {double(x), double(y), double(z)});
    same_as_cgal(sphere);  // two concentric spheres
    for (int x = 0; x < 5; ++x)
        for (int y = 0; y < 5; ++y)
            for (int z = 0; z < 5; ++z) {
                bcc.insert(bcc.end(), {double(2 * x), double(2 * y), double(2 * z)});
                bcc.insert(bcc.end(), {double(2 * x + 1), double(2 * y + 1), double(2 * z + 1)});
            }
    same_as_cgal(bcc);
    // Points on a box's faces only (each once: CGAL keeps an arbitrary one of repeated points):
    // coplanar hull faces triangulated by the tie rule.
    for (int x = 0; x <= 6; ++x)
        for (int y = 0; y <= 6; ++y)
            for (int z = 0; z <= 6; ++z)
                if (x == 0 || x == 6 || y == 0 || y == 6 || z == 0 || z == 6) box.insert(box.end(), {double(x), double(y), double(z)});
    same_as_cgal(box);
}

TEST_CASE("delaunay3 vs CGAL: lattices on both sides of the limit of the in-doubles shortcut", "[delaunay3][cgal]") {
    // Every integer point on a sphere of radius 329 (2646 points, 658 apart: the lattice's
    // predicates exact in doubles) and of radius 330 (1950, 660 apart: beyond the shortcut's 659,
    // the exact predicates in full), with the centre and a small inner sphere; all ties.
    for (const int radius : {329, 330}) {
        std::vector<double> xyz = {0, 0, 0};
        for (int x = -radius; x <= radius; ++x) {
            for (int y = -radius; y <= radius; ++y) {
                const int rest = radius * radius - x * x - y * y;
                if (rest < 0) continue;
                const int z = static_cast<int>(std::lround(std::sqrt(double(rest))));
                if (z * z != rest) continue;
                xyz.insert(xyz.end(), {double(x), double(y), double(z)});
                if (z != 0) xyz.insert(xyz.end(), {double(x), double(y), double(-z)});
            }
        }
        for (int x = -7; x <= 7; ++x)
            for (int y = -7; y <= 7; ++y)
                for (int z = -7; z <= 7; ++z)
                    if (x * x + y * y + z * z == 50) xyz.insert(xyz.end(), {double(x), double(y), double(z)});
        INFO("radius " << radius << ", " << xyz.size() / 3 << " points");
        same_as_cgal(xyz);
    }
    // A grid of multiples of 2^-7 far from the origin (the lattice's unit is not 1).
    std::vector<double> fine;
    for (int x = 0; x < 9; ++x)
        for (int y = 0; y < 8; ++y)
            for (int z = 0; z < 7; ++z) fine.insert(fine.end(), {1000 + x / 128.0, -3 + y / 128.0, 5 + z / 64.0});
    same_as_cgal(fine);
}

TEST_CASE("delaunay3 vs CGAL: points on spheres up to rounding (near-cospherical, in-sphere stage C)", "[delaunay3][cgal]") {
    // Rounded unit vectors: every five points are cospherical up to the rounding of their
    // coordinates, so most in-sphere tests go past the filter (hullkit's stage C decides them).
    std::mt19937_64 rng(17);
    std::normal_distribution<double> g;
    for (const double offset : {0.0, 1e3}) {
        std::vector<double> xyz;
        for (int i = 0; i < 8000; ++i) {
            double v[3] = {g(rng), g(rng), g(rng)};
            const double r = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            xyz.insert(xyz.end(), {offset + v[0] / r, v[1] / r, v[2] / r});
        }
        INFO("centre offset " << offset);
        same_as_cgal(xyz);
    }
}
