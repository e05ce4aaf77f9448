// delaunay_giftwrap_trace: the recorded gift wrap on the lifted points replays to delaunay()'s
// triangles (as a set: the trace wraps in input order, the library in a Hilbert order).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "hullkit/delaunay.hpp"
#include "hullkit/giftwrap.hpp"

using hullkit::GiftwrapEvent;
using hullkit::GiftwrapTrace;

namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::vector<Triangle> sorted_triangles(const std::vector<std::uint32_t>& flat) {
    std::vector<Triangle> out;
    for (std::size_t i = 0; i + 2 < flat.size(); i += 3) out.push_back({flat[i], flat[i + 1], flat[i + 2]});
    std::sort(out.begin(), out.end());
    return out;
}

/// Replays the events (stack from PushEdge, each PopEdge / SkipEdge taking its top) and returns the
/// accepted triangles.
std::vector<std::uint32_t> replay(const GiftwrapTrace& trace) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stack;
    std::vector<std::uint32_t> accepted;
    REQUIRE(trace.size() > 0);
    for (std::size_t i = 0; i < trace.size(); ++i) {
        const std::uint32_t* a = trace.arguments(i);
        INFO("event " << i << " " << hullkit::giftwrap_event_name(trace.kind(i)));
        switch (trace.kind(i)) {
            case GiftwrapEvent::PushEdge: stack.emplace_back(a[0], a[1]); break;
            case GiftwrapEvent::PopEdge:
            case GiftwrapEvent::SkipEdge:
                REQUIRE(!stack.empty());
                REQUIRE(stack.back() == std::make_pair(a[0], a[1]));
                stack.pop_back();
                break;
            case GiftwrapEvent::Accept: accepted.insert(accepted.end(), a, a + 3); break;
            case GiftwrapEvent::Done:
                REQUIRE(i + 1 == trace.size());
                REQUIRE(stack.empty());
                REQUIRE(a[1] == accepted.size() / 3);
                break;
            default: break;
        }
    }
    return accepted;
}

void check(const std::vector<double>& xy) {
    const hullkit::PointSpan2 points(xy);
    hullkit::DelaunayOptions options;
    options.algorithm = hullkit::DelaunayAlgorithm::Giftwrap;
    const hullkit::Delaunay one_shot = hullkit::delaunay(points, options);
    REQUIRE(one_shot.ok());
    const GiftwrapTrace trace = hullkit::delaunay_giftwrap_trace(points);
    REQUIRE(trace.ok());
    CHECK(trace.dimension == one_shot.dimension);
    CHECK(trace.triangles == one_shot.triangles);
    CHECK(sorted_triangles(replay(trace)) == sorted_triangles(one_shot.triangles));
    const GiftwrapTrace again = hullkit::delaunay_giftwrap_trace(points);
    CHECK(again.kinds == trace.kinds);
    CHECK(again.args == trace.args);
}

}  // namespace

TEST_CASE("delaunay giftwrap trace: replay gives delaunay()'s triangles") {
    SECTION("random") {
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        std::vector<double> xy(2 * 300);
        for (double& v : xy) v = unit(rng);
        check(xy);
    }
    SECTION("square grid (cocircular) with duplicates") {
        std::vector<double> xy;
        for (int x = 0; x < 6; ++x)
            for (int y = 0; y < 5; ++y) xy.insert(xy.end(), {double(x), double(y)});
        xy.insert(xy.end(), {2, 2, 0, 0, 5, 4});
        check(xy);
    }
    SECTION("tiny coordinates (rescaled)") {
        std::mt19937_64 rng(6);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        std::vector<double> xy(2 * 50);
        for (double& v : xy) v = std::ldexp(unit(rng), -600);
        check(xy);
    }
}

TEST_CASE("delaunay giftwrap trace: degenerate and invalid input") {
    const std::vector<double> collinear = {0, 0, 1, 1, 2, 2, 3, 3};
    const GiftwrapTrace line = hullkit::delaunay_giftwrap_trace(hullkit::PointSpan2(collinear));
    REQUIRE(line.ok());
    CHECK(line.dimension == 1);
    REQUIRE(line.size() == 1);
    CHECK(line.kind(0) == GiftwrapEvent::Done);
    const std::vector<double> bad = {0, 0, 1, 0, std::numeric_limits<double>::infinity(), 1};
    const GiftwrapTrace failed = hullkit::delaunay_giftwrap_trace(hullkit::PointSpan2(bad));
    CHECK(!failed.ok());
    CHECK(failed.error_point == 2);
    CHECK(failed.size() == 0);
}
