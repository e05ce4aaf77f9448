// The 2D point reader (parse_points_2d, native/src/io/points2d.cpp): inputs that are not 2D point
// files are named as what they are, and the regression inputs found while fuzzing it
// (tests/data/fuzz/points2d-*) give a clear error. `hullkit delaunay` passes those messages on.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "cli/cli_support.hpp"
#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"

namespace {

std::string error_of(const std::string& text) {
    std::vector<std::size_t> lines{7};
    const hullkit::Points2Result result = hullkit::parse_points_2d(text, "p.txt", &lines);
    REQUIRE_FALSE(result.ok());
    CHECK(result.xy.empty());
    CHECK(lines.empty());
    for (unsigned char c : result.error) CHECK((c >= 0x20 && c < 0x7f));
    return result.error;
}

const std::string kNotSupported = " is not supported by the 2D point reader (read: x y, x y z, rbox)";

}  // namespace

TEST_CASE("points2d: commas, a byte-order mark, a header row, no points is no error", "[points2d]") {
    std::vector<std::size_t> lines;
    const hullkit::Points2Result csv =
        hullkit::parse_points_2d("\xEF\xBB\xBF# exported\n\"x\",\"y\"\n1,2\n3 , 4\n\n5,6,7\n", "p.csv", &lines);
    // (every line as wide as the first: here a 3-column line after 2-column ones is an error)
    CHECK(csv.error == "p.csv:6: expected 2 coordinates, got 3");
    const hullkit::Points2Result ok = hullkit::parse_points_2d("\xEF\xBB\xBFx,y,z\n1,2,0\n3 , 4 ,0\n", "p.csv", &lines);
    REQUIRE(ok.ok());
    CHECK(ok.xy == std::vector<double>{1, 2, 3, 4});
    CHECK(lines == std::vector<std::size_t>{2, 3});
    CHECK(ok.warnings == std::vector<std::string>{"skipped header line 1: x,y,z"});
    for (const std::string text : {"", "# nothing\n", "\xEF\xBB\xBF", "2 rbox 0 D2\n0\n", "x,y\n"}) {
        INFO(text);
        const hullkit::Points2Result none = hullkit::parse_points_2d(text, "p.txt", &lines);
        CHECK(none.ok());
        CHECK(none.xy.empty());
        CHECK(lines.empty());
    }
    CHECK(error_of("1,,2\n") == "p.txt:1: empty field before a comma");
    CHECK(error_of("1,2,\n") == "p.txt:1: empty field after the last comma");
    CHECK(error_of("1 2\n3 nan\n") == "p.txt:2: coordinate \"nan\" of point 1 is not a finite number");
    CHECK(error_of("1 2\n3 -1e400\n") == "p.txt:2: coordinate \"-1e400\" of point 1 is out of the double range");
    // A byte-order mark before an OBJ: still named as OBJ (read_points_2d reads it as a mesh).
    CHECK(error_of("\xEF\xBB\xBFv 0 0 0\n") == "p.txt: not a point file: OBJ" + kNotSupported);
    const hullkit::Points2Result obj = hullkit::read_points_2d("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "upload");
    INFO(obj.error);
    CHECK(obj.xy == std::vector<double>{0, 0, 1, 0, 0, 1});
}

TEST_CASE("points2d: binary input and other formats are named, not read as bad coordinates", "[points2d]") {
    // A PNG signature: 0x89 may start UTF-8 text, 0x1a may not.
    CHECK(error_of(std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)) ==
          "p.txt: not a point file: binary data (byte 0x1a at offset 6)");
    CHECK(error_of(std::string("1 2\n3 4\n\0", 9)) == "p.txt: not a point file: binary data (byte 0x00 at offset 8)");
    std::string stl(84 + 50, '\0');
    stl.replace(0, 5, "solid");
    stl[80] = 1;
    CHECK(error_of(stl) == "p.txt: not a point file: binary STL" + kNotSupported);
    CHECK(error_of("solid s\nfacet normal 0 0 1\n") == "p.txt: not a point file: ASCII STL" + kNotSupported);
    CHECK(error_of("ply\nformat ascii 1.0\n") == "p.txt: not a point file: PLY" + kNotSupported);
    CHECK(error_of("# a mesh\nOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") == "p.txt: not a point file: OFF" + kNotSupported);
    CHECK(error_of("v 0 0 0\nv 1 0 0\n") == "p.txt: not a point file: OBJ" + kNotSupported);
    // UTF-8 in a comment is text; the points are read.
    const hullkit::Points2Result utf8 = hullkit::parse_points_2d("# Punkte \xc3\xbc\n1 2\n3 4\n", "p.txt");
    CHECK(utf8.xy == std::vector<double>{1, 2, 3, 4});
}

TEST_CASE("points2d: regression inputs from fuzzing give a clear error", "[points2d]") {
    std::string text, error;
    const std::string path = hullkit_test::data_path("fuzz/points2d-rbox-count-19-digits.txt");
    REQUIRE(hullkit::read_file(path, &text, &error));
    // A 19-digit count overflowed int64 while it was parsed (undefined behaviour).
    CHECK(error_of(text) == "p.txt:2: expected the point count (one non-negative integer), got \"9999999999999999999\"");
}

TEST_CASE("points2d: hullkit delaunay names a binary file, exit 2, nothing echoed", "[points2d]") {
    hullkit_test::TempDir dir("hullkit-points2d");
    const std::string png = dir.file("picture.png");
    hullkit_test::write_text(png, std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR\xff\xfe", 18));
    const hullkit_test::RunResult run = hullkit_test::run_cli(dir, {"delaunay", png});
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK(run.err == "hullkit: " + png + ": not a point file: binary data (byte 0x1a at offset 6)\n");
    // A PLY file goes to the PLY reader (its vertices are the points), which names what is wrong.
    const std::string ply = dir.file("mesh.ply");
    hullkit_test::write_text(ply, "ply\nformat binary_little_endian 1.0\nelement vertex 0\nend_header\n");
    const hullkit_test::RunResult run_ply = hullkit_test::run_cli(dir, {"delaunay", ply});
    CHECK(run_ply.exit_code == 2);
    CHECK(run_ply.err == "hullkit: " + ply + ": the PLY vertex element has no scalar property \"x\"\n");
}
