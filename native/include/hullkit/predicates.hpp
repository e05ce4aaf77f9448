// hullkit: exact geometric predicates (orientation tests) for the hull algorithms.
//
// Every predicate returns the exact sign of a polynomial in the input coordinates, as if it were
// evaluated in real arithmetic, for all finite doubles inside the valid range documented below.
// The method is Shewchuk's adaptive precision arithmetic ("Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates", Discrete & Computational Geometry 18, 1997):
//
//   stage A  the determinant in plain floating point, accepted when its magnitude exceeds an error
//            bound proven from the magnitudes of the terms (the "permanent"). This is the common
//            case and costs about 1.5x a naive determinant: no allocation, no loops, one branch.
//            (A permanent of exactly 0, e.g. four points on a plane z = const, also means an exact
//            0 and is answered here.)
//   stage B  the exact determinant of the rounded coordinate differences, as an expansion (a sum of
//            non-overlapping doubles) built with error-free transformations: Two-Sum, and
//            Two-Product by Veltkamp/Dekker splitting (never fma, so results are bit-identical on
//            every IEEE-754 binary64 target, Emscripten/wasm included). When the differences were
//            computed exactly (e.g. integer or shared-exponent coordinates) this value is exact.
//   stage C  a first-order correction for the roundoff of the differences, with its own bound.
//   stage D  the fully exact expansion of the determinant.
//
// Later stages run only when the earlier ones cannot decide; all expansions live in fixed-size stack
// arrays. The functions are pure and thread-safe.
//
// Requirements on the build: IEEE-754 binary64 with round-to-nearest-even, no excess precision
// (FLT_EVAL_METHOD == 0, i.e. SSE2 on x86, any 64-bit target, wasm), no -ffast-math, and no
// floating-point contraction into fma (-ffp-contract=off, set by the project's CMakeLists.txt);
// the error bounds and the error-free transformations assume exactly rounded + - *.
//
// ---- Valid input range ----
// The sign is guaranteed exact when every coordinate x passed to a predicate is finite and either
// 0 or  kPredicateMinMagnitude <= |x| <= kPredicateMaxMagnitude,  i.e. 2^-250 <= |x| <= 2^+335.
// Where that comes from (orient3d is the binding case; orient2d alone would allow more):
//  * Overflow. Differences of coordinates are below 2^336, products of three differences below
//    2^1008, and the permanent (a sum of six such products) and every partial sum of the exact
//    expansions stay below 2^1011; Veltkamp splitting multiplies values of at most ~2^676 (products
//    of two differences) by 2^27 + 1. Nothing comes near 2^1024 (the analysis gives 2^339 as the
//    hard limit for coordinates; 2^335 keeps a margin of 2^12).
//  * Underflow. A nonzero double with |x| >= 2^-250 is an integer multiple of q = 2^-302 (its last
//    significand bit), so every coordinate, every difference and the roundoff tail of every
//    difference is a multiple of q; every product of two of them a multiple of q^2, and every value
//    any stage computes from products of three (including all rounded results, since rounding to
//    the coarser grid of a larger number keeps a multiple of q^3) is a multiple of q^3 = 2^-906.
//    So every nonzero intermediate value is at least 2^-906, far from the subnormal range, and even
//    the smallest error bound, about 2^-101.3 times the permanent, is a normal number
//    (>= 2^-1008 > 2^-1022): every relative error bound used in the proofs holds and the
//    error-free transformations are exact. (The analysis gives 2^-254 as the hard limit; 2^-250
//    keeps a margin.)
// Note the lower limit is on the coordinates themselves, not on their differences: the roundoff
// tail of 1 - 2^-1000 is 2^-1000, and products of such tails would underflow.
// Outside the range the predicates still return +1, 0 or -1 and never crash or loop, but the sign
// may be wrong. Non-finite inputs (inf, NaN) give an unspecified sign.
//
// Multiplying all coordinates by the same power of two is exact (as long as it stays in range) and
// changes no sign, so a caller whose data lies outside the range but spans less than 2^585 between
// its largest and smallest nonzero |coordinate| can rescale first: see predicates_scale_exponent().
#pragma once

#include <algorithm>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hullkit {

