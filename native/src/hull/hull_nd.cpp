// Exact hulls and Delaunay triangulations in D dimensions: see hullkit/hull_nd.hpp.
//
// The predicate. Every decision is the sign of an n x n determinant (n <= 11) whose rows are points
// and whose columns are some of: the coordinates, the lifted coordinate |x|^2 and a column of ones.
// It is expanded by minors along the rows, all column subsets at once (f(S) for each subset S of the
// columns: the determinant of the last |S| rows on the columns S), n 2^(n-1) products. In floating
// point the same recursion on the absolute values bounds the rounding error (each level adds at
// most n roundings relative to that permanent, about n^2/2 eps over the n levels; the lifted column,
// rounded itself, adds at most (d + 1) eps of the permanent since the determinant is linear in it);
// the bound used is twice that plus an absolute 2^-960 for underflow in products of numbers below 1
// (the floating copy of the points is scaled by a power of two below 1). When the bound cannot tell,
// the same recursion runs on numbers with an exponent of their own (Wide: no underflow, the same
// relative bound), and when that cannot tell either, on big integers: each coordinate is m 2^e exactly, each column scaled by
// a power of two that makes it integral (a positive factor per column: the sign is unchanged).
//
// Each facet keeps its minors (the expansion's last step without the query row) and their
// permanents, so that a side test costs D + 1 products; the lifted hull's facets give the
// projected orientation (lower or upper facet) and the cospherical test from the same minors.
#include "hullkit/hull_nd.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace hullkit {
namespace {

constexpr int kMaxRows = kMaxHullNdDimension + 1;

/// Bits set in each mask of up to kMaxRows bits (a table: no popcount instruction is assumed).
struct BitCounts {
    std::array<std::uint8_t, 1u << kMaxRows> count{};
    BitCounts() {
        for (std::uint32_t m = 1; m < count.size(); ++m) count[m] = static_cast<std::uint8_t>(count[m >> 1] + (m & 1));
    }
};
const BitCounts kBits;
inline int bits(std::uint32_t mask) { return kBits.count[mask]; }

// ---- big integers (sign and magnitude, 32-bit limbs, little-endian, no leading zero limb) ----
struct Big {
    std::vector<std::uint32_t> limb;
    bool negative = false;
    bool zero() const { return limb.empty(); }
};

void trim(Big& a) {
    while (!a.limb.empty() && a.limb.back() == 0) a.limb.pop_back();
    if (a.limb.empty()) a.negative = false;
}

int compare_magnitude(const Big& a, const Big& b) {
    if (a.limb.size() != b.limb.size()) return a.limb.size() < b.limb.size() ? -1 : 1;
    for (std::size_t i = a.limb.size(); i-- > 0;)
        if (a.limb[i] != b.limb[i]) return a.limb[i] < b.limb[i] ? -1 : 1;
    return 0;
}

/// acc += (negate ? -t : t)
void accumulate(Big& acc, const Big& t, bool negate) {
    if (t.zero()) return;
    const bool t_negative = t.negative != negate;
    if (acc.zero()) {
        acc.limb = t.limb;
        acc.negative = t_negative;
        return;
    }
    if (acc.negative == t_negative) {
        if (acc.limb.size() < t.limb.size()) acc.limb.resize(t.limb.size(), 0);
        std::uint64_t carry = 0;
        for (std::size_t i = 0; i < acc.limb.size(); ++i) {
            const std::uint64_t s = std::uint64_t{acc.limb[i]} + (i < t.limb.size() ? t.limb[i] : 0) + carry;
            acc.limb[i] = static_cast<std::uint32_t>(s);
            carry = s >> 32;
        }
        if (carry) acc.limb.push_back(static_cast<std::uint32_t>(carry));
        return;
    }
    // Opposite signs: subtract the smaller magnitude from the larger.
    const int c = compare_magnitude(acc, t);
    if (c == 0) {
        acc.limb.clear();
        acc.negative = false;
        return;
    }
    // In place: each limb of acc is read before it is written.
    const bool acc_larger = c > 0;
    const std::size_t size = acc_larger ? acc.limb.size() : t.limb.size();
    acc.limb.resize(size, 0);
    std::int64_t borrow = 0;
    for (std::size_t i = 0; i < size; ++i) {
        const std::int64_t x = acc.limb[i];
        const std::int64_t y = i < t.limb.size() ? t.limb[i] : 0;
        std::int64_t d = (acc_larger ? x - y : y - x) - borrow;
        borrow = d < 0;
        if (d < 0) d += std::int64_t{1} << 32;
        acc.limb[i] = static_cast<std::uint32_t>(d);
    }
    acc.negative = acc_larger ? acc.negative : t_negative;
    trim(acc);
}

/// out = a b (out's storage reused).
void multiply_into(Big& out, const Big& a, const Big& b) {
    out.limb.clear();
    out.negative = false;
    if (a.zero() || b.zero()) return;
    out.limb.assign(a.limb.size() + b.limb.size(), 0);
    for (std::size_t i = 0; i < a.limb.size(); ++i) {
        if (a.limb[i] == 0) continue;  // entries are a 53-bit integer shifted: mostly zero limbs
        std::uint64_t carry = 0;
        for (std::size_t j = 0; j < b.limb.size(); ++j) {
            const std::uint64_t t = std::uint64_t{a.limb[i]} * b.limb[j] + out.limb[i + j] + carry;
            out.limb[i + j] = static_cast<std::uint32_t>(t);
            carry = t >> 32;
        }
        out.limb[i + b.limb.size()] = static_cast<std::uint32_t>(carry);
    }
    out.negative = a.negative != b.negative;
    trim(out);
}

Big multiply(const Big& a, const Big& b) {
    Big out;
    multiply_into(out, a, b);
    return out;
}

/// |m| 2^shift with sign, m below 2^53.
Big big_of(std::int64_t m, int shift) {
    Big out;
    if (m == 0) return out;
    out.negative = m < 0;
    std::uint64_t u = static_cast<std::uint64_t>(m < 0 ? -m : m);
    out.limb.assign(static_cast<std::size_t>(shift / 32) + 3, 0);
    const int bit = shift % 32;
    std::size_t at = static_cast<std::size_t>(shift / 32);
    // u << bit spans up to three limbs (53 + 31 bits).
    const std::uint64_t rest = bit ? u >> (32 - bit) : u >> 32;
    out.limb[at] = static_cast<std::uint32_t>(u << bit);
    out.limb[at + 1] = static_cast<std::uint32_t>(rest);
    out.limb[at + 2] = static_cast<std::uint32_t>(rest >> 32);
    trim(out);
    return out;
}

/// x = m 2^e with an integer m of at most 53 bits (x finite, nonzero).
void split_double(double x, std::int64_t* m, int* e) {
    int k = 0;
    const double f = std::frexp(x, &k);  // x = f 2^k, 0.5 <= |f| < 1
    *m = static_cast<std::int64_t>(std::ldexp(f, 53));
    *e = k - 53;
}

/// The exact sign of the n x n determinant of `a` (row-major, n <= kMaxRows), by minors.
int exact_sign(const std::vector<std::vector<Big>>& a, int n) {
    // Scratch kept between calls (per thread): the big numbers' storage is reused.
    thread_local std::vector<Big> f;
    thread_local Big product;
    if (f.size() < (std::size_t{1} << n)) f.resize(std::size_t{1} << n);
    f[0].limb.assign(1, 1);
    f[0].negative = false;
    for (std::uint32_t mask = 1; mask < (1u << n); ++mask) {
        const int row = n - bits(mask);
        Big& acc = f[mask];
        acc.limb.clear();
        acc.negative = false;
        int position = 0;
        for (int j = 0; j < n; ++j) {
            if (!(mask >> j & 1)) continue;
            const Big& minor = f[mask ^ (1u << j)];
            if (!minor.zero() && !a[row][j].zero()) {
                multiply_into(product, a[row][j], minor);
                accumulate(acc, product, position & 1);
            }
            ++position;
        }
    }
    const Big& det = f[(1u << n) - 1];
    return det.zero() ? 0 : det.negative ? -1 : 1;
}

/// A double with an exponent of its own (m 2^e, 0.5 <= |m| < 1 or m = 0): floating point without
/// underflow or overflow, so that the relative error bound of the expansion by minors holds for
/// coordinates of any magnitude (the second stage, between the doubles and the big integers).
struct Wide {
    double m = 0;
    long e = 0;
};
inline Wide wide_of(double m, long e) {
    if (m == 0) return {};
    int k = 0;
    const double f = std::frexp(m, &k);
    return {f, e + k};
}
inline Wide wide_mul(const Wide& a, const Wide& b) { return wide_of(a.m * b.m, a.e + b.e); }
inline Wide wide_add(Wide a, Wide b) {
    if (a.m == 0) return b;
    if (b.m == 0) return a;
    if (a.e < b.e) std::swap(a, b);
    const long shift = b.e - a.e;
    if (shift < -1100) return a;  // below 2^-1099 of a: far under its rounding
    return wide_of(a.m + std::ldexp(b.m, static_cast<int>(shift)), a.e);
}
inline Wide operator*(const Wide& a, const Wide& b) { return wide_mul(a, b); }
inline Wide operator+(const Wide& a, const Wide& b) { return wide_add(a, b); }
inline Wide operator-(Wide a) {
    a.m = -a.m;
    return a;
}
inline Wide magnitude(Wide a) {
    a.m = std::fabs(a.m);
    return a;
}
inline double magnitude(double a) { return std::fabs(a); }
/// |a| > |b|
inline bool wide_greater(const Wide& a, const Wide& b) {
    if (a.m == 0) return false;
    if (b.m == 0) return true;
    if (a.e != b.e) return a.e > b.e;
    return std::fabs(a.m) > std::fabs(b.m);
}

/// The expansion by minors in floating point (double, or Wide): for every column subset `mask`
/// below `end`, f[mask] the determinant of the last |mask| rows of `a` on those columns and
/// g[mask] its permanent (the same products in absolute value, which bound the rounding of f).
template <typename T>
void expand_minors(const T (*a)[kMaxRows], int n, std::uint32_t end, T one, T* f, T* g) {
    f[0] = g[0] = one;
    for (std::uint32_t mask = 1; mask < end; ++mask) {
        const int row = n - bits(mask);
        T sum{}, bound{};
        int position = 0;
        for (int j = 0; j < n; ++j) {
            if (!(mask >> j & 1)) continue;
            const std::uint32_t minor = mask ^ (1u << j);
            const T t = a[row][j] * f[minor];
            sum = sum + ((position & 1) ? -t : t);
            bound = bound + magnitude(a[row][j]) * g[minor];
            ++position;
        }
        f[mask] = sum;
        g[mask] = bound;
    }
}

/// The determinant of the n x n matrix `a` (row-major) in floating point, by Gaussian elimination
/// with partial pivoting (`a` is overwritten): a measurement or an order, never a decision.
double float_det(double* a, int n) {
    double det = 1;
    for (int c = 0; c < n; ++c) {
        int best = c;
        for (int r = c + 1; r < n; ++r)
            if (std::fabs(a[r * n + c]) > std::fabs(a[best * n + c])) best = r;
        if (a[best * n + c] == 0) return 0;
        if (best != c) {
            for (int k = 0; k < n; ++k) std::swap(a[best * n + k], a[c * n + k]);
            det = -det;
        }
        det *= a[c * n + c];
        for (int r = c + 1; r < n; ++r) {
            const double factor = a[r * n + c] / a[c * n + c];
            for (int k = c; k < n; ++k) a[r * n + k] -= factor * a[c * n + k];
        }
    }
    return det;
}

/// The bound on the rounding error of an n x n expansion by minors whose permanent is `permanent`
/// (with a rounded lift column of d squares when `lifted`): see the top of this file.
inline double rounding_factor(int n, bool lifted, int d) {
    return (2.0 * n * n + (lifted ? 2.0 * (d + 2) : 0.0)) * 0x1p-53 * (1.0 + 0x1p-20);
}
inline double rounding_bound(int n, bool lifted, int d, double permanent) {
    return rounding_factor(n, lifted, d) * permanent + 0x1p-960;  // + products below 1 underflowing
}

/// The columns a row may have: coordinate j (0 .. d - 1), the lift, or the ones.
constexpr int kLiftColumn = -1;
constexpr int kOnesColumn = -2;

/// Signs of determinants of points of one set (and queries, given as rows of raw coordinates).
class Predicate {
public:
    /// `infinity` (+1 or -1, 0 for none): the point index `count` is the point at infinity in the
    /// direction of (0, ..., 0, infinity) in the lifted space (row: zero coordinates, lift
    /// `infinity`, a zero in the ones column), so that lifted points that span one dimension less
    /// (all on one sphere) still have a full-dimensional hull, whose lower (upper) facets are
    /// unchanged.
    Predicate(const double* points, std::size_t count, int d, int infinity = 0)
        : raw_(points), count_(count), d_(d), infinity_(infinity) {
        // One power of two for the floating copy, so that every coordinate is below 1 in magnitude.
        double largest = 0;
        for (std::size_t i = 0; i < count * static_cast<std::size_t>(d); ++i)
            largest = std::max(largest, std::fabs(points[i]));
        int k = 0;
        if (largest > 0) std::frexp(largest, &k);
        shift_ = -k;  // largest * 2^shift in [0.5, 1)
        scaled_.assign((count + 1) * static_cast<std::size_t>(d), 0.0);
        lift_.assign(count + 1, static_cast<double>(infinity));
        exact_copy_.assign(count + 1, 1);
        for (std::size_t i = 0; i < count; ++i) {
            double lift = 0;
            for (int j = 0; j < d; ++j) {
                const double x = points[i * static_cast<std::size_t>(d) + static_cast<std::size_t>(j)];
                const double s = std::ldexp(x, shift_);
                if (std::ldexp(s, -shift_) != x) exact_copy_[i] = 0;  // underflowed: exact arithmetic only
                scaled_[i * static_cast<std::size_t>(d) + static_cast<std::size_t>(j)] = s;
                lift += s * s;
            }
            lift_[i] = lift;
        }
    }

