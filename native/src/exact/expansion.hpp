// hullkit: the exact arithmetic shared by the predicates (predicates.cpp: orient2d and orient3d;
// incircle.cpp: incircle and compare_distance): the error-free transformations and Shewchuk's
// expansion arithmetic, defined here so that every file compiles them into its own code (no calls
// across files on the exact paths).
//
// Terminology (Shewchuk 1997): an *expansion* is a sum of doubles e[0] + e[1] + ... + e[n-1], stored
// in order of increasing magnitude, whose components do not overlap (the lowest set bit of each is
// above the highest set bit of the previous one). Its value is exact, its sign is the sign of its
// largest component. Here expansions are kept free of zero components; length 0 means the value 0.
#pragma once

#include <cfloat>
#include <cmath>

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

namespace hullkit::exact_detail {

// ---------------------------------------------------------------------------------------------
// Constants

/// Unit roundoff of binary64: |fl(x op y) - (x op y)| <= kEpsilon * |x op y| without underflow.
constexpr double kEpsilon = 0x1p-53;
/// Veltkamp's splitter 2^ceil(53/2) + 1: splits a double into two halves of at most 26 bits each.
constexpr double kSplitter = 0x1p27 + 1.0;

/// Shewchuk's bound on the relative error of a stage C estimate, shared by every predicate; their
/// other error bounds are with them (see predicates.cpp for how they are derived).
constexpr double kResultErrBound = (3.0 + 8.0 * kEpsilon) * kEpsilon;

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
//
// The larger routines (expansion_sum, scale_expansion, multiply_short, exact_minor) are `static`,
// not `inline`: each file gets its own private copy, and the compiler inlines them, or calls them
// locally, just as when all the predicates were one file. Declared `inline` they would be inlined
// into every stage (much larger code, and -Wmaybe-uninitialized false positives).

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
static int expansion_sum(int elen, const double* e, int flen, const double* f, double* h) {
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
static int scale_expansion(int elen, const double* e, double b, double* h) {
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
static int multiply_short(int elen, const double* e, int flen, const double* f, double* h) {
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
static int exact_minor(int plen, const double* p, int qlen, const double* q, int rlen, const double* r,
                       int slen, const double* s, double* h) {
    double pq[8];
    double rs[8];
    const int pq_len = multiply_short(plen, p, qlen, q, pq);
    const int rs_len = multiply_short(rlen, r, slen, s, rs);
    for (int i = 0; i < rs_len; ++i) rs[i] = -rs[i];
    return expansion_sum(pq_len, pq, rs_len, rs, h);
}

}  // namespace hullkit::exact_detail
