// Mesh readers (native/src/io): every format written here by an independent writer and read
// back, the format detection, and every error path with its message.
#include "hullkit/mesh_read.hpp"

#include "cli/cli_support.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

using hullkit::MeshFormat;
using hullkit::MeshResult;

struct Mesh {
    std::vector<double> xyz;
    std::vector<std::uint32_t> triangles;
};

/// A closed octahedron-like mesh with coordinates exactly representable as floats (multiples of
/// 1/8), shuffled by a seed so that round trips are not tested on one lucky mesh only.
Mesh test_mesh(unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> eighths(-80, 80);
    Mesh mesh;
    const int count = 6 + static_cast<int>(seed % 5);
    for (int i = 0; i < 3 * count; ++i) mesh.xyz.push_back(eighths(random) / 8.0);
    std::uniform_int_distribution<int> pick(0, count - 1);
    for (int t = 0; t < 2 * count; ++t) {
        std::uint32_t a = pick(random), b = pick(random), c = pick(random);
        mesh.triangles.insert(mesh.triangles.end(), {a, b, c});
    }
    return mesh;
}

std::string number(double value) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

std::string write_obj(const Mesh& mesh) {
    std::string out = "# written by the test\no thing\n";
    for (std::size_t i = 0; i < mesh.xyz.size(); i += 3) {
        out += "v " + number(mesh.xyz[i]) + " " + number(mesh.xyz[i + 1]) + " " + number(mesh.xyz[i + 2]) + "\n";
    }
    out += "vt 0 0\nvn 0 0 1\n";
    // Alternate the corner forms: i, i/t, i//n, i/t/n and negative indices.
    const std::int64_t n = static_cast<std::int64_t>(mesh.xyz.size() / 3);
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
        out += "f";
        for (int c = 0; c < 3; ++c) {
            std::int64_t i = mesh.triangles[t + c] + 1;
            switch ((t / 3 + c) % 5) {
                case 0: out += " " + std::to_string(i); break;
                case 1: out += " " + std::to_string(i) + "/1"; break;
                case 2: out += " " + std::to_string(i) + "//1"; break;
                case 3: out += " " + std::to_string(i) + "/1/1"; break;
                default: out += " " + std::to_string(i - n - 1); break;  // -1 is vertex n
            }
        }
        out += "\n";
    }
    return out;
}

std::string write_off(const Mesh& mesh) {
    std::string out = "OFF\n" + std::to_string(mesh.xyz.size() / 3) + " " + std::to_string(mesh.triangles.size() / 3) + " 0\n";
    for (std::size_t i = 0; i < mesh.xyz.size(); i += 3) {
        out += number(mesh.xyz[i]) + " " + number(mesh.xyz[i + 1]) + " " + number(mesh.xyz[i + 2]) + "\n";
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
        out += "3 " + std::to_string(mesh.triangles[t]) + " " + std::to_string(mesh.triangles[t + 1]) + " " +
               std::to_string(mesh.triangles[t + 2]) + "\n";
    }
    return out;
}

void put(std::string& out, const void* data, std::size_t size, bool big_endian) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) out += static_cast<char>(bytes[big_endian ? size - 1 - i : i]);
}

