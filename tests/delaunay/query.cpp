// delaunay_find against brute force (GMP distances) and Voronoi cells against their definition;
// verify_delaunay rejecting broken triangulations.
#include <cmath>
#include <cstring>
#include <random>
#include <set>

#include "delaunay_checks.hpp"
#include "sanitized.hpp"

using delaunay_test::q;
using hullkit::Delaunay;

namespace {

/// The exact sign of orient2d(a, b, c) in rational arithmetic (independent of the predicates).
int exact_orient(const double* a, const double* b, double cx, double cy) {
    const mpq_class det = (q(b[0]) - q(a[0])) * (q(cy) - q(a[1])) - (q(b[1]) - q(a[1])) * (q(cx) - q(a[0]));
    return sgn(det);
}

/// The nearest input point by brute force with exact rational distances, ties to the lowest index.
std::int64_t brute_nearest(const std::vector<double>& xy, double x, double y) {
    std::int64_t best = -1;
    mpq_class best_d;
    for (std::size_t i = 0; i < xy.size() / 2; ++i) {
        const mpq_class dx = q(xy[2 * i]) - q(x), dy = q(xy[2 * i + 1]) - q(y);
        const mpq_class d = dx * dx + dy * dy;
        if (best < 0 || d < best_d) best = static_cast<std::int64_t>(i), best_d = d;
    }
    return best;
}

std::vector<double> grid_with_random(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 10);
    std::vector<double> xy;
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) xy.insert(xy.end(), {double(i), double(j)});
    for (int k = 0; k < 100; ++k) xy.insert(xy.end(), {u(rng), u(rng)});
    xy.insert(xy.end(), {3.0, 3.0, 5.0, 5.0});  // duplicates of grid points
    return xy;
}

}  // namespace

TEST_CASE("delaunay_find: nearest point matches brute force, ties to the lowest index", "[query]") {
    const std::vector<double> xy = grid_with_random(21);
    const Delaunay d = hullkit::delaunay(xy);
    hullkit::DelaunayLocator locator(xy, d);
    std::mt19937_64 rng(22);
    std::uniform_real_distribution<double> u(-3, 13);
    std::uniform_int_distribution<std::uint32_t> start(0, static_cast<std::uint32_t>(xy.size() / 2 - 1));
    std::size_t wrong = 0;
    for (int i = 0; i < 3000; ++i) {
        // Half the queries at exact tie positions: grid cell centres and edge midpoints.
        const double x = i % 2 ? u(rng) : 0.5 * std::floor(2 * u(rng));
        const double y = i % 2 ? u(rng) : 0.5 * std::floor(2 * u(rng));
        const std::int64_t expected = brute_nearest(xy, x, y);
        wrong += hullkit::delaunay_find(xy, d, x, y, start(rng)) != expected;
        wrong += locator.find(x, y) != expected;
    }
    REQUIRE(wrong == 0);
    // Collinear, one point, none.
    const std::vector<double> line = {0, 0, 3, 3, 1, 1, 2, 2};
    const Delaunay dl = hullkit::delaunay(line);
    REQUIRE(hullkit::delaunay_find(line, dl, 2.9, 2.0) == brute_nearest(line, 2.9, 2.0));
    REQUIRE(hullkit::delaunay_find(line, dl, -5, 0, 1) == 0);
    const std::vector<double> one = {4, 4, 4, 4};
    REQUIRE(hullkit::delaunay_find(one, hullkit::delaunay(one), 0, 0) == 0);
    const std::vector<double> none;
    REQUIRE(hullkit::delaunay_find(none, hullkit::delaunay(none), 0, 0) == -1);
}

