// Tests of the point readers and hull writers in hullkit/mesh_io.hpp (no geometry involved:
// hulls are written by hand here).
#include "hullkit/mesh_io.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using hullkit::Hull;
using hullkit::MeshResult;
using hullkit::OutputFormat;
using hullkit::PointsResult;
using hullkit::PointSpan;
using hullkit::parse_points;
using hullkit::read_off_mesh;

namespace {

std::string data_path(const std::string& name) { return std::string(HULLKIT_TEST_DATA) + "/" + name; }

std::string load(const std::string& name) {
    std::string text, error;
    bool ok = hullkit::read_file(data_path(name), &text, &error);
    INFO(error);
    REQUIRE(ok);
    return text;
}

/// Parses text that must be valid; fails the test with the reader's message otherwise.
std::vector<double> points_of(const std::string& text, const std::string& source = "t.txt") {
    PointsResult result = parse_points(text, source);
    INFO(result.error);
    REQUIRE(result.ok());
    REQUIRE(result.xyz.size() % 3 == 0);
    return result.xyz;
}

/// Parses text that must be rejected; returns the message.
std::string error_of(const std::string& text, const std::string& source = "t.txt") {
    PointsResult result = parse_points(text, source);
    INFO("parsed " << result.count() << " points from: " << text);
    REQUIRE_FALSE(result.ok());
    CHECK(result.xyz.empty());
    CHECK(result.error.find('\n') == std::string::npos);  // one line
    return result.error;
}

std::string mesh_error_of(const std::string& text, const std::string& source = "m.off") {
    MeshResult result = read_off_mesh(text, source);
    INFO("read " << result.triangle_count() << " triangles from: " << text);
    REQUIRE_FALSE(result.ok());
    CHECK(result.xyz.empty());
    CHECK(result.triangles.empty());
    CHECK(result.error.find('\n') == std::string::npos);
    return result.error;
}

/// 7 points of which 1, 3, 4, 6 form a tetrahedron "hull"; faces CCW from outside.
struct SmallHull {
    std::vector<double> xyz = {
        0.5, 0.5, 0.5,  // 0 (inside)
        0,   0,   0,    // 1
        0.2, 0.2, 0.2,  // 2 (inside)
        1,   0,   0,    // 3
        0,   1,   0,    // 4
        0.1, 0.1, 0.1,  // 5 (inside)
        0,   0,   1.5,  // 6
    };
    Hull hull;
    SmallHull() {
        hull.dimension = 3;
        hull.vertices = {1, 3, 4, 6};
        hull.triangles = {1, 4, 3, 1, 3, 6, 1, 6, 4, 3, 4, 6};
        hull.volume = 0.25;
        hull.area = 2.5;
    }
    PointSpan span() const { return PointSpan(xyz); }
};

}  // namespace

// ---- plain x y z ----

TEST_CASE("mesh_io: plain xyz with whitespace, commas, comments and CRLF") {
    std::string text =
        "# header comment\n"
        "1 2 3\n"
        "\n"
        "  -4.5\t5e-1   +6  # trailing comment\r\n"
        "7,8,9\n"
        "10 , 11 ,12\n"
        "   \n"
        ".25 1e3 -0";
    std::vector<double> xyz = points_of(text);
    std::vector<double> expected = {1, 2, 3, -4.5, 0.5, 6, 7, 8, 9, 10, 11, 12, 0.25, 1000, 0};
    CHECK(xyz == expected);
    CHECK(std::signbit(xyz[14]));  // "-0" keeps its sign
}

TEST_CASE("mesh_io: xyz coordinate count errors name the line") {
    CHECK(error_of("1 2 3\n\n# comment\n4 5\n6 7 8\n") == "t.txt:4: expected 3 coordinates, got 2");
    CHECK(error_of("1 2 3 4\n") == "t.txt:1: expected 3 coordinates, got 4");
    CHECK(error_of("1 2 3\r\n1 2 3 4\r\n", "crlf.txt") == "crlf.txt:2: expected 3 coordinates, got 4");
}

TEST_CASE("mesh_io: xyz empty comma fields are errors, not silently dropped") {
    CHECK(error_of("1,,2,3\n") == "t.txt:1: empty field before a comma");
    CHECK(error_of("1 2 3\n,1,2,3\n") == "t.txt:2: empty field before a comma");
    CHECK(error_of("1,2,3,\n") == "t.txt:1: empty field after the last comma");
}

