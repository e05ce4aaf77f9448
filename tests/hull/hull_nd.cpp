// Tests for hullkit::hull_nd, delaunay_nd, locate_nd and orient_nd: every result checked with exact
// rational arithmetic (GMP, Gaussian elimination: a different method from the library's expansion
// by minors on big integers) on random, degenerate (cube corners, grids with repeats, points on
// one sphere) and extreme-scale inputs in 2 to 10 dimensions.
#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "hullkit/hull_nd.hpp"

namespace {

using Rows = std::vector<std::vector<mpq_class>>;

int sign_of_det(Rows a) {
    const std::size_t n = a.size();
    int sign = 1;
    for (std::size_t c = 0; c < n; ++c) {
        std::size_t p = c;
        while (p < n && a[p][c] == 0) ++p;
        if (p == n) return 0;
        if (p != c) {
            std::swap(a[p], a[c]);
            sign = -sign;
        }
        if (a[c][c] < 0) sign = -sign;
        for (std::size_t r = c + 1; r < n; ++r) {
            const mpq_class f = a[r][c] / a[c][c];
            for (std::size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
        }
    }
    return sign;
}

/// The row [p, (|p|^2,) 1] of point i.
std::vector<mpq_class> row(const std::vector<double>& p, int d, std::size_t i, bool lifted) {
    std::vector<mpq_class> r;
    mpq_class lift = 0;
    for (int j = 0; j < d; ++j) {
        const mpq_class x(p[i * static_cast<std::size_t>(d) + static_cast<std::size_t>(j)]);
        r.push_back(x);
        lift += x * x;
    }
    if (lifted) r.push_back(lift);
    r.push_back(1);
    return r;
}

std::vector<double> random_points(std::size_t n, int d, unsigned seed, double scale = 1.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> p(n * static_cast<std::size_t>(d));
    for (double& x : p) x = scale * u(rng);
    return p;
}

/// Checks a hull exactly: every point on or inside every facet, vertices exactly the facets'
/// corners, every facet's neighbours sharing all corners but the one across, each ridge twice.
void check_hull(const std::vector<double>& p, int d, const hullkit::HullNd& h) {
    REQUIRE(h.ok());
    const std::size_t n = p.size() / static_cast<std::size_t>(d), m = h.facet_count();
    REQUIRE(m >= static_cast<std::size_t>(d) + 1);
    std::set<std::uint32_t> corners;
    for (std::size_t f = 0; f < m; ++f) {
        Rows base;
        for (int k = 0; k < d; ++k) {
            const std::uint32_t c = h.facets[f * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)];
            corners.insert(c);
            base.push_back(row(p, d, c, false));
        }
        bool strict = false;
        for (std::size_t q = 0; q < n; ++q) {
            Rows a = base;
            a.push_back(row(p, d, q, false));
            const int s = sign_of_det(a);
            REQUIRE(s <= 0);
            strict = strict || s < 0;
        }
        REQUIRE(strict);  // not flat
        for (int k = 0; k < d; ++k) {
            const std::int32_t g = h.neighbors[f * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)];
            REQUIRE(g >= 0);
            REQUIRE(static_cast<std::size_t>(g) < m);
            std::set<std::uint32_t> mine(&h.facets[f * static_cast<std::size_t>(d)], &h.facets[f * static_cast<std::size_t>(d)] + d);
            mine.erase(h.facets[f * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)]);
            std::set<std::uint32_t> theirs(&h.facets[static_cast<std::size_t>(g) * static_cast<std::size_t>(d)],
                                           &h.facets[static_cast<std::size_t>(g) * static_cast<std::size_t>(d)] + d);
            for (std::uint32_t c : mine) REQUIRE(theirs.count(c) == 1);
        }
    }
    REQUIRE(std::vector<std::uint32_t>(corners.begin(), corners.end()) == h.vertices);
}

