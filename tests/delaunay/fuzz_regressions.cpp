// Inputs found by fuzz_delaunay (tests/fuzz, scripts/fuzz.sh), kept in tests/data/fuzz/.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "cli/cli_support.hpp"
#include "hullkit/delaunay.hpp"
#include "hullkit/mesh_io.hpp"

namespace {

std::vector<double> read_points(const std::string& name) {
    const std::string text = hullkit_test::read_text(hullkit_test::data_path("fuzz/" + name));
    const hullkit::Points2Result points = hullkit::parse_points_2d(text, name);
    INFO(points.error);
    REQUIRE(points.ok());
    return points.xy;
}

}  // namespace

// delaunay() rescales coordinates into incircle's exact range; delaunay_find / DelaunayLocator
// compared distances on the raw coordinates, where squares of 1e-209 underflow: a query at point 1
// answered point 0. They now compare on the same rescaled coordinates.
TEST_CASE("delaunay fuzz: nearest point for coordinates near 1e-209", "[delaunay][fuzz]") {
    const std::vector<double> xy = read_points("delaunay-find-coordinates-1e-209.txt");
    const hullkit::PointSpan2 points(xy);
    const hullkit::Delaunay d = hullkit::delaunay(points);
    REQUIRE(d.ok());
    CHECK(d.dimension == 2);
    CHECK(d.representative == std::vector<std::uint32_t>{0, 1, 1, 3});
    for (std::uint32_t i = 0; i < points.count; ++i) {
        for (std::uint32_t start = 0; start < points.count; ++start) {
            INFO("point " << i << " from " << start);
            CHECK(hullkit::delaunay_find(points, d, xy[2 * i], xy[2 * i + 1], start) == d.representative[i]);
        }
    }
}

// The Hilbert-curve keys turned NaN into an unsigned integer (undefined behaviour, a trap in wasm
// without saturating casts) for a box narrower than 65535 / DBL_MAX (infinite scale) or wider
// than DBL_MAX (infinite width). The triangulation itself must be unaffected.
TEST_CASE("delaunay fuzz: bounding boxes too narrow or too wide for the Hilbert scale", "[delaunay][fuzz]") {
    const std::vector<double> tiny = read_points("delaunay-hilbert-tiny-box.txt");
    const hullkit::Delaunay a = hullkit::delaunay(hullkit::PointSpan2(tiny));
    REQUIRE(a.ok());
    CHECK(a.dimension == 1);
    CHECK(a.triangles.empty());
    CHECK(a.hull == std::vector<std::uint32_t>{0, 1});

    const std::vector<double> wide = read_points("delaunay-hilbert-infinite-width.txt");
    const hullkit::PointSpan2 points(wide);
    const hullkit::Delaunay b = hullkit::delaunay(points);
    INFO(b.error);
    REQUIRE(b.ok());
    CHECK(b.dimension == 2);
    const hullkit::DelaunayVerifyReport report = hullkit::verify_delaunay(points, b.triangles.data(), b.triangle_count());
    std::string problems;
    for (const std::string& problem : report.problems) problems += problem + "\n";
    INFO(problems);
    CHECK(report.ok);
    CHECK(b.triangle_count() == 2);
}