TEST_CASE("delaunay_locate: the lowest-indexed triangle holding each query, barycentric weights and nearest points, any thread count", "[query]") {
    const std::vector<double> xy = grid_with_random(31);
    const Delaunay d = hullkit::delaunay(xy);
    REQUIRE(d.dimension == 2);
    const std::size_t triangles = d.triangle_count();
    std::mt19937_64 rng(32);
    std::uniform_real_distribution<double> u(-2, 12);
    std::vector<double> queries;
    // (A quarter of the queries under the sanitizers: tests/sanitized.hpp.)
    for (int i = 0; i < (hullkit_test::kSanitized ? 1500 : 6000); ++i) {
        // A third at exact vertices, edge midpoints and cell centres of the grid (on edges, at
        // corners: held by several triangles), a third at input points, a third anywhere.
        if (i % 3 == 0) queries.insert(queries.end(), {0.5 * std::floor(2 * u(rng)), 0.5 * std::floor(2 * u(rng))});
        else if (i % 3 == 1) {
            const std::size_t k = rng() % (xy.size() / 2);
            queries.insert(queries.end(), {xy[2 * k], xy[2 * k + 1]});
        } else queries.insert(queries.end(), {u(rng), u(rng)});
    }
    const std::size_t m = queries.size() / 2;
    hullkit::DelaunayQueryOptions options;
    options.barycentric = options.nearest = true;
    options.threads = 1;
    const hullkit::DelaunayQueries one = hullkit::delaunay_locate(xy, d, queries, options);
    REQUIRE(one.ok());
    REQUIRE(one.triangle.size() == m);
    std::size_t wrong_triangle = 0, wrong_weights = 0, wrong_nearest = 0, on_boundary = 0, outside = 0;
    for (std::size_t i = 0; i < m; ++i) {
        const double x = queries[2 * i], y = queries[2 * i + 1];
        // Brute force over every triangle with the exact orientation test: clockwise triangles
        // (y up) hold q when it is on no edge's outer (left) side.
        std::int32_t expected = -1;
        int holders = 0;
        for (std::size_t t = 0; t < triangles; ++t) {
            bool holds = true;
            for (int k = 0; k < 3 && holds; ++k) {
                const double* a = &xy[2 * d.triangles[3 * t + k]];
                const double* b = &xy[2 * d.triangles[3 * t + (k + 1) % 3]];
                holds = exact_orient(a, b, x, y) <= 0;
            }
            if (holds) {
                ++holders;
                if (expected < 0) expected = static_cast<std::int32_t>(t);
            }
        }
        on_boundary += holders > 1;
        outside += expected < 0;
        wrong_triangle += one.triangle[i] != expected;
        wrong_nearest += one.nearest[i] != brute_nearest(xy, x, y);
        const double* w = &one.barycentric[3 * i];
        if (expected < 0) {
            wrong_weights += !(std::isnan(w[0]) && std::isnan(w[1]) && std::isnan(w[2]));
            continue;
        }
        double rx = 0, ry = 0;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t c = d.triangles[3 * static_cast<std::size_t>(expected) + k];
            rx += w[k] * xy[2 * c], ry += w[k] * xy[2 * c + 1];
            // At a corner: exactly 1 there and 0 elsewhere.
            if (xy[2 * c] == x && xy[2 * c + 1] == y) wrong_weights += w[k] != 1.0;
        }
        wrong_weights += std::fabs(rx - x) > 1e-12 || std::fabs(ry - y) > 1e-12 || std::fabs(w[0] + w[1] + w[2] - 1) > 1e-12;
        // On the edge opposite a corner: that corner's weight exactly 0.
        for (int k = 0; k < 3; ++k) {
            const double* a = &xy[2 * d.triangles[3 * static_cast<std::size_t>(expected) + (k + 1) % 3]];
            const double* b = &xy[2 * d.triangles[3 * static_cast<std::size_t>(expected) + (k + 2) % 3]];
            if (exact_orient(a, b, x, y) == 0) wrong_weights += w[k] != 0.0;
        }
    }
    INFO("on shared edges or vertices: " << on_boundary << ", outside: " << outside);
    REQUIRE(on_boundary > 500);
    REQUIRE(outside > 300);
    REQUIRE(wrong_triangle == 0);
    REQUIRE(wrong_weights == 0);
    REQUIRE(wrong_nearest == 0);
    // Past one chunk of the threads' work, any thread count gives the same bits.
    for (unsigned threads : {2u, 3u, 8u}) {
        options.threads = threads;
        const hullkit::DelaunayQueries again = hullkit::delaunay_locate(xy, d, queries, options);
        REQUIRE(again.triangle == one.triangle);
        REQUIRE(again.nearest == one.nearest);
        REQUIRE(std::memcmp(again.barycentric.data(), one.barycentric.data(), 8 * again.barycentric.size()) == 0);
    }
}