    std::size_t count() const { return count_; }
    /// The index of the point at infinity (count()), when there is one.
    std::uint32_t infinity() const { return static_cast<std::uint32_t>(count_); }
    int infinity_sign() const { return infinity_; }
    int dimension() const { return d_; }
    double scaled(std::uint32_t i, int j) const { return scaled_[i * static_cast<std::size_t>(d_) + static_cast<std::size_t>(j)]; }
    double lift(std::uint32_t i) const { return lift_[i]; }
    /// Asks the caches for what a side test of point i reads (its scaled row, lift and flag).
    void prefetch(std::uint32_t i) const {
#if defined(__GNUC__) || defined(__clang__)
        const double* row = scaled_.data() + i * static_cast<std::size_t>(d_);
        __builtin_prefetch(row);
        __builtin_prefetch(row + d_ - 1);
        __builtin_prefetch(lift_.data() + i);
        __builtin_prefetch(exact_copy_.data() + i);
#else
        (void)i;
#endif
    }

    /// The row of point i (i < count) or of the query row `query` (i == kQuery).
    static constexpr std::uint32_t kQuery = 0xffffffffu;

    /// The floating (scaled) value of row r (a point, the point at infinity or the query) in
    /// column `col` (a coordinate, kLiftColumn or kOnesColumn).
    double entry(std::uint32_t r, int col) const {
        if (r == kQuery) return col >= 0 ? query_scaled_[static_cast<std::size_t>(col)] : col == kLiftColumn ? query_lift_ : 1.0;
        if (col >= 0) return scaled(r, col);
        return col == kLiftColumn ? lift_[r] : (r == count_ ? 0.0 : 1.0);
    }

