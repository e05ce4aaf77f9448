// Independent checks of Delaunay output for the tests: GMP rational arithmetic and brute force,
// nothing shared with the library's predicates.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "hullkit/delaunay.hpp"

namespace delaunay_test {

inline mpq_class q(double v) { return mpq_class(v); }

/// Exact sign of (b-a) x (c-a) by GMP.
inline int rational_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    const mpq_class det = (q(bx) - q(ax)) * (q(cy) - q(ay)) - (q(by) - q(ay)) * (q(cx) - q(ax));
    return sgn(det);
}

/// Exact sign of the in-circle determinant (rows a-d, b-d, c-d with squared lengths) by GMP:
/// positive when d is inside the circle of counter-clockwise a, b, c.
inline int gmp_incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                             double dy) {
    const mpq_class adx = q(ax) - q(dx), ady = q(ay) - q(dy);
    const mpq_class bdx = q(bx) - q(dx), bdy = q(by) - q(dy);
    const mpq_class cdx = q(cx) - q(dx), cdy = q(cy) - q(dy);
    const mpq_class det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                          (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                          (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
    return sgn(det);
}

/// rational_incircle with a shortcut: long double (64-bit significand, exponent range far beyond
/// double's, so no overflow or underflow for finite double input) with a generous bound of 1e-12
/// times the permanent (the rounding error is below 1e-17 of it); GMP otherwise.
inline int rational_incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                             double dy) {
    using L = long double;
    const L adx = L(ax) - dx, ady = L(ay) - dy, bdx = L(bx) - dx, bdy = L(by) - dy, cdx = L(cx) - dx,
            cdy = L(cy) - dy;
    const L al = adx * adx + ady * ady, bl = bdx * bdx + bdy * bdy, cl = cdx * cdx + cdy * cdy;
    const L det = al * (bdx * cdy - cdx * bdy) + bl * (cdx * ady - adx * cdy) + cl * (adx * bdy - bdx * ady);
    const L permanent = al * (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) +
                        bl * (std::fabs(cdx * ady) + std::fabs(adx * cdy)) +
                        cl * (std::fabs(adx * bdy) + std::fabs(bdx * ady));
    if (std::fabs(det) > 1e-12L * permanent) return det > 0 ? 1 : -1;
    return gmp_incircle(ax, ay, bx, by, cx, cy, dx, dy);
}

inline std::size_t next_edge(std::size_t e) { return e % 3 == 2 ? e - 2 : e + 1; }

/// Everything a caller relies on, checked independently of the library where possible:
/// verify_delaunay; representatives (exact coordinate equality, lowest index); half-edge symmetry
/// and matching ends; each triangle starts at its lowest index; the hull is the cycle of boundary
/// half-edges from its lowest index; and, for small inputs, the brute-force GMP empty-circle test of
/// every triangle against every point plus GMP orientation.
inline void check_delaunay(const std::vector<double>& xy, const hullkit::Delaunay& d, std::size_t brute_limit = 400) {
    using namespace hullkit;
    REQUIRE(d.ok());
    const PointSpan2 p(xy);
    const std::size_t n = p.count;
    REQUIRE(d.representative.size() == n);
    std::size_t duplicates = 0;
    std::map<std::pair<double, double>, std::uint32_t> lowest;
    for (std::size_t i = 0; i < n; ++i) {
        auto key = std::make_pair(p[i][0] + 0.0, p[i][1] + 0.0);  // +0.0: -0 and 0 are the same point
        if (!lowest.count(key)) lowest[key] = static_cast<std::uint32_t>(i);
    }
    std::size_t wrong_representative = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t expected = lowest[std::make_pair(p[i][0] + 0.0, p[i][1] + 0.0)];
        wrong_representative += d.representative[i] != expected;
        duplicates += expected != i;
    }
    REQUIRE(wrong_representative == 0);
    REQUIRE(d.duplicate_count == duplicates);
    const std::size_t distinct = lowest.size();

    const DelaunayVerifyReport report = verify_delaunay(p, d.triangles.data(), d.triangle_count());
    INFO((report.problems.empty() ? std::string() : report.problems.front()));
    REQUIRE(report.ok);

    if (d.dimension < 2) {
        REQUIRE(d.triangles.empty());
        REQUIRE(d.hull.size() == distinct);
        return;
    }
    REQUIRE(d.dimension == 2);
    REQUIRE(d.halfedges.size() == d.triangles.size());
    std::vector<bool> used(n, false);
    std::size_t bad_index = 0, bad_twin = 0, bad_rotation = 0;
    for (std::size_t e = 0; e < d.triangles.size(); ++e) {
        bad_index += d.representative[d.triangles[e]] != d.triangles[e];
        used[d.triangles[e]] = true;
        const std::int32_t f = d.halfedges[e];
        if (f >= 0) {
            bad_twin += d.halfedges[f] != static_cast<std::int32_t>(e) || d.triangles[f] != d.triangles[next_edge(e)] ||
                        d.triangles[next_edge(f)] != d.triangles[e];
        }
    }
    REQUIRE(bad_index == 0);
    REQUIRE(bad_twin == 0);
    REQUIRE(static_cast<std::size_t>(std::count(used.begin(), used.end(), true)) == distinct);
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        bad_rotation += d.triangles[3 * t] > d.triangles[3 * t + 1] || d.triangles[3 * t] > d.triangles[3 * t + 2];
    }
    REQUIRE(bad_rotation == 0);
    // Hull = boundary cycle from its lowest index.
    std::map<std::uint32_t, std::uint32_t> successor;
    for (std::size_t e = 0; e < d.triangles.size(); ++e)
        if (d.halfedges[e] == -1) successor[d.triangles[e]] = d.triangles[next_edge(e)];
    REQUIRE(d.hull.size() == successor.size());
    REQUIRE(d.hull.front() == successor.begin()->first);
    std::size_t bad_hull = 0;
    for (std::size_t k = 0; k < d.hull.size(); ++k) bad_hull += successor[d.hull[k]] != d.hull[(k + 1) % d.hull.size()];
    REQUIRE(bad_hull == 0);
    REQUIRE(d.triangle_count() == 2 * distinct - d.hull.size() - 2);

    if (distinct <= brute_limit) {
        std::vector<std::uint32_t> sites;
        for (auto& entry : lowest) sites.push_back(entry.second);
        std::size_t not_clockwise = 0, not_empty = 0;
        for (std::size_t t = 0; t < d.triangle_count(); ++t) {
            const double* a = p[d.triangles[3 * t]];
            const double* b = p[d.triangles[3 * t + 1]];
            const double* c = p[d.triangles[3 * t + 2]];
            not_clockwise += rational_orient2d(a[0], a[1], b[0], b[1], c[0], c[1]) >= 0;  // clockwise, y up
            for (std::uint32_t s : sites) {
                // a, c, b is counter-clockwise: no site strictly inside.
                not_empty += rational_incircle(a[0], a[1], c[0], c[1], b[0], b[1], p[s][0], p[s][1]) > 0;
            }
        }
        REQUIRE(not_clockwise == 0);
        REQUIRE(not_empty == 0);
    }
}

/// Both algorithms; asserts identical output (all arrays) and checks it; returns the result.
inline hullkit::Delaunay both_algorithms(const std::vector<double>& xy, std::size_t brute_limit = 400) {
    using namespace hullkit;
    DelaunayOptions options;
    options.merge_cocircular = true;
    const Delaunay incremental = delaunay(xy, options);
    options.algorithm = DelaunayAlgorithm::Giftwrap;
    const Delaunay giftwrap = delaunay(xy, options);
    check_delaunay(xy, incremental, brute_limit);
    REQUIRE(giftwrap.ok());
    REQUIRE(incremental.dimension == giftwrap.dimension);
    REQUIRE(incremental.triangles == giftwrap.triangles);
    REQUIRE(incremental.halfedges == giftwrap.halfedges);
    REQUIRE(incremental.hull == giftwrap.hull);
    REQUIRE(incremental.representative == giftwrap.representative);
    REQUIRE(incremental.polygon_offsets == giftwrap.polygon_offsets);
    REQUIRE(incremental.polygon_vertices == giftwrap.polygon_vertices);
    return incremental;
}

}  // namespace delaunay_test
