// The lattice shortcut of the 3D tetrahedralization's predicates (native/src/delaunay3,
// lattice_exact): which inputs take it, and, on the largest lattice it accepts, that the
// floating-point orient3d and insphere values it then trusts are the exact determinants, checked
// against rational arithmetic (GMP) on the configurations with the largest terms. Whole
// tetrahedralizations on both sides of the limit are compared with CGAL's in
// tests/delaunay3_cgal/cgal.cpp.
#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "delaunay3/delaunay3_internal.hpp"
#include "exact/gmp_determinant.hpp"

namespace {

using hullkit::delaunay3_detail::Lattice;
using hullkit::delaunay3_detail::lattice_exact;
using P3 = std::array<double, 3>;

bool takes_shortcut(const std::vector<double>& xyz, Lattice* lattice = nullptr) {
    Lattice found;
    const bool exact = lattice_exact(xyz, &found);
    if (lattice) *lattice = found;
    return exact;
}

std::vector<double> box_corners(double lo, double hi) {
    std::vector<double> xyz;
    for (int i = 0; i < 8; ++i) xyz.insert(xyz.end(), {i & 1 ? hi : lo, i & 2 ? hi : lo, i & 4 ? hi : lo});
    return xyz;
}

mpq_class exact_orient(const P3& a, const P3& b, const P3& c, const P3& d) {
    mpq_class m[3][3];
    const P3* rows[3] = {&b, &c, &d};
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) m[i][k] = mpq_class((*rows[i])[k]) - mpq_class(a[k]);
    return exact_test::det3(m[0], m[1], m[2]);
}

/// hullkit's in-sphere value (positive inside), as the 4x4 determinant of the rows relative to e
/// with their lifts, expanded along the lift column: a different formula from the code's.
mpq_class exact_insphere(const P3& a, const P3& b, const P3& c, const P3& d, const P3& e) {
    const P3* rows[4] = {&a, &b, &c, &d};
    mpq_class x[4][3], lift[4];
    for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 3; ++k) x[i][k] = mpq_class((*rows[i])[k]) - mpq_class(e[k]);
        lift[i] = x[i][0] * x[i][0] + x[i][1] * x[i][1] + x[i][2] * x[i][2];
    }
    // hullkit's sign is the opposite of det[x | lift]'s for a positively oriented a, b, c, d.
    return -exact_test::det4_by_last_column(x, lift);
}

}  // namespace

TEST_CASE("delaunay3 lattice shortcut: which coordinates take it", "[delaunay3]") {
    Lattice lattice;
    CHECK(takes_shortcut(box_corners(0, 659), &lattice));  // integers 659 apart: the limit
    CHECK(lattice.inverse_unit == 1.0);
    CHECK_FALSE(takes_shortcut(box_corners(0, 661)));
    CHECK(takes_shortcut(box_corners(0, 660), &lattice));  // 660 = 2 * 330: unit 2 (the smallest that fits)
    CHECK(lattice.inverse_unit == 0.5);
    CHECK(takes_shortcut(box_corners(-329, 330)));
    CHECK_FALSE(takes_shortcut(box_corners(-329, 332)));
    // Multiples of 2^-7 far from the origin (1000 + k / 128): the unit is the lowest bit.
    CHECK(takes_shortcut(box_corners(1000, 1000 + 659.0 / 128), &lattice));
    CHECK(lattice.inverse_unit == 128.0);
    CHECK(lattice.lo[0] == 1000.0);
    CHECK_FALSE(takes_shortcut(box_corners(1000, 1000 + 661.0 / 128)));
    CHECK(takes_shortcut(box_corners(0, std::ldexp(659.0, -100))));
    CHECK(takes_shortcut(box_corners(0, std::ldexp(659.0, 150))));
    // One coordinate with a finer bit than the rest spoils it, wherever it is.
    std::vector<double> grid;
    for (int x = 0; x < 40; ++x)
        for (int y = 0; y < 40; ++y)
            for (int z = 0; z < 40; ++z) grid.insert(grid.end(), {double(x), double(y), double(z)});
    CHECK(takes_shortcut(grid));
    grid[3 * 63999 + 2] = 39.5;  // 39.5 - 0 is 79 half units: still a lattice
    CHECK(takes_shortcut(grid));
    grid[3 * 63999 + 2] = 39.1;
    CHECK_FALSE(takes_shortcut(grid));
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> uniform(3 * 1000);
    for (double& v : uniform) v = u(rng);
    CHECK_FALSE(takes_shortcut(uniform));
    CHECK_FALSE(takes_shortcut({}));
}

TEST_CASE("delaunay3 lattice shortcut: on the largest lattice, doubles give the exact determinants",
          "[delaunay3]") {
    // Four points at corners of the box [0, 659]^3 (the largest differences, so the largest terms)
    // and one anywhere, or five anywhere, on the integers and on multiples of 2^-7 near 1000; every
    // value compared exactly, not only its sign.
    std::mt19937_64 rng(11);
    for (const double offset : {0.0, 1000.0}) {
        const double unit = offset == 0 ? 1.0 : 1.0 / 128;
        std::uniform_int_distribution<int> any(0, 659), side(0, 1);
        auto coordinate = [&](bool extreme) { return offset + unit * (extreme ? 659 * side(rng) : any(rng)); };
        std::size_t nonzero = 0;
        for (int trial = 0; trial < 20000; ++trial) {
            const bool extreme = trial % 2 == 0;
            P3 p[5];
            for (int i = 0; i < 5; ++i)
                for (double& v : p[(trial + i) % 5]) v = coordinate(extreme && i < 4);
            const double insphere = hullkit::detail::insphere_stage_a_det(p[0].data(), p[1].data(), p[2].data(),
                                                                          p[3].data(), p[4].data());
            const double orient = hullkit::detail::orient3d_stage_a(p[0].data(), p[1].data(), p[2].data(), p[3].data());
            INFO("offset " << offset << " trial " << trial);
            REQUIRE(mpq_class(insphere) == exact_insphere(p[0], p[1], p[2], p[3], p[4]));
            REQUIRE(mpq_class(orient) == exact_orient(p[0], p[1], p[2], p[3]));
            nonzero += insphere != 0;
        }
        CHECK(nonzero > 10000);  // the values compared were not all 0
    }
    // Four corners of the box and its centre: an in-sphere value within a factor of 50 of the
    // bound 72 * 659^5 behind the shortcut's claim.
    const P3 a = {658, 0, 0}, b = {0, 658, 0}, c = {0, 0, 658}, d = {658, 658, 658}, e = {329, 329, 329};
    const double value = hullkit::detail::insphere_stage_a_det(a.data(), b.data(), c.data(), d.data(), e.data());
    CHECK(mpq_class(value) == exact_insphere(a, b, c, d, e));
    CHECK(std::fabs(value) > 1.8e14);
}
