// hullkit: exact geometric predicates. See predicates.hpp for the contract and the valid range.
//
// Terminology (Shewchuk 1997): an *expansion* is a sum of doubles e[0] + e[1] + ... + e[n-1], stored
// in order of increasing magnitude, whose components do not overlap (the lowest set bit of each is
// above the highest set bit of the previous one). Its value is exact, its sign is the sign of its
// largest component. Here expansions are kept free of zero components; length 0 means the value 0.
#include "hullkit/predicates.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#if defined(__FAST_MATH__)
#error "hullkit predicates need strict IEEE-754 arithmetic: do not build them with -ffast-math"
#endif
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD != 0
#error "hullkit predicates need double arithmetic without excess precision (FLT_EVAL_METHOD == 0)"
#endif
#if defined(__clang__)
// Clang contracts a*b+c within one expression by default; the error-free transformations must not
// be fused. (GCC gets -ffp-contract=off from CMakeLists.txt.)
#pragma STDC FP_CONTRACT OFF
#endif

namespace hullkit {
namespace {

// ---------------------------------------------------------------------------------------------
// Constants

/// Unit roundoff of binary64: |fl(x op y) - (x op y)| <= kEpsilon * |x op y| without underflow.
constexpr double kEpsilon = 0x1p-53;
/// Veltkamp's splitter 2^ceil(53/2) + 1: splits a double into two halves of at most 26 bits each.
constexpr double kSplitter = 0x1p27 + 1.0;

// Error bounds, as multiples of the permanent (the determinant's terms taken in absolute value),
// from the forward error analysis in Shewchuk's paper (sections 4.2-4.3 and 6). Each leading
// coefficient counts the roundings a term of the determinant can pass through before the
// comparison (stage A of orient3d: three differences, two products, the 2x2 minor, one of the two
// outer additions = 7); the higher-order parts absorb the roundoff of computing the bound itself.
// All of them are exactly representable.
constexpr double kResultErrBound = (3.0 + 8.0 * kEpsilon) * kEpsilon;
constexpr double kOrient2dBoundA = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kOrient2dBoundB = (2.0 + 12.0 * kEpsilon) * kEpsilon;
constexpr double kOrient2dBoundC = (9.0 + 64.0 * kEpsilon) * kEpsilon * kEpsilon;
constexpr double kOrient3dBoundA = (7.0 + 56.0 * kEpsilon) * kEpsilon;
constexpr double kOrient3dBoundB = (3.0 + 28.0 * kEpsilon) * kEpsilon;
constexpr double kOrient3dBoundC = (26.0 + 288.0 * kEpsilon) * kEpsilon * kEpsilon;

inline int sign_of(double x) { return (x > 0.0) - (x < 0.0); }

// ---------------------------------------------------------------------------------------------
// Error-free transformations. Each takes its operands by value and writes a rounded result `x`
// plus the exact roundoff `y`, so that x + y equals the real-number result exactly. The order of
// the individual operations matters; they are written one per statement on purpose.

/// x = fl(a + b), y = (a + b) - x exactly (Knuth's Two-Sum; no precondition).
inline void two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    const double b_virtual = x - a;
    const double a_virtual = x - b_virtual;
    const double b_roundoff = b - b_virtual;
    const double a_roundoff = a - a_virtual;
    y = a_roundoff + b_roundoff;
}

/// Same as two_sum, for |a| >= |b| (or a == 0): Dekker's Fast-Two-Sum.
inline void fast_two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    const double b_virtual = x - a;
    y = b - b_virtual;
}

/// The roundoff (a - b) - x of an already computed x = fl(a - b).
inline double diff_roundoff(double a, double b, double x) {
    const double minus_b = -b;
    const double b_virtual = x - a;
    const double a_virtual = x - b_virtual;
    const double b_roundoff = minus_b - b_virtual;
    const double a_roundoff = a - a_virtual;
    return a_roundoff + b_roundoff;
}

/// Veltkamp splitting: a == hi + lo exactly, each half fits in 26 significand bits, so products
/// of halves are exact.
inline void split(double a, double& hi, double& lo) {
    const double scaled = kSplitter * a;
    const double big = scaled - a;
    hi = scaled - big;
    lo = a - hi;
}

