// Tests of hullkit::verify (correct hulls pass, each kind of defect is caught) and of the
// `hullkit verify` command.
#include "hullkit/verify.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"
#include "hull_checks.hpp"
#include "hullkit/hull.hpp"
#include "hullkit/mesh_io.hpp"

using hullkit::Algorithm;
using hullkit::Hull;
using hullkit::HullOptions;
using hullkit::VerifyReport;
using hullkit_test::Cloud;
using hullkit_test::cube_corners;
using hullkit_test::data_path;
using hullkit_test::read_text;
using hullkit_test::run_cli;
using hullkit_test::RunResult;
using hullkit_test::TempDir;
using hullkit_test::write_text;

namespace {

using Triangles = std::vector<std::uint32_t>;

std::string describe(const VerifyReport& report) {
    std::ostringstream out;
    out << "ok=" << report.ok << " problems=" << report.problem_count << "\n";
    for (const auto& line : report.lines()) out << "  " << line << "\n";
    for (const auto& note : report.notes) out << "  note: " << note << "\n";
    return out.str();
}

bool mentions(const VerifyReport& report, const std::string& text) {
    for (const auto& line : report.problems) {
        if (line.find(text) != std::string::npos) return true;
    }
    return false;
}

VerifyReport check_triangles(const std::vector<double>& xyz, const Triangles& triangles) {
    return hullkit::verify(hullkit::PointSpan(xyz), triangles.data(), triangles.size() / 3);
}

Hull compute(const std::vector<double>& xyz, Algorithm algorithm = Algorithm::Quickhull, bool merge = false) {
    HullOptions options;
    options.algorithm = algorithm;
    options.merge_coplanar = merge;
    Hull hull = hullkit::hull(xyz, options);
    INFO(hull.error);
    REQUIRE(hull.ok());
    return hull;
}

void require_ok(const std::vector<double>& xyz, const Hull& hull) {
    const VerifyReport report = hullkit::verify(xyz, hull);
    INFO(describe(report));
    REQUIRE(report.ok);
    CHECK(report.problem_count == 0);
    CHECK(report.checked_points == xyz.size() / 3);
}

const std::vector<double> kTetra = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};

/// The cube [-1,1]^3 (corners 0..7) triangulated by hand, two triangles per face, counter-clockwise
/// seen from outside. Face x = +1 is split into 4 triangles around point `centre` when given.
Triangles cube_triangles(std::int64_t centre = -1) {
    // corner index = (x>0) + 2 (y>0) + 4 (z>0)
    const std::uint32_t quads[6][4] = {
        {1, 3, 7, 5},  // x = +1 (counter-clockwise seen from +x)
        {0, 4, 6, 2},  // x = -1
        {2, 6, 7, 3},  // y = +1
        {0, 1, 5, 4},  // y = -1
        {4, 5, 7, 6},  // z = +1
        {0, 2, 3, 1},  // z = -1
    };
    Triangles t;
    for (int f = 0; f < 6; ++f) {
        const auto& q = quads[f];
        if (f == 0 && centre >= 0) {
            const auto c = static_cast<std::uint32_t>(centre);
            for (int k = 0; k < 4; ++k) t.insert(t.end(), {q[k], q[(k + 1) % 4], c});
        } else {
            t.insert(t.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
        }
    }
    return t;
}

}  // namespace

// ---- correct hulls ----

TEST_CASE("verify: hand-made tetrahedron and cube triangulations pass") {
    const Triangles tetra = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    VerifyReport report = check_triangles(kTetra, tetra);
    INFO(describe(report));
    CHECK(report.ok);
    CHECK(report.vertex_count == 4);
    CHECK(report.face_count == 4);
    CHECK(report.checked_points == 4);

    const std::vector<double> cube = cube_corners();
    report = check_triangles(cube, cube_triangles());
    INFO(describe(report));
    CHECK(report.ok);
    CHECK(report.face_count == 6);  // coplanar pairs are merged into squares
    CHECK(report.triangle_count == 12);
}

