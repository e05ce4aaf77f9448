// embind registrations for Delaunay triangulation and its queries (nearest point, point location,
// Voronoi cells and the whole diagram): the friendly API lives in delaunay.js. No geometry here.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <string>
#include <vector>

#include "embind_views.hpp"
#include "hullkit/delaunay.hpp"
#include "hullkit/giftwrap.hpp"

namespace {

using emscripten::val;

const double* doubles_at(std::uintptr_t address) { return reinterpret_cast<const double*>(address); }
const std::uint32_t* uint32s_at(std::uintptr_t address) { return reinterpret_cast<const std::uint32_t*>(address); }

// Points are copied by the JS layer into a malloc'ed block of 2*count doubles at `xy`; the JS
// layer has checked the option values.
hullkit::Delaunay delaunay_from_heap(std::uintptr_t xy, std::uint32_t count, const std::string& algorithm,
                                     bool merge_cocircular) {
    hullkit::DelaunayOptions options;
    if (!hullkit::parse_delaunay_algorithm(algorithm, &options.algorithm)) {
        hullkit::Delaunay unknown;
        unknown.error = "unknown algorithm \"" + algorithm + "\"";
        return unknown;
    }
    options.merge_cocircular = merge_cocircular;
    return hullkit::delaunay(hullkit::PointSpan2(doubles_at(xy), count), options);
}

/// A Delaunay rebuilt from the arrays a JS caller holds (triangles, halfedges, hull and the
/// `count` representatives in malloc'ed blocks, already checked by the JS layer to be in range),
/// for find, locate and voronoi.
hullkit::Delaunay triangulation_from_heap(std::uint32_t count, int dimension, std::uintptr_t triangles,
                                          std::uint32_t corner_count, std::uintptr_t halfedges, std::uintptr_t hull,
                                          std::uint32_t hull_count, std::uintptr_t representative) {
    hullkit::Delaunay result;
    result.dimension = dimension;
    result.representative.assign(uint32s_at(representative), uint32s_at(representative) + count);
    for (std::uint32_t i = 0; i < count; ++i) result.duplicate_count += result.representative[i] != i;
    result.triangles.assign(uint32s_at(triangles), uint32s_at(triangles) + corner_count);
    const auto* opposite = reinterpret_cast<const std::int32_t*>(halfedges);
    result.halfedges.assign(opposite, opposite + corner_count);
    result.hull.assign(uint32s_at(hull), uint32s_at(hull) + hull_count);
    return result;
}

double find_from_heap(std::uintptr_t xy, std::uint32_t count, int dimension, std::uintptr_t triangles,
                      std::uint32_t corner_count, std::uintptr_t halfedges, std::uintptr_t hull, std::uint32_t hull_count,
                      std::uintptr_t representative, double x, double y, std::uint32_t start) {
    const hullkit::Delaunay triangulation = triangulation_from_heap(count, dimension, triangles, corner_count, halfedges,
                                                                    hull, hull_count, representative);
    return static_cast<double>(
        hullkit::delaunay_find(hullkit::PointSpan2(doubles_at(xy), count), triangulation, x, y, start));
}

hullkit::VoronoiCells voronoi_from_heap(std::uintptr_t xy, std::uint32_t count, int dimension, std::uintptr_t triangles,
                                        std::uint32_t corner_count, std::uintptr_t halfedges, std::uintptr_t hull,
                                        std::uint32_t hull_count, std::uintptr_t representative, double xmin,
                                        double ymin, double xmax, double ymax) {
    const hullkit::Delaunay triangulation = triangulation_from_heap(count, dimension, triangles, corner_count, halfedges,
                                                                    hull, hull_count, representative);
    return hullkit::delaunay_voronoi(hullkit::PointSpan2(doubles_at(xy), count), triangulation, xmin, ymin, xmax, ymax);
}

/// The whole diagram (delaunay_voronoi_diagram), with its cell offsets as 32-bit numbers (a
/// wasm heap holds fewer than 2^32 bytes) for a Uint32Array.
struct VoronoiDiagramJs {
    hullkit::VoronoiDiagram diagram;
    std::vector<std::uint32_t> offsets;
};

VoronoiDiagramJs voronoi_diagram_from_heap(std::uintptr_t xy, std::uint32_t count, int dimension, std::uintptr_t triangles,
                                           std::uint32_t corner_count, std::uintptr_t halfedges, std::uintptr_t hull,
                                           std::uint32_t hull_count, std::uintptr_t representative) {
    const hullkit::Delaunay triangulation = triangulation_from_heap(count, dimension, triangles, corner_count, halfedges,
                                                                    hull, hull_count, representative);
    VoronoiDiagramJs out;
    out.diagram = hullkit::delaunay_voronoi_diagram(hullkit::PointSpan2(doubles_at(xy), count), triangulation, 1);
    out.offsets.assign(out.diagram.cell_offsets.begin(), out.diagram.cell_offsets.end());
    return out;
}

/// Point location (delaunay_locate) for `query_count` x y pairs in a malloc'ed block at `queries`;
/// the triangulation as find's. The flags were checked by the JS layer.
hullkit::DelaunayQueries locate_from_heap(std::uintptr_t xy, std::uint32_t count, int dimension, std::uintptr_t triangles,
                                          std::uint32_t corner_count, std::uintptr_t halfedges, std::uintptr_t hull,
                                          std::uint32_t hull_count, std::uintptr_t representative, std::uintptr_t queries,
                                          std::uint32_t query_count, bool barycentric, bool nearest) {
    const hullkit::Delaunay triangulation = triangulation_from_heap(count, dimension, triangles, corner_count, halfedges,
                                                                    hull, hull_count, representative);
    hullkit::DelaunayQueryOptions options;
    options.barycentric = barycentric;
    options.nearest = nearest;
    options.threads = 1;  // no threads in the wasm build; the answers are the same
    return hullkit::delaunay_locate(hullkit::PointSpan2(doubles_at(xy), count), triangulation,
                                    hullkit::PointSpan2(doubles_at(queries), query_count), options);
}

// Views into the results' own vectors; the JS layer copies them out before deleting the result.
using hullkit_wasm::view_of;
val triangles_view(const hullkit::Delaunay& d) { return view_of(d.triangles); }
val halfedges_view(const hullkit::Delaunay& d) { return view_of(d.halfedges); }
val hull_view(const hullkit::Delaunay& d) { return view_of(d.hull); }
val representative_view(const hullkit::Delaunay& d) { return view_of(d.representative); }
val polygon_offsets_view(const hullkit::Delaunay& d) { return view_of(d.polygon_offsets); }
val polygon_vertices_view(const hullkit::Delaunay& d) { return view_of(d.polygon_vertices); }
bool delaunay_ok(const hullkit::Delaunay& d) { return d.ok(); }
double delaunay_error_point(const hullkit::Delaunay& d) { return static_cast<double>(d.error_point); }
double duplicate_count(const hullkit::Delaunay& d) { return static_cast<double>(d.duplicate_count); }
val cell_offsets_view(const hullkit::VoronoiCells& cells) { return view_of(cells.cell_offsets); }
val cell_xy_view(const hullkit::VoronoiCells& cells) { return view_of(cells.cell_xy); }
val triangle_view(const hullkit::DelaunayQueries& q) { return view_of(q.triangle); }
val barycentric_view(const hullkit::DelaunayQueries& q) { return view_of(q.barycentric); }
val nearest_view(const hullkit::DelaunayQueries& q) { return view_of(q.nearest); }
double error_query(const hullkit::DelaunayQueries& q) { return static_cast<double>(q.error_query); }
bool diagram_ok(const VoronoiDiagramJs& v) { return v.diagram.ok(); }
std::string diagram_error(const VoronoiDiagramJs& v) { return v.diagram.error; }
val diagram_vertices_view(const VoronoiDiagramJs& v) { return view_of(v.diagram.vertices); }
val diagram_triangle_vertex_view(const VoronoiDiagramJs& v) { return view_of(v.diagram.triangle_vertex); }
val diagram_ridge_points_view(const VoronoiDiagramJs& v) { return view_of(v.diagram.ridge_points); }
val diagram_ridge_vertices_view(const VoronoiDiagramJs& v) { return view_of(v.diagram.ridge_vertices); }
val diagram_cells_view(const VoronoiDiagramJs& v) { return view_of(v.diagram.cells); }
val diagram_cell_offsets_view(const VoronoiDiagramJs& v) { return view_of(v.offsets); }
val diagram_cell_point_view(const VoronoiDiagramJs& v) { return view_of(v.diagram.cell_point); }
val diagram_point_cell_view(const VoronoiDiagramJs& v) { return view_of(v.diagram.point_cell); }
val diagram_areas_view(const VoronoiDiagramJs& v) { return view_of(v.diagram.areas); }

// The recorded gift wrap on the lifted points (class GiftwrapTrace is registered in bindings.cpp).
hullkit::GiftwrapTrace delaunay_giftwrap_trace_from_heap(std::uintptr_t xy, std::uint32_t count) {
    return hullkit::delaunay_giftwrap_trace(hullkit::PointSpan2(doubles_at(xy), count));
}

}  // namespace

