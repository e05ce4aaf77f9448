// embind registrations for the 3D Delaunay tetrahedralization only: the friendly API lives in
// delaunay3.js. No geometry here.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstddef>
#include <cstdint>

#include "embind_views.hpp"
#include "hullkit/delaunay3.hpp"

namespace {

using emscripten::val;
using hullkit_wasm::heap_at;
using hullkit_wasm::view_of;

// The points are in a malloc'ed block of 3*count doubles at `xyz`, checked by the JS layer for
// their count. `progress` is a JS function (points done, total) or null; the JS layer wraps the
// caller's so that it never throws (an exception thrown through these frames would skip the C++
// destructors and leak the working mesh).
hullkit::Delaunay3 delaunay3_from_heap(std::uintptr_t xyz, std::uint32_t count, val progress) {
    hullkit::Delaunay3Options options;
    options.threads = 1;  // the wasm build has no threads; the result is the same for every count
    if (!progress.isNull() && !progress.isUndefined()) {
        options.progress = [&progress](std::size_t done, std::size_t total) {
            progress(static_cast<double>(done), static_cast<double>(total));
        };
    }
    return hullkit::delaunay3(hullkit::PointSpan(heap_at<double>(xyz), count), options);
}

// Views into the result's own vectors; the JS layer copies them out before deleting the result.
val tetrahedra_view(const hullkit::Delaunay3& d) { return view_of(d.tetrahedra); }
val neighbors_view(const hullkit::Delaunay3& d) { return view_of(d.neighbors); }
val hull_view(const hullkit::Delaunay3& d) { return view_of(d.hull); }
val triangles_view(const hullkit::Delaunay3& d) { return view_of(d.triangles); }
val vertices_view(const hullkit::Delaunay3& d) { return view_of(d.vertices); }
val representative_view(const hullkit::Delaunay3& d) { return view_of(d.representative); }
val normal_view(const hullkit::Delaunay3& d) { return val(emscripten::typed_memory_view(3, d.normal)); }
bool delaunay3_ok(const hullkit::Delaunay3& d) { return d.ok(); }
double error_point(const hullkit::Delaunay3& d) { return static_cast<double>(d.error_point); }
double duplicate_count(const hullkit::Delaunay3& d) { return static_cast<double>(d.duplicate_count); }

// Points and `count` index quadruples in malloc'ed blocks (the indices are checked by the
// verifier itself); the report goes back as a plain object.
val verify_delaunay3_from_heap(std::uintptr_t xyz, std::uint32_t point_count, std::uintptr_t tetrahedra,
                               std::uint32_t count, bool perturbed) {
    const hullkit::Delaunay3VerifyReport report = hullkit::verify_delaunay3(
        hullkit::PointSpan(heap_at<double>(xyz), point_count), heap_at<std::uint32_t>(tetrahedra), count, perturbed);
    val out = val::object();
    out.set("ok", report.ok);
    out.set("problems", hullkit_wasm::string_array(report.problems));
    out.set("problemCount", static_cast<double>(report.problem_count));
    out.set("distinctPoints", static_cast<double>(report.distinct_points));
    out.set("hullTriangles", static_cast<double>(report.hull_triangles));
    return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(hullkit_delaunay3) {
    emscripten::class_<hullkit::Delaunay3>("Delaunay3")
        .property("dimension", &hullkit::Delaunay3::dimension)
        .property("error", &hullkit::Delaunay3::error)
        .function("ok", &delaunay3_ok)
        .function("errorPoint", &error_point)
        .function("duplicateCount", &duplicate_count)
        .function("tetrahedraView", &tetrahedra_view)
        .function("neighborsView", &neighbors_view)
        .function("hullView", &hull_view)
        .function("trianglesView", &triangles_view)
        .function("verticesView", &vertices_view)
        .function("normalView", &normal_view)
        .function("representativeView", &representative_view);
    emscripten::function("delaunay3FromHeap", &delaunay3_from_heap);
    emscripten::function("verifyDelaunay3FromHeap", &verify_delaunay3_from_heap);
}
