// embind registrations for constrained Delaunay triangulation (graphs, polygons with holes): the
// friendly API lives in constrained.js. No geometry here.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <string>

#include "embind_views.hpp"
#include "hullkit/constrained.hpp"

namespace {

using emscripten::val;
using hullkit_wasm::heap_at;
using hullkit_wasm::view_of;

/// The refinement options; `unsuitable` null or the JS layer's wrapper of the caller's test (it
/// never throws: see userTest in constrained.js).
hullkit::QualityOptions quality_of(double min_angle, double max_area, bool conforming, double max_steiner_points,
                                   unsigned keep_segments, val unsuitable) {
    hullkit::QualityOptions quality;
    quality.min_angle = min_angle;
    quality.max_area = max_area;
    quality.conforming = conforming;
    quality.max_steiner_points = static_cast<std::size_t>(max_steiner_points);
    quality.keep_segments = keep_segments;
    if (!unsuitable.isNull() && !unsuitable.isUndefined()) {
        quality.unsuitable = [unsuitable](const double* a, const double* b, const double* c, double area) {
            return unsuitable(a[0], a[1], b[0], b[1], c[0], c[1], area).as<bool>();
        };
    }
    return quality;
}

// The JS layer copied the points (2 * count doubles), the segments or ring starts (uint32) and the
// hole points (2 * hole_count doubles) into malloc'ed blocks and checked the options.
hullkit::ConstrainedDelaunay graph_from_heap(std::uintptr_t xy, std::uint32_t count, std::uintptr_t segments,
                                             std::uint32_t segment_count, std::uintptr_t holes, std::uint32_t hole_count,
                                             bool remove_exterior, double min_angle, double max_area, bool conforming,
                                             double max_steiner_points, unsigned keep_segments, val unsuitable) {
    hullkit::ConstrainedOptions options;
    options.threads = 1;  // no threads in the wasm build; the answer is the same
    options.remove_exterior = remove_exterior;
    options.holes.assign(heap_at<double>(holes), heap_at<double>(holes) + 2 * static_cast<std::size_t>(hole_count));
    options.quality = quality_of(min_angle, max_area, conforming, max_steiner_points, keep_segments, unsuitable);
    return hullkit::constrained_delaunay(hullkit::PointSpan2(heap_at<double>(xy), count), heap_at<std::uint32_t>(segments),
                                         segment_count, options);
}

hullkit::ConstrainedDelaunay polygon_from_heap(std::uintptr_t xy, std::uint32_t count, std::uintptr_t starts,
                                               std::uint32_t ring_count, const std::string& fill, double min_angle,
                                               double max_area, bool conforming, double max_steiner_points,
                                               unsigned keep_segments, val unsuitable) {
    hullkit::PolygonOptions options;
    options.threads = 1;
    options.quality = quality_of(min_angle, max_area, conforming, max_steiner_points, keep_segments, unsuitable);
    if (!hullkit::parse_fill_rule(fill, &options.fill)) {
        hullkit::ConstrainedDelaunay unknown;
        unknown.error = "unknown fill rule \"" + fill + "\"";
        return unknown;
    }
    return hullkit::triangulate_polygon(hullkit::PointSpan2(heap_at<double>(xy), count), heap_at<std::uint32_t>(starts),
                                        ring_count, options);
}

/// Triangle's -r: the mesh's triangles (3 * triangle_count uint32), optional kept segments and, when
/// areas is not 0, one area bound per triangle (doubles).
hullkit::ConstrainedDelaunay mesh_from_heap(std::uintptr_t xy, std::uint32_t count, std::uintptr_t triangles,
                                            std::uint32_t triangle_count, std::uintptr_t segments,
                                            std::uint32_t segment_count, std::uintptr_t areas, double min_angle,
                                            double max_area, bool conforming, double max_steiner_points,
                                            unsigned keep_segments, val unsuitable) {
    hullkit::RefineMeshOptions options;
    options.threads = 1;
    options.quality = quality_of(min_angle, max_area, conforming, max_steiner_points, keep_segments, unsuitable);
    if (areas != 0) {
        options.triangle_max_area.assign(heap_at<double>(areas), heap_at<double>(areas) + triangle_count);
    }
    return hullkit::refine_mesh(hullkit::PointSpan2(heap_at<double>(xy), count), heap_at<std::uint32_t>(triangles),
                                triangle_count, heap_at<std::uint32_t>(segments), segment_count, options);
}

val triangles_view(const hullkit::ConstrainedDelaunay& d) { return view_of(d.triangles); }
val triangle_region_view(const hullkit::ConstrainedDelaunay& d) { return view_of(d.triangle_region); }
double error_triangle(const hullkit::ConstrainedDelaunay& d) { return static_cast<double>(d.error_triangle); }
val halfedges_view(const hullkit::ConstrainedDelaunay& d) { return view_of(d.halfedges); }
val constrained_view(const hullkit::ConstrainedDelaunay& d) { return view_of(d.constrained); }
val coords_view(const hullkit::ConstrainedDelaunay& d) { return view_of(d.coords); }
val representative_view(const hullkit::ConstrainedDelaunay& d) { return view_of(d.representative); }
bool result_ok(const hullkit::ConstrainedDelaunay& d) { return d.ok(); }
double error_point(const hullkit::ConstrainedDelaunay& d) { return static_cast<double>(d.error_point); }
double error_segment(const hullkit::ConstrainedDelaunay& d) { return static_cast<double>(d.error_segment); }
double duplicate_count(const hullkit::ConstrainedDelaunay& d) { return static_cast<double>(d.duplicate_count); }
double crossing_count(const hullkit::ConstrainedDelaunay& d) { return static_cast<double>(d.crossing_count); }
double steiner_count(const hullkit::ConstrainedDelaunay& d) { return static_cast<double>(d.steiner_count); }
double unrefined_count(const hullkit::ConstrainedDelaunay& d) { return static_cast<double>(d.unrefined_count); }

}  // namespace

EMSCRIPTEN_BINDINGS(hullkit_constrained) {
    emscripten::class_<hullkit::ConstrainedDelaunay>("ConstrainedDelaunay")
        .property("dimension", &hullkit::ConstrainedDelaunay::dimension)
        .property("error", &hullkit::ConstrainedDelaunay::error)
        .function("ok", &result_ok)
        .function("errorPoint", &error_point)
        .function("errorSegment", &error_segment)
        .function("errorTriangle", &error_triangle)
        .function("triangleRegionView", &triangle_region_view)
        .function("duplicateCount", &duplicate_count)
        .function("crossingCount", &crossing_count)
        .function("steinerCount", &steiner_count)
        .function("unrefinedCount", &unrefined_count)
        .function("trianglesView", &triangles_view)
        .function("halfedgesView", &halfedges_view)
        .function("constrainedView", &constrained_view)
        .function("coordsView", &coords_view)
        .function("representativeView", &representative_view);
    emscripten::function("constrainedDelaunayFromHeap", &graph_from_heap);
    emscripten::function("triangulatePolygonFromHeap", &polygon_from_heap);
    emscripten::function("refineMeshFromHeap", &mesh_from_heap);
}
