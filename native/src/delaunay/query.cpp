// Queries on a finished triangulation: nearest input point by walking (delaunay_find,
// DelaunayLocator) and Voronoi cells clipped to a rectangle (delaunay_voronoi).
#include <algorithm>
#include <cmath>
#include <limits>

#include "hullkit/delaunay.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit {
namespace {

inline std::size_t next_edge(std::size_t e) { return e % 3 == 2 ? e - 2 : e + 1; }
inline std::size_t prev_edge(std::size_t e) { return e % 3 == 0 ? e + 2 : e - 1; }

/// Per point a half-edge leaving it (collinear input: its position in `hull`), a hull half-edge where there is one, so that turning from it
/// (see for_each_neighbour) meets every neighbour.
std::vector<std::int32_t> outgoing_edges(std::size_t point_count, const Delaunay& d) {
    std::vector<std::int32_t> out(point_count, -1);
    if (d.dimension == 1) {  // collinear: each point's position along the line instead
        for (std::size_t k = 0; k < d.hull.size(); ++k) out[d.hull[k]] = static_cast<std::int32_t>(k);
        return out;
    }
    for (std::size_t e = 0; e < d.triangles.size(); ++e) {
        const std::uint32_t u = d.triangles[e];
        if (out[u] == -1 || d.halfedges[e] == -1) out[u] = static_cast<std::int32_t>(e);
    }
    return out;
}

/// Calls f(v) for every Delaunay neighbour v of point u (dimension 2: around u's triangles;
/// dimension 1: the points before and after u along the line).
template <class F>
void for_each_neighbour(const Delaunay& d, const std::vector<std::int32_t>& outgoing, std::uint32_t u, F f) {
    if (d.dimension < 2) {
        if (d.dimension != 1 || outgoing[u] < 0) return;
        const std::size_t k = static_cast<std::size_t>(outgoing[u]);
        if (k > 0) f(d.hull[k - 1]);
        if (k + 1 < d.hull.size()) f(d.hull[k + 1]);
        return;
    }
    const std::int32_t first = outgoing[u];
    if (first < 0) return;
    std::int32_t e = first;
    for (;;) {
        f(d.triangles[next_edge(static_cast<std::size_t>(e))]);
        const std::size_t incoming = prev_edge(static_cast<std::size_t>(e));
        const std::int32_t turned = d.halfedges[incoming];
        if (turned == -1) {  // reached the hull: the incoming edge's start is the last neighbour
            f(d.triangles[incoming]);
            return;
        }
        if (turned == first) return;
        e = turned;
    }
}

/// The power of two delaunay() scales these points by before its exact tests (0 when they are in
/// range): distances are compared on the same scaled coordinates, where squares neither underflow
/// nor overflow. (Points outside every scale were refused by delaunay(); 0 then.)
int scale_exponent(PointSpan2 p) {
    double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.count; ++i) {
        for (int axis = 0; axis < 2; ++axis) {
            const double m = std::fabs(p[i][axis]);
            if (!(m <= std::numeric_limits<double>::max())) return 0;
            largest = std::max(largest, m);
            if (m != 0.0) smallest = std::min(smallest, m);
        }
    }
    int exponent = 0;
    if (!incircle_range_ok(largest, smallest) && !incircle_scale_exponent(largest, smallest, &exponent)) return 0;
    return exponent;
}

/// Greedy walk to the nearest point, then the lowest index among the exactly equidistant ones
/// (they lie on one empty circle, so they are connected by Delaunay edges). Coordinates are
/// scaled by 2^exponent (exact) before each comparison.
std::int64_t walk_to_nearest(PointSpan2 p, const Delaunay& d, const std::vector<std::int32_t>& outgoing,
                             std::uint32_t current, double x, double y, int exponent) {
    const auto s = [exponent](double v) { return exponent == 0 ? v : std::ldexp(v, exponent); };
    x = s(x), y = s(y);
    const auto compare = [&](std::uint32_t a, std::uint32_t b) {
        return compare_distance(s(p[a][0]), s(p[a][1]), s(p[b][0]), s(p[b][1]), x, y);
    };
    for (;;) {
        std::uint32_t best = current;
        for_each_neighbour(d, outgoing, current, [&](std::uint32_t v) {
            const int c = compare(v, best);
            if (c < 0 || (c == 0 && v < best)) best = v;
        });
        if (best == current) break;
        current = best;
    }
    std::vector<std::uint32_t> tied{current};
    std::uint32_t lowest = current;
    for (std::size_t k = 0; k < tied.size(); ++k) {
        for_each_neighbour(d, outgoing, tied[k], [&](std::uint32_t v) {
            if (compare(v, current) != 0) return;
            if (std::find(tied.begin(), tied.end(), v) != tied.end()) return;
            tied.push_back(v);
            lowest = std::min(lowest, v);
        });
    }
    return lowest;
}

