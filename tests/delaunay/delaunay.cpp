// hullkit::delaunay on ordinary and degenerate point sets: every result checked by verify_delaunay
// and independent GMP brute force, and both algorithms compared where the giftwrap is affordable.
#include <cmath>
#include <random>

#include "delaunay_checks.hpp"
#include "hullkit/predicates.hpp"
#include "exact/lattice.hpp"

using delaunay_test::both_algorithms;
using delaunay_test::check_delaunay;
using hullkit::Delaunay;
using hullkit::DelaunayAlgorithm;
using hullkit::DelaunayOptions;

namespace {

std::vector<double> uniform_points(std::size_t n, std::uint64_t seed, double scale = 1.0, double offset = 0.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> xy(2 * n);
    for (double& v : xy) v = offset + scale * u(rng);
    return xy;
}

std::vector<double> circle_points(std::size_t n, double radius, bool centre, double offset = 0.0) {
    std::vector<double> xy;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
        xy.push_back(offset + radius * std::cos(t));
        xy.push_back(offset + radius * std::sin(t));
    }
    if (centre) xy.insert(xy.end(), {offset, offset});
    return xy;
}

std::vector<double> grid_points(int nx, int ny, double angle = 0.0) {
    std::vector<double> xy;
    const double c = std::cos(angle), s = std::sin(angle);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            xy.push_back(c * i - s * j);
            xy.push_back(s * i + c * j);
        }
    return xy;
}

/// The seed's Figure 1 set: 1024 random points on the unit sphere (normalised Gaussian vectors,
/// seeded), flattened onto the x-y plane.
std::vector<double> figure1_points() {
    std::mt19937_64 rng(1024);
    std::normal_distribution<double> g(0, 1);
    std::vector<double> xy;
    while (xy.size() < 2 * 1024) {
        const double x = g(rng), y = g(rng), z = g(rng);
        const double r = std::sqrt(x * x + y * y + z * z);
        if (r < 1e-6) continue;
        xy.push_back(x / r);
        xy.push_back(y / r);
    }
    return xy;
}

}  // namespace

TEST_CASE("delaunay: 0 to 3 points", "[delaunay]") {
    REQUIRE(hullkit::delaunay(std::vector<double>{}).dimension == -1);
    Delaunay one = both_algorithms({2.5, -1});
    REQUIRE(one.dimension == 0);
    REQUIRE(one.hull == std::vector<std::uint32_t>{0});
    Delaunay two = both_algorithms({1, 1, 0, 0});
    REQUIRE(two.dimension == 1);
    REQUIRE(two.hull == std::vector<std::uint32_t>{1, 0});
    Delaunay three = both_algorithms({0, 0, 1, 0, 0, 1});
    REQUIRE(three.dimension == 2);
    // Clockwise with y up, from the lowest index, as delaunator 5 returns for this input.
    REQUIRE(three.triangles == std::vector<std::uint32_t>{0, 2, 1});
    REQUIRE(three.halfedges == std::vector<std::int32_t>{-1, -1, -1});
    REQUIRE(three.hull == std::vector<std::uint32_t>{0, 2, 1});
}

TEST_CASE("delaunay: uniform and gaussian", "[delaunay]") {
    both_algorithms(uniform_points(300, 1));
    check_delaunay(uniform_points(20000, 2), hullkit::delaunay(uniform_points(20000, 2)));
    std::mt19937_64 rng(3);
    std::normal_distribution<double> g(0, 1);
    std::vector<double> xy(2 * 500);
    for (double& v : xy) v = g(rng);
    both_algorithms(xy);
}

TEST_CASE("delaunay: the seed's Figure 1 set, identical by both algorithms", "[delaunay]") {
    const std::vector<double> xy = figure1_points();
    const Delaunay d = both_algorithms(xy, 1100);
    REQUIRE(d.dimension == 2);
    REQUIRE(d.duplicate_count == 0);
}