/// PLY with an extra vertex property and an extra element, so that skipping them is tested too.
std::string write_ply(const Mesh& mesh, const std::string& format) {
    const std::size_t nv = mesh.xyz.size() / 3, nf = mesh.triangles.size() / 3;
    std::string out = "ply\nformat " + format + " 1.0\ncomment test\nelement vertex " + std::to_string(nv) +
                      "\nproperty double x\nproperty float confidence\nproperty double y\nproperty double z\n"
                      "element face " + std::to_string(nf) +
                      "\nproperty list uchar int vertex_indices\nelement edge 1\nproperty int vertex1\nproperty int vertex2\n"
                      "end_header\n";
    if (format == "ascii") {
        for (std::size_t i = 0; i < nv; ++i) {
            out += number(mesh.xyz[3 * i]) + " 0.5 " + number(mesh.xyz[3 * i + 1]) + " " + number(mesh.xyz[3 * i + 2]) + "\n";
        }
        for (std::size_t t = 0; t < nf; ++t) {
            out += "3 " + std::to_string(mesh.triangles[3 * t]) + " " + std::to_string(mesh.triangles[3 * t + 1]) + " " +
                   std::to_string(mesh.triangles[3 * t + 2]) + "\n";
        }
        out += "0 1\n";
        return out;
    }
    const bool big = format == "binary_big_endian";
    for (std::size_t i = 0; i < nv; ++i) {
        const float confidence = 0.5f;
        put(out, &mesh.xyz[3 * i], 8, big);
        put(out, &confidence, 4, big);
        put(out, &mesh.xyz[3 * i + 1], 8, big);
        put(out, &mesh.xyz[3 * i + 2], 8, big);
    }
    for (std::size_t t = 0; t < nf; ++t) {
        out += static_cast<char>(3);
        for (int c = 0; c < 3; ++c) {
            const std::int32_t index = static_cast<std::int32_t>(mesh.triangles[3 * t + c]);
            put(out, &index, 4, big);
        }
    }
    const std::int32_t edge[2] = {0, 1};
    put(out, &edge[0], 4, big);
    put(out, &edge[1], 4, big);
    return out;
}

std::string write_ascii_stl(const Mesh& mesh) {
    std::string out = "solid test\n";
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
        out += "  facet normal 0 0 0\n    outer loop\n";
        for (int c = 0; c < 3; ++c) {
            const double* p = &mesh.xyz[3 * mesh.triangles[t + c]];
            out += "      vertex " + number(p[0]) + " " + number(p[1]) + " " + number(p[2]) + "\n";
        }
        out += "    endloop\n  endfacet\n";
    }
    return out + "endsolid test\n";
}

std::string write_binary_stl(const Mesh& mesh, const std::string& header_text = "binary STL from the test") {
    std::string out = header_text;
    out.resize(80, ' ');
    const std::uint32_t count = static_cast<std::uint32_t>(mesh.triangles.size() / 3);
    put(out, &count, 4, false);
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
        const float normal[3] = {0, 0, 0};
        for (float n : normal) put(out, &n, 4, false);
        for (int c = 0; c < 3; ++c) {
            for (int axis = 0; axis < 3; ++axis) {
                const float value = static_cast<float>(mesh.xyz[3 * mesh.triangles[t + c] + axis]);
                put(out, &value, 4, false);
            }
        }
        out += std::string(2, '\0');
    }
    return out;
}

/// Readers that keep the file's vertex list must give back exactly the mesh written.
void require_same_mesh(const MeshResult& read, const Mesh& mesh) {
    INFO(read.error);
    REQUIRE(read.ok());
    REQUIRE(read.xyz == mesh.xyz);
    REQUIRE(read.triangles == mesh.triangles);
}

/// STL has no shared vertices: compare corner coordinates triangle by triangle, and check that
/// no two read vertices are equal (the merge happened).
void require_same_soup(const MeshResult& read, const Mesh& mesh) {
    INFO(read.error);
    REQUIRE(read.ok());
    REQUIRE(read.triangles.size() == mesh.triangles.size());
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        for (int axis = 0; axis < 3; ++axis) {
            REQUIRE(read.xyz[3 * read.triangles[k] + axis] == mesh.xyz[3 * mesh.triangles[k] + axis]);
        }
    }
    std::map<std::array<double, 3>, int> seen;
    for (std::size_t i = 0; i < read.xyz.size(); i += 3) {
        REQUIRE(seen.emplace(std::array<double, 3>{read.xyz[i], read.xyz[i + 1], read.xyz[i + 2]}, 0).second);
    }
}

std::string error_of(const std::string& bytes, const std::string& source) {
    MeshResult result = hullkit::read_mesh(bytes, source);
    REQUIRE_FALSE(result.ok());
    REQUIRE(result.xyz.empty());
    REQUIRE(result.triangles.empty());
    REQUIRE(result.error.find('\n') == std::string::npos);
    return result.error;
}

}  // namespace