TEST_CASE("delaunay_locate: collinear, one point, none, errors name the query", "[query]") {
    hullkit::DelaunayQueryOptions options;
    options.nearest = options.barycentric = true;
    const std::vector<double> line = {0, 0, 3, 3, 1, 1, 2, 2, 1, 1};
    const std::vector<double> queries = {2.9, 2.0, -5, 0, 1, 1, 1.5, 1.5};
    const hullkit::DelaunayQueries found = hullkit::delaunay_locate(line, hullkit::delaunay(line), queries, options);
    REQUIRE(found.ok());
    REQUIRE(found.triangle == std::vector<std::int32_t>{-1, -1, -1, -1});
    REQUIRE(std::isnan(found.barycentric[0]));
    for (std::size_t i = 0; i < 4; ++i) REQUIRE(found.nearest[i] == brute_nearest(line, queries[2 * i], queries[2 * i + 1]));
    const std::vector<double> one = {4, 4, 4, 4};
    REQUIRE(hullkit::delaunay_locate(one, hullkit::delaunay(one), queries, options).nearest == std::vector<std::int32_t>{0, 0, 0, 0});
    const std::vector<double> none;
    REQUIRE(hullkit::delaunay_locate(none, hullkit::delaunay(none), queries, options).nearest == std::vector<std::int32_t>{-1, -1, -1, -1});
    const std::vector<double> square = {0, 0, 1, 0, 1, 1, 0, 1};
    const Delaunay d = hullkit::delaunay(square);
    const std::vector<double> bad = {0.5, 0.5, 0.25, std::nan("")};
    const hullkit::DelaunayQueries failed = hullkit::delaunay_locate(square, d, bad, options);
    REQUIRE_FALSE(failed.ok());
    REQUIRE(failed.error_query == 1);
    REQUIRE(failed.error == "query 1 has a non-finite y coordinate (nan)");
    REQUIRE(failed.triangle.empty());
    const std::vector<double> far = {0.5, 1e300};
    REQUIRE(hullkit::delaunay_locate(square, d, far, options).error_query == 0);
    options.nearest = false;  // orient2d's range is wider than the distance comparisons'
    const std::vector<double> farther = {0.5, 1e90};
    REQUIRE(hullkit::delaunay_locate(square, d, farther, options).triangle == std::vector<std::int32_t>{-1});
    const std::vector<double> other = {0, 0, 1, 0, 1, 1};
    REQUIRE_FALSE(hullkit::delaunay_locate(other, d, queries, options).ok());
}

TEST_CASE("delaunay_locate: a folded triangulation from outside cannot make a walk loop forever", "[query]") {
    // Two copies of one clockwise triangle whose half-edges send a walk toward (5, 5), beyond the
    // hypotenuse (edge 1), from one copy to the other and back, by a different edge each time.
    const std::vector<double> xy = {0, 0, 0, 1, 1, 0};
    Delaunay folded;
    folded.dimension = 2;
    folded.triangles = {0, 1, 2, 0, 1, 2};
    folded.halfedges = {-1, 5, -1, -1, 2, 1};
    folded.hull = {0, 1, 2};
    folded.representative = {0, 1, 2};
    const std::vector<double> queries = {5, 5, 0.25, 0.25};
    const hullkit::DelaunayQueries found = hullkit::delaunay_locate(xy, folded, queries);
    REQUIRE(found.ok());
    REQUIRE(found.triangle == std::vector<std::int32_t>{-1, 0});
}

