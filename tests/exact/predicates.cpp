// Tests for hullkit/predicates.hpp: every sign is checked against exact rational arithmetic (GMP
// mpq_class; every finite double converts to an mpq exactly).
#include "hullkit/predicates.hpp"

#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "hull/hull_checks.hpp"

using hullkit::collinear3d;
using hullkit::kPredicateMaxMagnitude;
using hullkit::kPredicateMinMagnitude;
using hullkit::orient2d;
using hullkit::orient3d;

namespace {

using P3 = std::array<double, 3>;
using P2 = std::array<double, 2>;

// ---- exact reference ----

int oracle_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    // det[b-a; c-a], a different (but equal) formula from the one the implementation uses
    const mpq_class abx = mpq_class(bx) - mpq_class(ax);
    const mpq_class aby = mpq_class(by) - mpq_class(ay);
    const mpq_class acx = mpq_class(cx) - mpq_class(ax);
    const mpq_class acy = mpq_class(cy) - mpq_class(ay);
    const mpq_class det = abx * acy - aby * acx;
    return sgn(det);
}

/// The definition: sign of ((b-a) x (c-a)) . (d-a), in rationals (shared with the hull checks).
int oracle_orient3d(const P3& a, const P3& b, const P3& c, const P3& d) {
    return hullkit_test::rational_orient3d(a.data(), b.data(), c.data(), d.data());
}

int oracle_collinear3d(const P3& a, const P3& b, const P3& c) {
    return hullkit_test::exact_collinear(a.data(), b.data(), c.data()) ? 1 : 0;
}

// ---- helpers ----

std::string fmt(double x) {
    std::ostringstream out;
    out << std::hexfloat << x;
    return out.str();
}
std::string fmt(const P3& p) { return "(" + fmt(p[0]) + ", " + fmt(p[1]) + ", " + fmt(p[2]) + ")"; }

/// x moved by k units in the last place (k < 0: towards -inf).
double ulps(double x, int k) {
    const double toward = k < 0 ? -INFINITY : INFINITY;
    for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, toward);
    return x;
}

/// Like ulps, but leaves 0 alone: the neighbours of 0 are subnormal, outside the valid range.
double nudge(double x, int k) { return x == 0.0 ? x : ulps(x, k); }

