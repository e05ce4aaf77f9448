// hullkit: exact geometric predicates. See predicates.hpp for the contract and the valid range.
// This file: orient2d and orient3d (stages A-D), collinear3d, the scale exponents of the exact
// ranges, and the testing hooks; the expansion arithmetic is in expansion.hpp, incircle and
// compare_distance in incircle.cpp.
#include "hullkit/predicates.hpp"

#include <cfloat>
#include <cmath>

#include "expansion.hpp"

namespace hullkit {

using namespace exact_detail;

namespace {

// ---------------------------------------------------------------------------------------------
// Error bounds, as multiples of the permanent (the determinant's terms taken in absolute value),
// from the forward error analysis in Shewchuk's paper (sections 4.2-4.3 and 6). Each leading
// coefficient counts the roundings a term of the determinant can pass through before the
// comparison (stage A of orient3d: three differences, two products, the 2x2 minor, one of the two
// outer additions = 7); the higher-order parts absorb the roundoff of computing the bound itself.
// All of them are exactly representable.
constexpr double kOrient2dBoundA = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kOrient2dBoundB = (2.0 + 12.0 * kEpsilon) * kEpsilon;
constexpr double kOrient2dBoundC = (9.0 + 64.0 * kEpsilon) * kEpsilon * kEpsilon;
constexpr double kOrient3dBoundA = (7.0 + 56.0 * kEpsilon) * kEpsilon;
constexpr double kOrient3dBoundB = (3.0 + 28.0 * kEpsilon) * kEpsilon;
constexpr double kOrient3dBoundC = (26.0 + 288.0 * kEpsilon) * kEpsilon * kEpsilon;

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

}  // namespace

// ---------------------------------------------------------------------------------------------
// Public entry points

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    return orient2d_impl(ax, ay, bx, by, cx, cy, nullptr);
}

int orient3d(const double* a, const double* b, const double* c, const double* d) {
    return det3_impl(b, a, c, d, nullptr);
}

namespace detail {

static_assert(kOrient2dFilterBound == kOrient2dBoundA, "the header's stage A bound must match");
static_assert(kOrient3dFilterBound == kOrient3dBoundA, "the header's stage A bound must match");

int orient2d_adapt_entry(double ax, double ay, double bx, double by, double cx, double cy,
                         double detsum) {
    return orient2d_adapt(ax, ay, bx, by, cx, cy, detsum, nullptr);
}

}  // namespace detail

bool incircle_scale_exponent(double max_abs_coordinate, double min_abs_nonzero_coordinate,
                             int* exponent) {
    static_assert(kIncircleMaxMagnitude == 0x1p+240 && kIncircleMinMagnitude == 0x1p-170,
                  "update the exponents below");
    return scale_exponent_for_range(max_abs_coordinate, min_abs_nonzero_coordinate, -170, 240,
                                    exponent);
}

bool insphere_scale_exponent(double max_abs_coordinate, double min_abs_nonzero_coordinate, int* exponent) {
    static_assert(kInsphereMaxMagnitude == 0x1p+195 && kInsphereMinMagnitude == 0x1p-120,
                  "update the exponents below");
    return scale_exponent_for_range(max_abs_coordinate, min_abs_nonzero_coordinate, -120, 195, exponent);
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

}  // namespace detail
}  // namespace hullkit
