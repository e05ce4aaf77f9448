// Quality meshes (hullkit/constrained.hpp, QualityOptions): Delaunay refinement checked from the
// outside: the exact verifier, every angle and area measured on the output, the covered area
// (GMP) equal to the input's up to the rounding of points placed on segments, every segment still
// covered by constrained edges, conforming meshes Delaunay by an exact brute-force check (GMP),
// small input angles left alone and counted, and errors.
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "delaunay/constrained_checks.hpp"
#include "hullkit/constrained.hpp"

namespace {

using hullkit::ConstrainedDelaunay;
using hullkit::PointSpan2;
using hullkit::QualityOptions;

using constrained_test::q;
using constrained_test::smallest_angle;
using constrained_test::twice_area;
using constrained_test::verified;

/// Twice the area enclosed by rings (even-odd: the shoelace sum with holes wound the other way
/// is taken as the absolute value per ring, outer minus holes).
mpq_class twice_ring_area(const std::vector<double>& xy, std::size_t begin, std::size_t end) {
    mpq_class sum = 0;
    for (std::size_t i = begin; i < end; ++i) {
        const std::size_t j = i + 1 < end ? i + 1 : begin;
        sum += q(xy[2 * i]) * q(xy[2 * j + 1]) - q(xy[2 * j]) * q(xy[2 * i + 1]);
    }
    return abs(sum);
}

double largest_area(const ConstrainedDelaunay& d) {
    double best = 0;
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        const double* a = &d.coords[2 * d.triangles[3 * t]];
        const double* b = &d.coords[2 * d.triangles[3 * t + 1]];
        const double* c = &d.coords[2 * d.triangles[3 * t + 2]];
        best = std::max(best, std::fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2);
    }
    return best;
}


/// The largest triangle area left and right of the line x = split (by each triangle's centroid).
std::pair<double, double> largest_areas_beside(const ConstrainedDelaunay& d, double split) {
    double left = 0, right = 0;
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        const double* a = &d.coords[2 * d.triangles[3 * t]];
        const double* b = &d.coords[2 * d.triangles[3 * t + 1]];
        const double* c = &d.coords[2 * d.triangles[3 * t + 2]];
        const double area = std::fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
        double& largest = (a[0] + b[0] + c[0]) / 3 < split ? left : right;
        largest = std::max(largest, area);
    }
    return {left, right};
}

/// Every constrained edge of the output lies along an input segment: both ends within `slack`
/// (relative to the segment's length) of one of them. Every input segment is covered: the
/// constrained edges near it add up to its length.
void segments_kept(const ConstrainedDelaunay& d, const std::vector<double>& xy, const std::vector<std::uint32_t>& segs) {
    auto distance = [&](const double* p, std::size_t s) {
        const double* a = &xy[2 * segs[2 * s]];
        const double* b = &xy[2 * segs[2 * s + 1]];
        const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
        const double t = std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2, 0.0, 1.0);
        return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy) / std::sqrt(l2);
    };
    std::vector<double> covered(segs.size() / 2, 0.0);
    for (std::size_t e = 0; e < d.triangles.size(); ++e) {
        if (!d.constrained[e] || (d.halfedges[e] >= 0 && static_cast<std::size_t>(d.halfedges[e]) < e)) continue;
        const double* p = &d.coords[2 * d.triangles[e]];
        const double* r = &d.coords[2 * d.triangles[e % 3 == 2 ? e - 2 : e + 1]];
        bool found = false;
        for (std::size_t s = 0; s < segs.size() / 2 && !found; ++s) {
            if (distance(p, s) < 1e-12 && distance(r, s) < 1e-12) {
                covered[s] += std::hypot(r[0] - p[0], r[1] - p[1]);
                found = true;
            }
        }
        INFO("constrained edge " << e << " from (" << p[0] << ", " << p[1] << ") to (" << r[0] << ", " << r[1] << ")");
        REQUIRE(found);
    }
    for (std::size_t s = 0; s < segs.size() / 2; ++s) {
        const double* a = &xy[2 * segs[2 * s]];
        const double* b = &xy[2 * segs[2 * s + 1]];
        INFO("segment " << s);
        REQUIRE(covered[s] == Approx(std::hypot(b[0] - a[0], b[1] - a[1])).epsilon(1e-9));
    }
}

