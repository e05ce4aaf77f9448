#include "exact/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullkit {
namespace detail {

bool lattice_unit(double span, double max_units, int degree, int* unit_out) {
    if (!(span > 0) || !(span <= std::numeric_limits<double>::max()) || !(max_units >= 1) || degree < 1) return false;
    // u: the smallest power of two with span <= max_units u. Any lattice that fits has a unit of at
    // least u, a multiple of u (both powers of two), so the points are on some fitting lattice
    // exactly when every coordinate is a multiple of u. (The computed span is at most max_units u
    // exactly when the true one is: it is rounded monotonically, and a true span that is a multiple
    // of u near max_units u < 2^53 u is representable.)
    int unit = 0;
    std::frexp(span / max_units, &unit);
    while (std::ldexp(max_units, unit) < span) ++unit;
    while (std::ldexp(max_units, unit - 1) >= span) --unit;
    if (unit < -(1022 / degree) || unit > (1023 - 53) / degree) return false;  // u^degree normal, 2^53 u^degree finite
    *unit_out = unit;
    return true;
}

bool all_multiples(const double* coords, std::size_t size, int unit) {
    const double u = std::ldexp(1.0, unit), inverse = std::ldexp(1.0, -unit);
    // v is a multiple of u when v / u (exact unless it under- or overflows: then x u != v) is an
    // integer: x itself from 2^52 on, otherwise when rounding it to an integer by adding and
    // subtracting 2^52 leaves it as it is. In blocks without branches, stopping at the first block
    // with a coordinate off the lattice (most inputs: the first).
    constexpr double kTwo52 = 4503599627370496.0;
    constexpr std::size_t kBlock = 256;
    for (std::size_t start = 0; start < size; start += kBlock) {
        const std::size_t end = std::min(size, start + kBlock);
        bool multiples = true;
        for (std::size_t i = start; i < end; ++i) {
            const double x = coords[i] * inverse, m = std::fabs(x);
            multiples &= (x * u == coords[i]) & ((m >= kTwo52) | ((m + kTwo52) - kTwo52 == m));
        }
        if (!multiples) return false;
    }
    return true;
}

bool small_lattice(const double* coords, std::size_t count, int dim, double max_units, int degree, int* unit_out,
                   double* lo_out) {
    constexpr int kMaxDim = 4;
    if (count == 0 || dim < 1 || dim > kMaxDim) return false;
    // The box, and whether every coordinate is finite (v - v is NaN for NaN and infinities).
    double lo[kMaxDim], hi[kMaxDim];
    for (int axis = 0; axis < dim; ++axis) lo[axis] = hi[axis] = coords[axis];
    bool finite = true;
    const std::size_t size = count * static_cast<std::size_t>(dim);
    for (std::size_t i = 0; i < size; i += static_cast<std::size_t>(dim)) {
        for (int axis = 0; axis < dim; ++axis) {
            const double v = coords[i + static_cast<std::size_t>(axis)];
            finite &= v - v == 0;
            lo[axis] = v < lo[axis] ? v : lo[axis];
            hi[axis] = v > hi[axis] ? v : hi[axis];
        }
    }
    double span = 0;
    for (int axis = 0; axis < dim; ++axis) span = std::max(span, hi[axis] - lo[axis]);
    int unit = 0;
    if (!finite || !lattice_unit(span, max_units, degree, &unit) || !all_multiples(coords, size, unit)) return false;
    *unit_out = unit;
    std::copy(lo, lo + dim, lo_out);
    return true;
}

}  // namespace detail
}  // namespace hullkit
