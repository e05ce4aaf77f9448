// The recorded gift wrap (giftwrap_trace): replaying its events gives exactly the one-shot hull.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "hull_checks.hpp"
#include "hullkit/giftwrap.hpp"

using hullkit::GiftwrapEvent;
using hullkit::GiftwrapScan;
using hullkit::GiftwrapTrace;
using hullkit_test::Cloud;

namespace {

/// What a replay of the events rebuilds.
struct Replay {
    std::vector<std::uint32_t> triangles;  ///< the Accept events' triangles, in order
    std::size_t pushes = 0, pops = 0, skips = 0, candidates = 0, replaces = 0, restarts = 0;
};

/// Replays `trace`, checking as it goes: every PopEdge / SkipEdge names the top of the edge stack
/// rebuilt from the PushEdge events, every candidate event belongs to the edge being wrapped, the
/// stack is empty at Done, which comes last and counts the accepted triangles.
Replay replay(const GiftwrapTrace& trace, std::size_t point_count) {
    Replay out;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stack;
    std::pair<std::uint32_t, std::uint32_t> wrapping{~0u, ~0u};  // edge whose face is searched
    std::uint32_t candidate = ~0u;
    REQUIRE(trace.args.size() == 3 * trace.kinds.size());
    REQUIRE(trace.size() > 0);
    for (std::size_t i = 0; i < trace.size(); ++i) {
        const std::uint32_t* a = trace.arguments(i);
        INFO("event " << i << ": " << hullkit::giftwrap_event_name(trace.kind(i)) << " " << a[0] << " " << a[1]
                      << " " << a[2]);
        REQUIRE(static_cast<int>(trace.kinds[i]) < hullkit::kGiftwrapEventKinds);
        if (trace.kind(i) != GiftwrapEvent::Done) {
            REQUIRE(a[0] < point_count);
            REQUIRE(a[1] < point_count);
            REQUIRE(a[2] < point_count);
        }
        switch (trace.kind(i)) {
            case GiftwrapEvent::FirstPoint:
                REQUIRE(i == 0);
                break;
            case GiftwrapEvent::FirstEdge:
                REQUIRE(i == 1);
                break;
            case GiftwrapEvent::VerticalFace:
            case GiftwrapEvent::WrapFirst:
                REQUIRE(i == 2);
                wrapping = {a[0], a[1]};
                break;
            case GiftwrapEvent::PushEdge:
                stack.emplace_back(a[0], a[1]);
                ++out.pushes;
                break;
            case GiftwrapEvent::PopEdge:
            case GiftwrapEvent::SkipEdge:
                REQUIRE(!stack.empty());
                REQUIRE(stack.back().first == a[0]);
                REQUIRE(stack.back().second == a[1]);
                stack.pop_back();
                if (trace.kind(i) == GiftwrapEvent::PopEdge) {
                    ++out.pops;
                    wrapping = {a[0], a[1]};
                    REQUIRE(i + 1 < trace.size());
                    REQUIRE(trace.kind(i + 1) == GiftwrapEvent::Candidate);
                } else {
                    ++out.skips;
                }
                break;
            case GiftwrapEvent::Candidate:
            case GiftwrapEvent::Replace:
            case GiftwrapEvent::Restart:
            case GiftwrapEvent::Coplanar:
                REQUIRE(a[0] == wrapping.first);
                REQUIRE(a[1] == wrapping.second);
                if (trace.kind(i) == GiftwrapEvent::Candidate) {
                    candidate = a[2];
                    ++out.candidates;
                } else if (trace.kind(i) == GiftwrapEvent::Replace) {
                    candidate = a[2];
                    ++out.replaces;
                } else if (trace.kind(i) == GiftwrapEvent::Restart) {
                    REQUIRE(candidate != ~0u);
                    REQUIRE(i + 1 < trace.size());
                    REQUIRE(trace.kind(i + 1) == GiftwrapEvent::Candidate);
                    ++out.restarts;
                }
                break;
            case GiftwrapEvent::Accept:
                out.triangles.insert(out.triangles.end(), a, a + 3);
                break;
            case GiftwrapEvent::Done:
                REQUIRE(i + 1 == trace.size());
                REQUIRE(stack.empty());
                REQUIRE(a[1] == out.triangles.size() / 3);
                break;
        }
    }
    REQUIRE(trace.kind(trace.size() - 1) == GiftwrapEvent::Done);
    return out;
}

/// A bumpy, non-convex closed surface with points inside, like a scanned figurine.
std::vector<double> lumpy(std::size_t n) {
    std::vector<double> xyz;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = std::acos(1.0 - 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(n));
        const double f = 2.399963229728653 * static_cast<double>(i);  // golden angle
        double r = 1.0 + 0.25 * std::sin(3.0 * t) * std::cos(2.0 * f) + 0.1 * std::cos(5.0 * f);
        if (i % 5 == 0) r *= 0.6;  // some points inside
        xyz.insert(xyz.end(), {r * std::sin(t) * std::cos(f), 0.8 * r * std::sin(t) * std::sin(f), 1.2 * r * std::cos(t)});
    }
    return xyz;
}

