// Queries on a finished triangulation: nearest input point by walking (delaunay_find,
// DelaunayLocator), point location with barycentric coordinates (delaunay_locate) and Voronoi cells
// clipped to a rectangle (delaunay_voronoi).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "delaunay_internal.hpp"
#include "hull/parallel.hpp"
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

int scale_exponent(PointSpan2 p) { return delaunay_detail::incircle_exponent(p); }

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

/// Triangle location by a visibility walk over the (clockwise, y up) triangles, on coordinates
/// scaled by 2^exponent (exact).
class TriangleWalker {
public:
    TriangleWalker(PointSpan2 p, const Delaunay& d, int exponent) : p_(p), d_(d), scale_(std::ldexp(1.0, exponent)) {}

    /// orient2d of triangle t's edge k (corner k to corner k + 1) and q: > 0 q is beyond the edge
    /// (outside the triangle's side), 0 on its line.
    int side(std::size_t t, int k, const double* q) const {
        const double* a = p_[d_.triangles[3 * t + k]];
        const double* b = p_[d_.triangles[3 * t + (k + 1) % 3]];
        return orient2d(a[0] * scale_, a[1] * scale_, b[0] * scale_, b[1] * scale_, q[0], q[1]);
    }

    /// The triangle holding q (the lowest index of those holding it), or -1 outside the hull;
    /// `*last` is where the walk ended. The first edge tried rotates pseudo-randomly, which makes
    /// the walk end on any triangulation.
    std::int32_t find(const double* q, std::int32_t start, std::int32_t* last) {
        std::size_t t = static_cast<std::size_t>(start);
        std::int32_t entered = -1;  // the half-edge we came in by: q is strictly inside it
        const std::size_t count = d_.triangles.size() / 3;
        sides_of_ = -1;
        for (std::size_t steps = 0;; ++steps) {
            // A walk ends on any valid triangulation; one handed in from outside (the JS face takes
            // delaunator's) might be folded: then, rather than walk forever, test every triangle.
            if (steps > 4 * count + 64) return scan(q);
            random_ ^= random_ << 13, random_ ^= random_ >> 17, random_ ^= random_ << 5;
            const int first = static_cast<int>(random_ % 3u);
            int exit = -1;
            for (int i = 0; i < 3 && exit < 0; ++i) {
                const int k = (first + i) % 3;
                // q was strictly beyond the edge we came in by, so strictly inside it from here.
                sides_[k] = static_cast<std::int32_t>(3 * t + k) == entered ? -1 : side(t, k, q);
                if (sides_[k] > 0) exit = k;
            }
            *last = static_cast<std::int32_t>(t);
            if (exit < 0) {
                sides_of_ = static_cast<std::int32_t>(t);  // kept for lowest_holding and barycentric
                return lowest_holding(static_cast<std::int32_t>(t), q);
            }
            const std::int32_t across = d_.halfedges[3 * t + static_cast<std::size_t>(exit)];
            if (across < 0) return -1;  // beyond a hull edge: outside the (convex) hull
            entered = across;
            t = static_cast<std::size_t>(across) / 3;
        }
    }

    /// side(t, k, q), from what the walk that ended in t computed when it can.
    int known_side(std::int32_t t, int k, const double* q) const {
        return t == sides_of_ ? sides_[k] : side(static_cast<std::size_t>(t), k, q);
    }

    /// The lowest-indexed triangle holding q, by testing them all; -1 for none.
    std::int32_t scan(const double* q) const {
        for (std::size_t t = 0; t < d_.triangles.size() / 3; ++t)
            if (side(t, 0, q) <= 0 && side(t, 1, q) <= 0 && side(t, 2, q) <= 0) return static_cast<std::int32_t>(t);
        return -1;
    }

    /// Of the triangles holding q, t among them, the lowest index: q on an edge is held by the
    /// triangle across it too, and a search across such edges meets every triangle around the
    /// edge or vertex that holds q.
    std::int32_t lowest_holding(std::int32_t t, const double* q) {
        seen_.assign(1, t);
        std::int32_t best = t;
        for (std::size_t i = 0; i < seen_.size(); ++i) {
            const std::size_t u = static_cast<std::size_t>(seen_[i]);
            best = std::min(best, seen_[i]);
            for (int k = 0; k < 3; ++k) {
                if (known_side(seen_[i], k, q) != 0) continue;
                const std::int32_t across = d_.halfedges[3 * u + static_cast<std::size_t>(k)];
                if (across < 0) continue;
                const std::int32_t v = across / 3;
                if (std::find(seen_.begin(), seen_.end(), v) != seen_.end()) continue;
                bool holds = true;
                for (int j = 0; j < 3 && holds; ++j) holds = side(static_cast<std::size_t>(v), j, q) <= 0;
                if (holds) seen_.push_back(v);
            }
        }
        return best;
    }

