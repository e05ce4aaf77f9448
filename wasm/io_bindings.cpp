// embind registrations for the file readers the CLI uses (mesh_io.hpp, mesh_read.hpp): the friendly
// API (readPoints, readPoints2d, readMesh) lives in hullkit.js. The JS layer copies the file's bytes
// into a malloc'ed block; each call reads them as a std::string (binary-safe) and returns the
// reader's result, whose arrays the JS layer copies out before deleting it.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <string>

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
std::string points_error(const hullkit::PointsResult& r) { return r.error; }
std::string points2_error(const hullkit::Points2Result& r) { return r.error; }
std::string mesh_error(const hullkit::MeshResult& r) { return r.error; }

}  // namespace

EMSCRIPTEN_BINDINGS(hullkit_io) {
    emscripten::class_<hullkit::PointsResult>("PointsResult")
        .function("error", &points_error)
        .function("view", &points_view);
    emscripten::class_<hullkit::Points2Result>("Points2Result")
        .function("error", &points2_error)
        .function("view", &points2_view);
    emscripten::class_<hullkit::MeshResult>("MeshResult")
        .function("error", &mesh_error)
        .function("verticesView", &mesh_vertices_view)
        .function("trianglesView", &mesh_triangles_view);
    emscripten::function("readPointsFromHeap", &read_points_from_heap);
    emscripten::function("readPoints2dFromHeap", &read_points_2d_from_heap);
    emscripten::function("readMeshFromHeap", &read_mesh_from_heap);
}