/// Checks a Delaunay triangulation exactly: positively oriented simplices, each circumsphere
/// empty (strictly, unless `cospherical`), neighbours across the right faces, every distinct
/// point a corner, and the simplices' volumes adding up to the hull's.
void check_delaunay(const std::vector<double>& p, int d, const hullkit::DelaunayNd& t, bool cospherical) {
    REQUIRE(t.ok());
    const std::size_t n = p.size() / static_cast<std::size_t>(d), m = t.simplex_count(), c = static_cast<std::size_t>(d) + 1;
    std::set<std::uint32_t> used;
    for (std::size_t s = 0; s < m; ++s) {
        Rows plain, lifted;
        for (std::size_t k = 0; k < c; ++k) {
            used.insert(t.simplices[s * c + k]);
            plain.push_back(row(p, d, t.simplices[s * c + k], false));
            lifted.push_back(row(p, d, t.simplices[s * c + k], true));
        }
        REQUIRE(sign_of_det(plain) > 0);
        for (std::size_t q = 0; q < n; ++q) {
            if (t.representative[q] != q || std::count(&t.simplices[s * c], &t.simplices[s * c] + c, q)) continue;
            Rows a = lifted;
            a.push_back(row(p, d, q, true));
            const int side = sign_of_det(a);  // negative: outside the circumsphere
            if (cospherical)
                REQUIRE(side <= 0);
            else
                REQUIRE(side < 0);
        }
        for (std::size_t k = 0; k < c; ++k) {
            const std::int32_t u = t.neighbors[s * c + k];
            if (u < 0) continue;
            const std::uint32_t* mine = &t.simplices[s * c];
            const std::uint32_t* theirs = &t.simplices[static_cast<std::size_t>(u) * c];
            for (std::size_t j = 0; j < c; ++j)
                if (j != k) REQUIRE(std::count(theirs, theirs + c, mine[j]) == 1);
        }
    }
    for (std::size_t q = 0; q < n; ++q)
        if (t.representative[q] == q) REQUIRE(used.count(static_cast<std::uint32_t>(q)) == 1);
    // Volumes: sum over simplices = the hull's volume (a fan of its facets from an interior point,
    // here the centroid of the first simplex).
    const hullkit::HullNd h = hullkit::hull_nd(p.data(), n, d);
    REQUIRE(h.ok());
    auto volume = [&](const std::vector<std::vector<mpq_class>>& corners) -> mpq_class {
        Rows a;
        for (std::size_t k = 1; k < corners.size(); ++k) {
            std::vector<mpq_class> r;
            for (int j = 0; j < d; ++j) r.push_back(corners[k][static_cast<std::size_t>(j)] - corners[0][static_cast<std::size_t>(j)]);
            a.push_back(r);
        }
        // |det| by elimination.
        const std::size_t size = a.size();
        mpq_class det = 1;
        for (std::size_t col = 0; col < size; ++col) {
            std::size_t piv = col;
            while (piv < size && a[piv][col] == 0) ++piv;
            if (piv == size) return mpq_class(0);
            std::swap(a[piv], a[col]);
            det *= a[col][col];
            for (std::size_t r = col + 1; r < size; ++r) {
                const mpq_class f = a[r][col] / a[col][col];
                for (std::size_t k = col; k < size; ++k) a[r][k] -= f * a[col][k];
            }
        }
        return mpq_class(abs(det));
    };
    mpq_class total = 0;
    std::vector<mpq_class> centre(static_cast<std::size_t>(d), 0);
    for (std::size_t k = 0; k < c; ++k)
        for (int j = 0; j < d; ++j) centre[static_cast<std::size_t>(j)] += mpq_class(p[t.simplices[k] * static_cast<std::size_t>(d) + static_cast<std::size_t>(j)]) / static_cast<long>(c);
    for (std::size_t s = 0; s < m; ++s) {
        std::vector<std::vector<mpq_class>> corners;
        for (std::size_t k = 0; k < c; ++k) corners.push_back(row(p, d, t.simplices[s * c + k], false));
        total += volume(corners);
    }
    mpq_class hull_volume = 0;
    for (std::size_t f = 0; f < h.facet_count(); ++f) {
        std::vector<std::vector<mpq_class>> corners{centre};
        for (int k = 0; k < d; ++k) corners.push_back(row(p, d, h.facets[f * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)], false));
        hull_volume += volume(corners);
    }
    REQUIRE(total == hull_volume);
}

}  // namespace

