// incircle against GMP rationals on adversarial cocircular and near-cocircular inputs.
#include <algorithm>
#include <cmath>
#include <random>

#include "delaunay_checks.hpp"
#include "hullkit/predicates.hpp"

using delaunay_test::gmp_incircle;

namespace {

/// Checks incircle, its stage D alone, and all 24 orderings' consistency against GMP.
int check_case(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
    const int expected = gmp_incircle(ax, ay, bx, by, cx, cy, dx, dy);
    REQUIRE(hullkit::incircle(ax, ay, bx, by, cx, cy, dx, dy) == expected);
    REQUIRE(hullkit::detail::incircle_exact(ax, ay, bx, by, cx, cy, dx, dy) == expected);
    // Swapping two of a, b, c flips the sign.
    REQUIRE(hullkit::incircle(bx, by, ax, ay, cx, cy, dx, dy) == -expected);
    return expected;
}

double ulp_step(double v, int steps) {
    for (int k = 0; k < std::abs(steps); ++k) v = std::nextafter(v, steps > 0 ? INFINITY : -INFINITY);
    return v;
}

}  // namespace

TEST_CASE("incircle: sign convention", "[incircle]") {
    // Unit circle through (1,0), (0,1), (-1,0) counter-clockwise.
    REQUIRE(hullkit::incircle(1, 0, 0, 1, -1, 0, 0, 0) == 1);     // centre: inside
    REQUIRE(hullkit::incircle(1, 0, 0, 1, -1, 0, 0, -1) == 0);    // on the circle
    REQUIRE(hullkit::incircle(1, 0, 0, 1, -1, 0, 0, -2) == -1);   // outside
    REQUIRE(hullkit::incircle(-1, 0, 0, 1, 1, 0, 0, 0) == -1);    // clockwise: flipped
}

TEST_CASE("incircle: random points agree with GMP", "[incircle]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 20000; ++i) check_case(u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng));
}

TEST_CASE("incircle: points on a circle with ulp perturbations agree with GMP", "[incircle]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> angle(0, 2 * M_PI);
    std::uniform_int_distribution<int> wiggle(-3, 3);
    int zero = 0, stages[4] = {0, 0, 0, 0};
    for (double scale : {1.0, 1e-30, 1e30, 3.0e-7}) {
        for (double offset : {0.0, 1e7, -12345.678, 1e15}) {
            for (int i = 0; i < 400; ++i) {
                double v[8];
                for (int k = 0; k < 4; ++k) {
                    const double t = angle(rng);
                    v[2 * k] = offset + scale * std::cos(t);
                    v[2 * k + 1] = offset + scale * std::sin(t);
                    if (k == 3) {
                        v[6] = ulp_step(v[6], wiggle(rng));
                        v[7] = ulp_step(v[7], wiggle(rng));
                    }
                }
                zero += check_case(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) == 0;
                int stage = -1;
                hullkit::detail::incircle_traced(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], &stage);
                ++stages[stage];
            }
        }
    }
    // The cases reach the adaptive stages (otherwise they would test only the filter).
    INFO("exactly cocircular after the perturbation: " << zero);
    REQUIRE(stages[1] + stages[2] + stages[3] > 100);
}

TEST_CASE("incircle: exactly cocircular integer and dyadic points", "[incircle]") {
    // Pythagorean points on circles of radius 5 and 65, shifted and scaled by powers of two: exact.
    const int pts5[][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, -3}, {0, -5}, {3, -4}};
    for (double s : {1.0, 0x1p-60, 0x1p+100, 0x1p-150}) {
        for (double shift : {0.0, 1024.0, -0x1p+40}) {
            for (int i = 0; i < 8; ++i)
                for (int j = i + 1; j < 8; ++j)
                    for (int k = j + 1; k < 8; ++k)
                        for (int l = 0; l < 8; ++l) {
                            if (l == i || l == j || l == k) continue;
                            auto x = [&](int m) { return (shift + pts5[m][0]) * s; };
                            auto y = [&](int m) { return (shift + pts5[m][1]) * s; };
                            REQUIRE(check_case(x(i), y(i), x(j), y(j), x(k), y(k), x(l), y(l)) == 0);
                        }
        }
    }
    // A 1-ulp move of the fourth point off the circle is detected on the correct side.
    const double dx = std::nextafter(3.0, 4.0), dy = -4.0;  // (3,-4) pushed outward in x
    REQUIRE(check_case(5, 0, 0, 5, -5, 0, dx, dy) == -1);
    REQUIRE(check_case(5, 0, 0, 5, -5, 0, std::nextafter(3.0, 0.0), dy) == 1);
}