struct Rng {
    std::mt19937_64 gen;
    explicit Rng(std::uint64_t seed) : gen(seed) {}
    /// Uniform in [0, 1), 53 random bits (independent of the standard library's distributions).
    double unit() { return static_cast<double>(gen() >> 11) * 0x1p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    /// Uniform integer in [lo, hi].
    std::int64_t integer(std::int64_t lo, std::int64_t hi) {
        return lo + static_cast<std::int64_t>(gen() % static_cast<std::uint64_t>(hi - lo + 1));
    }
    P3 point(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    double sign() { return integer(0, 1) ? 1.0 : -1.0; }
    /// uniform(lo, hi) * 2^e with e uniform in [emin, emax]. (Helpers like this one keep the order
    /// of the draws fixed: the order of evaluation of function arguments is not, and the cases
    /// should be the same with every compiler.)
    double scaled_uniform(double lo, double hi, int emin, int emax) {
        const double m = uniform(lo, hi);
        const int e = static_cast<int>(integer(emin, emax));
        return std::ldexp(m, e);
    }
    /// m * 2^e with the integer m uniform in [mlo, mhi].
    double dyadic(std::int64_t mlo, std::int64_t mhi, int e) {
        return std::ldexp(static_cast<double>(integer(mlo, mhi)), e);
    }
};

/// Counts of checked cases, and a record of the first mismatches.
struct Tally {
    long cases = 0;
    long zeros = 0;                 // exact answer 0
    long stage[4] = {0, 0, 0, 0};   // which adaptive stage decided
    long mismatches = 0;
    std::vector<std::string> failures;

    void fail(const std::string& what) {
        ++mismatches;
        if (failures.size() < 8) failures.push_back(what);
    }
    std::string summary() const {
        std::ostringstream out;
        out << cases << " cases, " << zeros << " exact zeros, decided by stage A/B/C/D: " << stage[0]
            << "/" << stage[1] << "/" << stage[2] << "/" << stage[3];
        return out.str();
    }
};

/// Checks orient3d(a, b, c, d) (public, traced and exact-only paths) against the oracle. Returns the
/// exact sign.
int check3(Tally& t, const P3& a, const P3& b, const P3& c, const P3& d) {
    int stage = -1;
    const int traced = hullkit::detail::orient3d_traced(a.data(), b.data(), c.data(), d.data(), &stage);
    const int pub = orient3d(a.data(), b.data(), c.data(), d.data());
    const int exact = hullkit::detail::orient3d_exact(a.data(), b.data(), c.data(), d.data());
    const int want = oracle_orient3d(a, b, c, d);
    ++t.cases;
    if (want == 0) ++t.zeros;
    if (stage >= 0 && stage < 4) ++t.stage[stage];
    if (traced != want || pub != want || exact != want || stage < 0 || stage > 3) {
        t.fail("orient3d" + fmt(a) + fmt(b) + fmt(c) + fmt(d) + ": want " + std::to_string(want) +
               ", public " + std::to_string(pub) + ", traced " + std::to_string(traced) +
               " (stage " + std::to_string(stage) + "), exact " + std::to_string(exact));
    }
    return want;
}

int check2(Tally& t, double ax, double ay, double bx, double by, double cx, double cy) {
    int stage = -1;
    const int traced = hullkit::detail::orient2d_traced(ax, ay, bx, by, cx, cy, &stage);
    const int pub = orient2d(ax, ay, bx, by, cx, cy);
    const int exact = hullkit::detail::orient2d_exact(ax, ay, bx, by, cx, cy);
    const int want = oracle_orient2d(ax, ay, bx, by, cx, cy);
    ++t.cases;
    if (want == 0) ++t.zeros;
    if (stage >= 0 && stage < 4) ++t.stage[stage];
    if (traced != want || pub != want || exact != want || stage < 0 || stage > 3) {
        t.fail("orient2d(" + fmt(ax) + ", " + fmt(ay) + ", " + fmt(bx) + ", " + fmt(by) + ", " +
               fmt(cx) + ", " + fmt(cy) + "): want " + std::to_string(want) + ", public " +
               std::to_string(pub) + ", traced " + std::to_string(traced) + " (stage " +
               std::to_string(stage) + "), exact " + std::to_string(exact));
    }
    return want;
}

int check2(Tally& t, const P2& a, const P2& b, const P2& c) {
    return check2(t, a[0], a[1], b[0], b[1], c[0], c[1]);
}

int check_collinear(Tally& t, const P3& a, const P3& b, const P3& c) {
    const int got = collinear3d(a.data(), b.data(), c.data());
    const int want = oracle_collinear3d(a, b, c);
    ++t.cases;
    if (want) ++t.zeros;
    if (got != want) {
        t.fail("collinear3d" + fmt(a) + fmt(b) + fmt(c) + ": want " + std::to_string(want) +
               ", got " + std::to_string(got));
    }
    return want;
}

void require_clean(const Tally& t, long min_cases) {
    INFO(t.summary());
    for (const auto& f : t.failures) UNSCOPED_INFO(f);
    CHECK(t.mismatches == 0);
    CHECK(t.cases >= min_cases);
}

/// p + s (q - p) + t (r - p) in floating point: a point near the plane p, q, r.
P3 near_plane(const P3& p, const P3& q, const P3& r, double s, double t) {
    P3 out;
    for (int i = 0; i < 3; ++i) out[i] = p[i] + s * (q[i] - p[i]) + t * (r[i] - p[i]);
    return out;
}

/// Puts `moving` into argument slot `slot` (0..3) and the fixed points, in order, around it.
int check3_slot(Tally& t, int slot, const P3& moving, const P3& f0, const P3& f1, const P3& f2) {
    switch (slot) {
        case 0: return check3(t, moving, f0, f1, f2);
        case 1: return check3(t, f0, moving, f1, f2);
        case 2: return check3(t, f0, f1, moving, f2);
        default: return check3(t, f0, f1, f2, moving);
    }
}

/// A point scaled by 2^k (exact inside the range).
P3 scaled(const P3& p, int k) { return {std::ldexp(p[0], k), std::ldexp(p[1], k), std::ldexp(p[2], k)}; }

// The 24 permutations of 4 items with their parity.
struct Perm4 {
    int idx[4];
    int parity;  // +1 even, -1 odd
};
std::vector<Perm4> all_perms4() {
    std::vector<Perm4> out;
    int p[4] = {0, 1, 2, 3};
    do {
        int inversions = 0;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) inversions += p[i] > p[j];
        out.push_back({{p[0], p[1], p[2], p[3]}, inversions % 2 ? -1 : 1});
    } while (std::next_permutation(p, p + 4));
    return out;
}

}  // namespace

// -------------------------------------------------------------------------------------------------

TEST_CASE("predicates: sign conventions") {
    // orient2d: counter-clockwise is +1
    CHECK(orient2d(0, 0, 1, 0, 0, 1) == 1);
    CHECK(orient2d(0, 0, 0, 1, 1, 0) == -1);
    CHECK(orient2d(0, 0, 1, 1, 2, 2) == 0);
    CHECK(orient2d(1, 1, 1, 1, 1, 1) == 0);
    // orient3d: +1 when d is on the side (b-a) x (c-a) points to (opposite of Shewchuk's)
    const P3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, up{0, 0, 1}, down{0, 0, -1};
    CHECK(orient3d(o.data(), x.data(), y.data(), up.data()) == 1);
    CHECK(orient3d(o.data(), x.data(), y.data(), down.data()) == -1);
    CHECK(orient3d(o.data(), y.data(), x.data(), up.data()) == -1);
    const P3 in_plane{0.25, 7.5, 0};
    CHECK(orient3d(o.data(), x.data(), y.data(), in_plane.data()) == 0);
    CHECK(orient3d(o.data(), o.data(), o.data(), o.data()) == 0);
    // collinear3d
    const P3 two_x{2, 0, 0};
    CHECK(collinear3d(o.data(), x.data(), two_x.data()) == 1);
    CHECK(collinear3d(o.data(), x.data(), y.data()) == 0);
    CHECK(collinear3d(x.data(), x.data(), y.data()) == 1);
}

