// Tests for hullkit::insphere: every sign checked against exact rational arithmetic (GMP), by a
// different formula (the 4x4 determinant of the lifted differences relative to a), on random,
// cospherical, near-cospherical and extreme-scale inputs; every stage is reached.
#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "hullkit/predicates.hpp"

namespace {

using P3 = std::array<double, 3>;

/// The definition: e inside the sphere of positively oriented a, b, c, d gives +1. The lifted
/// orientation det[b-a; c-a; d-a; e-a] (columns x, y, z, |p|^2) is negative then.
int oracle_insphere(const P3& a, const P3& b, const P3& c, const P3& d, const P3& e) {
    const P3* rows[4] = {&b, &c, &d, &e};
    mpq_class m[4][4];
    const mpq_class la = mpq_class(a[0]) * a[0] + mpq_class(a[1]) * a[1] + mpq_class(a[2]) * a[2];
    for (int i = 0; i < 4; ++i) {
        const P3& p = *rows[i];
        for (int k = 0; k < 3; ++k) m[i][k] = mpq_class(p[k]) - mpq_class(a[k]);
        m[i][3] = mpq_class(p[0]) * p[0] + mpq_class(p[1]) * p[1] + mpq_class(p[2]) * p[2] - la;
    }
    // Gaussian elimination in rationals.
    int sign = 1;
    for (int col = 0; col < 4; ++col) {
        int pivot = -1;
        for (int r = col; r < 4; ++r)
            if (sgn(m[r][col]) != 0) {
                pivot = r;
                break;
            }
        if (pivot < 0) return 0;
        if (pivot != col) {
            for (int k = 0; k < 4; ++k) std::swap(m[pivot][k], m[col][k]);
            sign = -sign;
        }
        if (sgn(m[col][col]) < 0) sign = -sign;
        for (int r = col + 1; r < 4; ++r) {
            const mpq_class f = m[r][col] / m[col][col];
            for (int k = col; k < 4; ++k) m[r][k] -= f * m[col][k];
        }
    }
    return -sign;
}

struct Counts {
    int stage[4] = {0, 0, 0, 0};
};

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define AVX2_ENCODED __attribute__((target("avx2")))
bool has_avx2() { return __builtin_cpu_supports("avx2"); }
#else
#define AVX2_ENCODED
bool has_avx2() { return false; }
#endif
/// Stage A in AVX2's encoding (the 3D insertion's conflict tests run so where the processor has it).
AVX2_ENCODED double stage_a_avx2(const P3& a, const P3& b, const P3& c, const P3& d, const P3& e) {
    return hullkit::detail::insphere_stage_a_det(a.data(), b.data(), c.data(), d.data(), e.data());
}

/// The stage A value insphere_stage_a_det returns (packed on x86-64) has the bits of the scalar
/// formula's, zeros' signs and NaNs included.
void check_same_bits(const P3& a, const P3& b, const P3& c, const P3& d, const P3& e) {
    const double want = hullkit::detail::insphere_stage_a_det_scalar(a.data(), b.data(), c.data(), d.data(), e.data());
    auto same_bits = [&](double got) {
        std::uint64_t got_bits = 0, want_bits = 0;
        std::memcpy(&got_bits, &got, sizeof got);
        std::memcpy(&want_bits, &want, sizeof want);
        INFO("stage A " << got << " against the scalar formula's " << want);
        if (std::isnan(want)) {
            REQUIRE(std::isnan(got));
        } else {
            REQUIRE(got_bits == want_bits);
        }
    };
    same_bits(hullkit::detail::insphere_stage_a_det(a.data(), b.data(), c.data(), d.data(), e.data()));
    if (has_avx2()) same_bits(stage_a_avx2(a, b, c, d, e));
}

void check(const P3& a, const P3& b, const P3& c, const P3& d, const P3& e, Counts* counts = nullptr) {
    check_same_bits(a, b, c, d, e);
    int stage = -1;
    const int got = hullkit::detail::insphere_traced(a.data(), b.data(), c.data(), d.data(), e.data(), &stage);
    const int want = oracle_insphere(a, b, c, d, e);
    INFO("a " << a[0] << " " << a[1] << " " << a[2] << " e " << e[0] << " " << e[1] << " " << e[2]);
    REQUIRE(got == want);
    REQUIRE(hullkit::insphere(a.data(), b.data(), c.data(), d.data(), e.data()) == want);
    REQUIRE(hullkit::detail::insphere_exact(a.data(), b.data(), c.data(), d.data(), e.data()) == want);
    const double span = 4.0 * std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2]), std::fabs(b[0]),
                                        std::fabs(b[1]), std::fabs(b[2]), std::fabs(c[0]), std::fabs(c[1]),
                                        std::fabs(c[2]), std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2]),
                                        std::fabs(e[0]), std::fabs(e[1]), std::fabs(e[2])});
    REQUIRE(hullkit::detail::insphere_semi_static(hullkit::detail::insphere_static_bound(span), a.data(), b.data(),
                                                  c.data(), d.data(), e.data()) == want);
    // The per-test bound of the 3D Delaunay's conflicts (insphere_local_bound) is never below the
    // adaptive filter's own bound, and whatever it decides is right.
    const double local = hullkit::detail::insphere_local_bound(a.data(), b.data(), c.data(), d.data(), e.data());
    const hullkit::detail::InsphereStageA filter = hullkit::detail::insphere_stage_a(a.data(), b.data(), c.data(),
                                                                                     d.data(), e.data());
    REQUIRE(local >= hullkit::detail::kInsphereFilterBound * filter.permanent);
    if (std::fabs(filter.det) > local) REQUIRE((filter.det > 0 ? 1 : -1) == want);
    if (counts && stage >= 0) ++counts->stage[stage];
}

}  // namespace

