// Checks of constrained triangulations shared by tests/delaunay/constrained.cpp and refine.cpp:
// exact areas (GMP) and the library's verifier with its problems reported.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <catch2/catch.hpp>

#include "hullkit/constrained.hpp"

namespace constrained_test {

inline mpq_class q(double v) { return mpq_class(v); }

/// Twice the signed area of the (clockwise) triangles, exactly: positive when they are clockwise.
inline mpq_class twice_area(const hullkit::ConstrainedDelaunay& d) {
    mpq_class sum = 0;
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        const double* a = &d.coords[2 * d.triangles[3 * t]];
        const double* b = &d.coords[2 * d.triangles[3 * t + 1]];
        const double* c = &d.coords[2 * d.triangles[3 * t + 2]];
        sum -= (q(b[0]) - q(a[0])) * (q(c[1]) - q(a[1])) - (q(b[1]) - q(a[1])) * (q(c[0]) - q(a[0]));
    }
    return sum;
}

/// The result is fine and passes verify_constrained (every unshared edge on a segment when
/// `boundary_constrained`, else the hull).
inline void verified(const hullkit::ConstrainedDelaunay& d, bool boundary_constrained) {
    REQUIRE(d.ok());
    const auto report = hullkit::verify_constrained(hullkit::PointSpan2(d.coords), d.triangles.data(), d.triangle_count(),
                                                    d.halfedges.data(), d.constrained.data(), boundary_constrained);
    for (const auto& p : report.problems) UNSCOPED_INFO(p);
    REQUIRE(report.ok);
}

/// The smallest angle of the output, in degrees (long double; measured, not decided).
inline double smallest_angle(const hullkit::ConstrainedDelaunay& d) {
    long double best = 180;
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const double* w = &d.coords[2 * d.triangles[3 * t + k]];
            const double* u = &d.coords[2 * d.triangles[3 * t + (k + 1) % 3]];
            const double* x = &d.coords[2 * d.triangles[3 * t + (k + 2) % 3]];
            const long double ux = u[0] - (long double)w[0], uy = u[1] - (long double)w[1];
            const long double xx = x[0] - (long double)w[0], xy = x[1] - (long double)w[1];
            const long double angle = std::atan2(std::fabs(ux * xy - uy * xx), ux * xx + uy * xy);
            best = std::min(best, angle * 180 / 3.14159265358979323846L);
        }
    }
    return static_cast<double>(best);
}

}  // namespace constrained_test