TEST_CASE("mesh_io: malformed numbers are quoted with their line") {
    CHECK(error_of("0 0 0\n1 0 0\n0 1.2.3 0\n", "x.txt") ==
          "x.txt:3: coordinate \"1.2.3\" is not a number");
    CHECK(error_of("1 2 abc\n") == "t.txt:1: coordinate \"abc\" is not a number");
    CHECK(error_of("1e 2 3\n") == "t.txt:1: coordinate \"1e\" is not a number");
    CHECK(error_of("--1 2 3\n") == "t.txt:1: coordinate \"--1\" is not a number");
    CHECK(error_of("+-1 2 3\n") == "t.txt:1: coordinate \"+-1\" is not a number");
    CHECK(error_of("0x10 2 3\n") == "t.txt:1: coordinate \"0x10\" is not a number");
    CHECK(error_of("1 2 3;\n") == "t.txt:1: coordinate \"3;\" is not a number");
    // Bytes that are not printable ASCII and very long tokens stay printable and short in the
    // one-line message. (Control bytes near the start make the whole input "binary data".)
    CHECK(error_of("1 2 \xc3\xa9\n") == "t.txt:1: coordinate \"??\" is not a number");
    CHECK(error_of(std::string(5000, '#') + "\n1 2 \x01\x02\n") == "t.txt:2: coordinate \"??\" is not a number");
    std::string long_token(100, '7');
    long_token += 'x';
    CHECK(error_of("1 2 " + long_token + "\n") ==
          "t.txt:1: coordinate \"" + std::string(40, '7') + "...\" is not a number");
}

TEST_CASE("mesh_io: nan, inf and numbers beyond the double range name their line and point") {
    CHECK(error_of("0 0 0\n# a comment\nnan 1 2\n") == "t.txt:3: coordinate \"nan\" of point 1 is not a finite number");
    CHECK(error_of("1 2 -Infinity\n") == "t.txt:1: coordinate \"-Infinity\" of point 0 is not a finite number");
    CHECK(error_of("1,2,inf\n") == "t.txt:1: coordinate \"inf\" of point 0 is not a finite number");
    CHECK(error_of("1 2 3\n4 5 6\n\n0 1e400 0\n") == "t.txt:4: coordinate \"1e400\" of point 2 is out of the double range");
    CHECK(error_of("-.5e999 0 0\n") == "t.txt:1: coordinate \"-.5e999\" of point 0 is out of the double range");
    // Every format: rbox, OFF (a mesh read as a point set too), OBJ.
    CHECK(error_of("3 rbox 2 D3\n2\n1 2 3\n4 nan 6\n") == "t.txt:4: coordinate \"nan\" of point 1 is not a finite number");
    CHECK(error_of("OFF\n2 0 0\n1 2 3\n4 5 1e309\n") == "t.txt:4: coordinate \"1e309\" of point 1 is out of the double range");
    CHECK(mesh_error_of("OFF\n3 1 0\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n") ==
          "m.off:4: coordinate \"inf\" of point 1 is not a finite number");
    CHECK(error_of("v 1 2 3\nvt 0 0\nv 1e400 2 3\n", "m.obj") == "m.obj:3: coordinate \"1e400\" of point 1 is out of the double range");
    // An underflow is a fine value: 0 (or a subnormal), as strtod gives.
    std::vector<double> xyz = points_of("1e-400 3 4\n");
    CHECK(xyz == std::vector<double>{0.0, 3, 4});
}

TEST_CASE("mesh_io: a byte-order mark and a header row of column names are skipped") {
    const std::string bom = "\xEF\xBB\xBF";
    CHECK(points_of(bom + "1 2 3\n") == std::vector<double>{1, 2, 3});
    CHECK(points_of(bom + "3 rbox 1 D3\n1\n1 2 3\n") == std::vector<double>{1, 2, 3});
    CHECK(points_of(bom + "v 1 2 3\n") == std::vector<double>{1, 2, 3});
    CHECK(points_of(bom + "OFF\n1 0 0\n1 2 3\n") == std::vector<double>{1, 2, 3});
    // A BOM only at the start: line 1 is still line 1 in messages.
    CHECK(error_of(bom + "1 2\n") == "t.txt:1: expected 3 coordinates, got 2");
    for (const std::string& header : {std::string("x,y,z"), std::string("X Y Z"), std::string("\"x\", \"y\", \"z\""),
                                      bom + "x,y,z"}) {
        INFO(header);
        const PointsResult csv = parse_points(header + "\n1,2,3\n4,5,6\n", "p.csv");
        REQUIRE(csv.ok());
        CHECK(csv.xyz == std::vector<double>{1, 2, 3, 4, 5, 6});
        const std::string shown = header.substr(header.rfind('\xBF') == std::string::npos ? 0 : 3);
        CHECK(csv.warnings == std::vector<std::string>{"skipped header line 1: " + shown});
    }
    // After comments the header names its own line; the names are shown as printable ASCII only.
    const PointsResult commented = parse_points("# scan\n\nh\xC3\xB6he,y,z\n1,2,3\n", "p.csv");
    REQUIRE(commented.ok());
    CHECK(commented.warnings == std::vector<std::string>{"skipped header line 3: h??he,y,z"});
    // Only the first content line can be a header, and only of three names; a header alone is no points.
    CHECK(error_of("x,y,z\n1,2,3\nx,y,z\n") == "t.txt:3: coordinate \"x\" is not a number");
    CHECK(error_of("x,y\n1,2\n") == "t.txt:1: expected 3 coordinates, got 2");
    CHECK(error_of("x,y,1\n1,2,3\n") == "t.txt:1: coordinate \"x\" is not a number");
    const PointsResult only_header = parse_points("x,y,z\n", "p.csv");
    CHECK(only_header.ok());
    CHECK(only_header.count() == 0);
    CHECK(only_header.warnings.size() == 1);
}

