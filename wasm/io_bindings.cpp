// embind registrations for the file readers the CLI uses (mesh_io.hpp, mesh_read.hpp): the friendly
// API (readPoints, readPoints2d, readMesh) lives in hullkit.js. The JS layer copies the file's bytes
// into a malloc'ed block; each call reads them as a std::string (binary-safe) and returns the
// reader's result, whose arrays the JS layer copies out before deleting it.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cctype>
#include <cstdint>
#include <string>

#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"

namespace {

using emscripten::val;

std::string bytes_at(std::uintptr_t address, std::uint32_t length) {
    return std::string(reinterpret_cast<const char*>(address), length);
}

/// The lower-case extension of `name` ("" if none).
std::string extension(const std::string& name) {
    const std::size_t dot = name.find_last_of('.');
    const std::size_t slash = name.find_last_of("/\\");
    if (dot == std::string::npos || (slash != std::string::npos && slash > dot)) return {};
    std::string ext = name.substr(dot + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

/// Whether the bytes go to the mesh readers rather than the point-text reader: a .ply or .stl name,
/// or else content that detect_mesh_format takes for PLY or STL. OBJ, OFF, rbox and "x y z" text go
/// to parse_points as with `hullkit hull` (which reads an OBJ's or OFF's vertices, also without
/// faces).
bool read_as_mesh(const std::string& bytes, const std::string& name) {
    const std::string ext = extension(name);
    if (ext == "ply" || ext == "stl") return true;
    if (ext == "obj" || ext == "off") return false;
    const hullkit::MeshFormat format = hullkit::detect_mesh_format(bytes, "");
    return format == hullkit::MeshFormat::Ply || format == hullkit::MeshFormat::StlAscii ||
           format == hullkit::MeshFormat::StlBinary;
}

/// 3D points: the vertices of a PLY or STL mesh, else parse_points (xyz, rbox, OBJ, OFF).
hullkit::PointsResult read_points_from_heap(std::uintptr_t address, std::uint32_t length, const std::string& name) {
    const std::string bytes = bytes_at(address, length);
    if (!read_as_mesh(bytes, name)) return hullkit::parse_points(bytes, name);
    hullkit::MeshResult mesh = hullkit::read_mesh(bytes, name);
    hullkit::PointsResult points;
    points.error = std::move(mesh.error);
    points.xyz = std::move(mesh.xyz);
    return points;
}

/// 2D points: parse_points_2d as `hullkit delaunay` reads them, or for a mesh file (OBJ, OFF, PLY,
/// STL, by name or content) the x and y of its points as read_points_from_heap reads them.
hullkit::Points2Result read_points_2d_from_heap(std::uintptr_t address, std::uint32_t length,
                                                const std::string& name) {
    const std::string bytes = bytes_at(address, length);
    const std::string ext = extension(name);
    const hullkit::MeshFormat format = hullkit::detect_mesh_format(bytes, "");
    const bool mesh_file = ext == "obj" || ext == "off" || ext == "ply" || ext == "stl" ||
                           format != hullkit::MeshFormat::Unknown;
    if (!mesh_file) return hullkit::parse_points_2d(bytes, name);
    hullkit::PointsResult points = read_points_from_heap(address, length, name);
    hullkit::Points2Result out;
    out.error = std::move(points.error);
    out.xy.reserve(2 * points.count());
    for (std::size_t i = 0; i < points.count(); ++i) {
        out.xy.push_back(points.xyz[3 * i]);
        out.xy.push_back(points.xyz[3 * i + 1]);
    }
    return out;
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