/// A k x k x k grid of integer points: each face of the cube holds k^2 coplanar points.
std::vector<double> grid(int k) {
    std::vector<double> xyz;
    for (int x = 0; x < k; ++x)
        for (int y = 0; y < k; ++y)
            for (int z = 0; z < k; ++z) xyz.insert(xyz.end(), {double(x), double(y), double(z)});
    return xyz;
}

std::vector<double> cube_with_interior() {
    auto xyz = hullkit_test::cube_corners(2.0);
    const auto inside = hullkit_test::random_cloud(Cloud::Cube, 40, 7);
    xyz.insert(xyz.end(), inside.begin(), inside.end());
    const double extra[][3] = {{2, 0, 0}, {0, -2, 0}, {0, 0, 2}, {2, 2, 0}, {-2, 0, -2}, {2, 2, 2}};
    for (const auto& p : extra) xyz.insert(xyz.end(), p, p + 3);
    return xyz;
}

void check_replays_to_hull(const std::vector<double>& xyz, GiftwrapScan scan) {
    const hullkit::Hull hull = hullkit::giftwrap(xyz, scan);
    REQUIRE(hull.ok());
    REQUIRE(hull.dimension == 3);
    const GiftwrapTrace trace = hullkit::giftwrap_trace(xyz, scan);
    INFO(trace.error);
    REQUIRE(trace.ok());
    CHECK(trace.dimension == 3);
    const Replay r = replay(trace, xyz.size() / 3);
    CHECK(r.triangles == hull.triangles);
    CHECK(trace.triangles == hull.triangles);
    CHECK(r.pops + r.skips == r.pushes);
    CHECK(r.candidates >= r.pops);
    if (scan == GiftwrapScan::SinglePass) {
        CHECK(r.restarts == 0);
    } else {
        CHECK(r.replaces == 0);
        CHECK(r.candidates == r.restarts + r.pops + (trace.kind(2) == GiftwrapEvent::WrapFirst ? 1 : 0));
    }
    // Deterministic.
    const GiftwrapTrace again = hullkit::giftwrap_trace(xyz, scan);
    CHECK(again.kinds == trace.kinds);
    CHECK(again.args == trace.args);
}

}  // namespace