    /// The columns of an orientation: the coordinates, the lift when `lifted`, the ones; their count.
    int orientation_columns(bool lifted, int* columns) const {
        for (int c = 0; c < d_; ++c) columns[c] = c;
        if (lifted) columns[d_] = kLiftColumn;
        columns[d_ + (lifted ? 1 : 0)] = kOnesColumn;
        return d_ + (lifted ? 2 : 1);
    }
    void set_query(const double* q) {
        query_raw_ = q;
        query_exact_copy_ = true;
        double lift = 0;
        for (int j = 0; j < d_; ++j) {
            const double s = std::ldexp(q[j], shift_);
            if (std::ldexp(s, -shift_) != q[j] || !std::isfinite(s) || std::fabs(s) > 0x1p100) query_exact_copy_ = false;
            query_scaled_[static_cast<std::size_t>(j)] = s;
            lift += s * s;
        }
        query_lift_ = lift;
    }

    /// The sign of det(rows x columns), n rows; `value` (when given) the floating-point estimate.
    int sign(const std::uint32_t* rows, int n, const int* columns, double* value = nullptr) const {
        double a[kMaxRows][kMaxRows];
        bool filter = true;
        const bool lifted = std::find(columns, columns + n, kLiftColumn) != columns + n;
        for (int r = 0; r < n; ++r) {
            if (rows[r] == kQuery ? !query_exact_copy_ : !exact_copy_[rows[r]]) filter = false;
            for (int c = 0; c < n; ++c) a[r][c] = entry(rows[r], columns[c]);
        }
        if (filter) {
            double f[1 << kMaxRows], g[1 << kMaxRows];
            const std::uint32_t all = (1u << n) - 1;
            expand_minors(a, n, all + 1, 1.0, f, g);
            const double error = rounding_bound(n, lifted, d_, g[all]);
            if (value) *value = f[all];
            if (std::isfinite(f[all]) && std::isfinite(error)) {
                if (f[all] > error) return 1;
                if (-f[all] > error) return -1;
            }
        } else if (value) {
            *value = 0;
        }
        return decide(rows, n, columns);
    }

    /// The sign where the doubles could not tell: the Wide stage, then the big integers.
    int decide(const std::uint32_t* rows, int n, const int* columns) const {
        const int wide = wide_sign(rows, n, columns);
        return wide != 2 ? wide : exact(rows, n, columns);
    }

private:
    /// The expansion by minors with Wide numbers on the unscaled coordinates, and its error bound
    /// (the doubles' without the allowance for underflow); 2 when it cannot tell.
    int wide_sign(const std::uint32_t* rows, int n, const int* columns) const {
        const bool lifted = std::find(columns, columns + n, kLiftColumn) != columns + n;
        Wide a[kMaxRows][kMaxRows];
        for (int r = 0; r < n; ++r) {
            if (rows[r] == count_) {
                for (int c = 0; c < n; ++c) a[r][c] = columns[c] == kLiftColumn ? wide_of(infinity_, 0) : Wide{};
                continue;
            }
            const double* x = row_raw(rows[r]);
            for (int c = 0; c < n; ++c) {
                const int col = columns[c];
                if (col >= 0) {
                    a[r][c] = wide_of(x[col], 0);
                } else if (col == kOnesColumn) {
                    a[r][c] = wide_of(1.0, 0);
                } else {
                    Wide lift;
                    for (int j = 0; j < d_; ++j) {
                        const Wide v = wide_of(x[j], 0);
                        lift = wide_add(lift, wide_mul(v, v));
                    }
                    a[r][c] = lift;
                }
            }
        }
        std::vector<Wide> f(std::size_t{1} << n), g(std::size_t{1} << n);
        const std::uint32_t all = (1u << n) - 1;
        expand_minors(a, n, all + 1, wide_of(1.0, 0), f.data(), g.data());
        const Wide error = wide_mul(g[all], wide_of(rounding_factor(n, lifted, d_), 0));
        if (wide_greater(f[all], error)) return f[all].m > 0 ? 1 : -1;
        return 2;
    }

public:
    /// The sign of det [[p_r, 1] for each of the d + 1 rows] in the points' own d dimensions, or
    /// with `lifted` of the d + 2 rows [p, |p|^2, 1].
    int orient(const std::uint32_t* rows, double* value = nullptr, bool lifted = false) const {
        int columns[kMaxRows];
        const int n = orientation_columns(lifted, columns);
        return sign(rows, n, columns, value);
    }

    /// The floating row of point i in the columns of an orientation (coordinates, lift if
    /// `lifted`, ones): n = d + 1 or d + 2 values.
    void row_values(std::uint32_t i, bool lifted, double* out) const {
        int columns[kMaxRows];
        const int n = orientation_columns(lifted, columns);
        for (int c = 0; c < n; ++c) out[c] = entry(i, columns[c]);
    }
    bool exact_copy(std::uint32_t i) const { return exact_copy_[i] != 0; }

    /// A facet's floating hyperplane: with the facet's D corners as the last D rows of an n x n
    /// determinant (n = D + 1, all columns), the minors f_j of the corners without column j and
    /// their permanents g_j, as the expansion by minors computes them (so that a query row q in
    /// front gives the same floating value and bound as sign() would: see side_of_plane).
    void facet_plane(const std::uint32_t* corners, bool lifted, double* f_out, double* g_out) const {
        const int n = d_ + (lifted ? 2 : 1);
        double a[kMaxRows][kMaxRows];
        for (int r = 1; r < n; ++r) row_values(corners[r - 1], lifted, a[r]);
        double f[1 << kMaxRows], g[1 << kMaxRows];
        const std::uint32_t all = (1u << n) - 1;
        expand_minors(a, n, all, 1.0, f, g);  // every subset but all: they use rows 1 .. n - 1 only
        for (int j = 0; j < n; ++j) {
            f_out[j] = f[all ^ (1u << j)];
            g_out[j] = g[all ^ (1u << j)];
        }
    }

