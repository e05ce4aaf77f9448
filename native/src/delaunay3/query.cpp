// Queries on a finished tetrahedralization (delaunay3_locate): the tetrahedron holding a point by
// a visibility walk, its barycentric coordinates, and the nearest input point by a greedy walk over
// Delaunay edges. Every decision is exact (orient3d, compare_distance3d on scaled coordinates).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "delaunay3_internal.hpp"
#include "hull/parallel.hpp"

namespace hullkit {
namespace {

constexpr std::size_t kChunk = 4096;  ///< queries per task on the threads

/// The Delaunay graph's edges as adjacency lists (CSR), from the tetrahedra, the triangles of
/// coplanar input, or the chain of collinear input.
struct Graph {
    std::vector<std::uint32_t> offsets, neighbours;
};

Graph delaunay_graph(std::size_t n, const Delaunay3& d) {
    std::vector<std::uint64_t> edges;
    auto add = [&](std::uint32_t a, std::uint32_t b) {
        edges.push_back(std::uint64_t{a} << 32 | b);
        edges.push_back(std::uint64_t{b} << 32 | a);
    };
    if (d.dimension == 3) {
        for (std::size_t t = 0; t < d.tetrahedron_count(); ++t)
            for (int i = 0; i < 4; ++i)
                for (int j = i + 1; j < 4; ++j) add(d.tetrahedra[4 * t + i], d.tetrahedra[4 * t + j]);
    } else if (d.dimension == 2) {
        for (std::size_t t = 0; t < d.triangles.size() / 3; ++t)
            for (int i = 0; i < 3; ++i) add(d.triangles[3 * t + i], d.triangles[3 * t + (i + 1) % 3]);
    } else if (d.dimension == 1) {
        for (std::size_t k = 0; k + 1 < d.vertices.size(); ++k) add(d.vertices[k], d.vertices[k + 1]);
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    Graph g;
    g.offsets.assign(n + 1, 0);
    for (const std::uint64_t e : edges) ++g.offsets[(e >> 32) + 1];
    for (std::size_t i = 0; i < n; ++i) g.offsets[i + 1] += g.offsets[i];
    g.neighbours.resize(edges.size());
    for (std::size_t k = 0; k < edges.size(); ++k) g.neighbours[k] = static_cast<std::uint32_t>(edges[k]);
    return g;
}

class Locator {
public:
    Locator(PointSpan points, const Delaunay3& d, double scale, const Graph* graph)
        : points_(points), d_(d), scale_(scale), graph_(graph) {}

    /// Point i scaled (copied into `out`).
    const double* point(std::uint32_t i, double* out) const {
        for (int k = 0; k < 3; ++k) out[k] = points_[i][k] * scale_;
        return out;
    }

    /// orient3d of tetrahedron t's corners with corner k replaced by q (scaled).
    int orient_replaced(std::size_t t, int k, const double* q) const {
        double p[4][3];
        const double* w[4];
        for (int i = 0; i < 4; ++i) w[i] = i == k ? q : point(d_.tetrahedra[4 * t + i], p[i]);
        return orient3d(w[0], w[1], w[2], w[3]);
    }

    /// The tetrahedron holding q (the lowest index of those holding it), or -1; `*last` is where the
    /// walk ended (the last tetrahedron inside, for a query outside).
    std::int32_t find(const double* q, std::int32_t start, std::int32_t* last) {
        std::int32_t t = start;
        int entered = 4;
        signs_of_ = -1;
        const std::size_t count = d_.tetrahedron_count();
        for (std::size_t steps = 0;; ++steps) {
            // A walk ends on any valid tetrahedralization; one handed in from outside (the JS face
            // rebuilds it from arrays) might be folded: then, rather than walk forever, test them all.
            if (steps > 4 * count + 64) return scan(q);
            const int first = static_cast<int>(next_random() & 3u);
            int exit = 4;
            // q was strictly beyond the face we came in by, so strictly inside it from here.
            for (int k = 0; k < 4; ++k) signs_[k] = k == entered ? 1 : 2;
            for (int i = 0; i < 4; ++i) {
                const int k = (first + i) & 3;
                if (k == entered) continue;
                signs_[k] = orient_replaced(static_cast<std::size_t>(t), k, q);
                if (signs_[k] < 0) {
                    exit = k;
                    break;
                }
            }
            *last = t;
            if (exit == 4) {
                signs_of_ = t;  // every sign of t is known: kept for lowest_holding and barycentric
                return lowest_holding(t, q);
            }
            const std::int32_t next = d_.neighbors[4 * static_cast<std::size_t>(t) + exit];
            if (next < 0) return -1;  // beyond a hull face: outside the (convex) hull
            entered = 4;  // the face of `next` we came in by
            for (int k = 0; k < 4; ++k)
                if (d_.neighbors[4 * static_cast<std::size_t>(next) + k] == t) entered = k;
            t = next;
        }
    }

    /// The lowest-indexed tetrahedron holding q, by testing them all; -1 for none.
    std::int32_t scan(const double* q) const {
        for (std::size_t t = 0; t < d_.tetrahedron_count(); ++t) {
            bool holds = true;
            for (int k = 0; k < 4 && holds; ++k) holds = orient_replaced(t, k, q) >= 0;
            if (holds) return static_cast<std::int32_t>(t);
        }
        return -1;
    }

    /// Of the tetrahedra holding q, t among them, the one with the lowest index: q on a face (an
    /// orientation of 0) is held by the neighbour across it too; a search over such faces meets
    /// every tetrahedron around the face, edge or vertex that holds q.
    std::int32_t lowest_holding(std::int32_t t, const double* q) {
        std::int32_t best = t;
        bool on_boundary = false;
        for (int k = 0; k < 4 && !on_boundary; ++k) on_boundary = sign(t, k, q) == 0;
        if (!on_boundary) return best;
        seen_.assign(1, t);
        for (std::size_t i = 0; i < seen_.size(); ++i) {
            const std::int32_t u = seen_[i];
            best = std::min(best, u);
            for (int k = 0; k < 4; ++k) {
                if (orient_replaced(static_cast<std::size_t>(u), k, q) != 0) continue;
                const std::int32_t v = d_.neighbors[4 * static_cast<std::size_t>(u) + k];
                if (v < 0 || std::find(seen_.begin(), seen_.end(), v) != seen_.end()) continue;
                bool holds = true;
                for (int j = 0; j < 4 && holds; ++j) holds = orient_replaced(static_cast<std::size_t>(v), j, q) >= 0;
                if (holds) seen_.push_back(v);
            }
        }
        return best;
    }

    /// orient_replaced(t, k, q), from what the walk that ended in t computed when it can.
    int sign(std::int32_t t, int k, const double* q) const {
        return t == signs_of_ ? signs_[k] : orient_replaced(static_cast<std::size_t>(t), k, q);
    }

    /// Barycentric coordinates of q in tetrahedron t (rounded; exact zeros on faces through q).
    /// Each weight is the volume with q in place of its corner over their sum (the whole volume),
    /// each rounded from differences to q; a weight whose exact sign is positive but whose rounded
    /// volume is not (a sliver far from the origin of its differences) is kept at the smallest
    /// positive double, so the weights are never negative, never NaN, and exactly 1 at a corner.
    void barycentric(std::int32_t t, const double* q, double* out) const {
        double p[4][3];
        const double* w[4];
        for (int i = 0; i < 4; ++i) w[i] = point(d_.tetrahedra[4 * static_cast<std::size_t>(t) + i], p[i]);
        double part[4], whole = 0.0;
        for (int k = 0; k < 4; ++k) {
            part[k] = 0.0;
            if (sign(t, k, q) == 0) continue;  // q inside t: the others are positive
            // q first (differences to q), the others in an order of the same parity.
            static constexpr int kOthers[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {2, 1, 0}};
            const double volume = volume6(q, w[kOthers[k][0]], w[kOthers[k][1]], w[kOthers[k][2]]);
            part[k] = std::max(volume, std::numeric_limits<double>::denorm_min());
            whole += part[k];
        }
        for (int k = 0; k < 4; ++k) out[k] = part[k] / whole;
    }

    /// The nearest input point to q (ties: the lowest index), by a greedy walk from `from`.
    std::int32_t nearest(const double* q, std::uint32_t from) {
        double a[3], b[3];
        std::uint32_t current = from;
        for (bool moved = true; moved;) {
            moved = false;
            for (std::uint32_t k = graph_->offsets[current]; k < graph_->offsets[current + 1]; ++k) {
                const std::uint32_t v = graph_->neighbours[k];
                if (compare_distance3d(point(v, a), point(current, b), q) < 0) {
                    current = v;
                    moved = true;
                    break;
                }
            }
        }
        // The points exactly as near lie on one empty sphere around q, joined by Delaunay edges.
        std::uint32_t best = current;
        seen_.assign(1, static_cast<std::int32_t>(current));
        for (std::size_t i = 0; i < seen_.size(); ++i) {
            const std::uint32_t u = static_cast<std::uint32_t>(seen_[i]);
            best = std::min(best, u);
            for (std::uint32_t k = graph_->offsets[u]; k < graph_->offsets[u + 1]; ++k) {
                const std::uint32_t v = graph_->neighbours[k];
                if (std::find(seen_.begin(), seen_.end(), static_cast<std::int32_t>(v)) != seen_.end()) continue;
                if (compare_distance3d(point(v, a), point(current, b), q) == 0) seen_.push_back(static_cast<std::int32_t>(v));
            }
        }
        return static_cast<std::int32_t>(best);
    }

private:
    static double volume6(const double* a, const double* b, const double* c, const double* d) {
        return detail::orient3d_stage_a(a, b, c, d);
    }
    std::uint32_t next_random() {
        random_ ^= random_ << 13;
        random_ ^= random_ >> 17;
        random_ ^= random_ << 5;
        return random_;
    }

    PointSpan points_;
    const Delaunay3& d_;
    double scale_;
    const Graph* graph_;
    std::vector<std::int32_t> seen_;
    std::uint32_t random_ = 0x2545f491u;
    int signs_[4] = {2, 2, 2, 2};  ///< orient_replaced(signs_of_, k, q) for the query being walked
    std::int32_t signs_of_ = -1;
};

Delaunay3Queries query_failure(std::string message, std::int64_t query) {
    Delaunay3Queries out;
    out.error = std::move(message);
    out.error_query = query;
    return out;
}

}  // namespace

Delaunay3Queries delaunay3_locate(PointSpan points, const Delaunay3& d, PointSpan queries,
                                  const Delaunay3QueryOptions& options) {
    if (!d.ok()) return query_failure("the tetrahedralization failed: " + d.error, -1);
    const std::size_t n = points.count, m = queries.count;
    if (d.representative.size() != n) {
        return query_failure("the tetrahedralization is of " + std::to_string(d.representative.size()) +
                                 " points, not of these " + std::to_string(n),
                             -1);
    }
    int exponent = 0;
    if (!delaunay3_detail::scale_exponent_of(points, &exponent)) {
        return query_failure("the points cannot be scaled into the exact range (delaunay3() refuses them too)", -1);
    }
    const double scale = std::ldexp(1.0, exponent);
    // Queries scaled, and checked.
    std::vector<double> scaled(3 * m);
    for (std::size_t i = 0; i < m; ++i) {
        for (int k = 0; k < 3; ++k) {
            const double v = queries[i][k], s = v * scale, magnitude = std::fabs(s);
            if (!(std::fabs(v) <= std::numeric_limits<double>::max())) {
                return query_failure("query " + std::to_string(i) + " has a non-finite " + "xyz"[k] + " coordinate (" +
                                         (std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf") + ")",
                                     static_cast<std::int64_t>(i));
            }
            if (magnitude != 0.0 && (magnitude > kPredicateMaxMagnitude || magnitude < kPredicateMinMagnitude)) {
                return query_failure("query " + std::to_string(i) + ": its " + "xyz"[k] +
                                         " coordinate is too far from the points' scale to be decided exactly",
                                     static_cast<std::int64_t>(i));
            }
            scaled[3 * i + k] = s;
        }
    }
    if (options.nearest && d.furthest_site) {
        return query_failure("nearest points need the ordinary tetrahedralization: the furthest-site one leaves the "
                             "points inside the hull out (locate in it, and find nearest points in delaunay3() "
                             "without furthest_site)",
                             -1);
    }
    Delaunay3Queries out;
    out.tetrahedron.assign(m, -1);
    if (options.barycentric) out.barycentric.assign(4 * m, std::numeric_limits<double>::quiet_NaN());
    if (options.nearest) out.nearest.assign(m, -1);
    const bool solid = d.dimension == 3 && d.tetrahedron_count() > 0;
    Graph graph;
    if (options.nearest && d.dimension >= 0) graph = delaunay_graph(n, d);
    // A vertex to start each nearest-point walk at when no tetrahedron is at hand.
    std::uint32_t any_vertex = 0;
    while (any_vertex < n && d.representative[any_vertex] != any_vertex) ++any_vertex;

    // Queries along a Hilbert curve over their bounding box, so that consecutive walks are short.
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) lo[k] = std::numeric_limits<double>::infinity(), hi[k] = -lo[k];
    for (std::size_t i = 0; i < m; ++i)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], scaled[3 * i + k]), hi[k] = std::max(hi[k], scaled[3 * i + k]);
    const std::vector<std::uint64_t> order = delaunay3_detail::hilbert_order(PointSpan(scaled.data(), m), lo, hi, options.threads);
    const std::size_t chunks = (m + kChunk - 1) / kChunk;
    detail::parallel_for(options.threads, chunks, [&](std::size_t chunk) {
        Locator locator(points, d, scale, &graph);
        std::int32_t start = 0, last = 0;
        for (std::size_t k = chunk * kChunk; k < std::min(m, (chunk + 1) * kChunk); ++k) {
            const std::size_t i = static_cast<std::uint32_t>(order[k]);
            const double* q = &scaled[3 * i];
            std::int32_t t = -1;
            if (solid) {
                t = locator.find(q, start, &last);
                start = t >= 0 ? t : last;
                out.tetrahedron[i] = t;
                if (options.barycentric && t >= 0) locator.barycentric(t, q, &out.barycentric[4 * i]);
            }
            if (options.nearest && any_vertex < n) {
                const std::uint32_t from = solid ? d.tetrahedra[4 * static_cast<std::size_t>(start)] : any_vertex;
                out.nearest[i] = locator.nearest(q, from);
            }
        }
    });
    return out;
}

}  // namespace hullkit
