// hullkit::verify: exact certification of a convex hull. See verify.hpp for what is checked and
// why it suffices. Nothing here is shared with the hull algorithms; only the predicates are.
//
// This file holds the entry points and the dispatch by dimension. The rest is in
//   verify_internal.hpp     what the files share (problem collector, prepared input, helpers)
//   verify_common.cpp       VerifyReport::lines, the preparation of the input, identical points
//   verify_solid.cpp        dimension 3: the surface's structure, convexity and winding; Hull fields
//   verify_containment.cpp  dimension 3: every input point lies in the hull
//   verify_lower.cpp        dimensions 2, 1, 0: polygon, segment, single point
#include "hullkit/verify.hpp"

#include <cstdint>
#include <string>

#include "verify_internal.hpp"

namespace hullkit {

using verify_detail::num;
using verify_detail::prepare;
using verify_detail::Prepared;
using verify_detail::Problems;
using verify_detail::SurfaceVerifier;
using verify_detail::verify_polygon;
using verify_detail::verify_segment;
using verify_detail::verify_single_point;
using verify_detail::verify_solid;

VerifyReport verify(PointSpan points, const std::uint32_t* triangles, std::size_t triangle_count) {
    VerifyReport report;
    report.dimension = 3;
    Problems out(report);
    Prepared prepared;
    if (!prepare(points, out, prepared)) return report;
    SurfaceVerifier(prepared, triangles, triangle_count, report).run();
    return report;
}

VerifyReport verify(PointSpan points, const Hull& hull) {
    VerifyReport report;
    report.dimension = hull.dimension;
    report.triangle_count = hull.face_count();
    report.vertex_count = hull.vertices.size();
    Problems out(report);
    if (!hull.ok()) {
        out.add("the hull computation failed: " + hull.error);
        return report;
    }
    Prepared prepared;
    if (!prepare(points, out, prepared)) return report;
    switch (hull.dimension) {
        case 3:
            verify_solid(prepared, hull, report, out);
            break;
        case 2:
            verify_polygon(prepared, hull, report, out);
            break;
        case 1:
            verify_segment(prepared, hull, report, out);
            break;
        case 0:
            verify_single_point(prepared, hull, report, out);
            break;
        case -1:
            if (points.count != 0) out.add("dimension -1 means no points, but there are " + num(points.count));
            if (!hull.vertices.empty() || !hull.triangles.empty()) out.add("an empty hull has no vertices or triangles");
            break;
        default:
            out.add("Hull::dimension " + std::to_string(hull.dimension) + " is not one of 3, 2, 1, 0, -1");
    }
    return report;
}

}  // namespace hullkit
