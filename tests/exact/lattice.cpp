// The small-lattice test behind the 2D predicates' shortcut (native/src/exact/lattice.hpp): which
// coordinates take it, and, at the largest lattice it accepts, that the floating-point orient2d
// and incircle values it then trusts are the exact determinants (GMP rationals, a different
// formula). The 3D limits are tested in tests/delaunay3/lattice.cpp; whole triangulations on both
// sides of the 2D limit in tests/delaunay/delaunay.cpp.
#include "exact/lattice.hpp"

#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "exact/gmp_determinant.hpp"
#include "hullkit/predicates.hpp"

namespace {

using hullkit::detail::kPlaneLatticeUnits;
using hullkit::detail::plane_lattice_exact;
using hullkit::detail::small_lattice;
using P2 = std::array<double, 2>;

/// small_lattice with the 2D limits; for finite points also the 2D entry point given their span,
/// which must agree.
bool lattice(const std::vector<double>& xy, int* unit = nullptr) {
    int found = 0;
    double lo[2];
    const bool yes = small_lattice(xy.data(), xy.size() / 2, 2, kPlaneLatticeUnits, 4, &found, lo);
    if (!xy.empty() && std::all_of(xy.begin(), xy.end(), [](double v) { return std::isfinite(v); })) {
        double span = 0;
        for (int axis = 0; axis < 2; ++axis) {
            double low = xy[axis], high = xy[axis];
            for (std::size_t i = axis; i < xy.size(); i += 2) low = std::min(low, xy[i]), high = std::max(high, xy[i]);
            span = std::max(span, high - low);
        }
        REQUIRE(yes == plane_lattice_exact(xy.data(), xy.size() / 2, span));
    }
    if (unit) *unit = found;
    return yes;
}

std::vector<double> square(double lo, double hi) { return {lo, lo, hi, lo, hi, hi, lo, hi}; }

/// incircle's value (positive: d inside the counter-clockwise a, b, c) as the 4x4 determinant with
/// rows (x, y, x^2 + y^2, 1), expanded along the last column: not the code's formula.
mpq_class exact_incircle(const P2& a, const P2& b, const P2& c, const P2& d) {
    const P2* points[4] = {&a, &b, &c, &d};
    mpq_class rows[4][3];
    const mpq_class ones[4] = {1, 1, 1, 1};
    for (int i = 0; i < 4; ++i) {
        rows[i][0] = (*points[i])[0];
        rows[i][1] = (*points[i])[1];
        rows[i][2] = rows[i][0] * rows[i][0] + rows[i][1] * rows[i][1];
    }
    return exact_test::det4_by_last_column(rows, ones);
}

mpq_class exact_orient(const P2& a, const P2& b, const P2& c) {
    return (mpq_class(b[0]) - a[0]) * (mpq_class(c[1]) - a[1]) - (mpq_class(b[1]) - a[1]) * (mpq_class(c[0]) - a[0]);
}

}  // namespace

TEST_CASE("plane lattice: which coordinates take the shortcut", "[lattice]") {
    int unit = 0;
    CHECK(lattice(square(0, 5234), &unit));  // integers 5234 apart: the limit
    CHECK(unit == 0);
    CHECK_FALSE(lattice(square(0, 5235)));  // needs u = 2, and 5235 is odd
    CHECK(lattice(square(0, 5236), &unit));  // 2618 units of 2
    CHECK(unit == 1);
    CHECK(lattice(square(-2617, 2617)));
    CHECK_FALSE(lattice(square(-2617, 2619)));
    // Multiples of 2^-10 far from the origin (UTM-like metres in millimetre-ish steps).
    CHECK(lattice(square(500000, 500000 + 5234.0 / 1024), &unit));
    CHECK(unit == -10);
    CHECK_FALSE(lattice(square(500000, 500000 + 5235.0 / 1024)));
    // The exponent range: u^4 normal, 2^53 u^4 finite.
    CHECK(lattice(square(0, std::ldexp(5234.0, -255))));
    CHECK_FALSE(lattice(square(0, std::ldexp(5234.0, -256))));
    CHECK(lattice(square(0, std::ldexp(5234.0, 242))));
    CHECK_FALSE(lattice(square(0, std::ldexp(5234.0, 243))));
    // One coordinate off the lattice spoils it, wherever it is; a half is still on a finer one.
    std::vector<double> grid;
    for (int x = 0; x < 300; ++x)
        for (int y = 0; y < 200; ++y) grid.insert(grid.end(), {double(x), double(y)});
    CHECK(lattice(grid));
    grid[grid.size() - 1] = 199.5;
    CHECK(lattice(grid, &unit));
    CHECK(unit == -4);  // the smallest power of two with 299 <= 5234 u: 2^-4 (then 199.5 is 3192 u)
    grid[grid.size() - 1] = 199.1;
    CHECK_FALSE(lattice(grid));
    // A subnormal coordinate whose quotient by u underflows to 0 must not pass as a multiple.
    CHECK_FALSE(lattice({0, 0, 4 * 5234.0, 0, std::numeric_limits<double>::denorm_min(), 1}));
    // Not finite, one point, nothing.
    CHECK_FALSE(lattice({0, 0, 1, 1, std::numeric_limits<double>::quiet_NaN(), 0}));
    CHECK_FALSE(lattice({0, 0, 1, 1, 0, std::numeric_limits<double>::infinity()}));
    CHECK_FALSE(lattice({3, 4, 3, 4}));
    CHECK_FALSE(lattice({}));
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> uniform(2 * 1000);
    for (double& v : uniform) v = u(rng);
    CHECK_FALSE(lattice(uniform));
}

TEST_CASE("plane lattice: on the largest lattice, doubles give the exact determinants", "[lattice]") {
    // Three points at corners of the box [0, 5234]^2 (the largest differences) and one anywhere, or
    // four anywhere, on the integers and on multiples of 2^-10 near 500000; every value compared
    // exactly, not only its sign.
    std::mt19937_64 rng(17);
    for (const double offset : {0.0, 500000.0}) {
        const double unit = offset == 0 ? 1.0 : 1.0 / 1024;
        std::uniform_int_distribution<int> any(0, 5234), side(0, 1);
        auto coordinate = [&](bool extreme) { return offset + unit * (extreme ? 5234 * side(rng) : any(rng)); };
        std::size_t nonzero = 0;
        double largest = 0;
        for (int trial = 0; trial < 40000; ++trial) {
            const bool extreme = trial % 2 == 0;
            P2 p[4];
            for (int i = 0; i < 4; ++i)
                for (double& v : p[(trial + i) % 4]) v = coordinate(extreme && i < 3);
            const double incircle = hullkit::detail::incircle_stage_a(p[0][0], p[0][1], p[1][0], p[1][1], p[2][0],
                                                                      p[2][1], p[3][0], p[3][1]).det;
            const double orient = hullkit::detail::orient2d_stage_a(p[0][0], p[0][1], p[1][0], p[1][1], p[2][0],
                                                                    p[2][1]).det;
            INFO("offset " << offset << " trial " << trial);
            REQUIRE(mpq_class(incircle) == exact_incircle(p[0], p[1], p[2], p[3]));
            REQUIRE(mpq_class(orient) == exact_orient(p[0], p[1], p[2]));
            nonzero += incircle != 0;
            largest = std::max(largest, std::fabs(incircle) / (unit * unit * unit * unit));
        }
        CHECK(nonzero > 20000);  // the values compared were not all 0
        CHECK(largest > 3e14);  // and reached 0.4 * 5234^4 (the terms summed to it several times that)
    }
}
