// Triangle-level geometry for route checking: exact intersection tests (orient3d / orient2d on the
// given doubles) and floating-point distances. See geometry.hpp for what is exact.
#include "geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hullkit/predicates.hpp"

namespace hullkit::route_detail {

namespace {

struct P2 {
    double u, v;
};

int orient(const P2& a, const P2& b, const P2& c) { return orient2d(a.u, a.v, b.u, b.v, c.u, c.v); }

/// Projection dropping coordinate `axis`; injective on any plane not parallel to that axis.
P2 project(const Vec& p, int axis) {
    switch (axis) {
        case 0: return {p.y, p.z};
        case 1: return {p.z, p.x};
        default: return {p.x, p.y};
    }
}

/// c lies in the bounding box of a, b (meaningful once c is known to be on the line a b).
bool in_box(const P2& a, const P2& b, const P2& c) {
    return std::min(a.u, b.u) <= c.u && c.u <= std::max(a.u, b.u) && std::min(a.v, b.v) <= c.v &&
           c.v <= std::max(a.v, b.v);
}

/// Closed 2-D segments a b and c d share a point (either may be a single point).
bool segments_meet_2d(const P2& a, const P2& b, const P2& c, const P2& d) {
    const int o1 = orient(a, b, c), o2 = orient(a, b, d);
    const int o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && in_box(a, b, c)) || (o2 == 0 && in_box(a, b, d)) ||
           (o3 == 0 && in_box(c, d, a)) || (o4 == 0 && in_box(c, d, b));
}

/// p inside or on the closed 2-D triangle q (q not degenerate).
bool point_in_triangle_2d(const P2& p, const P2* q) {
    const int o1 = orient(q[0], q[1], p), o2 = orient(q[1], q[2], p), o3 = orient(q[2], q[0], p);
    return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

/// The coordinate axis along which the non-collinear points a, b, c project to a proper triangle.
int projection_axis(const Vec& a, const Vec& b, const Vec& c) {
    for (int axis = 0; axis < 3; ++axis) {
        const P2 pa = project(a, axis), pb = project(b, axis), pc = project(c, axis);
        if (orient(pa, pb, pc) != 0) return axis;
    }
    return -1;  // collinear
}

/// Closed 3-D segments p0 p1 and u0 u1 share a point; exact, any degeneracy.
bool segments_meet_3d(const Vec& p0, const Vec& p1, const Vec& u0, const Vec& u1) {
    if (orient3d(ptr(p0), ptr(p1), ptr(u0), ptr(u1)) != 0) return false;
    // Coplanar: project along an axis to which their common plane is not parallel.
    const Vec* triples[4][3] = {{&p0, &p1, &u0}, {&p0, &p1, &u1}, {&p0, &u0, &u1}, {&p1, &u0, &u1}};
    for (const auto& t : triples) {
        const int axis = projection_axis(*t[0], *t[1], *t[2]);
        if (axis >= 0) {
            return segments_meet_2d(project(p0, axis), project(p1, axis), project(u0, axis),
                                    project(u1, axis));
        }
    }
    // All four on one line (or one point): compare intervals along an axis the line is not
    // perpendicular to, where the projection is injective.
    const Vec* pts[4] = {&p0, &p1, &u0, &u1};
    for (int axis = 0; axis < 3; ++axis) {
        bool varies = false;
        for (int i = 1; i < 4; ++i) varies |= (*pts[i])[axis] != p0[axis];
        if (!varies) continue;
        const double plo = std::min(p0[axis], p1[axis]), phi = std::max(p0[axis], p1[axis]);
        const double ulo = std::min(u0[axis], u1[axis]), uhi = std::max(u0[axis], u1[axis]);
        return plo <= uhi && ulo <= phi;
    }
    return true;  // all four points coincide
}

}  // namespace

bool segment_meets_triangle(const Vec& p0, const Vec& p1, const Vec& q0, const Vec& q1,
                            const Vec& q2) {
    if (collinear3d(ptr(q0), ptr(q1), ptr(q2))) {
        // A degenerate triangle is the union of its edges.
        return segments_meet_3d(p0, p1, q0, q1) || segments_meet_3d(p0, p1, q1, q2) ||
               segments_meet_3d(p0, p1, q2, q0);
    }
    const int s0 = orient3d(ptr(q0), ptr(q1), ptr(q2), ptr(p0));
    const int s1 = orient3d(ptr(q0), ptr(q1), ptr(q2), ptr(p1));
    if (s0 * s1 > 0) return false;
    if (s0 == 0 && s1 == 0) {
        // In the triangle's plane: exact 2-D test in a projection that keeps the triangle proper.
        const int axis = projection_axis(q0, q1, q2);
        const P2 q[3] = {project(q0, axis), project(q1, axis), project(q2, axis)};
        const P2 a = project(p0, axis), b = project(p1, axis);
        return point_in_triangle_2d(a, q) || point_in_triangle_2d(b, q) ||
               segments_meet_2d(a, b, q[0], q[1]) || segments_meet_2d(a, b, q[1], q[2]) ||
               segments_meet_2d(a, b, q[2], q[0]);
    }
    // The segment reaches the plane at exactly one point; its line passes through the closed
    // triangle iff the line is on the same side of (or on) all three edge lines.
    const int o1 = orient3d(ptr(p0), ptr(p1), ptr(q0), ptr(q1));
    const int o2 = orient3d(ptr(p0), ptr(p1), ptr(q1), ptr(q2));
    const int o3 = orient3d(ptr(p0), ptr(p1), ptr(q2), ptr(q0));
    return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

bool triangles_meet(const Vec* p, const Vec* q) {
    // Quick exact rejections: all of one triangle strictly on one side of the other's plane.
    int above = 0, below = 0;
    for (int i = 0; i < 3; ++i) {
        const int s = orient3d(ptr(q[0]), ptr(q[1]), ptr(q[2]), ptr(p[i]));
        above += s > 0;
        below += s < 0;
    }
    if (above == 3 || below == 3) return false;
    above = below = 0;
    for (int i = 0; i < 3; ++i) {
        const int s = orient3d(ptr(p[0]), ptr(p[1]), ptr(p[2]), ptr(q[i]));
        above += s > 0;
        below += s < 0;
    }
    if (above == 3 || below == 3) return false;
    // Two closed triangles meet iff an edge of one meets the other: the intersection (a segment,
    // a point or a convex polygon) has its extreme points on the boundary of one of them.
    for (int i = 0; i < 3; ++i) {
        if (segment_meets_triangle(p[i], p[(i + 1) % 3], q[0], q[1], q[2])) return true;
    }
    for (int i = 0; i < 3; ++i) {
        if (segment_meets_triangle(q[i], q[(i + 1) % 3], p[0], p[1], p[2])) return true;
    }
    return false;
}

int ray_crossing(const Vec& x, const Vec& far, const Vec* q) {
    if (collinear3d(ptr(q[0]), ptr(q[1]), ptr(q[2]))) {
        return segment_meets_triangle(x, far, q[0], q[1], q[2]) ? -1 : 0;
    }
    const int sx = orient3d(ptr(q[0]), ptr(q[1]), ptr(q[2]), ptr(x));
    const int sf = orient3d(ptr(q[0]), ptr(q[1]), ptr(q[2]), ptr(far));
    if (sx * sf > 0) return 0;
    if (sx == 0 || sf == 0) return segment_meets_triangle(x, far, q[0], q[1], q[2]) ? -1 : 0;
    const int o1 = orient3d(ptr(x), ptr(far), ptr(q[0]), ptr(q[1]));
    const int o2 = orient3d(ptr(x), ptr(far), ptr(q[1]), ptr(q[2]));
    const int o3 = orient3d(ptr(x), ptr(far), ptr(q[2]), ptr(q[0]));
    if ((o1 > 0 && o2 > 0 && o3 > 0) || (o1 < 0 && o2 < 0 && o3 < 0)) return 1;
    if ((o1 > 0 || o2 > 0 || o3 > 0) && (o1 < 0 || o2 < 0 || o3 < 0)) return 0;
    return -1;  // through an edge or a vertex
}

namespace {

/// Closest point to x on segment a b: returns the parameter s in [0, 1] (a + s (b - a)).
double closest_on_segment(const Vec& x, const Vec& a, const Vec& b) {
    const Vec ab = b - a;
    const double len2 = glm::dot(ab, ab);
    if (!(len2 > 0.0)) return 0.0;
    return std::clamp(glm::dot(x - a, ab) / len2, 0.0, 1.0);
}

/// Closest point to x on triangle q as barycentric weights w (Voronoi regions of the vertices,
/// edges and face); degenerate triangles fall back to their edges.
void closest_on_triangle(const Vec& x, const Vec* q, double w[3]) {
    const Vec ab = q[1] - q[0], ac = q[2] - q[0], ax = x - q[0];
    const double d1 = glm::dot(ab, ax), d2 = glm::dot(ac, ax);
    const Vec n = glm::cross(ab, ac);
    const double n2 = glm::dot(n, n);
    const double scale = glm::dot(ab, ab) * glm::dot(ac, ac);
    if (!(n2 > 1e-24 * scale)) {
        // (Nearly) degenerate: the closest point lies on one of the edges.
        double best = std::numeric_limits<double>::infinity();
        for (int i = 0; i < 3; ++i) {
            const Vec& a = q[i];
            const Vec& b = q[(i + 1) % 3];
            const double s = closest_on_segment(x, a, b);
            const Vec c = a + s * (b - a);
            const double d = glm::dot(x - c, x - c);
            if (d < best) {
                best = d;
                w[i] = 1.0 - s;
                w[(i + 1) % 3] = s;
                w[(i + 2) % 3] = 0.0;
            }
        }
        return;
    }
    auto set = [&](double a, double b, double c) { w[0] = a, w[1] = b, w[2] = c; };
    if (d1 <= 0.0 && d2 <= 0.0) return set(1, 0, 0);
    const Vec bx = x - q[1];
    const double d3 = glm::dot(ab, bx), d4 = glm::dot(ac, bx);
    if (d3 >= 0.0 && d4 <= d3) return set(0, 1, 0);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double s = d1 / (d1 - d3);
        return set(1 - s, s, 0);
    }
    const Vec cx = x - q[2];
    const double d5 = glm::dot(ab, cx), d6 = glm::dot(ac, cx);
    if (d6 >= 0.0 && d5 <= d6) return set(0, 0, 1);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double s = d2 / (d2 - d6);
        return set(1 - s, 0, s);
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double s = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return set(0, 1 - s, s);
    }
    const double denom = 1.0 / (va + vb + vc);
    const double v = vb * denom, u = vc * denom;
    set(1 - v - u, v, u);
}

/// Closest points between segments p0 p1 and q0 q1: parameters s (on p) and t (on q) in [0, 1].
void closest_between_segments(const Vec& p0, const Vec& p1, const Vec& q0, const Vec& q1,
                              double* s_out, double* t_out) {
    const Vec d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    double s = 0.0, t = 0.0;
    if (!(a > 0.0) && !(e > 0.0)) {
        // two points
    } else if (!(a > 0.0)) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = glm::dot(d1, r);
        if (!(e > 0.0)) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = glm::dot(d1, d2);
            const double denom = a * e - b * b;  // >= 0; 0 when parallel
            s = denom > 1e-30 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    *s_out = s;
    *t_out = t;
}

double length2(const Vec& v) { return glm::dot(v, v); }

}  // namespace