TEST_CASE("mesh_read: every format round trips", "[mesh_read]") {
    for (unsigned seed = 1; seed <= 8; ++seed) {
        const Mesh mesh = test_mesh(seed);
        INFO("seed " << seed);
        require_same_mesh(hullkit::read_mesh(write_obj(mesh), "m.obj"), mesh);
        require_same_mesh(hullkit::read_mesh(write_off(mesh), "m.off"), mesh);
        require_same_mesh(hullkit::read_mesh(write_ply(mesh, "ascii"), "m.ply"), mesh);
        require_same_mesh(hullkit::read_mesh(write_ply(mesh, "binary_little_endian"), "m.ply"), mesh);
        require_same_mesh(hullkit::read_mesh(write_ply(mesh, "binary_big_endian"), "m.ply"), mesh);
        require_same_soup(hullkit::read_mesh(write_ascii_stl(mesh), "m.stl"), mesh);
        require_same_soup(hullkit::read_mesh(write_binary_stl(mesh), "m.stl"), mesh);
        // Detection is by content: the names say nothing here.
        require_same_mesh(hullkit::read_mesh(write_ply(mesh, "binary_big_endian"), "bytes"), mesh);
        require_same_soup(hullkit::read_mesh(write_binary_stl(mesh), "bytes"), mesh);
    }
}

TEST_CASE("mesh_read: format detection", "[mesh_read]") {
    const Mesh mesh = test_mesh(3);
    CHECK(hullkit::detect_mesh_format(write_obj(mesh), "x") == MeshFormat::Obj);
    CHECK(hullkit::detect_mesh_format(write_off(mesh), "x") == MeshFormat::Off);
    CHECK(hullkit::detect_mesh_format(write_ply(mesh, "ascii"), "x") == MeshFormat::Ply);
    CHECK(hullkit::detect_mesh_format(write_ascii_stl(mesh), "x") == MeshFormat::StlAscii);
    CHECK(hullkit::detect_mesh_format(write_binary_stl(mesh), "x") == MeshFormat::StlBinary);
    // Binary STL headers that start with "solid" (some exporters write them) are still binary.
    const std::string tricky = write_binary_stl(mesh, "solid exported by a CAD tool");
    CHECK(hullkit::detect_mesh_format(tricky, "x") == MeshFormat::StlBinary);
    require_same_soup(hullkit::read_mesh(tricky, "x.stl"), mesh);
    // Nothing to go on but the extension.
    CHECK(hullkit::detect_mesh_format(std::string(30, '\x01'), "a.STL") == MeshFormat::StlBinary);
    CHECK(hullkit::detect_mesh_format("1 2 3\n", "a.txt") == MeshFormat::Unknown);
    CHECK(std::string(hullkit::mesh_format_name(MeshFormat::StlBinary)) == "binary STL");
}

TEST_CASE("mesh_read: OBJ polygons, negative indices and forward references", "[mesh_read]") {
    // A unit square as one quad (fan: 2 triangles), a pentagon face by negative indices, and a
    // face that names a vertex defined after it.
    const std::string text =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "f 1/1/1 2/2/2 3/3/3 4/4/4\n"
        "f 5 1 2\n"
        "v 0.5 0.5 1 0.1 0.2 0.3\n"
        "f -5 -4 -3 -2 -1\n";
    MeshResult mesh = hullkit::read_obj_mesh(text, "poly.obj");
    INFO(mesh.error);
    REQUIRE(mesh.ok());
    CHECK(mesh.point_count() == 5);
    CHECK(mesh.triangles == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 4, 0, 1, 0, 1, 2, 0, 2, 3, 0, 3, 4});
}

