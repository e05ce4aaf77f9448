// delaunay3_voronoi: cells checked against independent answers: unit cubes on a grid, the convex
// hull (hullkit::hull, independent code) of each bounded cell's vertices, faces turning the right
// way, unbounded cells exactly on the hull, and voro++ (Debian) where it is installed.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <vector>

#include "cli/cli_support.hpp"
#include "hullkit/delaunay3.hpp"
#include "hullkit/hull.hpp"

using hullkit::Delaunay3;
using hullkit::PointSpan;
using hullkit::Voronoi3;

namespace {

Voronoi3 voronoi_of(const std::vector<double>& xyz, Delaunay3* out = nullptr) {
    const Delaunay3 d = hullkit::delaunay3(PointSpan(xyz.data(), xyz.size() / 3));
    REQUIRE(d.ok());
    if (out) *out = d;
    return hullkit::delaunay3_voronoi(PointSpan(xyz.data(), xyz.size() / 3), d);
}

/// The cell's vertices (each once).
std::vector<double> cell_vertices(const Voronoi3& v, std::size_t i) {
    std::set<std::uint32_t> ids;
    for (std::uint32_t k = v.cell_offsets[i]; k < v.cell_offsets[i + 1]; ++k) {
        const std::uint32_t f = v.cell_faces[k];
        for (std::uint32_t j = v.face_offsets[f]; j < v.face_offsets[f + 1]; ++j) ids.insert(v.face_vertices[j]);
    }
    std::vector<double> out;
    for (const std::uint32_t id : ids) out.insert(out.end(), &v.vertices[3 * id], &v.vertices[3 * id + 3]);
    return out;
}

/// Every bounded face's normal (Newell's) points from p to q; unbounded faces only on hull points.
void check_faces(const std::vector<double>& xyz, const Voronoi3& v, const Delaunay3& d) {
    const std::set<std::uint32_t> on_hull(d.hull.begin(), d.hull.end());
    for (std::size_t f = 0; f < v.face_count(); ++f) {
        const std::uint32_t p = v.face_points[2 * f], q = v.face_points[2 * f + 1];
        REQUIRE(p < q);
        if (!v.face_bounded[f]) {
            REQUIRE(on_hull.count(p));
            REQUIRE(on_hull.count(q));
            continue;
        }
        double normal[3] = {0, 0, 0};
        const std::uint32_t b = v.face_offsets[f], e = v.face_offsets[f + 1];
        REQUIRE(e - b >= 3);
        for (std::uint32_t k = b; k < e; ++k) {
            const double* c = &v.vertices[3 * v.face_vertices[k]];
            const double* n = &v.vertices[3 * v.face_vertices[k + 1 < e ? k + 1 : b]];
            normal[0] += (c[1] - n[1]) * (c[2] + n[2]);
            normal[1] += (c[2] - n[2]) * (c[0] + n[0]);
            normal[2] += (c[0] - n[0]) * (c[1] + n[1]);
        }
        double dot = 0;
        for (int k = 0; k < 3; ++k) dot += normal[k] * (xyz[3 * q + k] - xyz[3 * p + k]);
        REQUIRE(dot > 0);
    }
    for (std::size_t i = 0; i < xyz.size() / 3; ++i) REQUIRE(std::isinf(v.volume[i]) == (on_hull.count(i) > 0));
}

}  // namespace

TEST_CASE("delaunay3_voronoi: a grid's inner cells are unit cubes, one vertex per cube", "[delaunay3]") {
    std::vector<double> xyz;
    for (int x = 0; x < 6; ++x)
        for (int y = 0; y < 6; ++y)
            for (int z = 0; z < 6; ++z) xyz.insert(xyz.end(), {double(x), double(y), double(z)});
    Delaunay3 d;
    const Voronoi3 v = voronoi_of(xyz, &d);
    REQUIRE(v.vertices.size() / 3 == 5 * 5 * 5);  // the cubes' centres, however each cube is cut
    check_faces(xyz, v, d);
    for (std::size_t i = 0; i < xyz.size() / 3; ++i) {
        const bool inner = xyz[3 * i] > 0 && xyz[3 * i] < 5 && xyz[3 * i + 1] > 0 && xyz[3 * i + 1] < 5 &&
                           xyz[3 * i + 2] > 0 && xyz[3 * i + 2] < 5;
        if (!inner) continue;
        INFO("point " << i);
        REQUIRE(v.volume[i] == Approx(1.0).epsilon(1e-12));
        REQUIRE(v.cell_offsets[i + 1] - v.cell_offsets[i] == 6);  // six faces, the cube's
        for (std::uint32_t k = v.cell_offsets[i]; k < v.cell_offsets[i + 1]; ++k) {
            const std::uint32_t f = v.cell_faces[k];
            REQUIRE(v.face_offsets[f + 1] - v.face_offsets[f] == 4);
        }
    }
}

