// incircle against GMP rationals on adversarial cocircular and near-cocircular inputs.
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