TEST_CASE("mesh_read: STL merges identical corners, -0 and +0 alike", "[mesh_read]") {
    const std::string text =
        "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
        "facet normal 0 0 1\nouter loop\nvertex -0 0 -0\nvertex 0 1 0\nvertex 1 1 0\nendloop\nendfacet\nendsolid s\n";
    MeshResult mesh = hullkit::read_stl_mesh(text, "s.stl");
    INFO(mesh.error);
    REQUIRE(mesh.ok());
    CHECK(mesh.point_count() == 4);
    CHECK(mesh.triangles == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
}

TEST_CASE("mesh_read: OBJ errors name the file and line", "[mesh_read]") {
    std::string eight = "# vessel\n";
    for (int i = 0; i < 8; ++i) eight += "v " + std::to_string(i) + " 0 " + std::to_string(i * i) + "\n";
    // Line 12 names vertex 9 of 8.
    CHECK(error_of(eight + "f 1 2 3\nf 2 3 4\nf 1 2 9\n", "vessel.obj") == "vessel.obj:12: face index 9 out of range (8 vertices)");
    CHECK(error_of(eight + "f 1 2 -9\n", "vessel.obj") == "vessel.obj:10: face index -9 out of range (8 vertices so far)");
    CHECK(error_of(eight + "f 1 0 2\n", "a.obj") == "a.obj:10: face corner \"0\" is not a vertex index (1-based, or negative)");
    CHECK(error_of(eight + "f 1 x/1 2\n", "a.obj") == "a.obj:10: face corner \"x/1\" is not a vertex index (1-based, or negative)");
    CHECK(error_of(eight + "f 1 2\n", "a.obj") == "a.obj:10: a face needs at least 3 vertices, got 2");
    CHECK(error_of("v 1 2\n", "a.obj") == "a.obj:1: a vertex needs 3 coordinates (\"v x y z\"), got 2 values");
    CHECK(error_of("v 1 2 nan\n", "a.obj") == "a.obj:1: coordinate \"nan\" is not a finite number");
    CHECK(error_of("v 1 2 1e999\n", "a.obj") == "a.obj:1: coordinate \"1e999\" is not a finite number");
    // Unknown records are skipped (see below), but a malformed vertex or face after one is not.
    CHECK(error_of("648 1292\nv 1 2 3\nbogus 1\nv 1 2\n", "a.obj") ==
          "a.obj:4: a vertex needs 3 coordinates (\"v x y z\"), got 2 values");
    CHECK(error_of("648 1292\nv 1 2 3\nbogus 1\nf 1 1\n", "a.obj") == "a.obj:4: a face needs at least 3 vertices, got 2");
    CHECK(error_of("o empty\n", "a.obj") == "a.obj: no vertices (\"v x y z\" lines), expected an OBJ mesh");
    CHECK(error_of("v 1 2 3\nv 2 3 4\n", "points.obj") == "points.obj: the mesh has no triangles");
}

TEST_CASE("mesh_read: unknown OBJ records are skipped with one warning per kind", "[mesh_read]") {
    const std::string body = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    const MeshResult clean = hullkit::read_mesh(body, "tetra.obj");
    REQUIRE(clean.ok());
    CHECK(clean.warnings.empty());
    // FCL's test meshes start with a "V F" count line; three.js's OBJLoader and tinyobjloader skip
    // such records, and so does hullkit, saying so.
    const std::string fcl = "4 4\n" + body + "bogus 1\nbogus 2\n";
    const MeshResult mesh = hullkit::read_mesh(fcl, "tetra.obj");
    INFO(mesh.error);
    REQUIRE(mesh.ok());
    CHECK(mesh.xyz == clean.xyz);
    CHECK(mesh.triangles == clean.triangles);
    CHECK(mesh.warnings == std::vector<std::string>{"skipped 1 unknown OBJ record \"4\" (first at line 1)",
                                                    "skipped 2 unknown OBJ records \"bogus\" (first at line 11)"});
    // read_points and read_points_2d pass the warnings on.
    const hullkit::PointsResult points = hullkit::read_points(fcl, "tetra.obj");
    REQUIRE(points.ok());
    CHECK(points.xyz == clean.xyz);
    CHECK(points.warnings == mesh.warnings);
    CHECK(hullkit::read_points_2d(fcl, "tetra.obj").warnings == mesh.warnings);
}

TEST_CASE("mesh_read: PLY errors", "[mesh_read]") {
    const Mesh mesh = test_mesh(2);
    const std::string ascii = write_ply(mesh, "ascii");
    const std::size_t body = ascii.find("end_header\n") + 11;
    const int header_lines = 14;  // "ply" ... "end_header": the body starts on line 15

    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 1\n", "a.ply") == "a.ply: the PLY header has no \"end_header\"");
    CHECK(error_of("ply\nformat text 1.0\nend_header\n", "a.ply") == "a.ply:2: unknown PLY format \"text\"");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n", "a.ply") ==
          "a.ply:4: unknown property type \"quad\"");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n", "a.ply") ==
          "a.ply: the PLY vertex element has no scalar property \"z\"");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
                   "a.ply") == "a.ply: the PLY header declares no \"face\" element");
    CHECK(error_of("ply\nend_header\n", "a.ply") == "a.ply:2: no \"format\" line before end_header");

    // Ascii body: a vertex line short of a value, one with a value too many, a bad number, a bad index.
    std::string text = ascii;
    const std::size_t line_end = text.find('\n', body);
    std::string first = text.substr(body, line_end - body);
    CHECK(error_of(text.substr(0, body) + first.substr(0, first.rfind(' ')) + text.substr(line_end), "a.ply") ==
          "a.ply:" + std::to_string(header_lines + 1) + ": vertex 0 has too few values");
    CHECK(error_of(text.substr(0, body) + first + " 7" + text.substr(line_end), "a.ply") ==
          "a.ply:" + std::to_string(header_lines + 1) + ": vertex 0 has 1 values too many");
    CHECK(error_of(text.substr(0, body) + "1 0.5 zz 3" + text.substr(line_end), "a.ply") ==
          "a.ply:" + std::to_string(header_lines + 1) + ": vertex 0: value \"zz\" is not a finite number");
    const std::size_t nv = mesh.xyz.size() / 3;
    const std::size_t face_line = header_lines + 1 + nv;
    std::size_t face_start = body;
    for (std::size_t i = 0; i < nv; ++i) face_start = text.find('\n', face_start) + 1;
    const std::size_t face_end = text.find('\n', face_start);
    CHECK(error_of(text.substr(0, face_start) + "3 0 1 " + std::to_string(nv) + text.substr(face_end), "a.ply") ==
          "a.ply:" + std::to_string(face_line) + ": face 0: index " + std::to_string(nv) + " out of range (" +
              std::to_string(nv) + " vertices)");
    CHECK(error_of(text.substr(0, face_start) + "2 0 1" + text.substr(face_end), "a.ply") ==
          "a.ply:" + std::to_string(face_line) + ": face 0: a face needs at least 3 vertices, got 2");
    CHECK(error_of(ascii + "1 2\n", "a.ply").find(": content after the last element") != std::string::npos);
    // Ascii integers must fit their declared type: a uchar count of 1e300 or 300, an int index of 1e10.
    CHECK(error_of(text.substr(0, face_start) + "1e300 0 1 2" + text.substr(face_end), "a.ply") ==
          "a.ply:" + std::to_string(face_line) + ": face 0: value \"1e300\" is outside the declared type's range [0, 255]");
    CHECK(error_of(text.substr(0, face_start) + "300 0 1 2" + text.substr(face_end), "a.ply") ==
          "a.ply:" + std::to_string(face_line) + ": face 0: value \"300\" is outside the declared type's range [0, 255]");
    CHECK(error_of(text.substr(0, face_start) + "3 0 1 1e10" + text.substr(face_end), "a.ply") ==
          "a.ply:" + std::to_string(face_line) +
              ": face 0: value \"1e10\" is outside the declared type's range [-2147483648, 2147483647]");

    // Binary: cut short, or with bytes left over.
    const std::string binary = write_ply(mesh, "binary_little_endian");
    const std::size_t binary_body = binary.find("end_header\n") + 11;
    CHECK(error_of(binary.substr(0, binary.size() - 3), "b.ply") ==
          "b.ply: binary PLY is truncated in edge 0 (byte " + std::to_string(binary.size() - 4) + " of " +
              std::to_string(binary.size() - 3) + ")");
    CHECK(error_of(binary.substr(0, binary_body + 10), "b.ply") ==
          "b.ply: binary PLY is truncated in vertex 0 (byte " + std::to_string(binary_body + 8) + " of " +
              std::to_string(binary_body + 10) + ")");
    CHECK(error_of(binary + "xy", "b.ply") == "b.ply: binary PLY has 2 bytes after the last element (byte " +
                                                 std::to_string(binary.size()) + ")");
    // A NaN coordinate in a binary body.
    std::string with_nan = binary;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::memcpy(&with_nan[binary_body], &nan, 8);
    CHECK(error_of(with_nan, "b.ply") == "b.ply: vertex 0 (byte " + std::to_string(binary_body) + "): a value is not a finite number");
}