TEST_CASE("verify: hulls of the tetrahedron and the cube, both algorithms, merge on and off") {
    auto cube = cube_corners(2.0);
    const double extra[][3] = {{0, 0, 0}, {2, 0, 0}, {0, -2, 0}, {0, 0, 2}, {2, 2, 0}, {-2, 0, -2}, {1, 1, 1}};
    for (const auto& p : extra) cube.insert(cube.end(), p, p + 3);
    for (Algorithm algorithm : {Algorithm::Quickhull, Algorithm::Giftwrap}) {
        for (bool merge : {false, true}) {
            INFO(hullkit::algorithm_name(algorithm) << " merge=" << merge);
            require_ok(kTetra, compute(kTetra, algorithm, merge));
            const Hull hull = compute(cube, algorithm, merge);
            require_ok(cube, hull);
            const VerifyReport report = hullkit::verify(cube, hull);
            CHECK(report.face_count == 6);
            CHECK(report.vertex_count == 8);
        }
    }
}

TEST_CASE("verify: random clouds, both algorithms") {
    for (Cloud kind : {Cloud::Cube, Cloud::Ball, Cloud::Sphere}) {
        for (std::uint64_t seed : {1u, 2u, 3u}) {
            const auto xyz = hullkit_test::random_cloud(kind, 2000, seed);
            for (Algorithm algorithm : {Algorithm::Quickhull, Algorithm::Giftwrap}) {
                INFO("cloud " << static_cast<int>(kind) << " seed " << seed << " " << hullkit::algorithm_name(algorithm));
                require_ok(xyz, compute(xyz, algorithm, seed == 2));
            }
        }
    }
}

TEST_CASE("verify: a large cloud is checked by walking, without exhaustive tests") {
    auto xyz = hullkit_test::random_cloud(Cloud::Ball, 200000, 7);
    const auto sphere = hullkit_test::random_cloud(Cloud::Sphere, 20000, 8);
    xyz.insert(xyz.end(), sphere.begin(), sphere.end());
    const Hull hull = compute(xyz);
    const VerifyReport report = hullkit::verify(xyz, hull);
    INFO(describe(report));
    REQUIRE(report.ok);
    CHECK(report.checked_points == xyz.size() / 3);
    CHECK(report.exhaustive_points == 0);
    CHECK(report.notes.empty());
}

TEST_CASE("verify: far from unit scale, offset far from the origin") {
    for (double scale : {1e-150, 1e150, 1e-300, 1e300}) {
        auto xyz = hullkit_test::random_cloud(Cloud::Ball, 300, 11);
        for (double& c : xyz) c *= scale;
        INFO("scale " << scale);
        require_ok(xyz, compute(xyz));
    }
    auto xyz = hullkit_test::random_cloud(Cloud::Cube, 300, 12);
    for (double& c : xyz) c += 1e9;
    require_ok(xyz, compute(xyz));
}

TEST_CASE("verify: lower-dimensional results") {
    // A polygon: a square with points inside and on its edges, tilted out of the axis planes.
    std::vector<double> square;
    for (int i = 0; i <= 4; ++i) {
        for (int j = 0; j <= 4; ++j) square.insert(square.end(), {double(i), double(j), double(i + 2 * j)});
    }
    for (bool merge : {false, true}) {
        const Hull polygon = compute(square, Algorithm::Quickhull, merge);
        REQUIRE(polygon.dimension == 2);
        require_ok(square, polygon);
    }
    // A segment, a repeated point, nothing.
    const std::vector<double> line = {3, 3, 3, 1, 2, 3, 5, 4, 3, 7, 5, 3, 1, 2, 3};
    const Hull segment = compute(line);
    REQUIRE(segment.dimension == 1);
    require_ok(line, segment);
    const std::vector<double> same = {1.5, -2, 7, 1.5, -2, 7, 1.5, -2, 7};
    const Hull point = compute(same);
    REQUIRE(point.dimension == 0);
    require_ok(same, point);
    const std::vector<double> none;
    const Hull empty = compute(none);
    REQUIRE(empty.dimension == -1);
    require_ok(none, empty);
}