/// x = fl(a * b), y = a * b - x exactly, with b already split into b_hi + b_lo (Dekker's
/// Two-Product). The roundoff is peeled off the rounded product one exact partial product at a time.
inline void two_product_split(double a, double b, double b_hi, double b_lo, double& x, double& y) {
    x = a * b;
    double a_hi, a_lo;
    split(a, a_hi, a_lo);
    const double err1 = x - a_hi * b_hi;
    const double err2 = err1 - a_lo * b_hi;
    const double err3 = err2 - a_hi * b_lo;
    y = a_lo * b_lo - err3;
}

inline void two_product(double a, double b, double& x, double& y) {
    double b_hi, b_lo;
    split(b, b_hi, b_lo);
    two_product_split(a, b, b_hi, b_lo, x, y);
}

// ---------------------------------------------------------------------------------------------
// Expansion arithmetic (all outputs zero-free, increasing magnitude; inputs must not alias outputs).

/// h = e + b (Grow-Expansion). h has room for elen + 1 components. Returns the length of h.
inline int grow_expansion(int elen, const double* e, double b, double* h) {
    int hlen = 0;
    double carry = b;
    for (int i = 0; i < elen; ++i) {
        double sum, roundoff;
        two_sum(carry, e[i], sum, roundoff);
        carry = sum;
        if (roundoff != 0.0) h[hlen++] = roundoff;
    }
    if (carry != 0.0) h[hlen++] = carry;
    return hlen;
}

/// h = (a_hi + a_lo) - (b_hi + b_lo) for two exact two-component values such as the outputs of
/// two_product. h has room for 4 components. Returns the length of h.
inline int two_two_diff(double a_hi, double a_lo, double b_hi, double b_lo, double* h) {
    double a[2];
    int alen = 0;
    if (a_lo != 0.0) a[alen++] = a_lo;
    if (a_hi != 0.0) a[alen++] = a_hi;
    double partial[3];
    const int plen = grow_expansion(alen, a, -b_lo, partial);
    return grow_expansion(plen, partial, -b_hi, h);
}

/// h = e + f (Fast-Expansion-Sum): merge the components of e and f by increasing magnitude, then
/// sweep a running sum through them, emitting each exact roundoff. Needs strongly non-overlapping
/// inputs and round-to-nearest-even, which every expansion built here satisfies. h has room for
/// elen + flen components. Returns the length of h.
int expansion_sum(int elen, const double* e, int flen, const double* f, double* h) {
    if (elen == 0 || flen == 0) {
        const double* src = elen == 0 ? f : e;
        const int n = elen == 0 ? flen : elen;
        for (int i = 0; i < n; ++i) h[i] = src[i];
        return n;
    }
    int i = 0;
    int j = 0;
    auto next_smallest = [&]() -> double {
        if (j == flen || (i < elen && std::fabs(e[i]) <= std::fabs(f[j]))) return e[i++];
        return f[j++];
    };
    int hlen = 0;
    const double first = next_smallest();
    const double second = next_smallest();
    double carry, roundoff;
    fast_two_sum(second, first, carry, roundoff);  // |second| >= |first| by the merge order
    if (roundoff != 0.0) h[hlen++] = roundoff;
    while (i < elen || j < flen) {
        const double g = next_smallest();
        double sum;
        two_sum(carry, g, sum, roundoff);
        carry = sum;
        if (roundoff != 0.0) h[hlen++] = roundoff;
    }
    if (carry != 0.0) h[hlen++] = carry;
    return hlen;
}

/// h = e * b (Scale-Expansion): each component's exact product is folded into a running sum; the
/// high half of every product is at least as large as the carry, which allows a Fast-Two-Sum.
/// h has room for 2 * elen components. Returns the length of h.
int scale_expansion(int elen, const double* e, double b, double* h) {
    if (elen == 0 || b == 0.0) return 0;
    double b_hi, b_lo;
    split(b, b_hi, b_lo);
    int hlen = 0;
    double carry, roundoff;
    two_product_split(e[0], b, b_hi, b_lo, carry, roundoff);
    if (roundoff != 0.0) h[hlen++] = roundoff;
    for (int i = 1; i < elen; ++i) {
        double product_hi, product_lo;
        two_product_split(e[i], b, b_hi, b_lo, product_hi, product_lo);
        double sum;
        two_sum(carry, product_lo, sum, roundoff);
        if (roundoff != 0.0) h[hlen++] = roundoff;
        fast_two_sum(product_hi, sum, carry, roundoff);
        if (roundoff != 0.0) h[hlen++] = roundoff;
    }
    if (carry != 0.0) h[hlen++] = carry;
    return hlen;
}

