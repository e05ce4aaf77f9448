// hullkit: the exact in-sphere test (see predicates.hpp for the contract and the valid range), the
// predicate of degree 5 that 3D Delaunay by lifting to 4D decides everything with, and the 3D
// distance comparison its nearest-point queries use.
//
// det = alift * M(b,c,d) - blift * M(c,d,a) + clift * M(d,a,b) - dlift * M(a,b,c), rows relative
// to e (aex = ax - ex, ..., alift = aex^2 + aey^2 + aez^2) and M the 3x3 minors of the x, y, z
// columns built from the six 2x2 minors of x and y (predicates.hpp, insphere_stage_a_det). This is
// hullkit's sign: +1 inside for positively oriented a, b, c, d.
//
// Stages (as the other predicates, Shewchuk 1997):
//   A  the value in floating point against Shewchuk's bound for this determinant,
//      (16 + 224 eps) eps times the permanent (in the header, inlinable);
//   B  when the twelve differences are exact (their roundoff is 0: grids, integer and dyadic
//      coordinates, the common degenerate inputs): small integers (after a power-of-two scale,
//      below 2^9) are evaluated in plain doubles, which is then exact; otherwise stage C first
//      (its tails are zero), then the determinant of the differences as an expansion (fixed
//      arrays, exact);
//   C  otherwise the rounded differences' determinant in double-word arithmetic plus the first-order
//      term of their roundoffs, against a bound of order 400 eps^2 times the permanent (below);
//      this decides points that are cospherical up to rounding (samples of a sphere's surface);
//   D  when C cannot decide, the full exact expansion from the exact differences (each of two
//      components), compressed after every product (heap arrays: this path is rare).
//
// Valid range (kInsphereMinMagnitude = 2^-120 .. kInsphereMaxMagnitude = 2^+195), by the argument of
// predicates.hpp for a polynomial of degree 5:
//  * Overflow: differences are below 2^196, products of five below 2^980; the permanent (72 such
//    products at most, each a lift of 3 squares times a minor of 6 products) and every partial sum of
//    the exact expansions stay below 2^990. Veltkamp splitting multiplies components of degree at
//    most 4 (below 2^790) by 2^27 + 1: nothing reaches 2^1024.
//  * Underflow: a nonzero |x| >= 2^-120 is a multiple of q = 2^-172, so every value any stage
//    computes is a multiple of q^5 = 2^-860; the smallest error bound, about 2^-49 times a nonzero
//    permanent, stays normal (>= 2^-1022), so all error-free transformations are exact and the
//    relative bounds hold.
#include "hullkit/predicates.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "expansion.hpp"