/// Largest |coordinate| for which the predicates are guaranteed exact: 2^+335 (about 7.0e+100).
inline constexpr double kPredicateMaxMagnitude = 0x1p+335;
/// Smallest nonzero |coordinate| for which the predicates are guaranteed exact: 2^-250
/// (about 5.5e-76). Exactly zero coordinates are always fine.
inline constexpr double kPredicateMinMagnitude = 0x1p-250;

/// True when coordinates with these extremes are inside the valid range: `max_abs_coordinate` is the
/// largest |coordinate| over all points, `min_abs_nonzero_coordinate` the smallest nonzero one
/// (ignored when max_abs_coordinate is 0, i.e. all coordinates are zero). False for inf or NaN.
inline constexpr bool predicates_range_ok(double max_abs_coordinate,
                                          double min_abs_nonzero_coordinate) {
    return max_abs_coordinate <= kPredicateMaxMagnitude &&
           (max_abs_coordinate == 0.0 || min_abs_nonzero_coordinate >= kPredicateMinMagnitude);
}

/// Finds a power of two 2^k that brings coordinates with these extremes (as for predicates_range_ok)
/// into the valid range: on success stores k in *exponent (0 when already in range, otherwise the
/// value closest to 0) and returns true; the caller then multiplies every coordinate by
/// std::ldexp(1.0, k), which is exact. Returns false (and leaves *exponent alone) when no power of
/// two works (the data spans more than the range) or an input is inf/NaN/negative.
bool predicates_scale_exponent(double max_abs_coordinate, double min_abs_nonzero_coordinate,
                               int* exponent);

/// Orientation of c relative to the directed line a->b:
///   +1  c lies to the left of a->b (a, b, c is counter-clockwise),
///   -1  c lies to the right (clockwise),
///    0  a, b, c are exactly collinear (also when two or all of them coincide).
/// Exact sign of (ax - cx) * (by - cy) - (ay - cy) * (bx - cx) = det[b-a; c-a].
int orient2d(double ax, double ay, double bx, double by, double cx, double cy);

/// Orientation of d relative to the plane through a, b, c (each a pointer to x, y, z):
///   +1  d lies on the side the normal (b-a) x (c-a) points to: "above" the triangle a, b, c when
///       that triangle is counter-clockwise seen from above,
///   -1  d lies below,
///    0  a, b, c, d are exactly coplanar (also when a, b, c are collinear).
/// Exact sign of ((b-a) x (c-a)) . (d-a) = det[b-a; c-a; d-a].
/// NOTE: this is the OPPOSITE of the sign convention of Shewchuk's orient3d in predicates.c
/// (which is positive when d is below); hullkit's orient3d(a,b,c,d) == -shewchuk_orient3d(a,b,c,d).
/// Consequence for hulls: a triangle a, b, c of a convex hull is oriented counter-clockwise seen
/// from outside iff orient3d(a, b, c, p) <= 0 for every input point p.
int orient3d(const double* a, const double* b, const double* c, const double* d);

/// 1 if a, b, c (pointers to x, y, z) are exactly collinear, i.e. (b-a) x (c-a) == 0 exactly
/// (equivalently orient2d == 0 on all three axis projections xy, yz, zx); also 1 when two or all
/// three points coincide. 0 otherwise.
int collinear3d(const double* a, const double* b, const double* c);

/// Largest |coordinate| for which incircle is guaranteed exact: 2^+240 (about 1.8e+72). incircle
/// is a degree-4 polynomial, so its range is tighter than orient3d's: see incircle.cpp.
inline constexpr double kIncircleMaxMagnitude = 0x1p+240;
/// Smallest nonzero |coordinate| for which incircle is guaranteed exact: 2^-170 (about 6.7e-52).
inline constexpr double kIncircleMinMagnitude = 0x1p-170;

/// As predicates_range_ok, for the (tighter) range of incircle. Inside this range orient2d and
/// orient3d are exact as well.
inline constexpr bool incircle_range_ok(double max_abs_coordinate,
                                        double min_abs_nonzero_coordinate) {
    return max_abs_coordinate <= kIncircleMaxMagnitude &&
           (max_abs_coordinate == 0.0 || min_abs_nonzero_coordinate >= kIncircleMinMagnitude);
}