TEST_CASE("mesh_read: STL errors", "[mesh_read]") {
    const Mesh mesh = test_mesh(4);
    const std::string binary = write_binary_stl(mesh);
    const std::size_t n = mesh.triangles.size() / 3;
    CHECK(error_of(binary.substr(0, binary.size() - 7), "t.stl") ==
          "t.stl: binary STL is truncated: 84 + 50*N bytes expected (N = " + std::to_string(n) + " triangles: " +
              std::to_string(84 + 50 * n) + " bytes), got " + std::to_string(binary.size() - 7));
    CHECK(error_of(binary.substr(0, 50), "t.stl") ==
          "t.stl: binary STL is truncated: at least 84 bytes expected (header and triangle count), got 50");
    CHECK(hullkit::read_stl_mesh(binary + "abc", "t.stl").error ==
          "t.stl: binary STL is too long: 84 + 50*N bytes expected (N = " + std::to_string(n) + " triangles: " +
              std::to_string(84 + 50 * n) + " bytes), got " + std::to_string(binary.size() + 3));
    std::string with_inf = binary;
    const float inf = std::numeric_limits<float>::infinity();
    std::memcpy(&with_inf[84 + 50 * 2 + 12 + 4], &inf, 4);
    CHECK(error_of(with_inf, "t.stl") == "t.stl: triangle 2 (byte " + std::to_string(84 + 100 + 16) +
                                             "): coordinate is not a finite number");

    const std::string ascii = write_ascii_stl(mesh);
    CHECK(error_of(ascii.substr(0, ascii.rfind("endsolid")), "a.stl") ==
          "a.stl: ASCII STL ends early (line " + std::to_string(1 + 7 * n) + "): no \"endsolid\"");
    CHECK(error_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid\n", "a.stl") ==
          "a.stl:6: a facet needs 3 vertices, got 2");
    CHECK(error_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n", "a.stl") == "a.stl:4: expected \"vertex x y z\"");
    CHECK(error_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 q\n", "a.stl") ==
          "a.stl:4: coordinate \"q\" is not a finite number");
    CHECK(error_of("solid x\nfacet normal 0 0 1\nloop\n", "a.stl") == "a.stl:3: expected \"outer loop\", got \"loop\"");
    CHECK(error_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendsolid\n",
                   "a.stl") == "a.stl:8: expected \"endfacet\", got \"endsolid\"");
}