double point_triangle_distance(const Vec& x, const Vec* q) {
    double w[3];
    closest_on_triangle(x, q, w);
    return std::sqrt(length2(x - (w[0] * q[0] + w[1] * q[1] + w[2] * q[2])));
}

namespace {

/// The point of the simplex s[0..n) (n <= 4 points) closest to the origin; s is reduced to the
/// points that carry it (the smallest face holding it).
Vec simplex_closest(Vec* s, int& n) {
    const Vec origin(0.0);
    if (n == 1) return s[0];
    if (n == 2) {
        const double t = closest_on_segment(origin, s[0], s[1]);
        if (t <= 0.0) {
            n = 1;
        } else if (t >= 1.0) {
            s[0] = s[1];
            n = 1;
        }
        return s[0] + t * (s[1] - s[0]);
    }
    if (n == 4) {
        // Inside the tetrahedron (each face sees the origin on the side of the opposite point):
        // the sets meet as far as floating point can tell.
        static constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}};
        bool inside = true;
        double best = std::numeric_limits<double>::infinity();
        Vec best_point(0.0), best_face[3];
        int best_count = 0;
        for (const auto& f : kFaces) {
            const Vec face[3] = {s[f[0]], s[f[1]], s[f[2]]};
            const Vec normal = glm::cross(face[1] - face[0], face[2] - face[0]);
            const double side_origin = glm::dot(normal, -face[0]), side_other = glm::dot(normal, s[f[3]] - face[0]);
            if (side_origin * side_other < 0.0 || side_other == 0.0) inside = false;
            double w[3];
            closest_on_triangle(origin, face, w);
            const Vec c = w[0] * face[0] + w[1] * face[1] + w[2] * face[2];
            if (length2(c) < best) {
                best = length2(c);
                best_point = c;
                best_count = 0;
                for (int k = 0; k < 3; ++k) {
                    if (w[k] > 0.0) best_face[best_count++] = face[k];
                }
            }
        }
        if (inside) return origin;
        n = best_count;
        for (int k = 0; k < n; ++k) s[k] = best_face[k];
        return best_point;
    }
    double w[3];
    closest_on_triangle(origin, s, w);
    const Vec c = w[0] * s[0] + w[1] * s[1] + w[2] * s[2];
    int kept = 0;
    for (int k = 0; k < 3; ++k) {
        if (w[k] > 0.0) s[kept++] = s[k];
    }
    n = kept;
    return c;
}

}  // namespace

