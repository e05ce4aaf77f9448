// Thousands of small seeded degenerate inputs: incremental and giftwrap must return identical
// arrays, each checked by verify_delaunay and GMP brute force.
#include <cmath>
#include <random>

#include "delaunay_checks.hpp"

namespace {

/// A small random degenerate input of kind 0..5.
std::vector<double> small_case(int kind, std::mt19937_64& rng) {
    std::uniform_int_distribution<int> count(1, 24), coord(-3, 3), pick(0, 1000);
    std::uniform_real_distribution<double> u(-1, 1);
    const int n = count(rng);
    std::vector<double> xy;
    switch (kind) {
        case 0:  // points of a small integer grid, with repeats
            for (int i = 0; i < n; ++i) xy.insert(xy.end(), {double(coord(rng)), double(coord(rng))});
            break;
        case 1: {  // points of a regular polygon (rounded), some repeated, maybe the centre
            const int sides = 3 + pick(rng) % 10;
            for (int i = 0; i < n; ++i) {
                const double t = 2 * M_PI * (pick(rng) % sides) / sides;
                xy.insert(xy.end(), {std::cos(t), std::sin(t)});
            }
            if (pick(rng) % 2) xy.insert(xy.end(), {0.0, 0.0});
            break;
        }
        case 2: {  // exactly cocircular integer points (radius 5 and 65) plus grid points
            const int r5[][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3},
                                 {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
            for (int i = 0; i < n; ++i) {
                const auto& p = r5[pick(rng) % 12];
                xy.insert(xy.end(), {double(p[0]), double(p[1])});
            }
            if (pick(rng) % 3 == 0) xy.insert(xy.end(), {double(coord(rng)), double(coord(rng))});
            break;
        }
        case 3: {  // collinear points, sometimes with one or two off the line
            const double dx = coord(rng), dy = coord(rng);
            for (int i = 0; i < n; ++i) {
                const double t = coord(rng);
                xy.insert(xy.end(), {t * dx, t * dy});
            }
            for (int extra = pick(rng) % 3; extra > 0; --extra) xy.insert(xy.end(), {u(rng), u(rng)});
            break;
        }
        case 4: {  // a rotated grid (rounding breaks exact cocircularity irregularly)
            const double a = u(rng) * M_PI, c = std::cos(a), s = std::sin(a);
            for (int i = 0; i < n; ++i) {
                const double x = coord(rng), y = coord(rng);
                xy.insert(xy.end(), {c * x - s * y, s * x + c * y});
            }
            break;
        }
        default:  // random points with exact duplicates
            for (int i = 0; i < n; ++i) {
                if (i > 0 && pick(rng) % 3 == 0) {
                    const std::size_t j = 2 * (pick(rng) % (xy.size() / 2));
                    xy.insert(xy.end(), {xy[j], xy[j + 1]});
                } else {
                    xy.insert(xy.end(), {u(rng), u(rng)});
                }
            }
    }
    return xy;
}

}  // namespace

TEST_CASE("delaunay: thousands of seeded small degenerate inputs, both algorithms identical", "[delaunay][degenerate]") {
    std::mt19937_64 rng(2026);
    int two_d = 0;
    for (int i = 0; i < 3000; ++i) {
        const int kind = i % 6;
        const std::vector<double> xy = small_case(kind, rng);
        INFO("case " << i << " kind " << kind << " points " << xy.size() / 2);
        two_d += delaunay_test::both_algorithms(xy).dimension == 2;
    }
    REQUIRE(two_d > 2000);  // most cases really triangulate
}
