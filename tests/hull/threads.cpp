// The hull does not depend on how it was computed: the same bits for every thread count
// (HullOptions::threads), and HullBuilder given the cloud in pieces of any size, in any order,
// gives what hull() gives for the whole. Every corpus the tests have: the degenerate corpus
// (tiled into large clouds of repeats, so that the threaded path runs and identical points sit in
// different chunks), random clouds, grids, flat and collinear clouds, small random degenerate
// inputs.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "hull_checks.hpp"
#include "hullkit/hull.hpp"
#include "hullkit/mesh_io.hpp"
#include "hullkit/verify.hpp"
#include "sanitized.hpp"

using hullkit::Hull;
using hullkit::HullBuilder;
using hullkit::HullOptions;
using hullkit::StreamedHull;
using hullkit_test::Cloud;
using hullkit_test::same_bits;

namespace {

/// Every field of two hulls, doubles by their bits.
void require_identical(const Hull& a, const Hull& b) {
    REQUIRE(a.error == b.error);
    REQUIRE(a.error_point == b.error_point);
    REQUIRE(a.dimension == b.dimension);
    REQUIRE(a.vertices == b.vertices);
    REQUIRE(a.triangles == b.triangles);
    REQUIRE(a.face_offsets == b.face_offsets);
    REQUIRE(a.face_vertices == b.face_vertices);
    for (int k = 0; k < 3; ++k) REQUIRE(same_bits(a.normal[k], b.normal[k]));
    REQUIRE(same_bits(a.volume, b.volume));
    REQUIRE(same_bits(a.area, b.area));
}

/// A streamed hull with its indices mapped to the caller's, as a Hull, for require_identical.
Hull globalised(const StreamedHull& s) {
    Hull out = s.hull;
    bool fits = true;  // one assertion, not one per corner: a sphere's hull has millions
    for (auto* list : {&out.triangles, &out.vertices, &out.face_vertices}) {
        for (std::uint32_t& v : *list) {
            fits = fits && s.index[v] <= 0xffffffffu;
            v = static_cast<std::uint32_t>(s.index[v]);
        }
    }
    REQUIRE(fits);
    return out;
}

Hull hull_with(const std::vector<double>& xyz, unsigned threads, bool merge = true) {
    HullOptions options;
    options.threads = threads;
    options.merge_coplanar = merge;
    return hullkit::hull(xyz, options);
}

/// `xyz` repeated until it has at least `at_least` points; every copy after the first is shuffled,
/// so the repeats of a point sit at scattered indices and in different chunks.
std::vector<double> tiled(const std::vector<double>& xyz, std::size_t at_least, std::uint64_t seed) {
    const std::size_t n = xyz.size() / 3;
    std::vector<double> out(xyz);
    std::mt19937_64 rng(seed);
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    while (out.size() / 3 < at_least) {
        std::shuffle(order.begin(), order.end(), rng);
        for (std::size_t i : order) out.insert(out.end(), &xyz[3 * i], &xyz[3 * i] + 3);
    }
    return out;
}

std::vector<double> load(const std::filesystem::path& file) {
    std::string text, error;
    REQUIRE(hullkit::read_file(file.string(), &text, &error));
    const hullkit::PointsResult points = hullkit::parse_points(text, file.string());
    REQUIRE(points.ok());
    return points.xyz;
}

/// Large clouds of every shape the threaded path must handle.
std::vector<std::pair<std::string, std::vector<double>>> large_clouds() {
    std::vector<std::pair<std::string, std::vector<double>>> clouds;
    clouds.emplace_back("ball", hullkit_test::random_cloud(Cloud::Ball, 200000, 1));
    // Chunks of whole blocks of 2^18 points (hull.cpp's chunk_candidates), two of three blocks on
    // 2 threads, one each on 3; and shuffled copies of a ball, whose identical points lie in
    // different chunks (the lowest index must win).
    clouds.emplace_back("ball of 6e5", hullkit_test::random_cloud(Cloud::Ball, 600000, 13));
    clouds.emplace_back("ball, repeated", tiled(hullkit_test::random_cloud(Cloud::Ball, 60000, 14), 600000, 15));
    clouds.emplace_back("cube", hullkit_test::random_cloud(Cloud::Cube, 200000, 2));
    clouds.emplace_back("sphere", hullkit_test::random_cloud(Cloud::Sphere, 140000, 3));
    // Clouds mostly on their hull (the split-and-join path), with coplanar faces, repeats and
    // cospherical points.
    clouds.emplace_back("surface of a box", hullkit_test::box_surface(80));
    std::vector<double> prism;
    for (int layer = 0; layer < 90; ++layer) {  // a 400-gon prism: coplanar caps, points on its edges
        for (int k = 0; k < 400; ++k) {
            const double angle = 2 * 3.141592653589793 * k / 400;
            prism.insert(prism.end(), {std::cos(angle), std::sin(angle), double(layer)});
        }
    }
    clouds.emplace_back("prism", prism);
    std::vector<double> lattice;  // the integer points with x^2 + y^2 + z^2 = 5^2 * 13^2 * 17^2
    const int r = 5 * 13 * 17;
    for (int x = -r; x <= r; ++x) {
        for (int y = -r; y <= r; ++y) {
            const long rest = long(r) * r - long(x) * x - long(y) * y;
            if (rest < 0) continue;
            const long z = std::lround(std::sqrt(double(rest)));
            if (z * z != rest) continue;
            lattice.insert(lattice.end(), {double(x), double(y), double(z)});
            if (z != 0) lattice.insert(lattice.end(), {double(x), double(y), double(-z)});
        }
    }
    clouds.emplace_back("cospherical lattice, repeated", tiled(lattice, 70000, 8));
    const std::vector<double> lifted = hullkit_test::lifted_grid(125);
    clouds.emplace_back("lifted grid", lifted);
    clouds.emplace_back("lifted grid, repeated", tiled(lifted, 130000, 9));
    std::vector<double> grid, flat, line;
    for (int x = 0; x < 50; ++x)
        for (int y = 0; y < 50; ++y)
            for (int z = 0; z < 50; ++z) grid.insert(grid.end(), {double(x), double(y), double(z)});
    clouds.emplace_back("grid 50^3", grid);
    const auto ball = hullkit_test::random_cloud(Cloud::Ball, 150000, 4);
    for (std::size_t i = 0; i < ball.size(); i += 3) {
        flat.insert(flat.end(), {ball[i] + 2 * ball[i + 1], ball[i + 1], 3 * ball[i] - ball[i + 1]});  // one plane
        line.insert(line.end(), {ball[i], 2 * ball[i], -ball[i]});
    }
    clouds.emplace_back("tilted plane", flat);
    clouds.emplace_back("line", line);
    clouds.emplace_back("one point repeated", std::vector<double>(3 * 100000, 0.25));
    return clouds;
}

}  // namespace