Vec hull_closest_direction(const Vec* a, int count, const Vec* q) {
    // Support points of A - Q in direction -v: the point of A lowest along v minus Q's highest.
    auto support = [&](const Vec& v) {
        int ia = 0, iq = 0;
        double lo = glm::dot(v, a[0]), hi = glm::dot(v, q[0]);
        for (int k = 1; k < count; ++k) {
            const double x = glm::dot(v, a[k]);
            if (x < lo) lo = x, ia = k;
        }
        for (int k = 1; k < 3; ++k) {
            const double x = glm::dot(v, q[k]);
            if (x > hi) hi = x, iq = k;
        }
        return a[ia] - q[iq];
    };
    Vec s[4] = {a[0] - q[0]};
    int n = 1;
    Vec v = s[0];
    for (int step = 0; step < 32; ++step) {
        const double vv = length2(v);
        if (!(vv > 0.0)) break;
        const Vec w = support(v);
        // Converged: no point of the difference is much lower along v than v itself.
        if (vv - glm::dot(v, w) <= 1e-12 * vv) break;
        bool repeated = false;
        for (int k = 0; k < n; ++k) repeated = repeated || s[k] == w;
        if (repeated) break;
        s[n++] = w;
        const Vec next = simplex_closest(s, n);
        if (!(length2(next) < vv)) break;  // no progress in floating point
        v = next;
    }
    return v;
}