TEST_CASE("predicates: orient2d near-degenerate grid") {
    // Shewchuk's classic experiment: a point stepped k ulps in x and y around a point on (or next
    // to) a line; naive evaluation gives a noisy sign pattern here, the exact sign is a clean split.
    struct Config {
        const char* name;
        P2 base;       // the point that is stepped
        P2 q, r;       // the fixed line
        int slot;      // argument position of the stepped point
    };
    const P2 q1{12, 12}, r1{24, 24};
    const P2 q2{0.1, 0.7}, r2{7.3, -2.9};
    // the classic configuration at a large offset: the line points are ~2^30 times farther away
    // than in the classic plot, so the ulp steps of 1e9 + 0.5 are as fine relative to them
    const P2 q3{1e9 + 12 * 0x1p30, 1e9 + 12 * 0x1p30}, r3{1e9 + 24 * 0x1p30, 1e9 + 24 * 0x1p30};
    const P2 q4{1e-3, 3e5}, r4{2e6, -7e-2};
    const double s = 0.37;
    const P2 on2{q2[0] + s * (r2[0] - q2[0]), q2[1] + s * (r2[1] - q2[1])};
    const P2 on4{q4[0] + s * (r4[0] - q4[0]), q4[1] + s * (r4[1] - q4[1])};
    const Config configs[] = {
        {"classic (0.5,0.5) / (12,12) / (24,24)", {0.5, 0.5}, q1, r1, 0},
        {"classic, stepped point last", {0.5, 0.5}, q1, r1, 2},
        {"non-dyadic line", on2, q2, r2, 1},
        {"classic at offset 1e9", {1e9 + 0.5, 1e9 + 0.5}, q3, r3, 0},
        {"classic with (0.1, 0.1): inexact differences", {0.1, 0.1}, q1, r1, 1},
        {"mixed magnitudes", on4, q4, r4, 2},
    };
    const int n = 64;
    Tally total;
    for (const Config& cfg : configs) {
        Tally t;
        for (int i = -n; i <= n; ++i) {
            for (int j = -n; j <= n; ++j) {
                const P2 p{ulps(cfg.base[0], i), ulps(cfg.base[1], j)};
                if (cfg.slot == 0) check2(t, p, cfg.q, cfg.r);
                else if (cfg.slot == 1) check2(t, cfg.q, p, cfg.r);
                else check2(t, cfg.q, cfg.r, p);
            }
        }
        INFO(cfg.name);
        require_clean(t, (2 * n + 1) * (2 * n + 1));
        CHECK(t.stage[0] < t.cases);  // the grid must reach past the filter
        total.cases += t.cases;
        total.zeros += t.zeros;
        for (int k = 0; k < 4; ++k) total.stage[k] += t.stage[k];
    }
    INFO(total.summary());
    CHECK(total.zeros > 0);
    CHECK(total.stage[1] > 0);
    CHECK(total.stage[2] > 0);
    CHECK(total.stage[3] > 0);
}

TEST_CASE("predicates: orient3d near-degenerate grid") {
    struct Config {
        const char* name;
        P3 base;         // the stepped point
        P3 f0, f1, f2;   // fixed points spanning the plane
        int axis_i, axis_j;
        int slot;
    };
    // the 3D analogue of the classic plot: (0.5, 0.5, 0.5) lies on the line through (12,12,12) and
    // (24,24,24), hence on every plane through that line
    const P3 c12{12, 12, 12}, c24{24, 24, 24}, side{0.5, 3.25, -7};
    const P3 b{0.1, 0.2, 0.3}, c{1.7, -0.4, 2.9}, d{-3.3, 5.5, 0.7};
    const double big = 0x1p30;
    const P3 o12{1e9 + 12 * big, 1e9 + 12 * big, 1e9 + 12 * big},
        o24{1e9 + 24 * big, 1e9 + 24 * big, 1e9 + 24 * big},
        oside{1e9 + 0.5 * big, 1e9 + 3.25 * big, 1e9 - 7 * big};
    const P3 mb{1e-3, 2e-3, 5}, mc{3e5, -2e4, 1}, md{7, 1e2, -3e-2};
    const Config configs[] = {
        {"classic (0.5,0.5,0.5) on the line (12,12,12)-(24,24,24)", {0.5, 0.5, 0.5}, c12, c24, side, 0, 1, 0},
        {"classic, stepped point last", {0.5, 0.5, 0.5}, c12, side, c24, 0, 2, 3},
        {"non-dyadic plane", near_plane(b, c, d, 0.3, 0.6), b, c, d, 0, 1, 3},
        {"non-dyadic plane, first slot", near_plane(b, c, d, -0.7, 1.3), b, c, d, 1, 2, 0},
        {"classic at offset 1e9", {1e9 + 0.5, 1e9 + 0.5, 1e9 + 0.5}, o12, o24, oside, 0, 2, 1},
        {"classic with (0.1, 0.1, 0.1): inexact differences", {0.1, 0.1, 0.1}, side, c24, c12, 1, 2, 2},
        {"mixed magnitudes", near_plane(mb, mc, md, 0.45, 0.15), mb, mc, md, 2, 0, 2},
    };
    const int n = 40;
    Tally total;
    for (const Config& cfg : configs) {
        Tally t;
        for (int i = -n; i <= n; ++i) {
            for (int j = -n; j <= n; ++j) {
                P3 p = cfg.base;
                p[cfg.axis_i] = ulps(p[cfg.axis_i], i);
                p[cfg.axis_j] = ulps(p[cfg.axis_j], j);
                check3_slot(t, cfg.slot, p, cfg.f0, cfg.f1, cfg.f2);
            }
        }
        INFO(cfg.name);
        require_clean(t, (2 * n + 1) * (2 * n + 1));
        CHECK(t.stage[0] < t.cases);
        total.cases += t.cases;
        total.zeros += t.zeros;
        for (int k = 0; k < 4; ++k) total.stage[k] += t.stage[k];
    }
    INFO(total.summary());
    CHECK(total.zeros > 0);
    CHECK(total.stage[1] > 0);
    CHECK(total.stage[2] > 0);
    CHECK(total.stage[3] > 0);
}

