// Route legs that turn: hand-worked answers (a plate turning towards a post, a bar through a slot,
// a sweep only the turning meets), legs of equal orientations checked as translations bit for bit,
// rotations in the scene format, and an oracle of dense static sampling on random scenes.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "hullkit/route.hpp"
#include "hullkit/scene_io.hpp"
#include "random_scenes.hpp"
#include "route_support.hpp"
#include "sanitized.hpp"

using namespace hullkit;
using Quat = std::array<double, 4>;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A turn by `degrees` about the unit axis (x, y, z), as w x y z.
Quat turn(double degrees, double x = 0, double y = 0, double z = 1) {
    const double half = degrees * kPi / 360.0;
    return {std::cos(half), std::sin(half) * x, std::sin(half) * y, std::sin(half) * z};
}

Scene with_rotations(Scene scene, const std::vector<Quat>& rotations) {
    scene.rotations.clear();
    for (const Quat& q : rotations) scene.rotations.insert(scene.rotations.end(), q.begin(), q.end());
    return scene;
}

/// The plate x in [0, 2], y = 0, z in [-1, 1] (two triangles, open): a rod seen from above.
TriangleMesh plate() {
    TriangleMesh m;
    m.name = "plate";
    m.xyz = {0, 0, -1, 2, 0, -1, 2, 0, 1, 0, 0, 1};
    m.triangles = {0, 1, 2, 0, 2, 3};
    return m;
}

/// The plate as a closed slab of half-thickness kSlab (x in [0, 2], |y| <= kSlab, z in [-1, 1]):
/// a convex part, checked through its hull's sweep rather than triangle by triangle.
constexpr double kSlab = 0.01;
TriangleMesh slab() { return route_test::box_mesh("slab", 0, -kSlab, -1, 2, kSlab, 1); }

/// The rod from above: the open plate (half-thickness 0), then the closed slab.
const std::pair<TriangleMesh, double> kRods[] = {{plate(), 0.0}, {slab(), kSlab}};

/// A post of half-width e around (x, y), z in [-2, 2].
TriangleMesh post(double x, double y, double e) { return route_test::box_mesh("post", x - e, y - e, -2, x + e, y + e, 2); }

/// The plate (or `part`) turning about z from yaw a to yaw b (degrees) in place, about the origin.
Scene turning_plate(const TriangleMesh& obstacle, double a, double b, const TriangleMesh& part = plate()) {
    Scene s;
    s.parts.push_back(part);
    s.obstacles.push_back(obstacle);
    s.route = {0, 0, 0, 0, 0, 0};
    return with_rotations(s, {turn(a), turn(b)});
}

/// The pose at fraction t of leg k of `scene`.
void pose_of(const Scene& scene, std::size_t k, double t, double offset[3], double rotation[4]) {
    leg_pose(&scene.route[3 * k], &scene.rotations[4 * k], &scene.route[3 * k + 3], &scene.rotations[4 * k + 4], t,
             offset, rotation);
}

bool contact_at(const RouteChecker& checker, std::size_t k, double t) {
    double offset[3], rotation[4];
    pose_of(checker.scene(), k, t, offset, rotation);
    return checker.static_contact(offset, rotation).contact;
}

/// A hit whose bracket [lo, hi] holds the first contact `contact` (known in closed form) and is at
/// most 1e-7 wide, not a graze, with the pose at hi in contact.
void check_bracket(const RouteChecker& checker, const LegReport& leg, double contact) {
    CAPTURE(contact, leg.fraction_lo, leg.fraction_hi);
    REQUIRE(leg.status == LegStatus::Hit);
    CHECK_FALSE(leg.grazing);
    CHECK(leg.fraction_lo <= contact + 1e-12);
    CHECK(leg.fraction_hi >= contact - 1e-12);
    CHECK(leg.fraction_hi - leg.fraction_lo <= 1e-7);
    CHECK(contact_at(checker, 0, leg.fraction_hi));
}

