// hullkit::delaunay3 with Delaunay3Options::furthest_site, checked with rational arithmetic (GMP),
// not with the library's predicates: every tetrahedron positively oriented, every point inside or on
// every circumsphere, faces paired as the neighbours say, the open faces the hull's (each with every
// point on its inner side), the corners exactly the hull's extreme points, and the volume exactly
// that of the ordinary tetrahedralization of the same points (both fill the hull). Ties (grids,
// points on a sphere) give the same tetrahedra in any input order and for any thread count.
#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "hullkit/delaunay3.hpp"
#include "hullkit/hull.hpp"
#include "delaunay3_test_points.hpp"

using hullkit::Delaunay3;
using hullkit::Delaunay3Options;
using hullkit::PointSpan;

namespace {

using hullkit_test::Tet;
using hullkit_test::tetrahedron_set;
using Face = std::array<std::uint32_t, 3>;

Delaunay3 furthest(const std::vector<double>& xyz, unsigned threads = 1) {
    Delaunay3Options options;
    options.threads = threads;
    options.furthest_site = true;
    return hullkit::delaunay3(PointSpan(xyz.data(), xyz.size() / 3), options);
}

mpq_class det3(const mpq_class e[3][3]) {
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

/// 6 x the signed volume of a, b, c, d (positive: d on the side (b - a) x (c - a) points to).
mpq_class orient(const double* a, const double* b, const double* c, const double* d) {
    mpq_class e[3][3];
    const double* rows[3] = {b, c, d};
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) e[r][k] = mpq_class(rows[r][k]) - mpq_class(a[k]);
    return det3(e);
}

/// Positive when e is strictly inside the sphere through the positively oriented a, b, c, d.
int insphere(const double* a, const double* b, const double* c, const double* d, const double* e) {
    const double* p[4] = {a, b, c, d};
    mpq_class m[4][4];
    for (int r = 0; r < 4; ++r) {
        m[r][3] = 0;
        for (int k = 0; k < 3; ++k) {
            m[r][k] = mpq_class(p[r][k]) - mpq_class(e[k]);
            m[r][3] += m[r][k] * m[r][k];
        }
    }
    // Expansion along the last column: det [x y z w] with rows a..d, minus e.
    mpq_class det = 0;
    for (int r = 0; r < 4; ++r) {
        mpq_class minor[3][3];
        for (int i = 0, row = 0; i < 4; ++i) {
            if (i == r) continue;
            for (int k = 0; k < 3; ++k) minor[row][k] = m[i][k];
            ++row;
        }
        const mpq_class term = m[r][3] * det3(minor);
        det += (r % 2 == 0) ? -term : term;  // cofactor sign (-1)^(r + 3)
    }
    return -sgn(det);  // the determinant is negative for e inside a positively oriented a, b, c, d
}

mpq_class six_volume(const std::vector<double>& xyz, const std::vector<std::uint32_t>& tetrahedra) {
    mpq_class sum = 0;
    for (std::size_t t = 0; t < tetrahedra.size() / 4; ++t) {
        const std::uint32_t* v = &tetrahedra[4 * t];
        sum += orient(&xyz[3 * v[0]], &xyz[3 * v[1]], &xyz[3 * v[2]], &xyz[3 * v[3]]);
    }
    return sum;
}

void check_furthest(const std::vector<double>& xyz, const Delaunay3& d) {
    REQUIRE(d.ok());
    REQUIRE(d.dimension == 3);
    const std::size_t n = xyz.size() / 3;
    const auto at = [&](std::uint32_t i) { return &xyz[3 * i]; };
    std::set<Face> open_faces, hull_faces;
    std::set<std::uint32_t> corners;
    for (std::size_t t = 0; t < d.tetrahedron_count(); ++t) {
        const std::uint32_t* v = &d.tetrahedra[4 * t];
        corners.insert(v, v + 4);
        REQUIRE(orient(at(v[0]), at(v[1]), at(v[2]), at(v[3])) > 0);
        // Every point inside or on the circumsphere.
        for (std::uint32_t i = 0; i < n; ++i) REQUIRE(insphere(at(v[0]), at(v[1]), at(v[2]), at(v[3]), at(i)) >= 0);
        for (int j = 0; j < 4; ++j) {
            Face face;
            for (int i = 0, k = 0; i < 4; ++i)
                if (i != j) face[k++] = v[i];
            std::sort(face.begin(), face.end());
            const std::int32_t u = d.neighbors[4 * t + j];
            if (u < 0) {
                REQUIRE(open_faces.insert(face).second);
                continue;
            }
            const std::uint32_t* w = &d.tetrahedra[4 * static_cast<std::size_t>(u)];
            for (const std::uint32_t c : face) REQUIRE(std::find(w, w + 4, c) != w + 4);
            REQUIRE(std::find(w, w + 4, v[j]) == w + 4);
            // And u names t across the same face (its corner off the face).
            int off = 0;
            while (std::find(face.begin(), face.end(), w[off]) != face.end()) ++off;
            REQUIRE(d.neighbors[4 * static_cast<std::size_t>(u) + off] == static_cast<std::int32_t>(t));
        }
    }
    for (std::size_t f = 0; f < d.hull.size() / 3; ++f) {
        const std::uint32_t* h = &d.hull[3 * f];
        for (std::uint32_t i = 0; i < n; ++i) REQUIRE(orient(at(h[0]), at(h[1]), at(h[2]), at(i)) <= 0);
        Face face = {h[0], h[1], h[2]};
        std::sort(face.begin(), face.end());
        hull_faces.insert(face);
    }
    REQUIRE(open_faces == hull_faces);
    // The corners are the hull's extreme points (hull() is independent code).
    const hullkit::Hull h = hullkit::hull(PointSpan(xyz.data(), n));
    REQUIRE(corners == std::set<std::uint32_t>(h.vertices.begin(), h.vertices.end()));
    // Both tetrahedralizations fill the hull: the same volume, exactly.
    Delaunay3Options nearest_options;
    nearest_options.threads = 1;
    const Delaunay3 nearest = hullkit::delaunay3(PointSpan(xyz.data(), n), nearest_options);
    REQUIRE(six_volume(xyz, d.tetrahedra) == six_volume(xyz, nearest.tetrahedra));
}

}  // namespace

