#include "hullkit/giftwrap.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "hull_checks.hpp"

using hullkit::GiftwrapScan;
using hullkit_test::Cloud;
using hullkit_test::cube_corners;
using hullkit_test::hull_problems;
using hullkit_test::join;

namespace {

void require_valid(const std::vector<double>& xyz, const hullkit::Hull& hull) {
    INFO(hull.error);
    REQUIRE(hull.ok());
    const auto problems = hull_problems(xyz, hull);
    INFO(join(problems));
    REQUIRE(problems.empty());
}

}  // namespace

TEST_CASE("giftwrap: tetrahedron") {
    const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const auto hull = hullkit::giftwrap(xyz);
    require_valid(xyz, hull);
    CHECK(hull.face_count() == 4);
    CHECK(hull.vertices == std::vector<std::uint32_t>{0, 1, 2, 3});
    CHECK(hull.volume == Approx(1.0 / 6.0).epsilon(1e-14));
    CHECK(hull.area == Approx(1.5 + std::sqrt(3.0) / 2.0).epsilon(1e-14));
}

TEST_CASE("giftwrap: cube corners") {
    const auto xyz = cube_corners();
    const auto hull = hullkit::giftwrap(xyz);
    require_valid(xyz, hull);
    CHECK(hull.face_count() == 12);  // 6 squares, 2 triangles each
    CHECK(hull.vertices.size() == 8);
    CHECK(hull.volume == Approx(8.0).epsilon(1e-14));
    CHECK(hull.area == Approx(24.0).epsilon(1e-14));
}

TEST_CASE("giftwrap: cube corners with interior, face and edge points") {
    auto xyz = cube_corners(2.0);
    const double extra[][3] = {{0, 0, 0}, {2, 0, 0}, {0, -2, 0}, {0, 0, 2}, {2, 2, 0}, {-2, 0, -2}, {1, 1, 1}};
    for (const auto& p : extra) xyz.insert(xyz.end(), p, p + 3);
    const auto hull = hullkit::giftwrap(xyz);
    require_valid(xyz, hull);
    CHECK(hull.vertices == std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7});
    CHECK(hull.face_count() == 12);
    CHECK(hull.volume == Approx(64.0).epsilon(1e-14));
}

TEST_CASE("giftwrap: octahedron with duplicated points") {
    std::vector<double> xyz = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    const std::vector<double> copy(xyz);
    xyz.insert(xyz.end(), copy.begin(), copy.end());  // points 6..11 repeat 0..5
    const auto hull = hullkit::giftwrap(xyz);
    require_valid(xyz, hull);
    CHECK(hull.vertices == std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5});  // lowest index of each copy
    CHECK(hull.face_count() == 8);
    CHECK(hull.volume == Approx(4.0 / 3.0).epsilon(1e-14));
}

TEST_CASE("giftwrap: random points in a cube, a ball and on a sphere") {
    const double pi = std::acos(-1.0);
    struct Case {
        Cloud cloud;
        std::size_t n;
        double bound;  // the volume of the body the points are drawn from
    };
    const Case cases[] = {{Cloud::Cube, 3000, 8.0}, {Cloud::Ball, 3000, 4.0 / 3.0 * pi}, {Cloud::Sphere, 600, 4.0 / 3.0 * pi}};
    for (const Case& c : cases) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            const auto xyz = hullkit_test::random_cloud(c.cloud, c.n, seed);
            const auto hull = hullkit::giftwrap(xyz);
            INFO("cloud " << static_cast<int>(c.cloud) << " seed " << seed);
            require_valid(xyz, hull);
            CHECK(hull.volume < c.bound);
            CHECK(hull.volume > 0.85 * c.bound);
            // Points in general position: a simplicial hull with F = 2V - 4.
            CHECK(hull.face_count() == 2 * hull.vertices.size() - 4);
            if (c.cloud == Cloud::Sphere) CHECK(hull.vertices.size() == c.n);  // every point is extreme
        }
    }
}