    /// The sign of det[[q], [corners...]] from the facet's plane (facet_plane), or 2 when the
    /// floating value cannot tell; `value` gets the estimate.
    int side_of_plane(const double* f, const double* g, const double* q, bool lifted, double* value) const {
        const int n = d_ + (lifted ? 2 : 1);
        double sum = 0, bound = 0;
        for (int j = 0; j < n; ++j) {
            const double t = q[j] * f[j];
            sum += (j & 1) ? -t : t;
            bound += std::fabs(q[j]) * g[j];
        }
        if (value) *value = sum;
        const double error = rounding_bound(n, lifted, d_, bound);
        if (!std::isfinite(sum) || !std::isfinite(error)) return 2;
        if (sum > error) return 1;
        if (-sum > error) return -1;
        return 2;
    }

private:
    const double* row_raw(std::uint32_t r) const {
        return r == kQuery ? query_raw_ : raw_ + r * static_cast<std::size_t>(d_);
    }

    /// The sign by big integers.
    int exact(const std::uint32_t* rows, int n, const int* columns) const {
        // Each coordinate column scaled by its own power of two; the lift and its coordinates by
        // one shared power (the lift is their sum of squares).
        const bool lifted = std::find(columns, columns + n, kLiftColumn) != columns + n;
        int lowest[kMaxRows];
        int shared = 0;
        bool any = false;
        for (int c = 0; c < n; ++c) {
            lowest[c] = 0;
            bool seen = false;
            if (columns[c] < 0) continue;
            for (int r = 0; r < n; ++r) {
                if (rows[r] == count_) continue;
                const double x = row_raw(rows[r])[columns[c]];
                if (x == 0) continue;
                std::int64_t m;
                int e;
                split_double(x, &m, &e);
                if (!seen || e < lowest[c]) lowest[c] = e;
                seen = true;
            }
        }
        if (lifted) {
            for (int r = 0; r < n; ++r)
                for (int j = 0; j < d_ && rows[r] != count_; ++j) {
                    const double x = row_raw(rows[r])[j];
                    if (x == 0) continue;
                    std::int64_t m;
                    int e;
                    split_double(x, &m, &e);
                    if (!any || e < shared) shared = e;
                    any = true;
                }
        }
        // The matrix's storage kept between calls (per thread); every cell is set below.
        thread_local std::vector<std::vector<Big>> a;
        if (a.size() < static_cast<std::size_t>(n)) a.resize(static_cast<std::size_t>(n));
        for (auto& r : a) {
            if (r.size() < static_cast<std::size_t>(n)) r.resize(static_cast<std::size_t>(n));
            for (Big& cell : r) {
                cell.limb.clear();
                cell.negative = false;
            }
        }
        for (int r = 0; r < n; ++r) {
            if (rows[r] == count_) {  // the point at infinity: only its lift, +-1
                for (int c = 0; c < n; ++c)
                    if (columns[c] == kLiftColumn) {
                        a[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)].limb = {1};
                        a[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)].negative = infinity_ < 0;
                    }
                continue;
            }
            const double* x = row_raw(rows[r]);
            for (int c = 0; c < n; ++c) {
                Big& cell = a[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
                if (columns[c] == kOnesColumn) {
                    cell.limb = {1};
                } else if (columns[c] >= 0) {
                    const double v = x[columns[c]];
                    if (v != 0) {
                        std::int64_t m;
                        int e;
                        split_double(v, &m, &e);
                        cell = big_of(m, e - lowest[c]);
                    }
                } else {
                    for (int j = 0; j < d_; ++j) {
                        if (x[j] == 0) continue;
                        std::int64_t m;
                        int e;
                        split_double(x[j], &m, &e);
                        const Big v = big_of(m, e - shared);
                        accumulate(cell, multiply(v, v), false);
                    }
                }
            }
        }
        return exact_sign(a, n);
    }

    const double* raw_;
    std::size_t count_;
    int d_;
    int infinity_ = 0;
    int shift_ = 0;
    std::vector<double> scaled_, lift_;
    std::vector<char> exact_copy_;  ///< per point: the scaled copy is exact (no underflow)
    const double* query_raw_ = nullptr;
    std::array<double, kMaxRows> query_scaled_{};
    double query_lift_ = 0;
    bool query_exact_copy_ = false;
};


/// Quickhull over the points `ids` of a Predicate, in its d dimensions or (lifted) d + 1.
class Quickhull {
public:
    Quickhull(const Predicate& predicate, bool lifted)
        : p_(predicate), lifted_(lifted), D_(predicate.dimension() + (lifted ? 1 : 0)) {}

    /// Builds the hull of `ids`; false (with `spanned` set) when they lie in a flat of lower
    /// dimension, or more precisely when no D + 1 of them are affinely independent.
    bool build(const std::vector<std::uint32_t>& ids, int* spanned) {
        std::vector<std::uint32_t> simplex;
        if (!initial_simplex(ids, &simplex, spanned)) return false;
        const int D = D_;
        for (int k = 0; k <= D; ++k) {
            std::uint32_t corners[kMaxRows];
            for (int i = 0, n = 0; i <= D; ++i)
                if (i != k) corners[n++] = simplex[static_cast<std::size_t>(i)];
            if (side(corners, simplex[static_cast<std::size_t>(k)]) > 0) std::swap(corners[0], corners[1]);
            add_facet(corners);
        }
        for (int k = 0; k <= D; ++k)
            for (int j = 0; j < D; ++j) {
                const std::uint32_t corner = corner_of(static_cast<std::uint32_t>(k), j);
                const auto m = std::find(simplex.begin(), simplex.end(), corner) - simplex.begin();
                neighbor_[static_cast<std::size_t>(k * D + j)] = static_cast<std::int32_t>(m);
            }
        std::vector<char> used(p_.count() + 1, 0);
        for (const std::uint32_t s : simplex) used[s] = 1;
        std::vector<std::uint32_t> all_facets(static_cast<std::size_t>(D) + 1);
        std::iota(all_facets.begin(), all_facets.end(), 0u);
        for (const std::uint32_t q : ids)
            if (!used[q]) assign(q, all_facets);
        std::vector<std::uint32_t> pending(all_facets.rbegin(), all_facets.rend());
        while (!pending.empty()) {
            const std::uint32_t f = pending.back();
            pending.pop_back();
            if (!alive_[f] || outside_[f].empty()) continue;
            add_point(f, &pending);
        }
        return true;
    }

    /// The ids of the live facets, in the order result() lists them.
    std::vector<std::uint32_t> live() const {
        std::vector<std::uint32_t> ids;
        for (std::size_t f = 0; f < alive_.size(); ++f)
            if (alive_[f]) ids.push_back(static_cast<std::uint32_t>(f));
        return ids;
    }

    /// For a lifted hull: the sign of det[[c_k, 1]] over facet f's corners (its projection's
    /// orientation), from the cached plane (the minor without the lift column) when its bound
    /// decides, exactly otherwise.
    int projected_orientation(std::uint32_t f) const {
        const std::size_t n = static_cast<std::size_t>(D_) + 1;
        const int d = p_.dimension();
        if (usable_[f]) {
            const double minor = plane_[2 * n * f + static_cast<std::size_t>(d)];
            const double bound = plane_[2 * n * f + n + static_cast<std::size_t>(d)];
            const double error = rounding_bound(D_, false, 0, bound);
            if (minor > error) return 1;
            if (-minor > error) return -1;
        }
        return p_.orient(&corners_[f * static_cast<std::size_t>(D_)]);
    }

