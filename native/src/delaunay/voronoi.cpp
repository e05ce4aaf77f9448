// The whole (unclipped) Voronoi diagram of a finished 2D triangulation in scipy.spatial.Voronoi's
// layout (delaunay_voronoi_diagram), and the circumcentre it places vertices with.
//
// The passes run over fixed chunks of the triangles (which the triangulation keeps in Hilbert
// order, so a chunk is a compact patch of the plane): the exact cocircularity flags, the vertices,
// the ridges and the cells. Each chunk writes only its own slots, and what is numbered in order
// (vertices, ridges, cell offsets) is counted per chunk and placed by prefix sums, so the arrays do
// not depend on the thread count.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "delaunay_internal.hpp"
#include "hull/parallel.hpp"
#include "hullkit/delaunay.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit {
namespace {

constexpr std::size_t kChunk = std::size_t{1} << 14;  // triangles per task
constexpr std::uint32_t kNone = ~std::uint32_t{0};

constexpr std::size_t kAhead = 48;  // triangles between a prefetch and the use

inline void prefetch(const void* address) {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(address);
#else
    (void)address;
#endif
}

/// 2^k for -1022 <= k <= 1023, from its bits.
inline double power_of_two(int k) {
    const std::uint64_t bits = static_cast<std::uint64_t>(k + 1023) << 52;
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

inline std::size_t next_edge(std::size_t e) { return e % 3 == 2 ? e - 2 : e + 1; }
inline std::size_t prev_edge(std::size_t e) { return e % 3 == 0 ? e + 2 : e - 1; }

/// Collinear points (dimension 1) or one point: ridges between neighbours along the line, no
/// vertices, every distinct point's cell {-1}.
void along_line(PointSpan2 p, const Delaunay& d, VoronoiDiagram& out) {
    if (d.dimension == 1) {
        for (std::size_t k = 0; k + 1 < d.hull.size(); ++k) {
            const std::uint32_t a = d.hull[k], b = d.hull[k + 1];
            out.ridge_points.insert(out.ridge_points.end(), {static_cast<std::int32_t>(std::min(a, b)), static_cast<std::int32_t>(std::max(a, b))});
            out.ridge_vertices.insert(out.ridge_vertices.end(), {-1, -1});
        }
    }
    out.cell_offsets.assign(1, 0);
    for (std::size_t i = 0; i < p.count; ++i) {
        if (d.representative[i] != i) {
            out.point_cell.push_back(out.point_cell[d.representative[i]]);
            continue;
        }
        out.point_cell.push_back(static_cast<std::int32_t>(out.cell_point.size()));
        out.cell_point.push_back(static_cast<std::uint32_t>(i));
        out.cells.push_back(-1);
        out.cell_offsets.push_back(static_cast<std::int64_t>(out.cells.size()));
        out.areas.push_back(std::numeric_limits<double>::infinity());
    }
}

}  // namespace

void circumcentre(const double* a, const double* b, const double* c, double* out) {
    double ba[2] = {b[0] - a[0], b[1] - a[1]}, ca[2] = {c[0] - a[0], c[1] - a[1]};
    const double largest = std::max(std::max(std::fabs(ba[0]), std::fabs(ba[1])), std::max(std::fabs(ca[0]), std::fabs(ca[1])));
    int exponent = 0;  // largest = f 2^exponent, 0.5 <= f < 1 (frexp's)
    std::uint64_t bits;
    std::memcpy(&bits, &largest, sizeof bits);
    const int biased = static_cast<int>(bits >> 52);  // the sign bit is 0
    const bool fast = biased > 64 && biased < 2047 - 64;  // normal, and 2^-exponent and 2^exponent too
    if (fast) {
        exponent = biased - 1022;
        const double down = power_of_two(-exponent);  // scaling by a power of two is exact here
        for (double* v : {ba, ca}) v[0] *= down, v[1] *= down;
    } else {
        std::frexp(largest, &exponent);
        for (double* v : {ba, ca}) v[0] = std::ldexp(v[0], -exponent), v[1] = std::ldexp(v[1], -exponent);
    }
    const double lb = ba[0] * ba[0] + ba[1] * ba[1], lc = ca[0] * ca[0] + ca[1] * ca[1];
    const double denominator = 2.0 * (ba[0] * ca[1] - ba[1] * ca[0]);
    const double x = (ca[1] * lb - ba[1] * lc) / denominator;
    const double y = (ba[0] * lc - ca[0] * lb) / denominator;
    // Scaling back: a product by a power of two is exact (so equal to ldexp's) unless it leaves the
    // normal range; below it ldexp rounds (a centre beyond the doubles' range is inf either way).
    double sx = 0.0, sy = 0.0;
    if (fast) {
        const double up = power_of_two(exponent);
        sx = x * up, sy = y * up;
    }
    const auto exact = [](double scaled, double v) { return v == 0.0 || !(std::fabs(scaled) < DBL_MIN); };
    if (!fast || !exact(sx, x) || !exact(sy, y)) sx = std::ldexp(x, exponent), sy = std::ldexp(y, exponent);
    out[0] = a[0] + sx;
    out[1] = a[1] + sy;
}

VoronoiDiagram delaunay_voronoi_diagram(PointSpan2 p, const Delaunay& d, unsigned threads) {
    VoronoiDiagram out;
    if (!d.ok()) {
        out.error = "delaunay_voronoi_diagram: the triangulation failed (" + d.error + ")";
        return out;
    }
    if (d.representative.size() != p.count || d.halfedges.size() != d.triangles.size()) {
        out.error = "delaunay_voronoi_diagram: the triangulation is not one of these " + std::to_string(p.count) + " points";
        return out;
    }
    if (d.dimension < 2) {
        along_line(p, d, out);
        return out;
    }
    const std::vector<std::uint32_t>& corner = d.triangles;
    const std::vector<std::int32_t>& twin = d.halfedges;
    const std::size_t triangles = corner.size() / 3, n = p.count;
    const std::size_t chunks = (triangles + kChunk - 1) / kChunk;
    const auto chunk_range = [&](std::size_t c) {
        return std::make_pair(c * kChunk, std::min(triangles, (c + 1) * kChunk));
    };

    // 1. Per triangle: its circumcentre, and bit k of its flags for an edge k (corner k to k + 1)
    // whose other side has a higher half-edge number: the triangle across is exactly cocircular with
    // it (their lifted faces coplanar: one Delaunay polygon). joined() reads the bit from the lower
    // side. Each chunk also counts its ridges: the edges between polygons, once, and hull edges.
    const int exponent = delaunay_detail::incircle_exponent(p);
    std::vector<std::uint8_t> flags(triangles, 0);
    std::vector<double> centres(2 * triangles);
    std::vector<std::int64_t> ridge_count(chunks, 0);
    detail::parallel_for(threads, chunks, [&](std::size_t c) {
        const auto [lo, hi] = chunk_range(c);
        const auto at = [&](std::uint32_t v, int axis) {
            return exponent == 0 ? p[v][axis] : std::ldexp(p[v][axis], exponent);
        };
        std::int64_t ridges = 0;
        for (std::size_t t = lo; t < hi; ++t) {
            // The points are in input order: ask for the corners of a triangle further on early
            // (a point's first use is a cache miss; its next ones, in nearby triangles, are not).
            if (t + kAhead < triangles) {
                for (std::size_t k = 0; k < 3; ++k) prefetch(p[corner[3 * (t + kAhead) + k]]);
            }
            const std::uint32_t a = corner[3 * t], b = corner[3 * t + 1], c3 = corner[3 * t + 2];
            circumcentre(p[a], p[b], p[c3], &centres[2 * t]);
            std::uint8_t bits = 0;
            for (std::size_t k = 0; k < 3; ++k) {
                const std::int32_t h = twin[3 * t + k];
                if (h < 0) {
                    ++ridges;
                    continue;
                }
                if (static_cast<std::size_t>(h) < 3 * t + k) continue;
                const std::uint32_t o = corner[prev_edge(static_cast<std::size_t>(h))];
                if (incircle(at(a, 0), at(a, 1), at(b, 0), at(b, 1), at(c3, 0), at(c3, 1), at(o, 0), at(o, 1)) == 0)
                    bits = static_cast<std::uint8_t>(bits | (1u << k));
                else
                    ++ridges;
            }
            flags[t] = bits;
        }
        ridge_count[c] = ridges;
    });
    const auto joined = [&](std::size_t e) {
        const std::int32_t h = twin[e];
        if (h < 0) return false;
        const std::size_t lower = std::min(e, static_cast<std::size_t>(h));
        return (flags[lower / 3] & (1u << (lower % 3))) != 0;
    };
    const auto alone = [&](std::size_t t) { return !joined(3 * t) && !joined(3 * t + 1) && !joined(3 * t + 2); };

    // 2. Polygons numbered by their first triangle (sequential: a flood over the merged ones, whose
    // triangles are kept in `members`, group g at member_start[g] ..), or when none is merged (points
    // in general position) one per triangle.
    const bool merged = std::any_of(flags.begin(), flags.end(), [](std::uint8_t f) { return f != 0; });
    out.triangle_vertex.assign(triangles, kNone);
    std::vector<std::uint32_t> members, member_start(1, 0), group_vertex;
    std::uint32_t polygons = 0;
    if (!merged) {
        polygons = static_cast<std::uint32_t>(triangles);
        std::iota(out.triangle_vertex.begin(), out.triangle_vertex.end(), 0u);
    }
    for (std::size_t t = merged ? 0 : triangles; t < triangles; ++t) {
        if (out.triangle_vertex[t] != kNone) continue;
        const std::uint32_t v = polygons++;
        out.triangle_vertex[t] = v;
        if (alone(t)) continue;
        const std::size_t begin = members.size();
        members.push_back(static_cast<std::uint32_t>(t));
        for (std::size_t q = begin; q < members.size(); ++q) {
            const std::size_t u = members[q];
            for (std::size_t k = 0; k < 3; ++k) {
                if (!joined(3 * u + k)) continue;
                const std::uint32_t w = static_cast<std::uint32_t>(twin[3 * u + k]) / 3;
                if (out.triangle_vertex[w] != kNone) continue;
                out.triangle_vertex[w] = v;
                members.push_back(w);
            }
        }
        member_start.push_back(static_cast<std::uint32_t>(members.size()));
        group_vertex.push_back(v);
    }

    // 3. Vertices: a lone triangle's circumcentre; a merged polygon's from its corners, chained
    // from its lowest index along its boundary half-edges.
    if (polygons == triangles) {
        out.vertices = std::move(centres);
    } else {
        out.vertices.assign(2 * static_cast<std::size_t>(polygons), 0.0);
        for (std::size_t t = 0; t < triangles; ++t) {
            if (!alone(t)) continue;
            const std::size_t v = out.triangle_vertex[t];
            out.vertices[2 * v] = centres[2 * t], out.vertices[2 * v + 1] = centres[2 * t + 1];
        }
        const std::size_t groups = group_vertex.size();
        detail::parallel_for(threads, (groups + kChunk - 1) / kChunk, [&](std::size_t c) {
            std::vector<std::uint32_t> ring;
            std::vector<std::pair<std::uint32_t, std::uint32_t>> sides;  // boundary from -> to
            for (std::size_t g = c * kChunk; g < std::min(groups, (c + 1) * kChunk); ++g) {
                sides.clear();
                for (std::size_t q = member_start[g]; q < member_start[g + 1]; ++q) {
                    for (std::size_t e = 3 * std::size_t{members[q]}; e < 3 * std::size_t{members[q]} + 3; ++e)
                        if (!joined(e)) sides.emplace_back(corner[e], corner[next_edge(e)]);
                }
                std::sort(sides.begin(), sides.end());
                const std::size_t m = sides.size();
                ring.assign(m, 0);
                ring[0] = sides[0].first;  // the lowest index
                for (std::size_t k = 1; k < m; ++k)
                    ring[k] = std::lower_bound(sides.begin(), sides.end(), std::make_pair(ring[k - 1], std::uint32_t{0}))->second;
                circumcentre(p[ring[0]], p[ring[m / 3]], p[ring[2 * m / 3]], &out.vertices[2 * std::size_t{group_vertex[g]}]);
            }
        });
    }

    // 4. Ridges in half-edge order: each chunk fills the slots after the earlier chunks' ridges.
    std::vector<std::int64_t> ridge_start(chunks + 1, 0);
    for (std::size_t c = 0; c < chunks; ++c) ridge_start[c + 1] = ridge_start[c] + ridge_count[c];
    out.ridge_points.resize(2 * static_cast<std::size_t>(ridge_start[chunks]));
    out.ridge_vertices.resize(out.ridge_points.size());
    detail::parallel_for(threads, chunks, [&](std::size_t c) {
        const auto [lo, hi] = chunk_range(c);
        std::size_t r = 2 * static_cast<std::size_t>(ridge_start[c]);
        for (std::size_t t = lo; t < hi; ++t) {
            for (std::size_t k = 0; k < 3; ++k) {
                const std::size_t e = 3 * t + k;
                const std::int32_t h = twin[e];
                if (!(h < 0 || (static_cast<std::size_t>(h) > e && !(flags[t] & (1u << k))))) continue;
                const std::uint32_t a = corner[e], b = corner[next_edge(e)];
                out.ridge_points[r] = static_cast<std::int32_t>(std::min(a, b));
                out.ridge_points[r + 1] = static_cast<std::int32_t>(std::max(a, b));
                out.ridge_vertices[r] = h < 0 ? -1 : static_cast<std::int32_t>(out.triangle_vertex[static_cast<std::size_t>(h) / 3]);
                out.ridge_vertices[r + 1] = static_cast<std::int32_t>(out.triangle_vertex[t]);
                r += 2;
            }
        }
    });

    // 5. Cells. Each point's walk starts at one out-half-edge: on the hull the one after the hull
    // edge that comes in (the cell is open there), elsewhere the first in triangle order. From an
    // out-half-edge e the next one counter-clockwise is next(twin(e)).
    // Each task scans every half-edge and keeps the points of its own index range.
    std::vector<std::int32_t> head(n, -1);
    const std::size_t ranges = detail::resolve_threads(threads, n / 65536 + 1);
    detail::parallel_for(threads, ranges, [&](std::size_t r) {
        const std::size_t lo = n * r / ranges, hi = n * (r + 1) / ranges;
        for (std::size_t e = 0; e < corner.size(); ++e) {
            const std::uint32_t s = corner[e];
            if (s < lo || s >= hi) continue;
            if (head[s] < 0 || twin[prev_edge(e)] < 0) head[s] = static_cast<std::int32_t>(e);
        }
    });
    // The walk, calling f(vertex) for each polygon met once (in order) and returning whether the
    // cell is open (a hull point's).
    const auto walk = [&](std::uint32_t s, auto&& f) {
        const std::int32_t first = head[s];
        const bool open = twin[prev_edge(static_cast<std::size_t>(first))] < 0;
        const std::uint32_t start_vertex = out.triangle_vertex[static_cast<std::size_t>(first) / 3];
        std::uint32_t last = kNone;
        std::int32_t e = first;
        for (;;) {
            const std::uint32_t v = out.triangle_vertex[static_cast<std::size_t>(e) / 3];
            if (v != last) f(v), last = v;
            const std::int32_t h = twin[static_cast<std::size_t>(e)];
            if (h < 0) break;
            e = static_cast<std::int32_t>(next_edge(static_cast<std::size_t>(h)));
            if (e == first) break;
            // A closed cell that started inside a polygon's run (its triangles around s are
            // consecutive) ends on coming back into that run.
            if (!open && last != start_vertex && out.triangle_vertex[static_cast<std::size_t>(e) / 3] == start_vertex) break;
        }
        return open;
    };
    // Cells are numbered in walk order: a point is walked by the chunk holding its head, in
    // triangle order, into the chunk's own arrays; the chunks are then joined in order.
    struct Part {
        std::vector<std::int32_t> cells;
        std::vector<std::int64_t> ends;
        std::vector<std::uint32_t> points;
        std::vector<double> areas;
    };
    std::vector<Part> parts(chunks);
    detail::parallel_for(threads, chunks, [&](std::size_t c) {
        const auto [lo, hi] = chunk_range(c);
        Part& part = parts[c];
        std::vector<std::uint32_t> ring;
        for (std::size_t e = 3 * lo; e < 3 * hi; ++e) {
            if (e + 3 * kAhead < corner.size()) prefetch(&head[corner[e + 3 * kAhead]]);
            const std::uint32_t s = corner[e];
            if (head[s] != static_cast<std::int32_t>(e)) continue;
            ring.clear();
            const bool open = walk(s, [&](std::uint32_t v) { ring.push_back(v); });
            part.points.push_back(s);
            if (open) {
                part.cells.insert(part.cells.end(), ring.begin(), ring.end());
                part.cells.push_back(-1);
                part.ends.push_back(static_cast<std::int64_t>(part.cells.size()));
                part.areas.push_back(std::numeric_limits<double>::infinity());
                continue;
            }
            const std::size_t shift = static_cast<std::size_t>(std::min_element(ring.begin(), ring.end()) - ring.begin());
            std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(shift), ring.end());
            part.cells.insert(part.cells.end(), ring.begin(), ring.end());
            part.ends.push_back(static_cast<std::int64_t>(part.cells.size()));
            // The shoelace formula from the lowest vertex (the cell is convex: every term >= 0).
            const double* o = &out.vertices[2 * static_cast<std::size_t>(ring[0])];
            double twice = 0.0;
            for (std::size_t k = 1; k + 1 < ring.size(); ++k) {
                const double* u = &out.vertices[2 * static_cast<std::size_t>(ring[k])];
                const double* w = &out.vertices[2 * static_cast<std::size_t>(ring[k + 1])];
                twice += (u[0] - o[0]) * (w[1] - o[1]) - (u[1] - o[1]) * (w[0] - o[0]);
            }
            part.areas.push_back(0.5 * twice);
        }
    });
    std::vector<std::size_t> first_cell(chunks + 1, 0), first_entry(chunks + 1, 0);
    for (std::size_t c = 0; c < chunks; ++c) {
        first_cell[c + 1] = first_cell[c] + parts[c].points.size();
        first_entry[c + 1] = first_entry[c] + parts[c].cells.size();
    }
    const std::size_t cell_count = first_cell[chunks];
    out.cells.resize(first_entry[chunks]);
    out.cell_offsets.assign(cell_count + 1, 0);
    out.cell_point.resize(cell_count);
    out.areas.resize(cell_count);
    out.point_cell.assign(n, -1);
    detail::parallel_for(threads, chunks, [&](std::size_t c) {
        Part& part = parts[c];
        std::copy(part.cells.begin(), part.cells.end(), out.cells.begin() + static_cast<std::ptrdiff_t>(first_entry[c]));
        for (std::size_t k = 0; k < part.points.size(); ++k) {
            const std::size_t cell = first_cell[c] + k;
            out.cell_offsets[cell + 1] = static_cast<std::int64_t>(first_entry[c]) + part.ends[k];
            out.cell_point[cell] = part.points[k];
            out.areas[cell] = part.areas[k];
            out.point_cell[part.points[k]] = static_cast<std::int32_t>(cell);
        }
        std::vector<std::int32_t>().swap(part.cells);  // freed as soon as copied
    });
    for (std::size_t s = 0; s < n; ++s) {
        if (d.representative[s] != s) out.point_cell[s] = out.point_cell[d.representative[s]];
    }
    return out;
}

}  // namespace hullkit
