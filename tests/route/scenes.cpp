// Route checks on scenes whose answers are worked out by hand (see each case), each also run with
// the obstacles and the route offset by 1e6.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "hullkit/route.hpp"
#include "route_support.hpp"

using namespace hullkit;
using route_test::offset_scene;
using route_test::plate_x;
using route_test::slot_scene;
using route_test::unit_cube_scene;
using route_test::wall_scene;

namespace {

/// The bracket holds `t` (widened by `slack` for the rounding of offset coordinates) and is
/// at most 1e-9 wide.
void require_bracket(const LegReport& leg, double t, double slack) {
    CAPTURE(leg.fraction_lo, leg.fraction_hi, t);
    REQUIRE(leg.fraction_hi - leg.fraction_lo <= 1e-9);
    REQUIRE(leg.fraction_lo <= t + slack);
    REQUIRE(leg.fraction_hi >= t - slack);
}

/// Runs `scene` as given and offset by 1e6 (where the fractions may move by the rounding of
/// coordinates near 1e6, about 1e-10 relative to a leg of length 10).
template <typename Check>
void both_offsets(const Scene& scene, Check&& check) {
    SECTION("at the origin") { check(check_route(scene), 1e-15); }
    SECTION("offset by 1e6") { check(check_route(offset_scene(scene, 1e6)), 3e-10); }
}

}  // namespace

TEST_CASE("route: box through a slot wider than itself is clear with the side gap as clearance") {
    // Cube [0,1]^3 moves 10 along x through a slot y in (-0.25, 1.25) between walls x in [5,6].
    both_offsets(slot_scene(-0.25, 1.25, 0.125), [](const RouteReport& r, double) {
        REQUIRE(r.ok());
        REQUIRE(r.legs.size() == 1);
        CHECK(r.clear);
        CHECK(r.legs[0].status == LegStatus::Clear);
        CHECK(r.legs[0].clearance == Approx(0.25).epsilon(1e-9));
        CHECK(r.min_clearance == Approx(0.25).epsilon(1e-9));
        // The side gap is 0.25 over the whole passage t in [0.4, 0.6]: the fraction lies there.
        CHECK(r.legs[0].fraction_lo >= 0.4 - 1e-9);
        CHECK(r.legs[0].fraction_lo <= 0.6 + 1e-9);
    });
}

TEST_CASE("route: box through a slot narrower than itself hits the wall's face") {
    // The high wall now starts at y = 0.75, inside the cube's y range: the front face x = 1 + 10t
    // reaches x = 5 at t = 0.4 (margin 0), or comes within the margin m at t = (4 - m) / 10.
    SECTION("margin 0") {
        both_offsets(slot_scene(-0.25, 0.75, 0.0), [](const RouteReport& r, double slack) {
            REQUIRE(r.ok());
            CHECK_FALSE(r.clear);
            const LegReport& leg = r.legs[0];
            REQUIRE(leg.status == LegStatus::Hit);
            CHECK(leg.obstacle == 1);
            CHECK(leg.part == 0);
            require_bracket(leg, 0.4, slack);
            CHECK(leg.clearance == 0.0);
        });
    }
    SECTION("margin 0.5") {
        both_offsets(slot_scene(-0.25, 0.75, 0.5), [](const RouteReport& r, double slack) {
            REQUIRE(r.ok());
            const LegReport& leg = r.legs[0];
            REQUIRE(leg.status == LegStatus::Hit);
            CHECK(leg.obstacle == 1);
            require_bracket(leg, 0.35, slack);
            CHECK(leg.clearance <= 0.5);
            CHECK(leg.clearance == Approx(0.5).epsilon(1e-8));
        });
    }
}

