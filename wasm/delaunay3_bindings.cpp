// embind registrations for the 3D Delaunay tetrahedralization and its queries (point location,
// nearest points, the Voronoi diagram): the friendly API lives in delaunay3.js. No geometry here.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstddef>
#include <cstdint>
#include <vector>

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
hullkit::Delaunay3 delaunay3_from_heap(std::uintptr_t xyz, std::uint32_t count, val progress, bool furthest_site) {
    hullkit::Delaunay3Options options;
    options.threads = 1;  // the wasm build has no threads; the result is the same for every count
    options.furthest_site = furthest_site;
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

// ---------------------------------------------------------------- queries on a tetrahedralization

/// A tetrahedralization the JS layer handed back, as malloc'ed blocks (checked there: indices in
/// range, neighbours that share their faces back, representatives of lower index): what
/// delaunay3_locate and delaunay3_voronoi read of a Delaunay3.
struct HeapTetrahedralization {
    int dimension = -1;
    std::uintptr_t tetrahedra = 0;  ///< 4 per tetrahedron (dimension 3)
    std::uint32_t tetrahedron_count = 0;
    std::uintptr_t neighbors = 0;  ///< 4 per tetrahedron (dimension 3), 3 per triangle (dimension 2)
    std::uintptr_t triangles = 0;  ///< 3 per triangle (dimension 2)
    std::uint32_t triangle_count = 0;
    std::uintptr_t vertices = 0;  ///< dimension 1 and 0
    std::uint32_t vertex_count = 0;
    std::uintptr_t representative = 0;  ///< one per point
    bool furthest_site = false;          ///< Delaunay3Options::furthest_site made it
};

template <typename T>
std::vector<T> block(std::uintptr_t address, std::size_t count) {
    const T* first = heap_at<T>(address);
    return count ? std::vector<T>(first, first + count) : std::vector<T>();
}

/// The Delaunay3 the arrays describe (a copy: the core's queries take a Delaunay3; nothing is
/// tetrahedralized again).
hullkit::Delaunay3 rebuilt(const HeapTetrahedralization& h, std::uint32_t point_count) {
    hullkit::Delaunay3 d;
    d.dimension = h.dimension;
    d.tetrahedra = block<std::uint32_t>(h.tetrahedra, 4 * std::size_t{h.tetrahedron_count});
    d.triangles = block<std::uint32_t>(h.triangles, 3 * std::size_t{h.triangle_count});
    d.neighbors = block<std::int32_t>(h.neighbors, h.dimension == 3 ? 4 * std::size_t{h.tetrahedron_count}
                                                                    : 3 * std::size_t{h.triangle_count});
    d.vertices = block<std::uint32_t>(h.vertices, h.vertex_count);
    d.representative = block<std::uint32_t>(h.representative, point_count);
    for (std::uint32_t i = 0; i < point_count; ++i) d.duplicate_count += d.representative[i] != i;
    d.furthest_site = h.furthest_site;
    return d;
}

hullkit::Delaunay3Queries locate_from_heap(std::uintptr_t xyz, std::uint32_t count, const HeapTetrahedralization& h,
                                           std::uintptr_t queries, std::uint32_t query_count, bool barycentric,
                                           bool nearest) {
    hullkit::Delaunay3QueryOptions options;
    options.barycentric = barycentric;
    options.nearest = nearest;
    options.threads = 1;  // no threads in the wasm build; the answers are the same
    return hullkit::delaunay3_locate(hullkit::PointSpan(heap_at<double>(xyz), count), rebuilt(h, count),
                                     hullkit::PointSpan(heap_at<double>(queries), query_count), options);
}

val tetrahedron_view(const hullkit::Delaunay3Queries& q) { return view_of(q.tetrahedron); }
val barycentric_view(const hullkit::Delaunay3Queries& q) { return view_of(q.barycentric); }
val nearest_view(const hullkit::Delaunay3Queries& q) { return view_of(q.nearest); }
double error_query(const hullkit::Delaunay3Queries& q) { return static_cast<double>(q.error_query); }

hullkit::Voronoi3 voronoi_from_heap(std::uintptr_t xyz, std::uint32_t count, const HeapTetrahedralization& h) {
    return hullkit::delaunay3_voronoi(hullkit::PointSpan(heap_at<double>(xyz), count), rebuilt(h, count));
}

val voronoi_vertices_view(const hullkit::Voronoi3& v) { return view_of(v.vertices); }
val tetrahedron_vertex_view(const hullkit::Voronoi3& v) { return view_of(v.tetrahedron_vertex); }
val face_points_view(const hullkit::Voronoi3& v) { return view_of(v.face_points); }
val face_offsets_view(const hullkit::Voronoi3& v) { return view_of(v.face_offsets); }
val face_vertices_view(const hullkit::Voronoi3& v) { return view_of(v.face_vertices); }
val face_bounded_view(const hullkit::Voronoi3& v) { return view_of(v.face_bounded); }
val cell_offsets_view(const hullkit::Voronoi3& v) { return view_of(v.cell_offsets); }
val cell_faces_view(const hullkit::Voronoi3& v) { return view_of(v.cell_faces); }
val volume_view(const hullkit::Voronoi3& v) { return view_of(v.volume); }

}  // namespace