/// As predicates_scale_exponent, for the range of incircle (data spanning less than 2^410 between
/// its largest and smallest nonzero |coordinate| can be brought into range).
bool incircle_scale_exponent(double max_abs_coordinate, double min_abs_nonzero_coordinate,
                             int* exponent);

/// In-circle test: where d lies relative to the circle through a, b, c (2D points, y up):
///   +1  d is strictly inside the circle when a, b, c are counter-clockwise (orient2d > 0),
///       strictly outside when they are clockwise,
///   -1  the opposite,
///    0  a, b, c, d are exactly cocircular (or a, b, c collinear and d on their line, or points
///       coincide so that the determinant vanishes).
/// Exact sign of det[a-d, |a-d|^2; b-d, |b-d|^2; c-d, |c-d|^2] (rows x, y, squared length), which is
/// also the orientation of the lifted points (x, y, x^2 + y^2): for counter-clockwise a, b, c, +1
/// means the lifted d lies strictly BELOW the plane of the lifted a, b, c. Same sign convention as
/// Shewchuk's incircle. Exact for coordinates inside [kIncircleMinMagnitude, kIncircleMaxMagnitude]
/// (or 0).
int incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx,
             double dy);

/// Which of a and b is nearer to q: the exact sign of |a - q|^2 - |b - q|^2 (-1: a is nearer,
/// +1: b is nearer, 0: exactly as far). Exact in the same range as incircle.
int compare_distance(double ax, double ay, double bx, double by, double qx, double qy);

/// Largest |coordinate| for which insphere is guaranteed exact: 2^+195 (about 5.0e+58). insphere
/// is a polynomial of degree 5, so its range is tighter still than incircle's: see insphere.cpp.
inline constexpr double kInsphereMaxMagnitude = 0x1p+195;
/// Smallest nonzero |coordinate| for which insphere is guaranteed exact: 2^-120 (about 7.5e-37).
inline constexpr double kInsphereMinMagnitude = 0x1p-120;

/// As predicates_range_ok, for the range of insphere. Inside this range orient3d is exact too.
inline constexpr bool insphere_range_ok(double max_abs_coordinate, double min_abs_nonzero_coordinate) {
    return max_abs_coordinate <= kInsphereMaxMagnitude &&
           (max_abs_coordinate == 0.0 || min_abs_nonzero_coordinate >= kInsphereMinMagnitude);
}

/// As predicates_scale_exponent, for the range of insphere (data spanning less than 2^315 between
/// its largest and smallest nonzero |coordinate| can be brought into range).
bool insphere_scale_exponent(double max_abs_coordinate, double min_abs_nonzero_coordinate, int* exponent);

/// In-sphere test: where e lies relative to the sphere through a, b, c, d (pointers to x, y, z):
///   +1  e is strictly inside the sphere when a, b, c, d are positively oriented
///       (orient3d(a, b, c, d) > 0), strictly outside when they are negatively oriented,
///   -1  the opposite,
///    0  the five points are exactly cospherical (or a, b, c, d coplanar and e on their circle or
///       plane, or points coincide so that the determinant vanishes).
/// Exact sign of -det[b-a, |b|^2-|a|^2; c-a, ...; d-a, ...; e-a, ...] (rows x, y, z, lift), i.e.
/// the orientation of the lifted points (x, y, z, x^2 + y^2 + z^2): for positively oriented
/// a, b, c, d, +1 means the lifted e lies strictly BELOW the hyperplane of the lifted a, b, c, d.
/// NOTE: like orient3d, the opposite sign of Shewchuk's insphere in predicates.c
/// (hullkit insphere(a,b,c,d,e) == -shewchuk_insphere(a,b,c,d,e)), so that "positively oriented,
/// +1 inside" holds with hullkit's orient3d. Exact for coordinates inside
/// [kInsphereMinMagnitude, kInsphereMaxMagnitude] (or 0).
int insphere(const double* a, const double* b, const double* c, const double* d, const double* e);

/// Which of a and b (pointers to x, y, z) is nearer to q: the exact sign of |a - q|^2 - |b - q|^2
/// (-1: a is nearer, +1: b is nearer, 0: exactly as far). Exact for coordinates in orient3d's
/// range (kPredicateMinMagnitude .. kPredicateMaxMagnitude, or 0).
int compare_distance3d(const double* a, const double* b, const double* q);