TEST_CASE("predicates: exactly collinear and coplanar points") {
    Rng rng(0x5eed0001);
    const auto perms = all_perms4();

    SECTION("integer coordinates: zero, and one ulp away") {
        Tally t;
        for (int iter = 0; iter < 1500; ++iter) {
            const double lim = 1 << 20;
            P3 a, b, c;
            for (int i = 0; i < 3; ++i) {
                a[i] = static_cast<double>(rng.integer(-lim, lim));
                b[i] = static_cast<double>(rng.integer(-lim, lim));
                c[i] = static_cast<double>(rng.integer(-lim, lim));
            }
            const double s = static_cast<double>(rng.integer(-8, 8));
            const double u = static_cast<double>(rng.integer(-8, 8));
            const P3 d = near_plane(a, b, c, s, u);  // exact: small integers
            CHECK(check3(t, a, b, c, d) == 0);
            const auto& perm = perms[iter % perms.size()];
            const P3* pts[4] = {&a, &b, &c, &d};
            CHECK(check3(t, *pts[perm.idx[0]], *pts[perm.idx[1]], *pts[perm.idx[2]], *pts[perm.idx[3]]) == 0);
            // one ulp off the plane in each axis: tiny nonzero (unless the plane contains the axis)
            for (int axis = 0; axis < 3; ++axis) {
                P3 e = d;
                e[axis] = nudge(e[axis], (iter & 1) ? 1 : -1);
                check3(t, a, b, c, e);
            }
        }
        require_clean(t, 7500);
        CHECK(t.zeros >= 3000);
    }

    SECTION("exact zeros with inexact differences: planes z = alpha x + beta y") {
        // Each point gets its own scale 2^e (e from -60 to 40), and z = alpha x + beta y with
        // power-of-two alpha, beta is then exact; the four points lie exactly on one plane through
        // the origin, but the differences of their coordinates are not representable, so the tail
        // stages and the full exact stage have to produce the zeros.
        Tally t;
        for (int iter = 0; iter < 1500; ++iter) {
            const double alpha = rng.sign() * std::ldexp(1.0, static_cast<int>(rng.integer(-3, 3)));
            const double beta = rng.sign() * std::ldexp(1.0, static_cast<int>(rng.integer(-3, 3)));
            P3 pts[4];
            for (P3& p : pts) {
                const int e = static_cast<int>(rng.integer(-60, 40));
                p[0] = std::ldexp(static_cast<double>(rng.integer(-(1 << 20), 1 << 20)), e);
                const int ey = e + static_cast<int>(rng.integer(-5, 5));
                p[1] = rng.dyadic(-(1 << 20), 1 << 20, ey);
                p[2] = alpha * p[0] + beta * p[1];  // exact: at most 20 + 5 + 6 + 2 bits
                if (iter % 3 == 0) std::swap(p[1], p[2]);  // also planes y = alpha x + beta z
            }
            CHECK(check3(t, pts[0], pts[1], pts[2], pts[3]) == 0);
            CHECK(check3(t, pts[3], pts[1], pts[0], pts[2]) == 0);
            P3 e = pts[3];
            const int axis = static_cast<int>(rng.integer(0, 2));
            e[axis] = nudge(e[axis], (iter & 1) ? 1 : -1);
            check3(t, pts[0], e, pts[1], pts[2]);
            // and orient2d on lines y = alpha x, with the same spread of scales
            const double x1 = pts[0][0], x2 = pts[1][0], x3 = pts[2][0];
            CHECK(check2(t, x1, alpha * x1, x2, alpha * x2, x3, alpha * x3) == 0);
            check2(t, x1, alpha * x1, x2, nudge(alpha * x2, 1), x3, alpha * x3);
        }
        require_clean(t, 7500);
        CHECK(t.zeros >= 4000);
        CHECK(t.stage[3] > 1000);  // exact zeros from inexact differences need the last stage
    }

    SECTION("coplanar points with a large offset") {
        Tally t;
        const double offset = 0x1p30;
        for (int iter = 0; iter < 1500; ++iter) {
            P3 a, b, c;
            for (int i = 0; i < 3; ++i) {
                a[i] = offset + std::ldexp(static_cast<double>(rng.integer(-4096, 4096)), -10);
                b[i] = offset + std::ldexp(static_cast<double>(rng.integer(-4096, 4096)), -10);
                c[i] = offset + std::ldexp(static_cast<double>(rng.integer(-4096, 4096)), -10);
            }
            const double s = std::ldexp(static_cast<double>(rng.integer(-16, 16)), -2);
            const double u = std::ldexp(static_cast<double>(rng.integer(-16, 16)), -2);
            const P3 d = near_plane(a, b, c, s, u);
            CHECK(check3(t, a, b, c, d) == 0);
            P3 e = d;
            e[iter % 3] = ulps(e[iter % 3], (iter & 2) ? 2 : -1);
            check3(t, b, a, e, c);
        }
        require_clean(t, 3000);
        CHECK(t.zeros >= 1500);
    }

    SECTION("points on axis-parallel and diagonal planes with arbitrary coordinates") {
        // z == 0 for all four points, or x == y: exactly coplanar whatever the other coordinates
        Tally t;
        for (int iter = 0; iter < 1000; ++iter) {
            P3 pts[4];
            for (auto& p : pts) {
                const double e1 = std::ldexp(1.0, static_cast<int>(rng.integer(-40, 40)));
                const double e2 = std::ldexp(1.0, static_cast<int>(rng.integer(-40, 40)));
                const double x = rng.uniform(-1, 1) * e1;
                const double y = rng.uniform(-1, 1) * e2;
                if (iter % 2 == 0) p = {x, y, 0.0};
                else p = {x, x, y};
            }
            CHECK(check3(t, pts[0], pts[1], pts[2], pts[3]) == 0);
        }
        require_clean(t, 1000);
        CHECK(t.zeros == t.cases);
    }

    SECTION("orient2d: collinear integer and dyadic points") {
        Tally t;
        for (int iter = 0; iter < 3000; ++iter) {
            const int e = static_cast<int>(rng.integer(-30, 30));
            const double ax = std::ldexp(static_cast<double>(rng.integer(-(1 << 24), 1 << 24)), e);
            const double ay = std::ldexp(static_cast<double>(rng.integer(-(1 << 24), 1 << 24)), e);
            const double bx = std::ldexp(static_cast<double>(rng.integer(-(1 << 24), 1 << 24)), e);
            const double by = std::ldexp(static_cast<double>(rng.integer(-(1 << 24), 1 << 24)), e);
            const double s = std::ldexp(static_cast<double>(rng.integer(-64, 64)), -3);
            const double cx = ax + s * (bx - ax);  // exact: at most 24 + 8 + 2 bits
            const double cy = ay + s * (by - ay);
            CHECK(check2(t, ax, ay, bx, by, cx, cy) == 0);
            CHECK(check2(t, cx, cy, ax, ay, bx, by) == 0);
            check2(t, ax, ay, bx, by, nudge(cx, 1), cy);
            check2(t, ax, ay, nudge(bx, -1), by, cx, cy);
        }
        require_clean(t, 12000);
        CHECK(t.zeros >= 6000);
    }
}