// [heavy]: too slow for the ThreadSanitizer run, which takes the light case at the end instead.
TEST_CASE("threads: the degenerate corpus, tiled into large clouds of repeats, is hulled alike by 1, 2, 3 and 8 threads",
          "[threads][heavy]") {
    const auto files = hullkit_test::degenerate_corpus();
    REQUIRE(files.size() >= 40);
    for (const auto& file : files) {
        INFO(file.filename().string());
        const std::vector<double> corpus = load(file);
        const std::vector<double> xyz = tiled(corpus, 140000, 7);
        const Hull one = hull_with(xyz, 1);
        REQUIRE(one.ok());
        // The first copy holds the lowest index of every point: the hull is the corpus's own.
        require_identical(one, hull_with(corpus, 1));
        for (unsigned threads : {2u, 3u, 8u}) {
            if (hullkit_test::kSanitized && threads == 2) continue;  // (tests/sanitized.hpp)
            INFO(threads << " threads");
            require_identical(hull_with(xyz, threads), one);
        }
    }
}

TEST_CASE("threads: large clouds (ball, cube, sphere, grid, plane, line, one point, surfaces) alike for 1, 2, 3, 8 threads",
          "[threads][heavy]") {
    for (const auto& [name, xyz] : large_clouds()) {
        INFO(name);
        const Hull one = hull_with(xyz, 1);
        REQUIRE(one.ok());
        const Hull triangles_only = hull_with(xyz, 1, false);
        // Under the sanitizers (tests/sanitized.hpp) 2, 3 and 8 threads, triangles only on 3.
        for (unsigned threads : {0u, 2u, 3u, 8u}) {
            if (hullkit_test::kSanitized && threads == 0) continue;
            INFO(threads << " threads");
            require_identical(hull_with(xyz, threads), one);
            if (!hullkit_test::kSanitized || threads == 3) require_identical(hull_with(xyz, threads, false), triangles_only);
        }
        const hullkit::VerifyReport report = hullkit::verify(xyz, hull_with(xyz, 2));  // exact check of the answer
        INFO(hullkit_test::join(report.lines()));
        CHECK(report.ok);
    }
}