TEST_CASE("mesh_io: shortest round-trip numbers read back to the same doubles") {
    std::mt19937_64 random(12345);
    std::uniform_real_distribution<double> uniform(-1e3, 1e3);
    std::vector<double> values;
    std::string text;
    for (int i = 0; i < 300; ++i) {
        double v = uniform(random) * std::pow(10.0, (i % 40) - 20);
        values.push_back(v);
        text += hullkit::format_double(v) + (i % 3 == 2 ? "\n" : " ");
    }
    CHECK(points_of(text) == values);
    CHECK(hullkit::format_double(0.1) == "0.1");  // the shortest text that reads back exactly
    CHECK(hullkit::format_double(1.0) == "1");
    CHECK(hullkit::format_json_number(NAN) == "null");
    CHECK(hullkit::format_json_number(-INFINITY) == "null");
    CHECK(hullkit::format_json_number(2.5) == "2.5");
}

TEST_CASE("mesh_io: empty input is no points and no error (the hull of nothing has dimension -1)") {
    for (const std::string text : {"", "# only a comment\n\n  \n", "\xEF\xBB\xBF", "3 rbox 0 D3\n0\n", "OFF\n0 0 0\n"}) {
        INFO(text);
        const PointsResult result = parse_points(text, "e.txt");
        CHECK(result.ok());
        CHECK(result.xyz.empty());
        CHECK(result.warnings.empty());
    }
}

// ---- qhull / rbox ----

TEST_CASE("mesh_io: rbox header without comment") {
    std::vector<double> xyz = points_of("3\n2\n1 2 3\n4 5 6\n");
    CHECK(xyz == std::vector<double>{1, 2, 3, 4, 5, 6});
}

TEST_CASE("mesh_io: rbox header with comment") {
    std::string text =
        "3 rbox 3 s D3\n"
        "3\n"
        "-0.2561591415905514 0.4074747497907592 -0.1354504428289179 \n"
        "-0.2464882009620465 -0.3343342839039356 0.2783238282880867 \n"
        "-0.3030051559778936 0.2571448267908443 0.3034211817021334 \n";
    std::vector<double> xyz = points_of(text);
    REQUIRE(xyz.size() == 9);
    CHECK(xyz[0] == -0.2561591415905514);
    CHECK(xyz[8] == 0.3034211817021334);
}

TEST_CASE("mesh_io: rbox count mismatch") {
    SECTION("fewer points than declared: blames the count line") {
        CHECK(error_of("3 rbox 3 D3\n3\n1 2 3\n4 5 6\n", "r.txt") ==
              "r.txt:2: header declares 3 points but the file has 2");
    }
    SECTION("more points than declared: blames the first extra line") {
        CHECK(error_of("3 rbox 1 D3\n1\n1 2 3\n\n4 5 6\n", "r.txt") ==
              "r.txt:5: more points than the 1 declared on line 2");
    }
    SECTION("missing or malformed count") {
        CHECK(error_of("3 rbox\n", "r.txt") ==
              "r.txt:1: file ends after the dimension line; expected the point count");
        CHECK(error_of("3 rbox\n1 2 3\n", "r.txt") ==
              "r.txt:2: expected the point count (one non-negative integer), got \"1 2 3\"");
        CHECK(error_of("3\n-4\n", "r.txt") ==
              "r.txt:2: expected the point count (one non-negative integer), got \"-4\"");
    }
    SECTION("a declared count of zero is no points, and no error") {
        CHECK(points_of("3 rbox 0 D3\n0\n", "r.txt").empty());
        CHECK(error_of("3 rbox 0 D3\n0\n1 2 3\n", "r.txt") == "r.txt:3: more points than the 0 declared on line 2");
    }
}

TEST_CASE("mesh_io: rbox wrong dimension") {
    CHECK(error_of("2 rbox 4 D2\n4\n0.1 0.2\n", "d2.txt") ==
          "d2.txt:1: dimension is 2, expected 3 (hullkit reads 3D points)");
    CHECK(error_of("4\n1\n1 2 3 4\n", "d4.txt") ==
          "d4.txt:1: dimension is 4, expected 3 (hullkit reads 3D points)");
}

TEST_CASE("mesh_io: rbox point lines are checked") {
    CHECK(error_of("3 rbox\n2\n1 2 3\n4 5\n", "r.txt") == "r.txt:4: expected 3 coordinates, got 2");
    CHECK(error_of("3 rbox\n1\n1 2 x\n", "r.txt") == "r.txt:3: coordinate \"x\" is not a number");
}

TEST_CASE("mesh_io: a numeric first line is a point, not an rbox header") {
    CHECK(points_of("3 1e3 2\n") == std::vector<double>{3, 1000, 2});
    CHECK(error_of("3 1000\n", "p.txt") == "p.txt:1: expected 3 coordinates, got 2");
}

// ---- OBJ ----

