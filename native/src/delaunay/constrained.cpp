// Constrained Delaunay triangulation: see hullkit/constrained.hpp for the method and the rules,
// constrained_mesh.hpp for the working mesh.
#include "hullkit/constrained.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "../exact/expansion.hpp"
#include "constrained_mesh.hpp"
#include "refine.hpp"
#include "delaunay_internal.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit {
namespace constrained_detail {
namespace {

using exact_detail::estimate;
using exact_detail::exact_diff;
using exact_detail::exact_minor;
using exact_detail::expansion_sign;
using exact_detail::expansion_sum;
using exact_detail::scale_expansion;

/// The exact orientation determinant of (p, q, r) as an expansion (16 components at most):
/// (p - r) x (q - r) as orient2d defines it.
int orient_expansion(const double* p, const double* q, const double* r, double* h) {
    double px[2], py[2], qx[2], qy[2];
    const int pxl = exact_diff(p[0], r[0], px), pyl = exact_diff(p[1], r[1], py);
    const int qxl = exact_diff(q[0], r[0], qx), qyl = exact_diff(q[1], r[1], qy);
    return exact_minor(pxl, px, qyl, qy, pyl, py, qxl, qx, h);
}

/// The nearest double to the exact quotient num / den (den != 0), ties to even.
double round_quotient(int nl, const double* num, int dl, const double* den) {
    double q = estimate(nl, num) / estimate(dl, den);
    const int den_sign = expansion_sign(dl, den);
    // side(m) = sign(num / den - m) for m = hi + lo (an exact two-component value).
    auto side = [&](double hi, double lo) {
        double a[64], b[64], s[128], t[256];
        const int al = scale_expansion(dl, den, -hi, a);
        const int bl = lo == 0.0 ? 0 : scale_expansion(dl, den, -lo, b);
        const int sl = expansion_sum(al, a, bl, b, s);
        const int tl = expansion_sum(nl, num, sl, s, t);
        return expansion_sign(tl, t) * den_sign;
    };
    // Ties go to the double whose last significand bit is 0.
    auto odd = [](double v) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        return (bits & 1) != 0;
    };
    for (int guard = 0; guard < 64; ++guard) {
        const double up = std::nextafter(q, std::numeric_limits<double>::infinity());
        const int above = side(q, (up - q) / 2);
        if (above > 0 || (above == 0 && odd(q))) {
            q = up;
            continue;
        }
        const double down = std::nextafter(q, -std::numeric_limits<double>::infinity());
        const int below = side(q, (down - q) / 2);
        if (below < 0 || (below == 0 && odd(q))) {
            q = down;
            continue;
        }
        break;
    }
    return q;
}

}  // namespace

/// The crossing of the lines through a, b and c, d (which cross properly), rounded to the nearest
/// double per coordinate. With o1 = orient(c, d, a), o2 = orient(c, d, b) (opposite signs), the
/// crossing is (b o1 - a o2) / (o1 - o2).
void rounded_crossing(const double* a, const double* b, const double* c, const double* d, double* out) {
    double o1[16], o2[16], den[32];
    const int l1 = orient_expansion(c, d, a, o1);
    int l2 = orient_expansion(c, d, b, o2);
    for (int i = 0; i < l2; ++i) o2[i] = -o2[i];
    const int dl = expansion_sum(l1, o1, l2, o2, den);  // o1 - o2
    for (int axis = 0; axis < 2; ++axis) {
        double s1[32], s2[32], num[64];
        const int n1 = scale_expansion(l1, o1, b[axis], s1);
        const int n2 = scale_expansion(l2, o2, a[axis], s2);  // a * (-o2)
        const int nl = expansion_sum(n1, s1, n2, s2, num);
        double v = nl == 0 ? 0.0 : round_quotient(nl, num, dl, den);
        // Keep the predicates' exact range: a coordinate nearer 0 than kIncircleMinMagnitude goes
        // to 0 or to +-that magnitude, whichever is nearer.
        if (v != 0.0 && std::fabs(v) < kIncircleMinMagnitude)
            v = std::fabs(v) < kIncircleMinMagnitude / 2 ? 0.0 : std::copysign(kIncircleMinMagnitude, v);
        out[axis] = v;
    }
}
}  // namespace constrained_detail