    /// The live facets (D corners each) and their neighbours, renumbered from 0.
    void result(std::vector<std::uint32_t>* facets, std::vector<std::int32_t>* neighbors) const {
        const std::size_t total = alive_.size();
        std::vector<std::int32_t> index(total, -1);
        std::int32_t live = 0;
        for (std::size_t f = 0; f < total; ++f)
            if (alive_[f]) index[f] = live++;
        facets->clear();
        neighbors->clear();
        for (std::size_t f = 0; f < total; ++f) {
            if (!alive_[f]) continue;
            for (int j = 0; j < D_; ++j) {
                facets->push_back(corners_[f * static_cast<std::size_t>(D_) + static_cast<std::size_t>(j)]);
                neighbors->push_back(index[static_cast<std::size_t>(neighbor_[f * static_cast<std::size_t>(D_) + static_cast<std::size_t>(j)])]);
            }
        }
    }

    /// The sign of q against live facet f (positive: strictly outside), from its cached plane
    /// when the floating value decides.
    int facet_side(std::uint32_t f, std::uint32_t q, double* value = nullptr) const {
        const std::size_t n = static_cast<std::size_t>(D_) + 1;
        if (usable_[f] && p_.exact_copy(q)) {
            double row[kMaxRows];
            p_.row_values(q, lifted_, row);
            const int s = p_.side_of_plane(&plane_[2 * n * f], &plane_[2 * n * f + n], row, lifted_, value);
            // q in front: (-1)^D times the orientation with q last.
            if (s != 2) return (D_ & 1) ? -s : s;
            if (value && (D_ & 1)) *value = -*value;
        }
        // The plane could not tell (or its rows are not exact copies): the later stages.
        std::uint32_t rows[kMaxRows];
        std::copy(&corners_[f * static_cast<std::size_t>(D_)], &corners_[f * static_cast<std::size_t>(D_)] + D_, rows);
        rows[D_] = q;
        int columns[kMaxRows];
        return p_.decide(rows, p_.orientation_columns(lifted_, columns), columns);
    }

    /// The sign of q against the facet with these D corners (positive: strictly outside).
    int side(const std::uint32_t* corners, std::uint32_t q, double* value = nullptr) const {
        std::uint32_t rows[kMaxRows];
        std::copy(corners, corners + D_, rows);
        rows[D_] = q;
        return p_.orient(rows, value, lifted_);
    }

private:
    std::uint32_t corner_of(std::uint32_t f, int j) const {
        return corners_[f * static_cast<std::size_t>(D_) + static_cast<std::size_t>(j)];
    }

    /// A new facet with these corners: in the slot of a removed one when there is one (the
    /// arrays then stop growing once the hull does: no reallocation copies or fresh pages).
    std::uint32_t add_facet(const std::uint32_t* corners) {
        const std::size_t n = static_cast<std::size_t>(D_) + 1;
        const std::size_t D = static_cast<std::size_t>(D_);
        std::uint32_t t;
        if (!free_facets_.empty()) {
            t = free_facets_.back();
            free_facets_.pop_back();
            std::copy(corners, corners + D_, &corners_[t * D]);
            std::fill(&neighbor_[t * D], &neighbor_[t * D] + D, -1);
            alive_[t] = 1;
            mark_[t] = 0;  // (its outside set was emptied when it was removed)
        } else {
            t = static_cast<std::uint32_t>(alive_.size());
            plane_.resize(plane_.size() + 2 * n);
            usable_.push_back(false);
            corners_.insert(corners_.end(), corners, corners + D_);
            neighbor_.insert(neighbor_.end(), D, -1);
            alive_.push_back(1);
            outside_.emplace_back();
            mark_.push_back(0);
        }
        p_.facet_plane(corners, lifted_, &plane_[2 * n * t], &plane_[2 * n * t + n]);
        bool usable = true;
        for (int k = 0; k < D_; ++k) usable = usable && p_.exact_copy(corners[k]);
        usable_[t] = usable;
        return t;
    }

    /// Puts q into the outside set of the first of `facets` it lies strictly beyond (if any).
    void assign(std::uint32_t q, const std::vector<std::uint32_t>& facets) {
        for (const std::uint32_t f : facets) {
            double value = 0;
            if (facet_side(f, q, &value) > 0) {
                outside_[f].push_back({q, value});
                return;
            }
        }
    }

    void add_point(std::uint32_t f, std::vector<std::uint32_t>* pending) {
        const int D = D_;
        // The furthest point of f's outside set (the floating estimate: an order, not a decision).
        const auto& out = outside_[f];
        std::size_t best = 0;
        for (std::size_t k = 1; k < out.size(); ++k)
            if (std::fabs(out[k].second) > std::fabs(out[best].second)) best = k;
        const std::uint32_t p = out[best].first;
        // The facets p sees strictly: a search over neighbours from f.
        stamp_ += 2;
        const std::uint32_t visible = stamp_, hidden = stamp_ + 1;
        std::vector<std::uint32_t> seen{f};
        mark_[f] = visible;
        const std::size_t n = static_cast<std::size_t>(D) + 1;
        for (std::size_t k = 0; k < seen.size(); ++k) {
            const std::uint32_t g = seen[k];
#if defined(__GNUC__) || defined(__clang__)
            // The neighbours' planes, about to be tested, lie anywhere in a large array.
            for (int j = 0; j < D; ++j) {
                const std::size_t h = static_cast<std::size_t>(neighbor_[g * static_cast<std::size_t>(D) + static_cast<std::size_t>(j)]);
                __builtin_prefetch(plane_.data() + 2 * n * h);
                __builtin_prefetch(plane_.data() + 2 * n * h + 2 * n - 1);
            }
#endif
            for (int j = 0; j < D; ++j) {
                const auto h = static_cast<std::uint32_t>(neighbor_[g * static_cast<std::size_t>(D) + static_cast<std::size_t>(j)]);
                if (mark_[h] == visible || mark_[h] == hidden) continue;
                if (facet_side(h, p) > 0) {
                    mark_[h] = visible;
                    seen.push_back(h);
                } else {
                    mark_[h] = hidden;
                }
            }
        }
        // One new facet per horizon ridge: the visible facet's corners with p for the corner
        // across from the hidden neighbour (the same orientation: its hidden corner is inside).
        std::vector<std::uint32_t> created;
        for (const std::uint32_t g : seen) {
            for (int j = 0; j < D; ++j) {
                const auto h = static_cast<std::uint32_t>(neighbor_[g * static_cast<std::size_t>(D) + static_cast<std::size_t>(j)]);
                if (mark_[h] == visible) continue;
                std::uint32_t corners[kMaxRows];
                std::copy(&corners_[g * static_cast<std::size_t>(D)], &corners_[g * static_cast<std::size_t>(D)] + D, corners);
                corners[j] = p;
                const std::uint32_t t = add_facet(corners);
                neighbor_[t * static_cast<std::size_t>(D) + static_cast<std::size_t>(j)] = static_cast<std::int32_t>(h);
                for (int i = 0; i < D; ++i)
                    if (neighbor_[h * static_cast<std::size_t>(D) + static_cast<std::size_t>(i)] == static_cast<std::int32_t>(g))
                        neighbor_[h * static_cast<std::size_t>(D) + static_cast<std::size_t>(i)] = static_cast<std::int32_t>(t);
                mark_[t] = 0;
                created.push_back(t);
            }
        }
        // The new facets' ridges through p, paired by their corner sets.
        std::vector<Ridge>& ridges = ridges_;
        ridges.clear();
        for (const std::uint32_t t : created) {
            const std::uint32_t* c = &corners_[t * static_cast<std::size_t>(D)];
            for (int i = 0; i < D; ++i) {
                if (c[i] == p) continue;
                Ridge r{};
                r.key.fill(0xffffffffu);
                for (int k = 0, n = 0; k < D; ++k)
                    if (k != i) r.key[static_cast<std::size_t>(n++)] = c[k];
                std::sort(r.key.begin(), r.key.begin() + (D - 1));
                r.hash = 0;
                for (int k = 0; k < D - 1; ++k) r.hash = (r.hash ^ r.key[static_cast<std::size_t>(k)]) * 0x9e3779b97f4a7c15ull;
                r.facet = t;
                r.across = i;
                ridges.push_back(r);
            }
        }
        // Each ridge is met twice (by the two new facets through it): paired in a small hash table
        // with linear probing, a slot keeping the first of a pair until the second comes (then
        // marked paired, and probed past). Linking is symmetric: the order does not matter.
        constexpr std::uint32_t kEmpty = 0xffffffffu, kPaired = 0xfffffffeu;
        std::size_t size = 16;
        while (size < 2 * ridges.size()) size *= 2;
        std::vector<std::uint32_t>& table = ridge_table_;
        table.assign(size, kEmpty);
        std::size_t pairs = 0;
        for (std::uint32_t k = 0; k < ridges.size(); ++k) {
            const Ridge& r = ridges[k];
            for (std::size_t at = (r.hash ^ (r.hash >> 29)) & (size - 1);; at = (at + 1) & (size - 1)) {
                const std::uint32_t other = table[at];
                if (other == kEmpty) {
                    table[at] = k;
                    break;
                }
                if (other == kPaired || ridges[other].hash != r.hash || ridges[other].key != r.key) continue;
                const Ridge& o = ridges[other];
                neighbor_[r.facet * static_cast<std::size_t>(D) + static_cast<std::size_t>(r.across)] = static_cast<std::int32_t>(o.facet);
                neighbor_[o.facet * static_cast<std::size_t>(D) + static_cast<std::size_t>(o.across)] = static_cast<std::int32_t>(r.facet);
                table[at] = kPaired;
                ++pairs;
                break;
            }
        }
        if (2 * pairs != ridges.size()) throw std::logic_error("hull_nd: unpaired ridge");
        // The visible facets go; their other outside points move to the new facets (or are inside).
        // (assign adds only to the new facets' sets: `points` stays in place.) Their slots are
        // free for the next point's facets.
        for (const std::uint32_t g : seen) {
            alive_[g] = 0;
            std::vector<std::pair<std::uint32_t, double>>& points = outside_[g];
            // The points lie anywhere in memory: their rows are fetched a few points ahead (a
            // quarter of a 4D hull's time went to waiting for them).
            constexpr std::size_t kAhead = 8;
            for (std::size_t k = 0; k < std::min(kAhead, points.size()); ++k) p_.prefetch(points[k].first);
            for (std::size_t k = 0; k < points.size(); ++k) {
                if (k + kAhead < points.size()) p_.prefetch(points[k + kAhead].first);
                if (points[k].first != p) assign(points[k].first, created);
            }
            points.clear();
            free_facets_.push_back(g);
        }
        for (auto it = created.rbegin(); it != created.rend(); ++it)
            if (!outside_[*it].empty()) pending->push_back(*it);
    }

