// The motion of the traverse along a leg: quaternion arithmetic, the slerp pose at a fraction,
// and distances from the rotation axis (see motion.hpp for the conventions and the bound).
#include "motion.hpp"

#include <algorithm>
#include <cmath>

namespace hullkit::route_detail {

Quat multiply(const Quat& a, const Quat& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

namespace {

constexpr double kHalfPi = 1.57079632679489661923;
// pi/2 = kHalfPiHigh + kHalfPiLow, the first with 33 significant bits so that k * kHalfPiHigh is
// exact for |k| < 2^20.
constexpr double kHalfPiHigh = 1.5707963267341256;
constexpr double kHalfPiLow = 6.077100506506192e-11;

/// sin r and cos r for |r| <= pi/4: Taylor series to r^19 and r^18 (remainders below 1e-19), by
/// Horner's rule over 1/n!.
void sin_cos_reduced(double r, double* s, double* c) {
    static constexpr double kInverseFactorial[20] = {
        1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720, 1.0 / 5040, 1.0 / 40320, 1.0 / 362880,
        1.0 / 3628800, 1.0 / 39916800, 1.0 / 479001600, 1.0 / 6227020800.0, 1.0 / 87178291200.0,
        1.0 / 1307674368000.0, 1.0 / 20922789888000.0, 1.0 / 355687428096000.0, 1.0 / 6402373705728000.0,
        1.0 / 121645100408832000.0};
    const double r2 = r * r;
    double sp = kInverseFactorial[19], cp = kInverseFactorial[18];
    for (int n = 17; n >= 1; n -= 2) sp = kInverseFactorial[n] - r2 * sp;
    for (int n = 16; n >= 0; n -= 2) cp = kInverseFactorial[n] - r2 * cp;
    *s = r * sp;
    *c = cp;
}

/// atan z for 0 <= z <= tan(pi/8) (series to z^45: the remainder is below 1e-18).
double atan_small(double z) {
    const double z2 = z * z;
    double sum = 0.0;
    for (int n = 45; n >= 1; n -= 2) sum = 1.0 / n - z2 * sum;
    return z * sum;
}

/// atan z for 0 <= z <= 1.
double atan_unit(double z) {
    constexpr double kTanEighthPi = 0.41421356237309503;  // sqrt(2) - 1
    if (z <= kTanEighthPi) return atan_small(z);
    return 0.5 * kHalfPi - atan_small((1.0 - z) / (1.0 + z));  // atan z = pi/4 + atan((z - 1)/(z + 1))
}

}  // namespace

void sin_cos(double x, double* s, double* c) {
    const double k = std::nearbyint(x / kHalfPi);
    const double r = (x - k * kHalfPiHigh) - k * kHalfPiLow;
    double sr, cr;
    sin_cos_reduced(r, &sr, &cr);
    const long quadrant = static_cast<long>(std::fmod(k, 4.0) + 4.0) % 4;
    switch (quadrant) {
        case 0: *s = sr, *c = cr; break;
        case 1: *s = cr, *c = -sr; break;
        case 2: *s = -sr, *c = -cr; break;
        default: *s = -cr, *c = sr; break;
    }
}

void sin_cos_degrees(double degrees, double* s, double* c) {
    // fmod is exact; a multiple of 90 degrees gives exact values.
    const double reduced = std::fmod(degrees, 360.0);
    const double quarter = reduced / 90.0;
    if (quarter == std::floor(quarter)) {
        static const double sines[] = {0.0, 1.0, 0.0, -1.0};
        const long q = (static_cast<long>(quarter) % 4 + 4) % 4;
        *s = sines[q];
        *c = sines[(q + 1) % 4];
        return;
    }
    sin_cos(reduced * (kHalfPi / 90.0), s, c);
}

double first_quadrant_angle(double y, double x) {
    if (!(y > 0.0)) return 0.0;
    if (!(x > 0.0)) return kHalfPi;
    return y <= x ? atan_unit(y / x) : kHalfPi - atan_unit(x / y);
}

Rotation rotation_of(const Quat& q) {
    Rotation r;
    const double w = q.w, x = q.x, y = q.y, z = q.z;
    r.row[0] = {1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)};
    r.row[1] = {2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)};
    r.row[2] = {2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)};
    r.identity = r.row[0] == Vec(1, 0, 0) && r.row[1] == Vec(0, 1, 0) && r.row[2] == Vec(0, 0, 1);
    return r;
}

LegMotion::LegMotion(const Vec& o0_, const Vec& o1_, const Quat& q0_, const Quat& q1_, const Vec& pivot_)
    : o0(o0_), o1(o1_), pivot(pivot_), q0(q0_), q1(q1_) {
    if (same_rotation(q0, q1)) {
        q1 = q0;
        return;
    }
    if (q0.w * q1.w + q0.x * q1.x + q0.y * q1.y + q0.z * q1.z < 0.0) q1 = Quat{-q1.w, -q1.x, -q1.y, -q1.z};
    // The relative rotation q0* q1 = (cos phi, sin phi a).
    const Quat relative = multiply(Quat{q0.w, -q0.x, -q0.y, -q0.z}, q1);
    const Vec v(relative.x, relative.y, relative.z);
    const double s = glm::length(v);
    if (!(s > 0.0)) {  // the same rotation up to rounding: a translation with q0 throughout
        q1 = q0;
        return;
    }
    axis = v / s;
    phi = first_quadrant_angle(s, std::max(relative.w, 0.0));
    theta = 2.0 * phi;
}

Quat LegMotion::orientation(double t) const {
    if (t == 0.0 || !turns()) return q0;
    if (t == 1.0) return q1;
    double s, c;
    sin_cos(t * phi, &s, &c);
    return multiply(q0, Quat{c, s * axis.x, s * axis.y, s * axis.z});
}

Pose LegMotion::at(double t) const {
    Pose pose;
    pose.rotation = rotation_of(orientation(t));
    pose.offset = t == 1.0 ? o1 : o0 + t * (o1 - o0);
    return pose;
}

double LegMotion::radius(const Vec& v) const {
    const Vec d = v - pivot;
    return glm::length(d - axis * glm::dot(axis, d));
}

double LegMotion::radius(const Vec& lo, const Vec& hi) const {
    // The distance from a line is convex, so over a box it is largest at a corner.
    double r = 0.0;
    for (int k = 0; k < 8; ++k) {
        const Vec corner(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
        r = std::max(r, radius(corner));
    }
    return r * (1.0 + 1e-12);
}

}  // namespace hullkit::route_detail
