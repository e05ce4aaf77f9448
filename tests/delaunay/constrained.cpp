// Constrained Delaunay triangulation (hullkit/constrained.hpp): hand-worked polygons and graphs,
// each through the exact verifier and through independent GMP checks (areas, the even-odd inside of
// every triangle, the rounding of crossings), threads, and errors.
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <vector>

#include <catch2/catch.hpp>

#include "delaunay/constrained_checks.hpp"
#include "hullkit/constrained.hpp"

namespace {

using hullkit::ConstrainedDelaunay;
using hullkit::FillRule;
using hullkit::PointSpan2;

using constrained_test::q;
using constrained_test::twice_area;
using constrained_test::verified;

/// Rings as earcut takes them: flat coordinates and the start of every ring after the first.
struct Rings {
    std::vector<double> xy;
    std::vector<std::uint32_t> starts;
    void ring(std::initializer_list<double> coords) {
        if (!xy.empty()) starts.push_back(static_cast<std::uint32_t>(xy.size() / 2));
        xy.insert(xy.end(), coords);
    }
};

/// Even-odd rule by exact ray crossing (GMP): is (px, py) inside the rings? The point must not be on
/// a ring.
bool inside_even_odd(const Rings& r, const mpq_class& px, const mpq_class& py) {
    bool in = false;
    const std::size_t n = r.xy.size() / 2;
    std::size_t begin = 0;
    for (std::size_t k = 0; k <= r.starts.size(); ++k) {
        const std::size_t end = k < r.starts.size() ? r.starts[k] : n;
        for (std::size_t i = begin; i < end; ++i) {
            const std::size_t j = i + 1 < end ? i + 1 : begin;
            const mpq_class ax = q(r.xy[2 * i]), ay = q(r.xy[2 * i + 1]), bx = q(r.xy[2 * j]), by = q(r.xy[2 * j + 1]);
            if ((ay > py) == (by > py)) continue;
            const mpq_class cross_x = ax + (py - ay) * (bx - ax) / (by - ay);
            if (cross_x > px) in = !in;
        }
        begin = end;
    }
    return in;
}

/// Every returned triangle's centroid is inside by the even-odd rule (exact).
void centroids_inside(const Rings& r, const ConstrainedDelaunay& d) {
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        mpq_class cx = 0, cy = 0;
        for (int k = 0; k < 3; ++k) cx += q(d.coords[2 * d.triangles[3 * t + k]]), cy += q(d.coords[2 * d.triangles[3 * t + k] + 1]);
        INFO("triangle " << t);
        REQUIRE(inside_even_odd(r, cx / 3, cy / 3));
    }
}


ConstrainedDelaunay polygon(const Rings& r, FillRule fill = FillRule::EvenOdd, unsigned threads = 0) {
    hullkit::PolygonOptions options;
    options.fill = fill;
    options.threads = threads;
    ConstrainedDelaunay d = hullkit::triangulate_polygon(PointSpan2(r.xy), r.starts.data(), r.starts.size(), options);
    verified(d, true);
    return d;
}

/// The polygon's triangles, checked: verifier, even-odd centroids, and the expected area.
ConstrainedDelaunay checked_polygon(const Rings& r, double area) {
    const ConstrainedDelaunay d = polygon(r);
    centroids_inside(r, d);
    REQUIRE(twice_area(d) == q(2 * area));
    return d;
}

/// The constrained edges as a graph, to ask whether a segment's ends are joined by a chain of them
/// (the segment, maybe split).
struct SegmentGraph {
    std::map<std::uint32_t, std::vector<std::uint32_t>> next;
    explicit SegmentGraph(const ConstrainedDelaunay& d) {
        for (std::size_t e = 0; e < d.triangles.size(); ++e) {
            if (!d.constrained[e]) continue;
            const std::size_t f = e % 3 == 2 ? e - 2 : e + 1;
            next[d.triangles[e]].push_back(d.triangles[f]);
            next[d.triangles[f]].push_back(d.triangles[e]);
        }
    }
    bool joined(std::uint32_t a, std::uint32_t b) {
        std::set<std::uint32_t> seen{a};
        std::vector<std::uint32_t> stack{a};
        while (!stack.empty()) {
            const std::uint32_t v = stack.back();
            stack.pop_back();
            if (v == b) return true;
            for (std::uint32_t w : next[v])
                if (seen.insert(w).second) stack.push_back(w);
        }
        return false;
    }
};

