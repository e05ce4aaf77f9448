// The split-and-join path (native/src/hull/quickhull_split.cpp) must not only give the right hull
// but apply where it is meant to: when a join cannot go on it gives up and the caller runs the
// serial quickhull, which gives the same bits, only later. The tests in threads.cpp would pass
// with a join that always gave up, so these call it directly (an internal function: this file
// includes native/src) and require that it succeeded.
#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

#include "hull/hull_internal.hpp"
#include "hull_checks.hpp"

using hullkit_test::Cloud;
using hullkit_test::same_bits;

TEST_CASE("quickhull split: the halves are joined, never given up, and give quickhull_faces' faces bit for bit",
          "[threads]") {
    const std::vector<std::pair<std::string, std::vector<double>>> clouds = {
        {"sphere", hullkit_test::random_cloud(Cloud::Sphere, 150000, 61)},
        {"lifted grid (square faces split by the cuts)", hullkit_test::lifted_grid(150)},
        {"surface of a box (coplanar faces across every cut, repeats)", hullkit_test::box_surface(120)}};
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
