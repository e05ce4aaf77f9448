// The scene reader's fast path for inline mesh arrays (native/src/route/scene_arrays.cpp): every
// scene gives the same result, bit for bit, or the same message, as reading it with every number
// a node of the JSON tree (parse_scene_tree_only); tricky numbers, indices, layouts and keys.
#include "route/scene_arrays.hpp"

#include "scene_bits.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace {

using hullkit::route_detail::PackedMeshArrays;

/// parse_scene (with the fast path) and the tree-only reader agree on `text`; returns the result.
hullkit::SceneResult both_ways(const std::string& text) {
    INFO(text.substr(0, 300));
    const hullkit::MeshLoader no_files;
    const hullkit::SceneResult fast = hullkit::parse_scene(text, "s.json", no_files);
    const hullkit::SceneResult tree = hullkit::route_detail::parse_scene_tree_only(text, "s.json", no_files);
    CHECK(fast.error == tree.error);
    CHECK(fast.warnings == tree.warnings);
    CHECK(hullkit_test::same_scene_bits(fast.scene, tree.scene));  // -0 and +0 differ
    return fast;
}

/// A scene whose traverse is an inline mesh with `vertices` and `triangles` spliced in as text.
std::string mesh_scene(const std::string& vertices, const std::string& triangles) {
    return R"({"traverse": {"parts": [{"name": "p", "vertices": )" + vertices + R"(, "triangles": )" + triangles +
           R"(}]}, "route": [[0,0,0],[1,0,0]], "obstacles": [{"box": {"min": [4,-1,-1], "max": [5,1,1]}}]})";
}

bool packs(const std::string& text) {
    std::string packed;
    PackedMeshArrays arrays;
    return hullkit::route_detail::pack_mesh_arrays(text, &packed, &arrays);
}

}  // namespace

TEST_CASE("scene_arrays: a scene's inline meshes are taken out of the text", "[scene_io]") {
    const std::string text = mesh_scene("[[0,0,0],[1,0,0],[0,1,0],[0,0,1]]", "[[0,2,1],[0,1,3],[0,3,2],[1,2,3]]");
    std::string packed;
    PackedMeshArrays arrays;
    REQUIRE(hullkit::route_detail::pack_mesh_arrays(text, &packed, &arrays));
    CHECK(packed.find("\"vertices\": [],") != std::string::npos);
    CHECK(packed.find("\"triangles\": []}") != std::string::npos);
    REQUIRE(arrays.vertices.size() == 1);
    REQUIRE(arrays.triangles.size() == 1);
    CHECK(arrays.vertices[0] == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
    CHECK(arrays.triangles[0] == std::vector<std::uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3});
    CHECK(arrays.vertices_keys == std::vector<std::int64_t>{0});
    const hullkit::SceneResult result = both_ways(text);
    REQUIRE(result.ok());
    CHECK(result.scene.parts[0].xyz.size() == 12);
    // A key written with escapes is left to the JSON parser (it alone knows what it means).
    CHECK_FALSE(packs(R"({"traverse": {"parts": [{"\u0076ertices": [[0,0,0]], "triangles": [[0,0,0]]}]}})"));
    CHECK_FALSE(packs(R"({"traverse": {"parts": [{"box": {"min": [0,0,0], "max": [1,1,1]}}]}})"));
}

TEST_CASE("scene_arrays: every number is the double the JSON tree gives", "[scene_io]") {
    const char* const tokens[] = {
        "0", "-0", "0.0", "-0.0", "-0e5", "1", "-1", "0.1", "1E5", "1e+5", "1e-5", "-1.5e-3", "2.5E+300",
        "3.141592653589793238462643383279502884197", "9007199254740993", "-9007199254740993",
        "9223372036854775807", "9223372036854775808", "-9223372036854775808", "-9223372036854775809",
        "18446744073709551615", "18446744073709551616", "123456789012345678901234567890",
        "4.9e-324", "2.4703282292062327e-324", "2.4703282292062328e-324", "1e-400", "-1e-400",
        "2.2250738585072011e-308", "1.7976931348623157e308", "1.7976931348623158e308", "0.30000000000000004",
        "100000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000001",
        // Not finite, or not JSON: the ordinary reader's message.
        "1e400", "-1e999", "01", "1.", ".5", "+1", "1e", "1e+", "- 1", "0x10", "NaN", "Infinity", "1.5.5", "\"1\"", "null", "true",
    };
    for (const char* token : tokens) {
        const std::string vertices = std::string("[[") + token + ",0,0],[1,0,0],[0,1,0],[0,0,1]]";
        both_ways(mesh_scene(vertices, "[[0,2,1],[0,1,3],[0,3,2],[1,2,3]]"));
    }
    // Random doubles written in several ways.
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::string vertices = "[";
    for (int i = 0; i < 3000; ++i) {
        char x[64], y[64], z[64];
        const double scale = std::ldexp(1.0, static_cast<int>(random() % 200) - 100);
        std::snprintf(x, sizeof x, "%.17g", unit(random) * scale);
        std::snprintf(y, sizeof y, "%.*e", static_cast<int>(random() % 20), unit(random) * scale);
        std::snprintf(z, sizeof z, "%lld", static_cast<long long>(random() >> (random() % 64)) * (i % 2 ? 1 : -1));
        vertices += std::string(i ? "," : "") + "[" + x + "," + y + "," + z + "]";
    }
    vertices += "]";
    const hullkit::SceneResult result = both_ways(mesh_scene(vertices, "[[0,1,2],[2999,1,0]]"));
    REQUIRE(result.ok());
    CHECK(result.scene.parts[0].xyz.size() == 9000);
    CHECK(packs(mesh_scene(vertices, "[[0,1,2]]")));
}