namespace hullkit {

using namespace exact_detail;

namespace {

/// 2^(9 - e) for the e with 2^(e-1) <= x < 2^e (x > 0 normal), so that x times it is below 2^9;
/// NaN when x is 0 or subnormal or the power is not a normal double (the caller's test then fails).
inline double power_of_two_below_512_over(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);  // x in [2^(biased-1023), 2^(biased-1022))
    const int result = 2054 - biased;                            // biased exponent of 2^(1031 - biased)
    if (biased == 0 || result < 1 || result > 2046) return std::numeric_limits<double>::quiet_NaN();
    const std::uint64_t out = static_cast<std::uint64_t>(result) << 52;
    double scale;
    std::memcpy(&scale, &out, sizeof scale);
    return scale;
}

/// Exact u * v - w * z of four doubles, as an expansion of at most 4 components.
inline int product_diff(double u, double v, double w, double z, double* h) {
    double hi1, lo1, hi2, lo2;
    two_product(u, v, hi1, lo1);
    two_product(w, z, hi2, lo2);
    return two_two_diff(hi1, lo1, hi2, lo2, h);
}

/// h = p * z1 + q * z2 + r * z3 for expansions p, q, r of at most 4 components (a 3x3 minor from
/// 2x2 minors); h has room for 24 components.
int minor3(int plen, const double* p, double z1, int qlen, const double* q, double z2, int rlen, const double* r,
           double z3, double* h) {
    double t1[8], t2[8], t3[8], t12[16];
    const int l1 = scale_expansion(plen, p, z1, t1);
    const int l2 = scale_expansion(qlen, q, z2, t2);
    const int l3 = scale_expansion(rlen, r, z3, t3);
    const int l12 = expansion_sum(l1, t1, l2, t2, t12);
    return expansion_sum(l12, t12, l3, t3, h);
}

/// h = minor * (x^2 + y^2 + z^2) * sign exactly, for a minor of at most 24 components (h: at most
/// 288), by repeated scaling.
int lift_times(int mlen, const double* minor, double x, double y, double z, double sign, double* h) {
    double m1[48], mx[96], my[96], mz[96], mxy[192];
    auto square_scaled = [&](double v, double* out) {
        const int l1 = scale_expansion(mlen, minor, v * sign, m1);
        return scale_expansion(l1, m1, v, out);
    };
    const int lx = square_scaled(x, mx);
    const int ly = square_scaled(y, my);
    const int lz = square_scaled(z, mz);
    const int lxy = expansion_sum(lx, mx, ly, my, mxy);
    return expansion_sum(lxy, mxy, lz, mz, h);
}

/// Shewchuk's Compress in place: the same value in (nearly) as few components as its bits allow,
/// increasing in magnitude, no zeros; returns the new length.
int compress_in_place(int m, double* e) {
    if (m == 0) return 0;
    double big = e[m - 1];
    int bottom = m - 1;
    for (int i = m - 2; i >= 0; --i) {
        double sum, small;
        fast_two_sum(big, e[i], sum, small);
        if (small != 0.0) {
            e[bottom--] = sum;
            big = small;
        } else {
            big = sum;
        }
    }
    e[bottom] = big;
    int top = 0;
    double carry = e[bottom];
    for (int i = bottom + 1; i < m; ++i) {
        double sum, small;
        fast_two_sum(e[i], carry, sum, small);
        if (small != 0.0) e[top++] = small;
        carry = sum;
    }
    if (carry != 0.0) e[top++] = carry;
    return top;
}

/// The determinant of twelve differences d (aex, aey, aez, bex, ..., dez), exactly, as an expansion
/// into det (room for 1152 components); returns its length. The 3x3 minors and the four terms are
/// compressed as they are made (a general double's terms fit in a few components; without it the
/// sums would run over hundreds).
int insphere_differences_expansion(const double* d, double* det) {
    const double aex = d[0], aey = d[1], aez = d[2], bex = d[3], bey = d[4], bez = d[5];
    const double cex = d[6], cey = d[7], cez = d[8], dex = d[9], dey = d[10], dez = d[11];
    double ab[4], bc[4], cd[4], da[4], ac[4], bd[4], ca[4], db[4];
    const int lab = product_diff(aex, bey, bex, aey, ab), lbc = product_diff(bex, cey, cex, bey, bc);
    const int lcd = product_diff(cex, dey, dex, cey, cd), lda = product_diff(dex, aey, aex, dey, da);
    const int lac = product_diff(aex, cey, cex, aey, ac), lbd = product_diff(bex, dey, dex, bey, bd);
    for (int i = 0; i < lac; ++i) ca[i] = -ac[i];
    for (int i = 0; i < lbd; ++i) db[i] = -bd[i];
    double abc[24], bcd[24], cda[24], dab[24];
    const int labc = compress_in_place(minor3(lbc, bc, aez, lac, ca, bez, lab, ab, cez, abc), abc);  // aez bc - bez ac + cez ab
    const int lbcd = compress_in_place(minor3(lcd, cd, bez, lbd, db, cez, lbc, bc, dez, bcd), bcd);  // bez cd - cez bd + dez bc
    const int lcda = compress_in_place(minor3(lda, da, cez, lac, ac, dez, lcd, cd, aez, cda), cda);  // cez da + dez ac + aez cd
    const int ldab = compress_in_place(minor3(lab, ab, dez, lbd, bd, aez, lda, da, bez, dab), dab);  // dez ab + aez bd + bez da
    double ta[288], tb[288], tc[288], td[288];
    const int la = compress_in_place(lift_times(lbcd, bcd, aex, aey, aez, 1.0, ta), ta);
    const int lb = compress_in_place(lift_times(lcda, cda, bex, bey, bez, -1.0, tb), tb);
    const int lc = compress_in_place(lift_times(ldab, dab, cex, cey, cez, 1.0, tc), tc);
    const int ld = compress_in_place(lift_times(labc, abc, dex, dey, dez, -1.0, td), td);
    double s1[576], s2[576];
    const int l1 = expansion_sum(la, ta, lb, tb, s1);
    const int l2 = expansion_sum(lc, tc, ld, td, s2);
    return expansion_sum(l1, s1, l2, s2, det);
}

/// Stage B on exact differences d: the exact sign.
int insphere_exact_differences(const double* d) {
    double det[1152];
    return expansion_sign(insphere_differences_expansion(d, det), det);
}

// ---- Stage C: the rounded differences' determinant in double-word arithmetic, plus the first-order ----
// ---- term of their roundoffs ----
//
// With d the rounded differences and t their roundoffs (d + t exact, |t| <= eps |d|), every term of
// the determinant is a product of five entries, so
//     det(d + t) = det(d) + F + R,   F = sum over the twelve entries of t_i * (d det / d d_i)(d),
// and R (the terms with two or more tails) is at most ((1 + eps)^5 - 1 - 5 eps) P <= 10.01 eps^2 P,
// P the permanent (the terms in absolute value; stage A's computed permanent is within a factor
// 1 + 12 eps of it).
//  * det(d) is evaluated by the same formula in double-word arithmetic (a value hi + lo): sums by
//    Joldes, Muller & Popescu's AccurateDWPlusDW (relative error below 3 eps^2 / (1 - 4 eps)),
//    products by their DWTimesDW1 (below 7 eps^2); taken here as at most eta = 16 eps^2 per
//    operation. Every product of five entries passes through at most 11 operations (2 for a 2x2
//    minor, 3 more for a 3x3 minor, 3 for a lift, 1 for their product, 2 for the final sums), so
//    the error is at most ((1 + eta)^11 - 1) P < 200 eps^2 P.
//  * F is computed in doubles by carrying each value's derivative along t through the formula
//    (dual numbers): a straight-line program of at most 30 roundings on any product of inputs, so
//    its error is at most gamma_30 < 31 eps times the same program run on |d|, |t| with every
//    subtraction an addition (Fabs, computed with all terms positive: rounded down by at most a
//    factor 1 - gamma_30). Fabs <= 5 eps P.
//  * hi + (lo + F) rounds twice: at most 2 eps (|value| + |lo| + |F|).
// The bound is of order 400 eps^2 P, while points that are cospherical up to the rounding of their
// coordinates (samples of a sphere's surface) give determinants of a few eps times P, which stages
// A and B cannot decide and stage D decides a hundred times more slowly.

/// A double-word number hi + lo (|lo| at most half an ulp of hi).
struct Word {
    double hi, lo;
};
inline Word operator+(Word x, Word y) {  // AccurateDWPlusDW
    double sh, sl, th, tl, vh, vl, zh, zl;
    two_sum(x.hi, y.hi, sh, sl);
    two_sum(x.lo, y.lo, th, tl);
    const double c = sl + th;
    fast_two_sum(sh, c, vh, vl);
    const double w = tl + vl;
    fast_two_sum(vh, w, zh, zl);
    return {zh, zl};
}
inline Word operator-(Word x, Word y) { return x + Word{-y.hi, -y.lo}; }
inline Word operator*(Word x, Word y) {  // DWTimesDW1
    double ch, cl1, zh, zl;
    two_product(x.hi, y.hi, ch, cl1);
    const double cl2 = x.hi * y.lo + x.lo * y.hi;
    const double cl3 = cl1 + cl2;
    fast_two_sum(ch, cl3, zh, zl);
    return {zh, zl};
}

struct Dual {
    double v, t;  ///< a value and its derivative along the tails
};
inline Dual operator*(Dual a, Dual b) { return {a.v * b.v, a.t * b.v + a.v * b.t}; }
inline Dual operator+(Dual a, Dual b) { return {a.v + b.v, a.t + b.t}; }
inline Dual operator-(Dual a, Dual b) { return {a.v - b.v, a.t - b.t}; }

/// Stage C: the sign of det(d + t) when the bound above decides it, else 0 (undecided).
int insphere_stage_c(const double* d, const double* t, double permanent) {
    Word w[12];
    Dual x[12], magnitude[12];
    for (int i = 0; i < 12; ++i) {
        w[i] = {d[i], 0.0};
        x[i] = {d[i], t[i]};
        magnitude[i] = {std::fabs(d[i]), std::fabs(t[i])};
    }
    const Word base = detail::insphere_formula(w);
    const double first = detail::insphere_formula(x).t;
    const double bound = detail::insphere_formula<Dual, true>(magnitude).t;
    const double value = base.hi + (base.lo + first);
    const double errbound = 2.0 * kEpsilon * (std::fabs(value) + std::fabs(base.lo) + std::fabs(first)) +
                            211.0 * kEpsilon * kEpsilon * permanent + 31.0 * kEpsilon * bound;
    if (value > errbound) return 1;
    if (-value > errbound) return -1;
    return 0;
}

// ---- Stage D: general expansions on the heap, compressed after each product ----

using Expansion = std::vector<double>;

/// compress_in_place on a heap expansion.
Expansion compress(Expansion e) {
    e.resize(static_cast<std::size_t>(compress_in_place(static_cast<int>(e.size()), e.data())));
    return e;
}

Expansion add(const Expansion& e, const Expansion& f) {
    Expansion h(e.size() + f.size());
    h.resize(expansion_sum(static_cast<int>(e.size()), e.data(), static_cast<int>(f.size()), f.data(), h.data()));
    return h;
}

Expansion negate(Expansion e) {
    for (double& x : e) x = -x;
    return e;
}

Expansion multiply(const Expansion& e, const Expansion& f) {
    Expansion h, part;
    for (double component : f) {
        part.resize(2 * e.size());
        part.resize(scale_expansion(static_cast<int>(e.size()), e.data(), component, part.data()));
        h = add(h, part);
    }
    return compress(h);
}

Expansion difference(double a, double b) {
    double h[2];
    const int len = exact_diff(a, b, h);
    return Expansion(h, h + len);
}

/// Stage D: the exact sign from the exact differences of the coordinates.
int insphere_exact_sign(const double* a, const double* b, const double* c, const double* d, const double* e) {
    const double* rows[4] = {a, b, c, d};
    Expansion x[4], y[4], z[4];
    for (int i = 0; i < 4; ++i) {
        x[i] = difference(rows[i][0], e[0]);
        y[i] = difference(rows[i][1], e[1]);
        z[i] = difference(rows[i][2], e[2]);
    }
    auto minor2 = [&](int i, int j) {  // x_i y_j - x_j y_i
        double h[16];
        const int len = exact_minor(static_cast<int>(x[i].size()), x[i].data(), static_cast<int>(y[j].size()),
                                    y[j].data(), static_cast<int>(x[j].size()), x[j].data(),
                                    static_cast<int>(y[i].size()), y[i].data(), h);
        return Expansion(h, h + len);
    };
    // 3x3 minor of rows i, j, k of (x, y, z): z_i m(j,k) - z_j m(i,k) + z_k m(i,j).
    auto minor3_of = [&](int i, int j, int k) {
        return add(add(multiply(z[i], minor2(j, k)), negate(multiply(z[j], minor2(i, k)))), multiply(z[k], minor2(i, j)));
    };
    auto lift = [&](int i) { return add(add(multiply(x[i], x[i]), multiply(y[i], y[i])), multiply(z[i], z[i])); };
    // Expanding det[rows - e, lift] by its lift column: the hullkit sign is
    // alift M(b,c,d) - blift M(a,c,d) + clift M(a,b,d) - dlift M(a,b,c) (minors of the rows in order).
    const Expansion ta = multiply(lift(0), minor3_of(1, 2, 3));
    const Expansion tb = multiply(lift(1), minor3_of(0, 2, 3));
    const Expansion tc = multiply(lift(2), minor3_of(0, 1, 3));
    const Expansion td = multiply(lift(3), minor3_of(0, 1, 2));
    const Expansion det = add(add(ta, negate(tb)), add(tc, negate(td)));
    return expansion_sign(static_cast<int>(det.size()), det.data());
}

int insphere_adapt(const double* a, const double* b, const double* c, const double* d, const double* e,
                   double permanent, int* stage) {
    if (permanent == 0.0) {
        // Every term has a factor that is exactly zero (in range no nonzero product rounds to 0).
        return 0;
    }
    const double* rows[4] = {a, b, c, d};
    double diff[12], tails[12];
    bool exact_differences = true;
    for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 3; ++k) {
            diff[3 * i + k] = rows[i][k] - e[k];
            tails[3 * i + k] = diff_roundoff(rows[i][k], e[k], diff[3 * i + k]);
            if (tails[3 * i + k] != 0.0) exact_differences = false;
        }
    }
    if (exact_differences) {
        double largest = 0.0;
        for (double v : diff) largest = std::max(largest, std::fabs(v));
        const double scale = power_of_two_below_512_over(largest);
        double scaled[12];
        bool integers = true;
        for (int i = 0; i < 12; ++i) {
            scaled[i] = diff[i] * scale;
            integers = integers && scaled[i] == std::trunc(scaled[i]);
        }
        // In plain doubles the formula is exact for integers below 2^9 in magnitude (every product and
        // sum is then an integer below 2^53: lifts below 3 * 2^18, minors below 6 * 2^27, terms below
        // 18 * 2^45, the sum below 72 * 2^45).
        if (integers) {
            if (stage) *stage = 1;
            return sign_of(detail::insphere_formula(scaled));
        }
    }
    // Stage C (with zero tails when the differences are exact: then its error is the double-word
    // evaluation's alone), before any expansion: near-cospherical floating-point points (a sphere's
    // samples) mostly have exact differences and would otherwise all take the expansions.
    if (stage) *stage = 2;
    if (const int sign = insphere_stage_c(diff, tails, permanent); sign != 0) return sign;
    if (exact_differences) {
        if (stage) *stage = 1;
        return insphere_exact_differences(diff);
    }
    if (stage) *stage = 3;
    return insphere_exact_sign(a, b, c, d, e);
}