/// Approximate value of an expansion (error below one ulp of the value plus a little).
inline double estimate(int elen, const double* e) {
    double sum = 0.0;
    for (int i = 0; i < elen; ++i) sum += e[i];
    return sum;
}

/// Exact sign of an expansion: the sign of its largest component.
inline int expansion_sign(int elen, const double* e) { return elen == 0 ? 0 : sign_of(e[elen - 1]); }

/// The exact difference a - b as an expansion of at most two components.
inline int exact_diff(double a, double b, double* h) {
    double x, y;
    two_sum(a, -b, x, y);
    int hlen = 0;
    if (y != 0.0) h[hlen++] = y;
    if (x != 0.0) h[hlen++] = x;
    return hlen;
}

/// Largest expansion multiply_short accepts as `e`.
constexpr int kMaxLongFactor = 16;

/// h = e * f where f has at most two components and e at most kMaxLongFactor.
/// h has room for 4 * elen components. Returns the length of h.
int multiply_short(int elen, const double* e, int flen, const double* f, double* h) {
    if (flen == 0 || elen == 0) return 0;
    if (flen == 1) return scale_expansion(elen, e, f[0], h);
    double low[2 * kMaxLongFactor];
    double high[2 * kMaxLongFactor];
    const int low_len = scale_expansion(elen, e, f[0], low);
    const int high_len = scale_expansion(elen, e, f[1], high);
    return expansion_sum(low_len, low, high_len, high, h);
}

/// h = p * q - r * s exactly, each factor an expansion of at most two components (exact
/// differences of coordinates). h has room for 16 components. Returns the length of h.
int exact_minor(int plen, const double* p, int qlen, const double* q, int rlen, const double* r,
                int slen, const double* s, double* h) {
    double pq[8];
    double rs[8];
    const int pq_len = multiply_short(plen, p, qlen, q, pq);
    const int rs_len = multiply_short(rlen, r, slen, s, rs);
    for (int i = 0; i < rs_len; ++i) rs[i] = -rs[i];
    return expansion_sum(pq_len, pq, rs_len, rs, h);
}

// ---------------------------------------------------------------------------------------------
// orient2d

/// Stage D: exact sign of (ax - cx)(by - cy) - (ay - cy)(bx - cx) from the exact differences.
int orient2d_exact_sign(double ax, double ay, double bx, double by, double cx, double cy) {
    double acx[2], acy[2], bcx[2], bcy[2];
    const int acx_len = exact_diff(ax, cx, acx);
    const int acy_len = exact_diff(ay, cy, acy);
    const int bcx_len = exact_diff(bx, cx, bcx);
    const int bcy_len = exact_diff(by, cy, bcy);
    double det[16];
    const int det_len = exact_minor(acx_len, acx, bcy_len, bcy, acy_len, acy, bcx_len, bcx, det);
    return expansion_sign(det_len, det);
}

