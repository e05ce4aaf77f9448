// hullkit's constrained Delaunay triangulation against CGAL's Constrained_Delaunay_triangulation_2
// (exact predicates). Points in general position with segments that do not cross: the CDT is
// unique, so both must return the same triangles; for polygons with holes, the same triangles
// inside (CGAL's nesting levels: odd levels are inside, the even-odd rule).
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <list>
#include <random>
#include <set>
#include <vector>

#include "hullkit/constrained.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using FaceInfo = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;  // nesting level, -1 unset
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, FaceInfo>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_tag>;
using Triangle = std::array<std::uint32_t, 3>;

Triangle sorted(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    Triangle t = {a, b, c};
    std::sort(t.begin(), t.end());
    return t;
}

/// CGAL's CDT; with `polygon` only the faces at odd nesting levels (flooded from the infinite face
/// across constraints, one level per crossing).
std::set<Triangle> cgal_triangles(const std::vector<double>& xy, const std::vector<std::uint32_t>& segments, bool polygon) {
    Cdt cdt;
    std::vector<Cdt::Vertex_handle> v;
    for (std::size_t i = 0; i < xy.size() / 2; ++i) {
        v.push_back(cdt.insert(Kernel::Point_2(xy[2 * i], xy[2 * i + 1])));
        v.back()->info() = static_cast<std::uint32_t>(i);
    }
    for (std::size_t k = 0; k < segments.size(); k += 2) cdt.insert_constraint(v[segments[k]], v[segments[k + 1]]);
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
    std::list<Cdt::Face_handle> frontier{cdt.infinite_face()};
    cdt.infinite_face()->info() = 0;
    while (!frontier.empty()) {
        const Cdt::Face_handle f = frontier.front();
        frontier.pop_front();
        for (int k = 0; k < 3; ++k) {
            const Cdt::Face_handle n = f->neighbor(k);
            if (n->info() != -1) continue;
            n->info() = f->info() + (cdt.is_constrained(Cdt::Edge(f, k)) ? 1 : 0);
            // Breadth-first with constrained steps last keeps each face at its lowest level.
            if (cdt.is_constrained(Cdt::Edge(f, k))) frontier.push_back(n);
            else frontier.push_front(n);
        }
    }
    std::set<Triangle> out;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (polygon && f->info() % 2 == 0) continue;
        out.insert(sorted(f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()));
    }
    return out;
}

std::set<Triangle> hullkit_triangles(const hullkit::ConstrainedDelaunay& d) {
    REQUIRE(d.ok());
    CHECK(d.added_count() == 0);
    std::set<Triangle> out;
    for (std::size_t t = 0; t < d.triangle_count(); ++t)
        out.insert(sorted(d.triangles[3 * t], d.triangles[3 * t + 1], d.triangles[3 * t + 2]));
    return out;
}

void same(const std::set<Triangle>& ours, const std::set<Triangle>& theirs) {
    std::size_t common = 0;
    for (const Triangle& t : ours) common += theirs.count(t);
    INFO("hullkit " << ours.size() << ", CGAL " << theirs.size() << ", in both " << common);
    REQUIRE(ours == theirs);
}

/// Random segments between nearby points, each kept only if it crosses no kept one and passes
/// through no point (CGAL's exact orientation decides).
std::vector<std::uint32_t> non_crossing_segments(const std::vector<double>& xy, std::size_t wanted, std::mt19937_64& rng) {
    const std::size_t n = xy.size() / 2;
    auto p = [&](std::uint32_t i) { return Kernel::Point_2(xy[2 * i], xy[2 * i + 1]); };
    std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(n - 1));
    std::vector<std::uint32_t> kept;
    for (std::size_t attempt = 0; attempt < 50 * wanted && kept.size() < 2 * wanted; ++attempt) {
        const std::uint32_t a = pick(rng), b = pick(rng);
        if (a == b || std::hypot(xy[2 * a] - xy[2 * b], xy[2 * a + 1] - xy[2 * b + 1]) > 0.3) continue;
        const Kernel::Segment_2 s(p(a), p(b));
        bool ok = true;
        for (std::size_t k = 0; k < kept.size() && ok; k += 2) {
            const std::uint32_t c = kept[k], d = kept[k + 1];
            const bool shared = a == c || a == d || b == c || b == d;
            if (!shared && CGAL::do_intersect(s, Kernel::Segment_2(p(c), p(d)))) ok = false;
            if (shared && (a == c ? b == d : a == d ? b == c : false)) ok = false;  // the same segment
        }
        for (std::uint32_t i = 0; i < n && ok; ++i)
            if (i != a && i != b && s.has_on(p(i))) ok = false;
        if (ok) kept.insert(kept.end(), {a, b});
    }
    return kept;
}

}  // namespace

TEST_CASE("constrained vs CGAL: random points and segments", "[constrained][cgal]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (std::size_t n : {30u, 200u, 2000u}) {
        std::vector<double> xy(2 * n);
        for (double& v : xy) v = u(rng);
        const std::vector<std::uint32_t> segments = non_crossing_segments(xy, n / 4, rng);
        INFO(n << " points, " << segments.size() / 2 << " segments");
        REQUIRE(segments.size() / 2 >= n / 10);
        const auto ours = hullkit::constrained_delaunay(hullkit::PointSpan2(xy), segments.data(), segments.size() / 2);
        same(hullkit_triangles(ours), cgal_triangles(xy, segments, false));
    }
}

TEST_CASE("constrained vs CGAL: star-shaped polygons with holes", "[constrained][cgal]") {
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(0, 1);
    for (int trial = 0; trial < 10; ++trial) {
        // The outer ring: radius between 8 and 10 at 300 angles. Holes: small radial rings in disjoint
        // discs of radius 1 around centres 3 apart (all inside radius 7).
        std::vector<double> xy;
        std::vector<std::uint32_t> starts, segments;
        auto ring = [&](double cx, double cy, double r_lo, double r_hi, int count, bool reverse) {
            const std::uint32_t first = static_cast<std::uint32_t>(xy.size() / 2);
            if (first != 0) starts.push_back(first);
            for (int k = 0; k < count; ++k) {
                const double angle = (reverse ? -1 : 1) * 2 * M_PI * (k + 0.5 * u(rng)) / count;
                const double r = r_lo + (r_hi - r_lo) * u(rng);
                xy.push_back(cx + r * std::cos(angle)), xy.push_back(cy + r * std::sin(angle));
            }
            for (int k = 0; k < count; ++k) segments.insert(segments.end(), {first + k, first + (k + 1) % count});
        };
        ring(0, 0, 8, 10, 300, false);
        for (int i = -2; i <= 2; ++i)
            for (int j = -2; j <= 2; ++j)
                if (std::hypot(3 * i, 3 * j) < 7 && u(rng) < 0.7) ring(3 * i, 3 * j, 0.4, 1, 12 + trial, u(rng) < 0.5);
        hullkit::PolygonOptions options;
        const auto ours = hullkit::triangulate_polygon(hullkit::PointSpan2(xy), starts.data(), starts.size(), options);
        INFO("trial " << trial << ": " << xy.size() / 2 << " points, " << starts.size() << " holes");
        same(hullkit_triangles(ours), cgal_triangles(xy, segments, true));
    }
}