TEST_CASE("delaunay_gradients: exact for linear values, close for smooth ones, repeated points share, errors", "[query]") {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> xy;
    for (int i = 0; i < 3000; ++i) xy.insert(xy.end(), {u(rng), u(rng)});
    xy.insert(xy.end(), {xy[10], xy[11]});  // point 3000 repeats point 5
    const std::size_t n = xy.size() / 2;
    const Delaunay d = hullkit::delaunay(xy);
    // Two columns: a plane, and a smooth function.
    std::vector<double> values(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = xy[2 * i], y = xy[2 * i + 1];
        values[2 * i] = 3 + 3 * x + 14.15 * y;
        values[2 * i + 1] = std::sin(2 * x) * std::cos(3 * y);
    }
    values[2 * (n - 1)] = 1e300;  // a repeated point's value is not used
    hullkit::GradientOptions options;
    options.tolerance = 1e-13;
    options.max_iterations = 5000;
    const hullkit::DelaunayGradients g = hullkit::delaunay_gradients(xy, d, values.data(), 2, options);
    REQUIRE(g.ok());
    REQUIRE(g.converged);
    INFO("sweeps: " << g.iterations);
    double plane = 0, smooth = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = xy[2 * i], y = xy[2 * i + 1];
        plane = std::max({plane, std::fabs(g.gradients[4 * i] - 3), std::fabs(g.gradients[4 * i + 1] - 14.15)});
        if (x > 0.1 && x < 0.9 && y > 0.1 && y < 0.9) {  // away from the boundary's one-sided estimates
            smooth = std::max({smooth, std::fabs(g.gradients[4 * i + 2] - 2 * std::cos(2 * x) * std::cos(3 * y)),
                               std::fabs(g.gradients[4 * i + 3] + 3 * std::sin(2 * x) * std::sin(3 * y))});
        }
    }
    CHECK(plane < 1e-9);
    CHECK(smooth < 0.1);
    REQUIRE(g.gradients[4 * (n - 1)] == g.gradients[4 * 5]);
    REQUIRE(g.gradients[4 * (n - 1) + 3] == g.gradients[4 * 5 + 3]);
    // The default tolerance stops early, with the plane still close.
    const hullkit::DelaunayGradients quick = hullkit::delaunay_gradients(xy, d, values.data(), 2);
    REQUIRE(quick.converged);
    REQUIRE(quick.iterations < g.iterations);
    REQUIRE(std::fabs(quick.gradients[0] - 3) < 1e-3);
    options.max_iterations = 2;
    REQUIRE_FALSE(hullkit::delaunay_gradients(xy, d, values.data(), 2, options).converged);
    values[3] = std::nan("");
    const hullkit::DelaunayGradients bad = hullkit::delaunay_gradients(xy, d, values.data(), 2);
    REQUIRE(bad.error == "the value of point 1 (column 1) is not finite");
    const std::vector<double> line = {0, 0, 1, 1, 2, 2};
    const std::vector<double> line_values = {1, 2, 3};
    const hullkit::DelaunayGradients flat = hullkit::delaunay_gradients(line, hullkit::delaunay(line), line_values.data(), 1);
    REQUIRE(flat.ok());
    REQUIRE(flat.gradients == std::vector<double>(6, 0.0));
}

TEST_CASE("delaunay_voronoi: cells are the points nearest to their site", "[query]") {
    const std::vector<double> xy = grid_with_random(31);
    const Delaunay d = hullkit::delaunay(xy);
    const double xmin = -1, ymin = -2, xmax = 11, ymax = 10.5;
    const hullkit::VoronoiCells cells = hullkit::delaunay_voronoi(xy, d, xmin, ymin, xmax, ymax);
    const std::size_t n = xy.size() / 2;
    REQUIRE(cells.cell_offsets.size() == n + 1);
    double total_area = 0;
    std::size_t bad = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t begin = cells.cell_offsets[i], end = cells.cell_offsets[i + 1];
        if (d.representative[i] != i) {
            bad += begin != end;  // duplicates get no cell
            continue;
        }
        REQUIRE(end - begin >= 3);
        double area = 0;
        double cx = 0, cy = 0;
        for (std::uint32_t k = begin; k < end; ++k) {
            const std::uint32_t l = k + 1 == end ? begin : k + 1;
            const double x0 = cells.cell_xy[2 * k], y0 = cells.cell_xy[2 * k + 1];
            const double x1 = cells.cell_xy[2 * l], y1 = cells.cell_xy[2 * l + 1];
            area += x0 * y1 - x1 * y0;
            cx += x0, cy += y0;
            // Every corner: inside the rectangle, and no site nearer than this cell's site (up to
            // rounding of the clipped coordinates).
            bad += x0 < xmin - 1e-9 || x0 > xmax + 1e-9 || y0 < ymin - 1e-9 || y0 > ymax + 1e-9;
            const double own = std::hypot(x0 - xy[2 * i], y0 - xy[2 * i + 1]);
            for (std::size_t j = 0; j < n; ++j) bad += std::hypot(x0 - xy[2 * j], y0 - xy[2 * j + 1]) < own - 1e-9;
        }
        bad += area <= 0;  // counter-clockwise, y up
        total_area += area / 2;
        // The site lies in its cell: the corner average is nearer to it than to any other site.
        cx /= end - begin, cy /= end - begin;
        const std::int64_t nearest = brute_nearest(xy, cx, cy);
        bad += nearest != static_cast<std::int64_t>(i) &&
               std::fabs(std::hypot(cx - xy[2 * nearest], cy - xy[2 * nearest + 1]) -
                         std::hypot(cx - xy[2 * i], cy - xy[2 * i + 1])) > 1e-9;
    }
    REQUIRE(bad == 0);
    // The cells tile the rectangle.
    REQUIRE(total_area == Approx((xmax - xmin) * (ymax - ymin)).epsilon(1e-9));
}