/// Conforming: no point of the output strictly inside any triangle's circumcircle (GMP, all pairs).
void delaunay_everywhere(const ConstrainedDelaunay& d) {
    const std::size_t n = d.coords.size() / 2;
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        const double* p[3];
        for (int k = 0; k < 3; ++k) p[k] = &d.coords[2 * d.triangles[3 * t + k]];
        for (std::size_t v = 0; v < n; ++v) {
            const double* s = &d.coords[2 * v];
            // A clear answer in long double first (a relative margin of 1e-9 on the terms' sizes);
            // GMP decides the rest.
            long double f[3][3], size = 0;
            for (int k = 0; k < 3; ++k) {
                const long double dx = (long double)p[k][0] - s[0], dy = (long double)p[k][1] - s[1];
                f[k][0] = dx, f[k][1] = dy, f[k][2] = dx * dx + dy * dy;
                size = std::max(size, f[k][2]);
            }
            const long double approx = f[0][0] * (f[1][1] * f[2][2] - f[1][2] * f[2][1]) - f[0][1] * (f[1][0] * f[2][2] - f[1][2] * f[2][0]) +
                                       f[0][2] * (f[1][0] * f[2][1] - f[1][1] * f[2][0]);
            if (approx > 1e-9L * size * size) continue;
            mpq_class m[3][3];
            for (int k = 0; k < 3; ++k) {
                const mpq_class dx = q(p[k][0]) - q(s[0]), dy = q(p[k][1]) - q(s[1]);
                m[k][0] = dx, m[k][1] = dy, m[k][2] = dx * dx + dy * dy;
            }
            const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                                  m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                                  m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
            // Clockwise triangles: a point strictly inside makes the determinant negative.
            if (sgn(det) < 0) {
                INFO("triangle " << t << ", point " << v);
                REQUIRE(sgn(det) >= 0);
            }
        }
    }
}

/// Rings as closed index loops (the segments of a .poly).
std::vector<std::uint32_t> ring_segments(std::initializer_list<std::pair<std::uint32_t, std::uint32_t>> rings) {
    std::vector<std::uint32_t> segs;
    for (const auto& r : rings) {
        for (std::uint32_t i = r.first; i < r.second; ++i) segs.push_back(i), segs.push_back(i + 1 < r.second ? i + 1 : r.first);
    }
    return segs;
}

}  // namespace

TEST_CASE("refine: a square with a square hole at 20, 28.6 and 33 degrees", "[refine]") {
    const std::vector<double> xy = {0, 0, 10, 0, 10, 10, 0, 10, 3, 3, 7, 3, 7, 6, 3, 6};
    const std::uint32_t starts[] = {4};
    const mpq_class expected = twice_ring_area(xy, 0, 4) - twice_ring_area(xy, 4, 8);
    const auto segs = ring_segments({{0, 4}, {4, 8}});
    for (double angle : {20.0, 28.6, 33.0}) {
        INFO("min angle " << angle);
        hullkit::PolygonOptions options;
        options.quality.min_angle = angle;
        const ConstrainedDelaunay d = hullkit::triangulate_polygon(PointSpan2(xy), starts, 1, options);
        verified(d, true);
        REQUIRE(d.unrefined_count == 0);
        REQUIRE(d.steiner_count > 0);
        REQUIRE(d.steiner_count == d.added_count());
        REQUIRE(smallest_angle(d) >= angle);
        // Points on these axis-parallel segments are exact: the area is the polygon's exactly.
        REQUIRE(twice_area(d) == expected);
        segments_kept(d, xy, segs);
    }
}