namespace {

using namespace constrained_detail;

ConstrainedDelaunay failure(std::string message, std::int64_t point = -1, std::int64_t segment = -1) {
    ConstrainedDelaunay out;
    out.error = std::move(message);
    out.error_point = point;
    out.error_segment = segment;
    return out;
}

/// Shared by both entry points: `segments` are directed (a, b, wind) triples in input order.
/// One sequence of steps on the calling thread (the options' threads do not enter).
/// What happens after the segments are in: the domain (a polygon's fill rule, or a graph's
/// exterior, holes and regions) and its refinement.
struct Domain {
    bool polygon = false;
    FillRule fill = FillRule::EvenOdd;
    bool remove_exterior = false;
    const std::vector<double>* holes = nullptr;
    const std::vector<RegionSeed>* regions = nullptr;
    /// refine_mesh with areas per triangle: the triangles' corners (3 each) and their bounds; the
    /// domain is then the even-odd inside, each triangle its own region.
    const std::vector<std::uint32_t>* mesh_corners = nullptr;
    const std::vector<double>* triangle_areas = nullptr;
    QualityOptions quality;
};

/// The options' numbers checked: an empty string when they are fine.
std::string check_quality(const QualityOptions& q, const std::vector<RegionSeed>* regions) {
    if (!(q.min_angle >= 0 && q.min_angle <= 34))
        return "min_angle must be between 0 and 34 degrees (got " + std::to_string(q.min_angle) + ")";
    if (!(q.max_area >= 0 && std::isfinite(q.max_area)))
        return "max_area must be a positive number or 0 for none (got " + std::to_string(q.max_area) + ")";
    if (q.keep_segments > 2)
        return "keep_segments must be 0 (none), 1 (the boundary's) or 2 (every segment), got " + std::to_string(q.keep_segments);
    for (std::size_t r = 0; regions && r < regions->size(); ++r) {
        const RegionSeed& seed = (*regions)[r];
        if (!std::isfinite(seed.x) || !std::isfinite(seed.y) || !(seed.max_area >= 0 && std::isfinite(seed.max_area)))
            return "region " + std::to_string(r) + ": its point must be finite and its max_area a positive number or 0";
    }
    return std::string();
}

/// `segments` are taken over (merged in place, freed once inserted: less memory at the peak).
ConstrainedDelaunay build(PointSpan2 points, std::vector<Segment> segments, const Domain& domain,
                          std::size_t max_added) {
    const std::string bad_options = check_quality(domain.quality, domain.regions);
    if (!bad_options.empty()) return failure(bad_options);
    Delaunay d;
    // Refinement adds points (how many, only refining tells): room for as many again, reserved
    // here, in the array the points are gathered in, which becomes the mesh's points after the
    // incremental triangulation (its pages are touched once). At CGAL's angle bound the bench's
    // polygons take 0.04 n (a grid of square holes) to 1.2 n (building footprints, lakes of 10^4
    // vertices) added points, the 10^5-vertex lake 1.7 n; an array that outgrows its room is
    // copied into fresh pages (with room for n / 2, footprint-1e3 meshed in 5.0 ms, with n in
    // 3.7 ms; a grid of 256 holes, which needs little, 1.71 ms against 1.79 ms: its arrays then
    // fit less well in the heap's free room). Reserved room is address space until used.
    const bool may_refine = domain.quality.active() || domain.mesh_corners || (domain.regions && !domain.regions->empty());
    const std::size_t spare_points = may_refine ? points.count + 256 : 0;
    std::vector<double> local_xy;
    local_xy.reserve(2 * (points.count + spare_points));
    delaunay_detail::Input in;
    const bool plane = delaunay_detail::prepare(points, d, local_xy, in);
    if (!d.ok()) return failure(d.error, d.error_point);
    ConstrainedDelaunay out;
    out.dimension = d.dimension;
    out.input_count = points.count;
    out.representative = std::move(d.representative);
    out.duplicate_count = d.duplicate_count;
    if (!plane) {  // no triangles; segments lie on the line
        out.coords.assign(points.xy, points.xy + 2 * points.count);
        return out;
    }
    const int exponent = in.exponent;  // delaunay()'s scale, found while checking the points
    in.spare_points = spare_points;
    in.keep_marks = true;
    delaunay_detail::Mesh mesh = delaunay_detail::incremental_mesh(in);
    std::vector<double> xy = std::move(local_xy);  // the input's order now, in the same room
    xy.reserve(2 * (points.count + spare_points));
    xy.assign(points.xy, points.xy + 2 * points.count);
    delaunay_detail::scale_by_power_of_two(xy, exponent);
    Cdt cdt(std::move(xy), std::move(mesh), in.original, max_added, exponent);
    in = delaunay_detail::Input();
    // Repeated segments (the same two points, either way round: a hole sharing an edge with the
    // outline, a segment given twice) become one with their counts and windings added, in the
    // place of the first: inserted twice, a copy could meet the first one's rounded crossing
    // points as new crossings and leave two chains a rounding apart.
    std::vector<Segment>& merged = segments;
    {
        std::size_t kept = 0;
        for (const Segment& s : segments) {
            Segment piece{out.representative[s.a], out.representative[s.b], s.wind, s.count, s.input};
            if (piece.a == piece.b) continue;
            if (piece.a > piece.b) std::swap(piece.a, piece.b), piece.wind = -piece.wind;
            merged[kept++] = piece;
        }
        merged.resize(kept);
    }
    {
        // Grouped by their lower end (a counting sort, stable: in order within a group); in each
        // group, the first segment to each upper end takes the later ones in.
        const std::size_t n = points.count;
        std::vector<std::uint32_t> start, order, first_to;  // first_to: within the group of `a`, 1 + the first segment to b
        detail::resize_large(start, n + 1);
        detail::resize_large(order, merged.size());
        detail::resize_large(first_to, n);
        for (const Segment& piece : merged) ++start[piece.a];
        for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];  // start[a]: the end of group a
        for (std::size_t k = merged.size(); k-- > 0;) order[--start[merged[k].a]] = static_cast<std::uint32_t>(k);
        for (std::size_t a = 0; a < n; ++a) {
            for (std::uint32_t j = start[a]; j < start[a + 1]; ++j) {
                Segment& piece = merged[order[j]];
                std::uint32_t& first = first_to[piece.b];
                if (first == 0 || merged[first - 1].a != a) {
                    first = order[j] + 1;
                } else {
                    merged[first - 1].wind += piece.wind, merged[first - 1].count += piece.count;
                    piece.count = 0;
                }
            }
        }
    }
    cdt.reserve_segments(merged.size());
    for (const Segment& piece : merged) {
        if (piece.count != 0 && !cdt.insert(piece)) return failure(cdt.error, -1, cdt.error_segment);
    }
    segments = std::vector<Segment>();
    out.crossing_count = cdt.crossings;
    Refiner refiner(cdt);
    // Scaled as the points are (exact: powers of two).
    auto scaled = [&](const std::vector<double>& xy) {
        std::vector<double> s(xy);
        delaunay_detail::scale_by_power_of_two(s, exponent);
        return s;
    };
    std::vector<double> region_xy;
    std::vector<double> area2(1, 0.0);  // per region id: 0 outside the domain
    const double global = std::ldexp(2 * domain.quality.max_area, 2 * exponent);
    area2.push_back(global);
    if (domain.regions) {
        for (const RegionSeed& r : *domain.regions) {
            region_xy.push_back(r.x), region_xy.push_back(r.y);
            const double own = std::ldexp(2 * r.max_area, 2 * exponent);
            area2.push_back(own > 0 && (global == 0 || own < global) ? own : global);
        }
    }
    if (domain.mesh_corners) {
        for (double a : *domain.triangle_areas) {
            const double own = a > 0 ? std::ldexp(2 * a, 2 * exponent) : 0.0;
            area2.push_back(own > 0 && (global == 0 || own < global) ? own : global);
        }
        std::vector<std::uint32_t> corners(*domain.mesh_corners);
        for (std::uint32_t& c : corners) c = out.representative[c];
        const std::int64_t missing = refiner.mark_triangles(corners);
        if (missing >= 0 && static_cast<std::size_t>(missing) < corners.size() / 3) {
            ConstrainedDelaunay bad = failure("triangle " + std::to_string(missing) +
                                              " is not a face of the mesh its edges make: a corner of another triangle "
                                              "lies on one of its edges or inside it, or triangles overlap");
            bad.error_triangle = missing;
            return bad;
        }
        if (missing >= 0) {
            return failure("the triangles leave a hole that their edges enclose, or overlap: the mesh is not a "
                           "triangulation of its region");
        }
    } else if (domain.polygon) {
        refiner.mark_polygon(domain.fill);
    } else {
        refiner.mark_graph(domain.remove_exterior, domain.holes ? scaled(*domain.holes) : std::vector<double>(), scaled(region_xy));
    }
    const bool regional_area = std::any_of(area2.begin(), area2.end(), [](double a) { return a > 0; });
    if (domain.quality.active() || regional_area) {
        if (!refiner.refine(domain.quality, area2, exponent)) return failure(refiner.error);
        out.steiner_count = refiner.steiner_count;
        out.unrefined_count = refiner.unrefined_count;
    }
    const bool regions = domain.mesh_corners || (!domain.polygon && domain.regions && !domain.regions->empty());
    cdt.write_and_release(points, out, regions, Refiner::kDomain + 1);
    return out;
}

}  // namespace