TEST_CASE("delaunay3 furthest_site: random points, every circumsphere holds every point", "[delaunay3][furthest]") {
    for (const std::size_t n : {4u, 5u, 9u, 60u, 400u}) {
        std::mt19937_64 rng(n);
        std::uniform_real_distribution<double> u(-1, 1);
        std::vector<double> xyz(3 * n);
        for (double& v : xyz) v = u(rng);
        INFO(n << " points");
        check_furthest(xyz, furthest(xyz));
    }
}

TEST_CASE("delaunay3 furthest_site: a point inside a hull face, an edge or the hull is in no tetrahedron",
          "[delaunay3][furthest]") {
    // A tetrahedron's corners, a point inside one face, one inside an edge, one inside, a duplicate.
    const std::vector<double> xyz = {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4, 1, 1, 0, 2, 0, 0, 0.5, 0.5, 0.5, 4, 0, 0};
    const Delaunay3 d = furthest(xyz);
    check_furthest(xyz, d);
    REQUIRE(d.tetrahedron_count() == 1);
    REQUIRE(tetrahedron_set(d) == std::set<Tet>{{0, 1, 2, 3}});
    REQUIRE(d.representative[7] == 1);
    REQUIRE(d.duplicate_count == 1);
}

TEST_CASE("delaunay3 furthest_site: grids and integer points on a sphere (ties), in any order and on any threads",
          "[delaunay3][furthest]") {
    std::vector<std::vector<double>> inputs = {hullkit_test::grid3(2), hullkit_test::grid3(3), hullkit_test::grid3(5)};
    // Integer points exactly on the sphere x^2 + y^2 + z^2 = 50: all cospherical, all extreme.
    std::vector<double> sphere;
    for (int x = -8; x <= 8; ++x)
        for (int y = -8; y <= 8; ++y)
            for (int z = -8; z <= 8; ++z)
                if (x * x + y * y + z * z == 50) sphere.insert(sphere.end(), {double(x), double(y), double(z)});
    inputs.push_back(sphere);
    for (const auto& xyz : inputs) {
        INFO(xyz.size() / 3 << " points");
        const Delaunay3 d = furthest(xyz);
        check_furthest(xyz, d);
        for (const unsigned threads : {2u, 3u, 8u}) {
            const Delaunay3 e = furthest(xyz, threads);
            REQUIRE(e.tetrahedra == d.tetrahedra);
            REQUIRE(e.neighbors == d.neighbors);
            REQUIRE(e.hull == d.hull);
        }
        for (const std::uint64_t seed : {1u, 2u}) {
            std::vector<std::uint32_t> perm;
            const std::vector<double> moved = hullkit_test::shuffled3(xyz, perm, seed);
            const Delaunay3 e = furthest(moved);
            check_furthest(moved, e);
            REQUIRE(tetrahedron_set(e, &perm) == tetrahedron_set(d));
        }
    }
}