TEST_CASE("predicates: collinear3d") {
    Rng rng(0x5eed0002);
    Tally t;
    for (int iter = 0; iter < 3000; ++iter) {
        const int e = static_cast<int>(rng.integer(-20, 20));
        P3 a, b, c;
        for (int i = 0; i < 3; ++i) {
            a[i] = std::ldexp(static_cast<double>(rng.integer(-(1 << 24), 1 << 24)), e);
            b[i] = (iter % 7 == 0) ? a[i] : std::ldexp(static_cast<double>(rng.integer(-(1 << 24), 1 << 24)), e);
        }
        const double s = std::ldexp(static_cast<double>(rng.integer(-64, 64)), -3);
        for (int i = 0; i < 3; ++i) c[i] = a[i] + s * (b[i] - a[i]);  // exactly on the line
        CHECK(check_collinear(t, a, b, c) == 1);
        CHECK(check_collinear(t, c, a, b) == 1);
        P3 off = c;
        off[iter % 3] = nudge(off[iter % 3], 1);
        check_collinear(t, a, b, off);
        // nearly collinear, inexact: a point on the line rounded
        const double r = rng.uniform(-2, 2);
        P3 near;
        for (int i = 0; i < 3; ++i) near[i] = a[i] + r * (b[i] - a[i]);
        check_collinear(t, a, b, near);
        check_collinear(t, a, b, rng.point(-1, 1));
    }
    require_clean(t, 15000);
    CHECK(t.zeros >= 6000);
    CHECK(t.zeros < t.cases);
}

TEST_CASE("predicates: random points with large offsets") {
    Rng rng(0x5eed0003);
    SECTION("orient3d") {
        Tally t;
        for (int iter = 0; iter < 6000; ++iter) {
            const int kind = iter % 4;
            const double offset = (iter / 4) % 2 ? 1e9 : 0.0;
            P3 a, b, c, d;
            if (kind == 0) {  // uniform in a small box around the offset
                a = rng.point(offset - 1, offset + 1);
                b = rng.point(offset - 1, offset + 1);
                c = rng.point(offset - 1, offset + 1);
                d = rng.point(offset - 1, offset + 1);
            } else if (kind == 1) {  // d on the plane, rounded: near-degenerate, inexact differences
                a = rng.point(offset - 1, offset + 1);
                b = rng.point(offset - 1, offset + 1);
                c = rng.point(offset - 1, offset + 1);
                const double s = rng.uniform(-2, 2);
                d = near_plane(a, b, c, s, rng.uniform(-2, 2));
            } else if (kind == 2) {  // mixed magnitudes
                auto coord = [&]() {
                    return offset + rng.scaled_uniform(-1, 1, -40, 40);
                };
                for (P3* p : {&a, &b, &c, &d})
                    for (double& v : *p) v = coord();
            } else {  // nearly collinear a, b, c and a rounded point near their plane
                a = rng.point(offset - 1, offset + 1);
                b = rng.point(offset - 1, offset + 1);
                for (int i = 0; i < 3; ++i) c[i] = a[i] + 0.5 * (b[i] - a[i]);
                c[iter % 3] = ulps(c[iter % 3], 3);
                const double s = rng.uniform(-2, 2);
                d = near_plane(a, b, c, s, rng.uniform(-2, 2));
            }
            check3(t, a, b, c, d);
        }
        require_clean(t, 6000);
        CHECK(t.stage[0] > 0);
        CHECK(t.stage[0] < t.cases);
    }
    SECTION("orient2d") {
        Tally t;
        for (int iter = 0; iter < 6000; ++iter) {
            const double offset = iter % 2 ? 1e9 : 0.0;
            const double ax = offset + rng.uniform(-1, 1), ay = offset + rng.uniform(-1, 1);
            const double bx = offset + rng.uniform(-1, 1), by = offset + rng.uniform(-1, 1);
            if (iter % 3 == 0) {
                const double cx = offset + rng.uniform(-1, 1);
                check2(t, ax, ay, bx, by, cx, offset + rng.uniform(-1, 1));
            } else {
                const double s = rng.uniform(-3, 3);
                check2(t, ax, ay, bx, by, ax + s * (bx - ax), ay + s * (by - ay));
            }
        }
        require_clean(t, 6000);
    }
}