ConstrainedDelaunay constrained_delaunay(PointSpan2 points, const std::uint32_t* segments, std::size_t segment_count,
                                         const ConstrainedOptions& options) {
    if (points.count > std::numeric_limits<std::uint32_t>::max() / 8)
        return failure("too many points: " + std::to_string(points.count));
    std::vector<Segment> list;
    list.reserve(segment_count);
    for (std::size_t k = 0; k < segment_count; ++k) {
        const std::uint32_t a = segments[2 * k], b = segments[2 * k + 1];
        if (a >= points.count || b >= points.count) {
            return failure("segment " + std::to_string(k) + " joins points " + std::to_string(a) + " and " +
                               std::to_string(b) + ", but there are " + std::to_string(points.count) + " points",
                           -1, static_cast<std::int64_t>(k));
        }
        list.push_back({a, b, 1, 1, static_cast<std::uint32_t>(k)});
    }
    if (options.holes.size() % 2 != 0) return failure("holes must be x y pairs (got " + std::to_string(options.holes.size()) + " numbers)");
    for (std::size_t h = 0; h < options.holes.size(); ++h) {
        if (!std::isfinite(options.holes[h])) return failure("hole point " + std::to_string(h / 2) + " is not finite");
    }
    Domain domain;
    domain.remove_exterior = options.remove_exterior;
    domain.holes = &options.holes;
    domain.regions = &options.regions;
    domain.quality = options.quality;
    return build(points, std::move(list), domain, options.max_added_points);
}