/// Stages B-D of orient2d, entered when the filter could not decide. `detsum` is the permanent
/// |(ax-cx)(by-cy)| + |(ay-cy)(bx-cx)| as computed by the filter.
int orient2d_adapt(double ax, double ay, double bx, double by, double cx, double cy, double detsum,
                   int* stage) {
    if (detsum == 0.0) {
        // Both products are exactly zero (in range a nonzero product never rounds to zero), so each
        // has a factor a - b with a == b: the exact determinant is 0 too. Common for axis-aligned
        // input, where the tail stages could not decide and would end in stage D.
        return 0;
    }
    const double acx = ax - cx;
    const double bcx = bx - cx;
    const double acy = ay - cy;
    const double bcy = by - cy;

    // Stage B: the exact determinant of the rounded differences.
    double left_hi, left_lo, right_hi, right_lo;
    two_product(acx, bcy, left_hi, left_lo);
    two_product(acy, bcx, right_hi, right_lo);
    double b_exp[4];
    const int b_len = two_two_diff(left_hi, left_lo, right_hi, right_lo, b_exp);
    double det = estimate(b_len, b_exp);
    double errbound = kOrient2dBoundB * detsum;
    if (std::fabs(det) > errbound) {
        if (stage) *stage = 1;
        return sign_of(det);
    }

    const double acx_tail = diff_roundoff(ax, cx, acx);
    const double bcx_tail = diff_roundoff(bx, cx, bcx);
    const double acy_tail = diff_roundoff(ay, cy, acy);
    const double bcy_tail = diff_roundoff(by, cy, bcy);
    if (acx_tail == 0.0 && bcx_tail == 0.0 && acy_tail == 0.0 && bcy_tail == 0.0) {
        // The differences were exact, so the stage B expansion is the determinant itself.
        if (stage) *stage = 1;
        return expansion_sign(b_len, b_exp);
    }

    // Stage C: add the first-order terms of the tails in floating point.
    errbound = kOrient2dBoundC * detsum + kResultErrBound * std::fabs(det);
    const double left_corr = acx * bcy_tail + bcy * acx_tail;
    const double right_corr = acy * bcx_tail + bcx * acy_tail;
    det += left_corr - right_corr;
    if (std::fabs(det) > errbound) {
        if (stage) *stage = 2;
        return sign_of(det);
    }

    // Stage D: exact.
    if (stage) *stage = 3;
    return orient2d_exact_sign(ax, ay, bx, by, cx, cy);
}

/// Stage A; falls through to orient2d_adapt.
inline int orient2d_impl(double ax, double ay, double bx, double by, double cx, double cy,
                         int* stage) {
    // Stage A (detail::orient2d_stage_a, shared with the header's inline and semi-static tests).
    // No early exit on opposite signs of left and right (Shewchuk's shortcut): on random input
    // that branch is unpredictable and costs more than it saves. With opposite signs there is no
    // cancellation and |det| exceeds the bound anyway.
    const detail::Orient2dStageA a = detail::orient2d_stage_a(ax, ay, bx, by, cx, cy);
    const double det = a.det, detsum = a.permanent;
    const double errbound = kOrient2dBoundA * detsum;
    if (stage) *stage = 0;
    if (std::fabs(det) > errbound) return sign_of(det);
    return orient2d_adapt(ax, ay, bx, by, cx, cy, detsum, stage);
}

// ---------------------------------------------------------------------------------------------
// orient3d
//
// Internally the determinant is taken with rows relative to the last point, as in the paper:
//   det3(p, q, r, s) = det[p-s; q-s; r-s]
//                    = (pz-sz) * M(q,r) + (qz-sz) * M(r,p) + (rz-sz) * M(p,q),
//   M(u,v) = (ux-sx)(vy-sy) - (vx-sx)(uy-sy).
// hullkit's orient3d(a,b,c,d) = det[b-a; c-a; d-a] = -det[a-d; b-d; c-d] = det3(b, a, c, d).

/// Stage D: exact sign of det3(p, q, r, s) from the exact differences.
int det3_exact_sign(const double* p, const double* q, const double* r, const double* s) {
    double psx[2], psy[2], psz[2], qsx[2], qsy[2], qsz[2], rsx[2], rsy[2], rsz[2];
    const int psx_len = exact_diff(p[0], s[0], psx);
    const int psy_len = exact_diff(p[1], s[1], psy);
    const int psz_len = exact_diff(p[2], s[2], psz);
    const int qsx_len = exact_diff(q[0], s[0], qsx);
    const int qsy_len = exact_diff(q[1], s[1], qsy);
    const int qsz_len = exact_diff(q[2], s[2], qsz);
    const int rsx_len = exact_diff(r[0], s[0], rsx);
    const int rsy_len = exact_diff(r[1], s[1], rsy);
    const int rsz_len = exact_diff(r[2], s[2], rsz);

    double minor_qr[16], minor_rp[16], minor_pq[16];
    const int qr_len = exact_minor(qsx_len, qsx, rsy_len, rsy, rsx_len, rsx, qsy_len, qsy, minor_qr);
    const int rp_len = exact_minor(rsx_len, rsx, psy_len, psy, psx_len, psx, rsy_len, rsy, minor_rp);
    const int pq_len = exact_minor(psx_len, psx, qsy_len, qsy, qsx_len, qsx, psy_len, psy, minor_pq);

    double term_p[64], term_q[64], term_r[64];
    const int tp_len = multiply_short(qr_len, minor_qr, psz_len, psz, term_p);
    const int tq_len = multiply_short(rp_len, minor_rp, qsz_len, qsz, term_q);
    const int tr_len = multiply_short(pq_len, minor_pq, rsz_len, rsz, term_r);

    double pq_sum[128];
    const int pq_sum_len = expansion_sum(tp_len, term_p, tq_len, term_q, pq_sum);
    double det[192];
    const int det_len = expansion_sum(pq_sum_len, pq_sum, tr_len, term_r, det);
    return expansion_sign(det_len, det);
}

