// Refining a given triangulation (hullkit::refine_mesh, Triangle's -r): the domain is the union of
// the input triangles, checked from the outside: the exact verifier, the covered area (GMP) equal
// to the input triangles' summed area, the area and angle bounds measured on the output, each
// output triangle inside its input triangle when areas are per triangle (exact orientations),
// unused points left out, kept segments, and the errors that name the triangle.
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "delaunay/constrained_checks.hpp"
#include "hullkit/constrained.hpp"
#include "hullkit/predicates.hpp"

namespace {

using hullkit::ConstrainedDelaunay;
using hullkit::PointSpan2;
using hullkit::RefineMeshOptions;

using constrained_test::q;
using constrained_test::smallest_angle;
using constrained_test::twice_area;
using constrained_test::verified;

/// Twice the summed area of triangles (either orientation), exactly.
mpq_class twice_input_area(const std::vector<double>& xy, const std::vector<std::uint32_t>& tris) {
    mpq_class sum = 0;
    for (std::size_t t = 0; 3 * t < tris.size(); ++t) {
        const double* a = &xy[2 * tris[3 * t]];
        const double* b = &xy[2 * tris[3 * t + 1]];
        const double* c = &xy[2 * tris[3 * t + 2]];
        sum += abs((q(b[0]) - q(a[0])) * (q(c[1]) - q(a[1])) - (q(b[1]) - q(a[1])) * (q(c[0]) - q(a[0])));
    }
    return sum;
}

double area_of(const ConstrainedDelaunay& d, std::size_t t) {
    const double* a = &d.coords[2 * d.triangles[3 * t]];
    const double* b = &d.coords[2 * d.triangles[3 * t + 1]];
    const double* c = &d.coords[2 * d.triangles[3 * t + 2]];
    return std::fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
}

/// The annulus between the squares [0, 4]^2 and [1, 3]^2, as 8 triangles (an input mesh with a hole).
void annulus(std::vector<double>* xy, std::vector<std::uint32_t>* tris) {
    *xy = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3};
    *tris = {0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
}

bool point_in_closed_triangle(const double* p, const double* a, const double* b, const double* c) {
    const int o = hullkit::orient2d(a[0], a[1], b[0], b[1], c[0], c[1]);
    return o * hullkit::orient2d(a[0], a[1], b[0], b[1], p[0], p[1]) >= 0 &&
           o * hullkit::orient2d(b[0], b[1], c[0], c[1], p[0], p[1]) >= 0 &&
           o * hullkit::orient2d(c[0], c[1], a[0], a[1], p[0], p[1]) >= 0;
}

std::string error_of(const std::vector<double>& xy, const std::vector<std::uint32_t>& tris, RefineMeshOptions options = {},
                     const std::vector<std::uint32_t>& segments = {}) {
    const ConstrainedDelaunay d = hullkit::refine_mesh(PointSpan2(xy), tris.data(), tris.size() / 3, segments.data(),
                                                       segments.size() / 2, options);
    CHECK(d.triangles.empty());
    return d.error;
}

}  // namespace

TEST_CASE("refine_mesh: an annulus mesh keeps its hole and its area under area and angle bounds", "[refine_mesh]") {
    std::vector<double> xy;
    std::vector<std::uint32_t> tris;
    annulus(&xy, &tris);
    for (double max_area : {0.0, 0.05}) {
        for (double min_angle : {0.0, 20.0, 30.0}) {
            INFO("max_area " << max_area << ", min_angle " << min_angle);
            RefineMeshOptions options;
            options.quality.max_area = max_area;
            options.quality.min_angle = min_angle;
            const ConstrainedDelaunay d = hullkit::refine_mesh(PointSpan2(xy), tris.data(), tris.size() / 3, nullptr, 0, options);
            verified(d, true);
            CHECK(twice_area(d) == twice_input_area(xy, tris));  // 2 * (16 - 4)
            CHECK(twice_area(d) == 24);
            CHECK(d.input_count == 8);
            for (std::size_t t = 0; t < d.triangle_count(); ++t) {
                // Nothing in the hole: every centroid outside the open inner square.
                double cx = 0, cy = 0;
                for (int k = 0; k < 3; ++k) cx += d.coords[2 * d.triangles[3 * t + k]], cy += d.coords[2 * d.triangles[3 * t + k] + 1];
                cx /= 3, cy /= 3;
                CHECK(!(cx > 1 && cx < 3 && cy > 1 && cy < 3));
                if (max_area > 0) CHECK(area_of(d, t) <= max_area);
            }
            if (min_angle > 0) CHECK(smallest_angle(d) >= min_angle - 1e-9);
            if (max_area == 0 && min_angle == 0) CHECK(d.triangle_count() == 8);
            CHECK(d.triangle_region.empty());
        }
    }
}