EMSCRIPTEN_BINDINGS(hullkit_delaunay3) {
    emscripten::class_<hullkit::Delaunay3>("Delaunay3")
        .property("dimension", &hullkit::Delaunay3::dimension)
        .property("error", &hullkit::Delaunay3::error)
        .function("ok", &delaunay3_ok)
        .function("errorPoint", &error_point)
        .function("duplicateCount", &duplicate_count)
        .property("furthestSite", &hullkit::Delaunay3::furthest_site)
        .function("tetrahedraView", &tetrahedra_view)
        .function("neighborsView", &neighbors_view)
        .function("hullView", &hull_view)
        .function("trianglesView", &triangles_view)
        .function("verticesView", &vertices_view)
        .function("normalView", &normal_view)
        .function("representativeView", &representative_view);
    emscripten::function("delaunay3FromHeap", &delaunay3_from_heap);
    emscripten::function("verifyDelaunay3FromHeap", &verify_delaunay3_from_heap);

    emscripten::value_object<HeapTetrahedralization>("HeapTetrahedralization")
        .field("dimension", &HeapTetrahedralization::dimension)
        .field("tetrahedra", &HeapTetrahedralization::tetrahedra)
        .field("tetrahedronCount", &HeapTetrahedralization::tetrahedron_count)
        .field("neighbors", &HeapTetrahedralization::neighbors)
        .field("triangles", &HeapTetrahedralization::triangles)
        .field("triangleCount", &HeapTetrahedralization::triangle_count)
        .field("vertices", &HeapTetrahedralization::vertices)
        .field("vertexCount", &HeapTetrahedralization::vertex_count)
        .field("representative", &HeapTetrahedralization::representative)
        .field("furthestSite", &HeapTetrahedralization::furthest_site);
    emscripten::class_<hullkit::Delaunay3Queries>("Delaunay3Queries")
        .property("error", &hullkit::Delaunay3Queries::error)
        .function("errorQuery", &error_query)
        .function("tetrahedronView", &tetrahedron_view)
        .function("barycentricView", &barycentric_view)
        .function("nearestView", &nearest_view);
    emscripten::class_<hullkit::Voronoi3>("Voronoi3")
        .function("verticesView", &voronoi_vertices_view)
        .function("tetrahedronVertexView", &tetrahedron_vertex_view)
        .function("facePointsView", &face_points_view)
        .function("faceOffsetsView", &face_offsets_view)
        .function("faceVerticesView", &face_vertices_view)
        .function("faceBoundedView", &face_bounded_view)
        .function("cellOffsetsView", &cell_offsets_view)
        .function("cellFacesView", &cell_faces_view)
        .function("volumeView", &volume_view);
    emscripten::function("delaunay3LocateFromHeap", &locate_from_heap);
    emscripten::function("delaunay3VoronoiFromHeap", &voronoi_from_heap);
}