TEST_CASE("verify: a hull too thin for any interior double is still certified") {
    // z = 2^30 and one ulp above: no double lies strictly between, so no exact interior point exists.
    const double z = 1073741824.0, up = std::nextafter(z, 2 * z);
    std::vector<double> xyz = {0, 0, z, 1, 0, z, 0, 1, z, 0.25, 0.25, up, 0.1, 0.1, z, 0.2, 0.3, z};
    const Hull hull = compute(xyz);
    const VerifyReport report = hullkit::verify(xyz, hull);
    INFO(describe(report));
    REQUIRE(report.ok);
    CHECK(report.exhaustive_points == 2);
    REQUIRE(report.notes.size() == 1);
    CHECK(report.notes[0].find("too thin") != std::string::npos);

    xyz.insert(xyz.end(), {0.9, 0.9, z});  // beyond the edge 1-2 in the base plane: outside
    const VerifyReport outside = hullkit::verify(hullkit::PointSpan(xyz), hull.triangles.data(), hull.face_count());
    INFO(describe(outside));
    CHECK_FALSE(outside.ok);
    CHECK(mentions(outside, "point 6 (0.90000000000000002 0.90000000000000002 1073741824) is outside the hull"));
}

// ---- defects ----

TEST_CASE("verify: a flipped triangle is caught") {
    const std::vector<double> cube = cube_corners();
    Triangles t = cube_triangles();
    std::swap(t[1], t[2]);  // triangle 0 turned inside out
    const VerifyReport report = check_triangles(cube, t);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(mentions(report, "is used in the same direction by triangle"));
    CHECK(mentions(report, "has no reverse edge"));
    CHECK(report.notes.size() == 1);
}

TEST_CASE("verify: a missing triangle is caught") {
    const std::vector<double> cube = cube_corners();
    Triangles t = cube_triangles();
    t.resize(t.size() - 3);
    const VerifyReport report = check_triangles(cube, t);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(report.problem_count == 3);  // the hole's three edges
    CHECK(mentions(report, "has no reverse edge"));
}

TEST_CASE("verify: a duplicated triangle is caught") {
    const std::vector<double> cube = cube_corners();
    Triangles t = cube_triangles();
    t.insert(t.end(), {t[0], t[1], t[2]});
    const VerifyReport report = check_triangles(cube, t);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(mentions(report, "edge 1->3 is used in the same direction by triangle 0 (1 3 7) and triangle 12 (1 3 7)"));
}

TEST_CASE("verify: a point outside the hull is caught, even by one ulp") {
    auto xyz = cube_corners();
    xyz.insert(xyz.end(), {1.0, 0.25, -0.5});  // point 8: on the face x = 1
    xyz.insert(xyz.end(), {0.5, 0.5, 0.5});    // point 9: inside
    const Hull hull = compute(xyz);
    require_ok(xyz, hull);

    auto moved = xyz;
    moved[3 * 8] = std::nextafter(1.0, 2.0);  // one ulp beyond the face
    VerifyReport report = hullkit::verify(moved, hull);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(report.problem_count == 1);
    CHECK(mentions(report, "point 8 (1.0000000000000002 0.25 -0.5) is outside the hull: above the plane of triangle"));

    moved = xyz;
    moved[3 * 9 + 2] = 3.0;  // the inside point moved out through the top
    report = hullkit::verify(moved, hull);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(mentions(report, "point 9 (0.5 0.5 3) is outside the hull"));

    // A random cloud whose hull is checked against the cloud with one interior point moved out.
    auto cloud = hullkit_test::random_cloud(Cloud::Ball, 5000, 21);
    const Hull ball = compute(cloud);
    std::uint32_t inner = 0;
    while (std::binary_search(ball.vertices.begin(), ball.vertices.end(), inner)) ++inner;
    cloud[3 * inner] = 1.5;
    report = hullkit::verify(cloud, ball);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(report.problem_count == 1);
    CHECK(mentions(report, "point " + std::to_string(inner) + " "));
}