TEST_CASE("mesh_read: unknown, empty and OFF input through read_mesh", "[mesh_read]") {
    CHECK(error_of("", "e.obj") == "e.obj: no vertices (\"v x y z\" lines), expected an OBJ mesh");
    CHECK(error_of("", "bytes") == "bytes: empty file, expected a mesh (OBJ, OFF, PLY, STL or glTF)");
    CHECK(error_of("hello world\n", "x.txt") == "x.txt: not a mesh file this reader knows (OBJ, OFF, PLY, STL or glTF)");
    // OFF goes to the existing reader, with its own messages; non-finite coordinates are refused here.
    CHECK(error_of("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", "t.off").rfind("t.off:6:", 0) == 0);
    CHECK(error_of("OFF\n3 1 0\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n", "t.off") ==
          "t.off:4: coordinate \"nan\" of point 1 is not a finite number");
}

TEST_CASE("mesh_read: the committed fixtures read", "[mesh_read]") {
    for (const char* name : {"route/vessel.obj", "route/load.stl", "route/plate.ply", "route/post.off"}) {
        INFO(name);
        std::string bytes, error;
        REQUIRE(hullkit::read_file(hullkit_test::data_path(name), &bytes, &error));
        MeshResult mesh = hullkit::read_mesh(bytes, name);
        INFO(mesh.error);
        CHECK(mesh.ok());
        CHECK(mesh.triangle_count() > 0);
    }
}