inline int insphere_impl(const double* a, const double* b, const double* c, const double* d, const double* e,
                         int* stage) {
    const detail::InsphereStageA s = detail::insphere_stage_a(a, b, c, d, e);
    if (stage) *stage = 0;
    const double errbound = detail::kInsphereFilterBound * s.permanent;
    if (s.det > errbound) return 1;
    if (-s.det > errbound) return -1;
    return insphere_adapt(a, b, c, d, e, s.permanent, stage);
}

/// Stage D of compare_distance3d: |a-q|^2 - |b-q|^2 from the exact differences.
int compare_distance3d_exact(const double* a, const double* b, const double* q) {
    Expansion sum;
    for (int k = 0; k < 3; ++k) {
        const Expansion da = difference(a[k], q[k]), db = difference(b[k], q[k]);
        sum = add(add(sum, multiply(da, da)), negate(multiply(db, db)));
    }
    return expansion_sign(static_cast<int>(sum.size()), sum.data());
}

}  // namespace

int compare_distance3d(const double* a, const double* b, const double* q) {
    // Forward error of the sum of three squares minus three squares: each square carries its
    // difference's rounding twice and its own (3 eps), the five additions one each: below
    // 8 eps (plus higher order) times the sum of the six squares.
    double a2 = 0.0, b2 = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double da = a[k] - q[k], db = b[k] - q[k];
        a2 += da * da;
        b2 += db * db;
    }
    const double det = a2 - b2;
    if (std::fabs(det) > (9.0 + 64.0 * kEpsilon) * kEpsilon * (a2 + b2)) return sign_of(det);
    return compare_distance3d_exact(a, b, q);
}

int insphere(const double* a, const double* b, const double* c, const double* d, const double* e) {
    return insphere_impl(a, b, c, d, e, nullptr);
}

namespace detail {

int insphere_traced(const double* a, const double* b, const double* c, const double* d, const double* e,
                    int* stage) {
    int ignored = 0;
    return insphere_impl(a, b, c, d, e, stage ? stage : &ignored);
}

int insphere_exact(const double* a, const double* b, const double* c, const double* d, const double* e) {
    return insphere_exact_sign(a, b, c, d, e);
}

}  // namespace detail
}  // namespace hullkit