bool joined(const ConstrainedDelaunay& d, std::uint32_t a, std::uint32_t b) { return SegmentGraph(d).joined(a, b); }

}  // namespace

TEST_CASE("constrained: a square with a square hole, either orientation, both fill rules", "[constrained]") {
    Rings r;
    r.ring({0, 0, 4, 0, 4, 4, 0, 4});
    r.ring({1, 1, 3, 1, 3, 3, 1, 3});  // same orientation as the outer ring
    const ConstrainedDelaunay d = checked_polygon(r, 12);
    CHECK(d.triangle_count() == 8);
    CHECK(d.added_count() == 0);
    // nonzero: a hole wound the same way as the outer ring is filled (winding 2)...
    CHECK(twice_area(polygon(r, FillRule::NonZero)) == 32);
    // ...and one wound the other way is a hole.
    Rings reversed;
    reversed.ring({0, 0, 4, 0, 4, 4, 0, 4});
    reversed.ring({1, 1, 1, 3, 3, 3, 3, 1});
    CHECK(twice_area(polygon(reversed, FillRule::NonZero)) == 24);
    CHECK(twice_area(checked_polygon(reversed, 12)) == 24);
    // Closed rings (last point repeated) give the same triangles.
    Rings closed;
    closed.ring({0, 0, 4, 0, 4, 4, 0, 4, 0, 0});
    closed.ring({1, 1, 3, 1, 3, 3, 1, 3, 1, 1});
    const ConstrainedDelaunay c = checked_polygon(closed, 12);
    CHECK(c.triangle_count() == 8);
    CHECK(c.duplicate_count == 2);
}

TEST_CASE("constrained: touching holes, a hole touching the outer ring, nested islands", "[constrained]") {
    Rings touching;
    touching.ring({0, 0, 10, 0, 10, 10, 0, 10});
    touching.ring({2, 2, 5, 2, 5, 5, 2, 5});
    touching.ring({5, 5, 8, 5, 8, 8, 5, 8});  // shares the point (5, 5) with the first hole
    checked_polygon(touching, 100 - 9 - 9);
    Rings on_outer;
    on_outer.ring({0, 0, 10, 0, 10, 10, 0, 10});
    on_outer.ring({0, 4, 3, 4, 3, 6, 0, 6});  // a notch: shares the edge (0, 4)-(0, 6) with the outer ring
    checked_polygon(on_outer, 100 - 6);
    Rings island;  // a hole with an island in it, given in the opposite order
    island.ring({4, 4, 6, 4, 6, 6, 4, 6});
    island.ring({0, 0, 10, 0, 10, 10, 0, 10});
    island.ring({2, 2, 8, 2, 8, 8, 2, 8});
    checked_polygon(island, 100 - 36 + 4);
}

TEST_CASE("constrained: collinear runs, spikes and repeated points", "[constrained]") {
    Rings collinear;  // every side of the square has points along it
    collinear.ring({0, 0, 1, 0, 2, 0, 3, 0, 4, 0, 4, 1, 4, 2, 4, 3, 4, 4, 2, 4, 0, 4, 0, 2});
    const ConstrainedDelaunay c = checked_polygon(collinear, 16);
    CHECK(c.added_count() == 0);
    Rings spike;  // out to (7, 2) and back along the same line: no area, nothing added
    spike.ring({0, 0, 4, 0, 4, 2, 7, 2, 4, 2, 4, 4, 0, 4});
    checked_polygon(spike, 16);
    Rings repeated;
    repeated.ring({0, 0, 0, 0, 4, 0, 4, 0, 4, 0, 4, 4, 0, 4, 0, 4});
    const ConstrainedDelaunay d = checked_polygon(repeated, 16);
    CHECK(d.duplicate_count == 4);
    for (std::uint32_t v : d.triangles) CHECK(d.representative[v] == v);  // triangles name representatives
}