TEST_CASE("orient_nd: the exact sign in 1 to 10 dimensions, random, dependent and extreme rows", "[hull_nd]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int d = 1; d <= hullkit::kMaxHullNdDimension; ++d) {
        for (int trial = 0; trial < 40; ++trial) {
            std::vector<double> rows(static_cast<std::size_t>((d + 1) * d));
            const int kind = trial % 4;
            for (double& x : rows) x = u(rng);
            if (kind == 1) {  // the last point an affine combination of two others: exactly dependent
                for (int j = 0; j < d; ++j)
                    rows[static_cast<std::size_t>(d * d + j)] = 0.5 * rows[static_cast<std::size_t>(j)] + 0.5 * rows[static_cast<std::size_t>(d + j)];
            } else if (kind == 2) {  // extreme scales in one determinant
                for (std::size_t k = 0; k < rows.size(); ++k) rows[k] *= (k % 3 == 0) ? 1e-300 : (k % 3 == 1 ? 1e290 : 1.0);
            } else if (kind == 3) {  // nearly dependent: one ulp off
                for (int j = 0; j < d; ++j)
                    rows[static_cast<std::size_t>(d * d + j)] = std::nextafter(rows[static_cast<std::size_t>(j)], 2.0);
                if (d > 1) rows[static_cast<std::size_t>(d * d)] = rows[0];
            }
            Rows a;
            for (int i = 0; i <= d; ++i) a.push_back(row(rows, d, static_cast<std::size_t>(i), false));
            INFO("d " << d << " trial " << trial);
            REQUIRE(hullkit::orient_nd(rows.data(), d) == sign_of_det(a));
        }
    }
}

TEST_CASE("hull_nd: random points in 2 to 7 dimensions, every facet checked exactly", "[hull_nd]") {
    for (int d = 2; d <= 7; ++d) {
        const std::size_t n = d <= 4 ? 60 : d == 5 ? 25 : 13;
        const std::vector<double> p = random_points(n, d, static_cast<unsigned>(d));
        INFO("d " << d);
        check_hull(p, d, hullkit::hull_nd(p.data(), n, d));
    }
}

TEST_CASE("hull_nd: cube corners, a cross-polytope with its centre, repeats and extreme scales", "[hull_nd]") {
    for (int d = 3; d <= 6; ++d) {
        std::vector<double> p;
        for (std::uint32_t mask = 0; mask < (1u << d); ++mask)
            for (int j = 0; j < d; ++j) p.push_back(mask >> j & 1 ? 1.0 : 0.0);
        // The centre, a repeat of a corner and a point in a face's plane inside the face.
        for (int j = 0; j < d; ++j) p.push_back(0.5);
        for (int j = 0; j < d; ++j) p.push_back(1.0);
        for (int j = 0; j < d; ++j) p.push_back(j == 0 ? 0.0 : 0.25);
        const std::size_t n = p.size() / static_cast<std::size_t>(d);
        const hullkit::HullNd h = hullkit::hull_nd(p.data(), n, d);
        INFO("d " << d);
        check_hull(p, d, h);
        REQUIRE(h.vertices.size() == (std::size_t{1} << d));  // neither the centre, the repeat nor the face point
    }
    // Coordinates from 1e-300 to 1e300: the floating copy underflows, the exact path decides.
    std::vector<double> p = random_points(30, 4, 11);
    for (std::size_t k = 0; k < p.size(); ++k) p[k] *= (k % 5 == 0) ? 1e300 : (k % 5 == 1 ? 1e-300 : 1.0);
    check_hull(p, 4, hullkit::hull_nd(p.data(), 30, 4));
}

TEST_CASE("delaunay_nd: random points in 2 to 5 dimensions, exactly Delaunay", "[hull_nd]") {
    for (int d = 2; d <= 5; ++d) {
        const std::size_t n = d <= 4 ? 40 : 22;
        std::vector<double> p = random_points(n, d, static_cast<unsigned>(100 + d));
        // Two repeats.
        p.insert(p.end(), p.begin(), p.begin() + 2 * d);
        const hullkit::DelaunayNd t = hullkit::delaunay_nd(p.data(), n + 2, d);
        INFO("d " << d);
        REQUIRE(t.duplicate_count == 2);
        REQUIRE(t.representative[n] == 0);
        REQUIRE(t.representative[n + 1] == 1);
        check_delaunay(p, d, t, false);
        for (std::size_t s = 0; s < t.simplex_count(); ++s) REQUIRE(t.group[s] == static_cast<std::int32_t>(s));
    }
}

