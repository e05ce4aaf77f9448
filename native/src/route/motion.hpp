// Private to the route module: the motion of the traverse along one leg, and the coordinates of a
// traverse vertex at a pose.
//
// A pose is a unit quaternion q = (w, x, y, z) and an offset o: a traverse vertex v (in the
// traverse's own coordinates) is placed at
//     place(v) = fl(fl(c + R(q) fl(v - c)) + o)           (c the traverse's pivot)
// with every operation rounded to double in the order written, and place(v) = fl(v + o) exactly
// when R(q) is the identity matrix (q = ±(1, 0, 0, 0)), so that routes without rotations keep
// today's coordinates bit for bit. Over a leg from pose (q0, o0) to (q1, o1), at fraction t:
//     o(t) = o0 + t (o1 - o0)   (exactly o1 at t = 1)
//     q(t) = q0 (cos(t phi), sin(t phi) a)                    (exactly q1 at t = 1)
// where q0* q1 = ±(cos phi, sin phi a), a unit axis in the traverse's coordinates, phi in [0, pi/2]
// (the shorter arc: slerp). The traverse turns by theta = 2 phi about the axis R(q0) a through
// the moving pivot c + o(t), at constant angular speed.
//
// The bound behind turning legs (RouteChecker on legs whose orientations differ). A point at
// distance r from the rotation axis moves, relative to the pivot, along a circular arc through
// angle theta (t1 - t0) over [t0, t1]; the translation is linear in t. Its path p(t) has
// |p''(t)| = r theta^2 (per unit of t), so by the remainder of linear interpolation,
// |p(t) - ((t1 - t) p(t0) + (t - t0) p(t1)) / (t1 - t0)| <= (t - t0)(t1 - t)/2 * r theta^2
//                                                         <= r (theta (t1 - t0))^2 / 8  =: delta
// (the bound holds for vector-valued functions: the interpolation error is the integral of p''
// against a non-negative kernel of total mass (t - t0)(t1 - t)/2). A point of a triangle is an
// affine combination of its vertices and the motion is affine in the point, so every point of the
// triangle stays within the largest delta of its vertices from the convex hull of the triangle's
// two end poses; the same holds for any set of points with r the largest distance of the set from
// the axis. Rounding: the placed coordinates differ from the exact real motion by a few ulps of
// (|c| + |v - c| + |o|), the computed theta and axis from the exact ones by a few ulps; the route
// checker grows every bound by its tolerance (1e-12 of the scene's scale), which is far larger.
#pragma once

#include "geometry.hpp"

namespace hullkit::route_detail {

struct Quat {
    double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
};

inline bool operator==(const Quat& a, const Quat& b) {
    return a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z;
}

/// True when q and r are the same rotation bit for bit (r == q or r == -q).
inline bool same_rotation(const Quat& q, const Quat& r) {
    return q == r || (q.w == -r.w && q.x == -r.x && q.y == -r.y && q.z == -r.z);
}

/// A rotation matrix (rows) and whether it is exactly the identity.
struct Rotation {
    Vec row[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    bool identity = true;

    Vec apply(const Vec& v) const {
        return {glm::dot(row[0], v), glm::dot(row[1], v), glm::dot(row[2], v)};
    }
    /// The transpose applied (the inverse rotation, up to rounding).
    Vec apply_transpose(const Vec& v) const { return row[0] * v.x + row[1] * v.y + row[2] * v.z; }
};

/// The matrix of a unit quaternion (its sign does not matter: every entry is quadratic in q).
Rotation rotation_of(const Quat& q);

/// A pose: where the traverse's points go.
struct Pose {
    Rotation rotation;
    Vec offset{0.0};
};

/// The traverse vertex v (own coordinates) at `pose`, rounded as the header describes.
inline Vec place(const Pose& pose, const Vec& pivot, const Vec& v) {
    if (pose.rotation.identity) return v + pose.offset;
    return (pivot + pose.rotation.apply(v - pivot)) + pose.offset;
}

/// One leg's motion.
struct LegMotion {
    Vec o0, o1, pivot;
    Quat q0, q1;       ///< q1 on q0's side (q0 . q1 >= 0)
    Vec axis{0.0};     ///< unit rotation axis in the traverse's own coordinates
    double phi = 0.0;  ///< half the angle turned
    double theta = 0.0;  ///< the angle turned over the whole leg, in [0, pi]

    LegMotion(const Vec& o0, const Vec& o1, const Quat& q0, const Quat& q1, const Vec& pivot);

    bool turns() const { return theta > 0.0; }
    /// The pose at fraction t in [0, 1]: exactly (q0, o0) at 0 and (q1, o1) at 1.
    Pose at(double t) const;
    /// The orientation at fraction t.
    Quat orientation(double t) const;
    /// The largest distance of `box`'s points from the rotation axis through the pivot.
    double radius(const Vec& lo, const Vec& hi) const;
    /// The distance of v from the rotation axis through the pivot.
    double radius(const Vec& v) const;
    /// delta for points within `radius` of the axis over a sub-interval of length `span`, grown
    /// by a relative 1e-9 for the rounding of theta.
    double deviation(double radius, double span) const {
        const double turned = theta * span;
        return radius * turned * turned * (0.125 * (1.0 + 1e-9));
    }
};

/// The Hamilton product a b.
Quat multiply(const Quat& a, const Quat& b);

// Sine, cosine and arctangent from +, -, *, / and sqrt alone (no FMA: the build has
// -ffp-contract=off), so that every platform gets the same bits: libm's sin and cos differ in the
// last bit between glibc (native) and musl (the wasm build). Accurate to a few ulps.

/// sin x and cos x; x is reduced by multiples of pi/2 (two-part constant: accurate for |x| up to
/// about 1e6, deterministic for any finite x).
void sin_cos(double x, double* s, double* c);
/// The angle of (x, y) for x >= 0, y >= 0: in [0, pi/2].
double first_quadrant_angle(double y, double x);
/// sin and cos of `degrees` (exactly reduced modulo 360 first).
void sin_cos_degrees(double degrees, double* s, double* c);

}  // namespace hullkit::route_detail