    /// Some D + 1 affinely independent points of `ids`, chosen in floating point (largest distance
    /// from the span so far) and confirmed exactly.
    bool initial_simplex(const std::vector<std::uint32_t>& ids, std::vector<std::uint32_t>* simplex, int* spanned) {
        const int D = D_;
        const int d = p_.dimension();
        // The point at infinity (if any) as a point far above (below) the others: an order only.
        double far = 0;
        for (const std::uint32_t i : ids)
            if (i != p_.infinity()) far = std::max(far, std::fabs(lift(i)));
        far = 4 * far + 4;
        auto coordinate = [&](std::uint32_t i, int j) {
            if (i == p_.infinity()) return j < d ? 0.0 : p_.infinity_sign() * far;
            return j < d ? scaled(i, j) : lift(i);
        };
        simplex->assign(1, ids[0]);
        std::vector<std::vector<double>> basis;  // orthonormal directions of the span so far
        std::vector<std::pair<double, std::uint32_t>> order;
        std::vector<double> v(static_cast<std::size_t>(D));
        // v = q - the first point, less its parts along the basis; returns |v|^2.
        auto residual = [&](std::uint32_t q) {
            for (int j = 0; j < D; ++j) v[static_cast<std::size_t>(j)] = coordinate(q, j) - coordinate((*simplex)[0], j);
            for (const auto& b : basis) {
                double dot = 0;
                for (int j = 0; j < D; ++j) dot += v[static_cast<std::size_t>(j)] * b[static_cast<std::size_t>(j)];
                for (int j = 0; j < D; ++j) v[static_cast<std::size_t>(j)] -= dot * b[static_cast<std::size_t>(j)];
            }
            double norm = 0;
            for (double x : v) norm += x * x;
            return norm;
        };
        for (int k = 1; k <= D; ++k) {
            order.clear();
            std::size_t best = 0;
            for (const std::uint32_t q : ids) {
                const double norm = residual(q);
                if (order.empty() || norm > -order[best].first) best = order.size();
                order.push_back({-norm, q});
            }
            // The furthest candidate first; the rest in order of distance only if it fails.
            bool found = false;
            const std::uint32_t first = order[best].second;
            if (std::find(simplex->begin(), simplex->end(), first) == simplex->end()) {
                simplex->push_back(first);
                found = independent(*simplex);
                if (!found) simplex->pop_back();
            }
            if (!found) {
                std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
                for (const auto& candidate : order) {
                    if (candidate.second == first ||
                        std::find(simplex->begin(), simplex->end(), candidate.second) != simplex->end())
                        continue;
                    simplex->push_back(candidate.second);
                    if (independent(*simplex)) {
                        found = true;
                        break;
                    }
                    simplex->pop_back();
                }
            }
            if (!found) {
                *spanned = k - 1;
                return false;
            }
            // The new direction, orthonormalised (floating point: it only orders the candidates).
            const double norm = std::sqrt(residual(simplex->back()));
            if (norm > 0)
                for (double& x : v) x /= norm;
            basis.push_back(v);
        }
        return true;
    }