/// Every field of two leg reports, bit for bit (NaN equals NaN); `rotation` only when asked.
bool same_leg(const LegReport& a, const LegReport& b, bool compare_rotation = true) {
    auto same = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    bool ok = a.status == b.status && a.obstacle == b.obstacle && a.triangle == b.triangle && a.part == b.part &&
              same(a.fraction_lo, b.fraction_lo) && same(a.fraction_hi, b.fraction_hi) && same(a.clearance, b.clearance) &&
              a.sampled_hit == b.sampled_hit && same(a.sampled_fraction, b.sampled_fraction) && a.grazing == b.grazing;
    for (int k = 0; k < 3; ++k) ok = ok && same(a.position[k], b.position[k]);
    for (int k = 0; k < 4 && compare_rotation; ++k) ok = ok && same(a.rotation[k], b.rotation[k]);
    return ok;
}

/// The documented placement (motion.hpp): v -> fl(fl(c + R fl(v - c)) + 0), R the matrix of q.
TriangleMesh rotated(TriangleMesh m, const Quat& q, const double c[3]) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double r[3][3] = {{1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)},
                            {2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)},
                            {2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)}};
    for (std::size_t i = 0; i < m.xyz.size(); i += 3) {
        const double d[3] = {m.xyz[i] - c[0], m.xyz[i + 1] - c[1], m.xyz[i + 2] - c[2]};
        for (int k = 0; k < 3; ++k) m.xyz[i + k] = c[k] + ((r[k][0] * d[0] + r[k][1] * d[1]) + r[k][2] * d[2]);
    }
    return m;
}

}  // namespace

TEST_CASE("turning: a plate turning about one end meets a post at the angle the geometry gives", "[turning]") {
    // Seen from above the plate is a ray from the origin at the yaw angle phi; the post's points
    // Q have the distance Q . (-sin phi, cos phi) from its line, least at the corner (x + e, y - e)
    // while phi < 90 degrees: (y - e) cos phi - (x + e) sin phi = margin at the first contact, and
    // yaw grows linearly with t. The slab meets it when that distance is the margin plus its
    // half-thickness.
    const double x = std::cos(kPi / 6), y = std::sin(kPi / 6), e = 0.05;
    const double A = y - e, B = x + e;
    for (const auto& [rod, half] : kRods)
    for (double margin : {0.0, 0.1}) {
        INFO(rod.name << ", margin " << margin);
        const double contact = (std::acos((margin + half) / std::hypot(A, B)) - std::atan2(B, A)) / (kPi / 2);
        Scene scene = turning_plate(post(x, y, e), 0, 90, rod);
        scene.margin = margin;
        const RouteChecker checker(scene);
        const RouteReport report = checker.check();
        REQUIRE(report.ok());
        const LegReport& leg = report.legs[0];
        check_bracket(checker, leg, contact);
        CHECK(leg.clearance <= margin);
        CHECK_FALSE(contact_at(checker, 0, leg.fraction_lo - 1e-6));
        // The report's pose is the one at lo: yaw 90 lo degrees.
        const Quat at_lo = turn(90 * leg.fraction_lo);
        for (int k = 0; k < 4; ++k) CHECK(leg.rotation[k] == Approx(at_lo[k]).margin(1e-12));
    }
    // The same motion about a pivot: the part drawn at (5, 5, 0), turning about (5, 5, 0), carried
    // back by the waypoints.
    const double contact = std::atan2(A, B) / (kPi / 2);
    Scene moved = turning_plate(post(x, y, e), 0, 90);
    route_test::shift(moved.parts[0], 5, 5, 0);
    moved.pivot[0] = moved.pivot[1] = 5;
    moved.route = {-5, -5, 0, -5, -5, 0};
    const RouteChecker moved_checker(moved);
    check_bracket(moved_checker, moved_checker.check().legs[0], contact);
}

TEST_CASE("turning: a plate turning away from the post is clear, its clearance at the start", "[turning]") {
    const double x = std::cos(kPi / 6), y = std::sin(kPi / 6), e = 0.05;
    for (const auto& [rod, half] : kRods) {
        INFO(rod.name);
        const LegReport leg = check_route(turning_plate(post(x, y, e), 0, -90, rod)).legs[0];
        REQUIRE(leg.status == LegStatus::Clear);
        // At yaw 0 the plate lies on the x axis (x in [0, 2]): the post's face y = y - e is nearest.
        CHECK(leg.clearance == Approx(y - e - half).epsilon(1e-6));
        CHECK(leg.clearance <= (y - e - half) * (1 + 1e-12));
        CHECK(leg.fraction_lo == 0.0);
        CHECK(leg.obstacle == 0);
    }
}

