// Side tests the hull algorithms are written against, as policy classes:
//   orient_xy(a, b, c)             side of c from the directed line a->b, x-y plane (+1 left)
//   orient_in_plane(a, b, c, i, j) the same in the plane of axes i, j
//   orient3d(a, b, c, d)           side of d from the plane of a, b, c (+1 where (b-a)x(c-a) points)
//   collinear(a, b, c)             c on the line through a and b
// ExactSides answers exactly (hullkit/predicates.hpp); SeedEpsilon the way the seed document does.
#pragma once

#include <cfloat>
#include <cmath>

#include <glm/glm.hpp>

#include "hullkit/hull.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit::detail {

inline glm::dvec3 vec3(const double* p) { return {p[0], p[1], p[2]}; }

struct ExactSides {
    int orient_xy(const double* a, const double* b, const double* c) const {
        return orient2d(a[0], a[1], b[0], b[1], c[0], c[1]);
    }
    int orient_in_plane(const double* a, const double* b, const double* c, int i, int j) const {
        return orient2d(a[i], a[j], b[i], b[j], c[i], c[j]);
    }
    int orient3d(const double* a, const double* b, const double* c, const double* d) const {
        return hullkit::orient3d(a, b, c, d);
    }
    bool collinear(const double* a, const double* b, const double* c) const { return collinear3d(a, b, c) != 0; }
};

/// The seed document's tests: signed distances (unit normals) compared with an epsilon scaled to
/// the taxicab extent of the cloud, eps_2D = DBL_EPSILON * (dx + dy) for the flattened step and
/// eps_3D = DBL_EPSILON * (dx + dy + dz) otherwise. 0 means "within epsilon".
class SeedEpsilon {
public:
    explicit SeedEpsilon(PointSpan points) {
        glm::dvec3 lo(0.0), hi(0.0);
        if (points.count > 0) lo = hi = vec3(points[0]);
        for (std::size_t i = 1; i < points.count; ++i) {
            lo = glm::min(lo, vec3(points[i]));
            hi = glm::max(hi, vec3(points[i]));
        }
        const glm::dvec3 extent = hi - lo;
        eps_2d_ = DBL_EPSILON * (extent.x + extent.y);
        eps_3d_ = DBL_EPSILON * (extent.x + extent.y + extent.z);
    }

    int orient_xy(const double* a, const double* b, const double* c) const {
        return orient_projected(a, b, c, 0, 1, eps_2d_);
    }
    int orient_in_plane(const double* a, const double* b, const double* c, int i, int j) const {
        return orient_projected(a, b, c, i, j, eps_3d_);
    }
    int orient3d(const double* a, const double* b, const double* c, const double* d) const {
        const glm::dvec3 pa = vec3(a);
        const glm::dvec3 n = glm::cross(vec3(b) - pa, vec3(c) - vec3(b));
        const double length = glm::length(n);
        if (length == 0.0) return 0;
        return sign(glm::dot(n, vec3(d) - pa) / length, eps_3d_);
    }
    bool collinear(const double* a, const double* b, const double* c) const {
        const glm::dvec3 e = vec3(b) - vec3(a);
        const double length = glm::length(e);
        if (length == 0.0) return true;
        return glm::length(glm::cross(e, vec3(c) - vec3(a))) / length <= eps_3d_;
    }

private:
    static int sign(double distance, double eps) { return distance > eps ? 1 : (distance < -eps ? -1 : 0); }

    static int orient_projected(const double* a, const double* b, const double* c, int i, int j, double eps) {
        const double ex = b[i] - a[i];
        const double ey = b[j] - a[j];
        const double length = std::hypot(ex, ey);
        if (length == 0.0) return 0;
        return sign((ex * (c[j] - a[j]) - ey * (c[i] - a[i])) / length, eps);
    }

    double eps_2d_ = 0.0;
    double eps_3d_ = 0.0;
};

}  // namespace hullkit::detail