namespace detail {

// Testing and diagnostics hooks. Same results as the public functions.

/// orient2d / orient3d that also report in *stage which stage decided: 0 = floating-point filter,
/// 1 = exact products of the rounded differences, 2 = first-order tail correction, 3 = full exact
/// expansion.
int orient2d_traced(double ax, double ay, double bx, double by, double cx, double cy, int* stage);
int orient3d_traced(const double* a, const double* b, const double* c, const double* d, int* stage);

/// The fully exact expansion alone (stage D), skipping every filter.
int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy);
int orient3d_exact(const double* a, const double* b, const double* c, const double* d);
/// incircle that reports the deciding stage (as orient2d_traced), and its stage D alone.
int incircle_traced(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                    double dy, int* stage);
int incircle_exact(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                   double dy);

// ---- Inlinable fast paths (same results as orient2d / incircle) ----
// Stage A (the floating-point filter with Shewchuk's error bound, the same bounds as in
// predicates.cpp and incircle.cpp) in the header, so that hot loops can inline it; when the
// filter cannot decide, the exact stages B-D run out of line. The sign is always the exact sign,
// like the public functions. Clang contracts a*b+c into fma within one expression by default;
// the bounds assume separately rounded operations, hence the pragma (GCC gets -ffp-contract=off
// from CMakeLists.txt).

/// Stage A error bound factors (multiples of the permanent); see predicates.cpp and incircle.cpp.
inline constexpr double kOrient2dFilterBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
inline constexpr double kIncircleFilterBound = (10.0 + 96.0 * 0x1p-53) * 0x1p-53;

/// Stages B-D of orient2d / incircle, given the permanent computed by stage A (out of line).
int orient2d_adapt_entry(double ax, double ay, double bx, double by, double cx, double cy,
                         double detsum);
int incircle_adapt_entry(double ax, double ay, double bx, double by, double cx, double cy,
                         double dx, double dy, double permanent);

/// orient2d's stage A: the determinant in floating point and its permanent, |left| + |right|
/// (the bound on its rounding error is kOrient2dFilterBound times the permanent).
/// The stage A permanents take std::fabs (a mask) rather than `x < 0 ? -x : x`, which GCC
/// compiled into a branch per term: six unpredictable branches in every incircle that the
/// semi-static bound leaves to the full predicate (a third of them on a 10 km lake shore sampled
/// every metre: its 2D Delaunay 57 -> 48 ms). The values are the same but for the sign of a zero
/// permanent, which no comparison tells apart.
struct Orient2dStageA {
    double det;
    double permanent;
};
inline Orient2dStageA orient2d_stage_a(double ax, double ay, double bx, double by, double cx, double cy) {
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    const double left = (ax - cx) * (by - cy);
    const double right = (ay - cy) * (bx - cx);
    return {left - right, std::fabs(left) + std::fabs(right)};
}

/// orient2d with stage A inline.
inline int orient2d_inline(double ax, double ay, double bx, double by, double cx, double cy) {
    const Orient2dStageA a = orient2d_stage_a(ax, ay, bx, by, cx, cy);
    const double errbound = kOrient2dFilterBound * a.permanent;
    if (a.det > errbound) return 1;
    if (-a.det > errbound) return -1;
    return orient2d_adapt_entry(ax, ay, bx, by, cx, cy, a.permanent);
}

/// incircle's stage A: the determinant in floating point and its permanent (the bound on its
/// rounding error is kIncircleFilterBound times the permanent). Shared with incircle.cpp.
struct IncircleStageA {
    double det;
    double permanent;
};
inline IncircleStageA incircle_stage_a(double ax, double ay, double bx, double by, double cx, double cy,
                                       double dx, double dy) {
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    const double adx = ax - dx, ady = ay - dy;
    const double bdx = bx - dx, bdy = by - dy;
    const double cdx = cx - dx, cdy = cy - dy;
    const double bdx_cdy = bdx * cdy, cdx_bdy = cdx * bdy;
    const double cdx_ady = cdx * ady, adx_cdy = adx * cdy;
    const double adx_bdy = adx * bdy, bdx_ady = bdx * ady;
    const double alift = adx * adx + ady * ady;
    const double blift = bdx * bdx + bdy * bdy;
    const double clift = cdx * cdx + cdy * cdy;
    const double det = alift * (bdx_cdy - cdx_bdy) + blift * (cdx_ady - adx_cdy) +
                       clift * (adx_bdy - bdx_ady);
    const double permanent =
        (std::fabs(bdx_cdy) + std::fabs(cdx_bdy)) * alift + (std::fabs(cdx_ady) + std::fabs(adx_cdy)) * blift +
        (std::fabs(adx_bdy) + std::fabs(bdx_ady)) * clift;
    return {det, permanent};
}