TEST_CASE("turning: a sweep only the turning meets: outside the hull of the end poses", "[turning]") {
    // A small box at 45 degrees, 1.8 from the pivot: outside the triangle (0,0) (2,0) (0,2) that
    // the two end poses span (x + y > 2 on the whole box), inside the quarter disc swept.
    // The slab's end poses span that triangle grown by its half-thickness: still short of the box.
    const double r = 1.8 * std::sqrt(0.5), e = 0.03;
    REQUIRE(2 * (r - e) > 2.0 + 2 * kSlab);
    for (const auto& [rod, half] : kRods) {
        INFO(rod.name);
        const RouteChecker checker(turning_plate(post(r, r, e), 0, 90, rod));
        CHECK_FALSE(contact_at(checker, 0, 0.0));
        CHECK_FALSE(contact_at(checker, 0, 1.0));
        const LegReport leg = checker.check().legs[0];
        REQUIRE(leg.status == LegStatus::Hit);
        CHECK_FALSE(leg.grazing);
        CHECK(leg.fraction_lo > 0.4);
        CHECK(leg.fraction_hi < 0.5);
        CHECK(contact_at(checker, 0, leg.fraction_hi));
    }
}

TEST_CASE("turning: of two posts outside the hull of the end poses, the first met is reported", "[turning]") {
    // The slab turning 90 degrees passes posts at 1.8 from the pivot at two yaws; both lie outside
    // the hull of its end poses, so only the bound's growth finds them, in every sub-interval.
    const double e = 0.03;
    auto post_at = [&](double degrees) {
        return post(1.8 * std::cos(degrees * kPi / 180), 1.8 * std::sin(degrees * kPi / 180), e);
    };
    for (const auto& yaws : {std::array<double, 2>{30, 60}, std::array<double, 2>{60, 30}, std::array<double, 2>{35, 50},
                             std::array<double, 2>{50, 35}}) {
        const double first = std::min(yaws[0], yaws[1]);
        INFO("posts at " << yaws[0] << " and " << yaws[1] << " degrees");
        Scene scene = turning_plate(post_at(yaws[0]), 0, 90, slab());
        scene.obstacles.push_back(post_at(yaws[1]));
        const RouteChecker checker(scene);
        const LegReport leg = checker.check().legs[0];
        REQUIRE(leg.status == LegStatus::Hit);
        CHECK(leg.obstacle == (yaws[0] < yaws[1] ? 0 : 1));
        CHECK(leg.fraction_lo > (first - 5) / 90);
        CHECK(leg.fraction_hi < first / 90);
        CHECK(contact_at(checker, 0, leg.fraction_hi));
        CHECK_FALSE(contact_at(checker, 0, leg.fraction_lo - 1e-6));
    }
}

TEST_CASE("turning: a part that is not its hull: a post in the gap between its two bars", "[turning]") {
    // Two bars (one mesh, two closed boxes) along x at |y| in [0.2, 0.3], turning 90 degrees about
    // z: their hull covers the gap, so every obstacle triangle there is left to the part's own
    // triangles. A square post of half-width e on the axis stays in the gap: clear, nearest when
    // it is turned 45 degrees against the bars (its reach across the gap is then e sqrt 2). A
    // post at (1, 0) meets the lower bar when, in the part's frame, its corner reaches y = -0.2:
    // sin(phi) (1 + e) + e cos(phi) = 0.2.
    TriangleMesh bars = route_test::box_mesh("bars", 0, 0.2, -0.5, 2, 0.3, 0.5);
    const TriangleMesh lower = route_test::box_mesh("lower", 0, -0.3, -0.5, 2, -0.2, 0.5);
    const auto offset = static_cast<std::uint32_t>(bars.xyz.size() / 3);
    bars.xyz.insert(bars.xyz.end(), lower.xyz.begin(), lower.xyz.end());
    for (std::uint32_t v : lower.triangles) bars.triangles.push_back(v + offset);
    const double e = 0.05;

    const LegReport clear = check_route(turning_plate(post(0, 0, e), 0, 90, bars)).legs[0];
    REQUIRE(clear.status == LegStatus::Clear);
    CHECK(clear.clearance == Approx(0.2 - e * std::sqrt(2.0)).epsilon(1e-6));
    CHECK(clear.fraction_lo == Approx(0.5).margin(1e-3));

    const double phi = std::asin(0.2 / std::hypot(1 + e, e)) - std::atan2(e, 1 + e);
    const RouteChecker checker(turning_plate(post(1, 0, e), 0, 90, bars));
    check_bracket(checker, checker.check().legs[0], phi / (kPi / 2));
}

