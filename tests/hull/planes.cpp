// hullkit::plane_equations (native/src/hull/planes.cpp): each normal against the exact one (GMP),
// on hulls and on nearly flat triangles that take the exact path; outward on hulls; the same bits
// under power-of-two scaling; a polygon's planes on the side of Hull::normal.
#include "hullkit/hull.hpp"

#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "hull_checks.hpp"

namespace {

/// The exact unit normal and offset of triangle (a, b, c), rounded from 256-bit arithmetic.
std::vector<double> exact_plane(const double* a, const double* b, const double* c) {
    mpq_class e[3], f[3];
    for (int k = 0; k < 3; ++k) {
        e[k] = mpq_class(b[k]) - mpq_class(a[k]);
        f[k] = mpq_class(c[k]) - mpq_class(a[k]);
    }
    const mpq_class n[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
    const mpq_class dot = n[0] * a[0] + n[1] * a[1] + n[2] * a[2];
    mpf_class squared(0, 256);
    for (const mpq_class& v : n) squared += mpf_class(v * v, 256);
    const mpf_class length = sqrt(squared);
    std::vector<double> out(4);
    for (int k = 0; k < 3; ++k) out[k] = mpf_class(mpf_class(n[k], 256) / length, 256).get_d();
    out[3] = mpf_class(-mpf_class(dot, 256) / length, 256).get_d();
    return out;
}

double max_abs(const double* p) { return std::max({std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])}); }

/// Every plane of `triangles` within 2e-14 of the exact one (normal), the offset within 1e-15 of
/// the corners' largest magnitude.
void check_against_exact(const std::vector<double>& xyz, const std::vector<std::uint32_t>& triangles) {
    const hullkit::PointSpan points(xyz);
    const std::vector<double> planes = hullkit::plane_equations(points, triangles.data(), triangles.size() / 3);
    REQUIRE(planes.size() == 4 * (triangles.size() / 3));
    for (std::size_t t = 0; 3 * t < triangles.size(); ++t) {
        const double* a = points[triangles[3 * t]];
        const double* b = points[triangles[3 * t + 1]];
        const double* c = points[triangles[3 * t + 2]];
        const std::vector<double> exact = exact_plane(a, b, c);
        const double* got = &planes[4 * t];
        INFO("triangle " << t << ": " << got[0] << " " << got[1] << " " << got[2] << " " << got[3] << " vs " << exact[0]
                         << " " << exact[1] << " " << exact[2] << " " << exact[3]);
        for (int k = 0; k < 3; ++k) CHECK(std::fabs(got[k] - exact[k]) <= 2e-14);
        const double scale = std::max({max_abs(a), max_abs(b), max_abs(c)});
        CHECK(std::fabs(got[3] - exact[3]) <= 1e-15 * scale);
    }
}

}  // namespace

TEST_CASE("planes: hull triangles' planes agree with the exact ones and face outwards") {
    using hullkit_test::Cloud;
    for (Cloud kind : {Cloud::Cube, Cloud::Ball, Cloud::Sphere}) {
        const std::vector<double> xyz = hullkit_test::random_cloud(kind, 3000, 11);
        const hullkit::Hull hull = hullkit::hull(hullkit::PointSpan(xyz));
        REQUIRE(hull.dimension == 3);
        check_against_exact(xyz, hull.triangles);
        // Outwards: every point on the inner side, up to rounding.
        const std::vector<double> planes = hullkit::plane_equations(hullkit::PointSpan(xyz), hull);
        double worst = -1.0;
        for (std::size_t t = 0; t < hull.face_count(); ++t) {
            const double* n = &planes[4 * t];
            for (std::size_t i = 0; i < xyz.size() / 3; ++i) {
                worst = std::max(worst, n[0] * xyz[3 * i] + n[1] * xyz[3 * i + 1] + n[2] * xyz[3 * i + 2] + n[3]);
            }
        }
        CHECK(worst <= 1e-15);
        CHECK(worst >= -1e-15);  // the hull's own corners lie on their planes
    }
}