TEST_CASE("mesh_io: OBJ vertices, other records ignored") {
    std::vector<double> xyz = points_of(load("cube.obj"), "cube.obj");
    std::vector<double> expected = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                    0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    CHECK(xyz == expected);

    // "v x y z w" and the "v x y z r g b" colour extension keep only x y z.
    CHECK(points_of("g a\nv 1 2 3 0.5\nvn 0 0 1\nv 4 5 6 1 0 0\nf 1 2 3\nl 1 2\n") ==
          std::vector<double>{1, 2, 3, 4, 5, 6});
}

TEST_CASE("mesh_io: OBJ errors") {
    CHECK(error_of("# obj\nv 1 2 3\nv 1 2\n", "m.obj") ==
          "m.obj:3: expected \"v x y z [w]\", got 2 numbers");
    CHECK(error_of("v 1 2 3\nv 1 2 3 4 5\n", "m.obj") ==
          "m.obj:2: expected \"v x y z [w]\", got 5 numbers");
    CHECK(error_of("v 1 2 3\nv 1 q 3\n", "m.obj") == "m.obj:2: coordinate \"q\" is not a number");
    CHECK(error_of("v 1 2 3\nv 1 2 3 w\n", "m.obj") ==
          "m.obj:2: vertex value \"w\" is not a number");
    CHECK(points_of("o empty\nf 1 2 3\n", "m.obj").empty());  // no vertices: no points
    // Unknown records are skipped (with a warning), but not a broken vertex after them.
    CHECK(error_of("648 1292\nv 1 2 3\nv 1 2\n", "fcl.obj") == "fcl.obj:3: expected \"v x y z [w]\", got 2 numbers");
}

TEST_CASE("mesh_io: OBJ records that are not OBJ's are skipped with one warning per kind") {
    const std::string plain = "v 1 2 3\nv 4 5 6\nvt 0 0\nf 1 2 1\nv 7 8 9\n";
    const PointsResult clean = parse_points(plain, "m.obj");
    REQUIRE(clean.ok());
    CHECK(clean.warnings.empty());
    // FCL's meshes start with a "V F" count line; a bare point line and a made-up keyword too.
    const std::string text = "648 1292\n# comment\nv 1 2 3\nbogus a\nv 4 5 6\nvt 0 0\n1 2 3\nf 1 2 1\n"
                             "bogus b\nv 7 8 9\nbogus c\n";
    for (unsigned threads : {1u, 2u, 3u}) {
        const PointsResult result = parse_points(text, "fcl.obj", threads);
        INFO(result.error);
        REQUIRE(result.ok());
        CHECK(result.xyz == clean.xyz);
        CHECK(result.warnings == std::vector<std::string>{
                                     "skipped 1 unknown OBJ record \"648\" (first at line 1)",
                                     "skipped 3 unknown OBJ records \"bogus\" (first at line 4)",
                                     "skipped 1 unknown OBJ record \"1\" (first at line 7)"});
    }
    // By content alone "648 1292" is no OBJ keyword: the .obj name decides.
    CHECK(parse_points(text, "<stdin>").error == "<stdin>:1: expected 3 coordinates, got 2");
    // More kinds than are named: the rest are counted together.
    std::string many = "v 0 0 0\n";
    for (int k = 0; k < 12; ++k) many += "x" + std::to_string(k) + "\n";
    const PointsResult lumped = parse_points(many, "many.obj");
    REQUIRE(lumped.ok());
    REQUIRE(lumped.warnings.size() == 8);
    CHECK(lumped.warnings[0] == "skipped 1 unknown OBJ record \"x0\" (first at line 2)");
    CHECK(lumped.warnings[7] == "skipped 5 other unknown OBJ records (first at line 9)");
}

// ---- OFF ----

TEST_CASE("mesh_io: OFF points, faces ignored") {
    std::vector<double> xyz = points_of(load("tetra.off"), "tetra.off");
    CHECK(xyz == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});

    // Counts on the "OFF" line, comments anywhere, faces not even checked.
    CHECK(points_of("# c\nOFF 2 1 0\n1 2 3 # first\n\n4 5 6\n3 0 1 7 junk\n") ==
          std::vector<double>{1, 2, 3, 4, 5, 6});
}

TEST_CASE("mesh_io: OFF header and vertex errors") {
    CHECK(error_of("OFF\n", "x.off") ==
          "x.off:1: file ends after \"OFF\"; expected \"vertices faces edges\"");
    CHECK(error_of("OFF\n4 4\n", "x.off") ==
          "x.off:2: expected the counts \"vertices faces edges\", got 2 values");
    CHECK(error_of("OFF\nfour 4 6\n", "x.off") ==
          "x.off:2: vertex count \"four\" is not a non-negative integer");
    CHECK(error_of("OFF\n2 0 0\n1 2 3\n", "x.off") ==
          "x.off:2: header declares 2 vertices but the file has 1");
    CHECK(error_of("OFF\n2 0 0\n1 2 3\n1.2.3 0 0\n", "x.off") ==
          "x.off:4: coordinate \"1.2.3\" is not a number");
    CHECK(error_of("COFF\n1 0 0\n1 2 3 255 0 0 255\n", "x.off") ==
          "x.off:1: unsupported OFF variant \"COFF\" (only plain OFF is read)");
}