TEST_CASE("scene_arrays: indices, layouts and keys read as the JSON tree reads them", "[scene_io]") {
    const std::string v = "[[0,0,0],[1,0,0],[0,1,0],[0,0,1]]";
    const char* const triangles[] = {
        "[[0,2,1],[0,1,3]]", "[[0,2,4]]", "[[0,2,-1]]", "[[0,2,-0]]", "[[0,2,1.0]]", "[[0,2,1e0]]", "[[0,2,1.5]]",
        "[[0,2,4294967295]]", "[[0,2,4294967296]]", "[[0,2,18446744073709551616]]", "[[0,2,01]]", "[[0,2]]",
        "[[0,2,1,3]]", "[]", "[[]]", "[0,2,1]", "[[[0,2,1]]]", "[[0,2,1],]", "[[0,2,1]", "[[0,\"2\",1]]", "{}",
        " [ [ 0 ,\n2 ,\t1 ] ,\r\n[0,1,3] ] ",
    };
    for (const char* t : triangles) both_ways(mesh_scene(v, t));
    const char* const vertex_arrays[] = {
        "[]", "[[0,0,0]]", "[[0,0]]", "[[0,0,0,0]]", "[[0,0,0],[1,0,0],[0,1,0],[0,0,null]]", "[[0,0,0],]", "[0,0,0]",
        " [\n [ 0 , 0 , 0 ] ,[1,0,0]\t,[0,1,0], [0,0,1]\n ] ", "[[0,0,0] [1,0,0]]", "[[0,0,0],[1,0,0],[0,1,0],[0,0,1]] x",
        "[[0,0,0],[1,0,0],[0,1,0],[0,0,1] /* c */]", "[[0,0,0],[1,0,0],[0,1,0],[0,0,1]\v]",
    };
    for (const char* vertices : vertex_arrays) both_ways(mesh_scene(vertices, "[[0,2,1]]"));
    // "vertices" and "triangles" elsewhere, twice, with strings about them, and unfinished texts.
    const std::string box = R"({"box": {"min": [4,-1,-1], "max": [5,1,1]}})";
    const std::string others[] = {
        R"({"vertices": [[0,0,0]], "traverse": {"parts": [)" + box + R"(]}, "route": [[0,0,0],[1,0,0]], "obstacles": []})",
        R"({"traverse": {"parts": [{"box": {"min": [0,0,0], "max": [1,1,1], "vertices": [[0,0,0]]}}]}, "route": [[0,0,0],[1,0,0]], "obstacles": []})",
        R"({"traverse": {"parts": [)" + box + R"(]}, "route": [[0,0,0],{"position": [1,0,0], "triangles": [[0,1,2]]}], "obstacles": []})",
        R"({"traverse": {"parts": [{"vertices": [[9,9,9]], "vertices": )" + v + R"(, "triangles": [[0,2,1]]}]}, "route": [[0,0,0],[1,0,0]], "obstacles": []})",
        R"({"traverse": {"parts": [{"vertices": )" + v + R"(, "triangles": [[0,2,1]], "triangles": [[0,2,9]]}]}, "route": [[0,0,0],[1,0,0]], "obstacles": []})",
        R"({"traverse": {"parts": [{"name": "\"vertices\": [[1,2,3]]", "vertices": )" + v + R"(, "triangles": [[0,2,1]]}]}, "route": [[0,0,0],[1,0,0]], "obstacles": []})",
        R"({"traverse": {"parts": [{"name": "a\\", "vertices": )" + v + R"(, "triangles": [[0,2,1]]}]}, "route": [[0,0,0],[1,0,0]], "obstacles": []})",
        R"({"traverse": {"parts": [{"triangles": [[0,2,1]], "vertices": )" + v + R"(}]}, "route": [[0,0,0],[1,0,0]], "obstacles": [{"vertices": )" + v + R"(, "triangles": [[3,2,1]]}]})",
        R"({"traverse": {"parts": [{"vertices": )" + v + R"(, "triangles": [[0,2,1]]}]}, "route": [[0,0,0],[1,0,0]], "obstacles": [)",
        R"({"traverse": {"parts": [{"vertices": )" + v + R"(, "triangles": [[0,2,1]]}]}, "route": [[0,0,0],[1,0,0]], "obstacles": []} trailing)",
        R"({"traverse": {"parts": [{"vertices": )" + v + R"(, "triangles": [[0,2,1]]}]}, "route": [[0,0,0],[1,0,0]], "obstacles": [], "name": "unfinished)",
        R"({"traverse": {"parts": [{"vertices": )" + v + R"(, "triangles": [[0,2,1]]}]}, "route": [[0,0,0],[1,0,0]], "obstacles": [], "x": "\)",
        R"({"vertices": )" + v + R"(})",
        R"([{"vertices": )" + v + R"(, "triangles": [[0,2,1]]}])",
    };
    for (const std::string& text : others) both_ways(text);
}