TEST_CASE("delaunay: square grid, rotated grid, hexagonal grid", "[delaunay]") {
    const Delaunay square = both_algorithms(grid_points(12, 9));
    // Every Delaunay face of a square grid is a unit square: 11 * 8 squares, 2 triangles each.
    REQUIRE(square.polygon_offsets.size() == 11 * 8 + 1);
    REQUIRE(square.triangle_count() == 2 * 11 * 8);
    REQUIRE(square.hull.size() == 2 * (12 + 9) - 4);  // points on hull edges included
    both_algorithms(grid_points(15, 15, M_PI / 6));
    std::vector<double> hex;
    for (int j = 0; j < 14; ++j)
        for (int i = 0; i < 14; ++i) {
            hex.push_back(i + 0.5 * (j % 2));
            hex.push_back(j * std::sqrt(3.0) / 2);
        }
    both_algorithms(hex);
    // An exact hexagonal lattice (integer coordinates of a sheared lattice is not cocircular; this
    // one is: x in halves, y in units of 1 with the triangle sides not equal, still checked).
    std::vector<double> tri_lattice;
    for (int j = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i) tri_lattice.insert(tri_lattice.end(), {2.0 * i + (j % 2), 2.0 * j});
    both_algorithms(tri_lattice);
}

TEST_CASE("delaunay: points on a circle, with and without the centre", "[delaunay]") {
    const Delaunay ring = both_algorithms(circle_points(64, 1.0, false));
    REQUIRE(ring.hull.size() == 64);
    both_algorithms(circle_points(64, 1.0, true));
    // Exactly cocircular points: the 12 integer points on the circle of radius 5 (with the 4
    // axis points) and of radius 65 (many Pythagorean triples): one polygon each.
    std::vector<double> r5;
    for (int x = -5; x <= 5; ++x)
        for (int y = -5; y <= 5; ++y)
            if (x * x + y * y == 25) r5.insert(r5.end(), {double(x), double(y)});
    const Delaunay polygon = both_algorithms(r5);
    REQUIRE(polygon.polygon_offsets.size() == 2);
    REQUIRE(polygon.triangle_count() == r5.size() / 2 - 2);
    std::vector<double> r65;
    for (int x = -65; x <= 65; ++x)
        for (int y = -65; y <= 65; ++y)
            if (x * x + y * y == 65 * 65) r65.insert(r65.end(), {double(x), double(y)});
    r65.insert(r65.end(), {0.0, 0.0});
    both_algorithms(r65);
    // Large: incremental only, checked by verify_delaunay.
    const std::vector<double> big = circle_points(20000, 1.0, false);
    const Delaunay many = hullkit::delaunay(big);
    check_delaunay(big, many);
    REQUIRE(many.hull.size() == 20000);
}

TEST_CASE("delaunay: a 3017 x 2018 integer grid subset and a full 300 x 200 grid", "[delaunay]") {
    // delaunator issue: integer grids give degenerate triangles there. Random subset of the big
    // grid plus a full small grid (every face a square).
    std::mt19937_64 rng(3017);
    std::uniform_int_distribution<int> x(0, 3016), y(0, 2017);
    std::vector<double> subset;
    for (int i = 0; i < 30000; ++i) subset.insert(subset.end(), {double(x(rng)), double(y(rng))});
    check_delaunay(subset, hullkit::delaunay(subset));
    const std::vector<double> full = grid_points(300, 200);
    const Delaunay d = hullkit::delaunay(full);
    check_delaunay(full, d);
    REQUIRE(d.triangle_count() == 2 * 299 * 199);
}

TEST_CASE("delaunay: at the edge of the small-lattice shortcut (exact doubles, ties decided alone)", "[delaunay]") {
    // Integers at most 5234 apart take the shortcut (exact/lattice.hpp); 5235 apart do not. On both
    // sides: random integer points, the integer points of a circle of radius 2617 (r^2 = 6848689 has
    // many representations) and a full small grid, checked by verify_delaunay and the brute-force
    // empty-circle test against GMP where small.
    for (const int span : {5234, 5235}) {
        std::mt19937_64 rng(static_cast<unsigned>(span));
        std::uniform_int_distribution<int> any(0, span);
        std::vector<double> xy = {0.0, 0.0, double(span), double(span)};  // the extremes
        for (int i = 0; i < 20000; ++i) xy.insert(xy.end(), {double(any(rng)), double(any(rng))});
        const int r = 2617;
        std::vector<double> ring;
        for (int x = -r; x <= r; ++x) {
            const double y = std::sqrt(double(r) * r - double(x) * x);
            if (y == std::floor(y)) {
                ring.insert(ring.end(), {double(r + x), double(r + y)});
                if (y != 0) ring.insert(ring.end(), {double(r + x), double(r - y)});
            }
        }
        REQUIRE(ring.size() / 2 > 8);
        ring.insert(ring.end(), {0.0, 0.0, double(span), 0.0});  // the box's extent in the second set
        for (int k = 0; k < 30; ++k) ring.insert(ring.end(), {double(span - 3 * k), double(span)});
        INFO("span " << span);
        REQUIRE(hullkit::detail::plane_lattice_exact(xy.data(), xy.size() / 2, double(span)) == (span == 5234));
        check_delaunay(xy, hullkit::delaunay(xy));
        both_algorithms(ring, 2000);
    }
}

