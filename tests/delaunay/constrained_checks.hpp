// Checks of constrained triangulations shared by tests/delaunay/constrained.cpp and refine.cpp:
// exact areas (GMP) and the library's verifier with its problems reported.
#pragma once

#include <gmpxx.h>

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

}  // namespace constrained_test