TEST_CASE("planes: nearly flat triangles (the exact path) and far-off tiny ones keep their accuracy") {
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<double> xyz;
    std::vector<std::uint32_t> triangles;
    auto add = [&](const double* a, const double* b, const double* c) {
        const auto first = static_cast<std::uint32_t>(xyz.size() / 3);
        for (const double* p : {a, b, c}) xyz.insert(xyz.end(), p, p + 3);
        triangles.insert(triangles.end(), {first, first + 1, first + 2});
    };
    for (int trial = 0; trial < 300; ++trial) {
        const double a[3] = {unit(random), unit(random), unit(random)};
        const double b[3] = {unit(random), unit(random), unit(random)};
        // c near the middle of a-b: an angle near 180 degrees at c, lifted off the line by 1e-6..1e-13.
        const double lift = std::pow(10.0, -6.0 - trial % 8);
        const double c[3] = {(a[0] + b[0]) / 2 + lift * unit(random), (a[1] + b[1]) / 2 + lift * unit(random),
                             (a[2] + b[2]) / 2 + lift * unit(random)};
        add(a, b, c);
        // A small triangle far from the origin: every coordinate near 1e3, the edges near 1e-9.
        const double far[3] = {1e3 + unit(random), 1e3 + unit(random), 1e3 + unit(random)};
        const double p[3] = {far[0] + 1e-9 * unit(random), far[1] + 1e-9 * unit(random), far[2]};
        const double q[3] = {far[0], far[1] + 1e-9 * unit(random), far[2] + 1e-9 * unit(random)};
        add(far, p, q);
    }
    check_against_exact(xyz, triangles);
}

TEST_CASE("planes: powers of two scale the offsets and leave the normals' bits alone, at any magnitude") {
    const std::vector<double> xyz = hullkit_test::random_cloud(hullkit_test::Cloud::Ball, 500, 3);
    const hullkit::Hull hull = hullkit::hull(hullkit::PointSpan(xyz));
    const std::vector<double> planes = hullkit::plane_equations(hullkit::PointSpan(xyz), hull);
    for (double scale : {0x1p-900, 0x1p-300, 0x1p300, 0x1p900}) {
        std::vector<double> scaled = xyz;
        for (double& v : scaled) v *= scale;
        const std::vector<double> got = hullkit::plane_equations(hullkit::PointSpan(scaled), hull);
        REQUIRE(got.size() == planes.size());
        for (std::size_t k = 0; k < got.size(); ++k) {
            INFO("scale " << scale << " value " << k);
            CHECK(got[k] == (k % 4 == 3 ? planes[k] * scale : planes[k]));
        }
    }
}

TEST_CASE("planes: a polygon's planes are its own, on the side of Hull::normal, bad corners throw") {
    // A hexagon in a tilted plane, exactly: z = x / 2 - y / 4 + 2 at integer x and y (a hexagon of
    // cos and sin values is not coplanar once rounded, and its exact hull is a solid).
    std::vector<double> xyz;
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{2, 0}, {1, 2}, {-1, 2}, {-2, 0}, {-1, -2}, {1, -2}})
        xyz.insert(xyz.end(), {x, y, 0.5 * x - 0.25 * y + 2});
    const hullkit::Hull hull = hullkit::hull(hullkit::PointSpan(xyz));
    REQUIRE(hull.dimension == 2);
    const std::vector<double> planes = hullkit::plane_equations(hullkit::PointSpan(xyz), hull);
    REQUIRE(planes.size() == 4 * hull.face_count());
    for (std::size_t t = 0; t < hull.face_count(); ++t) {
        for (int k = 0; k < 3; ++k) CHECK(planes[4 * t + k] == Approx(hull.normal[k]).margin(1e-15));
        for (std::size_t i = 0; i < 6; ++i) {
            const double* p = &xyz[3 * i];
            CHECK(std::fabs(planes[4 * t] * p[0] + planes[4 * t + 1] * p[1] + planes[4 * t + 2] * p[2] + planes[4 * t + 3]) <
                  1e-14);
        }
    }
    const std::uint32_t bad[3] = {0, 1, 6};
    CHECK_THROWS_AS(hullkit::plane_equations(hullkit::PointSpan(xyz), bad, 1), std::invalid_argument);
    // A triangle without area has no plane: zeros.
    const std::uint32_t flat[3] = {0, 0, 1};
    CHECK(hullkit::plane_equations(hullkit::PointSpan(xyz), flat, 1) == std::vector<double>{0, 0, 0, 0});
}