TEST_CASE("verify: a vertex that is not extreme is caught") {
    // The face x = 1 split around its centre (point 8).
    auto xyz = cube_corners();
    xyz.insert(xyz.end(), {1.0, 0.0, 0.0});
    VerifyReport report = check_triangles(xyz, cube_triangles(8));
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(report.problem_count == 1);
    CHECK(mentions(report, "vertex 8 is not extreme: its triangles lie in only 1 plane"));

    // The midpoint of edge 1-3 (point 8) as a vertex of the two triangles beside that edge.
    xyz = cube_corners();
    xyz.insert(xyz.end(), {1.0, 0.0, -1.0});
    Triangles t = cube_triangles();
    // Triangles 0 (1 3 7) and 11 (0 3 1) share edge 1-3; split both at the midpoint.
    REQUIRE(Triangles(t.begin(), t.begin() + 3) == Triangles{1, 3, 7});
    REQUIRE(Triangles(t.begin() + 33, t.begin() + 36) == Triangles{0, 3, 1});
    t[1] = 8;                       // (1 8 7)
    t.insert(t.end(), {8, 3, 7});   // (8 3 7)
    t[35] = 8;                      // (0 3 8)
    t.insert(t.end(), {0, 8, 1});   // (0 8 1)
    report = check_triangles(xyz, t);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(report.problem_count == 1);
    CHECK(mentions(report, "vertex 8 is not extreme: its triangles lie in only 2 planes (it lies on an edge"));
}

TEST_CASE("verify: a zero-area triangle is caught") {
    // Tetrahedron 0..3 plus the midpoint 4 of edge 0-1; the triangle beside 0-1 is split at it and
    // the sliver (1 0 4) closes the surface.
    std::vector<double> xyz = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 2, 1, 0, 0};
    // Tetra triangles: (0 2 1) (0 1 3) (0 3 2) (1 2 3); (0 1 3) is replaced.
    const Triangles t = {0, 2, 1, 1, 0, 4, 4, 1, 3, 0, 4, 3, 0, 3, 2, 1, 2, 3};
    const VerifyReport report = check_triangles(xyz, t);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(mentions(report, "triangle 1 (1 0 4) has zero area"));
}

TEST_CASE("verify: an index out of range is caught") {
    const Triangles t = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 4};
    const VerifyReport report = check_triangles(kTetra, t);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(report.problems == std::vector<std::string>{"triangle 3: index 4 is out of range (4 points)"});
    CHECK(check_triangles(kTetra, {}).problems == std::vector<std::string>{"there are no triangles"});
}

TEST_CASE("verify: a non-convex surface is caught") {
    // The cube with corner 7 pushed inwards: a closed, oriented surface, but dented.
    auto xyz = cube_corners();
    xyz[3 * 7] = xyz[3 * 7 + 1] = xyz[3 * 7 + 2] = 0.5;
    const VerifyReport report = check_triangles(xyz, cube_triangles());
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(mentions(report, "is not convex: corner"));
}

TEST_CASE("verify: a surface wrapped twice around the octahedron is caught") {
    // A closed, locally convex sphere (V - E + F = 2) covering the octahedron twice, branched at
    // its poles: the equator is walked twice, through copies 6..9 of points 0..3.
    const std::vector<double> xyz = {1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1,
                                     1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0};
    const std::uint32_t ring[8] = {0, 1, 2, 3, 6, 7, 8, 9};
    Triangles t;
    for (int k = 0; k < 8; ++k) {
        t.insert(t.end(), {ring[k], ring[(k + 1) % 8], 4});
        t.insert(t.end(), {ring[(k + 1) % 8], ring[k], 5});
    }
    const VerifyReport report = check_triangles(xyz, t);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(mentions(report, "vertex 4: its triangles wind 2 times around it"));
    CHECK(mentions(report, "vertex 5: its triangles wind 2 times around it"));
}