TEST_CASE("delaunay_voronoi: collinear points give slabs, one point the rectangle", "[query]") {
    const std::vector<double> line = {0, 0, 2, 0, 1, 0};
    const hullkit::VoronoiCells slabs = hullkit::delaunay_voronoi(line, hullkit::delaunay(line), -1, -1, 3, 1);
    REQUIRE(slabs.cell_offsets == std::vector<std::uint32_t>{0, 4, 8, 12});
    const std::vector<double> one = {0.5, 0.5};
    const hullkit::VoronoiCells all = hullkit::delaunay_voronoi(one, hullkit::delaunay(one), 0, 0, 1, 1);
    REQUIRE(all.cell_xy == std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1});
}

namespace {

/// The whole diagram against its definition, independently of delaunay_voronoi_diagram's code:
/// a vertex per exactly cocircular group of triangles (GMP incircle across every interior edge),
/// each ridge a Delaunay edge between two groups (or on the hull), each cell the groups around its
/// point counter-clockwise, and each bounded cell equal to the cell clipped by bisectors
/// (delaunay_voronoi) in a rectangle holding it: the same corners and area up to rounding.
void check_voronoi_diagram(const std::vector<double>& xy, const Delaunay& d, const hullkit::VoronoiDiagram& v) {
    REQUIRE(v.ok());
    const std::size_t n = xy.size() / 2, triangles = d.triangle_count();
    REQUIRE(v.triangle_vertex.size() == triangles);
    REQUIRE(v.point_cell.size() == n);
    const std::size_t cell_count = v.cell_point.size();
    REQUIRE(v.cell_offsets.size() == cell_count + 1);
    REQUIRE(v.areas.size() == cell_count);
    REQUIRE(v.cell_offsets.back() == static_cast<std::int64_t>(v.cells.size()));
    std::size_t bad = 0;
    // Groups: same vertex across an interior edge exactly when the four corners are cocircular;
    // numbered by first triangle.
    std::uint32_t next_new = 0;
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t g = v.triangle_vertex[t];
        if (g == next_new) ++next_new;
        bad += g > next_new;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::int32_t h = d.halfedges[3 * t + k];
            if (h < 0) continue;
            const double* a = &xy[2 * d.triangles[3 * t]];
            const double* b = &xy[2 * d.triangles[3 * t + 1]];
            const double* c = &xy[2 * d.triangles[3 * t + 2]];
            const double* o = &xy[2 * d.triangles[3 * (h / 3) + (h % 3 + 2) % 3]];
            const bool cocircular = delaunay_test::gmp_incircle(a[0], a[1], b[0], b[1], c[0], c[1], o[0], o[1]) == 0;
            bad += cocircular != (g == v.triangle_vertex[static_cast<std::size_t>(h) / 3]);
        }
    }
    REQUIRE(bad == 0);
    REQUIRE(v.vertices.size() == 2 * std::size_t{next_new});
    // Every vertex is equidistant (to rounding) from the corners of its triangles.
    for (std::size_t t = 0; t < triangles; ++t) {
        const double* c = &v.vertices[2 * v.triangle_vertex[t]];
        const double* a = &xy[2 * d.triangles[3 * t]];
        const double r = std::hypot(c[0] - a[0], c[1] - a[1]);
        for (int k = 1; k < 3; ++k) {
            const double* b = &xy[2 * d.triangles[3 * t + k]];
            bad += std::fabs(std::hypot(c[0] - b[0], c[1] - b[1]) - r) > 1e-9 * (1 + r);
        }
    }
    // Ridges: each undirected Delaunay edge between different groups (or on the hull) once.
    std::set<std::pair<std::int32_t, std::int32_t>> expected, got;
    for (std::size_t e = 0; e < d.triangles.size(); ++e) {
        const std::int32_t h = d.halfedges[e];
        if (h >= 0 && v.triangle_vertex[e / 3] == v.triangle_vertex[static_cast<std::size_t>(h) / 3]) continue;
        const auto a = static_cast<std::int32_t>(d.triangles[e]), b = static_cast<std::int32_t>(d.triangles[delaunay_test::next_edge(e)]);
        expected.emplace(std::min(a, b), std::max(a, b));
    }
    const std::size_t ridges = v.ridge_points.size() / 2;
    REQUIRE(v.ridge_vertices.size() == 2 * ridges);
    for (std::size_t r = 0; r < ridges; ++r) {
        got.emplace(v.ridge_points[2 * r], v.ridge_points[2 * r + 1]);
        bad += v.ridge_points[2 * r] >= v.ridge_points[2 * r + 1];
        bad += v.ridge_vertices[2 * r + 1] < 0 || v.ridge_vertices[2 * r] == v.ridge_vertices[2 * r + 1];
    }
    REQUIRE(got.size() == ridges);
    REQUIRE(got == expected);
    // Cells against the clipped ones in a rectangle holding every vertex.
    double lo[2] = {0, 0}, hi[2] = {0, 0};
    for (std::size_t i = 0; i < v.vertices.size(); ++i) {
        lo[i % 2] = std::min(lo[i % 2], v.vertices[i]), hi[i % 2] = std::max(hi[i % 2], v.vertices[i]);
    }
    for (std::size_t i = 0; i < xy.size(); ++i) lo[i % 2] = std::min(lo[i % 2], xy[i]), hi[i % 2] = std::max(hi[i % 2], xy[i]);
    const hullkit::VoronoiCells clipped = hullkit::delaunay_voronoi(xy, d, lo[0] - 1, lo[1] - 1, hi[0] + 1, hi[1] + 1);
    std::size_t distinct = 0;
    for (std::size_t s = 0; s < n; ++s) {
        const auto cell = static_cast<std::size_t>(v.point_cell[s]);
        REQUIRE(cell < cell_count);
        if (d.representative[s] != s) {
            bad += v.point_cell[s] != v.point_cell[d.representative[s]];
            continue;
        }
        ++distinct;
        bad += v.cell_point[cell] != s;
        const auto begin = static_cast<std::size_t>(v.cell_offsets[cell]), end = static_cast<std::size_t>(v.cell_offsets[cell + 1]);
        REQUIRE(end > begin);
        const double area = v.areas[cell];
        const bool open = v.cells[end - 1] == -1;
        bad += open != std::isinf(area);
        // Distinct groups around s, counter-clockwise: a bounded cell from its lowest vertex.
        std::set<std::int32_t> around;
        for (std::size_t e = 0; e < d.triangles.size(); ++e)
            if (d.triangles[e] == s) around.insert(static_cast<std::int32_t>(v.triangle_vertex[e / 3]));
        const std::set<std::int32_t> listed(v.cells.begin() + static_cast<std::ptrdiff_t>(begin),
                                            v.cells.begin() + static_cast<std::ptrdiff_t>(end - (open ? 1 : 0)));
        bad += listed != around || listed.size() != end - begin - (open ? 1 : 0);
        if (open) continue;
        bad += v.cells[begin] != *listed.begin();
        double twice = 0;
        for (std::size_t k = begin; k < end; ++k) {
            const double* u = &v.vertices[2 * static_cast<std::size_t>(v.cells[k])];
            const double* w = &v.vertices[2 * static_cast<std::size_t>(v.cells[k + 1 == end ? begin : k + 1])];
            twice += u[0] * w[1] - u[1] * w[0];
        }
        bad += !(twice > 0) || std::fabs(twice / 2 - area) > 1e-9 * (1 + std::fabs(area));
        double clipped_twice = 0;
        const std::uint32_t cb = clipped.cell_offsets[s], ce = clipped.cell_offsets[s + 1];
        for (std::uint32_t k = cb; k < ce; ++k) {
            const std::uint32_t l = k + 1 == ce ? cb : k + 1;
            clipped_twice += clipped.cell_xy[2 * k] * clipped.cell_xy[2 * l + 1] - clipped.cell_xy[2 * l] * clipped.cell_xy[2 * k + 1];
            // Each clipped corner is one of the cell's vertices.
            double nearest = INFINITY;
            for (std::size_t j = begin; j < end; ++j) {
                const double* u = &v.vertices[2 * static_cast<std::size_t>(v.cells[j])];
                nearest = std::min(nearest, std::hypot(u[0] - clipped.cell_xy[2 * k], u[1] - clipped.cell_xy[2 * k + 1]));
            }
            bad += nearest > 1e-7;
        }
        bad += std::fabs(clipped_twice / 2 - area) > 1e-7 * (1 + std::fabs(area));
    }
    REQUIRE(distinct == cell_count);
    REQUIRE(bad == 0);
}

}  // namespace

