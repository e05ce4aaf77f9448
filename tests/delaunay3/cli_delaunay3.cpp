// Tests of the `hullkit delaunay3` and `hullkit verify-delaunay3` commands (the built binary,
// HULLKIT_CLI_PATH): each output format read back (JSON parsed, .ele/.node re-read, VTK counted) and
// the tetrahedra checked by the library's verifier and against the library call; errors name the
// file and line; verify-delaunay3 accepts good tetrahedra and rejects broken ones.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"
#include "hullkit/delaunay3.hpp"

namespace {

using hullkit_test::RunResult;
using hullkit_test::TempDir;
using hullkit_test::read_text;
using hullkit_test::run_cli;
using hullkit_test::write_text;

/// Random points as "x y z" lines (printed with 17 digits, so they read back exactly).
std::vector<double> write_cloud(const std::string& path, std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> xyz(3 * n);
    std::ostringstream text;
    text.precision(17);
    for (std::size_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) {
            xyz[3 * i + k] = u(rng);
            text << xyz[3 * i + k] << (k == 2 ? "\n" : " ");
        }
    }
    write_text(path, text.str());
    return xyz;
}

std::vector<std::uint32_t> flatten(const nlohmann::json& list) {
    std::vector<std::uint32_t> out;
    for (const auto& tuple : list)
        for (const auto& v : tuple) out.push_back(v.get<std::uint32_t>());
    return out;
}

}  // namespace

