// libFuzzer target: hullkit::delaunay on arbitrary bytes read as 2D points. The first byte picks
// how the rest is read: (0) little-endian doubles x y (NaN, infinities, huge and tiny magnitudes);
// (1) int8 pairs (grids, collinear and cocircular sets, repeats); (2) int8 pairs scaled by 2^-30
// around (1e6, -1e6) (the same, exactly, far from the origin); (3) int16 pairs. Checked:
//  - a triangulation that is returned passes the exact verify_delaunay; the half-edges pair up
//    (halfedges[halfedges[e]] == e, the two half-edges running between the same points in opposite
//    directions); each point's representative is the lowest index with its coordinates;
//  - gift wrapping gives the very same arrays on small inputs, and so does merge_cocircular (each
//    of its polygons has 3 or more corners and starts at its lowest index);
//  - delaunay_find from varying starts answers a query at an input point with its representative
//    (at any scale), and, inside incircle's exact range, a query elsewhere with the nearest point
//    (exact compare_distance, lowest index on ties);
//  - delaunay_locate finds the lowest-indexed triangle holding each query (brute force), weights
//    exactly 1 at a corner, input points nearest to themselves, the same on 1 and 3 threads;
//  - delaunay_voronoi_diagram has a vertex per merge_cocircular polygon (the same corner sets), a
//    cell per distinct point, and the same arrays on 1 and 3 threads;
//  - an error is one line, with no triangulation.
// Built by scripts/fuzz.sh (clang++ -fsanitize=fuzzer,address,undefined).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "hullkit/delaunay.hpp"
#include "hullkit/predicates.hpp"
#include "points2d_bytes.hpp"

namespace {

std::vector<double> read_points(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return {};
    return fuzz_input::points2d(data + 1, size - 1, data[0] & 3);
}

bool same(const hullkit::Delaunay& a, const hullkit::Delaunay& b) {
    return a.dimension == b.dimension && a.triangles == b.triangles && a.halfedges == b.halfedges &&
           a.hull == b.hull && a.representative == b.representative && a.duplicate_count == b.duplicate_count &&
           a.error == b.error;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<double> xy = read_points(data, size);
    const std::size_t n = xy.size() / 2;
    if (n > 300) return 0;  // keeps each input fast; structure matters, not size
    const hullkit::PointSpan2 points(xy.data(), n);
    const hullkit::Delaunay tri = hullkit::delaunay(points);
    if (!tri.ok()) {
        if (tri.error.find('\n') != std::string::npos || !tri.triangles.empty() || !tri.halfedges.empty()) std::abort();
        if (tri.error_point >= static_cast<std::int64_t>(n)) std::abort();
        return 0;
    }
    if (n == 0 ? tri.dimension != -1 : tri.dimension < 0 || tri.dimension > 2) std::abort();
    if ((tri.dimension == 2) != !tri.triangles.empty()) std::abort();
    const hullkit::DelaunayVerifyReport report = hullkit::verify_delaunay(points, tri.triangles.data(), tri.triangle_count());
    if (!report.ok) std::abort();

    // Half-edges pair up with their opposites.
    if (tri.halfedges.size() != tri.triangles.size()) std::abort();
    auto next = [](std::size_t e) { return e % 3 == 2 ? e - 2 : e + 1; };
    for (std::size_t e = 0; e < tri.halfedges.size(); ++e) {
        const std::int32_t o = tri.halfedges[e];
        if (o == -1) continue;
        if (o < 0 || static_cast<std::size_t>(o) >= tri.halfedges.size() || tri.halfedges[o] != static_cast<std::int32_t>(e))
            std::abort();
        if (tri.triangles[e] != tri.triangles[next(o)] || tri.triangles[next(e)] != tri.triangles[o]) std::abort();
    }
    // Representatives: the lowest index with the same coordinates.
    if (tri.representative.size() != n) std::abort();
    std::size_t duplicates = 0;
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t lowest = i;
        for (std::size_t j = 0; j < i; ++j) {
            if (xy[2 * j] == xy[2 * i] && xy[2 * j + 1] == xy[2 * i + 1]) {
                lowest = j;
                break;
            }
        }
        if (tri.representative[i] != lowest) std::abort();
        duplicates += lowest != i;
    }
    if (duplicates != tri.duplicate_count) std::abort();

