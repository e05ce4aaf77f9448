#include "hullkit/hull.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "hull_checks.hpp"

using hullkit::Algorithm;
using hullkit_test::Cloud;

namespace {

hullkit::Hull run(const std::vector<double>& xyz, Algorithm algorithm = Algorithm::Quickhull) {
    hullkit::HullOptions options;
    options.algorithm = algorithm;
    return hullkit::hull(xyz, options);
}

}  // namespace

TEST_CASE("hull: no points is dimension -1, not an error") {
    for (auto algorithm : {Algorithm::Quickhull, Algorithm::Giftwrap}) {
        const auto hull = run({}, algorithm);
        CHECK(hull.ok());
        CHECK(hull.dimension == -1);
        CHECK(hull.vertices.empty());
        CHECK(hull.triangles.empty());
    }
}

TEST_CASE("hull: one point, repeated, is dimension 0 with the lowest index") {
    for (auto algorithm : {Algorithm::Quickhull, Algorithm::Giftwrap}) {
        const auto one = run({1, 2, 3}, algorithm);
        CHECK(one.dimension == 0);
        CHECK(one.vertices == std::vector<std::uint32_t>{0});
        const auto many = run({1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3}, algorithm);
        CHECK(many.dimension == 0);
        CHECK(many.vertices == std::vector<std::uint32_t>{0});
        CHECK(many.volume == 0.0);
    }
}

TEST_CASE("hull: collinear points give the segment's two end points") {
    // On the line (1, 2, 3) + t (1, -1, 2), t = 0, 3, -2, 1, 3 (a repeat), -2 (a repeat).
    std::vector<double> xyz;
    for (double t : {0.0, 3.0, -2.0, 1.0, 3.0, -2.0}) xyz.insert(xyz.end(), {1 + t, 2 - t, 3 + 2 * t});
    for (auto algorithm : {Algorithm::Quickhull, Algorithm::Giftwrap}) {
        const auto hull = run(xyz, algorithm);
        CHECK(hull.dimension == 1);
        CHECK(hull.vertices == std::vector<std::uint32_t>{1, 2});
        CHECK(hull.triangles.empty());
    }
    const auto two = run({0, 0, 0, 1e-300, 0, 0});
    CHECK(two.dimension == 1);
    CHECK(two.vertices == std::vector<std::uint32_t>{0, 1});
}

TEST_CASE("hull: coplanar points give a convex polygon in order") {
    // A square in the plane z = x + y with its centre, an edge midpoint and a repeated corner.
    const std::vector<double> xyz = {0, 0, 0,  2, 0, 2,  2, 2, 4,  0, 2, 2,  1, 1, 2,  1, 0, 1,  2, 2, 4};
    for (auto algorithm : {Algorithm::Quickhull, Algorithm::Giftwrap}) {
        const auto hull = run(xyz, algorithm);
        REQUIRE(hull.ok());
        CHECK(hull.dimension == 2);
        REQUIRE(hull.vertices.size() == 4);
        CHECK(hull.vertices[0] == 0);
        // Counter-clockwise seen from `normal`: the cycle 0 1 2 3 or 0 3 2 1, whichever the normal says.
        const bool up = hull.normal[2] > 0;
        CHECK(hull.vertices == (up ? std::vector<std::uint32_t>{0, 1, 2, 3} : std::vector<std::uint32_t>{0, 3, 2, 1}));
        CHECK(std::fabs(hull.normal[0] + 1 / std::sqrt(3.0) * (up ? 1 : -1)) < 1e-15);
        CHECK(hull.triangles.size() == 6);
        CHECK(hull.area == Approx(4 * std::sqrt(3.0)).epsilon(1e-14));  // |(2,0,2) x (0,2,2)|
        CHECK(hull.volume == 0.0);
    }
}

TEST_CASE("hull: clouds far from unit scale get exact answers") {
    const auto unit = hullkit_test::random_cloud(Cloud::Ball, 2000, 9);
    const auto reference = run(unit);
    for (double scale : {1e-150, 1e150, 0x1p-1000, 0x1p+900}) {
        std::vector<double> scaled(unit);
        for (double& c : scaled) c *= scale;
        for (auto algorithm : {Algorithm::Quickhull, Algorithm::Giftwrap}) {
            const auto hull = run(scaled, algorithm);
            INFO("scale " << scale);
            REQUIRE(hull.ok());
            CHECK(hull.vertices == reference.vertices);
            auto problems = hullkit_test::hull_problems(scaled, hull);
            if (scale < 1e-100) {  // a volume of about scale^3 underflows to 0 in doubles: expected
                CHECK(hull.volume == 0.0);
                problems.erase(std::remove_if(problems.begin(), problems.end(),
                                              [](const std::string& p) { return p.rfind("volume", 0) == 0; }),
                               problems.end());
            }
            INFO(hullkit_test::join(problems));
            CHECK(problems.empty());
        }
    }
    // Offset by 1e9: rounding makes a different point set, but the hull is still exact for it.
    std::vector<double> offset(unit);
    for (double& c : offset) c += 1e9;
    const auto far = run(offset);
    CHECK(hullkit_test::hull_problems(offset, far).empty());
    CHECK(far.vertices == run(offset, Algorithm::Giftwrap).vertices);
}

TEST_CASE("hull: a spread of magnitudes no scale can fit is a clear error") {
    const std::vector<double> xyz = {1e300, 0, 0, 0, 1e-300, 0, 0, 0, 1, 1, 1, 1};
    const auto hull = run(xyz);
    CHECK_FALSE(hull.ok());
    CHECK_THAT(hull.error, Catch::Contains("orders of magnitude"));
}

TEST_CASE("hull: the seed's epsilon is for gift wrapping only") {
    hullkit::HullOptions options;
    options.side_test = hullkit::SideTest::Seed;
    const auto hull = hullkit::hull(hullkit_test::random_cloud(Cloud::Ball, 100, 1), options);
    CHECK_THAT(hull.error, Catch::Contains("gift wrapping only"));
}

TEST_CASE("hull: non-finite coordinates name the point") {
    std::vector<double> xyz = hullkit_test::random_cloud(Cloud::Cube, 50, 2);
    xyz[3 * 17 + 0] = std::numeric_limits<double>::infinity();
    const auto hull = run(xyz);
    CHECK(hull.error == "point 17 has a non-finite x coordinate (inf)");
    CHECK(hull.error_point == 17);
}

TEST_CASE("hull: the same input gives the same output") {
    const auto xyz = hullkit_test::random_cloud(Cloud::Sphere, 5000, 11);
    const auto first = run(xyz);
    const auto second = run(xyz);
    CHECK(first.triangles == second.triangles);
    CHECK(first.volume == second.volume);
}