TEST_CASE("constrained: a self-crossing bow-tie gets its crossing point", "[constrained]") {
    Rings bowtie;
    bowtie.ring({0, 0, 2, 2, 2, 0, 0, 2});
    const ConstrainedDelaunay d = checked_polygon(bowtie, 2);
    CHECK(d.crossing_count == 1);
    REQUIRE(d.added_count() == 1);
    CHECK(d.coords[8] == 1.0);
    CHECK(d.coords[9] == 1.0);
    CHECK(d.triangle_count() == 2);
}

TEST_CASE("constrained: crossings are rounded to the nearest double, exactly", "[constrained]") {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<double> xy;
        for (int i = 0; i < 4; ++i) xy.push_back(u(rng)), xy.push_back(u(rng));
        const double* p = xy.data();
        auto orient = [&](int a, int b, int c) {
            return sgn((q(p[2 * b]) - q(p[2 * a])) * (q(p[2 * c + 1]) - q(p[2 * a + 1])) -
                       (q(p[2 * b + 1]) - q(p[2 * a + 1])) * (q(p[2 * c]) - q(p[2 * a])));
        };
        if (orient(0, 1, 2) * orient(0, 1, 3) >= 0 || orient(2, 3, 0) * orient(2, 3, 1) >= 0) continue;  // no crossing
        const std::uint32_t segments[] = {0, 1, 2, 3};
        const ConstrainedDelaunay d = hullkit::constrained_delaunay(PointSpan2(xy), segments, 2);
        verified(d, false);
        CHECK(d.crossing_count == 1);
        REQUIRE(d.added_count() == 1);
        CHECK(joined(d, 0, 1));
        CHECK(joined(d, 2, 3));
        // The exact crossing, and each rounded coordinate its nearest double.
        const mpq_class o1 = (q(p[6]) - q(p[4])) * (q(p[1]) - q(p[5])) - (q(p[7]) - q(p[5])) * (q(p[0]) - q(p[4]));
        const mpq_class o2 = (q(p[6]) - q(p[4])) * (q(p[3]) - q(p[5])) - (q(p[7]) - q(p[5])) * (q(p[2]) - q(p[4]));
        for (int axis = 0; axis < 2; ++axis) {
            const mpq_class exact = (q(p[2 + axis]) * o1 - q(p[axis]) * o2) / (o1 - o2);
            const double got = d.coords[8 + axis];
            const mpq_class err = abs(exact - q(got));
            CHECK(err <= abs(exact - q(std::nextafter(got, 2.0))));
            CHECK(err <= abs(exact - q(std::nextafter(got, -2.0))));
        }
    }
}

TEST_CASE("constrained: a grid with every grid line constrained", "[constrained]") {
    const int k = 12;
    std::vector<double> xy;
    for (int y = 0; y < k; ++y)
        for (int x = 0; x < k; ++x) xy.push_back(x), xy.push_back(y);
    std::vector<std::uint32_t> segments;
    for (int i = 0; i < k; ++i) {  // whole lines: each passes through k - 2 points
        segments.insert(segments.end(), {std::uint32_t(i * k), std::uint32_t(i * k + k - 1)});
        segments.insert(segments.end(), {std::uint32_t(i), std::uint32_t((k - 1) * k + i)});
    }
    const ConstrainedDelaunay d = hullkit::constrained_delaunay(PointSpan2(xy), segments.data(), segments.size() / 2);
    verified(d, false);
    CHECK(d.triangle_count() == 2 * (k - 1) * (k - 1));
    CHECK(d.added_count() == 0);
    std::size_t flagged = 0;
    for (std::uint8_t f : d.constrained) flagged += f;
    // Every unit grid edge is flagged on both sides, except on the boundary (one side).
    CHECK(flagged == 2 * 2 * k * (k - 1) - 4 * (k - 1));
}