TEST_CASE("threads: a non-finite coordinate is reported at the same point whatever the thread count", "[threads]") {
    std::vector<double> xyz = hullkit_test::random_cloud(Cloud::Ball, 300000, 5);
    xyz[3 * 250000 + 1] = std::nan("");
    xyz[3 * 123456 + 2] = -HUGE_VAL;
    for (unsigned threads : {1u, 2u, 8u}) {
        const Hull hull = hull_with(xyz, threads);
        CHECK(hull.error == "point 123456 has a non-finite z coordinate (-inf)");
        CHECK(hull.error_point == 123456);
    }
}

namespace {

/// HullBuilder fed `xyz` in pieces of `piece` points, in order or with the pieces shuffled; with
/// explicit indices when `indexed`.
StreamedHull streamed(const std::vector<double>& xyz, std::size_t piece, bool shuffled, bool indexed,
                      unsigned threads = 1) {
    HullOptions options;
    options.merge_coplanar = true;
    options.threads = threads;
    HullBuilder builder(options);
    const std::size_t n = xyz.size() / 3;
    std::vector<std::size_t> starts;
    for (std::size_t first = 0; first < n; first += piece) starts.push_back(first);
    if (shuffled) std::shuffle(starts.begin(), starts.end(), std::mt19937_64(n + piece));
    for (std::size_t first : starts) {
        const std::size_t count = std::min(piece, n - first);
        const hullkit::PointSpan span(&xyz[3 * first], count);
        if (indexed) {
            std::vector<std::uint64_t> indices(count);
            std::iota(indices.begin(), indices.end(), std::uint64_t{first});
            std::reverse(indices.begin(), indices.end());  // indices in any order
            std::vector<double> reversed;
            for (std::size_t k = count; k-- > 0;) reversed.insert(reversed.end(), span[k], span[k] + 3);
            REQUIRE(builder.add_indexed(hullkit::PointSpan(reversed.data(), count), indices.data()));
        } else {
            REQUIRE(builder.add(span, first));
        }
    }
    CHECK(builder.points_added() == n);
    StreamedHull result = builder.finish();
    CHECK(result.point_count == n);
    return result;
}

}  // namespace

TEST_CASE("HullBuilder: pieces of 1, 7 and 1000 points give hull() of the whole, every corpus file", "[threads]") {
    for (const auto& file : hullkit_test::degenerate_corpus()) {
        INFO(file.filename().string());
        const std::vector<double> xyz = load(file);
        const Hull whole = hull_with(xyz, 1);
        for (std::size_t piece : {std::size_t{1}, std::size_t{7}, std::size_t{1000}}) {
            INFO("pieces of " << piece);
            const StreamedHull s = streamed(xyz, piece, false, false);
            REQUIRE(s.ok());
            require_identical(globalised(s), whole);
            CHECK(s.points.size() == 3 * s.index.size());
            CHECK(s.index.size() == whole.vertices.size());  // only the vertices are kept
            require_identical(globalised(streamed(xyz, piece, true, true)), whole);
        }
    }
}