TEST_CASE("delaunay: radius 1e10, offset 1e7, tiny scales", "[delaunay]") {
    both_algorithms(uniform_points(300, 5, 1e10));
    both_algorithms(uniform_points(300, 6, 1.0, 1e7));
    both_algorithms(circle_points(100, 1.0, true, 1e7));
    both_algorithms(uniform_points(300, 7, 1e-200));  // rescaled internally
    both_algorithms(uniform_points(300, 8, 1e200));
    std::vector<double> mixed = uniform_points(100, 9, 1e-60);
    mixed.insert(mixed.end(), {1e60, 1e60});
    both_algorithms(mixed);
}

TEST_CASE("delaunay: near-duplicates and exact duplicates", "[delaunay]") {
    std::vector<double> xy = uniform_points(200, 10);
    std::vector<double> near;
    for (std::size_t i = 0; i < 50; ++i) {
        near.push_back(xy[2 * i] + 1e-18);
        near.push_back(xy[2 * i + 1]);
    }
    std::vector<double> with_near = xy;
    with_near.insert(with_near.end(), near.begin(), near.end());
    both_algorithms(with_near);
    std::vector<double> with_dups = xy;
    for (std::size_t i = 0; i < 50; ++i) with_dups.insert(with_dups.end(), {xy[4 * i], xy[4 * i + 1]});
    with_dups.insert(with_dups.end(), {-0.0, 0.0, 0.0, -0.0, 0.0, 0.0});
    const Delaunay d = both_algorithms(with_dups);
    REQUIRE(d.duplicate_count == 50 + 2);
    REQUIRE(d.representative[200] == 0);
    // Many copies of a few points (long runs of one curve key).
    std::vector<double> copies;
    for (int i = 0; i < 3000; ++i) copies.insert(copies.end(), {double(i % 3), double(i % 5 == 0)});
    both_algorithms(copies);
}

TEST_CASE("delaunay: collinear sets", "[delaunay]") {
    const Delaunay line = both_algorithms({3, 3, 0, 0, 2, 2, 1, 1, 2, 2});
    REQUIRE(line.dimension == 1);
    REQUIRE(line.hull == std::vector<std::uint32_t>{1, 3, 2, 0});
    REQUIRE(line.triangles.empty());
    std::vector<double> vertical;
    for (int i = 0; i < 100; ++i) vertical.insert(vertical.end(), {0.1, 0.1 * (i * 37 % 100)});
    REQUIRE(both_algorithms(vertical).dimension == 1);
    // Collinear plus one point: a fan; all line points are hull points.
    std::vector<double> fan = {0.5, 7.0};
    for (int i = 0; i < 50; ++i) fan.insert(fan.end(), {double(i), 0.0});
    const Delaunay f = both_algorithms(fan);
    REQUIRE(f.triangle_count() == 49);
    REQUIRE(f.hull.size() == 51);
}

TEST_CASE("delaunay: bad input is an error naming the point", "[delaunay]") {
    const Delaunay nan = hullkit::delaunay(std::vector<double>{0, 0, 1, 1, NAN, 2});
    REQUIRE_FALSE(nan.ok());
    REQUIRE(nan.error_point == 2);
    REQUIRE(nan.error.find("point 2") != std::string::npos);
    const Delaunay inf = hullkit::delaunay(std::vector<double>{0, 0, 1, INFINITY});
    REQUIRE(inf.error_point == 1);
    const Delaunay span = hullkit::delaunay(std::vector<double>{1e-200, 0, 1e200, 1, 0, 2});
    REQUIRE_FALSE(span.ok());
    REQUIRE(span.error.find("orders of magnitude") != std::string::npos);
}