/// Semi-static bounds for a whole point set (computed once): when every coordinate difference of
/// the points, as computed in floating point, is at most `span` in magnitude (e.g. all points lie
/// in a box whose computed width and height are at most span), the permanent stage A computes is
/// below 12 span^4 (1 + 2^-49) for incircle and 2 span^2 (1 + 2^-50) for orient2d, so a stage A
/// determinant larger in magnitude than these bounds has the exact sign (stage A itself would have
/// decided the same). The factor 1 + 2^-40 covers the rounding of the bound's own products. Skips
/// computing the permanent in hot loops; the caller falls back to the full predicate otherwise.
inline double incircle_static_bound(double span) {
    return kIncircleFilterBound * 12.0 * (span * span) * (span * span) * (1.0 + 0x1p-40);
}
inline double orient2d_static_bound(double span) {
    return kOrient2dFilterBound * 2.0 * (span * span) * (1.0 + 0x1p-40);
}

/// orient2d and incircle that first try a semi-static bound for the whole point set
/// (orient2d_static_bound / incircle_static_bound): the stage A determinant alone, without its
/// permanent; the full predicate when the bound cannot tell. Always the exact sign.
/// `exact_in_doubles`: the caller knows stage A is exact for this point set (a small lattice,
/// native/src/exact/lattice.hpp), so its sign is the answer even inside the bound (0 included).
inline int orient2d_semi_static(double bound, double ax, double ay, double bx, double by, double cx, double cy,
                                bool exact_in_doubles = false) {
    const double det = orient2d_stage_a(ax, ay, bx, by, cx, cy).det;
    if (det > bound) return 1;
    if (-det > bound) return -1;
    if (exact_in_doubles) return (det > 0) - (det < 0);
    return orient2d(ax, ay, bx, by, cx, cy);
}
inline int incircle_semi_static(double bound, double ax, double ay, double bx, double by, double cx, double cy,
                                double dx, double dy, bool exact_in_doubles = false) {
    const double det = incircle_stage_a(ax, ay, bx, by, cx, cy, dx, dy).det;
    if (det > bound) return 1;
    if (-det > bound) return -1;
    if (exact_in_doubles) return (det > 0) - (det < 0);
    return incircle(ax, ay, bx, by, cx, cy, dx, dy);
}

/// insphere that reports the deciding stage: 0 = floating-point filter, 1 = exact arithmetic on
/// exactly computed differences (integer fast path or expansions), 2 = the rounded differences'
/// exact determinant plus the first-order term of their roundoff (an error bound of order
/// eps^2 times the permanent), 3 = the full exact expansion from the rounded differences and their
/// roundoff. And its full exact evaluation alone.
int insphere_traced(const double* a, const double* b, const double* c, const double* d, const double* e,
                    int* stage);
int insphere_exact(const double* a, const double* b, const double* c, const double* d, const double* e);

/// Stage A bounds of orient3d and insphere (multiples of the permanent; Shewchuk 1997).
inline constexpr double kOrient3dFilterBound = (7.0 + 56.0 * 0x1p-53) * 0x1p-53;
inline constexpr double kInsphereFilterBound = (16.0 + 224.0 * 0x1p-53) * 0x1p-53;

/// orient3d's stage A value det[b-a; c-a; d-a] in floating point (without its permanent).
inline double orient3d_stage_a(const double* a, const double* b, const double* c, const double* d) {
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    const double bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
    const double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
    const double dx = d[0] - a[0], dy = d[1] - a[1], dz = d[2] - a[2];
    return bx * (cy * dz - cz * dy) + by * (cz * dx - cx * dz) + bz * (cx * dy - cy * dx);
}

