// delaunay3_locate: every answer checked by brute force with GMP rationals (which tetrahedra hold a
// point, which input point is nearest), on random points and on grids where queries fall exactly
// on vertices, edges and faces; barycentric coordinates rebuild the query.
#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "hull/hull_checks.hpp"
#include "hullkit/delaunay3.hpp"
#include "sanitized.hpp"

using hullkit::Delaunay3;
using hullkit::PointSpan;

namespace {

/// The lowest index of the tetrahedra holding q (closed), or -1: brute force, exact.
std::int32_t brute_locate(const std::vector<double>& xyz, const Delaunay3& d, const double* q) {
    for (std::size_t t = 0; t < d.tetrahedron_count(); ++t) {
        const double* p[4];
        for (int k = 0; k < 4; ++k) p[k] = &xyz[3 * d.tetrahedra[4 * t + k]];
        bool holds = true;
        for (int k = 0; k < 4 && holds; ++k) {
            const double* r[4] = {p[0], p[1], p[2], p[3]};
            r[k] = q;
            holds = hullkit_test::rational_orient3d(r[0], r[1], r[2], r[3]) >= 0;
        }
        if (holds) return static_cast<std::int32_t>(t);
    }
    return -1;
}

/// The nearest input point (lowest index among ties), exact.
std::int32_t brute_nearest(const std::vector<double>& xyz, const double* q) {
    std::int32_t best = -1;
    mpq_class best_d;
    for (std::size_t i = 0; i < xyz.size() / 3; ++i) {
        mpq_class dist = 0;
        for (int k = 0; k < 3; ++k) {
            const mpq_class diff = mpq_class(xyz[3 * i + k]) - q[k];
            dist += diff * diff;
        }
        if (best < 0 || dist < best_d) best = static_cast<std::int32_t>(i), best_d = dist;
    }
    return best;
}

void check_queries(const std::vector<double>& xyz, const std::vector<double>& queries, unsigned threads = 1) {
    const Delaunay3 d = hullkit::delaunay3(PointSpan(xyz.data(), xyz.size() / 3));
    REQUIRE(d.ok());
    hullkit::Delaunay3QueryOptions options;
    options.barycentric = true;
    options.nearest = true;
    options.threads = threads;
    const auto r = hullkit::delaunay3_locate(PointSpan(xyz.data(), xyz.size() / 3), d,
                                             PointSpan(queries.data(), queries.size() / 3), options);
    REQUIRE(r.ok());
    for (std::size_t i = 0; i < queries.size() / 3; ++i) {
        const double* q = &queries[3 * i];
        INFO("query " << i << " (" << q[0] << ", " << q[1] << ", " << q[2] << ")");
        const std::int32_t t = r.tetrahedron[i];
        if (d.dimension == 3) REQUIRE(t == brute_locate(xyz, d, q));
        REQUIRE(r.nearest[i] == brute_nearest(xyz, q));
        if (t < 0) {
            REQUIRE(std::isnan(r.barycentric[4 * i]));
            continue;
        }
        double sum = 0, rebuilt[3] = {0, 0, 0};
        for (int k = 0; k < 4; ++k) {
            const double w = r.barycentric[4 * i + k];
            sum += w;
            for (int a = 0; a < 3; ++a) rebuilt[a] += w * xyz[3 * d.tetrahedra[4 * static_cast<std::size_t>(t) + k] + a];
        }
        REQUIRE(sum == Approx(1.0).epsilon(1e-9));
        for (int a = 0; a < 3; ++a) REQUIRE(rebuilt[a] == Approx(q[a]).margin(1e-9));
    }
}

}  // namespace

TEST_CASE("delaunay3_locate: random points and queries inside and outside", "[delaunay3]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1), wide(-1.3, 1.3);
    // (150 random queries under the sanitizers, tests/sanitized.hpp: the exact oracle is the cost.)
    std::vector<double> xyz(3 * 300), queries(3 * (hullkit_test::kSanitized ? 150 : 600));
    for (double& v : xyz) v = u(rng);
    for (double& v : queries) v = wide(rng);
    // Queries exactly at input points: barycentric 1 at the corner, exactly.
    queries.insert(queries.end(), xyz.begin(), xyz.begin() + 30);
    check_queries(xyz, queries);
    const Delaunay3 d = hullkit::delaunay3(PointSpan(xyz.data(), 300));
    hullkit::Delaunay3QueryOptions options;
    options.barycentric = true;
    const auto r = hullkit::delaunay3_locate(PointSpan(xyz.data(), 300), d, PointSpan(xyz.data(), 10), options);
    for (std::size_t i = 0; i < 10; ++i) {
        const std::size_t t = static_cast<std::size_t>(r.tetrahedron[i]);
        for (int k = 0; k < 4; ++k) REQUIRE(r.barycentric[4 * i + k] == (d.tetrahedra[4 * t + k] == i ? 1.0 : 0.0));
    }
}

