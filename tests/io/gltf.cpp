// glTF 2.0 (native/src/io/gltf.cpp): files built here by hand (JSON with base64 data: URIs, .glb
// with a BIN chunk, external .bin files), the node hierarchy's transforms checked exactly, the
// .glb writer round trip, and every error path with its message. No sample files are downloaded.
#include "hullkit/hull.hpp"
#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"

#include "cli/cli_support.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace {

using hullkit::MeshResult;

std::string base64(const std::string& bytes) {
    static const char* const kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const std::uint32_t n = (std::uint8_t(bytes[i]) << 16) | (std::uint8_t(bytes[i + 1]) << 8) | std::uint8_t(bytes[i + 2]);
        for (int k = 3; k >= 0; --k) out += kDigits[(n >> (6 * k)) & 63];
    }
    if (i + 1 == bytes.size()) {
        const std::uint32_t n = std::uint8_t(bytes[i]) << 16;
        out += std::string{kDigits[(n >> 18) & 63], kDigits[(n >> 12) & 63], '=', '='};
    } else if (i + 2 == bytes.size()) {
        const std::uint32_t n = (std::uint8_t(bytes[i]) << 16) | (std::uint8_t(bytes[i + 1]) << 8);
        out += std::string{kDigits[(n >> 18) & 63], kDigits[(n >> 12) & 63], kDigits[(n >> 6) & 63], '='};
    }
    return out;
}

template <class T>
void append(std::string* bytes, T value) {
    bytes->append(reinterpret_cast<const char*>(&value), sizeof value);  // little endian, as glTF
}

void put_u32(std::string* bytes, std::uint32_t value) { append(bytes, value); }

/// A .glb of `json` and `bin` (both padded here).
std::string make_glb(std::string json, std::string bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string out;
    put_u32(&out, 0x46546C67u);
    put_u32(&out, 2);
    put_u32(&out, static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
    put_u32(&out, static_cast<std::uint32_t>(json.size()));
    put_u32(&out, 0x4E4F534Au);
    out += json;
    if (!bin.empty()) {
        put_u32(&out, static_cast<std::uint32_t>(bin.size()));
        put_u32(&out, 0x004E4942u);
        out += bin;
    }
    return out;
}

/// The buffer of the hierarchy scene: one triangle (float positions, uint16 indices + padding),
/// then a line (uint8 indices).
std::string triangle_buffer() {
    std::string bin;
    for (float v : {1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f}) append(&bin, v);  // 36 bytes
    for (std::uint16_t i : {0, 1, 2}) append(&bin, i);                                      // 6 bytes
    bin += std::string(2, '\0');                                                            // to 44
    for (std::uint8_t i : {0, 1}) append(&bin, i);                                          // 2 bytes: 46
    return bin;
}

/// The scene's JSON, the buffer given as `buffer` (a "uri" member or nothing for a .glb) and the
/// top-level "scene" member as `scene` (e.g. "\"scene\": 0," or "").
std::string hierarchy_json(const std::string& buffer, const std::string& scene) {
    return R"({"asset": {"version": "2.0"}, )" + scene + R"(
  "scenes": [{"nodes": [0]}, {"nodes": [2]}],
  "nodes": [
    {"translation": [10, 20, 30], "rotation": [0, 0, 1, 0], "scale": [2, 4, 8], "children": [1]},
    {"matrix": [0, 1, 0, 0,  -1, 0, 0, 0,  0, 0, 1, 0,  5, 6, 7, 1], "mesh": 0},
    {"mesh": 0}
  ],
  "meshes": [{"primitives": [
    {"attributes": {"POSITION": 0}, "indices": 1},
    {"attributes": {"POSITION": 0}, "indices": 2, "mode": 1}
  ]}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 1]},
    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
    {"bufferView": 2, "componentType": 5121, "count": 2, "type": "SCALAR"}
  ],
  "bufferViews": [
    {"buffer": 0, "byteOffset": 0, "byteLength": 36},
    {"buffer": 0, "byteOffset": 36, "byteLength": 6},
    {"buffer": 0, "byteOffset": 44, "byteLength": 2}
  ],
  "buffers": [{"byteLength": 46)" + buffer + R"(}]
})";
}

std::string embedded(const std::string& scene = "\"scene\": 0,") {
    return hierarchy_json(R"(, "uri": "data:application/octet-stream;base64,)" + base64(triangle_buffer()) + "\"", scene);
}