/// With every coordinate difference of the points (as computed) at most `span`: the permanent of
/// orient3d's determinant is below 6 span^3 (1 + 2^-48), so a stage A value beyond this bound has
/// the exact sign (the factor 1 + 2^-40 covers the rounding of the bound's own products and the
/// order in which orient3d_stage_a sums, which rounds no worse than the filter's own formula).
inline double orient3d_static_bound(double span) {
    return kOrient3dFilterBound * 6.0 * (span * span * span) * (1.0 + 0x1p-40);
}
inline int orient3d_semi_static(double bound, const double* a, const double* b, const double* c, const double* d) {
    const double det = orient3d_stage_a(a, b, c, d);
    if (det > bound) return 1;
    if (-det > bound) return -1;
    return orient3d(a, b, c, d);
}

/// insphere's determinant of the twelve differences x (aex, aey, aez, bex, ..., dez; hullkit's sign)
/// in any arithmetic T with +, - and *: expanded by its lift column into four 3x3 minors, each from
/// the six 2x2 minors of the x, y columns. Stage A runs it on doubles, insphere.cpp's stage C on
/// double-word numbers and on dual numbers; with `absolute` every subtraction is an addition (for
/// inputs given in absolute value: an error bound's program).
template <class T, bool absolute = false>
inline T insphere_formula(const T* x) {
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    const auto minus = [](T p, T q) { return absolute ? p + q : p - q; };
    const T aex = x[0], aey = x[1], aez = x[2], bex = x[3], bey = x[4], bez = x[5];
    const T cex = x[6], cey = x[7], cez = x[8], dex = x[9], dey = x[10], dez = x[11];
    const T ab = minus(aex * bey, bex * aey), bc = minus(bex * cey, cex * bey), cd = minus(cex * dey, dex * cey);
    const T da = minus(dex * aey, aex * dey), ac = minus(aex * cey, cex * aey), bd = minus(bex * dey, dex * bey);
    const T abc = minus(aez * bc, bez * ac) + cez * ab;
    const T bcd = minus(bez * cd, cez * bd) + dez * bc;
    const T cda = cez * da + dez * ac + aez * cd;
    const T dab = dez * ab + aez * bd + bez * da;
    const T alift = aex * aex + aey * aey + aez * aez;
    const T blift = bex * bex + bey * bey + bez * bez;
    const T clift = cex * cex + cey * cey + cez * cez;
    const T dlift = dex * dex + dey * dey + dez * dez;
    return minus(alift * bcd, blift * cda) + minus(clift * dab, dlift * abc);
}

/// insphere's stage A value in floating point: insphere_formula on the rows relative to e.
inline double insphere_stage_a_det_scalar(const double* a, const double* b, const double* c, const double* d,
                                          const double* e) {
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    const double x[12] = {a[0] - e[0], a[1] - e[1], a[2] - e[2], b[0] - e[0], b[1] - e[1], b[2] - e[2],
                          c[0] - e[0], c[1] - e[1], c[2] - e[2], d[0] - e[0], d[1] - e[1], d[2] - e[2]};
    return insphere_formula(x);
}