TEST_CASE("refine_mesh: areas per triangle hold over each input triangle, which every output triangle lies in", "[refine_mesh]") {
    // The square [0, 2]^2 as two triangles, then a third point set apart that no triangle uses.
    const std::vector<double> xy = {0, 0, 2, 0, 2, 2, 0, 2, 1, 1};
    const std::vector<std::uint32_t> tris = {0, 1, 2, 0, 3, 2};  // the second one clockwise
    RefineMeshOptions options;
    options.triangle_max_area = {0.01, -1};  // -1: only the global bound (none here)
    options.quality.min_angle = 20;
    const ConstrainedDelaunay d = hullkit::refine_mesh(PointSpan2(xy), tris.data(), 2, nullptr, 0, options);
    verified(d, true);
    CHECK(twice_area(d) == 8);
    REQUIRE(d.triangle_region.size() == d.triangle_count());
    std::size_t in_first = 0, in_second = 0;
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        const std::int32_t r = d.triangle_region[t];
        REQUIRE((r == 0 || r == 1));
        for (int k = 0; k < 3; ++k) {
            const double* p = &d.coords[2 * d.triangles[3 * t + k]];
            CHECK(point_in_closed_triangle(p, &xy[2 * tris[3 * r]], &xy[2 * tris[3 * r + 1]], &xy[2 * tris[3 * r + 2]]));
        }
        if (r == 0) {
            ++in_first;
            CHECK(area_of(d, t) <= 0.01);
        } else {
            ++in_second;
        }
        // Point 4 (1, 1) lies on the diagonal but no triangle uses it: it is no corner.
        for (int k = 0; k < 3; ++k) CHECK(d.triangles[3 * t + k] != 4);
    }
    CHECK(in_first >= 200);  // area 2 in pieces of at most 0.01
    CHECK(in_second < in_first / 4);
    CHECK(d.coords.size() / 2 == 5 + d.steiner_count);
    CHECK(d.coords[8] == 1.0);  // the unused point stays in coords
}

TEST_CASE("refine_mesh: a kept segment inside and a seam of repeated points", "[refine_mesh]") {
    // The square [0, 2]^2 as four triangles around its centre, with the right half's corners given
    // again (points 5-7 repeat 1, 2, 4): the seam x = 1 ... is inner, not a boundary.
    const std::vector<double> xy = {0, 0, 2, 0, 2, 2, 0, 2, 1, 1, 2, 0, 2, 2, 1, 1};
    const std::vector<std::uint32_t> tris = {0, 1, 4, 5, 6, 7, 2, 3, 4, 3, 0, 4};
    const std::vector<std::uint32_t> segment = {0, 2};  // the diagonal through the centre
    RefineMeshOptions options;
    options.quality.max_area = 0.02;
    const ConstrainedDelaunay d = hullkit::refine_mesh(PointSpan2(xy), tris.data(), 4, segment.data(), 1, options);
    verified(d, true);
    CHECK(twice_area(d) == 8);
    // The diagonal is covered by constrained edges: their lengths along it add up to its length.
    double along = 0;
    for (std::size_t e = 0; e < d.triangles.size(); ++e) {
        if (!d.constrained[e] || (d.halfedges[e] >= 0 && static_cast<std::size_t>(d.halfedges[e]) < e)) continue;
        const double* a = &d.coords[2 * d.triangles[e]];
        const double* b = &d.coords[2 * d.triangles[e % 3 == 2 ? e - 2 : e + 1]];
        if (a[0] == a[1] && b[0] == b[1] && d.halfedges[e] >= 0) along += std::fabs(b[0] - a[0]);
    }
    CHECK(along == Approx(2.0));
    // No constrained edge inside other than on the diagonal: the seam is not a segment.
    for (std::size_t e = 0; e < d.triangles.size(); ++e) {
        if (!d.constrained[e] || d.halfedges[e] < 0) continue;
        const double* a = &d.coords[2 * d.triangles[e]];
        const double* b = &d.coords[2 * d.triangles[e % 3 == 2 ? e - 2 : e + 1]];
        CHECK(hullkit::orient2d(0, 0, 2, 2, a[0], a[1]) == 0);
        CHECK(hullkit::orient2d(0, 0, 2, 2, b[0], b[1]) == 0);
    }
    for (double v : {d.representative[5], d.representative[6], d.representative[7]}) CHECK(v < 5);
}