TEST_CASE("turning: a bar passes the slot when turned first, not when turned while passing", "[turning]") {
    Scene slot;
    slot.parts.push_back(route_test::box_mesh("bar", -0.2, -1.5, -0.2, 0.2, 1.5, 0.2));  // 3 long along y
    slot.obstacles.push_back(route_test::box_mesh("low", 5, -10, -1, 6, -0.5, 1));
    slot.obstacles.push_back(route_test::box_mesh("high", 5, 0.5, -1, 6, 10, 1));

    Scene first = slot;  // turn in place, then move along x turned (a translation of the turned bar)
    first.route = {0, 0, 0, 0, 0, 0, 12, 0, 0};
    first = with_rotations(first, {turn(0), turn(90), turn(90)});
    const RouteReport turned_first = check_route(first);
    REQUIRE(turned_first.ok());
    CHECK(turned_first.clear);
    CHECK(turned_first.legs[1].clearance == Approx(0.5 - 0.2).epsilon(1e-9));

    Scene passing = slot;
    passing.route = {0, 0, 0, 12, 0, 0};
    passing = with_rotations(passing, {turn(0), turn(90)});
    const RouteChecker checker(passing);
    const LegReport leg = checker.check().legs[0];
    REQUIRE(leg.status == LegStatus::Hit);
    CHECK_FALSE(leg.grazing);
    CHECK(contact_at(checker, 0, leg.fraction_hi));
    // The bar reaches x = 5 - 0.2 cos(yaw) - ... before t = 5 / 12, still turned less than 40
    // degrees: far wider than the slot.
    CHECK(leg.fraction_hi < 5.0 / 12);
    CHECK(leg.fraction_lo > 4.0 / 12 - 0.2);

    Scene straight = slot;  // never turned: the translation hits as well
    straight.route = {0, 0, 0, 12, 0, 0};
    CHECK(check_route(straight).legs[0].status == LegStatus::Hit);
}

TEST_CASE("turning: legs of equal orientations are today's translations, bit for bit", "[turning]") {
    const double pivot[3] = {0.25, -0.5, 0.125};
    for (const route_test::NamedScene& named : route_test::hand_worked_scenes()) {
        INFO(named.name);
        const Scene& scene = named.scene;
        const std::size_t waypoints = scene.route.size() / 3;
        RouteOptions options;
        options.samples = 16;
        const RouteReport plain = check_route(scene, options);
        REQUIRE(plain.ok());
        // Identity orientations at every waypoint.
        const RouteReport identity = check_route(with_rotations(scene, std::vector<Quat>(waypoints, Quat{1, 0, 0, 0})), options);
        REQUIRE(identity.legs.size() == plain.legs.size());
        for (std::size_t k = 0; k < plain.legs.size(); ++k) CHECK(same_leg(identity.legs[k], plain.legs[k]));
        // One turned orientation throughout, about a pivot: the turned part translated.
        const Quat q = turn(37, 0.48, 0.6, 0.64);
        Scene turned = with_rotations(scene, std::vector<Quat>(waypoints, q));
        std::copy(pivot, pivot + 3, turned.pivot);
        Scene prerotated = scene;
        for (TriangleMesh& part : prerotated.parts) part = rotated(part, q, pivot);
        const RouteReport a = check_route(turned, options), b = check_route(prerotated, options);
        REQUIRE(a.ok());
        REQUIRE(b.ok());
        for (std::size_t k = 0; k < a.legs.size(); ++k) {
            CHECK(same_leg(a.legs[k], b.legs[k], false));
            for (int c = 0; c < 4; ++c) CHECK(a.legs[k].rotation[c] == Approx(q[c]).margin(1e-15));
        }
    }
}

