// RouteOptions::threads and RouteOptions::progress: for every scene the route tests use (the
// hand-worked scenes of scenes.cpp, the crane scene, the oracle's random scenes) the report
// is the same field by field and bit by bit for 1, 2, 3 and 8 threads (and 0, every hardware
// thread), with and without clearance and samples; also on routes of thousands of legs, where the
// threads really share the work; the progress counts increase and end at the leg count.
// The ThreadSanitizer build runs the tag [threads].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"
#include "hullkit/route.hpp"
#include "hullkit/scene_io.hpp"
#include "random_scenes.hpp"
#include "route_support.hpp"

using namespace hullkit;

namespace {

constexpr unsigned kThreadCounts[] = {2, 3, 8, 0};  // each compared with 1

std::uint64_t bits_of(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return bits;
}

std::string hex(double x) {
    char text[40];
    std::snprintf(text, sizeof text, "%a (0x%016llx)", x, static_cast<unsigned long long>(bits_of(x)));
    return text;
}

/// The first field in which the reports differ ("" when none does). Doubles are compared by their
/// bits, so NaN equals NaN and -0 differs from +0; the timings are left out.
std::string first_difference(const RouteReport& a, const RouteReport& b) {
    if (a.error != b.error) return "error: '" + a.error + "' vs '" + b.error + "'";
    if (a.clear != b.clear) return "clear";
    if (a.turned != b.turned) return "turned";
    if (bits_of(a.min_clearance) != bits_of(b.min_clearance)) {
        return "min_clearance: " + hex(a.min_clearance) + " vs " + hex(b.min_clearance);
    }
    if (a.legs.size() != b.legs.size()) {
        return "leg count: " + std::to_string(a.legs.size()) + " vs " + std::to_string(b.legs.size());
    }
    for (std::size_t k = 0; k < a.legs.size(); ++k) {
        const LegReport& x = a.legs[k];
        const LegReport& y = b.legs[k];
        const std::string leg = "legs[" + std::to_string(k) + "].";
        if (x.status != y.status) {
            return leg + "status: " + leg_status_name(x.status) + " vs " + leg_status_name(y.status);
        }
        if (x.obstacle != y.obstacle) return leg + "obstacle";
        if (x.triangle != y.triangle) return leg + "triangle";
        if (x.part != y.part) return leg + "part";
        if (x.sampled_hit != y.sampled_hit) return leg + "sampled_hit";
        if (x.grazing != y.grazing) return leg + "grazing";
        const struct {
            const char* name;
            double x, y;
        } doubles[] = {
            {"fraction_lo", x.fraction_lo, y.fraction_lo},
            {"fraction_hi", x.fraction_hi, y.fraction_hi},
            {"position[0]", x.position[0], y.position[0]},
            {"position[1]", x.position[1], y.position[1]},
            {"position[2]", x.position[2], y.position[2]},
            {"clearance", x.clearance, y.clearance},
            {"sampled_fraction", x.sampled_fraction, y.sampled_fraction},
            {"rotation[0]", x.rotation[0], y.rotation[0]},
            {"rotation[1]", x.rotation[1], y.rotation[1]},
            {"rotation[2]", x.rotation[2], y.rotation[2]},
            {"rotation[3]", x.rotation[3], y.rotation[3]},
        };
        for (const auto& field : doubles) {
            if (bits_of(field.x) != bits_of(field.y)) {
                return leg + field.name + ": " + hex(field.x) + " vs " + hex(field.y);
            }
        }
    }
    return "";
}

/// The option sets every scene is checked with: clearance on and off, samples off and on.
std::vector<RouteOptions> option_sets(std::uint32_t samples) {
    std::vector<RouteOptions> sets;
    for (bool clearance : {true, false}) {
        for (std::uint32_t n : {0u, samples}) {
            RouteOptions options;
            options.clearance = clearance;
            options.samples = n;
            sets.push_back(options);
        }
    }
    return sets;
}

std::string describe(const RouteOptions& options) {
    return std::string("clearance ") + (options.clearance ? "on" : "off") + ", samples " +
           std::to_string(options.samples);
}

/// Checks `scene`'s route with every option set on 1 thread and on each of kThreadCounts, and
/// requires the same report from all of them.
void require_same_for_every_thread_count(const Scene& scene, std::uint32_t samples = 20) {
    const RouteChecker checker(scene);
    for (RouteOptions options : option_sets(samples)) {
        options.threads = 1;
        const RouteReport reference = checker.check(options);
        for (unsigned threads : kThreadCounts) {
            options.threads = threads;
            CAPTURE(describe(options), threads);
            CHECK(first_difference(reference, checker.check(options)) == "");
        }
    }
}

/// A route of `legs` legs wandering through (and beyond) the box of the scene's obstacles: mostly
/// short steps, so that clear legs (with their clearance) mix with hits and start overlaps, and
/// now and then a jump across the box.
std::vector<double> wandering_route(const Scene& scene, std::size_t legs, std::uint64_t seed) {
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (const TriangleMesh& m : scene.obstacles) {
        for (std::size_t i = 0; i < m.xyz.size(); ++i) {
            lo[i % 3] = std::min(lo[i % 3], m.xyz[i]);
            hi[i % 3] = std::max(hi[i % 3], m.xyz[i]);
        }
    }
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> route = {0, 0, 0};
    for (std::size_t k = 0; k < legs; ++k) {
        const bool jump = unit(rng) < 0.05;
        for (int axis = 0; axis < 3; ++axis) {
            const double span = hi[axis] - lo[axis] + 2.0;
            const double from = route[route.size() - 3];
            double to = jump ? lo[axis] - 1.0 + span * unit(rng) : from + 0.1 * span * (unit(rng) - 0.5);
            to = std::clamp(to, lo[axis] - 1.0, hi[axis] + 1.0);
            route.push_back(to);
        }
    }
    return route;
}

Scene crane_scene() {
    SceneResult result = read_scene_file(hullkit_test::data_path("route/crane.json"));
    INFO(result.error);
    REQUIRE(result.ok());
    return result.scene;
}

}  // namespace