TEST_CASE("predicates: values near the range limits") {
    Rng rng(0x5eed0004);
    const auto magnitude_limits = [](const std::vector<P3>& pts) {
        double hi = 0.0, lo = INFINITY;
        for (const P3& p : pts)
            for (double v : p) {
                if (v == 0.0) continue;
                hi = std::max(hi, std::fabs(v));
                lo = std::min(lo, std::fabs(v));
            }
        return std::pair<double, double>(hi, lo);
    };

    SECTION("near-degenerate grids scaled to the top and the bottom of the range") {
        const P3 b{0.1, 0.2, 0.3}, c{1.7, -0.4, 2.9}, d{-3.3, 5.5, 0.7};
        const P3 base = near_plane(b, c, d, 0.3, 0.6);
        std::vector<std::array<P3, 4>> cases;
        for (int i = -12; i <= 12; ++i)
            for (int j = -12; j <= 12; ++j) {
                P3 p = base;
                p[0] = ulps(p[0], i);
                p[1] = ulps(p[1], j);
                cases.push_back({b, c, d, p});
            }
        std::vector<P3> all;
        for (const auto& q : cases) all.insert(all.end(), q.begin(), q.end());
        const auto [hi, lo] = magnitude_limits(all);
        int ehi = 0, elo = 0;
        std::frexp(hi, &ehi);  // hi < 2^ehi
        std::frexp(lo, &elo);  // lo >= 2^(elo-1)
        const int k_top = 335 - ehi;      // hi * 2^k_top < 2^335
        const int k_bottom = -249 - elo;  // lo * 2^k_bottom >= 2^-250
        Tally t;
        for (const auto& q : cases) {
            const int unscaled = check3(t, q[0], q[1], q[2], q[3]);
            for (int k : {k_top, k_bottom}) {
                const P3 sa = scaled(q[0], k), sb = scaled(q[1], k), sc = scaled(q[2], k), sd = scaled(q[3], k);
                const auto [shi, slo] = magnitude_limits({sa, sb, sc, sd});
                CHECK(hullkit::predicates_range_ok(shi, slo));
                CHECK(check3(t, sa, sb, sc, sd) == unscaled);
            }
        }
        // the scaled sets really touch the limits
        CHECK(std::ldexp(hi, k_top) > kPredicateMaxMagnitude / 2);
        CHECK(std::ldexp(lo, k_bottom) < kPredicateMinMagnitude * 2);
        require_clean(t, 3 * 625);
    }

    SECTION("2D grid scaled to the limits") {
        Tally t;
        const int n = 16;
        for (int k : {335 - 5, -250 + 2}) {  // (24,24) * 2^330 < 2^335; 0.5 * 2^-248 >= 2^-250
            for (int i = -n; i <= n; ++i)
                for (int j = -n; j <= n; ++j) {
                    const double px = ulps(0.5, i), py = ulps(0.5, j);
                    const int unscaled = check2(t, px, py, 12, 12, 24, 24);
                    CHECK(check2(t, std::ldexp(px, k), std::ldexp(py, k), std::ldexp(12.0, k),
                                 std::ldexp(12.0, k), std::ldexp(24.0, k), std::ldexp(24.0, k)) == unscaled);
                }
        }
        require_clean(t, 4 * 33 * 33);
    }

    SECTION("exactly coplanar lattices at both ends") {
        Tally t;
        for (int iter = 0; iter < 800; ++iter) {
            const int k = iter % 2 ? 335 - 21 : -250;  // coordinates up to 2^20 * 2^314, or >= 2^-250
            P3 a, b, c;
            for (int i = 0; i < 3; ++i) {
                a[i] = static_cast<double>(rng.integer(1, 1 << 16));
                a[i] *= rng.sign();
                b[i] = static_cast<double>(rng.integer(1, 1 << 16));
                b[i] *= rng.sign();
                c[i] = static_cast<double>(rng.integer(1, 1 << 16));
                c[i] *= rng.sign();
            }
            const double s = static_cast<double>(rng.integer(-4, 4));
            const P3 d = near_plane(a, b, c, s, static_cast<double>(rng.integer(-4, 4)));
            const P3 sa = scaled(a, k), sb = scaled(b, k), sc = scaled(c, k), sd = scaled(d, k);
            const auto [shi, slo] = magnitude_limits({sa, sb, sc, sd});
            CHECK(hullkit::predicates_range_ok(shi, slo));
            CHECK(check3(t, sa, sb, sc, sd) == 0);
            P3 e = sd;
            e[iter % 3] = nudge(e[iter % 3], iter % 4 < 2 ? 1 : -1);
            check3(t, sa, sb, sc, e);
            CHECK(check_collinear(t, sa, sb, scaled(near_plane(a, b, a, 3.0, 0.0), k)) == 1);
        }
        require_clean(t, 2400);
    }

    SECTION("coordinates mixing the largest and the smallest magnitudes") {
        // Every coordinate is 0, about +-2^-250 or about +-2^335 (or 1): differences like
        // 2^335 - 2^-250 round, and their tails are as small as the range allows.
        const double values[] = {0.0,
                                 kPredicateMinMagnitude,
                                 kPredicateMinMagnitude * 3,
                                 ulps(kPredicateMinMagnitude, 5),
                                 1.0,
                                 ulps(1.0, -1),
                                 kPredicateMaxMagnitude,
                                 kPredicateMaxMagnitude / 2,
                                 ulps(kPredicateMaxMagnitude, -1),
                                 ulps(kPredicateMaxMagnitude * 0.75, 3)};
        const int nvalues = sizeof(values) / sizeof(values[0]);
        auto pick = [&]() {
            const double v = values[rng.integer(0, nvalues - 1)];
            return rng.integer(0, 1) ? v : -v;
        };
        Tally t;
        for (int iter = 0; iter < 6000; ++iter) {
            P3 a, b, c, d;
            for (P3* p : {&a, &b, &c, &d})
                for (double& v : *p) v = pick();
            if (iter % 3 == 0) d = c;        // forces degeneracies
            if (iter % 5 == 0) d[0] = a[0];  // partial coincidences
            const auto [hi, lo] = magnitude_limits({a, b, c, d});
            CHECK(hullkit::predicates_range_ok(hi, lo));
            check3(t, a, b, c, d);
            check2(t, a[0], a[1], b[0], b[1], c[0], c[1]);
            check_collinear(t, a, b, c);
        }
        require_clean(t, 18000);
        CHECK(t.stage[0] > 0);
        CHECK(t.stage[0] < t.cases);
    }

    SECTION("predicates_range_ok and predicates_scale_exponent") {
        using hullkit::predicates_range_ok;
        using hullkit::predicates_scale_exponent;
        CHECK(predicates_range_ok(kPredicateMaxMagnitude, kPredicateMinMagnitude));
        CHECK(predicates_range_ok(1.0, 1.0));
        CHECK(predicates_range_ok(0.0, 0.0));
        CHECK_FALSE(predicates_range_ok(ulps(kPredicateMaxMagnitude, 1), 1.0));
        CHECK_FALSE(predicates_range_ok(1.0, ulps(kPredicateMinMagnitude, -1)));
        CHECK_FALSE(predicates_range_ok(INFINITY, 1.0));
        CHECK_FALSE(predicates_range_ok(NAN, 1.0));

        int k = 12345;
        CHECK(predicates_scale_exponent(1e10, 1e-10, &k));
        CHECK(k == 0);
        CHECK(predicates_scale_exponent(0.0, 0.0, &k));
        CHECK(k == 0);
        CHECK(predicates_scale_exponent(0x1p400, 1.0, &k));
        CHECK(k == -65);
        CHECK(predicates_scale_exponent(0x1.8p400, 1.0, &k));
        CHECK(k == -66);
        CHECK(predicates_scale_exponent(1.0, 0x1p-300, &k));
        CHECK(k == 50);
        CHECK(predicates_scale_exponent(0x1p-1000, 0x1p-1074, &k));  // subnormal input
        CHECK(k == 824);
        k = 777;
        CHECK_FALSE(predicates_scale_exponent(1e200, 1e-200, &k));
        CHECK_FALSE(predicates_scale_exponent(INFINITY, 1.0, &k));
        CHECK_FALSE(predicates_scale_exponent(NAN, 1.0, &k));
        CHECK_FALSE(predicates_scale_exponent(1.0, 0.0, &k));
        CHECK(k == 777);

        // random extremes: success iff some power of two fits, and the one found is closest to 0
        long ok_count = 0, bad = 0;
        for (int iter = 0; iter < 2000; ++iter) {
            const double hi = rng.scaled_uniform(1, 2, -1070, 1020);
            const double lo = std::min(hi, rng.scaled_uniform(1, 2, -1070, 1020));
            int e = 0;
            const bool ok = predicates_scale_exponent(hi, lo, &e);
            // brute force over all exponents that keep hi and lo finite and nonzero
            bool any = false;
            int best = 0;
            for (int cand = -2200; cand <= 2200; ++cand) {
                if (predicates_range_ok(std::ldexp(hi, cand), std::ldexp(lo, cand)) &&
                    std::ldexp(std::ldexp(lo, cand), -cand) == lo) {
                    if (!any || std::abs(cand) < std::abs(best)) best = cand;
                    any = true;
                }
            }
            if (ok != any || (ok && e != best)) ++bad;
            ok_count += ok;
        }
        CHECK(bad == 0);
        CHECK(ok_count > 100);
    }
}