const std::string kLineWarning = "skipped 1 primitive of mode LINES (1), only TRIANGLES are read (first: mesh 0, primitive 1)";

}  // namespace

TEST_CASE("gltf: the node hierarchy's transforms (TRS and matrix) are applied exactly", "[gltf]") {
    // Node 0: T (10,20,30) * R (180 degrees about z) * S (2,4,8); its child node 1: a matrix that
    // turns x into y and y into -x, then moves by (5,6,7). p -> (10 - 2(5 - y), 20 - 4(x + 6), 30 + 8(z + 7)).
    const std::vector<double> transformed = {0, -8, 86, 2, -4, 86, 0, -4, 94};
    for (const bool binary : {false, true}) {
        const std::string bytes = binary ? make_glb(hierarchy_json("", "\"scene\": 0,"), triangle_buffer()) : embedded();
        const std::string name = binary ? "scene.glb" : "scene.gltf";
        INFO(name);
        const MeshResult mesh = hullkit::read_mesh(bytes, name);
        INFO(mesh.error);
        REQUIRE(mesh.ok());
        CHECK(mesh.xyz == transformed);
        CHECK(mesh.triangles == std::vector<std::uint32_t>{0, 1, 2});
        CHECK(mesh.warnings == std::vector<std::string>{kLineWarning});
        // By content alone too, and as points.
        CHECK(hullkit::read_mesh(bytes, "upload").xyz == transformed);
        const hullkit::PointsResult points = hullkit::read_points(bytes, name);
        REQUIRE(points.ok());
        CHECK(points.xyz == transformed);
        CHECK(points.warnings == mesh.warnings);
        CHECK(hullkit::read_points(bytes, "upload").xyz == transformed);
    }
    // Detection: by content, then by name.
    CHECK(hullkit::detect_mesh_format(embedded(), "x") == hullkit::MeshFormat::Gltf);
    CHECK(hullkit::detect_mesh_format(make_glb("{}", ""), "x") == hullkit::MeshFormat::Glb);
    CHECK(hullkit::detect_mesh_format("", "a.GLTF") == hullkit::MeshFormat::Gltf);
    CHECK(hullkit::detect_mesh_format("", "a.glb") == hullkit::MeshFormat::Glb);
    CHECK(std::string(hullkit::mesh_format_name(hullkit::MeshFormat::Glb)) == "binary glTF");
    // No default scene: every scene's nodes (scene 1 holds node 2, the mesh untransformed).
    const MeshResult all = hullkit::read_mesh(embedded(""), "scenes.gltf");
    REQUIRE(all.ok());
    CHECK(all.xyz == std::vector<double>{0, -8, 86, 2, -4, 86, 0, -4, 94, 1, 0, 0, 0, 1, 0, 0, 0, 1});
    CHECK(all.triangles == std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5});
    CHECK(all.warnings == std::vector<std::string>{
                              "skipped 2 primitives of mode LINES (1), only TRIANGLES are read (first: mesh 0, primitive 1)"});
    // The default scene 1.
    CHECK(hullkit::read_mesh(embedded("\"scene\": 1,"), "one.gltf").xyz == std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1});
}

TEST_CASE("gltf: without scenes every mesh is read as it is, unindexed triangles", "[gltf]") {
    std::string bin;
    for (float v : {0.5f, 0.0f, 0.0f, 0.0f, 0.25f, 0.0f, 0.0f, 0.0f, -2.0f}) append(&bin, v);
    const std::string json = R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}], "buffers": [{"byteLength": 36}]})";
    const MeshResult mesh = hullkit::read_mesh(make_glb(json, bin), "flat.glb");
    INFO(mesh.error);
    REQUIRE(mesh.ok());
    CHECK(mesh.xyz == std::vector<double>{0.5, 0, 0, 0, 0.25, 0, 0, 0, -2});
    CHECK(mesh.triangles == std::vector<std::uint32_t>{0, 1, 2});
    CHECK(mesh.warnings.empty());
}

TEST_CASE("gltf: normalized integer positions and interleaved (strided) vertices", "[gltf]") {
    // UNSIGNED_SHORT normalized, 8-byte stride (x y z + 2 bytes of something else).
    std::string bin;
    for (std::uint16_t v : {65535, 0, 0, 7, 0, 65535, 0, 7, 0, 0, 65535, 7}) append(&bin, v);
    const std::string json = R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5123, "normalized": true, "count": 3, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteLength": 24, "byteStride": 8}], "buffers": [{"byteLength": 24}]})";
    const MeshResult mesh = hullkit::read_mesh(make_glb(json, bin), "quantized.glb");
    INFO(mesh.error);
    REQUIRE(mesh.ok());
    CHECK(mesh.xyz == std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1});
}