/// Stages B-D of orient3d, entered when the filter could not decide. `permanent` is as computed by
/// the filter.
int det3_adapt(const double* p, const double* q, const double* r, const double* s,
               double permanent, int* stage) {
    if (permanent == 0.0) {
        // Every term has a factor a - b with a == b (a nonzero product never rounds to zero in
        // range), so the exact determinant is 0: e.g. four points on a plane z = const.
        return 0;
    }
    const double psx = p[0] - s[0], psy = p[1] - s[1], psz = p[2] - s[2];
    const double qsx = q[0] - s[0], qsy = q[1] - s[1], qsz = q[2] - s[2];
    const double rsx = r[0] - s[0], rsy = r[1] - s[1], rsz = r[2] - s[2];

    // Stage B: the exact determinant of the rounded differences.
    double hi1, lo1, hi2, lo2;
    double minor_qr[4], minor_rp[4], minor_pq[4];
    two_product(qsx, rsy, hi1, lo1);
    two_product(rsx, qsy, hi2, lo2);
    const int qr_len = two_two_diff(hi1, lo1, hi2, lo2, minor_qr);
    two_product(rsx, psy, hi1, lo1);
    two_product(psx, rsy, hi2, lo2);
    const int rp_len = two_two_diff(hi1, lo1, hi2, lo2, minor_rp);
    two_product(psx, qsy, hi1, lo1);
    two_product(qsx, psy, hi2, lo2);
    const int pq_len = two_two_diff(hi1, lo1, hi2, lo2, minor_pq);

    double term_p[8], term_q[8], term_r[8];
    const int tp_len = scale_expansion(qr_len, minor_qr, psz, term_p);
    const int tq_len = scale_expansion(rp_len, minor_rp, qsz, term_q);
    const int tr_len = scale_expansion(pq_len, minor_pq, rsz, term_r);
    double pq_sum[16];
    const int pq_sum_len = expansion_sum(tp_len, term_p, tq_len, term_q, pq_sum);
    double b_exp[24];
    const int b_len = expansion_sum(pq_sum_len, pq_sum, tr_len, term_r, b_exp);

    double det = estimate(b_len, b_exp);
    double errbound = kOrient3dBoundB * permanent;
    if (std::fabs(det) > errbound) {
        if (stage) *stage = 1;
        return sign_of(det);
    }

    const double psx_t = diff_roundoff(p[0], s[0], psx);
    const double psy_t = diff_roundoff(p[1], s[1], psy);
    const double psz_t = diff_roundoff(p[2], s[2], psz);
    const double qsx_t = diff_roundoff(q[0], s[0], qsx);
    const double qsy_t = diff_roundoff(q[1], s[1], qsy);
    const double qsz_t = diff_roundoff(q[2], s[2], qsz);
    const double rsx_t = diff_roundoff(r[0], s[0], rsx);
    const double rsy_t = diff_roundoff(r[1], s[1], rsy);
    const double rsz_t = diff_roundoff(r[2], s[2], rsz);
    if (psx_t == 0.0 && psy_t == 0.0 && psz_t == 0.0 && qsx_t == 0.0 && qsy_t == 0.0 &&
        qsz_t == 0.0 && rsx_t == 0.0 && rsy_t == 0.0 && rsz_t == 0.0) {
        // The differences were exact, so the stage B expansion is the determinant itself.
        if (stage) *stage = 1;
        return expansion_sign(b_len, b_exp);
    }

    // Stage C: add the terms linear in the tails, in floating point.
    errbound = kOrient3dBoundC * permanent + kResultErrBound * std::fabs(det);
    const double corr_p = psz * ((qsx * rsy_t + rsy * qsx_t) - (qsy * rsx_t + rsx * qsy_t)) +
                          psz_t * (qsx * rsy - qsy * rsx);
    const double corr_q = qsz * ((rsx * psy_t + psy * rsx_t) - (rsy * psx_t + psx * rsy_t)) +
                          qsz_t * (rsx * psy - rsy * psx);
    const double corr_r = rsz * ((psx * qsy_t + qsy * psx_t) - (psy * qsx_t + qsx * psy_t)) +
                          rsz_t * (psx * qsy - psy * qsx);
    det += corr_p + corr_q + corr_r;
    if (std::fabs(det) > errbound) {
        if (stage) *stage = 2;
        return sign_of(det);
    }

    // Stage D: exact.
    if (stage) *stage = 3;
    return det3_exact_sign(p, q, r, s);
}