TEST_CASE("delaunay: delaunator's orientation and half-edge conventions", "[delaunay]") {
    // The square with its centre: delaunator 5.1 returns the hull 0, 3, 2, 1 (clockwise, y up).
    const Delaunay d = both_algorithms({0, 0, 2, 0, 2, 2, 0, 2, 1, 1});
    REQUIRE(d.hull == std::vector<std::uint32_t>{0, 3, 2, 1});
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        const std::uint32_t* v = &d.triangles[3 * t];
        const std::vector<double> xy = {0, 0, 2, 0, 2, 2, 0, 2, 1, 1};
        REQUIRE(hullkit::orient2d(xy[2 * v[0]], xy[2 * v[0] + 1], xy[2 * v[1]], xy[2 * v[1] + 1], xy[2 * v[2]],
                                  xy[2 * v[2] + 1]) < 0);
    }
}

TEST_CASE("delaunay: 1e5 uniform and 1e5 on a circle, checked by verify", "[delaunay][large]") {
    const std::vector<double> a = uniform_points(100000, 12);
    const hullkit::Delaunay d = hullkit::delaunay(a);
    check_delaunay(a, d);
    // The output stage's second thread changes nothing: one thread gives identical arrays.
    hullkit::DelaunayOptions one_thread;
    one_thread.threads = 1;
    const hullkit::Delaunay single = hullkit::delaunay(a, one_thread);
    REQUIRE(single.triangles == d.triangles);
    REQUIRE(single.halfedges == d.halfedges);
    REQUIRE(single.hull == d.hull);
    const std::vector<double> b = circle_points(100000, 1.0, false);
    check_delaunay(b, hullkit::delaunay(b));
}

TEST_CASE("delaunay: the output stage's second thread gives the same arrays (1 thread, 2, every)", "[threads]") {
    // Above the 50 000 points where the output stage takes a second thread; a grid also takes the
    // cocircular path (run beside the counting sort, stopped early).
    std::vector<double> grid;
    for (int x = 0; x < 250; ++x)
        for (int y = 0; y < 240; ++y) grid.insert(grid.end(), {double(x), double(y)});
    for (const std::vector<double>& xy : {uniform_points(60000, 5), grid}) {
        hullkit::DelaunayOptions one;
        one.threads = 1;
        const hullkit::Delaunay reference = hullkit::delaunay(xy, one);
        for (unsigned threads : {0u, 2u, 8u}) {
            hullkit::DelaunayOptions options;
            options.threads = threads;
            const hullkit::Delaunay d = hullkit::delaunay(xy, options);
            REQUIRE(d.triangles == reference.triangles);
            REQUIRE(d.halfedges == reference.halfedges);
            REQUIRE(d.hull == reference.hull);
        }
    }
}

TEST_CASE("delaunay: progress counts the distinct points inserted, rising to the total once, arrays unchanged",
          "[threads]") {
    // 200 000 points with 1000 exact repeats: the total is the number of distinct points.
    std::vector<double> xy = uniform_points(200000, 17);
    for (std::size_t i = 0; i < 1000; ++i) {
        xy[2 * (199000 + i)] = xy[2 * i];
        xy[2 * (199000 + i) + 1] = xy[2 * i + 1];
    }
    const Delaunay reference = hullkit::delaunay(xy);
    for (unsigned threads : {1u, 0u}) {
        CAPTURE(threads);
        std::vector<std::pair<std::size_t, std::size_t>> calls;
        DelaunayOptions options;
        options.threads = threads;
        options.progress = [&calls](std::size_t done, std::size_t total) { calls.emplace_back(done, total); };
        const Delaunay d = hullkit::delaunay(xy, options);
        REQUIRE(d.triangles == reference.triangles);
        REQUIRE(d.halfedges == reference.halfedges);
        REQUIRE(calls.size() >= 3);  // every 65 536 points, then once at the end
        for (std::size_t k = 0; k < calls.size(); ++k) {
            REQUIRE(calls[k].second == 199000);
            if (k > 0) REQUIRE(calls[k].first > calls[k - 1].first);
        }
        REQUIRE(calls.back().first == 199000);
    }
    // Collinear input and gift wrapping report nothing; neither do they fail.
    std::size_t reported = 0;
    DelaunayOptions options;
    options.progress = [&reported](std::size_t, std::size_t) { ++reported; };
    REQUIRE(hullkit::delaunay(std::vector<double>{0, 0, 1, 1, 2, 2, 3, 3}, options).ok());
    options.algorithm = DelaunayAlgorithm::Giftwrap;
    REQUIRE(hullkit::delaunay(uniform_points(300, 3), options).ok());
    REQUIRE(reported == 0);
}