EMSCRIPTEN_BINDINGS(hullkit_delaunay) {
    emscripten::function("delaunayGiftwrapTraceFromHeap", &delaunay_giftwrap_trace_from_heap);
    emscripten::class_<hullkit::Delaunay>("Delaunay")
        .property("dimension", &hullkit::Delaunay::dimension)
        .property("error", &hullkit::Delaunay::error)
        .function("ok", &delaunay_ok)
        .function("errorPoint", &delaunay_error_point)
        .function("duplicateCount", &duplicate_count)
        .function("trianglesView", &triangles_view)
        .function("halfedgesView", &halfedges_view)
        .function("hullView", &hull_view)
        .function("representativeView", &representative_view)
        .function("polygonOffsetsView", &polygon_offsets_view)
        .function("polygonVerticesView", &polygon_vertices_view);
    emscripten::class_<hullkit::VoronoiCells>("VoronoiCells")
        .function("cellOffsetsView", &cell_offsets_view)
        .function("cellXYView", &cell_xy_view);
    emscripten::function("delaunayFromHeap", &delaunay_from_heap);
    emscripten::function("delaunayFindFromHeap", &find_from_heap);
    emscripten::class_<hullkit::DelaunayQueries>("DelaunayQueries")
        .property("error", &hullkit::DelaunayQueries::error)
        .function("errorQuery", &error_query)
        .function("triangleView", &triangle_view)
        .function("barycentricView", &barycentric_view)
        .function("nearestView", &nearest_view);
    emscripten::function("delaunayLocateFromHeap", &locate_from_heap);
    emscripten::function("delaunayVoronoiFromHeap", &voronoi_from_heap);
    emscripten::class_<VoronoiDiagramJs>("VoronoiDiagram")
        .function("ok", &diagram_ok)
        .function("error", &diagram_error)
        .function("verticesView", &diagram_vertices_view)
        .function("triangleVertexView", &diagram_triangle_vertex_view)
        .function("ridgePointsView", &diagram_ridge_points_view)
        .function("ridgeVerticesView", &diagram_ridge_vertices_view)
        .function("cellsView", &diagram_cells_view)
        .function("cellOffsetsView", &diagram_cell_offsets_view)
        .function("cellPointView", &diagram_cell_point_view)
        .function("pointCellView", &diagram_point_cell_view)
        .function("areasView", &diagram_areas_view);
    emscripten::function("delaunayVoronoiDiagramFromHeap", &voronoi_diagram_from_heap);
}