TEST_CASE("giftwrap trace: replay gives the one-shot hull") {
    const auto scan = GENERATE(GiftwrapScan::SinglePass, GiftwrapScan::Restart);
    SECTION("random ball") { check_replays_to_hull(hullkit_test::random_cloud(Cloud::Ball, 300, 11), scan); }
    SECTION("random sphere") { check_replays_to_hull(hullkit_test::random_cloud(Cloud::Sphere, 120, 12), scan); }
    SECTION("cube corners, interior, face and edge points") { check_replays_to_hull(cube_with_interior(), scan); }
    SECTION("grid with coplanar points") { check_replays_to_hull(grid(4), scan); }
    SECTION("lumpy figurine") { check_replays_to_hull(lumpy(400), scan); }
    SECTION("tetrahedron with duplicates") {
        check_replays_to_hull({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0}, scan);
    }
    SECTION("tiny coordinates (rescaled)") {
        auto xyz = hullkit_test::random_cloud(Cloud::Ball, 60, 13);
        for (double& v : xyz) v = std::ldexp(v, -900);
        check_replays_to_hull(xyz, scan);
    }
}

TEST_CASE("giftwrap trace: event kinds and first steps") {
    const auto xyz = hullkit_test::random_cloud(Cloud::Ball, 50, 3);
    const GiftwrapTrace trace = hullkit::giftwrap_trace(xyz);
    REQUIRE(trace.size() > 3);
    CHECK(trace.kind(0) == GiftwrapEvent::FirstPoint);
    CHECK(trace.kind(1) == GiftwrapEvent::FirstEdge);
    CHECK(trace.arguments(1)[0] == trace.arguments(0)[0]);
    // Step 1: the point with the largest x.
    const std::uint32_t first = trace.arguments(0)[0];
    for (std::size_t i = 0; i < xyz.size() / 3; ++i) CHECK(xyz[3 * i] <= xyz[3 * first]);
    CHECK(std::string(hullkit::giftwrap_event_name(GiftwrapEvent::Replace)) == "replace");
    CHECK(std::string(hullkit::giftwrap_event_name(GiftwrapEvent::Done)) == "done");
}

TEST_CASE("giftwrap trace: a cube's vertical face is found without a search") {
    const auto xyz = hullkit_test::cube_corners();
    const GiftwrapTrace trace = hullkit::giftwrap_trace(xyz);
    REQUIRE(trace.ok());
    CHECK(trace.kind(2) == GiftwrapEvent::VerticalFace);
    CHECK(trace.kind(3) == GiftwrapEvent::Accept);
    CHECK(replay(trace, 8).triangles == hullkit::giftwrap(xyz).triangles);
}

TEST_CASE("giftwrap trace: input without volume is not wrapped") {
    SECTION("coplanar") {
        const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0};
        const GiftwrapTrace trace = hullkit::giftwrap_trace(xyz);
        REQUIRE(trace.ok());
        CHECK(trace.dimension == 2);
        REQUIRE(trace.size() == 1);
        CHECK(trace.kind(0) == GiftwrapEvent::Done);
        CHECK(trace.arguments(0)[1] == 2);
        CHECK(trace.triangles == hullkit::giftwrap(xyz).triangles);
    }
    SECTION("collinear and identical") {
        for (const std::vector<double>& xyz :
             {std::vector<double>{0, 0, 0, 1, 1, 1, 2, 2, 2}, std::vector<double>{1, 2, 3, 1, 2, 3}, std::vector<double>{}}) {
            const GiftwrapTrace trace = hullkit::giftwrap_trace(xyz);
            REQUIRE(trace.ok());
            CHECK(trace.dimension == hullkit::giftwrap(xyz).dimension);
            REQUIRE(trace.size() == 1);
            CHECK(trace.kind(0) == GiftwrapEvent::Done);
            CHECK(trace.triangles.empty());
        }
    }
    SECTION("non-finite coordinates") {
        const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0, std::numeric_limits<double>::quiet_NaN(), 0, 0, 0, 1};
        const GiftwrapTrace trace = hullkit::giftwrap_trace(xyz);
        CHECK(!trace.ok());
        CHECK(trace.error == hullkit::giftwrap(xyz).error);
        CHECK(trace.error_point == 2);
        CHECK(trace.size() == 0);
    }
}