TEST_CASE("giftwrap: the single-pass scan finds the same hull as the seed's restarting scan") {
    for (Cloud cloud : {Cloud::Cube, Cloud::Ball, Cloud::Sphere}) {
        for (std::uint64_t seed = 10; seed < 14; ++seed) {
            const auto xyz = hullkit_test::random_cloud(cloud, 300, seed);
            const auto single = hullkit::giftwrap(xyz, GiftwrapScan::SinglePass);
            const auto restart = hullkit::giftwrap(xyz, GiftwrapScan::Restart);
            REQUIRE(single.ok());
            REQUIRE(restart.ok());
            CHECK(single.triangles == restart.triangles);
            CHECK(single.vertices == restart.vertices);
        }
    }
    const auto cube = cube_corners();
    CHECK(hullkit::giftwrap(cube, GiftwrapScan::SinglePass).triangles ==
          hullkit::giftwrap(cube, GiftwrapScan::Restart).triangles);
}

TEST_CASE("giftwrap: the seed's epsilon reports degenerate input instead of computing it") {
    hullkit::HullOptions seed;
    seed.algorithm = hullkit::Algorithm::Giftwrap;
    seed.side_test = hullkit::SideTest::Seed;
    auto error_of = [&](const std::vector<double>& xyz) { return hullkit::hull(xyz, seed).error; };
    CHECK_THAT(error_of({0, 0, 0, 1, 0, 0, 0, 1, 0}), Catch::Contains("at least 4 points, got 3"));
    CHECK_THAT(error_of({1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3}), Catch::Contains("identical"));
    CHECK_THAT(error_of({0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, -5, -5, -5}), Catch::Contains("collinear"));
    CHECK_THAT(error_of({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.25, 0}), Catch::Contains("coplanar"));
    // A tilted plane: 2x + 3y - z = 1.
    std::vector<double> tilted;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) tilted.insert(tilted.end(), {double(i), double(j), 2.0 * i + 3.0 * j - 1.0});
    CHECK_THAT(error_of(tilted), Catch::Contains("coplanar"));
    // In general position it finds the exact hull.
    const auto ball = hullkit_test::random_cloud(Cloud::Ball, 1000, 3);
    CHECK(hullkit::hull(ball, seed).triangles == hullkit::giftwrap(ball).triangles);
}

TEST_CASE("giftwrap: non-finite coordinates are reported with the point's index") {
    auto xyz = cube_corners();
    xyz[3 * 5 + 1] = std::numeric_limits<double>::quiet_NaN();
    const auto nan = hullkit::giftwrap(xyz);
    CHECK_THAT(nan.error, Catch::Contains("point 5") && Catch::Contains("y coordinate") && Catch::Contains("nan"));
    CHECK(nan.error_point == 5);
    CHECK(nan.triangles.empty());
    xyz = cube_corners();
    xyz[3 * 2 + 2] = -std::numeric_limits<double>::infinity();
    CHECK_THAT(hullkit::giftwrap(xyz).error, Catch::Contains("point 2") && Catch::Contains("-inf"));
}

TEST_CASE("giftwrap: hullkit::hull dispatches to gift wrapping") {
    const auto xyz = hullkit_test::random_cloud(Cloud::Ball, 500, 7);
    hullkit::HullOptions options;
    options.algorithm = hullkit::Algorithm::Giftwrap;
    CHECK(hullkit::hull(xyz, options).triangles == hullkit::giftwrap(xyz).triangles);
    hullkit::Algorithm parsed{};
    CHECK(hullkit::parse_algorithm("giftwrap", &parsed));
    CHECK(std::string(hullkit::algorithm_name(parsed)) == "giftwrap");
    CHECK(hullkit::parse_algorithm("quickhull", &parsed));
    CHECK(std::string(hullkit::algorithm_name(parsed)) == "quickhull");
    CHECK_FALSE(hullkit::parse_algorithm("qhull", &parsed));
}