TEST_CASE("gltf: a hull written as .glb reads back: same triangles, positions rounded to float", "[gltf]") {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<double> xyz;
    for (int i = 0; i < 3 * 500; ++i) xyz.push_back(uniform(random) * 1e3 + 0.1);
    const hullkit::Hull hull = hullkit::hull(hullkit::PointSpan(xyz));
    REQUIRE(hull.ok());
    const std::string glb = hullkit::write_glb(hullkit::PointSpan(xyz), hull);
    CHECK(glb.size() % 4 == 0);
    std::string via_dispatch = hullkit::write_hull(hullkit::OutputFormat::Glb, hullkit::PointSpan(xyz), hull);
    CHECK(via_dispatch == glb);
    const MeshResult back = hullkit::read_mesh(glb, "hull.glb");
    INFO(back.error);
    REQUIRE(back.ok());
    CHECK(back.warnings.empty());
    REQUIRE(back.point_count() == hull.vertices.size());
    std::vector<std::uint32_t> position(xyz.size() / 3, 0);
    for (std::size_t i = 0; i < hull.vertices.size(); ++i) {
        position[hull.vertices[i]] = static_cast<std::uint32_t>(i);
        for (int k = 0; k < 3; ++k) {
            CHECK(back.xyz[3 * i + k] == static_cast<double>(static_cast<float>(xyz[3 * hull.vertices[i] + k])));
        }
    }
    std::vector<std::uint32_t> expected;
    for (std::uint32_t corner : hull.triangles) expected.push_back(position[corner]);
    CHECK(back.triangles == expected);
    // The format is named and picked from the extension.
    hullkit::OutputFormat format = hullkit::OutputFormat::Off;
    CHECK(hullkit::output_format_from_path("out.GLB", &format));
    CHECK(format == hullkit::OutputFormat::Glb);
    CHECK(std::string(hullkit::output_format_name(format)) == "glb");
    // A coordinate beyond float's range cannot be written.
    std::vector<double> huge = xyz;
    huge[3 * hull.vertices[0]] = 1e300;
    CHECK_THROWS_AS(hullkit::write_glb(hullkit::PointSpan(huge), hull), std::domain_error);
    // A segment is a POINTS primitive: read back, it has no triangles (with a warning).
    const std::vector<double> segment = {0, 0, 0, 1, 1, 1, 2, 2, 2};
    const hullkit::Hull line = hullkit::hull(hullkit::PointSpan(segment));
    REQUIRE(line.dimension == 1);
    const MeshResult no_triangles = hullkit::read_mesh(hullkit::write_glb(hullkit::PointSpan(segment), line), "segment.glb");
    CHECK(no_triangles.error == "segment.glb: the mesh has no triangles");
}

TEST_CASE("gltf: a .gltf with external buffer files", "[gltf]") {
    hullkit_test::TempDir dir("hullkit-gltf");
    const std::string json = hierarchy_json(R"(, "uri": "parts/triangle.bin")", "\"scene\": 0,");
    std::filesystem::create_directories(dir.file("parts"));
    hullkit_test::write_text(dir.file("parts/triangle.bin"), triangle_buffer());
    hullkit_test::write_text(dir.file("scene.gltf"), json);
    // Natively, next to the file.
    const MeshResult mesh = hullkit::read_mesh(json, dir.file("scene.gltf"));
    INFO(mesh.error);
    REQUIRE(mesh.ok());
    CHECK(mesh.xyz == std::vector<double>{0, -8, 86, 2, -4, 86, 0, -4, 94});
    CHECK(hullkit::read_points(json, dir.file("scene.gltf")).xyz == mesh.xyz);
    // Missing: the file named, and why.
    const std::string missing = hierarchy_json(R"(, "uri": "missing.bin")", "");
    CHECK(hullkit::read_mesh(missing, dir.file("m.gltf")).error ==
          dir.file("m.gltf") + ": cannot read its buffer file \"missing.bin\": " + dir.file("missing.bin") +
              ": cannot open: No such file or directory");
    // Without a loader (as in the browser): refused, saying what to use instead.
    CHECK(hullkit::read_gltf_mesh(json, "scene.gltf", {}).error ==
          "scene.gltf: its buffer refers to the external file \"parts/triangle.bin\", which cannot be read here: use a "
          ".glb, or a .gltf with its buffers embedded as data: URIs");
}