TEST_CASE("hullkit delaunay3: JSON output is the library's tetrahedralization", "[delaunay3][cli]") {
    TempDir dir("hk-d3");
    const std::vector<double> xyz = write_cloud(dir.file("points.txt"), 400, 1);
    const RunResult r = run_cli(dir, {"delaunay3", dir.file("points.txt"), "--stats"});
    REQUIRE(r.exit_code == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    REQUIRE(j["dimension"] == 3);
    const hullkit::Delaunay3 d = hullkit::delaunay3(hullkit::PointSpan(xyz.data(), 400));
    REQUIRE(flatten(j["tetrahedra"]) == d.tetrahedra);
    REQUIRE(flatten(j["hull"]) == d.hull);
    std::vector<std::int32_t> neighbors;
    for (const auto& tuple : j["neighbors"])
        for (const auto& v : tuple) neighbors.push_back(v.get<std::int32_t>());
    REQUIRE(neighbors == d.neighbors);
    REQUIRE(j["duplicates"].empty());
    const nlohmann::json stats = nlohmann::json::parse(r.err);
    REQUIRE(stats["points"] == 400);
    REQUIRE(stats["tetrahedra"] == d.tetrahedron_count());
    REQUIRE(stats["hull"] == d.hull.size() / 3);
    REQUIRE(stats["seconds"].get<double>() >= 0);
    // And it verifies.
    write_text(dir.file("tets.json"), r.out);
    const RunResult v = run_cli(dir, {"verify-delaunay3", dir.file("points.txt"), dir.file("tets.json")});
    REQUIRE(v.exit_code == 0);
    REQUIRE(v.out.rfind("ok: 400 points", 0) == 0);
}

TEST_CASE("hullkit delaunay3 --furthest-site: the library's furthest-site tetrahedralization, and its diagram",
          "[delaunay3][cli][furthest]") {
    TempDir dir("hk-d3");
    const std::vector<double> xyz = write_cloud(dir.file("points.txt"), 300, 7);
    const RunResult r = run_cli(dir, {"delaunay3", dir.file("points.txt"), "--furthest-site", "--voronoi",
                                      dir.file("cells.json"), "-o", dir.file("tets.json")});
    REQUIRE(r.exit_code == 0);
    const nlohmann::json j = nlohmann::json::parse(read_text(dir.file("tets.json")));
    hullkit::Delaunay3Options options;
    options.furthest_site = true;
    const hullkit::Delaunay3 d = hullkit::delaunay3(hullkit::PointSpan(xyz.data(), 300), options);
    REQUIRE(flatten(j["tetrahedra"]) == d.tetrahedra);
    REQUIRE(flatten(j["hull"]) == d.hull);
    // Not the nearest-site tetrahedralization: fewer tetrahedra, only on the hull's corners, and
    // it does not verify as Delaunay.
    const hullkit::Delaunay3 nearest = hullkit::delaunay3(hullkit::PointSpan(xyz.data(), 300));
    REQUIRE(d.tetrahedron_count() < nearest.tetrahedron_count());
    const RunResult v = run_cli(dir, {"verify-delaunay3", dir.file("points.txt"), dir.file("tets.json")});
    REQUIRE(v.exit_code == 1);
    // The diagram: every corner's cell unbounded (volume null), every other point's empty (volume 0).
    const nlohmann::json cells = nlohmann::json::parse(read_text(dir.file("cells.json")));
    std::vector<bool> corner(300, false);
    for (const std::uint32_t c : d.tetrahedra) corner[c] = true;
    for (std::size_t i = 0; i < 300; ++i) {
        INFO("point " << i);
        REQUIRE(cells["volume"][i].is_null() == corner[i]);
        REQUIRE(cells["cells"][i].empty() == !corner[i]);
    }
}

TEST_CASE("hullkit delaunay3: TetGen .ele and .node, VTK, and verification of the .ele", "[delaunay3][cli]") {
    TempDir dir("hk-d3");
    const std::vector<double> xyz = write_cloud(dir.file("points.txt"), 300, 2);
    REQUIRE(run_cli(dir, {"delaunay3", dir.file("points.txt"), "-o", dir.file("mesh.ele")}).exit_code == 0);
    const hullkit::Delaunay3 d = hullkit::delaunay3(hullkit::PointSpan(xyz.data(), 300));
    std::istringstream ele(read_text(dir.file("mesh.ele")));
    std::size_t count = 0, per = 0, attributes = 1;
    ele >> count >> per >> attributes;
    REQUIRE(count == d.tetrahedron_count());
    REQUIRE(per == 4);
    REQUIRE(attributes == 0);
    for (std::size_t t = 0; t < count; ++t) {
        std::size_t number = 0;
        ele >> number;
        REQUIRE(number == t + 1);
        for (int k = 0; k < 4; ++k) {
            std::uint64_t node = 0;
            ele >> node;
            REQUIRE(node == d.tetrahedra[4 * t + k] + 1);
        }
    }
    std::istringstream node(read_text(dir.file("mesh.node")));
    std::size_t nodes = 0, dim = 0, a = 1, b = 1;
    node >> nodes >> dim >> a >> b;
    REQUIRE(nodes == 300);
    REQUIRE(dim == 3);
    for (std::size_t i = 0; i < nodes; ++i) {
        std::size_t number = 0;
        double x, y, z;
        node >> number >> x >> y >> z;
        REQUIRE(number == i + 1);
        REQUIRE(x == xyz[3 * i]);
        REQUIRE(z == xyz[3 * i + 2]);
    }
    REQUIRE(run_cli(dir, {"verify-delaunay3", dir.file("points.txt"), dir.file("mesh.ele")}).exit_code == 0);
    // A broken .ele: one tetrahedron's corners swapped (negative orientation).
    std::string text = read_text(dir.file("mesh.ele"));
    std::istringstream lines(text);
    std::string header, first;
    std::getline(lines, header);
    std::getline(lines, first);
    std::istringstream fields(first);
    std::string n0, c0, c1, c2, c3;
    fields >> n0 >> c0 >> c1 >> c2 >> c3;
    const std::string swapped = n0 + " " + c1 + " " + c0 + " " + c2 + " " + c3;
    text.replace(text.find(first), first.size(), swapped);
    write_text(dir.file("broken.ele"), text);
    write_text(dir.file("broken.node"), read_text(dir.file("mesh.node")));
    const RunResult bad = run_cli(dir, {"verify-delaunay3", dir.file("points.txt"), dir.file("broken.ele")});
    REQUIRE(bad.exit_code == 1);
    REQUIRE(bad.out.find("negatively oriented") != std::string::npos);

    REQUIRE(run_cli(dir, {"delaunay3", dir.file("points.txt"), "-o", dir.file("mesh.vtk")}).exit_code == 0);
    const std::string vtk = read_text(dir.file("mesh.vtk"));
    REQUIRE(vtk.rfind("# vtk DataFile Version 3.0\n", 0) == 0);
    REQUIRE(vtk.find("POINTS 300 double\n") != std::string::npos);
    REQUIRE(vtk.find("CELLS " + std::to_string(count) + " " + std::to_string(5 * count) + "\n") != std::string::npos);
    REQUIRE(vtk.find("CELL_TYPES " + std::to_string(count) + "\n") != std::string::npos);
}

TEST_CASE("hullkit delaunay3: outputs formatted on threads in batches are the same bytes for every thread count", "[delaunay3][cli][threads]") {
    // 8000 points: about 50 000 tetrahedra, more than one batch of rows (2^15) per format.
    TempDir dir("hk-d3");
    const std::vector<double> xyz = write_cloud(dir.file("points.txt"), 8000, 7);
    const hullkit::Delaunay3 d = hullkit::delaunay3(hullkit::PointSpan(xyz.data(), 8000));
    REQUIRE(d.tetrahedron_count() > 40000);
    for (const char* ext : {"ele", "json", "vtk"}) {
        INFO(ext);
        std::string first;
        for (const char* threads : {"1", "2", "3"}) {
            const std::string out = dir.file(std::string("t") + threads + "." + ext);
            REQUIRE(run_cli(dir, {"delaunay3", dir.file("points.txt"), "-o", out, "--threads", threads}).exit_code == 0);
            const std::string text = read_text(out);
            if (first.empty()) first = text;
            REQUIRE(text == first);
        }
        if (std::string(ext) == "json") REQUIRE(flatten(nlohmann::json::parse(first)["tetrahedra"]) == d.tetrahedra);
        if (std::string(ext) == "ele") {
            std::istringstream ele(first);
            std::size_t count = 0, per = 0, attributes = 0;
            ele >> count >> per >> attributes;
            REQUIRE(count == d.tetrahedron_count());
            std::vector<std::uint32_t> read(4 * count);
            for (std::size_t t = 0; t < count; ++t) {
                std::size_t number = 0;
                ele >> number;
                REQUIRE(number == t + 1);
                for (int k = 0; k < 4; ++k) {
                    ele >> read[4 * t + k];
                    --read[4 * t + k];
                }
            }
            REQUIRE(read == d.tetrahedra);
            std::istringstream node(read_text(dir.file("t3.node")));
            std::size_t nodes = 0, dim = 0, a = 0, b = 0;
            node >> nodes >> dim >> a >> b;
            REQUIRE(nodes == 8000);
            std::size_t wrong = 0;
            for (std::size_t i = 0; i < nodes; ++i) {
                std::size_t number = 0;
                double p[3];
                node >> number >> p[0] >> p[1] >> p[2];
                wrong += number != i + 1 || p[0] != xyz[3 * i] || p[1] != xyz[3 * i + 1] || p[2] != xyz[3 * i + 2];
            }
            REQUIRE(wrong == 0);
        }
    }
}

TEST_CASE("hullkit delaunay3 --voronoi: the library's Voronoi diagram as JSON", "[delaunay3][cli]") {
    TempDir dir("hk-d3");
    // A 4x4x4 grid: the 8 inner cells are unit cubes, the 56 on the hull unbounded (null).
    std::string grid;
    std::vector<double> xyz;
    for (int x = 0; x < 4; ++x)
        for (int y = 0; y < 4; ++y)
            for (int z = 0; z < 4; ++z) {
                grid += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
                xyz.insert(xyz.end(), {double(x), double(y), double(z)});
            }
    write_text(dir.file("grid.txt"), grid);
    const RunResult r = run_cli(dir, {"delaunay3", dir.file("grid.txt"), "-o", dir.file("grid.json"), "--voronoi", "-"});
    REQUIRE(r.exit_code == 0);
    const nlohmann::json v = nlohmann::json::parse(r.out);
    const hullkit::Delaunay3 d = hullkit::delaunay3(hullkit::PointSpan(xyz.data(), 64));
    const hullkit::Voronoi3 expected = hullkit::delaunay3_voronoi(hullkit::PointSpan(xyz.data(), 64), d);
    REQUIRE(v["vertices"].size() == 27);
    for (std::size_t i = 0; i < 27; ++i)
        for (int k = 0; k < 3; ++k) REQUIRE(v["vertices"][i][k].get<double>() == expected.vertices[3 * i + k]);
    REQUIRE(v["tetrahedron_vertex"].get<std::vector<std::uint32_t>>() == expected.tetrahedron_vertex);
    REQUIRE(v["faces"].size() == expected.face_count());
    for (std::size_t f = 0; f < expected.face_count(); ++f) {
        const nlohmann::json& face = v["faces"][f];
        REQUIRE(face[0] == expected.face_points[2 * f]);
        REQUIRE(face[1] == expected.face_points[2 * f + 1]);
        REQUIRE(face[2].get<bool>() == (expected.face_bounded[f] != 0));
        const std::vector<std::uint32_t> corners(expected.face_vertices.begin() + expected.face_offsets[f],
                                                 expected.face_vertices.begin() + expected.face_offsets[f + 1]);
        REQUIRE(face[3].get<std::vector<std::uint32_t>>() == corners);
    }
    std::size_t cubes = 0, unbounded = 0;
    for (std::size_t i = 0; i < 64; ++i) {
        const std::vector<std::uint32_t> faces(expected.cell_faces.begin() + expected.cell_offsets[i],
                                               expected.cell_faces.begin() + expected.cell_offsets[i + 1]);
        REQUIRE(v["cells"][i].get<std::vector<std::uint32_t>>() == faces);
        if (v["volume"][i].is_null()) {
            ++unbounded;
        } else {
            REQUIRE(v["volume"][i].get<double>() == 1.0);
            ++cubes;
        }
    }
    REQUIRE(cubes == 8);
    REQUIRE(unbounded == 56);
    // Both to standard output would mix them; an empty name is no file.
    const RunResult both = run_cli(dir, {"delaunay3", dir.file("grid.txt"), "--voronoi", "-"});
    REQUIRE(both.exit_code == 2);
    REQUIRE(both.err.find("--voronoi - and the tetrahedra would both go to standard output") != std::string::npos);
    REQUIRE(run_cli(dir, {"delaunay3", dir.file("grid.txt"), "--voronoi", ""}).exit_code == 2);
    // A file, with the tetrahedra on standard output.
    REQUIRE(run_cli(dir, {"delaunay3", dir.file("grid.txt"), "--voronoi", dir.file("cells.json")}).exit_code == 0);
    REQUIRE(nlohmann::json::parse(read_text(dir.file("cells.json"))) == v);
}

TEST_CASE("hullkit delaunay3: lower dimensions and duplicates in JSON", "[delaunay3][cli]") {
    TempDir dir("hk-d3");
    write_text(dir.file("plane.txt"), "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0.5 0.5 0\n1 0 0\n");
    const RunResult r = run_cli(dir, {"delaunay3", dir.file("plane.txt")});
    REQUIRE(r.exit_code == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    REQUIRE(j["dimension"] == 2);
    REQUIRE(j["triangles"].size() == 4);
    REQUIRE(j["normal"] == nlohmann::json::array({0, 0, 1}));
    REQUIRE(j["duplicates"] == nlohmann::json::parse("[[5,1]]"));
    write_text(dir.file("line.txt"), "2 2 2\n0 0 0\n1 1 1\n");
    const nlohmann::json l = nlohmann::json::parse(run_cli(dir, {"delaunay3", dir.file("line.txt")}).out);
    REQUIRE(l["dimension"] == 1);
    REQUIRE(l["vertices"] == nlohmann::json::parse("[[1],[2],[0]]"));
    // No tetrahedra for a .ele file.
    const RunResult ele = run_cli(dir, {"delaunay3", dir.file("plane.txt"), "-o", dir.file("x.ele")});
    REQUIRE(ele.exit_code == 2);
    REQUIRE(ele.err.find("coplanar") != std::string::npos);
}

TEST_CASE("hullkit delaunay3: usage and input errors", "[delaunay3][cli]") {
    TempDir dir("hk-d3");
    write_text(dir.file("bad.txt"), "0 0 0\n1 0 0\n0 nan 0\n");
    const RunResult nan = run_cli(dir, {"delaunay3", dir.file("bad.txt")});
    REQUIRE(nan.exit_code == 2);
    REQUIRE(nan.err.find(dir.file("bad.txt") + ":3") != std::string::npos);
    REQUIRE(run_cli(dir, {"delaunay3", "--format", "xml"}).err == "hullkit: unknown format \"xml\" (known: json, ele, vtk)\n");
    REQUIRE(run_cli(dir, {"delaunay3", "--format", "ele"}).exit_code == 2);
    REQUIRE(run_cli(dir, {"delaunay3", "--bogus"}).exit_code == 2);
    REQUIRE(run_cli(dir, {"delaunay3", dir.file("missing.txt")}).err.find("missing.txt: cannot open") != std::string::npos);
    const RunResult help = run_cli(dir, {"delaunay3", "--help"});
    REQUIRE(help.exit_code == 0);
    REQUIRE(help.out.rfind("Usage: hullkit delaunay3", 0) == 0);
    REQUIRE(run_cli(dir, {"verify-delaunay3", dir.file("bad.txt")}).exit_code == 2);
    write_text(dir.file("t.json"), "{\"tetrahedra\":[[0,1,2]]}");
    write_text(dir.file("ok.txt"), "0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
    REQUIRE(run_cli(dir, {"verify-delaunay3", dir.file("ok.txt"), dir.file("t.json")}).err.find("not quadruples") !=
            std::string::npos);
}