double triangle_distance(const Vec* p, const Vec* q, double weights_p[3]) {
    return std::sqrt(triangle_distance2(p, q, weights_p));
}

double triangle_distance2(const Vec* p, const Vec* q, double weights_p[3]) {
    // Between disjoint triangles the closest pair is vertex-face or edge-edge.
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {  // vertices of p against q
        double w[3];
        closest_on_triangle(p[i], q, w);
        const double d = length2(p[i] - (w[0] * q[0] + w[1] * q[1] + w[2] * q[2]));
        if (d < best) {
            best = d;
            weights_p[0] = weights_p[1] = weights_p[2] = 0.0;
            weights_p[i] = 1.0;
        }
    }
    for (int i = 0; i < 3; ++i) {  // vertices of q against p
        double w[3];
        closest_on_triangle(q[i], p, w);
        const double d = length2(q[i] - (w[0] * p[0] + w[1] * p[1] + w[2] * p[2]));
        if (d < best) {
            best = d;
            std::copy(w, w + 3, weights_p);
        }
    }
    for (int i = 0; i < 3; ++i) {  // edges against edges
        const Vec& a = p[i];
        const Vec& b = p[(i + 1) % 3];
        for (int j = 0; j < 3; ++j) {
            const Vec& c = q[j];
            const Vec& e = q[(j + 1) % 3];
            double s, t;
            closest_between_segments(a, b, c, e, &s, &t);
            const double d = length2((a + s * (b - a)) - (c + t * (e - c)));
            if (d < best) {
                best = d;
                weights_p[i] = 1.0 - s;
                weights_p[(i + 1) % 3] = s;
                weights_p[(i + 2) % 3] = 0.0;
            }
        }
    }
    if (best > 0.0 && triangles_meet(p, q)) best = 0.0;
    return best;
}

}  // namespace hullkit::route_detail