TEST_CASE("predicates: permutation symmetry") {
    Rng rng(0x5eed0005);
    const auto perms = all_perms4();
    Tally t;
    long perm_mismatches = 0;
    for (int iter = 0; iter < 600; ++iter) {
        P3 pts[4];
        const int kind = iter % 3;
        if (kind == 0) {  // near-degenerate, inexact
            for (int i = 0; i < 3; ++i) pts[i] = rng.point(-1, 1);
            const double s = rng.uniform(-2, 2);
            pts[3] = near_plane(pts[0], pts[1], pts[2], s, rng.uniform(-2, 2));
        } else if (kind == 1) {  // exactly coplanar integers, sometimes nudged
            for (int i = 0; i < 3; ++i)
                for (double& v : pts[i]) v = static_cast<double>(rng.integer(-1000, 1000));
            pts[3] = near_plane(pts[0], pts[1], pts[2], 2.0, -3.0);
            if (iter % 2) pts[3][1] = nudge(pts[3][1], 1);
        } else {  // general position, large offset
            for (auto& p : pts) p = rng.point(1e9 - 1, 1e9 + 1);
        }
        const int base = check3(t, pts[0], pts[1], pts[2], pts[3]);
        for (const Perm4& perm : perms) {
            const P3& a = pts[perm.idx[0]];
            const P3& b = pts[perm.idx[1]];
            const P3& c = pts[perm.idx[2]];
            const P3& d = pts[perm.idx[3]];
            if (orient3d(a.data(), b.data(), c.data(), d.data()) != perm.parity * base) ++perm_mismatches;
        }
        // mirror (negate all coordinates): orient3d flips, orient2d keeps its sign
        P3 neg[4];
        for (int i = 0; i < 4; ++i) neg[i] = {-pts[i][0], -pts[i][1], -pts[i][2]};
        if (orient3d(neg[0].data(), neg[1].data(), neg[2].data(), neg[3].data()) != -base) ++perm_mismatches;
        // axis permutations: cyclic keeps the sign, a swap flips it
        P3 cyc[4], swp[4];
        for (int i = 0; i < 4; ++i) {
            cyc[i] = {pts[i][1], pts[i][2], pts[i][0]};
            swp[i] = {pts[i][1], pts[i][0], pts[i][2]};
        }
        if (orient3d(cyc[0].data(), cyc[1].data(), cyc[2].data(), cyc[3].data()) != base) ++perm_mismatches;
        if (orient3d(swp[0].data(), swp[1].data(), swp[2].data(), swp[3].data()) != -base) ++perm_mismatches;

        // orient2d on the xy projection: 6 permutations of 3 points
        const int base2 = check2(t, pts[0][0], pts[0][1], pts[1][0], pts[1][1], pts[3][0], pts[3][1]);
        int idx[3] = {0, 1, 3};
        std::sort(idx, idx + 3);
        do {
            const int inv = (idx[0] > idx[1]) + (idx[0] > idx[2]) + (idx[1] > idx[2]);
            const int parity = inv % 2 ? -1 : 1;
            if (orient2d(pts[idx[0]][0], pts[idx[0]][1], pts[idx[1]][0], pts[idx[1]][1], pts[idx[2]][0],
                         pts[idx[2]][1]) != parity * base2)
                ++perm_mismatches;
        } while (std::next_permutation(idx, idx + 3));
        if (orient2d(-pts[0][0], -pts[0][1], -pts[1][0], -pts[1][1], -pts[3][0], -pts[3][1]) != base2)
            ++perm_mismatches;
    }
    require_clean(t, 1200);
    CHECK(perm_mismatches == 0);
}