TEST_CASE("delaunay3_voronoi: faces only between cells that share a polygon (none across a flat hull polygon's diagonal)", "[delaunay3]") {
    // A cube's corners: one vertex (the centre); the cells are octants, and two corners share a
    // face (a quarter-plane) only along a cube edge: 12 faces. Across a square face's diagonal the
    // cells meet in a half-line only, which is no face. A 3 x 3 x 3 grid: its 54 unit-length edges.
    std::vector<double> cube, grid;
    for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y)
            for (int z = 0; z < 3; ++z) {
                grid.insert(grid.end(), {double(x), double(y), double(z)});
                if (x < 2 && y < 2 && z < 2) cube.insert(cube.end(), {double(x), double(y), double(z)});
            }
    for (const auto& [points, faces] : {std::pair{cube, std::size_t{12}}, std::pair{grid, std::size_t{54}}}) {
        const Voronoi3 v = voronoi_of(points);
        REQUIRE(v.face_count() == faces);
        for (std::size_t f = 0; f < v.face_count(); ++f) {
            const double* a = &points[3 * v.face_points[2 * f]];
            const double* b = &points[3 * v.face_points[2 * f + 1]];
            REQUIRE(std::fabs(a[0] - b[0]) + std::fabs(a[1] - b[1]) + std::fabs(a[2] - b[2]) == 1.0);
        }
    }
}

TEST_CASE("delaunay3_voronoi: random points, each bounded cell the hull of its vertices", "[delaunay3]") {
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> xyz(3 * 800);
    for (double& c : xyz) c = u(rng);
    Delaunay3 d;
    const Voronoi3 v = voronoi_of(xyz, &d);
    check_faces(xyz, v, d);
    std::size_t bounded = 0;
    for (std::size_t i = 0; i < 800; ++i) {
        if (std::isinf(v.volume[i])) continue;
        ++bounded;
        const std::vector<double> corners = cell_vertices(v, i);
        const hullkit::Hull h = hullkit::hull(PointSpan(corners.data(), corners.size() / 3));
        REQUIRE(h.ok());
        INFO("cell " << i);
        REQUIRE(v.volume[i] == Approx(h.volume).epsilon(1e-9));
        // The point is inside its cell.
        REQUIRE(v.volume[i] > 0);
    }
    REQUIRE(bounded > 400);
}

TEST_CASE("delaunay3_voronoi: the same volumes as voro++ for cells away from its box", "[delaunay3]") {
    if (std::system("command -v voro++ >/dev/null 2>&1") != 0) {
        WARN("voro++ is not installed (Debian voro++): the comparison is skipped");
        return;
    }
    hullkit_test::TempDir dir("hk-voro");
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> xyz(3 * 2000);
    std::ostringstream text;
    text.precision(17);
    for (std::size_t i = 0; i < 2000; ++i) {
        for (int k = 0; k < 3; ++k) xyz[3 * i + k] = u(rng);
        text << i << ' ' << xyz[3 * i] << ' ' << xyz[3 * i + 1] << ' ' << xyz[3 * i + 2] << '\n';
    }
    hullkit_test::write_text(dir.file("pts.txt"), text.str());
    const std::string command = "cd " + hullkit_test::sh_quote(dir.file("")) + " && voro++ -c '%i %v %n' 0 1 0 1 0 1 pts.txt";
    REQUIRE(std::system(command.c_str()) == 0);
    const Voronoi3 v = voronoi_of(xyz);
    std::ifstream in(dir.file("pts.txt.vol"));
    std::string line;
    std::size_t compared = 0;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::size_t id;
        double volume;
        fields >> id >> volume;
        bool walls = false;
        for (long neighbour; fields >> neighbour;) walls = walls || neighbour < 0;
        if (walls) continue;  // voro++ clipped this cell to its box
        INFO("cell " << id);
        REQUIRE(v.volume[id] == Approx(volume).epsilon(2e-5));  // voro++ prints 6 digits
        ++compared;
    }
    REQUIRE(compared > 1000);
}
