// A program outside hullkit that uses its installed (or add_subdirectory'd) libraries the way any
// other project would: only the public headers and the hullkit::core, hullkit::delaunay and
// hullkit::route targets (or `pkg-config hullkit`). scripts/consumer_test.sh builds and runs it;
// it prints what it found and exits 1 on any difference from the expected answers.
#include <hullkit/delaunay.hpp>
#include <hullkit/delaunay3.hpp>
#include <hullkit/hull.hpp>
#include <hullkit/route.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

int failures = 0;

void expect(bool condition, const std::string& what) {
    if (!condition) {
        std::fprintf(stderr, "consumer: FAILED: %s\n", what.c_str());
        ++failures;
    }
}

// The cube [0, 2]^3 (its 8 corners) and its centre: 8 vertices, 12 triangles, volume exactly 8,
// and the centre is no vertex.
void check_hull() {
    std::vector<double> xyz;
    for (int corner = 0; corner < 8; ++corner) {
        xyz.push_back(corner & 1 ? 2.0 : 0.0);
        xyz.push_back(corner & 2 ? 2.0 : 0.0);
        xyz.push_back(corner & 4 ? 2.0 : 0.0);
    }
    const std::uint32_t centre = 8;
    xyz.insert(xyz.end(), {1.0, 1.0, 1.0});

    const hullkit::Hull hull = hullkit::hull(xyz);
    expect(hull.ok(), "hull() failed: " + hull.error);
    expect(hull.dimension == 3, "hull dimension " + std::to_string(hull.dimension) + ", expected 3");
    expect(hull.vertices.size() == 8,
           "hull has " + std::to_string(hull.vertices.size()) + " vertices, expected 8");
    expect(hull.face_count() == 12,
           "hull has " + std::to_string(hull.face_count()) + " triangles, expected 12");
    expect(hull.volume == 8.0, "hull volume " + std::to_string(hull.volume) + ", expected exactly 8");
    expect(std::find(hull.vertices.begin(), hull.vertices.end(), centre) == hull.vertices.end(),
           "the cube's centre is a hull vertex");
    std::printf("hull: %zu vertices, %zu triangles, volume %.17g\n", hull.vertices.size(),
                hull.face_count(), hull.volume);
}

// The unit square's corners and its centre: 4 triangles, all meeting at the centre.
void check_delaunay() {
    const std::vector<double> xy = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    const hullkit::Delaunay triangulation = hullkit::delaunay(xy);
    expect(triangulation.ok(), "delaunay() failed: " + triangulation.error);
    expect(triangulation.triangle_count() == 4,
           "triangulation has " + std::to_string(triangulation.triangle_count()) +
               " triangles, expected 4");
    expect(std::count(triangulation.triangles.begin(), triangulation.triangles.end(), 4u) == 4,
           "the square's centre is not a corner of every triangle");
    std::printf("delaunay: %zu triangles\n", triangulation.triangle_count());
}

// The unit cube's corners and its centre: 12 tetrahedra (two on each face, all meeting at the
// centre), each positively oriented, their volumes summing to exactly 1.
void check_delaunay3() {
    std::vector<double> xyz;
    for (int corner = 0; corner < 8; ++corner) xyz.insert(xyz.end(), {double(corner & 1), double(corner >> 1 & 1), double(corner >> 2 & 1)});
    xyz.insert(xyz.end(), {0.5, 0.5, 0.5});
    const hullkit::Delaunay3 mesh = hullkit::delaunay3(xyz);
    expect(mesh.ok(), "delaunay3() failed: " + mesh.error);
    expect(mesh.dimension == 3, "delaunay3 dimension " + std::to_string(mesh.dimension) + ", expected 3");
    expect(mesh.tetrahedron_count() == 12,
           "tetrahedralization has " + std::to_string(mesh.tetrahedron_count()) + " tetrahedra, expected 12");
    double volume = 0;
    for (std::size_t t = 0; t < mesh.tetrahedron_count(); ++t) {
        const double* p[4];
        for (int k = 0; k < 4; ++k) p[k] = &xyz[3 * mesh.tetrahedra[4 * t + k]];
        double e[3][3];
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) e[k][a] = p[k + 1][a] - p[0][a];
        const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
        expect(det > 0, "tetrahedron " + std::to_string(t) + " is not positively oriented");
        volume += det / 6;
    }
    expect(volume == 1.0, "tetrahedra's volume " + std::to_string(volume) + ", expected exactly 1");
    std::printf("delaunay3: %zu tetrahedra, volume %.17g\n", mesh.tetrahedron_count(), volume);
}

// A tetrahedron moved along x from 0 to 10 through a wall at x = 5: the one leg hits it.
void check_route() {
    hullkit::Scene scene;
    scene.parts.push_back({"tetrahedron",
                           {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1},
                           {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}});
    scene.obstacles.push_back({"wall", {5, -10, -10, 5, 10, -10, 5, 0, 10}, {0, 1, 2}});
    scene.route = {0, 0, 0, 10, 0, 0};
    const hullkit::RouteReport report = hullkit::check_route(scene);
    expect(report.ok(), "check_route() failed: " + report.error);
    expect(report.legs.size() == 1, "route has " + std::to_string(report.legs.size()) + " legs, expected 1");
    expect(!report.clear, "the route through the wall is reported clear");
    if (report.legs.size() == 1) {
        expect(report.legs[0].status == hullkit::LegStatus::Hit,
               std::string("leg status ") + hullkit::leg_status_name(report.legs[0].status) +
                   ", expected hit");
        // First contact: the tetrahedron's corner (1, 0, 0) reaches x = 5 at offset 4, fraction 0.4.
        expect(report.legs[0].fraction_lo <= 0.4 && report.legs[0].fraction_hi >= 0.4 - 1e-9,
               "first contact at fraction " + std::to_string(report.legs[0].fraction_lo) +
                   ", expected 0.4");
        std::printf("route: %s at fraction %.6f\n", hullkit::leg_status_name(report.legs[0].status),
                    report.legs[0].fraction_lo);
    }
}

}  // namespace

int main() {
    check_hull();
    check_delaunay();
    check_delaunay3();
    check_route();
    return failures == 0 ? 0 : 1;
}