TEST_CASE("route: grazing at exactly the margin is a hit, and touching at margin 0 is a hit") {
    SECTION("side gap 0.25 with margin 0.25: within the margin from t = 0.4") {
        // Before x = 5 the nearest wall point is its edge (5, 1.25): sqrt((4 - 10t)^2 + 1/16).
        both_offsets(wall_scene(1.25, 0.25), [](const RouteReport& r, double slack) {
            REQUIRE(r.ok());
            REQUIRE(r.legs[0].status == LegStatus::Hit);
            // A tangential approach: the squared distance exceeds 1/16 by 100 dt^2, which double
            // rounding cannot see below dt ~ 3e-10; lo stays before the contact regardless.
            CHECK(r.legs[0].fraction_lo <= 0.4);
            require_bracket(r.legs[0], 0.4, std::max(slack, 1e-9));
        });
    }
    SECTION("a slot exactly as wide as the cube, margin 0: the faces slide along each other") {
        both_offsets(slot_scene(0.0, 1.0, 0.0), [](const RouteReport& r, double slack) {
            REQUIRE(r.ok());
            REQUIRE(r.legs[0].status == LegStatus::Hit);
            require_bracket(r.legs[0], 0.4, slack);
        });
    }
    SECTION("a slot wider by 2^-40 on each side is clear, clearance 2^-40") {
        const double g = std::ldexp(1.0, -40);
        const RouteReport r = check_route(slot_scene(-g, 1 + g, 0.0));  // at the origin only: 2^-40 is below 1e6's ulp
        REQUIRE(r.ok());
        REQUIRE(r.legs[0].status == LegStatus::Clear);
        CHECK(r.legs[0].clearance == Approx(g).epsilon(1e-9));
    }
}

TEST_CASE("route: a zero-thickness plate that 100-step sampling misses, with its exact fraction") {
    // A cube of side 2^-10 moves 1 along x; the plate x = 0.5 + 2^-8 is inside the cube only for
    // t in [0.5 + 2^-8 - 2^-10, 0.5 + 2^-8] = [0.5029296875, 0.50390625], between samples 0.50
    // and 0.51.
    const Scene s = route_test::thin_plate_scene();
    RouteOptions options;
    options.samples = 100;
    SECTION("at the origin") {
        const RouteReport r = check_route(s, options);
        REQUIRE(r.ok());
        REQUIRE(r.legs[0].status == LegStatus::Hit);
        require_bracket(r.legs[0], 0.5029296875, 0.0);
        CHECK_FALSE(r.legs[0].sampled_hit);
        CHECK(std::isnan(r.legs[0].sampled_fraction));
    }
    SECTION("offset by 1e6") {
        const RouteReport r = check_route(offset_scene(s, 1e6), options);
        REQUIRE(r.ok());
        REQUIRE(r.legs[0].status == LegStatus::Hit);
        require_bracket(r.legs[0], 0.5029296875, 3e-10);
        CHECK_FALSE(r.legs[0].sampled_hit);
    }
    SECTION("1000-step sampling finds it") {
        options.samples = 1000;
        const RouteReport r = check_route(s, options);
        CHECK(r.legs[0].sampled_hit);
        CHECK(r.legs[0].sampled_fraction == Approx(0.503).margin(1e-12));
    }
}

TEST_CASE("route: starting in contact is a start overlap, the next leg starts clear") {
    // The cube [0,1]^3 shares its face x = 1 with the obstacle, then moves down 5 and away.
    both_offsets(route_test::touching_start_scene(), [](const RouteReport& r, double) {
        REQUIRE(r.ok());
        REQUIRE(r.legs.size() == 2);
        CHECK(r.legs[0].status == LegStatus::StartOverlap);
        CHECK(r.legs[0].obstacle == 0);
        CHECK(r.legs[0].fraction_lo == 0.0);
        CHECK(r.legs[1].status == LegStatus::Clear);
        CHECK(r.legs[1].clearance == Approx(4.5).epsilon(1e-9));  // z gap from -4 to 0.5
    });
}

TEST_CASE("route: an obstacle entirely inside the swept hull is a hit") {
    // A small closed box and a lone triangle in the cube's path: the front face reaches x = 5 at
    // t = 0.4 and x = 7 at t = 0.6.
    both_offsets(route_test::bead_scene(), [](const RouteReport& r, double slack) {
        REQUIRE(r.ok());
        REQUIRE(r.legs[0].status == LegStatus::Hit);
        require_bracket(r.legs[0], 0.4, slack);
    });
    both_offsets(route_test::chip_scene(), [](const RouteReport& r, double slack) {
        REQUIRE(r.ok());
        REQUIRE(r.legs[0].status == LegStatus::Hit);
        require_bracket(r.legs[0], 0.6, slack);
    });
}