TEST_CASE("threads: the report comparison sees one bit and the sign of zero, NaN equals NaN", "[threads]") {
    const RouteReport a = check_route(route_test::touching_start_scene(), RouteOptions{});
    REQUIRE(a.legs.size() == 2);
    REQUIRE(std::isnan(a.legs[0].sampled_fraction));  // no samples: NaN
    RouteReport b = a;
    CHECK(first_difference(a, b) == "");
    b.legs[1].clearance = std::nextafter(a.legs[1].clearance, 1e300);
    CHECK(first_difference(a, b).rfind("legs[1].clearance: ", 0) == 0);
    b = a;
    REQUIRE(a.legs[0].position[1] == 0.0);
    b.legs[0].position[1] = -a.legs[0].position[1];
    CHECK(first_difference(a, b).rfind("legs[0].position[1]: ", 0) == 0);
}

TEST_CASE("threads: the hand-worked scenes give the same report on any thread count", "[threads]") {
    for (const route_test::NamedScene& named : route_test::hand_worked_scenes()) {
        for (double offset : {0.0, 1e6}) {
            CAPTURE(named.name, offset);
            require_same_for_every_thread_count(route_test::offset_scene(named.scene, offset), 100);
        }
    }
}

TEST_CASE("threads: the crane scene gives the same report on any thread count", "[threads]") {
    require_same_for_every_thread_count(crane_scene());
}

TEST_CASE("threads: the oracle's random scenes give the same report on any thread count", "[threads]") {
    std::mt19937_64 rng(route_test::kRandomSceneSeed);
    for (int scene_index = 0; scene_index < 40; ++scene_index) {
        CAPTURE(scene_index);
        require_same_for_every_thread_count(route_test::random_scene(rng, scene_index).scene);
    }
}