    /// Whether the rows [p, (lift,) 1] of `points` are linearly independent: some square minor
    /// (columns: any of the coordinates, with the ones) is nonzero, exactly.
    bool independent(const std::vector<std::uint32_t>& points) const {
        const int n = static_cast<int>(points.size());
        int all[kMaxRows];
        const int total = p_.orientation_columns(lifted_, all);
        // Column subsets of size n; the floating estimates first, the exact signs if none decides.
        std::vector<std::vector<int>> subsets;
        std::vector<int> pick(static_cast<std::size_t>(n));
        std::iota(pick.begin(), pick.end(), 0);
        while (true) {
            std::vector<int> columns;
            for (int i : pick) columns.push_back(all[i]);
            subsets.push_back(std::move(columns));
            int i = n - 1;
            while (i >= 0 && pick[static_cast<std::size_t>(i)] == total - n + i) --i;
            if (i < 0) break;
            ++pick[static_cast<std::size_t>(i)];
            for (int k = i + 1; k < n; ++k) pick[static_cast<std::size_t>(k)] = pick[static_cast<std::size_t>(k - 1)] + 1;
        }
        // Largest floating estimate first: with the exact sign it usually settles at once.
        std::vector<std::pair<double, std::size_t>> ranked;
        for (std::size_t s = 0; s < subsets.size(); ++s) {
            double a[kMaxRows * kMaxRows];
            for (int r = 0; r < n; ++r)
                for (int c = 0; c < n; ++c) a[r * n + c] = p_.entry(points[static_cast<std::size_t>(r)], subsets[s][static_cast<std::size_t>(c)]);
            ranked.push_back({-std::fabs(float_det(a, n)), s});
        }
        std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& r : ranked)
            if (p_.sign(points.data(), n, subsets[r.second].data()) != 0) return true;
        return false;
    }

    double scaled(std::uint32_t i, int j) const { return p_.scaled(i, j); }
    double lift(std::uint32_t i) const { return p_.lift(i); }

    /// A ridge of a new facet through its new point: its other corners (sorted) and their hash.
    struct Ridge {
        std::uint64_t hash;
        std::array<std::uint32_t, kMaxRows> key;
        std::uint32_t facet;
        int across;
    };
    std::vector<Ridge> ridges_;  ///< add_point's workspace
    std::vector<std::uint32_t> ridge_table_;
    std::vector<std::uint32_t> free_facets_;  ///< slots of removed facets, reused last-in first-out

    const Predicate& p_;
    bool lifted_;
    int D_;
    std::vector<std::uint32_t> corners_;
    std::vector<std::int32_t> neighbor_;
    std::vector<char> alive_;
    std::vector<std::vector<std::pair<std::uint32_t, double>>> outside_;
    std::vector<std::uint32_t> mark_;
    std::vector<double> plane_;   ///< per facet: its minors f_j, then their permanents g_j
    std::vector<char> usable_;    ///< per facet: its corners' floating rows are exact
    std::uint32_t stamp_ = 0;
};


/// Per facet (rows of `width` corners, neighbours across each corner; -1 for none; `id` its facet
/// of `hull`): the lowest
/// facet joined to it through neighbours whose far corner lies on the facet's hyperplane, exactly
/// (the flat pieces of a hull's boundary; the cospherical groups of a triangulation).
std::vector<std::int32_t> coplanar_groups(const Quickhull& hull, const std::vector<std::uint32_t>& id,
                                          const std::vector<std::uint32_t>& facets,
                                          const std::vector<std::int32_t>& neighbors, std::size_t width) {
    const std::size_t m = facets.size() / width;
    std::vector<std::int32_t> parent(m);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](std::int32_t x) {
        while (parent[static_cast<std::size_t>(x)] != x)
            x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
        return x;
    };
    for (std::size_t s = 0; s < m; ++s) {
        for (std::size_t k = 0; k < width; ++k) {
            const std::int32_t t = neighbors[s * width + k];
            if (t < static_cast<std::int32_t>(s)) continue;  // each pair once (and none across -1)
            std::size_t back = 0;
            while (neighbors[static_cast<std::size_t>(t) * width + back] != static_cast<std::int32_t>(s)) ++back;
            if (hull.facet_side(id[s], facets[static_cast<std::size_t>(t) * width + back]) == 0) {
                const std::int32_t a = find(static_cast<std::int32_t>(s)), b = find(t);
                parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
            }
        }
    }
    std::vector<std::int32_t> group(m);
    for (std::size_t s = 0; s < m; ++s) group[s] = find(static_cast<std::int32_t>(s));
    return group;
}

/// An error for input `name` (hull_nd, delaunay_nd) takes no further: a dimension outside
/// lowest .. highest, too many points or a non-finite coordinate (its point in `blamed`); or empty.
std::string check_input(const char* name, int lowest, int highest, const double* points, std::size_t count, int d,
                        std::int64_t* blamed) {
    if (d < lowest || d > highest)
        return std::string(name) + " takes " + std::to_string(lowest) + " to " + std::to_string(highest) +
               " dimensions, not " + std::to_string(d);
    if (count >= (std::size_t{1} << 31)) return "more than 2^31 points";
    for (std::size_t i = 0; i < count; ++i)
        for (int j = 0; j < d; ++j)
            if (!std::isfinite(points[i * static_cast<std::size_t>(d) + static_cast<std::size_t>(j)])) {
                *blamed = static_cast<std::int64_t>(i);
                return "point " + std::to_string(i) + " has a non-finite coordinate " + std::to_string(j);
            }
    return {};
}

std::string flat_message(int spanned, int dimension, const char* what) {
    return std::string(what) + " needs points spanning all " + std::to_string(dimension) +
           " dimensions: these lie in a flat of " + std::to_string(spanned) + " dimension" + (spanned == 1 ? "" : "s");
}

}  // namespace

HullNd hull_nd(const double* points, std::size_t count, int dimension) {
    HullNd out;
    out.dimension = dimension;
    out.error = check_input("hull_nd", 2, kMaxHullNdDimension, points, count, dimension, &out.error_point);
    if (!out.ok()) return out;
    if (count < static_cast<std::size_t>(dimension) + 1) {
        out.error = "a hull in " + std::to_string(dimension) + " dimensions needs at least " +
                    std::to_string(dimension + 1) + " points, got " + std::to_string(count);
        return out;
    }
    const Predicate predicate(points, count, dimension);
    Quickhull hull(predicate, false);
    std::vector<std::uint32_t> ids(count);
    std::iota(ids.begin(), ids.end(), 0u);
    int spanned = 0;
    if (!hull.build(ids, &spanned)) {
        out.error = flat_message(spanned, dimension, "a hull");
        return out;
    }
    hull.result(&out.facets, &out.neighbors);
    out.group = coplanar_groups(hull, hull.live(), out.facets, out.neighbors, static_cast<std::size_t>(dimension));
    out.vertices = out.facets;
    std::sort(out.vertices.begin(), out.vertices.end());
    out.vertices.erase(std::unique(out.vertices.begin(), out.vertices.end()), out.vertices.end());
    return out;
}

double hull_nd_volume(const double* points, std::size_t count, int dimension) {
    const HullNd h = hull_nd(points, count, dimension);
    if (!h.ok()) return std::numeric_limits<double>::quiet_NaN();
    const std::size_t d = static_cast<std::size_t>(dimension);
    std::vector<double> centre(d, 0.0);
    for (const std::uint32_t v : h.vertices)
        for (std::size_t j = 0; j < d; ++j) centre[j] += points[v * d + j];
    for (double& x : centre) x /= static_cast<double>(h.vertices.size());
    double total = 0, factorial = 1;
    for (std::size_t k = 2; k <= d; ++k) factorial *= static_cast<double>(k);
    std::vector<double> a(d * d);
    for (std::size_t f = 0; f < h.facet_count(); ++f) {
        for (std::size_t r = 0; r < d; ++r)
            for (std::size_t j = 0; j < d; ++j) a[r * d + j] = points[h.facets[f * d + r] * d + j] - centre[j];
        total += std::fabs(float_det(a.data(), dimension));
    }
    return total / factorial;
}