TEST_CASE("refine_mesh: the same arrays every run, and the mesh's own triangles without bounds", "[refine_mesh]") {
    std::vector<double> xy;
    std::vector<std::uint32_t> tris;
    annulus(&xy, &tris);
    RefineMeshOptions options;
    options.quality.min_angle = 28;
    options.quality.max_area = 0.1;
    const ConstrainedDelaunay a = hullkit::refine_mesh(PointSpan2(xy), tris.data(), 8, nullptr, 0, options);
    const ConstrainedDelaunay b = hullkit::refine_mesh(PointSpan2(xy), tris.data(), 8, nullptr, 0, options);
    CHECK(a.triangles == b.triangles);
    CHECK(a.coords == b.coords);
    // Per-triangle bounds of 0 keep every edge: without other bounds the output is the input mesh.
    RefineMeshOptions same;
    same.triangle_max_area.assign(8, 0.0);
    const ConstrainedDelaunay c = hullkit::refine_mesh(PointSpan2(xy), tris.data(), 8, nullptr, 0, same);
    verified(c, true);
    REQUIRE(c.triangle_count() == 8);
    for (std::size_t t = 0; t < 8; ++t) {
        std::vector<std::uint32_t> got(c.triangles.begin() + 3 * t, c.triangles.begin() + 3 * t + 3);
        std::vector<std::uint32_t> want(tris.begin() + 3 * c.triangle_region[t], tris.begin() + 3 * c.triangle_region[t] + 3);
        std::sort(got.begin(), got.end());
        std::sort(want.begin(), want.end());
        CHECK(got == want);
    }
}

TEST_CASE("refine_mesh: errors name the triangle", "[refine_mesh]") {
    std::vector<double> xy;
    std::vector<std::uint32_t> tris;
    annulus(&xy, &tris);
    CHECK(error_of(xy, {}) == "there are no triangles to refine");
    CHECK(error_of(xy, {0, 1, 9}) == "triangle 0 has corner 9, but there are 8 points");
    CHECK(error_of(xy, {0, 1, 5, 0, 4, 6}) == "triangle 1 (points 0, 4, 6) has no area: its corners are collinear or repeated");
    CHECK(error_of(xy, {0, 1, 5, 5, 1, 0}).find("triangles 0 and 1 overlap: both have the edge") == 0);
    RefineMeshOptions areas;
    areas.triangle_max_area = {1, 2};
    CHECK(error_of(xy, tris, areas) == "triangle_max_area holds 2 numbers for 8 triangles");
    areas.triangle_max_area.assign(8, 0.5);
    areas.triangle_max_area[3] = std::nan("");
    CHECK(error_of(xy, tris, areas) == "triangle 3: its max_area is not a finite number");
    CHECK(error_of(xy, tris, {}, {0, 8}).find("segment 0 joins points 0 and 8, but there are 8 points") == 0);
    // A T-junction: point 4 of the left half lies on the edge of the right triangle.
    const std::vector<double> t_xy = {0, 0, 2, 0, 2, 2, 0, 2, 2, 1, 4, 1};
    const std::vector<std::uint32_t> t_tris = {0, 1, 4, 0, 4, 2, 0, 2, 3, 1, 5, 2};
    RefineMeshOptions per;
    per.triangle_max_area = {0, 0, 0, 0};
    CHECK(error_of(t_xy, t_tris, per).find("triangle 3 is not a face of the mesh its edges make") == 0);
    // The same triangles with the split one first: the error names it by its own index.
    const std::vector<std::uint32_t> first = {1, 5, 2, 0, 1, 4, 0, 4, 2, 0, 2, 3};
    const ConstrainedDelaunay named = hullkit::refine_mesh(PointSpan2(t_xy), first.data(), 4, nullptr, 0, per);
    CHECK(named.error.find("triangle 0 is not a face of the mesh its edges make") == 0);
    CHECK(named.error_triangle == 0);
    RefineMeshOptions bad;
    bad.quality.min_angle = 40;
    CHECK(error_of(xy, tris, bad).find("min_angle must be between 0 and 34") == 0);
}

TEST_CASE("refine_mesh: a triangle whose area underflows in doubles is tested on scaled points (fuzz regression)", "[refine_mesh]") {
    // tests/data/fuzz/constrained-refine-underflowing-area.bin: the triangle (4e-320, 0), (0, 0),
    // (0, 1.3e-259) has an area below the smallest double; unscaled, orient2d called it flat.
    const std::vector<double> xy = {4.0711009217318715e-320, 0, 0, 0, 0, 1.3328545234157988e-259};
    const std::vector<std::uint32_t> tris = {0, 1, 2};
    RefineMeshOptions same;
    same.triangle_max_area = {0};
    const ConstrainedDelaunay d = hullkit::refine_mesh(PointSpan2(xy), tris.data(), 1, nullptr, 0, same);
    REQUIRE(d.ok());
    REQUIRE(d.triangle_count() == 1);
    CHECK(d.triangle_region == std::vector<std::int32_t>{0});
    // Points the triangulation refuses fail there, named (not as a flat triangle).
    const std::vector<double> bad = {0, 0, 1, 0, 0, std::nan("")};
    const ConstrainedDelaunay e = hullkit::refine_mesh(PointSpan2(bad), tris.data(), 1, nullptr, 0, {});
    CHECK(e.error.find("point 2 has a non-finite y coordinate") == 0);
    CHECK(e.error_point == 2);
}