TEST_CASE("verify: holes, pinches and pieces are caught") {
    // Two disjoint tetrahedra: closed and oriented, but two pieces (and V - E + F = 4).
    std::vector<double> xyz = kTetra;
    for (double c : kTetra) xyz.push_back(c + 5);
    const Triangles two = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 4, 6, 5, 4, 5, 7, 4, 7, 6, 5, 6, 7};
    VerifyReport report = check_triangles(xyz, two);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(mentions(report, "the triangles are not connected"));
    CHECK(mentions(report, "Euler characteristic"));

    // Two tetrahedra sharing vertex 0: every edge is paired but the surface is pinched at 0.
    xyz = kTetra;
    for (int k = 1; k < 4; ++k) {
        for (int axis = 0; axis < 3; ++axis) xyz.push_back(-kTetra[3 * k + axis]);
    }
    const Triangles pinched = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 4, 5, 0, 6, 4, 0, 5, 6, 4, 6, 5};
    report = check_triangles(xyz, pinched);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(mentions(report, "vertex 0: its triangles form 2 separate fans"));
}

TEST_CASE("verify: identical points must be represented by the lowest index") {
    auto xyz = cube_corners();
    const std::vector<double> copy(xyz.begin() + 3 * 5, xyz.begin() + 3 * 6);
    xyz.insert(xyz.begin(), copy.begin(), copy.end());  // point 0 = old corner 5; corners move up by one
    Triangles t = cube_triangles();
    for (auto& i : t) ++i;  // the hull uses index 6 for that corner, not 0
    VerifyReport report = check_triangles(xyz, t);
    INFO(describe(report));
    CHECK_FALSE(report.ok);
    CHECK(report.problems == std::vector<std::string>{
                                 "vertex 6 repeats point 0 (1 -1 1): the lowest index must represent identical points"});
    // The hull function gets it right.
    require_ok(xyz, compute(xyz));
}

TEST_CASE("verify: Hull fields that do not match the triangles are caught") {
    const auto cube = cube_corners();
    Hull hull = compute(cube, Algorithm::Quickhull, true);
    require_ok(cube, hull);

    Hull wrong = hull;
    wrong.vertices.pop_back();
    CHECK(mentions(hullkit::verify(cube, wrong), "corner 7 is not listed"));
    wrong = hull;
    wrong.volume = -1;
    CHECK(mentions(hullkit::verify(cube, wrong), "Hull::volume is -1, negative"));
    wrong = hull;
    wrong.face_offsets = {0, 4, 8, 12, 16, 20};
    wrong.face_vertices.resize(20);
    CHECK(mentions(hullkit::verify(cube, wrong), "merge_coplanar reported 5 faces, but the triangles form 6"));
    wrong = hull;
    wrong.error = "boom";
    CHECK(hullkit::verify(cube, wrong).problems == std::vector<std::string>{"the hull computation failed: boom"});
}

TEST_CASE("verify: broken lower-dimensional results are caught") {
    // Seen from +z (hull()'s side for this plane) the corners 0 3 2 1 run counter-clockwise.
    std::vector<double> square = {0, 0, 0, 2, 0, 0, 2, -2, 0, 0, -2, 0, 1, -1, 0, 1, 0, 0};
    const Hull polygon = compute(square);
    REQUIRE(polygon.dimension == 2);
    REQUIRE(polygon.vertices == std::vector<std::uint32_t>{0, 3, 2, 1});  // counter-clockwise about the normal
    require_ok(square, polygon);

    Hull wrong = polygon;
    std::swap(wrong.vertices[1], wrong.vertices[2]);  // a bow tie
    CHECK(mentions(hullkit::verify(square, wrong), "is not strictly convex"));
    wrong = polygon;
    wrong.vertices = {0, 1, 2, 3, 0, 1, 2, 3};
    CHECK(mentions(hullkit::verify(square, wrong), "is listed twice"));
    wrong = polygon;
    wrong.vertices = {0, 3, 2, 1, 5};  // point 5 lies on edge 1-0
    wrong.triangles = {0, 3, 2, 0, 2, 1, 0, 1, 5};
    CHECK(mentions(hullkit::verify(square, wrong), "polygon corner 5 is not strictly convex: 1, 5, 0 are collinear"));
    wrong = polygon;
    wrong.triangles = {0, 1, 2};
    CHECK(mentions(hullkit::verify(square, wrong), "Hull::triangles is not the fan"));

    auto moved = square;
    moved[3 * 4 + 2] = 0x1p-400;  // point 4 leaves the plane, by a tiny amount (rescaled for the check)
    CHECK(hullkit::verify(moved, polygon).problems ==
          std::vector<std::string>{"point 4 (1 -1 3.8725919148493183e-121) is not in the polygon's plane"});
    moved[3 * 4 + 2] = 1e-300;  // more than 2^585 from the other coordinates: cannot be checked
    CHECK(mentions(hullkit::verify(moved, polygon), "span more than a factor of 2^585"));
    moved = square;
    moved[3 * 5 + 1] = 0.5;  // point 5 leaves the polygon, in its plane
    CHECK(mentions(hullkit::verify(moved, polygon), "point 5 (1 0.5 0) is outside the polygon: beyond its edge 1-0"));

    const std::vector<double> line = {0, 0, 0, 4, 4, 4, 1, 1, 1};
    const Hull segment = compute(line);
    require_ok(line, segment);
    wrong = segment;
    wrong.vertices = {0, 2};
    CHECK(mentions(hullkit::verify(line, wrong), "point 1 (4 4 4) is beyond the segment's ends 0 and 2"));
    auto bent = line;
    bent[3 * 2] = 1.5;
    CHECK(mentions(hullkit::verify(bent, segment), "point 2 (1.5 1 1) is not on the line through 0 and 1"));

    const std::vector<double> two = {1, 1, 1, 1, 1, 1.5};
    Hull single;
    single.dimension = 0;
    single.vertices = {0};
    CHECK(mentions(hullkit::verify(two, single), "point 1 (1 1 1.5) differs from the single vertex 0"));
}