TEST_CASE("mesh_io: read_off_mesh reads triangles and fan-triangulates polygons") {
    MeshResult tetra = read_off_mesh(load("tetra.off"), "tetra.off");
    INFO(tetra.error);
    REQUIRE(tetra.ok());
    CHECK(tetra.point_count() == 4);
    CHECK(tetra.triangles == std::vector<std::uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3});

    MeshResult quads = read_off_mesh(
        "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n4 0 3 2 1\n5 0 1 2 3 4 0.5 0.5 0.5\n",
        "q.off");
    INFO(quads.error);
    REQUIRE(quads.ok());
    CHECK(quads.triangles ==
          std::vector<std::uint32_t>{0, 3, 2, 0, 2, 1, 0, 1, 2, 0, 2, 3, 0, 3, 4});
}

TEST_CASE("mesh_io: read_off_mesh errors") {
    const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
    CHECK(mesh_error_of(head + "3 0 1 3\n") ==
          "m.off:6: vertex index 3 is out of range (the file has 3 vertices)");
    CHECK(mesh_error_of(head + "3 0 1\n") == "m.off:6: face declares 3 vertices but lists 2");
    CHECK(mesh_error_of(head + "2 0 1\n") == "m.off:6: face has 2 vertices, need at least 3");
    CHECK(mesh_error_of(head + "3 0 -1 2\n") ==
          "m.off:6: vertex index \"-1\" is not a non-negative integer");
    CHECK(mesh_error_of(head + "3 0 1 2 red\n") ==
          "m.off:6: face colour value \"red\" is not a number");
    CHECK(mesh_error_of(head) == "m.off:2: header declares 1 faces but the file has 0");
    CHECK(mesh_error_of(head + "3 0 1 2\n3 0 2 1\n") ==
          "m.off:7: unexpected content after the last of the 1 faces");
    CHECK(mesh_error_of("1 2 3\n") == "m.off:1: not an OFF file: expected \"OFF\", got \"1\"");
    CHECK(mesh_error_of("") == "m.off: empty input, expected an OFF file");
}

// ---- writers ----

TEST_CASE("mesh_io: OFF writer re-indexes faces to the hull vertices") {
    SmallHull s;
    CHECK(hullkit::write_off(s.span(), s.hull) ==
          "OFF\n"
          "4 4 0\n"
          "0 0 0\n"
          "1 0 0\n"
          "0 1 0\n"
          "0 0 1.5\n"
          "3 0 2 1\n"
          "3 0 1 3\n"
          "3 0 3 2\n"
          "3 1 2 3\n");
}

TEST_CASE("mesh_io: OBJ writer uses 1-based indices into the hull vertices") {
    SmallHull s;
    CHECK(hullkit::write_obj(s.span(), s.hull) ==
          "v 0 0 0\n"
          "v 1 0 0\n"
          "v 0 1 0\n"
          "v 0 0 1.5\n"
          "f 1 3 2\n"
          "f 1 2 4\n"
          "f 1 4 3\n"
          "f 2 3 4\n");
}

TEST_CASE("mesh_io: JSON writer: triangles index points, vertices give their input indices, equations their planes") {
    SmallHull s;
    const std::string json = hullkit::write_json(s.span(), s.hull);
    // The input's triangle {1, 4, 3} is points 0, 2, 1: vertices[0] = 1, vertices[2] = 4, vertices[1] = 3.
    CHECK(json.rfind("{\"vertices\":[1,3,4,6],"
                     "\"triangles\":[[0,2,1],[0,1,3],[0,3,2],[1,2,3]],"
                     "\"points\":[[0,0,0],[1,0,0],[0,1,0],[0,0,1.5]],"
                     "\"equations\":[[0,0,-1,0],[0,-1,0,0],[-1,0,0,0],[",
                     0) == 0);
    CHECK(json.find("],\"volume\":0.25,\"area\":2.5,\"dimension\":3}\n") != std::string::npos);
    // The slanted face x + y + z / 1.5 = 1: normal (3, 3, 2) / sqrt(22), offset -3 / sqrt(22).
    const std::vector<double> planes = hullkit::plane_equations(s.span(), s.hull);
    REQUIRE(planes.size() == 16);
    const double root = std::sqrt(22.0);
    CHECK(planes[12] == Approx(3 / root).epsilon(1e-15));
    CHECK(planes[13] == Approx(3 / root).epsilon(1e-15));
    CHECK(planes[14] == Approx(2 / root).epsilon(1e-15));
    CHECK(planes[15] == Approx(-3 / root).epsilon(1e-15));
    CHECK(json.find("[" + hullkit::format_double(planes[12]) + "," + hullkit::format_double(planes[13]) + "," +
                    hullkit::format_double(planes[14]) + "," + hullkit::format_double(planes[15]) + "]]") != std::string::npos);
    // The planes in qconvex's `n` layout.
    const std::string normals = hullkit::write_normals(s.span(), s.hull);
    CHECK(normals.rfind("4\n4\n0 0 -1 0\n0 -1 0 0\n-1 0 0 0\n", 0) == 0);
    CHECK(hullkit::write_hull(OutputFormat::Normals, s.span(), s.hull) == normals);
}