    // Every algorithm and option gives the same triangulation.
    hullkit::DelaunayOptions merged;
    merged.merge_cocircular = true;
    const hullkit::Delaunay polygons = hullkit::delaunay(points, merged);
    if (!same(polygons, tri)) std::abort();
    if (polygons.polygon_offsets.empty() ? tri.dimension == 2 : polygons.polygon_offsets.front() != 0 ||
                                                                   polygons.polygon_offsets.back() != polygons.polygon_vertices.size()) {
        std::abort();
    }
    for (std::size_t p = 0; p + 1 < polygons.polygon_offsets.size(); ++p) {
        const std::uint32_t first = polygons.polygon_offsets[p], last = polygons.polygon_offsets[p + 1];
        if (last < first + 3) std::abort();
        for (std::uint32_t k = first + 1; k < last; ++k) {  // starts at its lowest index
            if (polygons.polygon_vertices[k] <= polygons.polygon_vertices[first]) std::abort();
        }
    }
    // The whole Voronoi diagram: a vertex per Delaunay polygon (the corner sets of merge_cocircular's
    // polygons, found here by incircle across edges), a nonempty cell per distinct point, ridge
    // ends distinct points; the same arrays on 1 and 3 threads.
    const hullkit::VoronoiDiagram vor = hullkit::delaunay_voronoi_diagram(points, tri, 1);
    if (!vor.ok() || vor.point_cell.size() != n || vor.cell_offsets.size() != vor.cell_point.size() + 1) std::abort();
    if (tri.dimension == 2) {
        const std::size_t count = polygons.polygon_offsets.size() - 1;
        if (vor.vertices.size() != 2 * count || vor.triangle_vertex.size() != tri.triangle_count()) std::abort();
        std::vector<std::vector<std::uint32_t>> mine(count), theirs(count);
        for (std::size_t e = 0; e < tri.triangles.size(); ++e) {
            if (vor.triangle_vertex[e / 3] >= count) std::abort();
            mine[vor.triangle_vertex[e / 3]].push_back(tri.triangles[e]);
        }
        for (std::size_t p = 0; p < count; ++p) {
            std::sort(mine[p].begin(), mine[p].end());
            mine[p].erase(std::unique(mine[p].begin(), mine[p].end()), mine[p].end());
            theirs[p].assign(polygons.polygon_vertices.begin() + polygons.polygon_offsets[p],
                             polygons.polygon_vertices.begin() + polygons.polygon_offsets[p + 1]);
            std::sort(theirs[p].begin(), theirs[p].end());
        }
        std::sort(mine.begin(), mine.end());
        std::sort(theirs.begin(), theirs.end());
        if (mine != theirs) std::abort();
    }
    std::size_t cells = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto cell = static_cast<std::size_t>(vor.point_cell[i]);
        if (cell >= vor.cell_point.size() || vor.point_cell[i] != vor.point_cell[tri.representative[i]]) std::abort();
        if (tri.representative[i] != i) continue;
        ++cells;
        if (vor.cell_point[cell] != i || vor.cell_offsets[cell + 1] <= vor.cell_offsets[cell]) std::abort();
    }
    if (cells != vor.cell_point.size()) std::abort();
    for (std::size_t r = 0; r < vor.ridge_points.size(); r += 2) {
        const auto a = vor.ridge_points[r], b = vor.ridge_points[r + 1];
        if (a >= b || a < 0 || static_cast<std::size_t>(b) >= n || tri.representative[a] != static_cast<std::uint32_t>(a)) std::abort();
    }
    const hullkit::VoronoiDiagram three = hullkit::delaunay_voronoi_diagram(points, tri, 3);
    if (three.vertices.size() != vor.vertices.size() ||
        (!vor.vertices.empty() &&
         std::memcmp(three.vertices.data(), vor.vertices.data(), vor.vertices.size() * sizeof(double)) != 0) ||
        three.cells != vor.cells || three.cell_offsets != vor.cell_offsets || three.ridge_points != vor.ridge_points ||
        three.ridge_vertices != vor.ridge_vertices || three.point_cell != vor.point_cell) {
        std::abort();
    }
    if (n <= 60) {
        hullkit::DelaunayOptions wrap;
        wrap.algorithm = hullkit::DelaunayAlgorithm::Giftwrap;
        if (!same(hullkit::delaunay(points, wrap), tri)) std::abort();
    }

    // Nearest-point queries: at every input point (any scale: the locator compares distances on
    // the coordinates delaunay() rescaled), then against a brute force (inside the predicates'
    // exact range, where compare_distance on the raw coordinates is exact).
    if (n == 0 || n > 120) return 0;
    hullkit::DelaunayLocator locator(points, tri);
    for (std::size_t i = 0; i < n; ++i) {
        if (locator.find(xy[2 * i], xy[2 * i + 1], static_cast<std::int64_t>((i * 7) % n)) != tri.representative[i]) std::abort();
    }
    double largest = 0, smallest = 0;
    for (double v : xy) {
        const double a = std::fabs(v);
        largest = std::max(largest, a);
        if (a != 0 && (smallest == 0 || a < smallest)) smallest = a;
    }
    if (!hullkit::incircle_range_ok(largest, smallest)) return 0;
    // A query made of one point's x and another's y (inside the predicates' exact range).
    for (std::size_t k = 0; k < 4 && k < n; ++k) {
        const double qx = xy[2 * k], qy = xy[2 * (n - 1 - k) + 1];
        std::size_t best = 0;
        for (std::size_t i = 1; i < n; ++i) {
            if (hullkit::compare_distance(xy[2 * i], xy[2 * i + 1], xy[2 * best], xy[2 * best + 1], qx, qy) < 0) best = i;
        }
        if (hullkit::delaunay_find(points, tri, qx, qy, static_cast<std::uint32_t>(k)) != static_cast<std::int64_t>(best)) std::abort();
    }
    // delaunay_locate on the input points and the mixed queries: the lowest-indexed triangle
    // holding each (brute force, exact orient2d on the raw coordinates), weights exactly 1 at a
    // corner, the nearest point a query at an input point is its representative; the same
    // answers on 1 and 3 threads.
    std::vector<double> queries(xy);
    for (std::size_t k = 0; k < n; ++k) queries.insert(queries.end(), {xy[2 * k], xy[2 * (n - 1 - k) + 1]});
    hullkit::DelaunayQueryOptions options;
    options.barycentric = options.nearest = true;
    options.threads = 1;
    const hullkit::DelaunayQueries found = hullkit::delaunay_locate(points, tri, queries, options);
    options.threads = 3;
    const hullkit::DelaunayQueries again = hullkit::delaunay_locate(points, tri, queries, options);
    if (!found.ok() || again.triangle != found.triangle || again.nearest != found.nearest) std::abort();
    if (std::memcmp(again.barycentric.data(), found.barycentric.data(), 8 * found.barycentric.size()) != 0) std::abort();
    for (std::size_t i = 0; i < queries.size() / 2; ++i) {
        const double qx = queries[2 * i], qy = queries[2 * i + 1];
        std::int32_t lowest = -1;
        for (std::size_t t = 0; t < tri.triangle_count() && lowest < 0; ++t) {
            bool holds = true;
            for (int k = 0; k < 3 && holds; ++k) {
                const double* a = &xy[2 * tri.triangles[3 * t + k]];
                const double* b = &xy[2 * tri.triangles[3 * t + (k + 1) % 3]];
                holds = hullkit::orient2d(a[0], a[1], b[0], b[1], qx, qy) <= 0;
            }
            if (holds) lowest = static_cast<std::int32_t>(t);
        }
        if (found.triangle[i] != lowest) std::abort();
        if (i < n && found.nearest[i] != static_cast<std::int32_t>(tri.representative[i])) std::abort();
        if (i < n && lowest >= 0) {
            int ones = 0;
            for (int k = 0; k < 3; ++k) ones += found.barycentric[3 * i + k] == 1.0 && tri.representative[i] == tri.triangles[3 * lowest + k];
            if (ones != 1) std::abort();
        }
    }
    return 0;
}
