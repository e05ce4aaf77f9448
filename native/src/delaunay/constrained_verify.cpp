// verify_constrained: an exact check of a constrained triangulation from its arrays alone (see
// constrained.hpp). The argument is verify_delaunay's: consistently oriented triangles whose
// directed edges are all distinct form an oriented surface; with a convex boundary cycle that winds
// once and T = 2n - h - 2 it triangulates the hull; every unflagged interior edge passing the
// empty-circle test makes it constrained Delaunay for the flagged edges (the constrained form of
// Delaunay's lemma).
#include <algorithm>
#include <cmath>
#include <numeric>

#include "delaunay_internal.hpp"
#include "hullkit/constrained.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit {

ConstrainedVerifyReport verify_constrained(PointSpan2 coords, const std::uint32_t* triangles, std::size_t triangle_count,
                                           const std::int32_t* halfedges, const std::uint8_t* constrained,
                                           bool boundary_constrained) {
    ConstrainedVerifyReport report;
    auto problem = [&](const std::string& message) {
        report.ok = false;
        if (report.problems.size() < 40) report.problems.push_back(message);
        ++report.problem_count;
    };
    const std::size_t edges = 3 * triangle_count;
    for (std::size_t e = 0; e < edges; ++e) {
        if (triangles[e] >= coords.count) {
            problem("triangle " + std::to_string(e / 3) + " names point " + std::to_string(triangles[e]) + " of " +
                    std::to_string(coords.count));
            return report;
        }
    }
    const double scale = std::ldexp(1.0, delaunay_detail::incircle_exponent(coords));
    auto x = [&](std::uint32_t v) { return coords[v][0] * scale; };
    auto y = [&](std::uint32_t v) { return coords[v][1] * scale; };
    auto orient = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) { return orient2d(x(a), y(a), x(b), y(b), x(c), y(c)); };
    auto next = [](std::size_t e) { return e % 3 == 2 ? e - 2 : e + 1; };
    for (std::size_t t = 0; t < triangle_count; ++t) {
        const std::uint32_t* v = triangles + 3 * t;
        if (orient(v[0], v[1], v[2]) >= 0)
            problem("triangle " + std::to_string(t) + " (" + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " +
                    std::to_string(v[2]) + ") is not clockwise with nonzero area");
    }
    // Directed edges sorted by (from, to): none twice; each one's reverse, if present, is its pair.
    std::vector<std::uint32_t> order(edges);
    std::iota(order.begin(), order.end(), 0u);
    auto key = [&](std::size_t e) { return std::pair<std::uint32_t, std::uint32_t>(triangles[e], triangles[next(e)]); };
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    for (std::size_t k = 1; k < edges; ++k)
        if (key(order[k]) == key(order[k - 1]))
            problem("edge " + std::to_string(key(order[k]).first) + " -> " + std::to_string(key(order[k]).second) +
                    " is used by two triangles the same way (overlap)");
    auto pair_of = [&](std::size_t e) -> std::int64_t {
        const auto want = std::pair<std::uint32_t, std::uint32_t>(triangles[next(e)], triangles[e]);
        const auto it = std::lower_bound(order.begin(), order.end(), want,
                                         [&](std::uint32_t f, const std::pair<std::uint32_t, std::uint32_t>& k) { return key(f) < k; });
        return it != order.end() && key(*it) == want ? static_cast<std::int64_t>(*it) : -1;
    };
    std::vector<std::uint32_t> boundary_next(coords.count, 0xFFFFFFFFu);  // boundary edge leaving each point
    std::size_t boundary_edges = 0;
    bool boundary_ok = true;
    for (std::size_t e = 0; e < edges; ++e) {
        const std::int64_t f = pair_of(e);
        if (halfedges && halfedges[e] != f)
            problem("halfedges[" + std::to_string(e) + "] is " + std::to_string(halfedges[e]) + ", expected " + std::to_string(f));
        if (f < 0) {
            ++boundary_edges;
            if (boundary_constrained && constrained && !constrained[e])
                problem("boundary edge " + std::to_string(triangles[e]) + " -> " + std::to_string(triangles[next(e)]) +
                        " is not on a segment");
            if (boundary_next[triangles[e]] != 0xFFFFFFFFu) boundary_ok = false;
            boundary_next[triangles[e]] = triangles[next(e)];
            continue;
        }
        if (constrained && constrained[e] != constrained[f])
            problem("the two halves of edge " + std::to_string(triangles[e]) + " - " + std::to_string(triangles[next(e)]) +
                    " disagree on the segment flag");
        if (constrained && constrained[e]) continue;
        // Clockwise (a, b, c) with d across a -> b: d must not be strictly inside the circle.
        const std::uint32_t a = triangles[e], b = triangles[next(e)], c = triangles[next(next(e))];
        const std::uint32_t d = triangles[next(next(static_cast<std::size_t>(f)))];
        if (incircle(x(a), y(a), x(b), y(b), x(c), y(c), x(d), y(d)) < 0)
            problem("edge " + std::to_string(a) + " - " + std::to_string(b) + " is not on a segment and not locally Delaunay");
    }
    if (boundary_constrained || triangle_count == 0) return report;
    // A triangulation of the convex hull: one convex boundary cycle (clockwise), winding once.
    std::vector<std::uint8_t> used(coords.count, 0);
    for (std::size_t e = 0; e < edges; ++e) used[triangles[e]] = 1;
    const std::size_t n = static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
    if (!boundary_ok) problem("the boundary touches a point twice: not a triangulation of the hull");
    std::uint32_t first = 0xFFFFFFFFu;
    for (std::size_t e = 0; e < edges && first == 0xFFFFFFFFu; ++e)
        if (pair_of(e) < 0) first = triangles[e];
    std::size_t walked = 0;
    double turning = 0;  // the total turn, in radians, only to tell once round from more
    std::uint32_t u = first;
    do {
        const std::uint32_t v = boundary_next[u];
        if (v == 0xFFFFFFFFu || boundary_next[v] == 0xFFFFFFFFu) break;
        const std::uint32_t w = boundary_next[v];
        if (orient(u, v, w) > 0) problem("the boundary turns left at point " + std::to_string(v) + ": not convex");
        double d = std::atan2(y(w) - y(v), x(w) - x(v)) - std::atan2(y(v) - y(u), x(v) - x(u));
        while (d > M_PI) d -= 2 * M_PI;
        while (d < -M_PI) d += 2 * M_PI;
        turning += d;
        u = v;
        ++walked;
    } while (u != first && walked <= boundary_edges);
    if (walked != boundary_edges) problem("the boundary is not one cycle through every boundary edge");
    if (std::fabs(turning + 2 * M_PI) > 1.0) problem("the boundary does not wind once round the hull");
    if (triangle_count + boundary_edges + 2 != 2 * n)
        problem("T = " + std::to_string(triangle_count) + " but 2n - h - 2 = " +
                std::to_string(2 * static_cast<long long>(n) - static_cast<long long>(boundary_edges) - 2));
    return report;
}

}  // namespace hullkit