TEST_CASE("insphere: the sign convention (inside a positively oriented tetrahedron's sphere is +1)", "[exact]") {
    const P3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
    REQUIRE(hullkit::orient3d(a.data(), b.data(), c.data(), d.data()) == 1);
    const P3 centre{0.5, 0.5, 0.5}, far{3, 3, 3}, on{1, 1, 1};
    REQUIRE(hullkit::insphere(a.data(), b.data(), c.data(), d.data(), centre.data()) == 1);
    REQUIRE(hullkit::insphere(a.data(), b.data(), c.data(), d.data(), far.data()) == -1);
    REQUIRE(hullkit::insphere(a.data(), b.data(), c.data(), d.data(), on.data()) == 0);
    // Swapping two corners turns the orientation and the sign round.
    REQUIRE(hullkit::insphere(b.data(), a.data(), c.data(), d.data(), centre.data()) == -1);
    check(a, b, c, d, centre);
    check(a, b, c, d, far);
    check(a, b, c, d, on);
}

TEST_CASE("insphere: random points agree with rationals", "[exact]") {
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Counts counts;
    for (int trial = 0; trial < 3000; ++trial) {
        P3 p[5];
        for (auto& q : p)
            for (double& v : q) v = unit(rng);
        check(p[0], p[1], p[2], p[3], p[4], &counts);
    }
    CHECK(counts.stage[0] > 0);
}

TEST_CASE("insphere: cospherical integer points and their neighbours one ulp away", "[exact]") {
    // Integer points with x^2 + y^2 + z^2 = 325 (exactly cospherical), moved by ulps and scaled.
    std::vector<P3> sphere;
    for (int x = -18; x <= 18; ++x)
        for (int y = -18; y <= 18; ++y)
            for (int z = -18; z <= 18; ++z)
                if (x * x + y * y + z * z == 325) sphere.push_back({double(x), double(y), double(z)});
    REQUIRE(sphere.size() > 20);
    std::mt19937_64 rng(7);
    Counts counts;
    for (int trial = 0; trial < 1500; ++trial) {
        P3 p[5];
        for (auto& q : p) q = sphere[rng() % sphere.size()];
        const double scale = std::ldexp(1.0, static_cast<int>(rng() % 60) - 30) * (trial % 3 == 0 ? 0.1 : 1.0);
        for (auto& q : p)
            for (double& v : q) v *= scale;
        if (trial % 2) {
            double& v = p[4][rng() % 3];
            if (v != 0.0) v = std::nextafter(v, (rng() & 1) ? 1e300 : -1e300);  // 0 would go subnormal
        }
        check(p[0], p[1], p[2], p[3], p[4], &counts);
    }
    CHECK(counts.stage[1] > 0);                        // exact differences
    CHECK(counts.stage[2] + counts.stage[3] > 0);      // the 0.1 scale makes differences inexact
}