TEST_CASE("delaunay_voronoi_diagram: vertices per cocircular group, ridges, cells and areas, any thread count", "[query]") {
    std::vector<std::vector<double>> inputs = {grid_with_random(5), grid_with_random(6)};
    {  // a 12 x 9 grid (every square one vertex at its centre, interior cells of area 1)
        std::vector<double> grid;
        for (int j = 0; j < 9; ++j)
            for (int i = 0; i < 12; ++i) grid.insert(grid.end(), {double((i * 7) % 12), double(j)});
        inputs.push_back(grid);
    }
    {  // the twelve lattice points of x^2 + y^2 = 25 (exactly cocircular: one 12-gon) and three outside
        std::vector<double> ring = {7, 1, -6.5, 3, 0.5, -8};
        for (const auto& [x, y] : std::vector<std::pair<double, double>>{
                 {5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}})
            ring.insert(ring.end(), {x, y});
        inputs.push_back(ring);
    }
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> many;
    // (10 000 under the sanitizers, tests/sanitized.hpp: still several chunks of triangles.)
    for (int k = 0; k < (hullkit_test::kSanitized ? 10000 : 40000); ++k) many.insert(many.end(), {u(rng), u(rng)});
    for (int j = 0; j < 60; ++j)
        for (int i = 0; i < 60; ++i) many.insert(many.end(), {2 + i / 16.0, j / 16.0});  // a grid beside them
    for (std::size_t input = 0; input < inputs.size(); ++input) {
        INFO("input " << input);
        const std::vector<double>& xy = inputs[input];
        const Delaunay d = hullkit::delaunay(xy);
        check_voronoi_diagram(xy, d, hullkit::delaunay_voronoi_diagram(xy, d, 1));
    }
    // The 12 x 9 grid: one vertex per square, at its centre exactly; every interior cell of area 1.
    const std::vector<double>& grid = inputs[2];
    const hullkit::VoronoiDiagram g = hullkit::delaunay_voronoi_diagram(grid, hullkit::delaunay(grid));
    REQUIRE(g.vertices.size() == 2 * 11 * 8);
    for (std::size_t k = 0; k < g.vertices.size(); ++k) REQUIRE(g.vertices[k] - std::floor(g.vertices[k]) == 0.5);
    std::size_t unit = 0;
    for (double a : g.areas) unit += a == 1.0;
    REQUIRE(unit == 10 * 7);
    // The circle: its twelve lattice points share one vertex, at (0, 0); 5 vertices in all (the
    // 12-gon and the four triangles between it and the three points outside).
    const std::vector<double>& ring = inputs[3];
    const hullkit::VoronoiDiagram c = hullkit::delaunay_voronoi_diagram(ring, hullkit::delaunay(ring));
    std::set<std::int32_t> shared;
    for (std::size_t s = 3; s < 15; ++s) {
        const auto k = static_cast<std::size_t>(c.point_cell[s]);
        std::set<std::int32_t> cell(c.cells.begin() + c.cell_offsets[k], c.cells.begin() + c.cell_offsets[k + 1]);
        if (s == 3) shared = cell;
        std::set<std::int32_t> both;
        for (std::int32_t x : cell) if (shared.count(x)) both.insert(x);
        shared = both;
    }
    REQUIRE(shared.size() == 1);
    const double* centre = &c.vertices[2 * static_cast<std::size_t>(*shared.begin())];
    REQUIRE(std::hypot(centre[0], centre[1]) < 1e-12);
    // Identical arrays for every thread count, on a larger input with a grid in it.
    const Delaunay d = hullkit::delaunay(many);
    const hullkit::VoronoiDiagram one = hullkit::delaunay_voronoi_diagram(many, d, 1);
    check_voronoi_diagram(many, d, one);
    for (unsigned threads : {2u, 3u, 8u, 0u}) {
        const hullkit::VoronoiDiagram other = hullkit::delaunay_voronoi_diagram(many, d, threads);
        REQUIRE(other.vertices == one.vertices);
        REQUIRE(other.triangle_vertex == one.triangle_vertex);
        REQUIRE(other.ridge_points == one.ridge_points);
        REQUIRE(other.ridge_vertices == one.ridge_vertices);
        REQUIRE(other.cells == one.cells);
        REQUIRE(other.cell_offsets == one.cell_offsets);
        REQUIRE(other.cell_point == one.cell_point);
        REQUIRE(other.point_cell == one.point_cell);
        REQUIRE(std::memcmp(other.areas.data(), one.areas.data(), one.areas.size() * sizeof(double)) == 0);
    }
}