TEST_CASE("incircle: large offsets and tiny scales agree with GMP", "[incircle]") {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(-1, 1);
    for (double offset : {1e10, 1e15, 0x1p+60}) {
        for (double scale : {1.0, 1e-5, 1e-3}) {
            for (int i = 0; i < 500; ++i) {
                double v[8];
                for (double& c : v) c = offset + scale * u(rng);
                check_case(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
            }
        }
    }
    // Near the documented range limits.
    for (double s : {hullkit::kIncircleMaxMagnitude / 4, hullkit::kIncircleMinMagnitude * 4}) {
        for (int i = 0; i < 200; ++i) {
            double v[8];
            for (double& c : v) c = s * u(rng);
            check_case(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
        }
    }
}

TEST_CASE("incircle: degenerate configurations", "[incircle]") {
    REQUIRE(check_case(0, 0, 0, 0, 1, 1, 2, 3) == 0);          // a == b
    REQUIRE(check_case(0, 0, 1, 1, 2, 2, 3, 3) == 0);          // all collinear
    check_case(0, 0, 1, 1, 2, 2, 1, 0);                        // collinear a, b, c, d off the line
    REQUIRE(check_case(1, 2, 3, 4, 5, 7, 1, 2) == 0);          // d == a
}

TEST_CASE("incircle: scale exponent", "[incircle]") {
    int k = 0;
    REQUIRE(hullkit::incircle_scale_exponent(1e100, 1e90, &k));
    REQUIRE(hullkit::incircle_range_ok(std::ldexp(1e100, k), std::ldexp(1e90, k)));
    REQUIRE(hullkit::incircle_scale_exponent(1e-100, 1e-120, &k));
    REQUIRE(hullkit::incircle_range_ok(std::ldexp(1e-100, k), std::ldexp(1e-120, k)));
    REQUIRE_FALSE(hullkit::incircle_scale_exponent(1e200, 1e-200, &k));
}

TEST_CASE("compare_distance: agrees with GMP", "[incircle]") {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(-1, 1);
    auto rational = [](double ax, double ay, double bx, double by, double x, double y) {
        using delaunay_test::q;
        const mpq_class da = (q(ax) - q(x)) * (q(ax) - q(x)) + (q(ay) - q(y)) * (q(ay) - q(y));
        const mpq_class db = (q(bx) - q(x)) * (q(bx) - q(x)) + (q(by) - q(y)) * (q(by) - q(y));
        return sgn(da - db);
    };
    for (int i = 0; i < 5000; ++i) {
        const double ax = u(rng), ay = u(rng), x = u(rng), y = u(rng);
        // b: a reflected through a line through (x, y), then nudged by an ulp: near-ties.
        double bx = 2 * x - ax, by = 2 * y - ay;
        if (i % 2) bx = std::nextafter(bx, 2.0);
        REQUIRE(hullkit::compare_distance(ax, ay, bx, by, x, y) == rational(ax, ay, bx, by, x, y));
        const double cx = u(rng), cy = u(rng);
        REQUIRE(hullkit::compare_distance(ax, ay, cx, cy, x, y) == rational(ax, ay, cx, cy, x, y));
    }
}

TEST_CASE("static bounds: every decision they allow is the exact sign, and they cover stage A's bound", "[incircle]") {
    // Points in boxes of several widths and offsets: uniform, nearly cocircular (on a circle,
    // rounded), nearly collinear, and on the box's corners (the largest differences). Wherever the
    // semi-static bound lets |det| decide, the sign must be GMP's; the bound must be at least
    // stage A's own error bound for the same points (the argument the filters rest on); and
    // orient2d_semi_static / incircle_semi_static must give GMP's sign.
    using namespace hullkit::detail;
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> u(0, 1);
    std::size_t decided_incircle = 0, decided_orient = 0, cases = 0, in_range_cases = 0;
    for (double offset : {0.0, -3.5, 1e7, 0x1p+60}) {
        for (double width : {1.0, 1e-6, 3e5}) {
            const double lo = offset, hi = offset + width;
            const double span = hi - lo;  // as computed: every difference of points in [lo, hi] is at most this
            const double circle_bound = incircle_static_bound(span);
            const double line_bound = orient2d_static_bound(span);
            auto in_box = [&](double t) { return std::min(hi, std::max(lo, lo + t * width)); };
            for (int i = 0; i < 3000; ++i, ++cases) {
                double v[8];
                const int kind = i % 4;
                for (int k = 0; k < 4; ++k) {
                    double x, y;
                    if (kind == 0) {
                        x = in_box(u(rng)), y = in_box(u(rng));
                    } else if (kind == 1) {  // on a circle inside the box, rounded
                        const double angle = 6.283185307179586 * u(rng);
                        x = in_box(0.5 + 0.5 * std::cos(angle)), y = in_box(0.5 + 0.5 * std::sin(angle));
                    } else if (kind == 2) {  // on a line through the box, rounded
                        const double t = u(rng);
                        x = in_box(t), y = in_box(0.25 + 0.5 * t);
                    } else {  // box corners, one of them moved by an ulp
                        x = (rng() & 1) ? hi : lo, y = (rng() & 1) ? hi : lo;
                        if (k == 3) x = x == hi ? std::nextafter(hi, lo) : std::nextafter(lo, hi);
                    }
                    v[2 * k] = x, v[2 * k + 1] = y;
                }
                const IncircleStageA a = incircle_stage_a(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
                REQUIRE(circle_bound >= kIncircleFilterBound * a.permanent);
                if (a.det > circle_bound || -a.det > circle_bound) {
                    ++decided_incircle;
                    REQUIRE((a.det > 0 ? 1 : -1) == gmp_incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
                }
                // The full answer, where the coordinates are in the predicates' exact range (a corner
                // moved off 0 by an ulp is subnormal, outside it).
                double largest = 0, smallest = INFINITY;
                for (double c : v) {
                    largest = std::max(largest, std::fabs(c));
                    if (c != 0) smallest = std::min(smallest, std::fabs(c));
                }
                const bool in_range = hullkit::incircle_range_ok(largest, smallest);
                in_range_cases += in_range;
                if (in_range) {
                    REQUIRE(incircle_semi_static(circle_bound, v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) ==
                            gmp_incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
                }
                const Orient2dStageA o = orient2d_stage_a(v[0], v[1], v[2], v[3], v[4], v[5]);
                const double det = o.det;
                REQUIRE(line_bound >= kOrient2dFilterBound * o.permanent);
                if (det > line_bound || -det > line_bound) {
                    ++decided_orient;
                    REQUIRE((det > 0 ? 1 : -1) == delaunay_test::rational_orient2d(v[0], v[1], v[2], v[3], v[4], v[5]));
                }
                if (in_range) {
                    REQUIRE(orient2d_semi_static(line_bound, v[0], v[1], v[2], v[3], v[4], v[5]) ==
                            delaunay_test::rational_orient2d(v[0], v[1], v[2], v[3], v[4], v[5]));
                }
            }
        }
    }
    // The filters must decide most random cases, or they would be useless.
    CHECK(decided_incircle > cases / 8);
    CHECK(in_range_cases > cases / 2);
    CHECK(decided_orient > cases / 8);
}

TEST_CASE("incircle: near-cocircular points with exact and inexact differences agree with GMP", "[incircle]") {
    // Stage B first tries the determinant in double-double arithmetic. Nearby points on a circle
    // far from the origin have exact differences (Sterbenz), the case where that value decides
    // against a bound of eps^2 rather than eps; points across the origin have inexact ones. Both
    // kinds, rounded onto a circle and moved by a few ulps, must agree with GMP, and the
    // adaptive stages must be reached often.
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> unit(0, 1);
    std::uniform_int_distribution<int> wiggle(-2, 2);
    int adaptive = 0, cases = 0;
    for (double centre : {1.5, 1e6 + 0.25, 0.0}) {
        for (double radius : {1e-3, 0.4, 3.0}) {
            for (int i = 0; i < 1500; ++i, ++cases) {
                double v[8];
                const double base = 2 * M_PI * unit(rng), spread = (i % 3 == 0 ? 1.0 : 1e-4) * 2 * M_PI;
                for (int k = 0; k < 4; ++k) {
                    const double t = base + spread * unit(rng);
                    v[2 * k] = centre + radius * std::cos(t);
                    v[2 * k + 1] = centre + radius * std::sin(t);
                    if (i % 2 == 0) {
                        v[2 * k] = ulp_step(v[2 * k], wiggle(rng));
                        v[2 * k + 1] = ulp_step(v[2 * k + 1], wiggle(rng));
                    }
                }
                check_case(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
                int stage = -1;
                hullkit::detail::incircle_traced(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], &stage);
                adaptive += stage > 0;
            }
        }
    }
    INFO("cases past the filter: " << adaptive << " of " << cases);
    REQUIRE(adaptive > cases / 10);
}

TEST_CASE("incircle: small integer and dyadic grids, cocircular or not, agree with GMP", "[incircle]") {
    // Differences that are small multiples of one power of two are decided by the plain formula
    // on scaled integers (exact below 2^53). Rectangles and isosceles trapezoids are cocircular;
    // random lattice points mostly are not. Coordinates up to 3000 units, in units of 2^-30, 1
    // and 2^40, and offset so that the differences, not the coordinates, are small.
    std::mt19937_64 rng(37);
    std::uniform_int_distribution<int> coordinate(-3000, 3000);
    int zeros = 0;
    for (double unit : {0x1p-30, 1.0, 0x1p+40}) {
        for (double offset : {0.0, 0x1p+20}) {
            for (int i = 0; i < 2000; ++i) {
                double v[8];
                if (i % 2 == 0) {  // a rectangle or trapezoid: cocircular
                    const int x0 = coordinate(rng), y0 = coordinate(rng), w = coordinate(rng) / 2, h = coordinate(rng) / 2;
                    const int inset = i % 4 == 0 ? 0 : coordinate(rng) / 8;
                    const int corners[8] = {x0, y0, x0 + w, y0, x0 + w - inset, y0 + h, x0 + inset, y0 + h};
                    for (int k = 0; k < 8; ++k) v[k] = offset + unit * corners[k];
                } else {
                    for (double& c : v) c = offset + unit * coordinate(rng);
                }
                zeros += check_case(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]) == 0;
            }
        }
    }
    INFO("zeros: " << zeros);
    REQUIRE(zeros > 3000);
}