TEST_CASE("refine: a maximum area, global and per region", "[refine]") {
    const std::vector<double> xy = {0, 0, 4, 0, 4, 4, 0, 4, 2, 0, 2, 4};
    const std::vector<std::uint32_t> segs = {0, 4, 4, 1, 1, 2, 2, 5, 5, 3, 3, 0, 4, 5};
    hullkit::ConstrainedOptions options;
    options.quality.max_area = 0.5;
    ConstrainedDelaunay d = hullkit::constrained_delaunay(PointSpan2(xy), segs.data(), segs.size() / 2, options);
    verified(d, true);
    REQUIRE(largest_area(d) <= 0.5);
    REQUIRE(twice_area(d) == 32);
    segments_kept(d, xy, segs);
    // The right half gets a finer bound of its own.
    options.regions.push_back({3, 2, 0.05});
    d = hullkit::constrained_delaunay(PointSpan2(xy), segs.data(), segs.size() / 2, options);
    verified(d, true);
    const auto [left, right] = largest_areas_beside(d, 2);
    REQUIRE(left <= 0.5);
    REQUIRE(left > 0.05);
    REQUIRE(right <= 0.05);
    REQUIRE(twice_area(d) == 32);
    // Each triangle's region point (Triangle's -A attributes come from it): 0 on the right, none on the left.
    REQUIRE(d.triangle_region.size() == d.triangle_count());
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        const double cx = (d.coords[2 * d.triangles[3 * t]] + d.coords[2 * d.triangles[3 * t + 1]] + d.coords[2 * d.triangles[3 * t + 2]]) / 3;
        REQUIRE(d.triangle_region[t] == (cx < 2 ? -1 : 0));
    }
}