/// Stage A; falls through to det3_adapt.
inline int det3_impl(const double* p, const double* q, const double* r, const double* s,
                     int* stage) {
    const double psx = p[0] - s[0], psy = p[1] - s[1], psz = p[2] - s[2];
    const double qsx = q[0] - s[0], qsy = q[1] - s[1], qsz = q[2] - s[2];
    const double rsx = r[0] - s[0], rsy = r[1] - s[1], rsz = r[2] - s[2];

    const double qsx_rsy = qsx * rsy;
    const double rsx_qsy = rsx * qsy;
    const double rsx_psy = rsx * psy;
    const double psx_rsy = psx * rsy;
    const double psx_qsy = psx * qsy;
    const double qsx_psy = qsx * psy;

    const double det = psz * (qsx_rsy - rsx_qsy) + qsz * (rsx_psy - psx_rsy) +
                       rsz * (psx_qsy - qsx_psy);
    const double permanent = (std::fabs(qsx_rsy) + std::fabs(rsx_qsy)) * std::fabs(psz) +
                             (std::fabs(rsx_psy) + std::fabs(psx_rsy)) * std::fabs(qsz) +
                             (std::fabs(psx_qsy) + std::fabs(qsx_psy)) * std::fabs(rsz);
    const double errbound = kOrient3dBoundA * permanent;
    if (stage) *stage = 0;
    if (std::fabs(det) > errbound) return sign_of(det);
    return det3_adapt(p, q, r, s, permanent, stage);
}

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

/// The power of two 2^k bringing [min_abs_nonzero, max_abs] into [2^low_exp, 2^high_exp] (see
/// predicates_scale_exponent; low_exp, high_exp are the exponents of the range's powers of two).
bool scale_exponent_for_range(double max_abs_coordinate, double min_abs_nonzero_coordinate,
                              int low_exp, int high_exp, int* exponent) {
    if (!(max_abs_coordinate >= 0.0) || !(max_abs_coordinate <= DBL_MAX)) return false;
    if (max_abs_coordinate == 0.0) {
        *exponent = 0;
        return true;
    }
    if (!(min_abs_nonzero_coordinate > 0.0) || !(min_abs_nonzero_coordinate <= max_abs_coordinate))
        return false;
    // With max = fmax * 2^emax and min = fmin * 2^emin (frexp: fmax, fmin in [0.5, 1)):
    //   max * 2^k <= 2^high  <=>  emax + k <= high, or <= high + 1 when max is a power of two;
    //   min * 2^k >= 2^low   <=>  emin + k - 1 >= low.
    int emax = 0, emin = 0;
    const double fmax = std::frexp(max_abs_coordinate, &emax);
    std::frexp(min_abs_nonzero_coordinate, &emin);
    const int k_high = high_exp - emax + (fmax == 0.5 ? 1 : 0);
    const int k_low = low_exp + 1 - emin;
    if (k_low > k_high) return false;
    int k = 0;
    if (k < k_low) k = k_low;
    if (k > k_high) k = k_high;
    *exponent = k;
    return true;
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

// ---------------------------------------------------------------------------------------------
// Public entry points

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    return orient2d_impl(ax, ay, bx, by, cx, cy, nullptr);
}

int orient3d(const double* a, const double* b, const double* c, const double* d) {
    return det3_impl(b, a, c, d, nullptr);
}

int incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
             double dy) {
    return incircle_impl(ax, ay, bx, by, cx, cy, dx, dy, nullptr);
}