TEST_CASE("delaunay_nd: cospherical cube corners and grids get full, exact triangulations", "[hull_nd]") {
    for (int d = 3; d <= 5; ++d) {
        std::vector<double> corners;
        for (std::uint32_t mask = 0; mask < (1u << d); ++mask)
            for (int j = 0; j < d; ++j) corners.push_back(mask >> j & 1 ? 1.0 : 0.0);
        const hullkit::DelaunayNd t = hullkit::delaunay_nd(corners.data(), std::size_t{1} << d, d);
        INFO("cube d " << d);
        check_delaunay(corners, d, t, true);
        for (const std::int32_t g : t.group) REQUIRE(g == 0);  // one sphere through all corners
        const hullkit::DelaunayNd far = hullkit::delaunay_nd(corners.data(), std::size_t{1} << d, d, true);
        REQUIRE(far.ok());
        REQUIRE(far.simplex_count() == t.simplex_count());  // all on one sphere: the same cell
    }
    std::vector<double> grid;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            for (int c = 0; c < 3; ++c)
                for (int e = 0; e < 3; ++e) grid.insert(grid.end(), {0.5 * a, 0.5 * b, 0.5 * c, 0.5 * e});
    const hullkit::DelaunayNd t = hullkit::delaunay_nd(grid.data(), 81, 4);
    check_delaunay(grid, 4, t, true);
    // Point location: each grid point lies in a simplex holding it, the lowest-indexed such.
    const std::vector<std::int32_t> found = hullkit::locate_nd(grid.data(), t, grid.data(), 81);
    for (std::size_t q = 0; q < 81; ++q) {
        REQUIRE(found[q] >= 0);
        std::int32_t lowest = -1;
        for (std::size_t s = 0; s < t.simplex_count() && lowest < 0; ++s)
            if (std::count(&t.simplices[s * 5], &t.simplices[s * 5] + 5, q)) lowest = static_cast<std::int32_t>(s);
        REQUIRE(found[q] == lowest);
    }
}

TEST_CASE("locate_nd: random queries inside and outside, checked against every simplex", "[hull_nd]") {
    const int d = 4;
    const std::vector<double> p = random_points(30, d, 21);
    const hullkit::DelaunayNd t = hullkit::delaunay_nd(p.data(), 30, d);
    REQUIRE(t.ok());
    const std::vector<double> q = random_points(50, d, 22, 1.3);
    const std::vector<std::int32_t> found = hullkit::locate_nd(p.data(), t, q.data(), 50);
    for (std::size_t i = 0; i < 50; ++i) {
        std::int32_t expected = -1;
        for (std::size_t s = 0; s < t.simplex_count() && expected < 0; ++s) {
            bool inside = true;
            for (int k = 0; k <= d && inside; ++k) {
                Rows a;
                for (int j = 0; j <= d; ++j)
                    a.push_back(j == k ? row(q, d, i, false) : row(p, d, t.simplices[s * 5 + static_cast<std::size_t>(j)], false));
                inside = sign_of_det(a) >= 0;
            }
            if (inside) expected = static_cast<std::int32_t>(s);
        }
        INFO("query " << i);
        REQUIRE(found[i] == expected);
    }
    const double nan_query[4] = {0.1, NAN, 0.0, 0.0};
    REQUIRE(hullkit::locate_nd(p.data(), t, nan_query, 1)[0] == -1);
}