TEST_CASE("turning: rotations in the scene format, and their errors", "[turning]") {
    auto parse = [](const std::string& route, const std::string& traverse_extra = "") {
        return parse_scene("{\"traverse\": {\"parts\": [{\"box\": {\"min\": [0,0,0], \"max\": [1,1,1]}}]" + traverse_extra +
                               "}, \"obstacles\": [], \"route\": " + route + "}",
                           "s.json", nullptr);
    };
    const SceneResult plain = parse("[[0,0,0], {\"position\": [1,2,3]}]");
    REQUIRE(plain.ok());
    CHECK(plain.scene.route == std::vector<double>{0, 0, 0, 1, 2, 3});
    CHECK(plain.scene.rotations.empty());

    const SceneResult kinds = parse(
        "[{\"position\": [0,0,0], \"rotation\": {\"quaternion\": [0.7071067811865476, 0, 0, 0.7071067811865476]}},"
        " {\"position\": [1,0,0], \"rotation\": {\"axis\": [0, 0, 2], \"degrees\": 90}},"
        " {\"position\": [2,0,0], \"rotation\": {\"yaw_pitch_roll_degrees\": [90, 0, 0]}},"
        " [3, 0, 0]]",
        ", \"pivot\": [0.5, 0.5, 0.5]");
    REQUIRE(kinds.ok());
    const std::vector<double>& r = kinds.scene.rotations;
    REQUIRE(r.size() == 16);
    for (int w = 0; w < 3; ++w) {
        CHECK(r[4 * w] == Approx(std::sqrt(0.5)).margin(1e-15));
        CHECK(r[4 * w + 1] == Approx(0).margin(1e-15));
        CHECK(r[4 * w + 2] == Approx(0).margin(1e-15));
        CHECK(r[4 * w + 3] == Approx(std::sqrt(0.5)).margin(1e-15));
    }
    CHECK(std::vector<double>(r.begin() + 12, r.end()) == std::vector<double>{1, 0, 0, 0});
    // The core's own sine and cosine (the same bits natively and in wasm) against the library's.
    for (double degrees : {0.001, 1.0, 37.0, 89.999, 90.0, 135.5, 180.0, 271.0, -33.3, 719.0, 1e5 + 0.7}) {
        const SceneResult one = parse("[{\"position\": [0,0,0], \"rotation\": {\"axis\": [0, 1, 0], \"degrees\": " +
                                      std::to_string(degrees) + "}}, [1,0,0]]");
        REQUIRE(one.ok());
        const double half = std::stod(std::to_string(degrees)) * kPi / 360.0;
        CAPTURE(degrees);
        CHECK(std::fabs(one.scene.rotations[0] - std::cos(half)) <= 4e-16 * (1 + std::fabs(half)));
        CHECK(std::fabs(one.scene.rotations[2] - std::sin(half)) <= 4e-16 * (1 + std::fabs(half)));
    }
    CHECK(kinds.scene.pivot[0] == 0.5);
    // Yaw, then pitch about the turned y: (yaw 90, pitch 90) takes x to -z... and y to x.
    const SceneResult ypr = parse("[{\"position\": [0,0,0], \"rotation\": {\"yaw_pitch_roll_degrees\": [0, 90, 0]}}, [1,0,0]]");
    REQUIRE(ypr.ok());
    CHECK(ypr.scene.rotations[0] == Approx(std::sqrt(0.5)));
    CHECK(ypr.scene.rotations[2] == Approx(std::sqrt(0.5)));

    CHECK(parse("[{\"position\": [0,0,0], \"rotation\": {\"quaternion\": [1, 0, 0, 0.001]}}, [1,0,0]]").error ==
          "s.json: route[0].rotation.quaternion: not a unit quaternion (its length is 1.000000499999875; allowed: 1 "
          "within 1e-9)");
    CHECK(parse("[[0,0,0], {\"position\": [1,0,0], \"rotation\": {\"axis\": [0,0,0], \"degrees\": 5}}]").error ==
          "s.json: route[1].rotation.axis: a zero axis has no direction");
    CHECK(parse("[[0,0,0], {\"position\": [1,0,0], \"rotation\": {\"axis\": [0,0,1]}}]").error ==
          "s.json: route[1].rotation: \"axis\" without \"degrees\"");
    CHECK(parse("[[0,0,0], {\"position\": [1,0,0], \"rotation\": {}}]").error.find("s.json: route[1].rotation: needs one of") == 0);
    CHECK(parse("[[0,0,0], {\"rotation\": {\"axis\": [0,0,1], \"degrees\": 5}}]").error ==
          "s.json: route[1]: missing \"position\"");
    CHECK(parse("[[0,0,0], {\"position\": [1,0,0], \"turn\": 5}]").error ==
          "s.json: route[1].turn: unknown key (known here: position, rotation)");
    CHECK(parse("[[0,0,0], [1,0]]").error ==
          "s.json: route[1]: expected 3 numbers [x, y, z] or {\"position\": [x, y, z], \"rotation\": ...}, got 2 values");
    CHECK(parse("[[0,0,0], [1,0,0]]", ", \"pivot\": [1, 2]").error == "s.json: traverse.pivot: expected 3 numbers [x, y, z], got 2 values");
    const SceneResult misplaced = parse_scene(
        "{\"traverse\": {\"parts\": [{\"box\": {\"min\": [0,0,0], \"max\": [1,1,1]}, \"rotation\": 5}]}, \"obstacles\": [], "
        "\"route\": [[0,0,0],[1,0,0]]}",
        "s.json", nullptr);
    CHECK(misplaced.error.find("s.json: traverse.parts[0].rotation: a rotation belongs to a waypoint") == 0);
}