TEST_CASE("delaunay_voronoi_diagram: collinear points, one point, repeated points, errors", "[query]") {
    const std::vector<double> line = {0, 0, 2, 0, 1, 0, 2, 0};
    const hullkit::VoronoiDiagram l = hullkit::delaunay_voronoi_diagram(line, hullkit::delaunay(line));
    REQUIRE(l.ok());
    REQUIRE(l.vertices.empty());
    REQUIRE(l.ridge_points == std::vector<std::int32_t>{0, 2, 1, 2});
    REQUIRE(l.ridge_vertices == std::vector<std::int32_t>{-1, -1, -1, -1});
    REQUIRE(l.cells == std::vector<std::int32_t>{-1, -1, -1});
    REQUIRE(l.cell_offsets == std::vector<std::int64_t>{0, 1, 2, 3});
    REQUIRE(l.point_cell == std::vector<std::int32_t>{0, 1, 2, 1});
    REQUIRE(std::isinf(l.areas[2]));
    const std::vector<double> one = {0.5, 0.5};
    const hullkit::VoronoiDiagram o = hullkit::delaunay_voronoi_diagram(one, hullkit::delaunay(one));
    REQUIRE(o.cells == std::vector<std::int32_t>{-1});
    REQUIRE(o.ridge_points.empty());
    // A triangle: one vertex, three rays, three open cells.
    const std::vector<double> tri = {0, 0, 4, 0, 0, 4, 0, 0};
    const hullkit::VoronoiDiagram t = hullkit::delaunay_voronoi_diagram(tri, hullkit::delaunay(tri));
    REQUIRE(t.vertices == std::vector<double>{2, 2});
    REQUIRE(t.ridge_vertices == std::vector<std::int32_t>{-1, 0, -1, 0, -1, 0});
    REQUIRE(t.cells == std::vector<std::int32_t>{0, -1, 0, -1, 0, -1});
    REQUIRE(t.cell_offsets == std::vector<std::int64_t>{0, 2, 4, 6});
    REQUIRE(t.point_cell[3] == t.point_cell[0]);
    // Errors: a failed triangulation, and one of other points.
    const std::vector<double> nan = {0, 0, 1, 0, NAN, 1};
    REQUIRE_FALSE(hullkit::delaunay_voronoi_diagram(nan, hullkit::delaunay(nan)).ok());
    const hullkit::VoronoiDiagram other = hullkit::delaunay_voronoi_diagram(one, hullkit::delaunay(tri));
    REQUIRE_FALSE(other.ok());
    REQUIRE(other.error.find("not one of these 1 points") != std::string::npos);
}