TEST_CASE("gltf: errors name the file and what is wrong", "[gltf]") {
    const std::string good = make_glb(hierarchy_json("", "\"scene\": 0,"), triangle_buffer());
    auto error_of = [](const std::string& bytes, const std::string& name) {
        const MeshResult mesh = hullkit::read_mesh(bytes, name);
        INFO(name);
        CHECK_FALSE(mesh.ok());
        CHECK(mesh.xyz.empty());
        CHECK(mesh.error.find('\n') == std::string::npos);
        return mesh.error;
    };
    CHECK(error_of(good.substr(0, good.size() - 10), "cut.glb") ==
          "cut.glb: binary glTF is truncated: its header says " + std::to_string(good.size()) + " bytes, the file has " +
              std::to_string(good.size() - 10));
    CHECK(error_of(good.substr(0, 12), "short.glb") == "short.glb: binary glTF is truncated: 12 bytes, a header and a chunk take at least 20");
    CHECK(error_of("{\"asset\": {\"version\": \"2.0\"}, ", "broken.gltf").rfind("broken.gltf: not a valid glTF 2.0 file: ", 0) == 0);
    // An index past the vertices.
    std::string bad_index = hierarchy_json(R"(, "uri": "data:application/octet-stream;base64,)" + base64([] {
        std::string bin = triangle_buffer();
        bin[36 + 4] = 9;  // the third index
        return bin;
    }()) + "\"", "");
    CHECK(error_of(bad_index, "index.gltf") ==
          "index.gltf: mesh 0, primitive 0: indices accessor 1: index 9 (element 2) out of range (3 vertices)");
    // An accessor past its buffer view.
    std::string long_accessor = embedded();
    long_accessor.replace(long_accessor.find("\"count\": 3, \"type\": \"VEC3\""), 10, "\"count\": 4");
    CHECK(error_of(long_accessor, "long.gltf") ==
          "long.gltf: mesh 0, primitive 0: POSITION accessor 0: 4 elements run past the end of buffer view 0 (36 bytes)");
    // Sparse accessors are refused.
    std::string sparse = embedded();
    sparse.replace(sparse.find("\"min\": [0, 0, 0]"), 16,
                   R"("sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0}})");
    CHECK(error_of(sparse, "sparse.gltf") == "sparse.gltf: mesh 0, primitive 0: POSITION accessor 0 is sparse, which hullkit does not read");
    // Only lines: no triangles, and the warning is not lost in the error... the mesh is refused.
    std::string lines = embedded();
    lines.replace(lines.find("\"indices\": 1}"), 13, "\"indices\": 1, \"mode\": 3}");
    CHECK(error_of(lines, "lines.gltf") == "lines.gltf: the mesh has no triangles");
    // A cycle in the hierarchy.
    std::string cycle = embedded();
    cycle.replace(cycle.find("\"mesh\": 0},"), 11, "\"mesh\": 0, \"children\": [0]},");
    CHECK(error_of(cycle, "cycle.gltf").rfind("cycle.gltf: the node hierarchy has a cycle", 0) == 0);
}