TEST_CASE("route: the traverse inside a closed vessel starts overlapping, an open one is clear") {
    // The cube [0,1]^3 inside the vessel [-5,6]^3 moves by (1, 1, 1).
    both_offsets(route_test::vessel_scene(true), [](const RouteReport& r, double) {
        REQUIRE(r.ok());
        CHECK(r.legs[0].status == LegStatus::StartOverlap);
        CHECK(r.legs[0].obstacle == 0);
    });
    // Without its top (two triangles) the vessel is an open surface with no inside.
    both_offsets(route_test::vessel_scene(false), [](const RouteReport& r, double) {
        REQUIRE(r.ok());
        CHECK(r.legs[0].status == LegStatus::Clear);
        CHECK(r.legs[0].clearance == Approx(4.0).epsilon(1e-9));  // from x = 2 to the wall at 6
    });
}

TEST_CASE("route: an obstacle inside a closed part starts overlapping") {
    // The box [0.25,0.75]^3 inside the cube [0,1]^3, which moves 0.1 along z.
    both_offsets(route_test::obstacle_inside_part_scene(), [](const RouteReport& r, double) {
        REQUIRE(r.ok());
        CHECK(r.legs[0].status == LegStatus::StartOverlap);
    });
}

TEST_CASE("route: an L-shaped part passes around a post its hull would hit") {
    // The L [0,3]x[0,1] u [0,1]x[0,3] (z in [0,1]) around the post [1.5,1.7]^2 (z in [-5,5]): the
    // post is inside the L's hull but 0.5 from the L. Moving by (0.25, 0.25, 2) brings the L's
    // inner faces to 0.25 from the post at the end of the leg.
    both_offsets(route_test::l_post_scene(0.25, 0.25, 2), [](const RouteReport& r, double) {
        REQUIRE(r.ok());
        REQUIRE(r.legs[0].status == LegStatus::Clear);
        CHECK(r.legs[0].clearance == Approx(0.25).epsilon(1e-9));
        CHECK(r.legs[0].fraction_lo == Approx(1.0).margin(1e-9));
        CHECK(r.legs[0].obstacle == 0);
    });
    // Further, the inner corner of the L meets the post's corner (1.5, 1.5) at t = 0.5/0.75.
    both_offsets(route_test::l_post_scene(0.75, 0.75, 0), [](const RouteReport& r, double slack) {
        REQUIRE(r.ok());
        REQUIRE(r.legs[0].status == LegStatus::Hit);
        require_bracket(r.legs[0], 0.5 / 0.75, slack + 1e-15);
    });
}

TEST_CASE("route: bad scenes name the part, obstacle, triangle or point") {
    Scene s = unit_cube_scene();
    s.route = {0, 0, 0, 1, 0, 0};
    SECTION("no parts") {
        s.parts.clear();
        CHECK(check_route(s).error == "the traverse has no parts");
    }
    SECTION("index out of range") {
        s.obstacles.push_back(plate_x("plate", 5, 0, 1));
        s.obstacles[0].triangles[4] = 9;
        const RouteReport r = check_route(s);
        CHECK_FALSE(r.clear);
        CHECK(r.error == "obstacle 0 ('plate'): triangle 1 refers to point 9, but there are only 4 points");
    }
    SECTION("non-finite coordinate") {
        s.parts[0].xyz[7] = std::nan("");
        CHECK(check_route(s).error == "part 0 ('cube'): point 2 has a non-finite coordinate");
    }
    SECTION("negative margin") {
        s.margin = -1;
        CHECK(check_route(s).error.rfind("margin must be a finite number >= 0", 0) == 0);
    }
    SECTION("one waypoint") {
        s.route = {0, 0, 0};
        const RouteReport r = check_route(s);
        CHECK(r.error == "route: at least 2 waypoints are needed (got 1)");
        CHECK_FALSE(r.clear);
    }
    SECTION("non-finite waypoint") {
        s.route[4] = INFINITY;
        CHECK(check_route(s).error == "route: waypoint 1 has a non-finite coordinate");
    }
}
