// embind registrations for the file readers the CLI uses (mesh_io.hpp, mesh_read.hpp): the friendly
// API (readPoints, readPoints2d, readMesh) lives in hullkit.js. The JS layer copies the file's bytes
// into a malloc'ed block; each call reads them as a std::string (binary-safe) and returns the
// reader's result, whose arrays the JS layer copies out before deleting it.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <cmath>
#include <string>
#include <vector>

#include "hullkit/hull.hpp"
#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"

namespace {

using emscripten::val;

std::string bytes_at(std::uintptr_t address, std::uint32_t length) {
    return std::string(reinterpret_cast<const char*>(address), length);
}

/// 3D points from any file hullkit reads (hullkit::read_points: PLY and STL vertices, xyz, rbox,
/// OBJ, OFF).
hullkit::PointsResult read_points_from_heap(std::uintptr_t address, std::uint32_t length, const std::string& name) {
    return hullkit::read_points(bytes_at(address, length), name);
}

/// 2D points (hullkit::read_points_2d: x y text as `hullkit delaunay` reads it, or the x and y of a
/// mesh file's points).
hullkit::Points2Result read_points_2d_from_heap(std::uintptr_t address, std::uint32_t length,
                                                const std::string& name) {
    return hullkit::read_points_2d(bytes_at(address, length), name);
}

hullkit::MeshResult read_mesh_from_heap(std::uintptr_t address, std::uint32_t length, const std::string& name) {
    return hullkit::read_mesh(bytes_at(address, length), name);
}

val points_view(const hullkit::PointsResult& r) { return val(emscripten::typed_memory_view(r.xyz.size(), r.xyz.data())); }
val points2_view(const hullkit::Points2Result& r) { return val(emscripten::typed_memory_view(r.xy.size(), r.xy.data())); }
val mesh_vertices_view(const hullkit::MeshResult& r) {
    return val(emscripten::typed_memory_view(r.xyz.size(), r.xyz.data()));
}
val mesh_triangles_view(const hullkit::MeshResult& r) {
    return val(emscripten::typed_memory_view(r.triangles.size(), r.triangles.data()));
}
/// A reader's warnings as a JS array of strings.
val warnings_array(const std::vector<std::string>& warnings) {
    val out = val::array();
    for (const std::string& warning : warnings) out.call<void>("push", val(warning));
    return out;
}
val points_warnings(const hullkit::PointsResult& r) { return warnings_array(r.warnings); }
val points2_warnings(const hullkit::Points2Result& r) { return warnings_array(r.warnings); }
val mesh_warnings(const hullkit::MeshResult& r) { return warnings_array(r.warnings); }

std::string points_error(const hullkit::PointsResult& r) { return r.error; }
std::string points2_error(const hullkit::Points2Result& r) { return r.error; }
std::string mesh_error(const hullkit::MeshResult& r) { return r.error; }

/// The .glb of a hull (hullkit::write_glb): points, the hull's vertices and its triangles are in
/// malloc'ed blocks. {bytes: Uint8Array} (a copy), or {error} for a coordinate beyond float32 or a
/// hull that does not fit the points.
val write_glb_from_heap(std::uintptr_t xyz, std::uint32_t count, std::uintptr_t vertices, std::uint32_t vertex_count,
                        std::uintptr_t triangles, std::uint32_t index_count) {
    hullkit::Hull hull;
    const auto* v = reinterpret_cast<const std::uint32_t*>(vertices);
    const auto* t = reinterpret_cast<const std::uint32_t*>(triangles);
    hull.vertices.assign(v, v + vertex_count);
    hull.triangles.assign(t, t + index_count);
    val out = val::object();
    // write_glb throws for what is checked here: the WebAssembly build cannot catch exceptions.
    const hullkit::PointSpan points(reinterpret_cast<const double*>(xyz), count);
    std::vector<bool> listed(count, false);
    for (std::uint32_t vertex : hull.vertices) {
        if (vertex >= count || listed[vertex]) {
            out.set("error", "hull vertex " + std::to_string(vertex) + (vertex >= count ? " is out of range" : " is listed twice"));
            return out;
        }
        listed[vertex] = true;
        for (int k = 0; k < 3; ++k) {
            const double x = points[vertex][k];
            if (!std::isfinite(static_cast<float>(x))) {
                out.set("error", "coordinate " + hullkit::format_double(x) + " of hull vertex " + std::to_string(vertex) +
                                     " does not fit a glTF float32 position");
                return out;
            }
        }
    }
    for (std::uint32_t corner : hull.triangles) {
        if (corner >= count || !listed[corner]) {
            out.set("error", "triangle corner " + std::to_string(corner) + " is not a hull vertex");
            return out;
        }
    }
    if (hull.triangles.size() % 3 != 0) {
        out.set("error", std::string("the triangles are not whole (a multiple of 3 indices)"));
        return out;
    }
    const std::string bytes = hullkit::write_glb(points, hull);
    val view = val(emscripten::typed_memory_view(bytes.size(), reinterpret_cast<const unsigned char*>(bytes.data())));
    out.set("bytes", view.call<val>("slice"));
    return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(hullkit_io) {
    emscripten::class_<hullkit::PointsResult>("PointsResult")
        .function("error", &points_error)
        .function("warnings", &points_warnings)
        .function("view", &points_view);
    emscripten::class_<hullkit::Points2Result>("Points2Result")
        .function("error", &points2_error)
        .function("warnings", &points2_warnings)
        .function("view", &points2_view);
    emscripten::class_<hullkit::MeshResult>("MeshResult")
        .function("error", &mesh_error)
        .function("warnings", &mesh_warnings)
        .function("verticesView", &mesh_vertices_view)
        .function("trianglesView", &mesh_triangles_view);
    emscripten::function("readPointsFromHeap", &read_points_from_heap);
    emscripten::function("readPoints2dFromHeap", &read_points_2d_from_heap);
    emscripten::function("readMeshFromHeap", &read_mesh_from_heap);
    emscripten::function("writeGlbFromHeap", &write_glb_from_heap);
}