    /// Barycentric coordinates of q in triangle t (rounded; exactly 0 for a corner whose opposite
    /// edge holds q, exactly 1 at a corner: the same products with q in the corner's place).
    void barycentric(std::int32_t t, const double* q, double* out) const {
        double w[3][2];
        for (int i = 0; i < 3; ++i) {
            const double* c = p_[d_.triangles[3 * static_cast<std::size_t>(t) + i]];
            w[i][0] = c[0] * scale_, w[i][1] = c[1] * scale_;
        }
        const double whole = area2(w[0], w[1], w[2]);
        for (int k = 0; k < 3; ++k) {
            // Corner k's weight is the area opposite it with q in its place; the edge opposite
            // corner k runs from corner k + 1 to k + 2.
            if (known_side(t, (k + 1) % 3, q) == 0) {
                out[k] = 0.0;
                continue;
            }
            const double* r[3] = {w[0], w[1], w[2]};
            r[k] = q;
            out[k] = area2(r[0], r[1], r[2]) / whole;
        }
    }

private:
    static double area2(const double* a, const double* b, const double* c) {
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }

    PointSpan2 p_;
    const Delaunay& d_;
    double scale_;
    std::vector<std::int32_t> seen_;
    std::uint32_t random_ = 0x2545f491u;
    int sides_[3] = {2, 2, 2};  ///< side(sides_of_, k, q) for the query being walked
    std::int32_t sides_of_ = -1;
};

DelaunayQueries locate_failure(std::string message, std::int64_t query) {
    DelaunayQueries out;
    out.error = std::move(message);
    out.error_query = query;
    return out;
}

constexpr std::size_t kLocateChunk = 4096;  ///< queries per task on the threads

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

DelaunayQueries delaunay_locate(PointSpan2 p, const Delaunay& d, PointSpan2 queries, const DelaunayQueryOptions& options) {
    if (!d.ok()) return locate_failure("the triangulation failed: " + d.error, -1);
    const std::size_t n = p.count, m = queries.count;
    if (d.representative.size() != n) {
        return locate_failure("the triangulation is of " + std::to_string(d.representative.size()) +
                                  " points, not of these " + std::to_string(n),
                              -1);
    }
    const int exponent = scale_exponent(p);
    const double scale = std::ldexp(1.0, exponent);
    // Nearest points compare squared distances (incircle's range); location needs orient2d's only.
    const double top = options.nearest ? kIncircleMaxMagnitude : kPredicateMaxMagnitude;
    const double bottom = options.nearest ? kIncircleMinMagnitude : kPredicateMinMagnitude;
    std::vector<double> scaled(2 * m);
    double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    double hi[2] = {-lo[0], -lo[1]};
    for (std::size_t i = 0; i < m; ++i) {
        for (int k = 0; k < 2; ++k) {
            const double v = queries[i][k], s = v * scale, magnitude = std::fabs(s);
            if (!(std::fabs(v) <= std::numeric_limits<double>::max())) {
                return locate_failure("query " + std::to_string(i) + " has a non-finite " + "xy"[k] + " coordinate (" +
                                          (std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf") + ")",
                                      static_cast<std::int64_t>(i));
            }
            if (magnitude != 0.0 && (magnitude > top || magnitude < bottom)) {
                return locate_failure("query " + std::to_string(i) + ": its " + "xy"[k] +
                                          " coordinate is too far from the points' scale to be decided exactly",
                                      static_cast<std::int64_t>(i));
            }
            scaled[2 * i + k] = s;
            lo[k] = std::min(lo[k], s), hi[k] = std::max(hi[k], s);
        }
    }
    DelaunayQueries out;
    out.triangle.assign(m, -1);
    if (options.barycentric) out.barycentric.assign(3 * m, std::numeric_limits<double>::quiet_NaN());
    if (options.nearest) out.nearest.assign(m, -1);
    const bool planar = d.dimension == 2 && !d.triangles.empty();
    const bool points = options.nearest && !d.hull.empty();
    if (m == 0 || (!planar && !points)) return out;
    std::vector<std::int32_t> outgoing;
    if (points) outgoing = outgoing_edges(n, d);

    // Queries along a Hilbert curve over their bounding box, so that consecutive walks are short.
    const std::vector<std::uint64_t> order = delaunay_detail::hilbert_order(PointSpan2(scaled.data(), m), lo, hi);

    detail::parallel_for(options.threads, (m + kLocateChunk - 1) / kLocateChunk, [&](std::size_t chunk) {
        TriangleWalker walker(p, d, exponent);
        std::int32_t start = 0, last = 0;
        std::uint32_t from = d.hull.empty() ? 0 : d.hull.front();
        for (std::size_t k = chunk * kLocateChunk; k < std::min(m, (chunk + 1) * kLocateChunk); ++k) {
            const std::size_t i = static_cast<std::uint32_t>(order[k]);
            const double* q = &scaled[2 * i];
            if (planar) {
                const std::int32_t t = walker.find(q, start, &last);
                start = t >= 0 ? t : last;
                out.triangle[i] = t;
                if (options.barycentric && t >= 0) walker.barycentric(t, q, &out.barycentric[3 * i]);
                from = d.triangles[3 * static_cast<std::size_t>(start)];
            }
            if (points) {
                const std::int64_t near = walk_to_nearest(p, d, outgoing, from, queries[i][0], queries[i][1], exponent);
                out.nearest[i] = static_cast<std::int32_t>(near);
                if (!planar) from = static_cast<std::uint32_t>(near);
            }
        }
    });
    return out;
}