std::uint32_t start_point(const Delaunay& d, std::int64_t start) {
    if (start >= 0 && static_cast<std::size_t>(start) < d.representative.size())
        return d.representative[static_cast<std::size_t>(start)];
    return d.hull.front();
}

}  // namespace

DelaunayLocator::DelaunayLocator(PointSpan2 points, const Delaunay& triangulation)
    : points_(points),
      triangulation_(triangulation),
      outgoing_(outgoing_edges(points.count, triangulation)),
      exponent_(scale_exponent(points)) {}

std::int64_t DelaunayLocator::find(double x, double y, std::int64_t start) {
    if (triangulation_.hull.empty()) return -1;
    const std::uint32_t from = start_point(triangulation_, start >= 0 ? start : last_);
    last_ = walk_to_nearest(points_, triangulation_, outgoing_, from, x, y, exponent_);
    return last_;
}

std::int64_t delaunay_find(PointSpan2 points, const Delaunay& triangulation, double x, double y,
                           std::uint32_t start) {
    DelaunayLocator locator(points, triangulation);
    return locator.find(x, y, start);
}

VoronoiCells delaunay_voronoi(PointSpan2 p, const Delaunay& d, double xmin, double ymin, double xmax,
                              double ymax) {
    VoronoiCells cells;
    cells.cell_offsets.assign(1, 0);
    const std::vector<std::int32_t> outgoing = outgoing_edges(p.count, d);
    std::vector<double> polygon, clipped;
    for (std::size_t i = 0; i < p.count; ++i) {
        const bool is_site = d.ok() && d.dimension >= 0 && i < d.representative.size() && d.representative[i] == i;
        if (is_site && xmin <= xmax && ymin <= ymax) {
            polygon = {xmin, ymin, xmax, ymin, xmax, ymax, xmin, ymax};
            const double px = p[i][0], py = p[i][1];
            // Keep the half-plane of points at least as near to i as to v: (z - m) . (v - i) <= 0,
            // m the midpoint (Sutherland-Hodgman, one bisector at a time).
            for_each_neighbour(d, outgoing, static_cast<std::uint32_t>(i), [&](std::uint32_t v) {
                const double nx = p[v][0] - px, ny = p[v][1] - py;
                const double mx = 0.5 * (p[v][0] + px), my = 0.5 * (p[v][1] + py);
                clipped.clear();
                const std::size_t m = polygon.size() / 2;
                for (std::size_t k = 0; k < m; ++k) {
                    const double ax = polygon[2 * k], ay = polygon[2 * k + 1];
                    const double bx = polygon[2 * ((k + 1) % m)], by = polygon[2 * ((k + 1) % m) + 1];
                    const double sa = (ax - mx) * nx + (ay - my) * ny;
                    const double sb = (bx - mx) * nx + (by - my) * ny;
                    if (sa <= 0) clipped.insert(clipped.end(), {ax, ay});
                    if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) {
                        const double t = sa / (sa - sb);
                        clipped.insert(clipped.end(), {ax + t * (bx - ax), ay + t * (by - ay)});
                    }
                }
                polygon.swap(clipped);
            });
            if (polygon.size() >= 6) cells.cell_xy.insert(cells.cell_xy.end(), polygon.begin(), polygon.end());
        }
        cells.cell_offsets.push_back(static_cast<std::uint32_t>(cells.cell_xy.size() / 2));
    }
    return cells;
}

}  // namespace hullkit
