// verify_delaunay: an exact check of a triangulation, independent of how it was built. It uses only
// the triangles and the points (not half-edges or hull from the algorithms), exact orient2d and
// incircle, and sorting; see delaunay.hpp for the list of properties.
//
// Why these properties suffice: consistently oriented triangles whose edges are each shared by at
// most two triangles (in opposite directions) form an oriented surface; with one boundary cycle
// that is convex and winds once, no lost point and the Euler count T = 2n - h - 2, the surface is a
// triangulation of the convex hull; and a triangulation whose every interior edge passes the
// empty-circle test is Delaunay (Delaunay's lemma: locally Delaunay implies globally Delaunay).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "delaunay_internal.hpp"
#include "hullkit/delaunay.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit {
namespace {

constexpr std::size_t kMaxListedProblems = 40;

struct Reporter {
    DelaunayVerifyReport& report;
    void operator()(const std::string& message) {
        report.ok = false;
        if (report.problems.size() < kMaxListedProblems) report.problems.push_back(message);
        ++report.problem_count;
    }
};

std::string tri_text(std::size_t t, const std::uint32_t* v) {
    return "triangle " + std::to_string(t) + " (" + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " +
           std::to_string(v[2]) + ")";
}

}  // namespace

DelaunayVerifyReport verify_delaunay(PointSpan2 points, const std::uint32_t* input_triangles, std::size_t triangle_count) {
    DelaunayVerifyReport report;
    Reporter problem{report};
    const std::size_t n_points = points.count;
    for (std::size_t e = 0; e < 3 * triangle_count; ++e) {
        if (input_triangles[e] >= n_points) {
            problem("triangle " + std::to_string(e / 3) + " has index " + std::to_string(input_triangles[e]) +
                    " but there are " + std::to_string(n_points) + " points");
        }
    }
    if (!report.ok) return report;

    // The same exact power-of-two rescaling as delaunay(), so the predicates stay exact.
    double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < 2 * n_points; ++i) {
        const double m = std::fabs(points.xy[i]);
        if (!(m <= std::numeric_limits<double>::max())) {
            problem("point " + std::to_string(i / 2) + " has a non-finite coordinate");
            return report;
        }
        largest = std::max(largest, m);
        if (m != 0.0) smallest = std::min(smallest, m);
    }
    int exponent = 0;
    if (!incircle_range_ok(largest, smallest) && !incircle_scale_exponent(largest, smallest, &exponent)) {
        problem("coordinates span too many orders of magnitude for exact in-circle tests");
        return report;
    }
    std::vector<double> scaled;
    PointSpan2 p = points;
    if (exponent != 0) {
        scaled.resize(2 * n_points);
        for (std::size_t i = 0; i < scaled.size(); ++i) scaled[i] = std::ldexp(points.xy[i], exponent);
        p = PointSpan2(scaled.data(), n_points);
    }

    // Distinct points: each index stands for the lowest index with the same coordinates.
    std::vector<std::uint32_t> order(n_points);
    std::iota(order.begin(), order.end(), 0u);
    std::vector<std::uint32_t> rep(n_points);
    const std::vector<std::uint32_t> distinct = delaunay_detail::lowest_copies(p, std::move(order), rep);
    report.distinct_points = distinct.size();
    std::vector<std::uint32_t> tri(3 * triangle_count);
    for (std::size_t e = 0; e < tri.size(); ++e) tri[e] = rep[input_triangles[e]];
    auto pt = [&](std::uint32_t i) { return p[i]; };
    auto orient = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        return orient2d(pt(a)[0], pt(a)[1], pt(b)[0], pt(b)[1], pt(c)[0], pt(c)[1]);
    };

    if (triangle_count == 0) {
        // Correct only when the distinct points do not span the plane.
        for (std::size_t k = 2; k < distinct.size(); ++k) {
            if (orient(distinct[0], distinct[1], distinct[k]) != 0) {
                problem("no triangles, but the points are not all collinear (point " + std::to_string(distinct[k]) +
                        " is off the line through points " + std::to_string(distinct[0]) + " and " +
                        std::to_string(distinct[1]) + ")");
                break;
            }
        }
        return report;
    }

    for (std::size_t t = 0; t < triangle_count; ++t) {
        const int o = orient(tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]);
        if (o == 0) problem(tri_text(t, &input_triangles[3 * t]) + " is degenerate (zero area)");
        if (o > 0) problem(tri_text(t, &input_triangles[3 * t]) + " is counter-clockwise (y up); expected clockwise");
    }

    // Directed edges, sorted: each must be unique; an edge without its reverse is on the boundary.
    auto next = [](std::size_t e) { return e % 3 == 2 ? e - 2 : e + 1; };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> edges(tri.size());
    for (std::size_t e = 0; e < tri.size(); ++e) {
        edges[e] = {(std::uint64_t{tri[e]} << 32) | tri[next(e)], static_cast<std::uint32_t>(e)};
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t k = 1; k < edges.size(); ++k) {
        if (edges[k].first == edges[k - 1].first) {
            problem("edge " + std::to_string(edges[k].first >> 32) + "->" + std::to_string(edges[k].first & 0xffffffffu) +
                    " is used by two triangles in the same direction (overlap or duplicate)");
        }
    }
    auto find_edge = [&](std::uint32_t u, std::uint32_t v) -> std::int64_t {
        const std::uint64_t key = (std::uint64_t{u} << 32) | v;
        const auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(key, 0u));
        return it != edges.end() && it->first == key ? static_cast<std::int64_t>(it->second) : -1;
    };

    std::vector<std::uint32_t> successor(n_points, UINT32_MAX);
    std::vector<std::uint8_t> used(n_points, 0);
    std::size_t boundary = 0;
    std::uint32_t lowest_boundary = UINT32_MAX;
    for (std::size_t e = 0; e < tri.size(); ++e) {
        const std::uint32_t u = tri[e], v = tri[next(e)];
        used[u] = 1;
        const std::int64_t f = find_edge(v, u);
        if (f < 0) {
            ++boundary;
            if (successor[u] != UINT32_MAX) {
                problem("point " + std::to_string(u) + " starts two boundary edges (the boundary is not one simple cycle)");
            }
            successor[u] = v;
            lowest_boundary = std::min(lowest_boundary, u);
        } else if (u < v) {
            // Empty circle: the far corner of the neighbour must not be strictly inside the circle of
            // this triangle (u, v, w clockwise, so u, w, v counter-clockwise).
            const std::uint32_t w = tri[next(next(e))];
            const std::uint32_t x = tri[next(next(static_cast<std::size_t>(f)))];
            if (incircle(pt(u)[0], pt(u)[1], pt(w)[0], pt(w)[1], pt(v)[0], pt(v)[1], pt(x)[0], pt(x)[1]) > 0) {
                problem("edge " + std::to_string(u) + "-" + std::to_string(v) + " is not Delaunay: point " +
                        std::to_string(x) + " is strictly inside the circumcircle of triangle " + std::to_string(e / 3));
            }
        }
    }
    for (std::uint32_t i : distinct) {
        if (!used[i]) problem("point " + std::to_string(i) + " is not a vertex of any triangle");
    }

    // The boundary: one cycle through every boundary edge, turning only right (clockwise, y up) or
    // straight, and winding once (exactly one vertex lower in (x, y) order than both neighbours).
    std::size_t cycle = 0;
    std::size_t lowest_corners = 0;
    auto lex_less = [&](std::uint32_t a, std::uint32_t b) {
        return pt(a)[0] < pt(b)[0] || (pt(a)[0] == pt(b)[0] && pt(a)[1] < pt(b)[1]);
    };
    std::vector<std::uint32_t> hull;
    if (boundary > 0) {
        std::uint32_t v = lowest_boundary;
        do {
            hull.push_back(v);
            v = successor[v];
        } while (v != UINT32_MAX && v != lowest_boundary && hull.size() <= boundary);
        cycle = hull.size();
        if (v != lowest_boundary || cycle != boundary) {
            problem("the boundary edges do not form one closed cycle (" + std::to_string(boundary) +
                    " boundary edges, cycle of " + std::to_string(cycle) + ")");
        } else {
            for (std::size_t k = 0; k < cycle; ++k) {
                const std::uint32_t a = hull[(k + cycle - 1) % cycle], b = hull[k], c = hull[(k + 1) % cycle];
                if (orient(a, b, c) > 0) {
                    problem("the boundary turns left at point " + std::to_string(b) + ": it is not the convex hull");
                }
                if (lex_less(b, a) && lex_less(b, c)) ++lowest_corners;
            }
            if (lowest_corners != 1) problem("the boundary winds around more than once");
        }
    } else {
        problem("the triangles have no boundary (every edge is shared)");
    }
    report.hull_points = cycle;
    const std::size_t expected = 2 * distinct.size() - cycle - 2;
    if (cycle > 0 && triangle_count != expected) {
        problem("triangle count " + std::to_string(triangle_count) + " but 2n - h - 2 = " + std::to_string(expected) +
                " for n = " + std::to_string(distinct.size()) + " distinct points and h = " + std::to_string(cycle) +
                " hull points");
    }
    if (report.problem_count > report.problems.size()) {
        report.problems.push_back("... and " + std::to_string(report.problem_count - report.problems.size()) +
                                  " more problems");
    }
    return report;
}

}  // namespace hullkit