TEST_CASE("mesh_read: truncated and corrupted files give a mesh or a one-line error, never a crash", "[mesh_read]") {
    const Mesh mesh = test_mesh(5);
    const std::string files[] = {write_obj(mesh), write_off(mesh), write_ply(mesh, "ascii"), write_ply(mesh, "binary_little_endian"),
                                 write_ply(mesh, "binary_big_endian"), write_ascii_stl(mesh), write_binary_stl(mesh)};
    std::mt19937 random(7);
    for (const std::string& file : files) {
        for (int trial = 0; trial < 200; ++trial) {
            std::string bytes = file;
            if (trial % 2 == 0) {
                bytes.resize(random() % bytes.size());  // cut anywhere
            } else {
                for (int k = 0; k < 3; ++k) bytes[random() % bytes.size()] = static_cast<char>(random() % 256);
            }
            MeshResult result = hullkit::read_mesh(bytes, "f.mesh");
            if (result.ok()) {
                // Whatever was read must be a valid mesh: indices in range, finite coordinates.
                for (std::uint32_t index : result.triangles) REQUIRE(index < result.point_count());
                for (double x : result.xyz) REQUIRE(std::isfinite(x));
                REQUIRE(result.triangle_count() > 0);
            } else {
                REQUIRE(result.error.rfind("f.mesh", 0) == 0);
                REQUIRE(result.error.find('\n') == std::string::npos);
            }
        }
    }
}