#if defined(__SSE2__)
/// The same value two lanes at a time (SSE2, part of every x86-64): every lane performs, in the
/// same order, exactly the roundings of insphere_formula (a - b is a + (-b) in IEEE arithmetic,
/// and (-b) c = -(b c) exactly), so the result is the scalar one bit for bit; only the number of
/// instructions changes (the 3D insertion runs this about 50 times a point).
inline double insphere_stage_a_det_packed(const double* a, const double* b, const double* c, const double* d,
                                          const double* e) {
    const __m128d exy = _mm_loadu_pd(e), ez = _mm_set1_pd(e[2]);
    const __m128d axy = _mm_sub_pd(_mm_loadu_pd(a), exy), bxy = _mm_sub_pd(_mm_loadu_pd(b), exy);
    const __m128d cxy = _mm_sub_pd(_mm_loadu_pd(c), exy), dxy = _mm_sub_pd(_mm_loadu_pd(d), exy);
    const __m128d z_ab = _mm_sub_pd(_mm_loadh_pd(_mm_load_sd(a + 2), b + 2), ez);  // (aez, bez)
    const __m128d z_cd = _mm_sub_pd(_mm_loadh_pd(_mm_load_sd(c + 2), d + 2), ez);  // (cez, dez)
    const __m128d x_ab = _mm_unpacklo_pd(axy, bxy), y_ab = _mm_unpackhi_pd(axy, bxy);
    const __m128d x_cd = _mm_unpacklo_pd(cxy, dxy), y_cd = _mm_unpackhi_pd(cxy, dxy);
    const __m128d x_ac = _mm_unpacklo_pd(x_ab, x_cd), x_bd = _mm_unpackhi_pd(x_ab, x_cd);
    const __m128d y_ac = _mm_unpacklo_pd(y_ab, y_cd), y_bd = _mm_unpackhi_pd(y_ab, y_cd);
    auto swap = [](__m128d v) { return _mm_shuffle_pd(v, v, 1); };
    // The six 2x2 minors in pairs: (ab, cd), (bc, da), (ac, bd).
    const __m128d ab_cd = _mm_sub_pd(_mm_mul_pd(x_ac, y_bd), _mm_mul_pd(x_bd, y_ac));
    const __m128d bc_da = _mm_sub_pd(_mm_mul_pd(x_bd, swap(y_ac)), _mm_mul_pd(swap(x_ac), y_bd));
    const __m128d ac_bd = _mm_sub_pd(_mm_mul_pd(x_ab, y_cd), _mm_mul_pd(x_cd, y_ab));
    const __m128d ac_ac = _mm_unpacklo_pd(ac_bd, ac_bd), bd_bd = _mm_unpackhi_pd(ac_bd, ac_bd);
    const __m128d negate_low = _mm_set_pd(0.0, -0.0);
    const __m128d z_ac = _mm_unpacklo_pd(z_ab, z_cd), z_bd = _mm_unpackhi_pd(z_ab, z_cd);
    // (abc, cda) = ((aez bc - bez ac) + cez ab, (cez da + dez ac) + aez cd).
    const __m128d abc_cda = _mm_add_pd(
        _mm_add_pd(_mm_mul_pd(z_ac, bc_da), _mm_mul_pd(_mm_xor_pd(z_bd, negate_low), ac_ac)),
        _mm_mul_pd(swap(z_ac), ab_cd));
    // (bcd, dab) = ((bez cd - cez bd) + dez bc, (dez ab + aez bd) + bez da).
    const __m128d bcd_dab = _mm_add_pd(
        _mm_add_pd(_mm_mul_pd(z_bd, swap(ab_cd)), _mm_mul_pd(_mm_xor_pd(swap(z_ac), negate_low), bd_bd)),
        _mm_mul_pd(swap(z_bd), bc_da));
    const __m128d lift_ab =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(x_ab, x_ab), _mm_mul_pd(y_ab, y_ab)), _mm_mul_pd(z_ab, z_ab));
    const __m128d lift_cd =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(x_cd, x_cd), _mm_mul_pd(y_cd, y_cd)), _mm_mul_pd(z_cd, z_cd));
    // (alift bcd - blift cda, clift dab - dlift abc), then the two added.
    const __m128d halves = _mm_sub_pd(_mm_mul_pd(_mm_unpacklo_pd(lift_ab, lift_cd), bcd_dab),
                                      _mm_mul_pd(_mm_unpackhi_pd(lift_ab, lift_cd), swap(abc_cda)));
    return _mm_cvtsd_f64(_mm_add_sd(halves, _mm_unpackhi_pd(halves, halves)));
}
#endif

/// insphere's stage A value (the packed evaluation where there is one: the same bits).
inline double insphere_stage_a_det(const double* a, const double* b, const double* c, const double* d,
                                   const double* e) {
#if defined(__SSE2__)
    return insphere_stage_a_det_packed(a, b, c, d, e);
#else
    return insphere_stage_a_det_scalar(a, b, c, d, e);
#endif
}