TEST_CASE("verify_delaunay: rejects broken triangulations", "[verify]") {
    // The unit square split along the diagonal 0-2 with a point near the other diagonal's circle.
    const std::vector<double> xy = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    const Delaunay d = hullkit::delaunay(xy);
    REQUIRE(hullkit::verify_delaunay(xy, d.triangles.data(), d.triangle_count()).ok);
    auto bad = [&](std::vector<std::uint32_t> tris, const std::string& what) {
        const hullkit::DelaunayVerifyReport r = hullkit::verify_delaunay(xy, tris.data(), tris.size() / 3);
        INFO(what);
        REQUIRE_FALSE(r.ok);
        REQUIRE(r.problem_count > 0);
        REQUIRE_FALSE(r.problems.empty());
    };
    std::vector<std::uint32_t> flipped = d.triangles;
    std::swap(flipped[1], flipped[2]);
    bad(flipped, "counter-clockwise triangle");
    bad(std::vector<std::uint32_t>(d.triangles.begin(), d.triangles.end() - 3), "missing triangle");
    bad({0, 3, 2, 0, 2, 1}, "point 4 unused");
    std::vector<std::uint32_t> out_of_range = d.triangles;
    out_of_range[0] = 9;
    bad(out_of_range, "index out of range");
    // Not Delaunay: a quadrilateral with the wrong diagonal.
    const std::vector<double> quad = {0, 0, 2, -0.2, 4, 0, 2, 3};
    const std::vector<std::uint32_t> wrong = {0, 3, 1, 1, 3, 2};  // diagonal 1-3 is legal? check both
    const std::vector<std::uint32_t> other = {0, 3, 2, 0, 2, 1};
    const bool first_ok = hullkit::verify_delaunay(quad, wrong.data(), 2).ok;
    const bool second_ok = hullkit::verify_delaunay(quad, other.data(), 2).ok;
    REQUIRE(first_ok != second_ok);  // exactly one diagonal of a non-cocircular quad is Delaunay
    const Delaunay dq = hullkit::delaunay(quad);
    REQUIRE((first_ok ? wrong : other) == dq.triangles);
}