TEST_CASE("insphere: points on a sphere up to rounding (stage C decides them, GMP agrees)", "[exact]") {
    // Unit vectors rounded to doubles, at several scales and centres: five of them are cospherical
    // up to the rounding of their coordinates, so the determinant is a few eps times its permanent
    // and the filter cannot decide. Tuples of far-apart points (a Delaunay tetrahedralization of a
    // sphere's samples is made of such) and of near neighbours.
    std::mt19937_64 rng(41);
    std::normal_distribution<double> g;
    Counts counts;
    for (int trial = 0; trial < 6000; ++trial) {
        const double scale = std::ldexp(1.0, static_cast<int>(rng() % 40) - 20);
        const double centre[3] = {trial % 3 == 0 ? 0.0 : g(rng), trial % 3 == 2 ? 1e3 * g(rng) : 0.0, 0.0};
        const bool near = trial % 2 == 1;
        double axis[3] = {g(rng), g(rng), g(rng)};
        P3 p[5];
        for (auto& q : p) {
            double v[3];
            for (int k = 0; k < 3; ++k) v[k] = near ? axis[k] + 0.01 * g(rng) : g(rng);
            const double r = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            for (int k = 0; k < 3; ++k) q[k] = centre[k] + scale * (v[k] / r);
        }
        if (hullkit::orient3d(p[0].data(), p[1].data(), p[2].data(), p[3].data()) < 0) std::swap(p[0], p[1]);
        check(p[0], p[1], p[2], p[3], p[4], &counts);
    }
    INFO("stages " << counts.stage[0] << " " << counts.stage[1] << " " << counts.stage[2] << " " << counts.stage[3]);
    CHECK(counts.stage[2] > 1000);                      // decided by stage C
    CHECK(counts.stage[2] > 20 * counts.stage[3]);      // the exact stage is the rare case
}

TEST_CASE("insphere: large integer coordinates (exact differences beyond the plain fast path)", "[exact]") {
    // A sphere of radius 5 * 10^6 around an offset centre: integer points with exact differences that
    // need more than 9 bits.
    std::vector<P3> pts;
    const int r[][3] = {{3, 4, 0}, {0, 3, 4}, {4, 0, 3}, {-3, 4, 0}, {0, -3, 4}, {4, 0, -3}, {5, 0, 0}, {0, 0, -5}};
    for (const auto& q : r) pts.push_back({1e9 + q[0] * 1e6, -2e9 + q[1] * 1e6, 3e3 + q[2] * 1e6});
    Counts counts;
    for (std::size_t i = 0; i + 4 < pts.size(); ++i) {
        check(pts[i], pts[i + 1], pts[i + 2], pts[i + 3], pts[i + 4], &counts);
        P3 moved = pts[i + 4];
        moved[0] += 1.0;
        check(pts[i], pts[i + 1], pts[i + 2], pts[i + 3], moved, &counts);
    }
    CHECK(counts.stage[1] > 0);
}

TEST_CASE("insphere: the ends of the exact range", "[exact]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.5, 1.0);
    for (const double scale : {hullkit::kInsphereMinMagnitude, 0x1p-100, 0x1p+150, hullkit::kInsphereMaxMagnitude / 2}) {
        for (int trial = 0; trial < 200; ++trial) {
            P3 p[5];
            for (auto& q : p)
                for (double& v : q) v = scale * unit(rng) * ((rng() & 1) ? 1 : -1);
            check(p[0], p[1], p[2], p[3], p[4]);
            // Cospherical: the unit cube's corners, scaled.
            const P3 a{scale, 0, 0}, b{0, scale, 0}, c{0, 0, scale}, d{scale, scale, scale}, e{scale, scale, 0};
            check(a, b, c, d, e);
        }
    }
}