// ---- the command ----

namespace {

std::string points_text(const std::vector<double>& xyz) {
    std::string text;
    for (std::size_t i = 0; i < xyz.size(); i += 3) {
        text += hullkit::format_double(xyz[i]) + " " + hullkit::format_double(xyz[i + 1]) + " " +
                hullkit::format_double(xyz[i + 2]) + "\n";
    }
    return text;
}

}  // namespace

TEST_CASE("verify: cli accepts the hulls that hullkit hull writes") {
    TempDir dir("hullkit-verify");
    auto xyz = hullkit_test::random_cloud(Cloud::Ball, 3000, 31);
    auto cube = cube_corners(1.0);
    xyz.insert(xyz.end(), cube.begin(), cube.end());
    const std::string points = dir.file("points.txt"), off = dir.file("hull.off");
    write_text(points, points_text(xyz));
    for (const char* algorithm : {"quickhull", "giftwrap"}) {
        RunResult hull = run_cli(dir, {"hull", points, "-o", off, "--algorithm", algorithm});
        REQUIRE(hull.exit_code == 0);
        RunResult check = run_cli(dir, {"verify", points, off});
        INFO(check.out << check.err);
        CHECK(check.exit_code == 0);
        CHECK(check.out == "ok: 3008 points, 12 triangles, 8 vertices\n");
        CHECK(check.err.empty());
    }

    // Lower dimensions: a polygon, a segment and a point, written and read back.
    const std::vector<std::pair<std::vector<double>, std::string>> flat = {
        {{0, 0, 1, 4, 0, 1, 4, 3, 1, 0, 3, 1, 2, 1, 1, 4, 1, 1}, "ok: 6 points, 2 triangles, 4 vertices\n"},
        {{0, 0, 0, 1, 1, 1, 3, 3, 3, 2, 2, 2}, "ok: 4 points, 0 triangles, 2 vertices\n"},
        {{7, 7, 7, 7, 7, 7}, "ok: 2 points, 0 triangles, 1 vertices\n"},
    };
    for (const auto& [cloud, expected] : flat) {
        write_text(points, points_text(cloud));
        REQUIRE(run_cli(dir, {"hull", points, "-o", off}).exit_code == 0);
        RunResult check = run_cli(dir, {"verify", points, off});
        INFO(read_text(off) << check.out << check.err);
        CHECK(check.exit_code == 0);
        CHECK(check.out == expected);
    }
}