DelaunayGradients delaunay_gradients(PointSpan2 p, const Delaunay& d, const double* values, std::size_t columns,
                                     const GradientOptions& options) {
    DelaunayGradients out;
    const std::size_t n = p.count;
    if (!d.ok() || d.representative.size() != n) {
        out.error = d.ok() ? "the triangulation is of " + std::to_string(d.representative.size()) + " points, not of these " +
                                 std::to_string(n)
                           : "the triangulation failed: " + d.error;
        return out;
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (d.representative[i] != i) continue;
        for (std::size_t c = 0; c < columns; ++c) {
            if (!std::isfinite(values[i * columns + c])) {
                out.error = "the value of point " + std::to_string(i) + (columns > 1 ? " (column " + std::to_string(c) + ")" : "") +
                            " is not finite";
                return out;
            }
        }
    }
    out.gradients.assign(n * columns * 2, 0.0);
    if (d.dimension < 2 || columns == 0) return out;
    // Each point's neighbours once (CSR), and the inverse of its 2 x 2 system's matrix, which does
    // not depend on the values: sum over edges e of e e^T / |e|^3.
    const std::vector<std::int32_t> outgoing = outgoing_edges(n, d);
    std::vector<std::uint32_t> offsets(n + 1, 0), neighbours;
    neighbours.reserve(d.triangles.size() + d.hull.size());
    std::vector<double> inverse(3 * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        double a = 0, b = 0, c = 0;
        if (d.representative[i] == i) {
            for_each_neighbour(d, outgoing, static_cast<std::uint32_t>(i), [&](std::uint32_t v) {
                neighbours.push_back(v);
                const double ex = p[v][0] - p[i][0], ey = p[v][1] - p[i][1];
                const double length = std::sqrt(ex * ex + ey * ey), cube = length * length * length;
                a += ex * ex / cube, b += ex * ey / cube, c += ey * ey / cube;
            });
        }
        offsets[i + 1] = static_cast<std::uint32_t>(neighbours.size());
        const double det = a * c - b * b;
        if (det != 0.0) inverse[3 * i] = c / det, inverse[3 * i + 1] = -b / det, inverse[3 * i + 2] = a / det;
    }
    // Per column: minimising the curvature of the cubic along edge (i, j) over g_i gives, summed
    // over i's edges, (sum e e^T / L^3) g_i = sum e (3 (f_j - f_i) / 2 - (e . g_j) / 2) / L^3.
    std::vector<double> g(2 * n);
    for (std::size_t column = 0; column < columns; ++column) {
        std::fill(g.begin(), g.end(), 0.0);
        const auto f = [&](std::size_t i) { return values[i * columns + column]; };
        unsigned sweeps = 0;
        bool converged = false;
        while (!converged && sweeps < options.max_iterations) {
            ++sweeps;
            double change = 0.0;  // the largest change of a component relative to max(1, the gradient's largest)
            for (std::size_t i = 0; i < n; ++i) {
                if (offsets[i] == offsets[i + 1]) continue;
                double sx = 0.0, sy = 0.0;
                for (std::uint32_t k = offsets[i]; k < offsets[i + 1]; ++k) {
                    const std::uint32_t j = neighbours[k];
                    const double ex = p[j][0] - p[i][0], ey = p[j][1] - p[i][1];
                    const double length = std::sqrt(ex * ex + ey * ey), cube = length * length * length;
                    const double r = (1.5 * (f(j) - f(i)) - 0.5 * (ex * g[2 * j] + ey * g[2 * j + 1])) / cube;
                    sx += ex * r, sy += ey * r;
                }
                const double gx = inverse[3 * i] * sx + inverse[3 * i + 1] * sy;
                const double gy = inverse[3 * i + 1] * sx + inverse[3 * i + 2] * sy;
                const double moved = std::max(std::fabs(gx - g[2 * i]), std::fabs(gy - g[2 * i + 1]));
                change = std::max(change, moved / std::max({1.0, std::fabs(gx), std::fabs(gy)}));
                g[2 * i] = gx, g[2 * i + 1] = gy;
            }
            converged = change <= options.tolerance;
        }
        out.iterations = std::max(out.iterations, sweeps);
        out.converged = out.converged && converged;
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t r = d.representative[i];
            out.gradients[(i * columns + column) * 2] = g[2 * r];
            out.gradients[(i * columns + column) * 2 + 1] = g[2 * r + 1];
        }
    }
    return out;
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
