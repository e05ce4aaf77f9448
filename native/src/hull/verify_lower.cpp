// hullkit::verify in dimensions 2, 1, 0: a Hull that is a convex polygon, a segment or a single
// point, checked with exact predicates against every input point. (Dimension -1 is checked in
// verify.cpp.)
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "hullkit/predicates.hpp"
#include "hullkit/verify.hpp"
#include "verify_internal.hpp"

namespace hullkit::verify_detail {

namespace {

bool vertices_in_range(PointSpan points, const std::vector<Index>& vertices, Problems& out) {
    bool ok = true;
    for (Index v : vertices) {
        if (v >= points.count) {
            out.add("vertex index " + num(v) + " is out of range (" + num(points.count) + " points)");
            ok = false;
        }
    }
    std::vector<Index> sorted(vertices);
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t k = 1; k < sorted.size(); ++k) {
        if (sorted[k] == sorted[k - 1]) {
            out.add("vertex " + num(sorted[k]) + " is listed twice");
            ok = false;
        }
    }
    return ok;
}

}  // namespace

void verify_polygon(const Prepared& prepared, const Hull& hull, VerifyReport& report, Problems& out) {
    const PointSpan points = prepared.points;
    const std::vector<Index>& v = hull.vertices;
    const std::size_t m = v.size();
    report.face_count = 1;
    if (m < 3) {
        out.add("a polygon needs at least 3 vertices, Hull::vertices has " + num(m));
        return;
    }
    if (!vertices_in_range(points, v, out)) return;
    int i = 0, j = 0;
    const int s = projection(points[v[0]], points[v[1]], points[v[2]], &i, &j);
    if (s == 0) {
        out.add("polygon vertices " + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + " are collinear");
        return;
    }
    // Orientation in the polygon's plane, positive towards the polygon's interior side.
    auto side = [&](Index a, Index b, std::size_t q) {
        const double* pa = points[a];
        const double* pb = points[b];
        const double* pq = points[q];
        return s * orient2d(pa[i], pa[j], pb[i], pb[j], pq[i], pq[j]);
    };

    bool shape_ok = true;
    for (std::size_t k = 0; k < m; ++k) {
        const Index a = v[k], b = v[(k + 1) % m], c = v[(k + 2) % m];
        if (side(a, b, c) <= 0) {
            out.add("polygon corner " + num(b) + " is not strictly convex: " + num(a) + ", " + num(b) + ", " + num(c) +
                    (side(a, b, c) == 0 ? " are collinear" : " turn the wrong way"));
            shape_ok = false;
        }
    }
    // Traversed once: seen from v[0], the other corners come in strictly increasing angle within a
    // half-turn (each strictly left of v[0] -> v[1] and of the previous one).
    for (std::size_t k = 2; k < m && shape_ok; ++k) {
        if (side(v[0], v[1], v[k]) <= 0 || side(v[0], v[k - 1], v[k]) <= 0) {
            out.add("the polygon is not simple: corner " + num(v[k]) + " is out of angular order around corner " +
                    num(v[0]) + " (it winds around more than once)");
            shape_ok = false;
        }
    }

    const double* a = points[v[0]];
    const double* b = points[v[1]];
    const double* c = points[v[2]];
    bool planar = true;
    for (std::size_t q = 0; q < points.count; ++q) {
        if (orient3d(a, b, c, points[q]) != 0) {
            out.add("point " + num(q) + " " + coordinates(prepared.original[q]) + " is not in the polygon's plane");
            planar = false;
        }
    }
    check_representatives(points, prepared.original, v, out);

    // The triangles fan the polygon from vertices[0].
    std::vector<Index> fan;
    for (std::size_t k = 1; k + 1 < m; ++k) fan.insert(fan.end(), {v[0], v[k], v[k + 1]});
    if (hull.triangles != fan) out.add("Hull::triangles is not the fan of the polygon from vertices[0]");
    if (!hull.face_offsets.empty() &&
        (hull.face_offsets != std::vector<Index>{0, static_cast<Index>(m)} || hull.face_vertices != v)) {
        out.add("the merged face is not the polygon");
    }

    if (!shape_ok || !planar) {
        out.note("containment in the polygon was not checked: the polygon or the plane is wrong");
        return;
    }
    for (std::size_t q = 0; q < points.count; ++q) {
        std::size_t edge = m;  // the edge q is beyond (its first corner's position), m if inside
        if (side(v[0], v[1], q) < 0) {
            edge = 0;
        } else if (side(v[0], v[m - 1], q) > 0) {
            edge = m - 1;
        } else {
            std::size_t lo = 1, hi = m - 1;  // side(v[0], v[lo], q) >= 0
            while (lo < hi) {
                const std::size_t mid = (lo + hi + 1) / 2;
                if (side(v[0], v[mid], q) >= 0) {
                    lo = mid;
                } else {
                    hi = mid - 1;
                }
            }
            const std::size_t k = std::min(lo, m - 2);
            if (side(v[k], v[k + 1], q) < 0) edge = k;
        }
        if (edge == m) {
            ++report.checked_points;
        } else {
            out.add("point " + num(q) + " " + coordinates(prepared.original[q]) + " is outside the polygon: beyond its edge " +
                    num(v[edge]) + "-" + num(v[(edge + 1) % m]));
        }
    }
}