TEST_CASE("mesh_read: regression inputs from fuzzing (tests/data/fuzz) give a clear error or the mesh", "[mesh_read]") {
    auto read = [](const std::string& name) {
        std::string bytes, error;
        REQUIRE(hullkit::read_file(hullkit_test::data_path("fuzz/" + name), &bytes, &error));
        return hullkit::read_mesh(bytes, name);
    };
    // A 19-digit index overflowed int64 while it was parsed (undefined behaviour).
    CHECK(read("obj-face-index-19-digits.obj").error ==
          "obj-face-index-19-digits.obj:4: face corner \"9999999999999999999\" is not a vertex index (1-based, or negative)");
    // Ascii PLY values of any magnitude were cast to long long for the message, and a list count of
    // 1e300 to uint64 for the loop (undefined behaviour): integers must fit their declared type.
    CHECK(read("ply-ascii-list-count-minus-1e300.ply").error ==
          "ply-ascii-list-count-minus-1e300.ply:13: face 0: value \"-1e300\" is outside the declared type's range [0, 255]");
    CHECK(read("ply-ascii-list-count-1e300.ply").error ==
          "ply-ascii-list-count-1e300.ply:13: face 0: value \"1e300\" is outside the declared type's range [0, 255]");
    CHECK(read("ply-ascii-face-index-1e300.ply").error ==
          "ply-ascii-face-index-1e300.ply:13: face 0: value \"1e300\" is outside the declared type's range "
          "[-2147483648, 2147483647]");
    // Bytes of the file in a message: printable ASCII only (0xff 0xfe used to be echoed raw).
    // (Now a skipped record, so the file has no vertices; with some, its warning is printable too.)
    const std::string name = "obj-unknown-record-escape-and-high-bytes.obj";
    CHECK(read(name).error == name + ": no vertices (\"v x y z\" lines), expected an OBJ mesh");
    std::string bytes, why;
    REQUIRE(hullkit::read_file(hullkit_test::data_path("fuzz/" + name), &bytes, &why));
    const MeshResult escape = hullkit::read_mesh(bytes + "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", name);
    REQUIRE(escape.ok());
    CHECK(escape.warnings == std::vector<std::string>{"skipped 1 unknown OBJ record \"?[31m??\" (first at line 1)"});
    // 10^18 rows of an element without properties: nothing to read in a binary body, which used to
    // spin through every row.
    const MeshResult empty_rows = read("ply-binary-empty-element-1e18-rows.ply");
    INFO(empty_rows.error);
    CHECK(empty_rows.xyz == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0});
    CHECK(empty_rows.triangles == std::vector<std::uint32_t>{0, 1, 2});
    // An element named with non-ASCII bytes was echoed in "truncated in NAME ROW".
    const MeshResult named = read("ply-element-name-binary-bytes.ply");
    INFO(named.error);
    CHECK(named.error.rfind("ply-element-name-binary-bytes.ply: binary PLY is truncated in \"noe???", 0) == 0);
    for (unsigned char c : named.error) CHECK((c >= 0x20 && c < 0x7f));
}

TEST_CASE("mesh_read: PLY point clouds and read_points / read_points_2d for every format", "[mesh_read]") {
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    const std::string cloud = header + "end_header\n0 0 0\n1 2 3\n4 5 6\n";
    // Without a face element: a mesh reader refuses it, the point readers take the vertices.
    CHECK(hullkit::read_ply_mesh(cloud, "c.ply").error == "c.ply: the PLY header declares no \"face\" element");
    const hullkit::PointsResult points = hullkit::read_ply_points(cloud, "c.ply");
    REQUIRE(points.ok());
    CHECK(points.xyz == std::vector<double>{0, 0, 0, 1, 2, 3, 4, 5, 6});
    CHECK(hullkit::read_points(cloud, "c.ply").xyz == points.xyz);
    CHECK(hullkit::read_points(cloud, "upload").xyz == points.xyz);  // by content
    CHECK(hullkit::read_points_2d(cloud, "c.ply").xy == std::vector<double>{0, 0, 1, 2, 4, 5});
    // Faces that are there are still checked.
    const std::string bad_face = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                 "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";
    CHECK(hullkit::read_points(bad_face, "f.ply").error.find("index 7 out of range") != std::string::npos);
    // Text formats as parse_points / parse_points_2d read them; STL through the mesh reader.
    CHECK(hullkit::read_points("0 0 0\n1 1 1\n", "p.xyz").xyz == std::vector<double>{0, 0, 0, 1, 1, 1});
    CHECK(hullkit::read_points("v 0 0 0\nv 1 0 0\n", "cloud.obj").xyz.size() == 6);  // OBJ vertices, no faces
    CHECK(hullkit::read_points_2d("0 0\n1 0\n0 1\n", "p.txt").xy == std::vector<double>{0, 0, 1, 0, 0, 1});
    const std::string stl = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                            "endloop\nendfacet\nendsolid t\n";
    CHECK(hullkit::read_points(stl, "t.stl").xyz == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0});
    CHECK(hullkit::read_points_2d(stl, "t").xy == std::vector<double>{0, 0, 1, 0, 0, 1});
    // Errors keep the reader's wording.
    CHECK(hullkit::read_points("0 0\n", "p.xyz").error == "p.xyz:1: expected 3 coordinates, got 2");
    CHECK_FALSE(hullkit::read_points_2d(header + "end_header\n0 0\n", "short.ply").ok());
}
