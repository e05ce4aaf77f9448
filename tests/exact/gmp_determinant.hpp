// Exact determinants over GMP rationals, for the tests that compare the value a floating-point
// predicate computes with the exact one by a different formula (tests/exact/lattice.cpp,
// tests/delaunay3/lattice.cpp).
#pragma once

#include <gmpxx.h>

namespace exact_test {

/// The determinant of the 3x3 matrix with rows p, q, s.
inline mpq_class det3(const mpq_class* p, const mpq_class* q, const mpq_class* s) {
    return p[0] * (q[1] * s[2] - q[2] * s[1]) - p[1] * (q[0] * s[2] - q[2] * s[0]) + p[2] * (q[0] * s[1] - q[1] * s[0]);
}

/// The determinant of the 4x4 matrix whose row i is rows[i][0..2] followed by last[i], expanded
/// along that last column.
inline mpq_class det4_by_last_column(const mpq_class (&rows)[4][3], const mpq_class (&last)[4]) {
    mpq_class det = 0;
    for (int skip = 0; skip < 4; ++skip) {
        int r[3], n = 0;
        for (int i = 0; i < 4; ++i)
            if (i != skip) r[n++] = i;
        const mpq_class minor = det3(rows[r[0]], rows[r[1]], rows[r[2]]);
        det += (skip % 2 == 1 ? 1 : -1) * last[skip] * minor;  // (-1)^(skip + 3)
    }
    return det;
}

}  // namespace exact_test