DelaunayNd delaunay_nd(const double* points, std::size_t count, int dimension, bool furthest_site) {
    DelaunayNd out;
    out.dimension = dimension;
    const int d = dimension;
    out.error = check_input("delaunay_nd", 1, kMaxHullNdDimension - 1, points, count, d, &out.error_point);
    if (!out.ok()) return out;
    // Repeated points: the lowest index represents each group of equal points.
    auto row = [&](std::uint32_t i) { return points + i * static_cast<std::size_t>(d); };
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return std::lexicographical_compare(row(a), row(a) + d, row(b), row(b) + d);
    });
    out.representative.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t i = order[k];
        const bool same = k > 0 && std::equal(row(i), row(i) + d, row(order[k - 1]));
        out.representative[i] = same ? out.representative[order[k - 1]] : i;
    }
    std::vector<std::uint32_t> distinct;
    for (std::uint32_t i = 0; i < count; ++i) {
        if (out.representative[i] == i)
            distinct.push_back(i);
        else
            ++out.duplicate_count;
    }
    if (distinct.size() < static_cast<std::size_t>(d) + 1) {
        out.error = "a Delaunay triangulation in " + std::to_string(d) + " dimensions needs at least " +
                    std::to_string(d + 1) + " distinct points, got " + std::to_string(distinct.size());
        return out;
    }
    // With the point at infinity above (below, for the upper facets): cospherical points too have
    // a hull of full dimension; its facets through that point are vertical, in neither set.
    const Predicate predicate(points, count, d, furthest_site ? -1 : 1);
    Quickhull hull(predicate, true);
    int spanned = 0;
    distinct.push_back(predicate.infinity());
    if (!hull.build(distinct, &spanned)) {
        // The lifted points span one dimension more than the points.
        out.error = flat_message(spanned - 1, d, "a Delaunay triangulation");
        return out;
    }
    std::vector<std::uint32_t> facets;
    std::vector<std::int32_t> facet_neighbors;
    hull.result(&facets, &facet_neighbors);
    const std::vector<std::uint32_t> hull_id = hull.live();
    const std::size_t corners = static_cast<std::size_t>(d) + 1;
    const std::size_t facet_count = facets.size() / corners;
    // Lower facets: their projection is positively oriented; upper ones negatively.
    std::vector<std::int32_t> index(facet_count, -1);
    std::vector<std::uint32_t> kept_facet;  // per output simplex: its facet of the lifted hull
    std::int32_t kept = 0;
    for (std::size_t f = 0; f < facet_count; ++f) {
        const std::uint32_t* c = &facets[f * corners];
        if (std::find(c, c + corners, predicate.infinity()) != c + corners) continue;  // vertical
        const int s = hull.projected_orientation(hull_id[f]);
        if (furthest_site ? s < 0 : s > 0) {
            index[f] = kept++;
            kept_facet.push_back(hull_id[f]);
        }
    }
    out.simplices.reserve(static_cast<std::size_t>(kept) * corners);
    out.neighbors.reserve(static_cast<std::size_t>(kept) * corners);
    for (std::size_t f = 0; f < facet_count; ++f) {
        if (index[f] < 0) continue;
        const std::size_t at = out.simplices.size();
        for (std::size_t k = 0; k < corners; ++k) {
            out.simplices.push_back(facets[f * corners + k]);
            out.neighbors.push_back(index[static_cast<std::size_t>(facet_neighbors[f * corners + k])]);
        }
        if (furthest_site) {  // upper facets project negatively: two corners swapped
            std::swap(out.simplices[at], out.simplices[at + 1]);
            std::swap(out.neighbors[at], out.neighbors[at + 1]);
        }
    }
    // Cospherical neighbours (the neighbour's far corner on the simplex's sphere: on the lifted
    // facet's hyperplane, exactly) joined.
    out.group = coplanar_groups(hull, kept_facet, out.simplices, out.neighbors, corners);
    return out;
}

std::vector<std::int32_t> locate_nd(const double* points, const DelaunayNd& triangulation, const double* queries,
                                    std::size_t query_count) {
    const int d = triangulation.dimension;
    const std::size_t corners = static_cast<std::size_t>(d) + 1;
    const std::size_t m = triangulation.simplex_count();
    std::vector<std::int32_t> found(query_count, -1);
    if (m == 0) return found;
    const std::size_t count = triangulation.representative.size();
    Predicate predicate(points, count, d);
    const std::uint32_t* simplices = triangulation.simplices.data();
    const std::int32_t* neighbors = triangulation.neighbors.data();
    // The sign of q against face k of simplex s: negative when q is strictly beyond it.
    auto face_side = [&](std::size_t s, std::size_t k) {
        std::uint32_t rows[kMaxRows];
        std::copy(simplices + s * corners, simplices + s * corners + corners, rows);
        rows[k] = Predicate::kQuery;
        return predicate.orient(rows);
    };
    auto holds = [&](std::size_t s) {
        for (std::size_t k = 0; k < corners; ++k)
            if (face_side(s, k) < 0) return false;
        return true;
    };
    std::size_t start = 0;
    std::vector<std::size_t> around;
    std::vector<char> seen(m, 0);
    for (std::size_t i = 0; i < query_count; ++i) {
        const double* q = queries + i * static_cast<std::size_t>(d);
        if (!std::all_of(q, q + d, [](double x) { return std::isfinite(x); })) continue;
        predicate.set_query(q);
        // A visibility walk (the first face q is strictly beyond, scanned from a varying face).
        std::size_t s = start;
        std::int64_t at = -2;
        const std::size_t limit = 4 * m + 64;
        for (std::size_t step = 0; step < limit && at == -2; ++step) {
            at = static_cast<std::int64_t>(s);
            for (std::size_t j = 0; j < corners; ++j) {
                const std::size_t k = (j + step) % corners;
                if (face_side(s, k) < 0) {
                    const std::int32_t next = neighbors[s * corners + k];
                    if (next < 0) {
                        at = -1;  // beyond a hull face: outside the (convex) hull
                    } else {
                        s = static_cast<std::size_t>(next);
                        at = -2;
                    }
                    break;
                }
            }
        }
        if (at == -2) {  // no end in sight (never seen on a Delaunay triangulation): every simplex
            at = -1;
            for (std::size_t t = 0; t < m && at < 0; ++t)
                if (holds(t)) at = static_cast<std::int64_t>(t);
        }
        if (at < 0) continue;
        // The lowest-indexed simplex holding q: those around it share faces that hold q.
        around.assign(1, static_cast<std::size_t>(at));
        seen[static_cast<std::size_t>(at)] = 1;
        std::size_t lowest = static_cast<std::size_t>(at);
        for (std::size_t k = 0; k < around.size(); ++k) {
            const std::size_t t = around[k];
            lowest = std::min(lowest, t);
            for (std::size_t j = 0; j < corners; ++j) {
                const std::int32_t u = neighbors[t * corners + j];
                if (u < 0 || seen[static_cast<std::size_t>(u)] || face_side(t, j) != 0) continue;
                seen[static_cast<std::size_t>(u)] = 1;
                around.push_back(static_cast<std::size_t>(u));
            }
        }
        for (const std::size_t t : around) seen[t] = 0;
        found[i] = static_cast<std::int32_t>(lowest);
        start = static_cast<std::size_t>(at);
    }
    return found;
}

int orient_nd(const double* rows, int dimension) {
    if (dimension < 1 || dimension > kMaxHullNdDimension) throw std::invalid_argument("orient_nd: dimension out of range");
    const Predicate predicate(rows, static_cast<std::size_t>(dimension) + 1, dimension);
    std::uint32_t ids[kMaxRows];
    std::iota(ids, ids + dimension + 1, 0u);
    return predicate.orient(ids);
}

}  // namespace hullkit
