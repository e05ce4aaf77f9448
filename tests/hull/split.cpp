// The split-and-join path (native/src/hull/quickhull_split.cpp) must not only give the right hull
// but apply where it is meant to: when a join cannot go on it gives up and the caller runs the
// serial quickhull, which gives the same bits, only later. The tests in threads.cpp would pass
// with a join that always gave up, so these call it directly (an internal function: this file
// includes native/src) and require that it succeeded.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "hull/hull_internal.hpp"
#include "hull_checks.hpp"

using hullkit_test::Cloud;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("quickhull split: the halves are joined, never given up, and give quickhull_faces' faces bit for bit",
          "[threads]") {
    std::vector<double> lifted;  // every point extreme, square faces split by the cuts
    for (int x = -150; x < 150; ++x) {
        for (int y = -150; y < 150; ++y) lifted.insert(lifted.end(), {double(x), double(y), double(x * x + y * y)});
    }
    std::vector<double> box_surface;  // large coplanar faces across every cut; edges and corners repeat
    for (int a = 0; a <= 120; ++a) {
        for (int b = 0; b <= 120; ++b) {
            for (double fixed : {0.0, 120.0}) {
                box_surface.insert(box_surface.end(), {fixed, double(a), double(b)});
                box_surface.insert(box_surface.end(), {double(a), fixed, double(b)});
                box_surface.insert(box_surface.end(), {double(a), double(b), fixed});
            }
        }
    }
    const std::vector<std::pair<std::string, std::vector<double>>> clouds = {
        {"sphere", hullkit_test::random_cloud(Cloud::Sphere, 150000, 61)},
        {"lifted grid", lifted},
        {"surface of a box", box_surface}};
    for (const auto& [name, xyz] : clouds) {
        INFO(name);
        const hullkit::PointSpan points(xyz.data(), xyz.size() / 3);
        hullkit::detail::Polygons serial;
        double serial_volume = 0.0, serial_area = 0.0;
        std::string error;
        REQUIRE(hullkit::detail::quickhull_faces(points, hullkit::detail::find_simplex(points), serial, &serial_volume,
                                                 &serial_area, error));
        for (unsigned threads : {2u, 3u, 8u}) {  // one join; a join of joins, uneven; three levels
            INFO("threads " << threads);
            hullkit::detail::Polygons split;
            double volume = 0.0, area = 0.0;
            REQUIRE(hullkit::detail::quickhull_split_faces(points, threads, split, &volume, &area));
            REQUIRE(split.offsets == serial.offsets);
            REQUIRE(split.vertices == serial.vertices);
            REQUIRE(same_bits(volume, serial_volume));
            REQUIRE(same_bits(area, serial_area));
        }
    }
}