TEST_CASE("HullBuilder: random clouds, grids and degenerate draws in pieces, in any order", "[threads]") {
    std::vector<std::pair<std::string, std::vector<double>>> clouds;
    clouds.emplace_back("ball", hullkit_test::random_cloud(Cloud::Ball, 3000, 11));
    clouds.emplace_back("sphere", hullkit_test::random_cloud(Cloud::Sphere, 2000, 12));
    clouds.emplace_back("cube", hullkit_test::random_cloud(Cloud::Cube, 3000, 13));
    std::vector<double> grid;
    for (int x = 0; x < 12; ++x)
        for (int y = 0; y < 12; ++y)
            for (int z = 0; z < 12; ++z) grid.insert(grid.end(), {double(x), double(y), double(z)});
    clouds.emplace_back("grid 12^3", grid);
    for (const auto& [name, xyz] : clouds) {
        INFO(name);
        const Hull whole = hull_with(xyz, 1);
        for (std::size_t piece : {std::size_t{7}, std::size_t{1000}}) {
            INFO("pieces of " << piece);
            require_identical(globalised(streamed(xyz, piece, false, false)), whole);
            require_identical(globalised(streamed(xyz, piece, true, true, 3)), whole);
        }
    }
    std::mt19937_64 rng(99);
    for (int round = 0; round < 300; ++round) {
        int kind = 0;
        const std::vector<double> xyz = hullkit_test::random_degenerate(rng, &kind);
        INFO("round " << round << " kind " << kind);
        const Hull whole = hull_with(xyz, 1);
        for (std::size_t piece : {std::size_t{1}, std::size_t{3}}) {
            require_identical(globalised(streamed(xyz, piece, round % 2 == 0, round % 3 == 0)), whole);
        }
    }
}

TEST_CASE("HullBuilder: large pieces use threads and give the same bits", "[threads]") {
    const auto xyz = hullkit_test::random_cloud(Cloud::Ball, 400000, 21);
    const Hull whole = hull_with(xyz, 1);
    for (unsigned threads : {1u, 2u, 8u}) {
        INFO(threads << " threads");
        require_identical(globalised(streamed(xyz, 150000, false, false, threads)), whole);
    }
}

TEST_CASE("HullBuilder: one add() larger than a step is taken in steps and gives the same bits", "[threads][heavy]") {
    // On one thread a step is 2^19 points, and an add() of 2^20 or more is taken in steps: a
    // ball steps to the end; a sphere keeps what it is given, so the rest goes at once after
    // the first step; a grid repeated puts identical points in different steps (lowest index).
    std::vector<double> grid;
    for (int x = 0; x < 40; ++x)
        for (int y = 0; y < 40; ++y)
            for (int z = 0; z < 40; ++z) grid.insert(grid.end(), {double(x), double(y), double(z)});
    std::vector<std::pair<std::string, std::vector<double>>> clouds;
    clouds.emplace_back("ball", hullkit_test::random_cloud(Cloud::Ball, 1200000, 41));
    clouds.emplace_back("grid 40^3, repeated", tiled(grid, 1100000, 43));
    // (Under the sanitizers without the sphere, whose million-vertex hull is the slow one.)
    if (!hullkit_test::kSanitized) clouds.emplace_back("sphere", hullkit_test::random_cloud(Cloud::Sphere, 1050000, 42));
    for (const auto& [name, xyz] : clouds) {
        INFO(name);
        const Hull whole = hull_with(xyz, 1);
        const std::size_t n = xyz.size() / 3;
        require_identical(globalised(streamed(xyz, n, false, false)), whole);
        // Indices given, in reverse (the sphere's hull, a million vertices, is the slow one).
        if (name != "sphere") require_identical(globalised(streamed(xyz, n, false, true)), whole);
    }
}