TEST_CASE("delaunay3_locate: a grid, queries on vertices, edges and faces", "[delaunay3]") {
    std::vector<double> xyz, queries;
    for (int x = 0; x < 5; ++x)
        for (int y = 0; y < 5; ++y)
            for (int z = 0; z < 5; ++z) xyz.insert(xyz.end(), {double(x), double(y), double(z)});
    for (int x = -1; x <= 9; ++x)
        for (int y = -1; y <= 9; y += 2)
            for (int z = -1; z <= 9; z += 3) queries.insert(queries.end(), {0.5 * x, 0.5 * y, 0.5 * z});
    check_queries(xyz, queries, 2);
}

TEST_CASE("delaunay3_locate: barycentric weights of slivers whose rounded volume cancels to 0 (a fuzzer's find)",
          "[delaunay3]") {
    // Eight points within 1e-9 of each other at 6e-154 and one at 7e-77: each tetrahedron's volume,
    // rounded from differences to its far corner, came out 0, and the weights at its own corners NaN.
    const std::vector<double> xyz = {6.9916528033218717e-77, 6.0137435052281011e-154, 6.0134700169990685e-154,
                                     6.0134700169990685e-154, 6.0134700169990685e-154, 6.0134700169990685e-154,
                                     6.0134700169990685e-154, 6.0134700169990685e-154, 6.0134700169990685e-154,
                                     6.0134700169990685e-154, 6.0134700169990685e-154, 7.5051381632391098e-154,
                                     6.0134700169990685e-154, 6.0134700169990685e-154, 6.0134700169990685e-154,
                                     6.0134700169990685e-154, 6.0134700169990685e-154, 6.0134701059094185e-154,
                                     6.0134700169990685e-154, 6.0134700169990685e-154, 6.0134700169990685e-154,
                                     6.0134700170662234e-154, 6.0134700169990685e-154, 6.0134700169990685e-154,
                                     6.0134700169990672e-154, 6.0134700169990685e-154, 6.0134700169990685e-154};
    const PointSpan points(xyz.data(), 9);
    const Delaunay3 d = hullkit::delaunay3(points);
    REQUIRE(d.dimension == 3);
    hullkit::Delaunay3QueryOptions options;
    options.barycentric = true;
    const auto found = hullkit::delaunay3_locate(points, d, points, options);
    REQUIRE(found.ok());
    for (std::size_t i = 0; i < 9; ++i) {
        INFO("point " << i);
        const std::int32_t t = found.tetrahedron[i];
        REQUIRE(t >= 0);
        for (int k = 0; k < 4; ++k) {
            const bool corner = d.tetrahedra[4 * static_cast<std::size_t>(t) + k] == d.representative[i];
            REQUIRE(found.barycentric[4 * i + k] == (corner ? 1.0 : 0.0));
        }
    }
}

TEST_CASE("delaunay3_locate: threads give the same answers", "[delaunay3][threads]") {
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> xyz(3 * 5000), queries(3 * 20000);
    for (double& v : xyz) v = u(rng);
    for (double& v : queries) v = 1.1 * u(rng);
    const Delaunay3 d = hullkit::delaunay3(PointSpan(xyz.data(), 5000));
    hullkit::Delaunay3QueryOptions options;
    options.barycentric = options.nearest = true;
    options.threads = 1;
    const auto one = hullkit::delaunay3_locate(PointSpan(xyz.data(), 5000), d, PointSpan(queries.data(), 20000), options);
    for (unsigned threads : {2u, 3u, 8u}) {
        options.threads = threads;
        const auto other = hullkit::delaunay3_locate(PointSpan(xyz.data(), 5000), d, PointSpan(queries.data(), 20000), options);
        REQUIRE(other.tetrahedron == one.tetrahedron);
        REQUIRE(other.nearest == one.nearest);
        REQUIRE(std::memcmp(other.barycentric.data(), one.barycentric.data(), 8 * one.barycentric.size()) == 0);
    }
}

TEST_CASE("delaunay3_locate: lower dimensions, errors", "[delaunay3]") {
    SECTION("coplanar and collinear points: nearest points, no tetrahedra") {
        std::vector<double> plane, line;
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) plane.insert(plane.end(), {double(i), double(j), 0.0});
        for (int i = 0; i < 8; ++i) line.insert(line.end(), {double(i), 2.0 * i, 0.5});
        std::vector<double> queries = {2.4, 3.6, 5.0, -1, -1, -1, 2.5, 2.5, 0.0, 3.0, 6.0, 0.5};
        check_queries(plane, queries);
        check_queries(line, queries);
    }
    SECTION("a query that is not finite") {
        const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
        const Delaunay3 d = hullkit::delaunay3(PointSpan(xyz.data(), 4));
        const std::vector<double> queries = {0.1, 0.1, 0.1, 0.2, NAN, 0.0};
        const auto r = hullkit::delaunay3_locate(PointSpan(xyz.data(), 4), d, PointSpan(queries.data(), 2));
        REQUIRE_FALSE(r.ok());
        REQUIRE(r.error == "query 1 has a non-finite y coordinate (nan)");
        REQUIRE(r.error_query == 1);
        const std::vector<double> other = {0, 0, 0, 1, 1, 1};
        REQUIRE_FALSE(hullkit::delaunay3_locate(PointSpan(other.data(), 2), d, PointSpan(queries.data(), 1)).ok());
    }
}