ConstrainedDelaunay triangulate_polygon(PointSpan2 points, const std::uint32_t* ring_starts, std::size_t ring_count,
                                        const PolygonOptions& options) {
    if (points.count > std::numeric_limits<std::uint32_t>::max() / 8)
        return failure("too many points: " + std::to_string(points.count));
    std::vector<Segment> list;
    detail::reserve_populated(list, points.count, points.count);
    std::size_t begin = 0;
    for (std::size_t r = 0; r <= ring_count; ++r) {
        const std::size_t end = r < ring_count ? ring_starts[r] : points.count;
        if (end < begin || end > points.count) {
            return failure("ring " + std::to_string(r + 1) + " starts at point " + std::to_string(end) +
                           ", before ring " + std::to_string(r) + " (which starts at " + std::to_string(begin) +
                           ") or past the " + std::to_string(points.count) + " points");
        }
        // A closed ring repeats its first point at the end: the closing edge then has length 0.
        for (std::size_t i = begin; i < end; ++i) {
            const std::size_t j = i + 1 < end ? i + 1 : begin;
            list.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), 1, 1, static_cast<std::uint32_t>(i)});
        }
        begin = end;
    }
    Domain domain;
    domain.polygon = true;
    domain.fill = options.fill;
    domain.quality = options.quality;
    return build(points, std::move(list), domain, options.max_added_points);
}