TEST_CASE("HullBuilder: map-reduce, the hulls of k parts then the hull of their vertices, is the hull of the whole",
          "[threads]") {
    const auto xyz = hullkit_test::random_cloud(Cloud::Ball, 20000, 31);
    const Hull whole = hull_with(xyz, 1);
    for (std::size_t parts : {2u, 5u}) {
        HullBuilder reduce(HullOptions{});
        const std::size_t n = xyz.size() / 3;
        for (std::size_t p = 0; p < parts; ++p) {  // each part hulled on its own, as on another machine
            const std::size_t first = n * p / parts, last = n * (p + 1) / parts;
            HullBuilder map;
            REQUIRE(map.add(hullkit::PointSpan(&xyz[3 * first], last - first), first));
            const StreamedHull part = map.finish();
            REQUIRE(part.ok());
            REQUIRE(reduce.add_indexed(hullkit::PointSpan(part.points.data(), part.index.size()), part.index.data()));
        }
        HullOptions merged;
        merged.merge_coplanar = true;
        HullBuilder with_faces(merged);
        const StreamedHull result = reduce.finish();
        REQUIRE(result.ok());
        Hull triangles_only = hull_with(xyz, 1, false);
        require_identical(globalised(result), triangles_only);
    }
    (void)whole;
}

TEST_CASE("HullBuilder: errors name the global index, repeats and bad options are refused", "[threads]") {
    std::vector<double> xyz = hullkit_test::random_cloud(Cloud::Ball, 100, 41);
    xyz[3 * 40] = HUGE_VAL;
    HullBuilder builder;
    REQUIRE(builder.add(hullkit::PointSpan(xyz.data(), 30), 1000000000000));
    CHECK_FALSE(builder.add(hullkit::PointSpan(&xyz[90], 70), 1000000000030));
    CHECK(builder.error() == "point 1000000000040 has a non-finite x coordinate (inf)");
    CHECK_FALSE(builder.add(hullkit::PointSpan(xyz.data(), 1), 5));  // stays failed
    const StreamedHull failed = builder.finish();
    CHECK_FALSE(failed.ok());
    CHECK(failed.hull.error_point == 1000000000040);

    HullBuilder twice;
    REQUIRE(twice.add(hullkit::PointSpan(xyz.data(), 10), 0));
    const std::vector<std::uint64_t> again = {3};
    const bool added = twice.add_indexed(hullkit::PointSpan(&xyz[3 * 3], 1), again.data());
    if (added) {
        CHECK(twice.points_kept() > 0);  // point 3 was not kept: a repeat of it cannot be seen
    } else {
        CHECK(twice.error() == "point index 3 was added twice");
    }

    const std::vector<double> wide = {1e-170, 0, 0, 1e170, 0, 0, 0, 1, 0, 0, 0, 1};
    REQUIRE_FALSE(hullkit::hull(wide).ok());
    HullBuilder range;
    CHECK(range.add(hullkit::PointSpan(&wide[6], 2), 2));
    CHECK_FALSE(range.add(hullkit::PointSpan(wide.data(), 2), 0));
    CHECK(range.finish().hull.error == hullkit::hull(wide).error);

    HullOptions seed;
    seed.algorithm = hullkit::Algorithm::Giftwrap;
    HullBuilder giftwrap(seed);
    CHECK_FALSE(giftwrap.add(hullkit::PointSpan(xyz.data(), 3), 0));
    CHECK(giftwrap.finish().hull.error == "HullBuilder runs quickhull with exact side tests only");
}

TEST_CASE("threads: every threaded path once, small enough for ThreadSanitizer", "[threads]") {
    const std::vector<std::pair<std::string, std::vector<double>>> clouds = {
        {"ball (chunks)", hullkit_test::random_cloud(Cloud::Ball, 40000, 51)},
        {"ball (chunks of whole blocks)", hullkit_test::random_cloud(Cloud::Ball, 300000, 54)},
        {"cube (one quickhull, its passes over the points on threads)", hullkit_test::random_cloud(Cloud::Cube, 40000, 53)},
        {"sphere (split and join)", hullkit_test::random_cloud(Cloud::Sphere, 40000, 52)},
        {"lifted grid (split and join, coplanar)", hullkit_test::lifted_grid(100)}};
    for (const auto& [name, xyz] : clouds) {
        INFO(name);
        const Hull one = hull_with(xyz, 1);
        for (unsigned threads : {2u, 8u}) require_identical(hull_with(xyz, threads), one);
        require_identical(globalised(streamed(xyz, 20000, false, false, 2)), one);
    }
}