namespace {

/// The constrained edges of the output, each once, as (lower, higher) vertex pairs.
std::vector<std::pair<std::uint32_t, std::uint32_t>> constrained_edges(const ConstrainedDelaunay& d) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    for (std::size_t e = 0; e < d.triangles.size(); ++e) {
        if (!d.constrained[e] || (d.halfedges[e] >= 0 && static_cast<std::size_t>(d.halfedges[e]) < e)) continue;
        const std::uint32_t a = d.triangles[e], b = d.triangles[e % 3 == 2 ? e - 2 : e + 1];
        out.emplace_back(std::min(a, b), std::max(a, b));
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST_CASE("refine: keep_segments (Triangle's -Y, -YY) adds no point on the kept segments", "[refine]") {
    // A polygon: every ring edge is on the boundary; -Y keeps all eight whole.
    const std::vector<double> ring = {0, 0, 10, 0, 10, 10, 0, 10, 3, 3, 7, 3, 7, 6, 3, 6};
    const std::uint32_t starts[] = {4};
    hullkit::PolygonOptions polygon;
    polygon.quality.min_angle = 25;
    polygon.quality.max_area = 0.5;
    polygon.quality.keep_segments = 1;
    ConstrainedDelaunay d = hullkit::triangulate_polygon(PointSpan2(ring), starts, 1, polygon);
    verified(d, true);
    REQUIRE(d.steiner_count > 20);
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> rings = {{0, 1}, {0, 3}, {1, 2}, {2, 3}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
    REQUIRE(constrained_edges(d) == rings);
    REQUIRE(largest_area(d) <= 0.5);
    REQUIRE(twice_area(d) == twice_ring_area(ring, 0, 4) - twice_ring_area(ring, 4, 8));
    // A graph, the square [0, 4]^2 halved by x = 2: -Y keeps the outline whole and splits the
    // middle segment; -YY keeps that whole too. Without keep_segments both are split.
    const std::vector<double> xy = {0, 0, 4, 0, 4, 4, 0, 4, 2, 0, 2, 4};
    const std::vector<std::uint32_t> segs = {0, 4, 4, 1, 1, 2, 2, 5, 5, 3, 3, 0, 4, 5};
    const auto on_line = [&](const ConstrainedDelaunay& m, double x) {  // constrained edges along x = const
        std::size_t count = 0;
        for (const auto& [a, b] : constrained_edges(m)) count += m.coords[2 * a] == x && m.coords[2 * b] == x;
        return count;
    };
    for (unsigned keep : {0u, 1u, 2u}) {
        INFO("keep_segments " << keep);
        hullkit::ConstrainedOptions options;
        options.remove_exterior = true;
        options.quality.max_area = 0.1;
        options.quality.min_angle = 20;
        options.quality.keep_segments = keep;
        d = hullkit::constrained_delaunay(PointSpan2(xy), segs.data(), segs.size() / 2, options);
        verified(d, true);
        REQUIRE(twice_area(d) == 32);
        REQUIRE(largest_area(d) <= 0.1);
        REQUIRE((on_line(d, 0) == 1) == (keep >= 1));
        REQUIRE((on_line(d, 4) == 1) == (keep >= 1));
        REQUIRE((on_line(d, 2) == 1) == (keep == 2));
        const std::vector<std::pair<std::uint32_t, std::uint32_t>> edges = constrained_edges(d);
        const std::vector<std::pair<std::uint32_t, std::uint32_t>> outline = {{0, 3}, {0, 4}, {1, 2}, {1, 4}, {2, 5}, {3, 5}};
        for (const auto& edge : outline) REQUIRE(std::binary_search(edges.begin(), edges.end(), edge) == (keep >= 1));
        if (keep == 2) REQUIRE(edges.size() == 7);
    }
    hullkit::ConstrainedOptions bad;
    bad.quality.keep_segments = 3;
    REQUIRE(hullkit::constrained_delaunay(PointSpan2(xy), segs.data(), segs.size() / 2, bad).error.find("keep_segments must be") !=
            std::string::npos);
}

TEST_CASE("refine: a user's test (Triangle's -u) sees the input's units and is met", "[refine]") {
    // A square of side 2^-300: the core scales such points before its exact tests; the function
    // must still see the input's coordinates.
    const double side = std::ldexp(1.0, -300);
    const std::vector<double> xy = {0, 0, side, 0, side, side, 0, side};
    hullkit::PolygonOptions options;
    std::size_t calls = 0, outside = 0;
    options.quality.unsuitable = [&](const double* a, const double* b, const double* c, double area) {
        ++calls;
        for (const double* p : {a, b, c}) outside += p[0] < 0 || p[0] > side || p[1] < 0 || p[1] > side;
        outside += !(area > 0);
        const double cx = (a[0] + b[0] + c[0]) / 3;
        return area > (cx < side / 2 ? side * side / 64 : side * side / 8);  // finer on the left
    };
    const ConstrainedDelaunay d = hullkit::triangulate_polygon(PointSpan2(xy), nullptr, 0, options);
    verified(d, true);
    REQUIRE(calls > 0);
    REQUIRE(outside == 0);
    REQUIRE(d.steiner_count > 8);
    const auto [left, right] = largest_areas_beside(d, side / 2);
    REQUIRE(left <= side * side / 64);
    REQUIRE(right <= side * side / 8);
    REQUIRE(right > side * side / 64);
}

TEST_CASE("refine: conforming meshes are Delaunay everywhere", "[refine]") {
    // A thin slanted segment inside a box and a polygon with a narrow notch.
    const std::vector<double> xy = {0, 0, 8, 0, 8, 5, 0, 5, 1, 1, 7, 1.3};
    const std::vector<std::uint32_t> segs = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5};
    hullkit::ConstrainedOptions options;
    options.quality.conforming = true;
    ConstrainedDelaunay d = hullkit::constrained_delaunay(PointSpan2(xy), segs.data(), segs.size() / 2, options);
    verified(d, true);
    REQUIRE(d.steiner_count > 0);
    delaunay_everywhere(d);
    segments_kept(d, xy, segs);
    options.quality.min_angle = 25;
    d = hullkit::constrained_delaunay(PointSpan2(xy), segs.data(), segs.size() / 2, options);
    verified(d, true);
    delaunay_everywhere(d);
    REQUIRE(smallest_angle(d) >= 25);
}

TEST_CASE("refine: small input angles are left alone and counted, without a cascade", "[refine]") {
    // Two segments meeting at about 5 degrees at the origin, inside a box.
    const std::vector<double> xy = {-1, -1, 11, -1, 11, 3, -1, 3, 0, 0, 10, 0, 10, 0.875};
    const std::vector<std::uint32_t> segs = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 4, 6};
    hullkit::ConstrainedOptions options;
    options.quality.min_angle = 20;
    const ConstrainedDelaunay d = hullkit::constrained_delaunay(PointSpan2(xy), segs.data(), segs.size() / 2, options);
    verified(d, true);
    REQUIRE(d.unrefined_count > 0);
    REQUIRE(d.steiner_count < 2000);
    segments_kept(d, xy, segs);
    // Every triangle below the bound has a corner at the small angle's apex (the origin).
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        ConstrainedDelaunay one;
        one.coords = d.coords;
        one.triangles.assign(d.triangles.begin() + 3 * t, d.triangles.begin() + 3 * t + 3);
        if (smallest_angle(one) >= 20) continue;
        bool at_origin = false;
        for (int k = 0; k < 3; ++k) at_origin |= d.coords[2 * d.triangles[3 * t + k]] == 0 && d.coords[2 * d.triangles[3 * t + k] + 1] == 0;
        INFO("triangle " << t);
        REQUIRE(at_origin);
    }
}

