// embind registrations only: the friendly API lives in hullkit.js.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <string>
#include <vector>

#include "hullkit/giftwrap.hpp"
#include "hullkit/hull.hpp"
#include "hullkit/verify.hpp"

namespace {

using emscripten::val;

// Points are copied by the JS layer into a malloc'ed block of 3*count doubles at `xyz`; the JS
// layer has checked the option values.
hullkit::Hull hull_from_heap(std::uintptr_t xyz, std::uint32_t count, const std::string& algorithm,
                             bool seed_epsilon, bool merge_coplanar) {
    hullkit::HullOptions options;
    if (!hullkit::parse_algorithm(algorithm, &options.algorithm)) {
        hullkit::Hull unknown;
        unknown.error = "unknown algorithm \"" + algorithm + "\"";
        return unknown;
    }
    options.side_test = seed_epsilon ? hullkit::SideTest::Seed : hullkit::SideTest::Exact;
    options.merge_coplanar = merge_coplanar;
    return hullkit::hull(hullkit::PointSpan(reinterpret_cast<const double*>(xyz), count), options);
}

// Views into the Hull's own vectors; the JS layer copies them out before deleting the Hull.
val triangles_view(const hullkit::Hull& hull) {
    return val(emscripten::typed_memory_view(hull.triangles.size(), hull.triangles.data()));
}
val vertices_view(const hullkit::Hull& hull) {
    return val(emscripten::typed_memory_view(hull.vertices.size(), hull.vertices.data()));
}
val face_offsets_view(const hullkit::Hull& hull) {
    return val(emscripten::typed_memory_view(hull.face_offsets.size(), hull.face_offsets.data()));
}
val face_vertices_view(const hullkit::Hull& hull) {
    return val(emscripten::typed_memory_view(hull.face_vertices.size(), hull.face_vertices.data()));
}
val normal_view(const hullkit::Hull& hull) { return val(emscripten::typed_memory_view(3, hull.normal)); }
// The plane of each of the hull's triangles (hullkit::plane_equations) of the points at `xyz` (still
// in the heap), copied into a new Float64Array: nx ny nz offset per triangle.
val hull_equations(std::uintptr_t xyz, std::uint32_t count, const hullkit::Hull& hull) {
    const std::vector<double> planes =
        hullkit::plane_equations(hullkit::PointSpan(reinterpret_cast<const double*>(xyz), count), hull);
    return val::global("Float64Array").new_(val(emscripten::typed_memory_view(planes.size(), planes.data())));
}
bool hull_ok(const hullkit::Hull& hull) { return hull.ok(); }
double error_point(const hullkit::Hull& hull) { return static_cast<double>(hull.error_point); }

val strings(const std::vector<std::string>& lines) {
    val array = val::array();
    for (const std::string& line : lines) array.call<void>("push", val(line));
    return array;
}

// Points, triangles and (when `with_hull`) the hull's vertices are in malloc'ed blocks; a plain
// object of the report goes back.
val verify_from_heap(std::uintptr_t xyz, std::uint32_t count, std::uintptr_t triangles, std::uint32_t triangle_count,
                     std::uintptr_t vertices, std::uint32_t vertex_count, int dimension, bool with_hull) {
    const hullkit::PointSpan points(reinterpret_cast<const double*>(xyz), count);
    const auto* corners = reinterpret_cast<const std::uint32_t*>(triangles);
    hullkit::VerifyReport report;
    if (with_hull) {
        hullkit::Hull hull;
        hull.dimension = dimension;
        hull.triangles.assign(corners, corners + 3 * std::size_t{triangle_count});
        const auto* first = reinterpret_cast<const std::uint32_t*>(vertices);
        hull.vertices.assign(first, first + vertex_count);
        report = hullkit::verify(points, hull);
    } else {
        report = hullkit::verify(points, corners, triangle_count);
    }
    val out = val::object();
    out.set("ok", report.ok);
    out.set("problems", strings(report.lines()));
    out.set("problemCount", static_cast<double>(report.problem_count));
    out.set("notes", strings(report.notes));
    out.set("dimension", report.dimension);
    out.set("checkedPoints", static_cast<double>(report.checked_points));
    out.set("triangleCount", static_cast<double>(report.triangle_count));
    out.set("vertexCount", static_cast<double>(report.vertex_count));
    out.set("faceCount", static_cast<double>(report.face_count));
    return out;
}

// The recorded gift wrap of the points at `xyz` (exact sides); the JS layer has checked the count.
hullkit::GiftwrapTrace giftwrap_trace_from_heap(std::uintptr_t xyz, std::uint32_t count, bool restart) {
    return hullkit::giftwrap_trace(hullkit::PointSpan(reinterpret_cast<const double*>(xyz), count),
                                   restart ? hullkit::GiftwrapScan::Restart : hullkit::GiftwrapScan::SinglePass);
}
val trace_kinds_view(const hullkit::GiftwrapTrace& trace) {
    return val(emscripten::typed_memory_view(trace.kinds.size(), trace.kinds.data()));
}
val trace_args_view(const hullkit::GiftwrapTrace& trace) {
    return val(emscripten::typed_memory_view(trace.args.size(), trace.args.data()));
}
val trace_triangles_view(const hullkit::GiftwrapTrace& trace) {
    return val(emscripten::typed_memory_view(trace.triangles.size(), trace.triangles.data()));
}
bool trace_ok(const hullkit::GiftwrapTrace& trace) { return trace.ok(); }
double trace_error_point(const hullkit::GiftwrapTrace& trace) { return static_cast<double>(trace.error_point); }
val giftwrap_event_names() {
    val names = val::array();
    for (int k = 0; k < hullkit::kGiftwrapEventKinds; ++k)
        names.call<void>("push", val(hullkit::giftwrap_event_name(static_cast<hullkit::GiftwrapEvent>(k))));
    return names;
}

}  // namespace

EMSCRIPTEN_BINDINGS(hullkit) {
    emscripten::class_<hullkit::Hull>("Hull")
        .property("dimension", &hullkit::Hull::dimension)
        .property("volume", &hullkit::Hull::volume)
        .property("area", &hullkit::Hull::area)
        .property("error", &hullkit::Hull::error)
        .function("ok", &hull_ok)
        .function("errorPoint", &error_point)
        .function("trianglesView", &triangles_view)
        .function("verticesView", &vertices_view)
        .function("faceOffsetsView", &face_offsets_view)
        .function("faceVerticesView", &face_vertices_view)
        .function("normalView", &normal_view);
    emscripten::class_<hullkit::GiftwrapTrace>("GiftwrapTrace")
        .property("dimension", &hullkit::GiftwrapTrace::dimension)
        .property("error", &hullkit::GiftwrapTrace::error)
        .function("ok", &trace_ok)
        .function("errorPoint", &trace_error_point)
        .function("kindsView", &trace_kinds_view)
        .function("argsView", &trace_args_view)
        .function("trianglesView", &trace_triangles_view);
    emscripten::function("hullFromHeap", &hull_from_heap);
    emscripten::function("hullEquations", &hull_equations);
    emscripten::function("giftwrapTraceFromHeap", &giftwrap_trace_from_heap);
    emscripten::function("giftwrapEventNames", &giftwrap_event_names);
    emscripten::function("verifyFromHeap", &verify_from_heap);
}