TEST_CASE("gltf: hullkit hull reads .gltf/.glb and writes .glb, route reads glTF meshes", "[gltf][cli]") {
    hullkit_test::TempDir dir("hullkit-gltf-cli");
    // A cube's corners and its centre (last), all exact in float.
    std::string obj;
    for (int i = 0; i < 8; ++i) obj += "v " + std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " + std::to_string(i >> 2) + "\n";
    obj += "v 0.5 0.5 0.5\n";
    hullkit_test::write_text(dir.file("cube.obj"), obj);
    const hullkit_test::RunResult written = hullkit_test::run_cli(dir, {"hull", dir.file("cube.obj"), "-o", dir.file("cube.glb")});
    INFO(written.err);
    REQUIRE(written.exit_code == 0);
    CHECK(written.err.empty());
    const std::string glb = hullkit_test::read_text(dir.file("cube.glb"));
    CHECK(glb.compare(0, 4, "glTF") == 0);
    const hullkit_test::RunResult to_stdout = hullkit_test::run_cli(dir, {"hull", dir.file("cube.obj"), "--format", "glb"});
    CHECK(to_stdout.exit_code == 0);
    CHECK(to_stdout.out == glb);
    // The .glb's vertices are the cube's corners, in order: the same hull as from the OBJ.
    const hullkit_test::RunResult from_obj = hullkit_test::run_cli(dir, {"hull", dir.file("cube.obj")});
    const hullkit_test::RunResult from_glb = hullkit_test::run_cli(dir, {"hull", dir.file("cube.glb")});
    INFO(from_glb.err);
    CHECK(from_glb.exit_code == 0);
    CHECK(from_glb.err.empty());
    CHECK(from_glb.out == from_obj.out);
    // By content too (no extension), and the JSON flavour with an external buffer, with its warning.
    hullkit_test::write_text(dir.file("upload"), glb);
    CHECK(hullkit_test::run_cli(dir, {"hull", dir.file("upload")}).out == from_obj.out);
    hullkit_test::write_text(dir.file("triangle.bin"), triangle_buffer());
    hullkit_test::write_text(dir.file("scene.gltf"), hierarchy_json(R"(, "uri": "triangle.bin")", "\"scene\": 0,"));
    const hullkit_test::RunResult scene = hullkit_test::run_cli(dir, {"hull", dir.file("scene.gltf"), "--format", "xyz"});
    INFO(scene.err);
    CHECK(scene.exit_code == 0);
    CHECK(scene.err == "hullkit: warning: " + dir.file("scene.gltf") + ": " + kLineWarning + "\n");
    CHECK(scene.out.find("0 -8 86 # 0\n") != std::string::npos);
    // Errors: one line, exit 2.
    hullkit_test::write_text(dir.file("cut.glb"), glb.substr(0, glb.size() - 4));
    const hullkit_test::RunResult cut = hullkit_test::run_cli(dir, {"hull", dir.file("cut.glb")});
    CHECK(cut.exit_code == 2);
    CHECK(cut.err == "hullkit: " + dir.file("cut.glb") + ": binary glTF is truncated: its header says " +
                         std::to_string(glb.size()) + " bytes, the file has " + std::to_string(glb.size() - 4) + "\n");
    hullkit_test::write_text(dir.file("far.xyz"), "0 0 0\n1e39 0 0\n0 1 0\n0 0 1\n");
    const hullkit_test::RunResult far = hullkit_test::run_cli(dir, {"hull", dir.file("far.xyz"), "-o", dir.file("far.glb")});
    CHECK(far.exit_code == 2);
    CHECK(far.err == "hullkit: " + dir.file("far.glb") + ": coordinate 1e+39 of hull vertex 1 does not fit a glTF float32 position\n");
    // A route scene's obstacle from a .glb and one from a .gltf with its buffer file, next to the scene.
    hullkit_test::write_text(dir.file("route.json"), R"({"traverse": {"parts": [{"box": {"min": [-3,-3,-3], "max": [-2,-2,-2]}}]},
  "route": [[0,0,0], [0,0,-100]], "obstacles": [{"name": "cube", "mesh": "cube.glb"}, {"name": "tri", "mesh": "scene.gltf"}]})");
    const hullkit_test::RunResult route = hullkit_test::run_cli(dir, {"route", dir.file("route.json"), "--no-clearance"});
    INFO(route.out);
    CHECK(route.exit_code == 0);
    CHECK(route.err == "hullkit: warning: " + dir.file("route.json") + ": obstacles[1].mesh: scene.gltf: " + kLineWarning + "\n");
}

TEST_CASE("gltf: the committed fixtures (tests/data/gltf) read", "[gltf]") {
    auto read = [](const std::string& name) {
        std::string bytes, error;
        REQUIRE(hullkit::read_file(hullkit_test::data_path("gltf/" + name), &bytes, &error));
        return hullkit::read_mesh(bytes, name);
    };
    const MeshResult hierarchy = read("hierarchy.gltf");  // the scene above, written out by hand
    REQUIRE(hierarchy.ok());
    CHECK(hierarchy.xyz == std::vector<double>{0, -8, 86, 2, -4, 86, 0, -4, 94});
    CHECK(hierarchy.warnings == std::vector<std::string>{kLineWarning});
    const MeshResult cube = read("cube-hull.glb");  // `hullkit hull tests/data/cube.obj -o cube-hull.glb`
    REQUIRE(cube.ok());
    CHECK(cube.point_count() == 8);
    CHECK(cube.triangle_count() == 12);
    const MeshResult tetra = read("tetra-hull.glb");
    REQUIRE(tetra.ok());
    CHECK(tetra.triangle_count() == 4);
}
