// hullkit::plane_equations: the plane of each triangle as a unit normal and an offset, the facet
// equations qconvex's `n` prints and scipy's ConvexHull.equations holds. A construction, not a
// decision: the triangles come from the exact hull, their planes are rounded to doubles.
//
// Each normal is the cross product of two edges, taken at the corner opposite the longest edge (the
// largest angle, where the cross product cancels least). In plain doubles when a bound on its
// rounding error says every component is within 2^-46 of the largest one's magnitude; otherwise
// (a nearly flat triangle) from the exact cross product (exact differences, expansion products),
// rounded once. Before that the corners are scaled by a power of two (exact), and so are the edges,
// so that no product overflows or underflows whatever the magnitudes.
#include "hullkit/hull.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "exact/expansion.hpp"

namespace hullkit {
namespace {

using exact_detail::estimate;
using exact_detail::exact_diff;
using exact_detail::exact_minor;
using exact_detail::kEpsilon;

/// The power of two that brings `magnitude` (> 0, finite) into [0.5, 1) when multiplied by it; 1
/// when `magnitude` is within 2^-range .. 2^range already (no scaling needed: the common case,
/// without frexp and ldexp). Scaling by a power of two, or not, gives the same normals' bits
/// (every operation scales exactly), so the choice never shows.
double unit_scale(double magnitude, double range) {
    if (magnitude > 1.0 / range && magnitude < range) return 1.0;
    int exponent = 0;
    std::frexp(magnitude, &exponent);
    return std::ldexp(1.0, -exponent);
}

double max_abs(const double* v) { return std::fmax(std::fabs(v[0]), std::fmax(std::fabs(v[1]), std::fabs(v[2]))); }

/// The exact cross product (se (q - p)) x (sf (r - p)), each component rounded from its exact
/// value; se and sf are powers of two that bring the edges near 1 (no product underflows).
void exact_cross(const double* p, const double* q, const double* r, double se, double sf, double* n) {
    double e[3][2], f[3][2];
    int elen[3], flen[3];
    for (int k = 0; k < 3; ++k) {
        elen[k] = exact_diff(q[k], p[k], e[k]);
        flen[k] = exact_diff(r[k], p[k], f[k]);
        for (int i = 0; i < elen[k]; ++i) e[k][i] *= se;
        for (int i = 0; i < flen[k]; ++i) f[k][i] *= sf;
    }
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;  // n_k = e_i f_j - e_j f_i
        double h[16];
        const int hlen = exact_minor(elen[i], e[i], flen[j], f[j], elen[j], e[j], flen[i], f[i], h);
        n[k] = estimate(hlen, h);
    }
}

/// The plane of triangle (a, b, c) into out[0..3]: nx ny nz offset.
void plane_of(const double* a, const double* b, const double* c, double* out) {
    const double largest = std::fmax(max_abs(a), std::fmax(max_abs(b), max_abs(c)));
    if (!(largest > 0.0) || !std::isfinite(largest)) {
        for (int k = 0; k < 4; ++k) out[k] = 0.0;
        return;
    }
    // The corners scaled into [-1, 1] (exact), then taken from the one opposite the longest edge,
    // the order (and so the orientation) kept.
    const double s = unit_scale(largest, 0x1p300);
    const double scaled[3][3] = {{a[0] * s, a[1] * s, a[2] * s}, {b[0] * s, b[1] * s, b[2] * s}, {c[0] * s, c[1] * s, c[2] * s}};
    double longest = -1.0;
    int first = 0;
    for (int k = 0; k < 3; ++k) {
        const double* u = scaled[(k + 1) % 3];
        const double* v = scaled[(k + 2) % 3];
        const double d[3] = {v[0] - u[0], v[1] - u[1], v[2] - u[2]};
        const double length = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (length > longest) {
            longest = length;
            first = k;
        }
    }
    const double* p = scaled[first];
    const double* q = scaled[(first + 1) % 3];
    const double* r = scaled[(first + 2) % 3];
    double e[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    double f[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double e_max = max_abs(e), f_max = max_abs(f);
    double n[3] = {0.0, 0.0, 0.0};
    if (e_max > 0.0 && f_max > 0.0) {
        const double se = unit_scale(e_max, 0x1p200), sf = unit_scale(f_max, 0x1p200);
        for (int k = 0; k < 3; ++k) {
            e[k] *= se;
            f[k] *= sf;
        }
        double error = 0.0;
        for (int k = 0; k < 3; ++k) {
            const int i = (k + 1) % 3, j = (k + 2) % 3;
            const double u = e[i] * f[j], v = e[j] * f[i];
            n[k] = u - v;
            // Rounded edges (1 + d each), rounded products and difference: within
            // (3 eps + O(eps^2)) (|u| + |v|) + eps |n_k| of the exact component.
            error = std::fmax(error, 4.0 * kEpsilon * (std::fabs(u) + std::fabs(v)) + kEpsilon * std::fabs(n[k]));
        }
        const double n_max = max_abs(n);
        if (!(n_max > 0.0 && error <= 0x1p-46 * n_max)) {
            // Nearly flat: the exact cross product (only its direction is kept).
            exact_cross(p, q, r, se, sf, n);
        }
    }
    const double n_max = max_abs(n);
    if (!(n_max > 0.0)) {  // a triangle without area (a hull has none): no plane
        for (int k = 0; k < 4; ++k) out[k] = 0.0;
        return;
    }
    const double sn = unit_scale(n_max, 0x1p400);
    for (double& v : n) v *= sn;
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    // (+ 0.0: a zero is written "0", never "-0".)
    for (int k = 0; k < 3; ++k) out[k] = n[k] / length + 0.0;
    // From the scaled corner, then unscaled (exact): no product underflows or overflows.
    out[3] = -(out[0] * p[0] + out[1] * p[1] + out[2] * p[2]) / s + 0.0;
}

}  // namespace

std::vector<double> plane_equations(PointSpan points, const std::uint32_t* triangles, std::size_t triangle_count) {
    std::vector<double> equations(4 * triangle_count);
    for (std::size_t t = 0; t < triangle_count; ++t) {
        const std::uint32_t* corners = triangles + 3 * t;
        for (int k = 0; k < 3; ++k) {
            if (corners[k] >= points.count) {
                throw std::invalid_argument("triangle " + std::to_string(t) + " has corner " + std::to_string(corners[k]) +
                                            ", out of range for " + std::to_string(points.count) + " points");
            }
        }
        plane_of(points[corners[0]], points[corners[1]], points[corners[2]], &equations[4 * t]);
    }
    return equations;
}

std::vector<double> plane_equations(PointSpan points, const Hull& hull) {
    return plane_equations(points, hull.triangles.data(), hull.triangles.size() / 3);
}

}  // namespace hullkit