TEST_CASE("turning: the C++ API checks the rotations it is given", "[turning]") {
    const RouteChecker checker(turning_plate(post(5, 5, 0.1), 0, 0));
    const double route[6] = {0, 0, 0, 1, 0, 0};
    const double bad[8] = {1, 0, 0, 0, 1, 0, 0, 0.01};
    const RouteReport report = checker.check(route, bad, 2);
    CHECK(report.error == "route: waypoint 1: the rotation is not a unit quaternion (length 1.0000499987500624)");
    const double nan[8] = {1, 0, 0, 0, NAN, 0, 0, 0};
    CHECK(checker.check(route, nan, 2).error == "route: waypoint 1: the rotation has a non-finite component");
    const double good[8] = {1, 0, 0, 0, std::sqrt(0.5), 0, 0, std::sqrt(0.5)};
    CHECK(checker.check(route, good, 2).ok());
}

namespace {

/// A random unit quaternion from `rng`: a turn of 0 to 180 degrees about a random axis, composed
/// with `from` (so consecutive waypoints turn by that much).
Quat random_turn(std::mt19937_64& rng, const Quat& from) {
    std::normal_distribution<double> n;
    double a[3] = {n(rng), n(rng), n(rng)};
    const double len = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double degrees = std::uniform_real_distribution<double>(0, 180)(rng);
    const Quat t = turn(degrees, a[0] / len, a[1] / len, a[2] / len);
    return {from[0] * t[0] - from[1] * t[1] - from[2] * t[2] - from[3] * t[3],
            from[0] * t[1] + from[1] * t[0] + from[2] * t[3] - from[3] * t[2],
            from[0] * t[2] - from[1] * t[3] + from[2] * t[0] + from[3] * t[1],
            from[0] * t[3] + from[1] * t[2] - from[2] * t[1] + from[3] * t[0]};
}

}  // namespace

