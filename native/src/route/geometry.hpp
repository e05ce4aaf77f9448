// Private to the route module: the triangle-level geometry every route decision rests on.
//
// Exactness: the intersection tests below (segment-triangle, triangle-triangle, ray crossing) are
// decided by hullkit's exact orient3d / orient2d on the coordinates they are given, so every
// degenerate case (touching, coplanar, collinear, zero-area triangles, zero-length segments) is
// answered exactly for those doubles. The route checker feeds them translated vertices v + w
// rounded to doubles; its decisions are therefore exact for the rounded translated coordinates.
// The distance functions are plain floating point (closest points by region clamping); they are
// used where the answer is a length compared with a positive margin, never for a topological
// decision at clearance zero.
#pragma once

#include <glm/glm.hpp>

namespace hullkit::route_detail {

using Vec = glm::dvec3;

inline const double* ptr(const Vec& v) { return &v.x; }

/// True when the closed segment p0 p1 and the closed triangle q0 q1 q2 share a point. Any of them
/// may be degenerate (p0 == p1; q collinear or a single point).
bool segment_meets_triangle(const Vec& p0, const Vec& p1, const Vec& q0, const Vec& q1,
                            const Vec& q2);

/// True when the closed triangles p and q (3 points each) share a point; exact, any degeneracy.
bool triangles_meet(const Vec* p, const Vec* q);

/// Ray-crossing classification for parity tests: the segment from x to far (x strictly off the
/// triangle's surface is assumed by the caller) against triangle q:
///   0  no crossing,  1  a proper crossing through the triangle's interior,
///  -1  degenerate (the segment touches an edge, a vertex, or ends on the plane): pick another ray.
int ray_crossing(const Vec& x, const Vec& far, const Vec* q);

/// Closest points between triangle p and triangle q in floating point: returns the distance and,
/// in weights_p, barycentric weights of the closest point on p (used to tell where along a sweep
/// the minimum lies). The caller decides intersection exactly first (distance 0).
double triangle_distance(const Vec* p, const Vec* q, double weights_p[3]);
/// The square of triangle_distance (compared with margin^2 it keeps the bits a square root
/// would round away at tangential approaches).
double triangle_distance2(const Vec* p, const Vec* q, double weights_p[3]);

/// The vector from the closest point of triangle q to the closest point of the convex hull of
/// a[0..count) (GJK on their Minkowski difference, floating point, at most 32 steps; zero when they
/// seem to meet): a candidate separating direction, never a decision.
Vec hull_closest_direction(const Vec* a, int count, const Vec* q);

/// Distance from point x to triangle q (floating point, degenerate triangles handled).
double point_triangle_distance(const Vec& x, const Vec* q);

}  // namespace hullkit::route_detail