TEST_CASE("verify: cli reads the hull in every mesh format the other commands read") {
    TempDir dir("hullkit-verify");
    // Whole-number coordinates: exact in float32 too, so STL and GLB positions match the points.
    const std::string points = dir.file("points.txt");
    write_text(points, points_text(cube_corners()) + "0.5 0.5 0.5\n0 0.25 0.75\n");
    for (const char* name : {"hull.off", "hull.obj", "hull.glb"}) {
        REQUIRE(run_cli(dir, {"hull", points, "-o", dir.file(name)}).exit_code == 0);
        RunResult check = run_cli(dir, {"verify", points, dir.file(name)});
        INFO(name << ": " << check.out << check.err);
        CHECK(check.exit_code == 0);
        CHECK(check.out == "ok: 10 points, 12 triangles, 8 vertices\n");
    }
    // PLY and STL (ASCII), written here from the OFF: STL repeats corners, which are merged.
    const hullkit::MeshResult mesh = hullkit::read_off_mesh(read_text(dir.file("hull.off")), "hull.off");
    REQUIRE(mesh.ok());
    std::string ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(mesh.point_count()) +
                      "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                      std::to_string(mesh.triangle_count()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    std::string stl = "solid hull\n";
    for (std::size_t k = 0; k < mesh.point_count(); ++k) {
        ply += points_text({mesh.xyz.begin() + 3 * k, mesh.xyz.begin() + 3 * k + 3});
    }
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        ply += "3";
        stl += "facet normal 0 0 0\nouter loop\n";
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = mesh.triangles[3 * t + c];
            ply += " " + std::to_string(v);
            stl += "vertex " + points_text({mesh.xyz.begin() + 3 * v, mesh.xyz.begin() + 3 * v + 3});
        }
        ply += "\n";
        stl += "endloop\nendfacet\n";
    }
    write_text(dir.file("hull.ply"), ply);
    write_text(dir.file("hull.stl"), stl + "endsolid hull\n");
    write_text(dir.file("hull-by-content"), stl + "endsolid hull\n");  // no extension: the content says STL
    for (const char* name : {"hull.ply", "hull.stl", "hull-by-content"}) {
        RunResult check = run_cli(dir, {"verify", points, dir.file(name)});
        INFO(name << ": " << check.out << check.err);
        CHECK(check.exit_code == 0);
        CHECK(check.out == "ok: 10 points, 12 triangles, 8 vertices\n");
    }
    // The points in any format hullkit hull reads (a PLY cloud here).
    RunResult from_ply = run_cli(dir, {"verify", dir.file("hull.ply"), dir.file("hull.obj")});
    CHECK(from_ply.exit_code == 0);
    CHECK(from_ply.out == "ok: 8 points, 12 triangles, 8 vertices\n");

    // Lower dimensions and no points, as OBJ: a polygon, a segment, a point, nothing.
    const std::vector<std::pair<std::string, std::string>> flat = {
        {"0 0 1\n4 0 1\n4 3 1\n0 3 1\n2 1 1\n", "ok: 5 points, 2 triangles, 4 vertices\n"},
        {"0 0 0\n1 1 1\n3 3 3\n", "ok: 3 points, 0 triangles, 2 vertices\n"},
        {"7 7 7\n", "ok: 1 points, 0 triangles, 1 vertices\n"},
        {"", "ok: 0 points, 0 triangles, 0 vertices\n"},
    };
    for (const auto& [cloud, expected] : flat) {
        write_text(points, cloud);
        for (const char* name : {"flat.obj", "flat.off"}) {
            REQUIRE(run_cli(dir, {"hull", points, "-o", dir.file(name)}).exit_code == 0);
            RunResult check = run_cli(dir, {"verify", points, dir.file(name)});
            INFO(name << ": " << read_text(dir.file(name)) << check.out << check.err);
            CHECK(check.exit_code == 0);
            CHECK(check.out == expected);
        }
    }
    // float32 positions (STL, GLB) match only points that are floats: said, not hidden.
    write_text(points, "0 0 0\n1 0 0\n0 1 0\n0 0 0.1\n");
    REQUIRE(run_cli(dir, {"hull", points, "-o", dir.file("tenth.glb")}).exit_code == 0);
    RunResult rounded = run_cli(dir, {"verify", points, dir.file("tenth.glb")});
    CHECK(rounded.exit_code == 1);
    CHECK(rounded.out.find(dir.file("tenth.glb") + ": vertex 3 (0 0 0.10000000149011612) is not one of the input points") !=
          std::string::npos);
    // Not a mesh: the reader says what it is not.
    write_text(dir.file("notes.txt"), "hello\n");
    RunResult notes = run_cli(dir, {"verify", points, dir.file("notes.txt")});
    CHECK(notes.exit_code == 2);
    CHECK(notes.err == "hullkit: " + dir.file("notes.txt") + ": not a mesh file this reader knows (OBJ, OFF, PLY, STL or glTF)\n");
}