TEST_CASE("mesh_io: writers keep the vertex order of a planar hull") {
    // A polygon's vertices come in polygon order, not ascending: faces still re-index.
    SmallHull s;
    Hull polygon;
    polygon.dimension = 2;
    polygon.vertices = {4, 1, 3};
    polygon.triangles = {4, 1, 3};
    polygon.area = 0.5;
    CHECK(hullkit::write_off(s.span(), polygon) == "OFF\n3 1 0\n0 1 0\n0 0 0\n1 0 0\n3 0 1 2\n");
    CHECK(hullkit::write_obj(s.span(), polygon) == "v 0 1 0\nv 0 0 0\nv 1 0 0\nf 1 2 3\n");
    CHECK(hullkit::write_json(s.span(), polygon) ==
          "{\"vertices\":[4,1,3],\"triangles\":[[0,1,2]],\"points\":[[0,1,0],[0,0,0],[1,0,0]],"
          "\"equations\":[[0,0,1,0]],\"volume\":0,\"area\":0.5,\"dimension\":2}\n");
    CHECK(hullkit::write_normals(s.span(), polygon) == "4\n1\n0 0 1 0\n");

    Hull segment;
    segment.dimension = 1;
    segment.vertices = {6, 1};
    CHECK(hullkit::write_off(s.span(), segment) == "OFF\n2 0 0\n0 0 1.5\n0 0 0\n");
    CHECK(hullkit::write_json(s.span(), segment) ==
          "{\"vertices\":[6,1],\"triangles\":[],\"points\":[[0,0,1.5],[0,0,0]],"
          "\"equations\":[],\"volume\":0,\"area\":0,\"dimension\":1}\n");
    CHECK(hullkit::write_normals(s.span(), segment) == "4\n0\n");
    CHECK(hullkit::write_json(s.span(), Hull{}) ==
          "{\"vertices\":[],\"triangles\":[],\"points\":[],\"equations\":[],\"volume\":0,\"area\":0,\"dimension\":-1}\n");
}

TEST_CASE("mesh_io: merged faces are written as polygons") {
    // A unit square pyramid: the base is one quad, the sides are triangles.
    const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1};
    Hull hull;
    hull.dimension = 3;
    hull.vertices = {0, 1, 2, 3, 4};
    hull.triangles = {0, 3, 2, 0, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 0, 4, 3};
    hull.face_offsets = {0, 4, 7, 10, 13, 16};
    hull.face_vertices = {0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 0, 4, 3};
    const hullkit::PointSpan points(xyz);
    CHECK(hullkit::write_off(points, hull) ==
          "OFF\n5 5 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n"
          "4 0 3 2 1\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 0 4 3\n");
    CHECK(hullkit::write_obj(points, hull).find("f 1 4 3 2\nf 1 2 5\n") != std::string::npos);
    const std::string json = hullkit::write_json(points, hull);
    CHECK(json.find("\"faces\":[[0,3,2,1],[0,1,4],[1,2,4],[2,3,4],[0,4,3]]") != std::string::npos);
    // One plane per polygon in the normals format (the base quad once), one per triangle in JSON.
    const std::string normals = hullkit::write_normals(points, hull);
    CHECK(normals.rfind("4\n5\n0 0 -1 0\n", 0) == 0);
    CHECK(std::count(normals.begin(), normals.end(), '\n') == 7);
    CHECK(json.find("\"equations\":[[0,0,-1,0],[0,0,-1,0],") != std::string::npos);
    // The merged OFF reads back (fanned) as a closed surface of 6 triangles.
    const auto back = hullkit::read_off_mesh(hullkit::write_off(points, hull), "pyramid.off");
    REQUIRE(back.ok());
    CHECK(back.triangle_count() == 6);
}

TEST_CASE("mesh_io: writer output reads back exactly") {
    // Random coordinates need all 17 digits; the hull's connectivity is arbitrary here.
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<double> xyz(3 * 50);
    for (double& v : xyz) v = uniform(random) / 3.0;
    Hull hull;
    for (std::uint32_t i = 0; i < 50; i += 2) hull.vertices.push_back(i);  // even points only
    for (std::uint32_t i = 0; i + 4 < 50; i += 2) hull.triangles.insert(hull.triangles.end(), {i, i + 4, i + 2});
    PointSpan span(xyz);

    SECTION("OFF through read_off_mesh") {
        MeshResult mesh = read_off_mesh(hullkit::write_off(span, hull), "out.off");
        INFO(mesh.error);
        REQUIRE(mesh.ok());
        REQUIRE(mesh.point_count() == hull.vertices.size());
        REQUIRE(mesh.triangles.size() == hull.triangles.size());
        for (std::size_t k = 0; k < hull.vertices.size(); ++k) {
            for (int c = 0; c < 3; ++c) CHECK(mesh.xyz[3 * k + c] == xyz[3 * hull.vertices[k] + c]);
        }
        for (std::size_t i = 0; i < hull.triangles.size(); ++i) {
            CHECK(hull.vertices[mesh.triangles[i]] == hull.triangles[i]);
        }
    }
    SECTION("OFF and OBJ through parse_points") {
        std::vector<double> expected;
        for (std::uint32_t v : hull.vertices) expected.insert(expected.end(), &xyz[3 * v], &xyz[3 * v + 3]);
        CHECK(points_of(hullkit::write_off(span, hull), "out.off") == expected);
        CHECK(points_of(hullkit::write_obj(span, hull), "out.obj") == expected);
    }
}