TEST_CASE("turning: the bound: a point stays within r (theta dt)^2 / 8 of its end poses' segment", "[turning]") {
    // The motion of leg_pose (the checker's), a vertex placed by the documented formula, and the
    // bound of motion.hpp with r and theta worked out here; it is tight at the middle of a pure turn.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-3, 3), unit(0, 1);
    double tightest = 0.0;
    for (int trial = 0; trial < 300; ++trial) {
        const Quat q0 = random_turn(rng, {1, 0, 0, 0}), q1 = random_turn(rng, q0);
        const double o0[3] = {u(rng), u(rng), u(rng)};
        const double o1[3] = {trial % 3 ? u(rng) : o0[0], trial % 3 ? u(rng) : o0[1], trial % 3 ? u(rng) : o0[2]};
        const double pivot[3] = {u(rng), u(rng), u(rng)}, v[3] = {u(rng), u(rng), u(rng)};
        // theta and the axis (own coordinates) of q0* q1 on the shorter arc.
        const double dot = q0[0] * q1[0] + q0[1] * q1[1] + q0[2] * q1[2] + q0[3] * q1[3];
        const double theta = 2 * std::acos(std::min(1.0, std::fabs(dot)));
        const Quat c0 = {q0[0], -q0[1], -q0[2], -q0[3]};
        const Quat rel = {c0[0] * q1[0] - c0[1] * q1[1] - c0[2] * q1[2] - c0[3] * q1[3],
                          c0[0] * q1[1] + c0[1] * q1[0] + c0[2] * q1[3] - c0[3] * q1[2],
                          c0[0] * q1[2] - c0[1] * q1[3] + c0[2] * q1[0] + c0[3] * q1[1],
                          c0[0] * q1[3] + c0[1] * q1[2] - c0[2] * q1[1] + c0[3] * q1[0]};
        const double len = std::sqrt(rel[1] * rel[1] + rel[2] * rel[2] + rel[3] * rel[3]);
        const double a[3] = {rel[1] / len, rel[2] / len, rel[3] / len};
        const double d[3] = {v[0] - pivot[0], v[1] - pivot[1], v[2] - pivot[2]};
        const double along = a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
        const double r = std::sqrt(std::max(0.0, d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - along * along));
        auto at = [&](double t, double out[3]) {
            double offset[3], rotation[4];
            leg_pose(o0, q0.data(), o1, q1.data(), t, offset, rotation);
            TriangleMesh point;
            point.xyz = {v[0], v[1], v[2]};
            point = rotated(point, {rotation[0], rotation[1], rotation[2], rotation[3]}, pivot);
            for (int k = 0; k < 3; ++k) out[k] = point.xyz[k] + offset[k];
        };
        const double t0 = unit(rng), t1 = t0 + (1 - t0) * unit(rng);
        double p0[3], p1[3];
        at(t0, p0);
        at(t1, p1);
        const double bound = r * std::pow(theta * (t1 - t0), 2) / 8;
        for (int i = 1; i < 64; ++i) {
            const double s = i / 64.0, t = t0 + s * (t1 - t0);
            double p[3];
            at(t, p);
            // Distance to the segment p0 p1.
            double e[3], w[3], ee = 0, we = 0;
            for (int k = 0; k < 3; ++k) e[k] = p1[k] - p0[k], w[k] = p[k] - p0[k], ee += e[k] * e[k], we += w[k] * e[k];
            const double f = ee > 0 ? std::clamp(we / ee, 0.0, 1.0) : 0.0;
            double dist2 = 0;
            for (int k = 0; k < 3; ++k) dist2 += std::pow(w[k] - f * e[k], 2);
            const double dist = std::sqrt(dist2);
            CAPTURE(trial, t0, t1, s, r, theta, dist, bound);
            REQUIRE(dist <= bound + 1e-12);
            if (trial % 3 == 0 && i == 32 && bound > 1e-6) tightest = std::max(tightest, dist / bound);
        }
    }
    CHECK(tightest > 0.99);  // a pure turn's chord midpoint is r (1 - cos(theta dt / 2)) from the arc
}