namespace detail {

static_assert(kOrient2dFilterBound == kOrient2dBoundA && kIncircleFilterBound == kIncircleBoundA,
              "the header's stage A bounds must match");

int orient2d_adapt_entry(double ax, double ay, double bx, double by, double cx, double cy,
                         double detsum) {
    return orient2d_adapt(ax, ay, bx, by, cx, cy, detsum, nullptr);
}

int incircle_adapt_entry(double ax, double ay, double bx, double by, double cx, double cy,
                         double dx, double dy, double permanent) {
    return incircle_adapt(ax, ay, bx, by, cx, cy, dx, dy, permanent, nullptr);
}

}  // namespace detail

bool incircle_scale_exponent(double max_abs_coordinate, double min_abs_nonzero_coordinate,
                             int* exponent) {
    static_assert(kIncircleMaxMagnitude == 0x1p+240 && kIncircleMinMagnitude == 0x1p-170,
                  "update the exponents below");
    return scale_exponent_for_range(max_abs_coordinate, min_abs_nonzero_coordinate, -170, 240,
                                    exponent);
}

int compare_distance(double ax, double ay, double bx, double by, double qx, double qy) {
    const double aqx = ax - qx, aqy = ay - qy, bqx = bx - qx, bqy = by - qy;
    const double a2 = aqx * aqx + aqy * aqy;
    const double b2 = bqx * bqx + bqy * bqy;
    const double det = a2 - b2;
    if (std::fabs(det) > kDistanceBound * (a2 + b2)) return sign_of(det);
    return compare_distance_exact(ax, ay, bx, by, qx, qy);
}

int collinear3d(const double* a, const double* b, const double* c) {
    // (b-a) x (c-a) == 0 componentwise; each component is an orient2d of an axis projection.
    return orient2d_impl(a[0], a[1], b[0], b[1], c[0], c[1], nullptr) == 0 &&
                   orient2d_impl(a[1], a[2], b[1], b[2], c[1], c[2], nullptr) == 0 &&
                   orient2d_impl(a[2], a[0], b[2], b[0], c[2], c[0], nullptr) == 0
               ? 1
               : 0;
}

bool predicates_scale_exponent(double max_abs_coordinate, double min_abs_nonzero_coordinate,
                               int* exponent) {
    if (!(max_abs_coordinate >= 0.0) || !(max_abs_coordinate <= DBL_MAX)) return false;
    if (max_abs_coordinate == 0.0) {
        *exponent = 0;
        return true;
    }
    if (!(min_abs_nonzero_coordinate > 0.0) || !(min_abs_nonzero_coordinate <= max_abs_coordinate))
        return false;
    // With max = fmax * 2^emax and min = fmin * 2^emin (frexp: fmax, fmin in [0.5, 1)):
    //   max * 2^k <= 2^335   <=>  emax + k <= 335, or <= 336 when max is a power of two (fmax == 0.5);
    //   min * 2^k >= 2^-250  <=>  emin + k - 1 >= -250.
    static_assert(kPredicateMaxMagnitude == 0x1p+335 && kPredicateMinMagnitude == 0x1p-250,
                  "update the exponents below");
    int emax = 0, emin = 0;
    const double fmax = std::frexp(max_abs_coordinate, &emax);
    std::frexp(min_abs_nonzero_coordinate, &emin);
    const int k_high = 335 - emax + (fmax == 0.5 ? 1 : 0);
    const int k_low = -249 - emin;
    if (k_low > k_high) return false;
    int k = 0;
    if (k < k_low) k = k_low;
    if (k > k_high) k = k_high;
    *exponent = k;
    return true;
}

namespace detail {

int orient2d_traced(double ax, double ay, double bx, double by, double cx, double cy, int* stage) {
    int ignored = 0;
    return orient2d_impl(ax, ay, bx, by, cx, cy, stage ? stage : &ignored);
}

int orient3d_traced(const double* a, const double* b, const double* c, const double* d,
                    int* stage) {
    int ignored = 0;
    return det3_impl(b, a, c, d, stage ? stage : &ignored);
}

int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy) {
    return orient2d_exact_sign(ax, ay, bx, by, cx, cy);
}

int orient3d_exact(const double* a, const double* b, const double* c, const double* d) {
    return det3_exact_sign(b, a, c, d);
}

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