/// insphere's stage A: the value above and its permanent (the determinant's terms in absolute
/// value, as computed; the bound on the value's rounding error is kInsphereFilterBound times it).
struct InsphereStageA {
    double det;
    double permanent;
};
inline InsphereStageA insphere_stage_a(const double* a, const double* b, const double* c, const double* d,
                                       const double* e) {
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    const double aex = a[0] - e[0], aey = a[1] - e[1], aez = a[2] - e[2];
    const double bex = b[0] - e[0], bey = b[1] - e[1], bez = b[2] - e[2];
    const double cex = c[0] - e[0], cey = c[1] - e[1], cez = c[2] - e[2];
    const double dex = d[0] - e[0], dey = d[1] - e[1], dez = d[2] - e[2];
    auto mag = [](double x) { return std::fabs(x); };
    auto pair = [&](double p, double q, double r, double t) { return mag(p * q) + mag(r * t); };
    const double abp = pair(aex, bey, bex, aey), bcp = pair(bex, cey, cex, bey), cdp = pair(cex, dey, dex, cey);
    const double dap = pair(dex, aey, aex, dey), acp = pair(aex, cey, cex, aey), bdp = pair(bex, dey, dex, bey);
    const double az = mag(aez), bz = mag(bez), cz = mag(cez), dz = mag(dez);
    const double alift = aex * aex + aey * aey + aez * aez;
    const double blift = bex * bex + bey * bey + bez * bez;
    const double clift = cex * cex + cey * cey + cez * cez;
    const double dlift = dex * dex + dey * dey + dez * dez;
    const double permanent = ((cdp * bz + bdp * cz + bcp * dz) * alift + (dap * cz + acp * dz + cdp * az) * blift) +
                             ((abp * dz + bdp * az + dap * bz) * clift + (bcp * az + acp * bz + abp * cz) * dlift);
    return {insphere_stage_a_det(a, b, c, d, e), permanent};
}

/// With every coordinate difference of the points (as computed) at most `span`: each lift is
/// below 3 span^2 and each row's minor permanent below 6 span^3, so the permanent is below
/// 72 span^5 (1 + 2^-47); the factor 1 + 2^-40 covers that and the bound's own rounding.
inline double insphere_static_bound(double span) {
    const double s2 = span * span;
    return kInsphereFilterBound * 72.0 * (s2 * s2 * span) * (1.0 + 0x1p-40);
}
/// The same bound from the rows' own differences from e: with the x differences at most mx, the y
/// at most my, the z at most mz (as computed; M the largest of the three), each lift is below
/// 3 M^2 and each row's minor permanent below 6 mx my mz (each of its terms has one x, one y and
/// one z difference), so the permanent is below 72 M^2 mx my mz (1 + 2^-47). Much tighter than
/// the static bound where the five points are close together compared with the whole set
/// (clusters); a product that underflows is not possible in insphere's range.
inline double insphere_local_bound(const double* a, const double* b, const double* c, const double* d,
                                   const double* e) {
    double m[3];
    for (int k = 0; k < 3; ++k) {
        m[k] = std::max(std::max(std::fabs(a[k] - e[k]), std::fabs(b[k] - e[k])),
                        std::max(std::fabs(c[k] - e[k]), std::fabs(d[k] - e[k])));
    }
    const double largest = std::max(std::max(m[0], m[1]), m[2]);
    return kInsphereFilterBound * 72.0 * ((largest * largest) * (m[0] * m[1] * m[2])) * (1.0 + 0x1p-40);
}
/// insphere with the semi-static bound first (exact sign always).
inline int insphere_semi_static(double bound, const double* a, const double* b, const double* c, const double* d,
                                const double* e) {
    const double det = insphere_stage_a_det(a, b, c, d, e);
    if (det > bound) return 1;
    if (-det > bound) return -1;
    return insphere(a, b, c, d, e);
}

/// incircle with stage A inline.
inline int incircle_inline(double ax, double ay, double bx, double by, double cx, double cy,
                           double dx, double dy) {
    const IncircleStageA a = incircle_stage_a(ax, ay, bx, by, cx, cy, dx, dy);
    const double errbound = kIncircleFilterBound * a.permanent;
    if (a.det > errbound) return 1;
    if (-a.det > errbound) return -1;
    return incircle_adapt_entry(ax, ay, bx, by, cx, cy, dx, dy, a.permanent);
}

}  // namespace detail

}  // namespace hullkit
