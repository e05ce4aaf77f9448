// The scene reader's fast path for inline meshes (scene_arrays.cpp): the "vertices" and
// "triangles" arrays of a scene, nearly all of its bytes, read straight into flat arrays before
// the JSON tree is built, instead of one tree node per number.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hullkit/scene_io.hpp"

namespace hullkit::route_detail {

/// The arrays taken out of a scene's text, and where they were.
struct PackedMeshArrays {
    std::vector<std::vector<double>> vertices;          ///< per array taken out: x y z per vertex
    std::vector<std::vector<std::uint32_t>> triangles;  ///< per array taken out: i j k per triangle
    /// Per "vertices" (and "triangles") key of the text, in the order of the text: the index of its
    /// array above, or -1 where the value stayed in the text.
    std::vector<std::int64_t> vertices_keys, triangles_keys;
};

/// Copies `text` into *packed_text with the value of every "vertices" key that is a non-empty
/// array of [x, y, z] (3 JSON numbers, each finite as a double) and of every "triangles" key that
/// is a non-empty array of [i, j, k] (3 integers written as digits only, each < 2^32) replaced by
/// "[]", those values going to *arrays. A number becomes the double the JSON tree would give
/// (integers through their 64-bit value, so "-0" is +0; others rounded to nearest, as strtod).
/// Anything else stays in the text, to be read (and reported) the ordinary way. Returns false
/// when nothing was taken out, or when the text has a key written with escapes (whose meaning
/// only the JSON parser knows); *packed_text is then meaningless.
bool pack_mesh_arrays(const std::string& text, std::string* packed_text, PackedMeshArrays* arrays);

/// parse_scene without the fast path (every number a node of the JSON tree): for the tests and
/// the fuzzer, which require both to give the same scene, bit for bit, or the same message.
SceneResult parse_scene_tree_only(const std::string& json_text, const std::string& source, const MeshLoader& load_mesh,
                                  const SceneReadOptions& options = {});

}  // namespace hullkit::route_detail