TEST_CASE("refine: slanted segments and random polygons keep their segments and area", "[refine]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    for (int trial = 0; trial < 20; ++trial) {
        // A star-shaped ring of 12 to 40 vertices with a smaller star hole.
        const int n = 12 + trial % 29;
        std::vector<double> xy;
        for (int ring = 0; ring < 2; ++ring) {
            const double radius = ring == 0 ? 10 : 3;
            for (int i = 0; i < n; ++i) {
                const double angle = 2 * 3.14159265358979 * i / n * (ring == 0 ? 1 : -1);
                const double r = radius * (1 + jitter(rng));
                xy.push_back(r * std::cos(angle)), xy.push_back(r * std::sin(angle));
            }
        }
        const std::uint32_t starts[] = {static_cast<std::uint32_t>(n)};
        hullkit::PolygonOptions options;
        options.quality.min_angle = 25;
        options.quality.max_area = 1.0;
        const ConstrainedDelaunay d = hullkit::triangulate_polygon(PointSpan2(xy), starts, 1, options);
        INFO("trial " << trial);
        verified(d, true);
        REQUIRE(largest_area(d) <= 1.0);
        if (d.unrefined_count == 0) REQUIRE(smallest_angle(d) >= 25);
        std::vector<std::uint32_t> segs;
        for (int i = 0; i < n; ++i) segs.insert(segs.end(), {std::uint32_t(i), std::uint32_t((i + 1) % n)});
        for (int i = 0; i < n; ++i) segs.insert(segs.end(), {std::uint32_t(n + i), std::uint32_t(n + (i + 1) % n)});
        segments_kept(d, xy, segs);
        const mpq_class expected = twice_ring_area(xy, 0, n) - twice_ring_area(xy, n, 2 * n);
        const double relative = mpq_class(abs(twice_area(d) - expected) / expected).get_d();
        REQUIRE(relative < 1e-13);
    }
}

TEST_CASE("refine: the same arrays every run, and no refinement without options", "[refine]") {
    const std::vector<double> xy = {0, 0, 5, 0.3, 9, 4, 4, 9, -1, 6, 2, 2, 4, 3, 3, 5};
    const std::uint32_t starts[] = {5};
    hullkit::PolygonOptions options;
    const ConstrainedDelaunay plain = hullkit::triangulate_polygon(PointSpan2(xy), starts, 1, options);
    REQUIRE(plain.steiner_count == 0);
    REQUIRE(plain.added_count() == 0);
    options.quality.min_angle = 30;
    const ConstrainedDelaunay a = hullkit::triangulate_polygon(PointSpan2(xy), starts, 1, options);
    const ConstrainedDelaunay b = hullkit::triangulate_polygon(PointSpan2(xy), starts, 1, options);
    verified(a, true);
    REQUIRE(a.triangles == b.triangles);
    REQUIRE(a.coords == b.coords);
    REQUIRE(a.halfedges == b.halfedges);
}

TEST_CASE("refine: bad options and the point cap are errors", "[refine]") {
    const std::vector<double> xy = {0, 0, 1, 0, 1, 1, 0, 1};
    hullkit::PolygonOptions options;
    options.quality.min_angle = 40;
    ConstrainedDelaunay d = hullkit::triangulate_polygon(PointSpan2(xy), nullptr, 0, options);
    REQUIRE(!d.ok());
    REQUIRE(d.error.find("min_angle") != std::string::npos);
    options.quality.min_angle = 0;
    options.quality.max_area = -1;
    d = hullkit::triangulate_polygon(PointSpan2(xy), nullptr, 0, options);
    REQUIRE(d.error.find("max_area") != std::string::npos);
    options.quality.max_area = 1e-4;
    options.quality.max_steiner_points = 100;
    d = hullkit::triangulate_polygon(PointSpan2(xy), nullptr, 0, options);
    REQUIRE(d.error.find("max_steiner_points") != std::string::npos);
    REQUIRE(d.triangles.empty());
}