TEST_CASE("hull_nd and delaunay_nd: errors name what is wrong", "[hull_nd]") {
    std::vector<double> flat = random_points(20, 4, 3);
    for (std::size_t i = 0; i < 20; ++i) flat[i * 4 + 3] = flat[i * 4];  // in the hyperplane x_3 = x_0
    const hullkit::HullNd h = hullkit::hull_nd(flat.data(), 20, 4);
    REQUIRE(h.error == "a hull needs points spanning all 4 dimensions: these lie in a flat of 3 dimensions");
    const hullkit::DelaunayNd t = hullkit::delaunay_nd(flat.data(), 20, 4);
    REQUIRE(t.error == "a Delaunay triangulation needs points spanning all 4 dimensions: these lie in a flat of 3 dimensions");
    std::vector<double> bad = random_points(10, 5, 4);
    bad[3 * 5 + 2] = INFINITY;
    const hullkit::HullNd e = hullkit::hull_nd(bad.data(), 10, 5);
    REQUIRE(e.error == "point 3 has a non-finite coordinate 2");
    REQUIRE(e.error_point == 3);
    REQUIRE(hullkit::hull_nd(bad.data(), 10, 11).error == "hull_nd takes 2 to 10 dimensions, not 11");
    REQUIRE(hullkit::delaunay_nd(bad.data(), 10, 10).error == "delaunay_nd takes 1 to 9 dimensions, not 10");
    REQUIRE(hullkit::hull_nd(bad.data(), 4, 4).error == "a hull in 4 dimensions needs at least 5 points, got 4");
    std::vector<double> same(30, 0.5);
    REQUIRE(hullkit::delaunay_nd(same.data(), 6, 5).error ==
            "a Delaunay triangulation in 5 dimensions needs at least 6 distinct points, got 1");
}

namespace {

/// The bytes of tests/data/fuzz/NAME (fuzz_hull_nd's inputs: at most 4096 bytes).
std::vector<unsigned char> fuzz_bytes(const std::string& name) {
    std::FILE* file = std::fopen((std::string(HULLKIT_TEST_DATA "/fuzz/") + name).c_str(), "rb");
    REQUIRE(file != nullptr);
    std::vector<unsigned char> bytes(4096);
    bytes.resize(std::fread(bytes.data(), 1, bytes.size(), file));
    std::fclose(file);
    return bytes;
}

}  // namespace

TEST_CASE("hull_nd and delaunay_nd: a fuzz input of doubles from 1e-150 to 1e150 in 5D (exact, fast)", "[hull_nd]") {
    // tests/data/fuzz/hull_nd-wide-exponents.bin as fuzz_hull_nd reads it: the first byte the
    // dimension (2 + 123 % 5), the second doubles, then 72 doubles: 14 points whose exact
    // determinants spanned 11 000 bits (over 10 s under the sanitizers before the entries' zero
    // limbs were skipped and the wide floating stage was added).
    const std::vector<unsigned char> bytes = fuzz_bytes("hull_nd-wide-exponents.bin");
    REQUIRE(bytes.size() == 581);
    const int d = 2 + bytes[0] % 5;
    REQUIRE(d == 5);
    std::vector<double> p((bytes.size() - 2) / 8);
    std::memcpy(p.data(), bytes.data() + 2, 8 * p.size());
    const std::size_t n = p.size() / 5;
    p.resize(n * 5);
    const hullkit::HullNd h = hullkit::hull_nd(p.data(), n, d);
    const hullkit::DelaunayNd t = hullkit::delaunay_nd(p.data(), n, d);
    if (h.ok()) {
        check_hull(p, d, h);
        check_delaunay(p, d, t, true);
    } else {
        REQUIRE(h.error.find("flat") != std::string::npos);
        REQUIRE(!t.ok());
    }
}

TEST_CASE("hull_nd and delaunay_nd: a 4D boundary piece triangulated with more points in fewer simplices (fuzz input)", "[hull_nd]") {
    // tests/data/fuzz/hull_nd-4d-boundary-fewer-pieces.bin as fuzz_hull_nd reads it: 4D (2 + 27 %
    // 5), small integers (the second byte odd), 16 points. Flat pieces of the hull are 3D
    // polytopes: the hull triangulates them with its vertices in 50 facets, the Delaunay
    // triangulation's boundary with every point in 49 faces (a cube takes 5 or 6 tetrahedra).
    // Both are exact; the fuzz target's count check now holds only up to 3D.
    const std::vector<unsigned char> bytes = fuzz_bytes("hull_nd-4d-boundary-fewer-pieces.bin");
    const int d = 2 + bytes[0] % 5;
    REQUIRE(d == 4);
    REQUIRE((bytes[1] & 1) == 1);
    std::vector<double> p;
    for (std::size_t k = 2; k < bytes.size(); ++k) p.push_back(static_cast<double>(static_cast<std::int8_t>(bytes[k]) % 4));
    const std::size_t n = p.size() / 4;
    p.resize(n * 4);
    const hullkit::HullNd h = hullkit::hull_nd(p.data(), n, d);
    const hullkit::DelaunayNd t = hullkit::delaunay_nd(p.data(), n, d);
    REQUIRE(h.ok());
    REQUIRE(t.ok());
    check_hull(p, d, h);
    check_delaunay(p, d, t, true);
    const auto boundary = static_cast<std::size_t>(std::count(t.neighbors.begin(), t.neighbors.end(), -1));
    CHECK(boundary < h.facet_count());
}