TEST_CASE("predicates: filter and exact paths agree") {
    // Wherever a stage decides, its sign must be the exact one (check3/check2 compare the traced
    // adaptive result, the public function and the exact-only expansion with the oracle). The mix
    // of inputs makes every stage decide a good number of times.
    Rng rng(0x5eed0006);
    Tally t3, t2;
    for (int iter = 0; iter < 8000; ++iter) {
        const double offset = (iter >> 2) & 1 ? 0.0 : 1e3 * rng.uniform(-1, 1);
        P3 a = rng.point(offset - 1, offset + 1), b = rng.point(offset - 1, offset + 1),
           c = rng.point(offset - 1, offset + 1);
        P3 d;
        switch (iter % 4) {
            case 0: d = rng.point(offset - 1, offset + 1); break;  // filter
            case 1: {
                const double s = rng.uniform(-1, 2);
                d = near_plane(a, b, c, s, rng.uniform(-1, 2));
                break;
            }
            case 2: {  // exact differences: coordinates on a common fine grid, exactly coplanar + nudge
                for (P3* p : {&a, &b, &c})
                    for (double& v : *p) v = std::ldexp(std::round(std::ldexp(v, 30)), -30);
                d = near_plane(a, b, c, 0.25 * static_cast<double>(rng.integer(-8, 8)), 0.5);
                if ((iter >> 3) & 1) d[2] = nudge(d[2], 1);
                break;
            }
            default: {  // exactly coplanar, inexact differences: mixed scales on z = const or
                        // on z = 2x - y/2 (exact per point, since x and y share a scale)
                const bool tilted = (iter >> 4) & 1;
                for (P3* p : {&a, &b, &c, &d}) {
                    const int e = static_cast<int>(rng.integer(-30, 30));
                    (*p)[0] = std::ldexp(std::round(std::ldexp(rng.uniform(-1, 1), 30)), e - 30);
                    (*p)[1] = std::ldexp(std::round(std::ldexp(rng.uniform(-1, 1), 30)), e - 30);
                    (*p)[2] = tilted ? 2 * (*p)[0] - 0.5 * (*p)[1] : offset;
                }
                if ((iter >> 3) & 1) d[2] = nudge(d[2], -1);
                break;
            }
        }
        check3(t3, a, b, c, d);
        check2(t2, a[0], a[1], b[0], b[1], d[0], d[1]);
        check2(t2, a[0], a[1], b[0], b[1], nudge(a[0] + 0.5 * (b[0] - a[0]), iter % 5 - 2),
               a[1] + 0.5 * (b[1] - a[1]));
        // exactly collinear on y = -2x at mixed scales (inexact differences), sometimes nudged
        const double x1 = rng.scaled_uniform(-1, 1, -30, 30);
        const double x2 = rng.scaled_uniform(-1, 1, -30, 30);
        const double x3 = rng.scaled_uniform(-1, 1, -30, 30);
        check2(t2, x1, -2 * x1, x2, -2 * x2, x3, (iter >> 1) & 1 ? nudge(-2 * x3, 1) : -2 * x3);
    }
    {
        INFO("orient3d");
        require_clean(t3, 8000);
        for (int k = 0; k < 4; ++k) CHECK(t3.stage[k] > 0);
    }
    {
        INFO("orient2d");
        require_clean(t2, 24000);
        for (int k = 0; k < 4; ++k) CHECK(t2.stage[k] > 0);
    }
}