TEST_CASE("refine: random graphs with crossing segments, whole hull and Triangle's domain", "[refine]") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 12; ++trial) {
        const std::size_t n = 20 + 15 * trial;
        std::vector<double> xy(2 * n);
        for (double& v : xy) v = u(rng);
        // Every third trial far from the origin (1e6, extent 2e-3: 2e7 units in the last place), where
        // points placed on slanted segments are off their lines by a larger part of the mesh size,
        // and the split's Lawson flips must reach the new spokes (a fuzz finding).
        if (trial % 3 == 2)
            for (std::size_t i = 0; i < xy.size(); ++i) xy[i] = (i % 2 ? -1e6 : 1e6) + 1e-3 * xy[i];
        std::vector<std::uint32_t> segs;
        std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(n - 1));
        for (std::size_t k = 0; k < n / 3; ++k) segs.push_back(pick(rng)), segs.push_back(pick(rng));
        hullkit::ConstrainedOptions options;
        options.quality.min_angle = 20 + trial % 3 * 4;
        options.quality.max_area = trial % 2 ? (trial % 3 == 2 ? 1e-8 : 0.01) : 0;
        // Conforming only near the origin: far from it the crossings of random segments leave
        // features below refinement's resolution, which stay (and are counted) unconforming.
        options.quality.conforming = trial % 4 == 3 && trial % 3 != 2;
        options.remove_exterior = trial % 5 == 4;
        const ConstrainedDelaunay d = hullkit::constrained_delaunay(PointSpan2(xy), segs.data(), segs.size() / 2, options);
        INFO("trial " << trial << ": " << d.coords.size() / 2 << " points, " << d.triangle_count() << " triangles");
        verified(d, true);
        if (options.quality.max_area > 0) REQUIRE(largest_area(d) <= options.quality.max_area);
        if (options.quality.conforming) delaunay_everywhere(d);
        // Every triangle below the angle bound is counted (random segments meet at small angles).
        std::size_t below = 0;
        for (std::size_t t = 0; t < d.triangle_count(); ++t) {
            ConstrainedDelaunay one;
            one.coords = d.coords;
            one.triangles.assign(d.triangles.begin() + 3 * t, d.triangles.begin() + 3 * t + 3);
            below += smallest_angle(one) < options.quality.min_angle - 1e-9;
        }
        REQUIRE(below <= d.unrefined_count);
    }
}

TEST_CASE("refine: added points are ones the output can hold, where the input's units are subnormal (fuzz regression)", "[refine]") {
    // tests/data/fuzz/constrained-steiner-points-subnormal-in-input-units.bin: a triangle with x
    // coordinates near 1e-319. The points are scaled up while triangulated; the Steiner points,
    // divided back, lost bits in the subnormal range and made a flat triangle of the output. Each
    // new point is now rounded to one the output holds exactly.
    const std::vector<double> xy = {4.0711009217318715e-320, 0, 0, 0, 3.1873162944510497e-319, 1.3328545234157988e-259};
    const std::vector<std::uint32_t> segs = {0, 1};
    hullkit::ConstrainedOptions options;
    options.quality.min_angle = 4;
    options.quality.conforming = true;
    options.quality.max_steiner_points = 3000;
    const ConstrainedDelaunay d = hullkit::constrained_delaunay(PointSpan2(xy), segs.data(), segs.size() / 2, options);
    verified(d, true);
    REQUIRE(d.steiner_count > 0);
    // The triangles cover the input triangle up to the rounding of the points added on its sides
    // (whose coordinates, as the output holds them, are multiples of 2^-1074: coarse here).
    const mpq_class expected = (q(xy[2]) - q(xy[0])) * (q(xy[5]) - q(xy[1])) - (q(xy[3]) - q(xy[1])) * (q(xy[4]) - q(xy[0]));
    const mpq_class error = abs(abs(twice_area(d)) - abs(expected)) / abs(expected);
    CHECK(error.get_d() < 0.05);
}
