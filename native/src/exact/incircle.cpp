// hullkit: the exact in-circle test and compare_distance (see predicates.hpp for the contract and
// the valid range), the predicates of degree 4, built on the expansion arithmetic of expansion.hpp.
// orient2d and orient3d are in predicates.cpp.
#include "hullkit/predicates.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "expansion.hpp"

namespace hullkit {

using namespace exact_detail;

namespace {

// ---------------------------------------------------------------------------------------------
// incircle
//
// det = alift * M(b,c) + blift * M(c,a) + clift * M(a,b), with rows relative to d:
//   adx = ax - dx, ..., alift = adx^2 + ady^2, M(u,v) = udx * vdy - vdx * udy.
//
// Valid range (kIncircleMinMagnitude = 2^-170 .. kIncircleMaxMagnitude = 2^+240), by the argument
// used for orient3d in predicates.hpp, for a polynomial of degree 4:
//  * Overflow: differences are below 2^241, products of four of them below 2^964, the permanent and
//    every partial sum of the exact expansions below 2^969; Veltkamp splitting multiplies by
//    2^27 + 1 < 2^28 only components of degree at most 2 (differences, lifts, minors: below
//    2^484): nothing reaches 2^1024. (Components of degree-4 products are never split.)
//  * Underflow: a nonzero |x| >= 2^-170 is a multiple of q = 2^-222, so every value any stage
//    computes is a multiple of q^4 = 2^-888; the smallest error bound, about 2^-100 times a nonzero
//    permanent (>= 2^-888), stays normal (>= 2^-1022), so all error-free transformations are exact
//    and the relative bounds hold.

// Error bounds of the three filtering stages (Shewchuk 1997, section 6, for the in-circle
// determinant): stage A accumulates up to 10 roundings per term.
constexpr double kIncircleBoundA = (10.0 + 96.0 * kEpsilon) * kEpsilon;
constexpr double kIncircleBoundB = (4.0 + 48.0 * kEpsilon) * kEpsilon;
constexpr double kIncircleBoundC = (44.0 + 576.0 * kEpsilon) * kEpsilon * kEpsilon;

/// h = e * f for expansions of any length: the sum over f's components of e scaled by each.
/// `h` has room for 2 * elen * flen components; `scratch` for 2 * elen * flen as well, `part` for
/// 2 * elen. Returns the length of h.
int multiply_expansions(int elen, const double* e, int flen, const double* f, double* h,
                        double* scratch, double* part) {
    int hlen = 0;
    for (int j = 0; j < flen; ++j) {
        const int plen = scale_expansion(elen, e, f[j], part);
        const int slen = expansion_sum(hlen, h, plen, part, scratch);
        for (int i = 0; i < slen; ++i) h[i] = scratch[i];
        hlen = slen;
    }
    return hlen;
}

/// Exact p^2 + q^2 for expansions of at most two components each (at most 16 components).
int exact_square_sum(int plen, const double* p, int qlen, const double* q, double* h) {
    double pp[8], qq[8];
    const int pp_len = multiply_short(plen, p, plen, p, pp);
    const int qq_len = multiply_short(qlen, q, qlen, q, qq);
    return expansion_sum(pp_len, pp, qq_len, qq, h);
}

/// Stage D: exact sign of the in-circle determinant from the exact differences.
int incircle_exact_sign(double ax, double ay, double bx, double by, double cx, double cy,
                        double dx, double dy) {
    double adx[2], ady[2], bdx[2], bdy[2], cdx[2], cdy[2];
    const int adx_len = exact_diff(ax, dx, adx), ady_len = exact_diff(ay, dy, ady);
    const int bdx_len = exact_diff(bx, dx, bdx), bdy_len = exact_diff(by, dy, bdy);
    const int cdx_len = exact_diff(cx, dx, cdx), cdy_len = exact_diff(cy, dy, cdy);

    double alift[16], blift[16], clift[16];
    const int al = exact_square_sum(adx_len, adx, ady_len, ady, alift);
    const int bl = exact_square_sum(bdx_len, bdx, bdy_len, bdy, blift);
    const int cl = exact_square_sum(cdx_len, cdx, cdy_len, cdy, clift);
    double m_bc[16], m_ca[16], m_ab[16];
    const int bc = exact_minor(bdx_len, bdx, cdy_len, cdy, cdx_len, cdx, bdy_len, bdy, m_bc);
    const int ca = exact_minor(cdx_len, cdx, ady_len, ady, adx_len, adx, cdy_len, cdy, m_ca);
    const int ab = exact_minor(adx_len, adx, bdy_len, bdy, bdx_len, bdx, ady_len, ady, m_ab);

    double scratch[512], part[32];
    double ta[512], tb[512], tc[512];
    const int ta_len = multiply_expansions(al, alift, bc, m_bc, ta, scratch, part);
    const int tb_len = multiply_expansions(bl, blift, ca, m_ca, tb, scratch, part);
    const int tc_len = multiply_expansions(cl, clift, ab, m_ab, tc, scratch, part);
    double ab_sum[1024];
    const int ab_sum_len = expansion_sum(ta_len, ta, tb_len, tb, ab_sum);
    double det[1536];
    const int det_len = expansion_sum(ab_sum_len, ab_sum, tc_len, tc, det);
    return expansion_sign(det_len, det);
}

/// Exact u * v - w * z of four doubles, as an expansion of at most 4 components.
inline int product_diff(double u, double v, double w, double z, double* h) {
    double hi1, lo1, hi2, lo2;
    two_product(u, v, hi1, lo1);
    two_product(w, z, hi2, lo2);
    return two_two_diff(hi1, lo1, hi2, lo2, h);
}

// ---- Double-double numbers for a cheap look at stage B ----
// A value hi + lo with |lo| <= ulp(hi) / 2. The operations are the "accurate" algorithms analysed
// by Joldes, Muller and Popescu (ACM TOMS 44(2), 2017): the sum has relative error below 3 eps^2
// (their Algorithm 6) and the product below 7 eps^2 (Algorithm 10, no FMA needed); below they are
// counted as 4 eps^2 and 8 eps^2.
struct DoubleDouble {
    double hi, lo;
};

inline DoubleDouble dd_product(double a, double b) {
    DoubleDouble r;
    two_product(a, b, r.hi, r.lo);
    return r;
}

inline DoubleDouble dd_sum(DoubleDouble a, DoubleDouble b) {
    double s_hi, s_lo, t_hi, t_lo;
    two_sum(a.hi, b.hi, s_hi, s_lo);
    two_sum(a.lo, b.lo, t_hi, t_lo);
    double v_hi, v_lo;
    fast_two_sum(s_hi, s_lo + t_hi, v_hi, v_lo);
    DoubleDouble r;
    fast_two_sum(v_hi, t_lo + v_lo, r.hi, r.lo);
    return r;
}

inline DoubleDouble dd_negate(DoubleDouble a) { return {-a.hi, -a.lo}; }

inline DoubleDouble dd_times(DoubleDouble a, DoubleDouble b) {
    double c_hi, c_lo;
    two_product(a.hi, b.hi, c_hi, c_lo);
    const double cross = a.hi * b.lo + a.lo * b.hi;
    DoubleDouble r;
    fast_two_sum(c_hi, c_lo + cross, r.hi, r.lo);
    return r;
}

/// The in-circle determinant of the rounded differences (stage B's value) in double-double.
/// Error bound, with L = x^2 + y^2 of a row and P = |minor products| of that row (the row's
/// share of the permanent is L * P): the lift is a sum of two exact products (error <= 4 eps^2 L),
/// the minor a difference of two (<= 4 eps^2 P); their product errs by <= 8 eps^2 L P from the
/// rounded factors plus 8 eps^2 L P from its own rounding (+ O(eps^4)); the two sums add
/// 4 eps^2 of the permanent each. In all at most 24 eps^2 (1 + O(eps)) times the permanent.
double incircle_double_double(double adx, double ady, double bdx, double bdy, double cdx, double cdy) {
    auto row = [](double x, double y, double p, double q, double r, double t) {
        const DoubleDouble lift = dd_sum(dd_product(x, x), dd_product(y, y));
        const DoubleDouble minor = dd_sum(dd_product(p, q), dd_negate(dd_product(r, t)));
        return dd_times(lift, minor);
    };
    const DoubleDouble a = row(adx, ady, bdx, cdy, cdx, bdy);
    const DoubleDouble b = row(bdx, bdy, cdx, ady, adx, cdy);
    const DoubleDouble c = row(cdx, cdy, adx, bdy, bdx, ady);
    const DoubleDouble sum = dd_sum(dd_sum(a, b), c);
    return sum.hi;
}

/// Stage B's bound plus room for incircle_double_double: its 24 eps^2 of the permanent, the
/// neglected lo part (|lo| <= eps |hi|, about 4 eps^2 of the permanent near the bound), and the
/// rounding of the bound times the computed permanent (a few eps^2 more), with room to spare.
constexpr double kIncircleBoundBdd = kIncircleBoundB + 128.0 * kEpsilon * kEpsilon;
/// When the differences are exact, stage B's value is the determinant: then incircle_double_double
/// decides whenever it is clear of its own error (24 eps^2 of the permanent), with room to spare.
constexpr double kIncircleExactDifferencesDd = 64.0 * kEpsilon * kEpsilon;

/// 2^(12 - e) for the e with 2^(e-1) <= x < 2^e (x > 0 normal), so that x times it is below 2^12;
/// NaN when x is 0 or subnormal or the power is not a normal double (the caller's test then fails).
inline double power_of_two_below_4096_over(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);  // x in [2^(biased-1023), 2^(biased-1022))
    const int result = 2057 - biased;                            // biased exponent of 2^(1034 - biased)
    if (biased == 0 || result < 1 || result > 2046) return std::numeric_limits<double>::quiet_NaN();
    const std::uint64_t out = static_cast<std::uint64_t>(result) << 52;
    double scale;
    std::memcpy(&scale, &out, sizeof scale);
    return scale;
}

/// h = minor * (x^2 + y^2) exactly, for a minor of at most 4 components (h: at most 32).
int lift_times_minor(int mlen, const double* minor, double x, double y, double* h) {
    double mx[8], mxx[16], my[8], myy[16];
    const int mx_len = scale_expansion(mlen, minor, x, mx);
    const int mxx_len = scale_expansion(mx_len, mx, x, mxx);
    const int my_len = scale_expansion(mlen, minor, y, my);
    const int myy_len = scale_expansion(my_len, my, y, myy);
    return expansion_sum(mxx_len, mxx, myy_len, myy, h);
}

/// Stages B-D of incircle, entered when the filter could not decide.
int incircle_adapt(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                   double dy, double permanent, int* stage) {
    if (permanent == 0.0) {
        // Every term has a zero factor (in range no nonzero product rounds to zero): a lift of 0
        // means a point equals d, a zero minor product a zero difference. The determinant is 0.
        return 0;
    }
    const double adx = ax - dx, ady = ay - dy;
    const double bdx = bx - dx, bdy = by - dy;
    const double cdx = cx - dx, cdy = cy - dy;

    const double adx_t = diff_roundoff(ax, dx, adx), ady_t = diff_roundoff(ay, dy, ady);
    const double bdx_t = diff_roundoff(bx, dx, bdx), bdy_t = diff_roundoff(by, dy, bdy);
    const double cdx_t = diff_roundoff(cx, dx, cdx), cdy_t = diff_roundoff(cy, dy, cdy);
    const bool exact_differences = adx_t == 0.0 && ady_t == 0.0 && bdx_t == 0.0 && bdy_t == 0.0 &&
                                   cdx_t == 0.0 && cdy_t == 0.0;
    if (exact_differences) {
        // Differences that are small multiples of one power of two (grids, integer points): scaled
        // to integers below 2^12, every product and sum of the plain formula is an integer below
        // 2^53, so the double result is exact, zero included.
        const double largest = std::max({std::fabs(adx), std::fabs(ady), std::fabs(bdx), std::fabs(bdy),
                                         std::fabs(cdx), std::fabs(cdy)});
        const double scale = power_of_two_below_4096_over(largest);
        const double d[6] = {adx * scale, ady * scale, bdx * scale, bdy * scale, cdx * scale, cdy * scale};
        if (d[0] == std::trunc(d[0]) && d[1] == std::trunc(d[1]) && d[2] == std::trunc(d[2]) &&
            d[3] == std::trunc(d[3]) && d[4] == std::trunc(d[4]) && d[5] == std::trunc(d[5])) {
            if (stage) *stage = 1;
            return sign_of((d[0] * d[0] + d[1] * d[1]) * (d[2] * d[5] - d[4] * d[3]) +
                           (d[2] * d[2] + d[3] * d[3]) * (d[4] * d[1] - d[0] * d[5]) +
                           (d[4] * d[4] + d[5] * d[5]) * (d[0] * d[3] - d[2] * d[1]));
        }
    }

    // Stage B, first in double-double: when that value is clear of stage B's bound by more than
    // its own error, the exact value (below) is clear of the bound too and has its sign.
    const double det_dd = incircle_double_double(adx, ady, bdx, bdy, cdx, cdy);
    if (std::fabs(det_dd) > kIncircleBoundBdd * permanent) {
        if (stage) *stage = 1;
        return sign_of(det_dd);
    }
    if (exact_differences && std::fabs(det_dd) > kIncircleExactDifferencesDd * permanent) {
        // The differences were exact, so det_dd is within 24 eps^2 of the permanent of the
        // determinant itself.
        if (stage) *stage = 1;
        return sign_of(det_dd);
    }

    // Stage B: the exact determinant of the rounded differences, each row's term as
    // minor * dx * dx + minor * dy * dy by repeated scaling (fewer and shorter merges than
    // multiplying the lift and the minor as expansions).
    double m_bc[4], m_ca[4], m_ab[4];
    const int bc = product_diff(bdx, cdy, cdx, bdy, m_bc);
    const int ca = product_diff(cdx, ady, adx, cdy, m_ca);
    const int ab = product_diff(adx, bdy, bdx, ady, m_ab);
    double ta[32], tb[32], tc[32];
    const int ta_len = lift_times_minor(bc, m_bc, adx, ady, ta);
    const int tb_len = lift_times_minor(ca, m_ca, bdx, bdy, tb);
    const int tc_len = lift_times_minor(ab, m_ab, cdx, cdy, tc);
    double ab_sum[64];
    const int ab_sum_len = expansion_sum(ta_len, ta, tb_len, tb, ab_sum);
    double b_exp[96];
    const int b_len = expansion_sum(ab_sum_len, ab_sum, tc_len, tc, b_exp);
    if (exact_differences) {
        // The differences were exact, so the stage B expansion is the determinant itself.
        if (stage) *stage = 1;
        return expansion_sign(b_len, b_exp);
    }

    double det = estimate(b_len, b_exp);
    double errbound = kIncircleBoundB * permanent;
    if (std::fabs(det) > errbound) {
        if (stage) *stage = 1;
        return sign_of(det);
    }

    // Stage C: the terms linear in the tails (d/dt of lift * minor), in floating point.
    errbound = kIncircleBoundC * permanent + kResultErrBound * std::fabs(det);
    det += ((adx * adx + ady * ady) * ((bdx * cdy_t + cdy * bdx_t) - (bdy * cdx_t + cdx * bdy_t)) +
            2.0 * (adx * adx_t + ady * ady_t) * (bdx * cdy - bdy * cdx)) +
           ((bdx * bdx + bdy * bdy) * ((cdx * ady_t + ady * cdx_t) - (cdy * adx_t + adx * cdy_t)) +
            2.0 * (bdx * bdx_t + bdy * bdy_t) * (cdx * ady - cdy * adx)) +
           ((cdx * cdx + cdy * cdy) * ((adx * bdy_t + bdy * adx_t) - (ady * bdx_t + bdx * ady_t)) +
            2.0 * (cdx * cdx_t + cdy * cdy_t) * (adx * bdy - ady * bdx));
    if (std::fabs(det) > errbound) {
        if (stage) *stage = 2;
        return sign_of(det);
    }

    // Stage D: exact.
    if (stage) *stage = 3;
    return incircle_exact_sign(ax, ay, bx, by, cx, cy, dx, dy);
}

/// Stage A (detail::incircle_stage_a, shared with the header's inline test); falls through to
/// incircle_adapt.
inline int incircle_impl(double ax, double ay, double bx, double by, double cx, double cy,
                         double dx, double dy, int* stage) {
    const detail::IncircleStageA a = detail::incircle_stage_a(ax, ay, bx, by, cx, cy, dx, dy);
    const double det = a.det, permanent = a.permanent;
    const double errbound = kIncircleBoundA * permanent;
    if (stage) *stage = 0;
    if (std::fabs(det) > errbound) return sign_of(det);
    return incircle_adapt(ax, ay, bx, by, cx, cy, dx, dy, permanent, stage);
}

/// Stage D of compare_distance: |a-q|^2 - |b-q|^2 from the exact differences.
int compare_distance_exact(double ax, double ay, double bx, double by, double qx, double qy) {
    double aqx[2], aqy[2], bqx[2], bqy[2];
    const int aqx_len = exact_diff(ax, qx, aqx), aqy_len = exact_diff(ay, qy, aqy);
    const int bqx_len = exact_diff(bx, qx, bqx), bqy_len = exact_diff(by, qy, bqy);
    double a2[16], b2[16];
    const int a2_len = exact_square_sum(aqx_len, aqx, aqy_len, aqy, a2);
    const int b2_len = exact_square_sum(bqx_len, bqx, bqy_len, bqy, b2);
    for (int i = 0; i < b2_len; ++i) b2[i] = -b2[i];
    double diff[32];
    return expansion_sign(expansion_sum(a2_len, a2, b2_len, b2, diff), diff);
}

// Forward error of (aqx^2 + aqy^2) - (bqx^2 + bqy^2) in floating point: each square carries the
// rounding of its difference twice and its own (3 eps), each sum one more, the difference one
// more: at most 5 eps (plus higher order) times the sum of the four squares.
constexpr double kDistanceBound = (6.0 + 64.0 * kEpsilon) * kEpsilon;

}  // namespace

int incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
             double dy) {
    return incircle_impl(ax, ay, bx, by, cx, cy, dx, dy, nullptr);
}

namespace detail {

static_assert(kIncircleFilterBound == kIncircleBoundA, "the header's stage A bound must match");

int incircle_adapt_entry(double ax, double ay, double bx, double by, double cx, double cy,
                         double dx, double dy, double permanent) {
    return incircle_adapt(ax, ay, bx, by, cx, cy, dx, dy, permanent, nullptr);
}

}  // namespace detail

int compare_distance(double ax, double ay, double bx, double by, double qx, double qy) {
    const double aqx = ax - qx, aqy = ay - qy, bqx = bx - qx, bqy = by - qy;
    const double a2 = aqx * aqx + aqy * aqy;
    const double b2 = bqx * bqx + bqy * bqy;
    const double det = a2 - b2;
    if (std::fabs(det) > kDistanceBound * (a2 + b2)) return sign_of(det);
    return compare_distance_exact(ax, ay, bx, by, qx, qy);
}

namespace detail {

int incircle_traced(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                    double dy, int* stage) {
    int ignored = 0;
    return incircle_impl(ax, ay, bx, by, cx, cy, dx, dy, stage ? stage : &ignored);
}

int incircle_exact(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                   double dy) {
    return incircle_exact_sign(ax, ay, bx, by, cx, cy, dx, dy);
}

}  // namespace detail
}  // namespace hullkit