TEST_CASE("verify: cli reports a broken hull with exit status 1") {
    TempDir dir("hullkit-verify");
    const std::string points = dir.file("points.txt"), off = dir.file("hull.off");
    write_text(points, points_text(cube_corners()) + "0.5 0.5 0.5\n");
    REQUIRE(run_cli(dir, {"hull", points, "-o", off}).exit_code == 0);
    const std::string good = read_text(off);

    // The last triangle dropped: the header is adjusted so the file stays well-formed.
    std::string text = good;
    text.erase(text.find_last_of('\n', text.size() - 2) + 1);
    text.replace(text.find("8 12 0"), 6, "8 11 0");
    write_text(off, text);
    RunResult run = run_cli(dir, {"verify", points, off});
    INFO(text << run.out << run.err);
    CHECK(run.exit_code == 1);
    CHECK(run.out.find("has no reverse edge") != std::string::npos);
    CHECK(run.out.find("not the convex hull: 3 problems\n") != std::string::npos);
    CHECK(run.err.empty());

    // A vertex that is not an input point.
    text = good;
    text.replace(text.find("\n1 1 1\n"), 7, "\n1 1 1.5\n");
    write_text(off, text);
    run = run_cli(dir, {"verify", points, off});
    INFO(text << run.out);
    CHECK(run.exit_code == 1);
    CHECK(run.out.find("(1 1 1.5) is not one of the input points") != std::string::npos);

    // The hull of other points: point 8 is outside.
    write_text(off, good);
    write_text(points, points_text(cube_corners()) + "0.5 0.5 1.25\n");
    run = run_cli(dir, {"verify", points, off});
    INFO(run.out);
    CHECK(run.exit_code == 1);
    CHECK(run.out.find("point 8 (0.5 0.5 1.25) is outside the hull") != std::string::npos);
}

TEST_CASE("verify: cli usage and input errors exit 2 with one line") {
    TempDir dir("hullkit-verify");
    const std::string points = dir.file("points.txt"), off = dir.file("hull.off");
    write_text(points, points_text(kTetra));
    write_text(off, "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 7\n");
    RunResult run = run_cli(dir, {"verify", points, off});
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK(run.err.rfind("hullkit: " + off + ":7:", 0) == 0);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);

    const std::string malformed = data_path("malformed-line3.txt");
    run = run_cli(dir, {"verify", malformed, off});
    CHECK(run.exit_code == 2);
    CHECK(run.err == "hullkit: " + malformed + ":3: expected 3 coordinates, got 2\n");

    run = run_cli(dir, {"verify", points});
    CHECK(run.exit_code == 2);
    CHECK(run.err == "hullkit: verify needs two files, POINTS and HULL, got 1 (try 'hullkit verify --help')\n");
    run = run_cli(dir, {"verify", "--fast", points, off});
    CHECK(run.exit_code == 2);
    CHECK(run.err == "hullkit: unknown option \"--fast\" (try 'hullkit verify --help')\n");
    run = run_cli(dir, {"verify", points, dir.file("missing.off")});
    CHECK(run.exit_code == 2);
    CHECK(run.err.rfind("hullkit: " + dir.file("missing.off") + ": cannot open", 0) == 0);

    run = run_cli(dir, {"verify", "--help"});
    CHECK(run.exit_code == 0);
    CHECK(run.out.rfind("Usage: hullkit verify [options] POINTS HULL", 0) == 0);
    run = run_cli(dir, {"--help"});
    CHECK(run.out.find("\n  verify      ") != std::string::npos);
}