TEST_CASE("hull_nd: the flat pieces of the boundary (group) are exactly the coplanar neighbours", "[hull_nd]") {
    // A 4-cube: 8 cubic facets, each triangulated; with a point inside one face's plane.
    std::vector<double> p;
    for (std::uint32_t mask = 0; mask < 16; ++mask)
        for (int j = 0; j < 4; ++j) p.push_back(mask >> j & 1 ? 1.0 : 0.0);
    const hullkit::HullNd h = hullkit::hull_nd(p.data(), 16, 4);
    check_hull(p, 4, h);
    std::map<std::int32_t, std::set<std::uint32_t>> pieces;
    for (std::size_t f = 0; f < h.facet_count(); ++f) {
        REQUIRE(h.group[f] <= static_cast<std::int32_t>(f));
        REQUIRE(h.group[static_cast<std::size_t>(h.group[f])] == h.group[f]);
        pieces[h.group[f]].insert(&h.facets[f * 4], &h.facets[f * 4] + 4);
    }
    REQUIRE(pieces.size() == 8);
    for (const auto& piece : pieces) {
        REQUIRE(piece.second.size() == 8);  // a cube's corners: one coordinate fixed
        int fixed = 0;
        for (int j = 0; j < 4; ++j) {
            std::set<double> values;
            for (std::uint32_t c : piece.second) values.insert(p[c * 4 + static_cast<std::size_t>(j)]);
            fixed += values.size() == 1;
        }
        REQUIRE(fixed == 1);
    }
    // Random points: every facet its own piece.
    const std::vector<double> r = random_points(30, 5, 8);
    const hullkit::HullNd g = hullkit::hull_nd(r.data(), 30, 5);
    for (std::size_t f = 0; f < g.facet_count(); ++f) REQUIRE(g.group[f] == static_cast<std::int32_t>(f));
}

namespace {

/// The circumcentre of simplex s of t, exactly (GMP, Gaussian elimination on the bisector
/// equations 2 (c_k - c_0) . x = |c_k|^2 - |c_0|^2), rounded once.
std::vector<double> exact_circumcentre(const std::vector<double>& p, int d, const hullkit::DelaunayNd& t, std::size_t s) {
    const auto D = static_cast<std::size_t>(d);
    Rows a(D, std::vector<mpq_class>(D + 1));
    const std::uint32_t* c = &t.simplices[s * (D + 1)];
    for (std::size_t k = 1; k <= D; ++k) {
        mpq_class rhs = 0;
        for (std::size_t j = 0; j < D; ++j) {
            const mpq_class x(p[c[k] * D + j]), y(p[c[0] * D + j]);
            a[k - 1][j] = 2 * (x - y);
            rhs += x * x - y * y;
        }
        a[k - 1][D] = rhs;
    }
    for (std::size_t col = 0; col < D; ++col) {
        std::size_t pivot = col;
        while (a[pivot][col] == 0) ++pivot;
        std::swap(a[col], a[pivot]);
        for (std::size_t r = 0; r < D; ++r) {
            if (r == col || a[r][col] == 0) continue;
            const mpq_class f = a[r][col] / a[col][col];
            for (std::size_t j = col; j <= D; ++j) a[r][j] -= f * a[col][j];
        }
    }
    std::vector<double> out(D);
    for (std::size_t j = 0; j < D; ++j) out[j] = mpq_class(a[j][D] / a[j][j]).get_d();
    return out;
}

}  // namespace