ConstrainedDelaunay refine_mesh(PointSpan2 points, const std::uint32_t* triangles, std::size_t triangle_count,
                                const std::uint32_t* segments, std::size_t segment_count,
                                const RefineMeshOptions& options) {
    const std::size_t n = points.count;
    if (n > std::numeric_limits<std::uint32_t>::max() / 8) return failure("too many points: " + std::to_string(n));
    if (triangle_count == 0) return failure("there are no triangles to refine");
    auto blame = [](ConstrainedDelaunay out, std::size_t t) {
        out.error_triangle = static_cast<std::int64_t>(t);
        return out;
    };
    if (!options.triangle_max_area.empty() && options.triangle_max_area.size() != triangle_count) {
        return failure("triangle_max_area holds " + std::to_string(options.triangle_max_area.size()) +
                       " numbers for " + std::to_string(triangle_count) + " triangles");
    }
    for (std::size_t t = 0; t < options.triangle_max_area.size(); ++t) {
        if (std::isnan(options.triangle_max_area[t]) || std::isinf(options.triangle_max_area[t])) {
            return blame(failure("triangle " + std::to_string(t) + ": its max_area is not a finite number"), t);
        }
    }
    // Indices first; then only the points the triangles and segments use go on (in input order).
    std::vector<std::uint32_t> local(n, std::numeric_limits<std::uint32_t>::max());
    for (std::size_t t = 0; t < triangle_count; ++t) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = triangles[3 * t + k];
            if (v >= n) {
                return blame(failure("triangle " + std::to_string(t) + " has corner " + std::to_string(v) +
                                     ", but there are " + std::to_string(n) + " points"), t);
            }
            local[v] = 0;
        }
    }
    for (std::size_t k = 0; k < 2 * segment_count; ++k) {
        if (segments[k] >= n) {
            return failure("segment " + std::to_string(k / 2) + " joins points " + std::to_string(segments[k - k % 2]) + " and " +
                               std::to_string(segments[k - k % 2 + 1]) + ", but there are " + std::to_string(n) + " points",
                           -1, static_cast<std::int64_t>(k / 2));
        }
        local[segments[k]] = 0;
    }
    std::vector<std::uint32_t> used;
    std::vector<double> xy;
    for (std::uint32_t i = 0; i < n; ++i) {
        if (local[i] != 0) continue;
        local[i] = static_cast<std::uint32_t>(used.size());
        used.push_back(i);
        xy.push_back(points[i][0]), xy.push_back(points[i][1]);
    }
    const std::size_t m = used.size();
    // Back to the input's numbering: used point k is used[k], added point m + j is n + j.
    auto renumbered = [&](ConstrainedDelaunay sub) {
        if (!sub.ok()) {
            if (sub.error_point >= 0 && static_cast<std::size_t>(sub.error_point) < m) sub.error_point = used[sub.error_point];
            if (sub.error_segment >= static_cast<std::int64_t>(segment_count)) sub.error_segment = -1;
            return sub;
        }
        std::vector<double> coords(points.xy, points.xy + 2 * n);
        coords.insert(coords.end(), sub.coords.begin() + 2 * m, sub.coords.end());
        sub.coords = std::move(coords);
        sub.input_count = n;
        for (std::uint32_t& v : sub.triangles) v = v < m ? used[v] : static_cast<std::uint32_t>(n + (v - m));
        std::vector<std::uint32_t> representative(n);
        for (std::uint32_t i = 0; i < n; ++i) representative[i] = i;
        for (std::size_t k = 0; k < m; ++k) representative[used[k]] = used[sub.representative[k]];
        sub.representative = std::move(representative);
        return sub;
    };
    Domain domain;
    domain.polygon = true;
    domain.fill = FillRule::EvenOdd;
    domain.quality = options.quality;
    // Points the triangulation refuses (not finite, too spread for exact tests) fail there, named;
    // otherwise the checks below decide on the points scaled as it scales them (a power of two:
    // no product underflows).
    int exponent = 0;
    if (!delaunay_detail::scale_exponent(PointSpan2(xy.data(), m), &exponent)) {
        return renumbered(build(PointSpan2(xy.data(), m), {}, domain, options.max_added_points));
    }
    auto scaled = [&](std::uint32_t i, int axis) { return exponent == 0 ? points[i][axis] : std::ldexp(points[i][axis], exponent); };
    // Areas (exact orient2d) and each directed edge (counter-clockwise, by coordinates: copies of a
    // point are one point) in at most one triangle.
    std::vector<std::uint32_t> id(n);  // per used point: the lowest index with its coordinates
    delaunay_detail::lowest_copies(points, used, id);
    std::vector<std::uint32_t> corners(3 * triangle_count);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> directed;  // (from << 32 | to, half-edge 3t + k)
    directed.reserve(3 * triangle_count);
    for (std::size_t t = 0; t < triangle_count; ++t) {
        std::uint32_t v[3] = {triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]};
        const int o = orient2d(scaled(v[0], 0), scaled(v[0], 1), scaled(v[1], 0), scaled(v[1], 1), scaled(v[2], 0), scaled(v[2], 1));
        if (o == 0) {
            return blame(failure("triangle " + std::to_string(t) + " (points " + std::to_string(v[0]) + ", " + std::to_string(v[1]) +
                                 ", " + std::to_string(v[2]) + ") has no area: its corners are collinear or repeated"), t);
        }
        if (o < 0) std::swap(v[1], v[2]);
        for (int k = 0; k < 3; ++k) {
            corners[3 * t + k] = v[k];
            directed.push_back({(std::uint64_t{id[v[k]]} << 32) | id[v[(k + 1) % 3]], static_cast<std::uint32_t>(3 * t + k)});
        }
    }
    std::sort(directed.begin(), directed.end());
    for (std::size_t k = 1; k < directed.size(); ++k) {
        if (directed[k].first == directed[k - 1].first) {
            const std::uint32_t a = static_cast<std::uint32_t>(directed[k].first >> 32), b = static_cast<std::uint32_t>(directed[k].first);
            return blame(failure("triangles " + std::to_string(directed[k - 1].second / 3) + " and " + std::to_string(directed[k].second / 3) +
                                 " overlap: both have the edge from point " + std::to_string(a) + " to point " + std::to_string(b) +
                                 " on the same side"), directed[k].second / 3);
        }
    }
    // The boundary: directed edges whose reverse no triangle has (counted once, so that even-odd
    // takes the inside); every edge instead when each triangle has its own bound (an inner edge
    // then comes twice: even, no change of side). Given segments count twice (kept, no change of side).
    const bool per_triangle = !options.triangle_max_area.empty();
    std::vector<Segment> list;
    std::uint32_t position = 0;
    for (std::size_t k = 0; k < segment_count; ++k)
        list.push_back({local[segments[2 * k]], local[segments[2 * k + 1]], 0, 2, position++});
    // The sorted edges leaving each point (by id) are a run: where each run starts.
    std::vector<std::uint32_t> run_start(n + 1, 0);
    for (const auto& edge : directed) ++run_start[(edge.first >> 32) + 1];
    for (std::size_t i = 0; i < n; ++i) run_start[i + 1] += run_start[i];
    auto has_edge = [&](std::uint64_t from, std::uint64_t to) {
        for (std::uint32_t k = run_start[from]; k < run_start[from + 1]; ++k)
            if ((directed[k].first & 0xffffffffu) == to) return true;
        return false;
    };
    for (std::size_t e = 0; e < directed.size(); ++e) {
        const std::uint64_t key = directed[e].first;
        const bool inner = has_edge(key & 0xffffffffu, key >> 32);
        if (inner && !per_triangle) continue;
        // The triangle's own corners (not the lowest copies).
        const std::uint32_t h = directed[e].second, next = h % 3 == 2 ? h - 2 : h + 1;
        list.push_back({local[corners[h]], local[corners[next]], 1, 1, position++});
    }
    std::vector<std::uint32_t> mesh_corners;
    if (per_triangle) {
        mesh_corners.resize(corners.size());
        for (std::size_t k = 0; k < corners.size(); ++k) mesh_corners[k] = local[corners[k]];
        domain.mesh_corners = &mesh_corners;
        domain.triangle_areas = &options.triangle_max_area;
    }
    return renumbered(build(PointSpan2(xy.data(), m), std::move(list), domain, options.max_added_points));
}

const char* fill_rule_name(FillRule fill) { return fill == FillRule::EvenOdd ? "evenodd" : "nonzero"; }

bool parse_fill_rule(const std::string& name, FillRule* out) {
    if (name == "evenodd") *out = FillRule::EvenOdd;
    else if (name == "nonzero") *out = FillRule::NonZero;
    else return false;
    return true;
}

}  // namespace hullkit