TEST_CASE("threads: turning legs give the same report on any thread count", "[threads]") {
    // The oracle's random scenes with an orientation per waypoint: turns of 0 to 180 degrees about
    // random axes, the middle one repeated (a leg of one orientation: the turned parts translated).
    std::mt19937_64 rng(route_test::kRandomSceneSeed + 3);
    std::normal_distribution<double> normal;
    for (int scene_index = 0; scene_index < 20; ++scene_index) {
        CAPTURE(scene_index);
        Scene scene = route_test::random_scene(rng, scene_index).scene;
        scene.pivot[0] = 0.25 * scene_index;
        const std::size_t waypoints = scene.route.size() / 3;
        scene.route.insert(scene.route.begin() + 6, scene.route.begin() + 3, scene.route.begin() + 6);  // waypoint 1 twice
        for (std::size_t k = 0; k <= waypoints; ++k) {
            if (k == 2) {
                scene.rotations.insert(scene.rotations.end(), scene.rotations.end() - 4, scene.rotations.end());
                scene.route[3 * k] += 0.5;  // then moved along x, turned
                continue;
            }
            double q[4] = {normal(rng), normal(rng), normal(rng), normal(rng)};
            const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            for (double c : q) scene.rotations.push_back(c / length);
        }
        require_same_for_every_thread_count(scene, 8);
    }
}

TEST_CASE("threads: thousands of legs, shared by the threads, give the same report", "[threads]") {
    // 2500 legs make dozens of blocks for every thread count (at most 64 legs a block).
    Scene crane = crane_scene();
    crane.route = wandering_route(crane, 2500, 1);
    SECTION("the crane scene") {
        const RouteReport report = RouteChecker(crane).check(RouteOptions{});
        REQUIRE(report.ok());
        REQUIRE(report.legs.size() == 2500);
        // Every kind of leg is there, so every path of the check runs on the threads.
        std::size_t count[3] = {0, 0, 0};
        for (const LegReport& leg : report.legs) ++count[static_cast<int>(leg.status)];
        CAPTURE(count[0], count[1], count[2]);
        CHECK(count[static_cast<int>(LegStatus::Clear)] >= 100);
        CHECK(count[static_cast<int>(LegStatus::Hit)] >= 100);
        CHECK(count[static_cast<int>(LegStatus::StartOverlap)] >= 100);
        require_same_for_every_thread_count(crane, 10);
    }
    SECTION("random scenes") {
        std::mt19937_64 rng(route_test::kRandomSceneSeed + 1);
        for (int scene_index = 0; scene_index < 2; ++scene_index) {
            CAPTURE(scene_index);
            Scene scene = route_test::random_scene(rng, scene_index).scene;
            scene.route = wandering_route(scene, 2000, 2 + scene_index);
            require_same_for_every_thread_count(scene, 10);
        }
    }
}

TEST_CASE("threads: progress counts increase and end at the leg count, once", "[threads]") {
    Scene crane = crane_scene();
    const RouteChecker checker(crane);
    for (std::size_t legs : {std::size_t{1}, std::size_t{2}, std::size_t{63}, std::size_t{2500}}) {
        const std::vector<double> route = wandering_route(crane, legs, 7);
        for (unsigned threads : {1u, 2u, 3u, 8u, 0u}) {
            CAPTURE(legs, threads);
            std::mutex mutex;
            std::vector<std::size_t> counts;
            RouteOptions options;
            options.threads = threads;
            options.progress = [&](std::size_t done) {
                std::lock_guard<std::mutex> lock(mutex);  // the receiver must be thread-safe
                counts.push_back(done);
            };
            const RouteReport report = checker.check(route.data(), legs + 1, options);
            REQUIRE(report.ok());
            REQUIRE_FALSE(counts.empty());
            CHECK(counts.back() == legs);
            CHECK(std::count(counts.begin(), counts.end(), legs) == 1);
            CHECK(std::adjacent_find(counts.begin(), counts.end(), std::greater_equal<>()) == counts.end());
        }
    }
}

TEST_CASE("threads: a failed check reports no progress, the same error on any thread count", "[threads]") {
    const RouteChecker checker(route_test::unit_cube_scene());
    const double one_waypoint[3] = {0, 0, 0};
    const double bad_waypoints[6] = {0, 0, 0, 1, 0, std::numeric_limits<double>::infinity()};
    for (unsigned threads : {1u, 2u, 8u, 0u}) {
        CAPTURE(threads);
        bool called = false;
        RouteOptions options;
        options.threads = threads;
        options.progress = [&](std::size_t) { called = true; };
        CHECK(checker.check(one_waypoint, 1, options).error == "route: at least 2 waypoints are needed (got 1)");
        CHECK(checker.check(bad_waypoints, 2, options).error == "route: waypoint 1 has a non-finite coordinate");
        CHECK_FALSE(called);
    }
}