TEST_CASE("voronoi_nd_volumes: a line, and grid cells that are unit cubes in 2 to 5 dimensions", "[hull_nd][voronoi]") {
    const std::vector<double> line = {0, 3, 1};
    const hullkit::DelaunayNd segments = hullkit::delaunay_nd(line.data(), 3, 1);
    REQUIRE(segments.ok());
    const std::vector<double> lengths = hullkit::voronoi_nd_volumes(line.data(), 3, 1, segments.simplices.data(), segments.simplex_count());
    REQUIRE(std::isinf(lengths[0]));
    REQUIRE(std::isinf(lengths[1]));
    REQUIRE(lengths[2] == 1.5);  // from 0.5 to 2
    for (int d = 2; d <= 5; ++d) {
        const int side = d == 5 ? 3 : 4;
        std::vector<double> grid;
        std::size_t count = 1;
        for (int k = 0; k < d; ++k) count *= static_cast<std::size_t>(side);
        for (std::size_t i = 0; i < count; ++i)
            for (std::size_t j = 0, rest = i; j < static_cast<std::size_t>(d); ++j, rest /= static_cast<std::size_t>(side))
                grid.push_back(static_cast<double>(rest % static_cast<std::size_t>(side)));
        const hullkit::DelaunayNd t = hullkit::delaunay_nd(grid.data(), count, d);
        REQUIRE(t.ok());
        const std::vector<double> volume = hullkit::voronoi_nd_volumes(grid.data(), count, d, t.simplices.data(), t.simplex_count());
        INFO("grid in " << d << " dimensions");
        std::size_t interior = 0;
        for (std::size_t i = 0; i < count; ++i) {
            bool inside = true;
            for (int j = 0; j < d; ++j) inside = inside && grid[i * d + j] > 0 && grid[i * d + j] < side - 1;
            INFO("point " << i);
            if (inside) {
                REQUIRE(std::fabs(volume[i] - 1.0) < 1e-12);  // its cell: the unit cube about it
                ++interior;
            } else {
                REQUIRE(std::isinf(volume[i]));
            }
        }
        REQUIRE(interior > 0);
    }
}

TEST_CASE("voronoi_nd_volumes: random points, each bounded cell against the hull of its exact vertices", "[hull_nd][voronoi]") {
    for (int d = 2; d <= 5; ++d) {
        const std::size_t n = d == 5 ? 60 : d == 4 ? 80 : 120;
        const std::vector<double> p = random_points(n, d, 40 + static_cast<unsigned>(d));
        const hullkit::DelaunayNd t = hullkit::delaunay_nd(p.data(), n, d);
        REQUIRE(t.ok());
        const std::vector<double> volume = hullkit::voronoi_nd_volumes(p.data(), n, d, t.simplices.data(), t.simplex_count());
        // Points on the hull (in a facet without a neighbour) have unbounded cells.
        std::vector<char> on_hull(n, 0);
        std::vector<std::vector<std::size_t>> around(n);
        for (std::size_t s = 0; s < t.simplex_count(); ++s)
            for (int k = 0; k <= d; ++k) {
                around[t.simplices[s * (d + 1) + k]].push_back(s);
                if (t.neighbors[s * (d + 1) + k] < 0)
                    for (int j = 0; j <= d; ++j)
                        if (j != k) on_hull[t.simplices[s * (d + 1) + j]] = 1;
            }
        std::vector<std::vector<double>> centre(t.simplex_count());  // each once, exactly, when needed
        std::size_t bounded = 0;
        for (std::size_t i = 0; i < n; ++i) {
            INFO("d " << d << " point " << i);
            if (on_hull[i]) {
                REQUIRE(std::isinf(volume[i]));
                continue;
            }
            REQUIRE(std::isfinite(volume[i]));
            // The hull of rounded circumcentres is slow above 3D: a few cells there.
            if (d > 3 && bounded >= (d == 4 ? 8u : 2u)) continue;
            std::vector<double> vertices;
            for (const std::size_t s : around[i]) {
                if (centre[s].empty()) centre[s] = exact_circumcentre(p, d, t, s);
                vertices.insert(vertices.end(), centre[s].begin(), centre[s].end());
            }
            const double expected = hullkit::hull_nd_volume(vertices.data(), around[i].size(), d);
            REQUIRE(std::isfinite(volume[i]));
            REQUIRE(std::fabs(volume[i] - expected) <= 1e-9 * expected);
            ++bounded;
        }
        REQUIRE(bounded > 0);
    }
}