TEST_CASE("constrained: random graphs, crossing and not, through the verifier", "[constrained]") {
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 30; ++trial) {
        const int n = 50 + 30 * trial;
        std::vector<double> xy;
        // Integer coordinates on a small grid in half the trials: collinear and cocircular ties.
        std::uniform_int_distribution<int> small(0, 20);
        std::uniform_real_distribution<double> u(-1, 1);
        for (int i = 0; i < n; ++i) {
            if (trial % 2) xy.push_back(small(rng)), xy.push_back(small(rng));
            else xy.push_back(u(rng)), xy.push_back(u(rng));
        }
        std::uniform_int_distribution<std::uint32_t> pick(0, n - 1);
        std::vector<std::uint32_t> segments;
        for (int s = 0; s < n / 5; ++s) segments.push_back(pick(rng)), segments.push_back(pick(rng));
        INFO("trial " << trial);
        const ConstrainedDelaunay d = hullkit::constrained_delaunay(PointSpan2(xy), segments.data(), segments.size() / 2);
        verified(d, false);
        SegmentGraph graph(d);
        for (std::size_t s = 0; s < segments.size(); s += 2)
            CHECK(graph.joined(d.representative[segments[s]], d.representative[segments[s + 1]]));
    }
}

TEST_CASE("constrained: the same arrays for 1, 2, 3 and 8 threads", "[constrained]") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1000);
    std::vector<double> xy(2 * 60000);
    for (double& v : xy) v = u(rng);
    std::vector<std::uint32_t> segments;
    std::uniform_int_distribution<std::uint32_t> pick(0, 59999);
    for (int s = 0; s < 300; ++s) segments.push_back(pick(rng)), segments.push_back(pick(rng));
    ConstrainedDelaunay first;
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        hullkit::ConstrainedOptions options;
        options.threads = threads;
        ConstrainedDelaunay d = hullkit::constrained_delaunay(PointSpan2(xy), segments.data(), segments.size() / 2, options);
        REQUIRE(d.ok());
        if (threads == 1) {
            verified(d, false);
            first = std::move(d);
            continue;
        }
        CHECK(d.triangles == first.triangles);
        CHECK(d.halfedges == first.halfedges);
        CHECK(d.constrained == first.constrained);
        CHECK(d.coords == first.coords);
    }
}

TEST_CASE("constrained: bad input is an error naming what is wrong", "[constrained]") {
    const std::vector<double> xy = {0, 0, 1, 0, 0, 1, NAN, 2};
    const std::uint32_t bad_segment[] = {0, 1, 1, 9};
    const ConstrainedDelaunay a = hullkit::constrained_delaunay(PointSpan2(xy.data(), 3), bad_segment, 2);
    CHECK_FALSE(a.ok());
    CHECK(a.error_segment == 1);
    CHECK(a.error.find("segment 1") != std::string::npos);
    const ConstrainedDelaunay b = hullkit::constrained_delaunay(PointSpan2(xy), bad_segment, 1);
    CHECK_FALSE(b.ok());
    CHECK(b.error_point == 3);
    const std::uint32_t starts[] = {2, 1};
    const ConstrainedDelaunay c = hullkit::triangulate_polygon(PointSpan2(xy.data(), 3), starts, 2);
    CHECK_FALSE(c.ok());
    CHECK(c.error.find("ring 2") != std::string::npos);
    // Fewer than three points, or collinear ones: no triangles, no error.
    const std::vector<double> line = {0, 0, 1, 1, 2, 2};
    const ConstrainedDelaunay d = hullkit::triangulate_polygon(PointSpan2(line), nullptr, 0);
    REQUIRE(d.ok());
    CHECK(d.dimension == 1);
    CHECK(d.triangles.empty());
}