TEST_CASE("mesh_io: writers reject a hull that does not fit the points") {
    SmallHull s;
    Hull bad = s.hull;
    bad.triangles[0] = 2;  // an inside point, not in hull.vertices
    CHECK_THROWS_AS(hullkit::write_off(s.span(), bad), std::invalid_argument);
    CHECK_THROWS_AS(hullkit::write_json(s.span(), bad), std::invalid_argument);
    bad = s.hull;
    bad.vertices.push_back(7);  // past the last point
    CHECK_THROWS_AS(hullkit::write_obj(s.span(), bad), std::invalid_argument);
    bad = s.hull;
    bad.vertices.push_back(3);  // listed twice
    CHECK_THROWS_AS(hullkit::write_off(s.span(), bad), std::invalid_argument);
}

TEST_CASE("mesh_io: output format names and file extensions") {
    OutputFormat format = OutputFormat::Off;
    CHECK(hullkit::parse_output_format("json", &format));
    CHECK(format == OutputFormat::Json);
    CHECK_FALSE(hullkit::parse_output_format("JSON", &format));
    CHECK_FALSE(hullkit::parse_output_format("ply", &format));
    CHECK(format == OutputFormat::Json);  // untouched on failure

    CHECK(hullkit::output_format_from_path("dir/hull.OBJ", &format));
    CHECK(format == OutputFormat::Obj);
    CHECK(hullkit::output_format_from_path("a.b/hull.off", &format));
    CHECK(format == OutputFormat::Off);
    CHECK_FALSE(hullkit::output_format_from_path("a.json/hull", &format));
    CHECK_FALSE(hullkit::output_format_from_path("hull.txt", &format));
    CHECK(format == OutputFormat::Off);

    CHECK(std::string(hullkit::output_format_name(OutputFormat::Obj)) == "obj");
    SmallHull s;
    CHECK(hullkit::write_hull(OutputFormat::Json, s.span(), s.hull) == hullkit::write_json(s.span(), s.hull));
}

TEST_CASE("mesh_io: read_file reports a missing file") {
    std::string text = "stale", error;
    CHECK_FALSE(hullkit::read_file(data_path("no-such-file.txt"), &text, &error));
    CHECK(error == data_path("no-such-file.txt") + ": cannot open: No such file or directory");
}

TEST_CASE("mesh_io: malformed fixture names line 3") {
    CHECK(error_of(load("malformed-line3.txt"), "malformed-line3.txt") ==
          "malformed-line3.txt:3: expected 3 coordinates, got 2");
}

namespace {

/// parse_points through the chunked file reader: the text in a temporary file (a regular file,
/// whose size the reader uses) or, with `as_stream`, behind fmemopen (no size known).
PointsResult read_via_file(const std::string& text, bool as_stream) {
    std::FILE* file = as_stream ? fmemopen(const_cast<char*>(text.data()), text.size(), "rb") : std::tmpfile();
    REQUIRE(file != nullptr);
    if (!as_stream) {
        REQUIRE(std::fwrite(text.data(), 1, text.size(), file) == text.size());
        std::rewind(file);
    }
    PointsResult result = hullkit::read_points_file(file, "t.txt");
    std::fclose(file);
    return result;
}

/// The same points or the same message as parse_points, both from a file and from a stream.
void check_file_reader_agrees(const std::string& text) {
    const PointsResult expected = parse_points(text, "t.txt");
    for (bool as_stream : {false, true}) {
        INFO("as_stream " << as_stream);
        const PointsResult got = read_via_file(text, as_stream);
        CHECK(got.error == expected.error);
        CHECK(got.xyz == expected.xyz);
    }
}

}  // namespace

TEST_CASE("mesh_io: the chunked file reader gives parse_points' result across chunk boundaries") {
    // Several MiB, so lines straddle the 1 MiB chunks; numbers of every length; a comment line
    // longer than a chunk (the buffer must grow); CRLF and blank lines.
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> uniform(-1e3, 1e3);
    std::string rbox;
    std::size_t count = 0;
    std::string body;
    while (body.size() < (std::size_t{5} << 20)) {
        if (count == 40000) body += "# " + std::string(std::size_t{3} << 19, 'c') + "\n\n";
        for (int k = 0; k < 3; ++k) {
            body += hullkit::format_double(uniform(random) * std::pow(10.0, static_cast<int>(random() % 30) - 15));
            body += k < 2 ? " " : (count % 7 ? "\n" : "\r\n");
        }
        ++count;
    }
    check_file_reader_agrees("3 rbox test\n" + std::to_string(count) + "\n" + body);
    check_file_reader_agrees(body);                                                  // plain xyz
    check_file_reader_agrees("OFF\n" + std::to_string(count) + " 0 0\n" + body);   // OFF
    // Errors name the same line, also far into the file.
    check_file_reader_agrees(body + "1 2\n");
    check_file_reader_agrees("3\n" + std::to_string(count + 1) + "\n" + body);
    check_file_reader_agrees(body.substr(0, body.size() - 1));  // no final newline
    check_file_reader_agrees("");
}

