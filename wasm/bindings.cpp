// embind registrations only: the friendly API lives in hullkit.js.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <string>

#include "hullkit/hull.hpp"

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
bool hull_ok(const hullkit::Hull& hull) { return hull.ok(); }
double error_point(const hullkit::Hull& hull) { return static_cast<double>(hull.error_point); }

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
    emscripten::function("hullFromHeap", &hull_from_heap);
}
