// hullkit: reading triangle meshes from OBJ, OFF, PLY, STL and glTF 2.0 files held in memory.
//
// Every reader takes the file's bytes plus a `source` name (a file name, or a field name such as
// "obstacles[2].mesh" when the bytes came from elsewhere) that every error message starts with.
// Errors are one line: "source:LINE: what is wrong" for text formats (LINE 1-based),
// "source: record N (byte B): what is wrong" for binary ones, "source: what is wrong" otherwise.
// Faces with more than 3 vertices are fan-triangulated (v0 v1 v2, v0 v2 v3, ...). Coordinates
// must be finite. A mesh without a single triangle is an error.
#pragma once

#include "hullkit/mesh_io.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace hullkit {

enum class MeshFormat { Unknown, Obj, Off, Ply, StlAscii, StlBinary, Gltf, Glb };

/// "unknown", "OBJ", "OFF", "PLY", "ASCII STL", "binary STL", "glTF", "binary glTF".
const char* mesh_format_name(MeshFormat format);

/// Picks the format from the content: "ply" on the first line; a binary STL whose size is exactly
/// 84 + 50 * (its triangle count) and that does not read as ASCII STL; "solid" (ASCII STL); "OFF";
/// an OBJ record (v, f, vt, vn, o, g, ...); "glTF" first (binary glTF); a JSON object with an
/// "asset" key near its start (glTF). When the content decides nothing, the extension of `source`
/// (.obj .off .ply .stl .gltf .glb, any case) does, so a truncated binary STL still gets a useful
/// message. Unknown otherwise.
MeshFormat detect_mesh_format(const std::string& bytes, const std::string& source);

/// Fetches a file that a mesh file refers to (a glTF's external buffers), by its URI as written
/// (relative to the mesh file). Returns false with a one-line *error when it cannot.
using ExternalFileLoader = std::function<bool(const std::string& uri, std::string* bytes, std::string* error)>;

/// The loader read_mesh uses when given none: files relative to the directory of `source` (a
/// path). In the WebAssembly build there is no file system: an empty loader, so a .gltf with
/// external buffers is refused with a message saying to use a .glb.
ExternalFileLoader files_next_to(const std::string& source);

/// Reads a mesh in any of the formats above (detect_mesh_format decides which); a glTF's external
/// buffers through files_next_to(source), or `load` (empty: none are read).
MeshResult read_mesh(const std::string& bytes, const std::string& source);
MeshResult read_mesh(const std::string& bytes, const std::string& source, const ExternalFileLoader& load);

/// glTF 2.0, JSON (.gltf, buffers embedded as data: URIs or external files fetched by `load`) or
/// binary (.glb), parsed by tinygltf (images are never read). The mesh is every TRIANGLES
/// primitive (the default mode) of every mesh that the default scene's nodes reach (all scenes'
/// nodes when there is no default scene; every mesh, untransformed, when there are no scenes),
/// each instance with its node's world transform (matrix, or translation * rotation * scale,
/// composed down the hierarchy in double) applied to its vertices. POSITION is FLOAT VEC3, or
/// BYTE/UNSIGNED_BYTE/SHORT/UNSIGNED_SHORT (normalized or not, as KHR_mesh_quantization allows);
/// indices UNSIGNED_BYTE/SHORT/INT, or none (every three vertices a triangle). Primitives of other
/// modes (points, lines, strips, fans) or without POSITION are skipped, with a warning per kind.
/// Sparse accessors are refused. Errors: "source: mesh 0, primitive 1: indices accessor 2: index
/// 9 (element 4) out of range (8 vertices)", or tinygltf's reason for a file it cannot parse.
MeshResult read_gltf_mesh(const std::string& bytes, const std::string& source, const ExternalFileLoader& load);

/// OBJ: "v x y z [w | r g b]" vertices and "f" faces whose corners are "i", "i/t", "i//n" or
/// "i/t/n" (1-based; negative indices count back from the last vertex read so far). Texture,
/// normal, group, material, smoothing and line records are ignored; any other record (such as the
/// "648 1292" count line FCL's meshes start with) is skipped with a warning in
/// MeshResult::warnings, as three.js's OBJLoader and tinyobjloader do. A malformed "v" or "f"
/// record is an error.
MeshResult read_obj_mesh(const std::string& text, const std::string& source);

/// PLY 1.0, ascii, binary_little_endian or binary_big_endian: element "vertex" with scalar
/// properties x y z (any PLY scalar type), element "face" with a list property "vertex_indices"
/// (or "vertex_index"); other elements and properties are read and skipped.
MeshResult read_ply_mesh(const std::string& bytes, const std::string& source);

/// STL, ASCII ("solid" ... "facet" "outer loop" 3 x "vertex x y z" "endloop" "endfacet" ...
/// "endsolid") or binary (80-byte header, uint32 triangle count, 50 bytes per triangle, little
/// endian). STL repeats every corner; corners with exactly the same coordinates (-0 and +0 alike)
/// are merged into one vertex, in the order of first appearance.
MeshResult read_stl_mesh(const std::string& bytes, const std::string& source);

/// The vertices of a PLY file as points: as read_ply_mesh, but the "face" element may be missing
/// (a point cloud, as scanners write them); faces that are there are read and checked, not
/// returned.
PointsResult read_ply_points(const std::string& bytes, const std::string& source);

/// 3D points from the bytes of any file hullkit reads: PLY by read_ply_points, STL and glTF (the
/// mesh's vertices, transformed) by read_mesh, and xyz, rbox, OBJ and OFF text by parse_points (an
/// OBJ's or OFF's vertices, faces not needed). A .ply, .stl, .gltf or .glb name, or else content
/// that detect_mesh_format takes for one of those, picks the mesh readers; a .obj or .off name, or
/// anything else, parse_points.
PointsResult read_points(const std::string& bytes, const std::string& source);

/// Whether read_points would read a file with the mesh readers, judged from its first bytes
/// (`head`, at least 84 when the file is that long) and its `size`: a .ply, .stl, .gltf or .glb
/// name (not .obj or .off), "ply", "solid" or "glTF" first, or exactly the size of a binary STL with
/// the triangle count its header gives. For callers that stream point text and read mesh files whole.
bool starts_like_mesh_file(const std::string& head, std::uint64_t size, const std::string& source);

/// 2D points likewise: for a mesh file (OBJ, OFF, PLY, STL or glTF, by name or content) the x and y of
/// what read_points reads; otherwise parse_points_2d (x y, x y z or rbox text).
Points2Result read_points_2d(const std::string& bytes, const std::string& source);

}  // namespace hullkit