TEST_CASE("mesh_io: read_points_file reports a missing file and an unreadable one") {
    PointsResult missing = hullkit::read_points_file(data_path("no-such-file.txt"));
    CHECK(missing.error == data_path("no-such-file.txt") + ": cannot open: No such file or directory");
    PointsResult directory = hullkit::read_points_file(data_path("degenerate"));
    CHECK(directory.error == data_path("degenerate") + ": cannot read: Is a directory");
    CHECK(directory.xyz.empty());
    PointsResult fixture = hullkit::read_points_file(data_path("malformed-line3.txt"));
    CHECK(fixture.error == data_path("malformed-line3.txt") + ":3: expected 3 coordinates, got 2");
}

TEST_CASE("mesh_io: binary input and formats not read here are named as such") {
    // Binary STL: an 80-byte header, the triangle count, 50 bytes per triangle.
    std::string stl(84 + 2 * 50, '\0');
    stl.replace(0, 15, "binary STL head");
    stl[80] = 2;
    const std::string not_points = "t.txt: not a point file: ";
    CHECK(error_of(stl) == not_points + "binary STL is not supported by the point reader (read: xyz, rbox, OBJ, OFF)");
    // A header starting with "solid" (which some binary STL writers put there) is still binary.
    stl.replace(0, 5, "solid");
    CHECK(error_of(stl) == not_points + "binary STL is not supported by the point reader (read: xyz, rbox, OBJ, OFF)");
    CHECK(error_of(std::string("\x7f" "ELF\x02\x01\x01", 7) + std::string(100, '\0')) ==
          not_points + "binary data (byte 0x7f at offset 0)");
    CHECK(error_of(std::string("1 2 3\n4 5\0", 10)) == not_points + "binary data (byte 0x00 at offset 9)");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 1\nend_header\n0 0 0\n") ==
          not_points + "PLY is not supported by the point reader (read: xyz, rbox, OBJ, OFF)");
    CHECK(error_of("solid cube\n  facet normal 0 0 1\n    outer loop\n") ==
          not_points + "ASCII STL is not supported by the point reader (read: xyz, rbox, OBJ, OFF)");
    // The same through the file reader, and for read_off_mesh.
    CHECK(read_via_file(stl, false).error == error_of(stl));
    // From a stream (a pipe) the size that identifies binary STL is unknown: plain binary data.
    // (Found by fuzz_points, which first expected the same message.)
    CHECK(read_via_file(stl, true).error == not_points + "binary data (byte 0x00 at offset 15)");
    CHECK(mesh_error_of(stl) ==
          "m.off: not an OFF file: binary STL is not supported by the point reader (read: xyz, rbox, OBJ, OFF)");
    // Text that merely starts with those words is still read as points.
    CHECK(points_of("# ply\n1 2 3\n") == std::vector<double>{1, 2, 3});
}

TEST_CASE("mesh_io: write_hull_file writes what write_hull returns") {
    // A hull with many vertices, so the file writer flushes its buffer several times.
    std::vector<double> xyz;
    Hull hull;
    hull.dimension = 3;
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const std::uint32_t n = 120000;
    for (std::uint32_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) xyz.push_back(uniform(random));
        if (i % 3 == 1) hull.vertices.push_back(i);  // written in this order, whatever the geometry
    }
    for (std::size_t k = 0; k + 2 < hull.vertices.size(); ++k) {
        hull.triangles.insert(hull.triangles.end(), {hull.vertices[k], hull.vertices[k + 1], hull.vertices[k + 2]});
    }
    const PointSpan span(xyz.data(), n);
    for (OutputFormat format : {OutputFormat::Off, OutputFormat::Obj, OutputFormat::Json}) {
        INFO(hullkit::output_format_name(format));
        std::FILE* file = std::tmpfile();
        REQUIRE(file != nullptr);
        int error_number = 0;
        REQUIRE(hullkit::write_hull_file(format, span, hull, file, &error_number));
        std::string written(static_cast<std::size_t>(std::ftell(file)), '\0');
        std::rewind(file);
        REQUIRE(std::fread(&written[0], 1, written.size(), file) == written.size());
        std::fclose(file);
        const std::string expected = hullkit::write_hull(format, span, hull);
        CHECK(written.size() > (std::size_t{2} << 20));
        CHECK(written == expected);
    }
    // A full device: the failure and its errno come back.
    std::FILE* full = std::fopen("/dev/full", "wb");
    if (full) {
        int error_number = 0;
        CHECK_FALSE(hullkit::write_hull_file(OutputFormat::Off, span, hull, full, &error_number));
        CHECK(error_number == ENOSPC);
        std::fclose(full);
    }
}
