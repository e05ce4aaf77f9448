#include <catch2/catch.hpp>

#include <cmath>

#include "hull_checks.hpp"
#include "sanitized.hpp"
#include "hullkit/giftwrap.hpp"
#include "hullkit/hull.hpp"

using hullkit_test::Cloud;
using hullkit_test::hull_problems;
using hullkit_test::join;

namespace {

hullkit::Hull quickhull(const std::vector<double>& xyz) {
    hullkit::HullOptions options;
    options.algorithm = hullkit::Algorithm::Quickhull;
    return hullkit::hull(xyz, options);
}

void require_valid(const std::vector<double>& xyz, const hullkit::Hull& hull) {
    INFO(hull.error);
    REQUIRE(hull.ok());
    REQUIRE(hull.dimension == 3);
    const auto problems = hull_problems(xyz, hull);
    INFO(join(problems));
    REQUIRE(problems.empty());
}

}  // namespace

TEST_CASE("quickhull: is the default algorithm") {
    CHECK(hullkit::HullOptions{}.algorithm == hullkit::Algorithm::Quickhull);
}

TEST_CASE("quickhull: random points in a cube, a ball and on a sphere match gift wrapping") {
    for (Cloud cloud : {Cloud::Cube, Cloud::Ball, Cloud::Sphere}) {
        for (std::uint64_t seed = 1; seed <= 4; ++seed) {
            const auto xyz = hullkit_test::random_cloud(cloud, cloud == Cloud::Sphere ? 800 : 4000, seed);
            const auto quick = quickhull(xyz);
            INFO("cloud " << static_cast<int>(cloud) << " seed " << seed);
            require_valid(xyz, quick);
            const auto wrapped = hullkit::giftwrap(xyz);
            CHECK(quick.vertices == wrapped.vertices);
            CHECK(quick.face_count() == wrapped.face_count());
            CHECK(quick.volume == Approx(wrapped.volume).epsilon(1e-12));
            CHECK(quick.area == Approx(wrapped.area).epsilon(1e-12));
        }
    }
}

TEST_CASE("quickhull: large clouds exercise the interior box and the spatial order") {
    // 60 000 points: above the sizes where interior points are culled and work is reordered.
    // (Under the sanitizers the cube alone, tests/sanitized.hpp: checking the ball's large hull
    // against every point is what takes the time.)
    for (Cloud cloud : {Cloud::Cube, Cloud::Ball}) {
        if (hullkit_test::kSanitized && cloud == Cloud::Ball) continue;
        const auto xyz = hullkit_test::random_cloud(cloud, 60000, 42);
        const auto hull = quickhull(xyz);
        require_valid(xyz, hull);
    }
    const auto sphere = hullkit_test::random_cloud(Cloud::Sphere, 6000, 43);
    const auto hull = quickhull(sphere);
    require_valid(sphere, hull);
    CHECK(hull.vertices.size() == 6000);
}

TEST_CASE("quickhull: a cube's faces are merged, its face centres and edge midpoints are not vertices") {
    std::vector<double> xyz;
    // All points of the 3x3x3 grid {-1, 0, 1}^3: only the 8 corners are extreme.
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z) xyz.insert(xyz.end(), {double(x), double(y), double(z)});
    hullkit::HullOptions options;
    options.merge_coplanar = true;
    for (auto algorithm : {hullkit::Algorithm::Quickhull, hullkit::Algorithm::Giftwrap}) {
        options.algorithm = algorithm;
        const auto hull = hullkit::hull(xyz, options);
        require_valid(xyz, hull);
        CHECK(hull.vertices == std::vector<std::uint32_t>{0, 2, 6, 8, 18, 20, 24, 26});
        CHECK(hull.face_count() == 12);
        REQUIRE(hull.face_offsets.size() == 7);  // 6 quads
        for (std::size_t f = 0; f < 6; ++f) CHECK(hull.face_offsets[f + 1] - hull.face_offsets[f] == 4);
        CHECK(hull.volume == 8.0);
        CHECK(hull.area == 24.0);
    }
}

TEST_CASE("quickhull: identical points are represented by their lowest index") {
    auto xyz = hullkit_test::random_cloud(Cloud::Sphere, 300, 5);
    const std::vector<double> copy(xyz);
    xyz.insert(xyz.begin(), copy.begin(), copy.end());  // points 0..299 repeat 300..599
    const auto quick = quickhull(xyz);
    require_valid(xyz, quick);
    REQUIRE(quick.vertices.size() == 300);
    CHECK(quick.vertices.back() == 299);
    CHECK(quick.vertices == hullkit::giftwrap(xyz).vertices);
}