void verify_segment(const Prepared& prepared, const Hull& hull, VerifyReport& report, Problems& out) {
    const PointSpan points = prepared.points;
    const std::vector<Index>& v = hull.vertices;
    if (v.size() != 2) {
        out.add("a segment has 2 end points, Hull::vertices has " + num(v.size()));
        return;
    }
    if (!vertices_in_range(points, v, out)) return;
    const double* a = points[v[0]];
    const double* b = points[v[1]];
    if (key_of(a) == key_of(b)) {
        out.add("the end points " + num(v[0]) + " and " + num(v[1]) + " are the same point");
        return;
    }
    for (std::size_t q = 0; q < points.count; ++q) {
        const double* x = points[q];
        if (!collinear3d(a, b, x)) {
            out.add("point " + num(q) + " " + coordinates(prepared.original[q]) + " is not on the line through " +
                    num(v[0]) + " and " + num(v[1]));
            continue;
        }
        bool between = true;
        for (int axis = 0; axis < 3; ++axis) {
            between = between && std::min(a[axis], b[axis]) <= x[axis] && x[axis] <= std::max(a[axis], b[axis]);
        }
        if (between) {
            ++report.checked_points;
        } else {
            out.add("point " + num(q) + " " + coordinates(prepared.original[q]) + " is beyond the segment's ends " +
                    num(v[0]) + " and " + num(v[1]));
        }
    }
    check_representatives(points, prepared.original, v, out);
    if (!hull.triangles.empty()) out.add("a segment has no triangles, Hull::triangles has " + num(hull.face_count()));
}

void verify_single_point(const Prepared& prepared, const Hull& hull, VerifyReport& report, Problems& out) {
    const PointSpan points = prepared.points;
    const std::vector<Index>& v = hull.vertices;
    if (v.size() != 1) {
        out.add("a single point has 1 vertex, Hull::vertices has " + num(v.size()));
        return;
    }
    if (!vertices_in_range(points, v, out)) return;
    const PointKey only = key_of(points[v[0]]);
    for (std::size_t q = 0; q < points.count; ++q) {
        if (key_of(points[q]) == only) {
            ++report.checked_points;
        } else {
            out.add("point " + num(q) + " " + coordinates(prepared.original[q]) + " differs from the single vertex " +
                    num(v[0]));
        }
    }
    check_representatives(points, prepared.original, v, out);
    if (!hull.triangles.empty()) out.add("a single point has no triangles, Hull::triangles has " + num(hull.face_count()));
}

}  // namespace hullkit::verify_detail