TEST_CASE("delaunay3 furthest_site: many points on an ellipsoid cross the partitions, the same arrays on any threads",
          "[delaunay3][furthest][threads]") {
    // 70 000 points on an ellipsoid are all extreme: the last rounds are large enough to be cut
    // into partitions (the threads), whose walks start outside the hull.
    std::mt19937_64 rng(11);
    std::normal_distribution<double> g;
    std::vector<double> xyz;
    for (int i = 0; i < 70000; ++i) {
        double v[3] = {g(rng), g(rng), g(rng)};
        const double r = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        xyz.insert(xyz.end(), {v[0] / r, 2 * v[1] / r, 3 * v[2] / r});
    }
    const Delaunay3 one = furthest(xyz, 1);
    REQUIRE(one.ok());
    REQUIRE(one.dimension == 3);
    for (const unsigned threads : {2u, 3u}) {
        const Delaunay3 other = furthest(xyz, threads);
        REQUIRE(other.tetrahedra == one.tetrahedra);
        REQUIRE(other.neighbors == one.neighbors);
    }
    // Every point is a corner; the tetrahedra fill the hull (its volume from hull(), in floating
    // point); a sample of tetrahedra holds a sample of points, exactly.
    REQUIRE(std::set<std::uint32_t>(one.tetrahedra.begin(), one.tetrahedra.end()).size() == 70000);
    double volume = 0;
    for (std::size_t t = 0; t < one.tetrahedron_count(); ++t) {
        const std::uint32_t* v = &one.tetrahedra[4 * t];
        const double* p[4] = {&xyz[3 * v[0]], &xyz[3 * v[1]], &xyz[3 * v[2]], &xyz[3 * v[3]]};
        double e[3][3];
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) e[r][k] = p[r + 1][k] - p[0][k];
        volume += (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                   e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) / 6;
    }
    REQUIRE(volume == Approx(hullkit::hull(PointSpan(xyz.data(), xyz.size() / 3)).volume).epsilon(1e-9));
    for (std::size_t t = 0; t < one.tetrahedron_count(); t += one.tetrahedron_count() / 40) {
        const std::uint32_t* v = &one.tetrahedra[4 * t];
        for (std::uint32_t i = static_cast<std::uint32_t>(t % 37); i < 70000; i += 37)
            REQUIRE(insphere(&xyz[3 * v[0]], &xyz[3 * v[1]], &xyz[3 * v[2]], &xyz[3 * v[3]], &xyz[3 * i]) >= 0);
    }
}

TEST_CASE("delaunay3 furthest_site: coplanar and collinear points", "[delaunay3][furthest]") {
    // A square with its centre and a point inside an edge: the square's corners, two triangles.
    const std::vector<double> square = {0, 0, 1, 2, 0, 1, 2, 2, 1, 0, 2, 1, 1, 1, 1, 1, 0, 1};
    const Delaunay3 d = furthest(square);
    REQUIRE(d.ok());
    REQUIRE(d.dimension == 2);
    REQUIRE(d.triangles.size() == 6);
    std::set<std::uint32_t> used(d.triangles.begin(), d.triangles.end());
    REQUIRE(used == std::set<std::uint32_t>{0, 1, 2, 3});
    // A hexagon around a centre: the furthest-site triangles' circumcircles hold every corner.
    const std::vector<double> hexagon = {3, 0, 0, 1, 2, 0, -1, 2, 0, -3, 0, 0, -1, -2, 0, 1, -2, 0, 0, 0, 0};
    const Delaunay3 h = furthest(hexagon);
    REQUIRE(h.dimension == 2);
    REQUIRE(h.triangles.size() == 12);
    for (std::size_t t = 0; t < h.triangles.size() / 3; ++t) {
        const double* a = &hexagon[3 * h.triangles[3 * t]];
        const double* b = &hexagon[3 * h.triangles[3 * t + 1]];
        const double* c = &hexagon[3 * h.triangles[3 * t + 2]];
        for (std::size_t i = 0; i < 6; ++i) {
            // incircle in the plane z = 0 (counter-clockwise seen from +z or -z: sign by orientation).
            const double* p = &hexagon[3 * i];
            mpq_class m[3][3];
            const double* rows[3] = {a, b, c};
            for (int r = 0; r < 3; ++r) {
                m[r][0] = mpq_class(rows[r][0]) - mpq_class(p[0]);
                m[r][1] = mpq_class(rows[r][1]) - mpq_class(p[1]);
                m[r][2] = m[r][0] * m[r][0] + m[r][1] * m[r][1];
            }
            const mpq_class o = (mpq_class(b[0]) - a[0]) * (mpq_class(c[1]) - a[1]) - (mpq_class(b[1]) - a[1]) * (mpq_class(c[0]) - a[0]);
            REQUIRE(sgn(det3(m)) * sgn(o) >= 0);
        }
    }
    const std::vector<double> line = {0, 0, 0, 3, 3, 3, 1, 1, 1, 2, 2, 2};
    const Delaunay3 l = furthest(line);
    REQUIRE(l.dimension == 1);
    REQUIRE(l.vertices == std::vector<std::uint32_t>{0, 1});
}