TEST_CASE("insphere: insphere_scale_exponent brings data into range", "[exact]") {
    int k = 0;
    REQUIRE(hullkit::insphere_scale_exponent(1e150, 1e140, &k));
    REQUIRE(std::ldexp(1e150, k) <= hullkit::kInsphereMaxMagnitude);
    REQUIRE(std::ldexp(1e140, k) >= hullkit::kInsphereMinMagnitude);
    REQUIRE(hullkit::insphere_scale_exponent(1e-150, 1e-160, &k));
    REQUIRE(std::ldexp(1e-160, k) >= hullkit::kInsphereMinMagnitude);
    REQUIRE(hullkit::insphere_scale_exponent(1.0, 0.5, &k));
    REQUIRE(k == 0);
    REQUIRE_FALSE(hullkit::insphere_scale_exponent(1e100, 1e-100, &k));  // spans more than 2^315
}

TEST_CASE("compare_distance3d: agrees with rationals, ties included", "[exact]") {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    auto oracle = [](const P3& a, const P3& b, const P3& q) {
        mpq_class s = 0;
        for (int k = 0; k < 3; ++k) {
            const mpq_class da = mpq_class(a[k]) - q[k], db = mpq_class(b[k]) - q[k];
            s += da * da - db * db;
        }
        return sgn(s);
    };
    for (int trial = 0; trial < 3000; ++trial) {
        P3 a, b, q;
        for (int k = 0; k < 3; ++k) a[k] = unit(rng), b[k] = unit(rng), q[k] = unit(rng);
        if (trial % 3 == 0) b = {a[1], a[2], a[0]}, q = {0.25, 0.25, 0.25};  // equal distances from a symmetric q
        if (trial % 3 == 1) {                                              // one ulp apart
            b = a;
            b[trial % 3] = std::nextafter(b[trial % 3], 2.0);
            q = {a[0] * 0.5, a[1] * 0.5, a[2] * 0.5};
        }
        REQUIRE(hullkit::compare_distance3d(a.data(), b.data(), q.data()) == oracle(a, b, q));
    }
}

TEST_CASE("insphere: stage A evaluated two lanes at a time has the scalar formula's bits", "[exact]") {
    // Values chosen to round in every product and sum, to cancel to +0 and -0, to underflow to
    // subnormals and to overflow to infinity (beyond the predicates' range, where only the bits are
    // compared), and permutations of the same points.
    std::mt19937_64 rng(71);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double scales[] = {1.0, 0x1p-300, 0x1p-520, 0x1p+200, 0x1p+260, 3.0e-5};
    for (const double scale : scales) {
        for (int trial = 0; trial < 2000; ++trial) {
            P3 p[5];
            for (auto& q : p)
                for (double& v : q) v = scale * unit(rng);
            if (trial % 4 == 1) p[4] = p[trial % 3];                 // e on a corner: zero rows
            if (trial % 4 == 2) p[1] = P3{-p[0][0], p[0][1], -0.0};  // signed zeros in differences
            if (trial % 4 == 3)
                for (auto& q : p) q[2] = p[0][2];  // coplanar: zero z column
            check_same_bits(p[0], p[1], p[2], p[3], p[4]);
            check_same_bits(p[3], p[1], p[0], p[2], p[4]);
        }
    }
    const P3 zero{0.0, 0.0, 0.0}, negative_zero{-0.0, -0.0, -0.0}, big{1e300, -1e300, 1e300};
    check_same_bits(zero, negative_zero, zero, negative_zero, zero);
    check_same_bits(big, zero, negative_zero, P3{-1e300, 1e300, 0}, zero);  // infinities and NaN
}