TEST_CASE("turning: the static test at a turned pose is the translation test of the turned part", "[turning]") {
    std::mt19937_64 rng(route_test::kRandomSceneSeed + 1);
    for (int scene_index = 0; scene_index < 10; ++scene_index) {
        const route_test::RandomScene random = route_test::random_scene(rng, scene_index);
        Scene scene = random.scene;
        scene.pivot[0] = 0.3, scene.pivot[1] = -0.2, scene.pivot[2] = 0.1;
        const RouteChecker checker(scene);
        for (int k = 0; k < 30; ++k) {
            const Quat q = random_turn(rng, {1, 0, 0, 0});
            Scene turned = scene;
            for (TriangleMesh& part : turned.parts) part = rotated(part, q, scene.pivot);
            const RouteChecker reference(turned);
            const double offset[3] = {random.waypoints[k % 3][0], random.waypoints[k % 3][1], random.waypoints[k % 3][2]};
            const StaticContact a = checker.static_contact(offset, q.data(), true);
            const StaticContact b = reference.static_contact(offset, true);
            CAPTURE(scene_index, k);
            CHECK(a.contact == b.contact);
            if (!b.contact || scene.margin > 0) CHECK(a.distance == Approx(b.distance).epsilon(1e-12).margin(1e-15));
        }
    }
}

TEST_CASE("turning: randomized oracle, 20 000 static poses per turning leg", "[turning]") {
    constexpr int kPoses = 20000;
    std::mt19937_64 rng(route_test::kRandomSceneSeed + 2);
    int hits = 0, clears = 0, starts = 0, grazes = 0;
    const int scenes = hullkit_test::kSanitized ? 8 : 60;
    for (int scene_index = 0; scene_index < scenes; ++scene_index) {
        const route_test::RandomScene random = route_test::random_scene(rng, scene_index);
        Scene scene = random.scene;
        scene.pivot[0] = 0.4 * (scene_index % 3);
        std::vector<Quat> rotations{random_turn(rng, {1, 0, 0, 0})};
        while (rotations.size() < scene.route.size() / 3) rotations.push_back(random_turn(rng, rotations.back()));
        scene = with_rotations(scene, rotations);
        const RouteChecker checker(scene);
        const RouteReport report = checker.check();
        REQUIRE(report.ok());
        for (std::size_t k = 0; k < report.legs.size(); ++k) {
            int first = -1;
            for (int i = 0; i <= kPoses && first < 0; ++i) {
                if (contact_at(checker, k, static_cast<double>(i) / kPoses)) first = i;
            }
            const LegReport& leg = report.legs[k];
            CAPTURE(scene_index, k, first, leg_status_name(leg.status), leg.fraction_lo, leg.fraction_hi, leg.grazing);
            if (first >= 0) {
                REQUIRE(leg.status != LegStatus::Clear);
                if (first == 0) CHECK(leg.status == LegStatus::StartOverlap);
            }
            if (leg.status == LegStatus::StartOverlap) CHECK(contact_at(checker, k, 0.0));
            if (leg.status == LegStatus::Hit) {
                if (first >= 0) CHECK(leg.fraction_lo <= static_cast<double>(first) / kPoses);
                CHECK(leg.fraction_hi - leg.fraction_lo <= 1e-7);
                if (!leg.grazing) CHECK(contact_at(checker, k, leg.fraction_hi));
            }
            if (leg.status == LegStatus::Clear) {
                // The clearance is a distance the traverse reaches, no more than any sampled one.
                double offset[3], rotation[4];
                pose_of(scene, k, leg.fraction_lo, offset, rotation);
                const double there = checker.static_contact(offset, rotation, true).distance;
                CHECK(leg.clearance == Approx(there).epsilon(1e-12));
                for (int i = 0; i <= kPoses; i += 500) {
                    pose_of(scene, k, static_cast<double>(i) / kPoses, offset, rotation);
                    CHECK(leg.clearance <= checker.static_contact(offset, rotation, true).distance * (1 + 1e-6));
                }
            }
            hits += leg.status == LegStatus::Hit;
            clears += leg.status == LegStatus::Clear;
            starts += leg.status == LegStatus::StartOverlap;
            grazes += leg.grazing;
        }
    }
    CAPTURE(hits, clears, starts, grazes);
    CHECK(hits >= scenes / 6);
    CHECK(clears >= scenes / 6);
    CHECK(grazes == 0);
}
