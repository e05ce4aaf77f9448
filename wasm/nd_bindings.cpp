// embind registrations for hulls, Delaunay triangulations and point location in any dimension
// (hullkit/hull_nd.hpp): the friendly API lives in nd.js. No geometry here.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "embind_views.hpp"
#include "hullkit/hull_nd.hpp"

namespace {

using emscripten::val;
using hullkit_wasm::heap_at;
using hullkit_wasm::view_of;

// The points are a malloc'ed block of count * dimension doubles (checked by the JS layer).
hullkit::HullNd hull_nd_from_heap(std::uintptr_t points, std::uint32_t count, int dimension) {
    return hullkit::hull_nd(heap_at<double>(points), count, dimension);
}
hullkit::DelaunayNd delaunay_nd_from_heap(std::uintptr_t points, std::uint32_t count, int dimension, bool furthest) {
    return hullkit::delaunay_nd(heap_at<double>(points), count, dimension, furthest);
}

val facets_view(const hullkit::HullNd& h) { return view_of(h.facets); }
val hull_neighbors_view(const hullkit::HullNd& h) { return view_of(h.neighbors); }
val hull_vertices_view(const hullkit::HullNd& h) { return view_of(h.vertices); }
val hull_group_view(const hullkit::HullNd& h) { return view_of(h.group); }
bool hull_ok(const hullkit::HullNd& h) { return h.ok(); }
double hull_error_point(const hullkit::HullNd& h) { return static_cast<double>(h.error_point); }

val simplices_view(const hullkit::DelaunayNd& d) { return view_of(d.simplices); }
val simplex_neighbors_view(const hullkit::DelaunayNd& d) { return view_of(d.neighbors); }
val simplex_group_view(const hullkit::DelaunayNd& d) { return view_of(d.group); }
val representative_view(const hullkit::DelaunayNd& d) { return view_of(d.representative); }
bool delaunay_ok(const hullkit::DelaunayNd& d) { return d.ok(); }
double delaunay_error_point(const hullkit::DelaunayNd& d) { return static_cast<double>(d.error_point); }
double duplicate_count(const hullkit::DelaunayNd& d) { return static_cast<double>(d.duplicate_count); }

/// Point location in a triangulation the JS layer hands back (malloc'ed blocks): its simplices,
/// neighbours and representatives are checked here (indices in range, neighbours that are -1 or
/// a simplex), so that a changed array gives an error, not a read out of bounds. The result is an
/// Int32Array (a copy) or, on a bad triangulation, a string saying what is wrong.
val locate_nd_from_heap(std::uintptr_t points, std::uint32_t count, int dimension, std::uintptr_t simplices,
                        std::uint32_t simplex_count, std::uintptr_t neighbors, std::uintptr_t representative,
                        std::uintptr_t queries, std::uint32_t query_count) {
    hullkit::DelaunayNd d;
    d.dimension = dimension;
    const std::size_t corners = static_cast<std::size_t>(dimension) + 1;
    const std::uint32_t* s = heap_at<std::uint32_t>(simplices);
    const std::int32_t* n = heap_at<std::int32_t>(neighbors);
    d.simplices.assign(s, s + simplex_count * corners);
    d.neighbors.assign(n, n + simplex_count * corners);
    const std::uint32_t* r = heap_at<std::uint32_t>(representative);
    d.representative.assign(r, r + count);
    for (std::size_t k = 0; k < d.simplices.size(); ++k)
        if (d.simplices[k] >= count)
            return val("simplex " + std::to_string(k / corners) + " has a corner past the points");
    for (std::size_t k = 0; k < d.neighbors.size(); ++k)
        if (d.neighbors[k] < -1 || d.neighbors[k] >= static_cast<std::int64_t>(simplex_count))
            return val("simplex " + std::to_string(k / corners) + " has a neighbour that is no simplex");
    const std::vector<std::int32_t> found = hullkit::locate_nd(heap_at<double>(points), d, heap_at<double>(queries), query_count);
    return val::global("Int32Array").new_(val(emscripten::typed_memory_view(found.size(), found.data())));
}

}  // namespace

EMSCRIPTEN_BINDINGS(hullkit_nd) {
    emscripten::class_<hullkit::HullNd>("HullNd")
        .property("dimension", &hullkit::HullNd::dimension)
        .property("error", &hullkit::HullNd::error)
        .function("ok", &hull_ok)
        .function("errorPoint", &hull_error_point)
        .function("facetsView", &facets_view)
        .function("neighborsView", &hull_neighbors_view)
        .function("verticesView", &hull_vertices_view)
        .function("groupView", &hull_group_view);
    emscripten::class_<hullkit::DelaunayNd>("DelaunayNd")
        .property("dimension", &hullkit::DelaunayNd::dimension)
        .property("error", &hullkit::DelaunayNd::error)
        .function("ok", &delaunay_ok)
        .function("errorPoint", &delaunay_error_point)
        .function("duplicateCount", &duplicate_count)
        .function("simplicesView", &simplices_view)
        .function("neighborsView", &simplex_neighbors_view)
        .function("groupView", &simplex_group_view)
        .function("representativeView", &representative_view);
    emscripten::function("hullNdFromHeap", &hull_nd_from_heap);
    emscripten::function("delaunayNdFromHeap", &delaunay_nd_from_heap);
    emscripten::function("locateNdFromHeap", &locate_nd_from_heap);
}
