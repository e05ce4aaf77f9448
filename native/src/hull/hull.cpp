// hullkit::hull: checks and scales the input, settles its dimension exactly, runs the chosen 3D
// algorithm and brings every result into one canonical form.
#include "hullkit/hull.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <glm/glm.hpp>

#include "hull_internal.hpp"
#include "parallel.hpp"
#include "hullkit/giftwrap.hpp"
#include "hullkit/predicates.hpp"
#include "planar.hpp"
#include "sides.hpp"

namespace hullkit {

namespace detail {

Hull failure(std::string message, std::int64_t point) {
    Hull result;
    result.error = std::move(message);
    result.error_point = point;
    return result;
}

std::vector<std::uint32_t>::iterator sort_dropping_repeats(PointSpan points, std::vector<std::uint32_t>::iterator first,
                                                           std::vector<std::uint32_t>::iterator last) {
    std::sort(first, last, [&](std::uint32_t a, std::uint32_t b) {
        const double* p = points[a];
        const double* q = points[b];
        if (p[0] != q[0]) return p[0] < q[0];
        if (p[1] != q[1]) return p[1] < q[1];
        if (p[2] != q[2]) return p[2] < q[2];
        return a < b;
    });
    return std::unique(first, last, [&](std::uint32_t a, std::uint32_t b) {  // keeps the first: the lowest index
        const double* p = points[a];
        const double* q = points[b];
        return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
    });
}

std::vector<std::uint32_t> distinct_points(PointSpan points) {
    std::vector<std::uint32_t> kept(points.count);
    std::iota(kept.begin(), kept.end(), 0u);
    kept.erase(sort_dropping_repeats(points, kept.begin(), kept.end()), kept.end());
    std::sort(kept.begin(), kept.end());
    return kept;
}

std::vector<Extremes> block_extremes(PointSpan points, unsigned threads) {
    // Running values in locals: stores into a struct could alias the points, so the compiler
    // would keep them in memory.
    const auto n = static_cast<std::uint32_t>(points.count);
    const std::size_t blocks = (n + kExtremesBlock - 1) / kExtremesBlock;
    std::vector<Extremes> found(blocks);
    parallel_for(threads, blocks, [&](std::size_t block) {
        Extremes e;
        for (int k = 0; k < 14; ++k) e.best_value[k] = -std::numeric_limits<double>::infinity(), e.extreme_of[k] = 0;
        const std::uint32_t first = static_cast<std::uint32_t>(block * kExtremesBlock);
        const std::uint32_t last = static_cast<std::uint32_t>(std::min<std::size_t>(n, (block + 1) * kExtremesBlock));
        for (int axis = 0; axis < 3; ++axis) e.lo[axis] = e.hi[axis] = points[first][axis];
        for (std::uint32_t i = first; i < last; ++i) {
            const double* p = points[i];
            const double value[7] = {p[0], p[1], p[2], p[0] + p[1] + p[2], p[0] + p[1] - p[2], p[0] - p[1] + p[2], p[0] - p[1] - p[2]};
            for (int k = 0; k < 7; ++k) {
                if (value[k] > e.best_value[2 * k]) e.best_value[2 * k] = value[k], e.extreme_of[2 * k] = i;
                if (-value[k] > e.best_value[2 * k + 1]) e.best_value[2 * k + 1] = -value[k], e.extreme_of[2 * k + 1] = i;
            }
            for (int axis = 0; axis < 3; ++axis) {
                e.lo[axis] = std::min(e.lo[axis], p[axis]);
                e.hi[axis] = std::max(e.hi[axis], p[axis]);
            }
        }
        found[block] = e;
    });
    return found;
}

Extremes merged_extremes(const std::vector<Extremes>& blocks, std::size_t first, std::size_t last, std::uint32_t base) {
    // In order: a later block wins only when strictly better, so ties still go to the lowest index.
    Extremes all = blocks[first];
    for (std::size_t block = first + 1; block < last; ++block) {
        const Extremes& e = blocks[block];
        for (int k = 0; k < 14; ++k) {
            if (e.best_value[k] > all.best_value[k]) all.best_value[k] = e.best_value[k], all.extreme_of[k] = e.extreme_of[k];
        }
        for (int axis = 0; axis < 3; ++axis) {
            all.lo[axis] = std::min(all.lo[axis], e.lo[axis]);
            all.hi[axis] = std::max(all.hi[axis], e.hi[axis]);
        }
    }
    for (std::uint32_t& i : all.extreme_of) i -= base;
    return all;
}

Simplex find_simplex(PointSpan points, unsigned threads) {
    if (points.count == 0) return Simplex{};
    const std::vector<Extremes> blocks = block_extremes(points, threads);
    return simplex_from(points, merged_extremes(blocks, 0, blocks.size(), 0));
}

Simplex simplex_from(PointSpan points, const Extremes& all) {
    Simplex s;
    const auto n = static_cast<std::uint32_t>(points.count);
    if (n == 0) return s;
    auto at = [&](std::uint32_t i) { return vec3(points[i]); };
    std::copy(all.extreme_of, all.extreme_of + 14, s.extreme);
    std::copy(all.lo, all.lo + 3, s.lo);
    std::copy(all.hi, all.hi + 3, s.hi);
    const std::uint32_t* extreme = s.extreme;

    // The farthest pair of extremes (rounded distances choose; equality of points is exact).
    double best = -1.0;
    for (int i = 0; i < 14; ++i) {
        for (int j = i + 1; j < 14; ++j) {
            const glm::dvec3 d = at(extreme[j]) - at(extreme[i]);
            if (const double d2 = glm::dot(d, d); d2 > best) {
                best = d2;
                s.p[0] = std::min(extreme[i], extreme[j]);
                s.p[1] = std::max(extreme[i], extreme[j]);
            }
        }
    }
    s.dimension = 0;
    const double* a = points[s.p[0]];
    const double* b = points[s.p[1]];
    if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) {  // the bounding box is a point
        s.p[0] = 0;
        return s;
    }
    s.dimension = 1;

    // The extreme farthest from the line a-b, else the first point off it (exactly).
    const glm::dvec3 pa = at(s.p[0]);
    const glm::dvec3 ab = at(s.p[1]) - pa;
    best = -1.0;
    for (std::uint32_t e : s.extreme) {
        const glm::dvec3 c = glm::cross(ab, at(e) - pa);
        if (const double c2 = glm::dot(c, c); c2 > best || (c2 == best && e < s.p[2])) {
            best = c2;
            s.p[2] = e;
        }
    }
    if (collinear3d(a, b, points[s.p[2]])) {
        std::uint32_t i = 0;
        while (i < n && collinear3d(a, b, points[i])) ++i;
        if (i == n) return s;
        s.p[2] = i;
    }
    s.dimension = 2;

    // The extreme farthest from the plane a, b, c, else the first point off it (exactly).
    const double* c = points[s.p[2]];
    const glm::dvec3 normal = glm::cross(ab, at(s.p[2]) - pa);
    best = -1.0;
    for (std::uint32_t e : s.extreme) {
        if (const double h = std::fabs(glm::dot(normal, at(e) - pa)); h > best || (h == best && e < s.p[3])) {
            best = h;
            s.p[3] = e;
        }
    }
    if (orient3d(a, b, c, points[s.p[3]]) == 0) {
        std::uint32_t i = 0;
        while (i < n && orient3d(a, b, c, points[i]) == 0) ++i;
        if (i == n) return s;
        s.p[3] = i;
    }
    s.dimension = 3;
    return s;
}


Hull scan_magnitudes(PointSpan points, std::uint64_t first_index, const std::uint64_t* indices, unsigned threads,
                     Magnitudes* range) {
    // Blocks of points scanned in parallel; the first bad point in input order is reported, as a
    // serial scan would.
    constexpr std::size_t kBlock = std::size_t{1} << 16;
    const std::size_t blocks = (points.count + kBlock - 1) / kBlock;
    std::vector<Magnitudes> found(blocks);
    std::vector<std::size_t> bad(blocks, ~std::size_t{0});
    parallel_for(threads, blocks, [&](std::size_t block) {
        Magnitudes m;  // a local, written back once: neighbouring blocks' slots share cache lines
        const std::size_t end = std::min(points.count, (block + 1) * kBlock);
        for (std::size_t i = block * kBlock; i < end; ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                const double magnitude = std::fabs(points[i][axis]);
                if (!(magnitude <= std::numeric_limits<double>::max())) {  // inf or nan
                    bad[block] = i;
                    return;
                }
                m.largest = std::max(m.largest, magnitude);
                if (magnitude != 0.0) m.smallest = std::min(m.smallest, magnitude);
            }
        }
        found[block] = m;
    });
    for (std::size_t block = 0; block < blocks; ++block) {
        if (const std::size_t i = bad[block]; i != ~std::size_t{0}) {
            for (int axis = 0; axis < 3; ++axis) {
                const double value = points[i][axis];
                if (std::fabs(value) <= std::numeric_limits<double>::max()) continue;
                static const char* const kAxis[] = {"x", "y", "z"};
                const char* what = std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
                const std::uint64_t index = indices ? indices[i] : first_index + i;
                return failure("point " + std::to_string(index) + " has a non-finite " + kAxis[axis] +
                                   " coordinate (" + what + ")",
                               static_cast<std::int64_t>(index));
            }
        }
        range->largest = std::max(range->largest, found[block].largest);
        range->smallest = std::min(range->smallest, found[block].smallest);
    }
    return Hull{};
}

Hull scale_exponent(const Magnitudes& range, int* exponent) {
    *exponent = 0;
    if (!predicates_range_ok(range.largest, range.smallest) &&
        !predicates_scale_exponent(range.largest, range.smallest, exponent)) {
        return failure(
            "coordinates span too many orders of magnitude: the nonzero |coordinates| must fit within "
            "a factor of 2^585 (about 1e176) of each other for exact predicates");
    }
    return Hull{};
}

}  // namespace detail

namespace {

using detail::Polygons;
using detail::Simplex;

/// Too many points; else an ok() Hull. Non-finite coordinates and the magnitudes are scanned by
/// detail::scan_magnitudes.
Hull check_input(PointSpan points, unsigned threads, detail::Magnitudes* range) {
    if (points.count > std::numeric_limits<std::uint32_t>::max()) {
        return detail::failure("too many points: " + std::to_string(points.count) +
                               " (at most 4294967295 fit 32-bit indices)");
    }
    return detail::scan_magnitudes(points, 0, nullptr, threads, range);
}

/// Rotates each polygon to start at its lowest index.
void rotate_to_lowest(Polygons& faces, unsigned threads) {
    constexpr std::size_t kBlock = std::size_t{1} << 16;
    detail::parallel_for(threads, (faces.size() + kBlock - 1) / kBlock, [&](std::size_t block) {
        const std::size_t end = std::min(faces.size(), (block + 1) * kBlock);
        for (std::size_t f = block * kBlock; f < end; ++f) {
            const auto first = faces.vertices.begin() + faces.offsets[f];
            const auto last = faces.vertices.begin() + faces.offsets[f + 1];
            std::rotate(first, std::min_element(first, last), last);
        }
    });
}

/// Triangles fanned from each polygon's first corner and the sorted vertex list.
void fill_from_polygons(std::size_t point_count, const Polygons& faces, Hull& hull, unsigned threads = 1) {
    // Polygon f's fan starts at triangle offsets[f] - 2f (an m-gon has m - 2 triangles).
    hull.triangles.clear();
    const std::size_t size = 3 * (faces.vertices.size() - 2 * faces.size());
    detail::reserve_large(hull.triangles, size);
    if (size == faces.vertices.size()) {  // every face a triangle: the fans are the faces
        hull.triangles.assign(faces.vertices.begin(), faces.vertices.end());
    } else {
        hull.triangles.resize(size);
        constexpr std::size_t kBlock = std::size_t{1} << 16;
        detail::parallel_for(threads, (faces.size() + kBlock - 1) / kBlock, [&](std::size_t block) {
            const std::size_t end = std::min(faces.size(), (block + 1) * kBlock);
            for (std::size_t f = block * kBlock; f < end; ++f) {
                const std::uint32_t* corners = &faces.vertices[faces.offsets[f]];
                const std::size_t m = faces.offsets[f + 1] - faces.offsets[f];
                std::uint32_t* out = &hull.triangles[3 * (faces.offsets[f] - 2 * f)];
                for (std::size_t k = 1; k + 1 < m; ++k, out += 3) {
                    out[0] = corners[0];
                    out[1] = corners[k];
                    out[2] = corners[k + 1];
                }
            }
        });
    }
    if (faces.vertices.size() < point_count / 16) {  // few corners: sorting them is cheaper
        hull.vertices.assign(faces.vertices.begin(), faces.vertices.end());
        std::sort(hull.vertices.begin(), hull.vertices.end());
        hull.vertices.erase(std::unique(hull.vertices.begin(), hull.vertices.end()), hull.vertices.end());
        return;
    }
    std::vector<std::uint8_t> is_vertex(point_count, 0);
    for (std::uint32_t v : faces.vertices) is_vertex[v] = 1;
    hull.vertices.clear();
    for (std::uint32_t i = 0; i < point_count; ++i) {
        if (is_vertex[i]) hull.vertices.push_back(i);
    }
}

/// Volume and area measured on points scaled by 2^exponent, given back in the caller's units.
void unscale(int exponent, double volume, double area, Hull& hull) {
    hull.volume = std::ldexp(volume, -3 * exponent);
    hull.area = std::ldexp(area, -2 * exponent);
}

Hull lower_dimensional(PointSpan points, const Simplex& s, int exponent) {
    Hull hull;
    hull.dimension = s.dimension;
    if (s.dimension < 0) return hull;  // no points
    if (s.dimension == 0) {
        hull.vertices = {s.p[0]};
        return hull;
    }
    if (s.dimension == 1) {
        // Along the axis where the segment moves most, coordinates order the points on the line.
        const glm::dvec3 d = glm::abs(detail::vec3(points[s.p[1]]) - detail::vec3(points[s.p[0]]));
        const int axis = d.x >= d.y ? (d.x >= d.z ? 0 : 2) : (d.y >= d.z ? 1 : 2);
        std::uint32_t lo = 0, hi = 0;
        for (std::uint32_t i = 1; i < points.count; ++i) {
            if (points[i][axis] < points[lo][axis]) lo = i;
            if (points[i][axis] > points[hi][axis]) hi = i;
        }
        hull.vertices = {std::min(lo, hi), std::max(lo, hi)};
        return hull;
    }
    // The convex polygon of the points in the plane of the simplex's first three points.
    std::uint32_t a = s.p[0], b = s.p[1], c = s.p[2];
    std::vector<std::uint32_t> all(points.count), polygon;
    std::iota(all.begin(), all.end(), 0u);
    detail::convex_polygon(points, detail::ExactSides{}, std::move(all), a, b, c, polygon);
    // Its orientation and normal from the polygon alone (its lowest corner and that corner's two
    // neighbours), so that they do not depend on which three points spanned the plane: seen from
    // the side where the normal's largest component (x before y before z on ties) is positive,
    // the corners run counter-clockwise. Reversing the polygon negates the rounded cross product
    // exactly, so the axis chosen is the same either way; the exact orient2d decides the side.
    std::rotate(polygon.begin(), std::min_element(polygon.begin(), polygon.end()), polygon.end());
    auto normal = [&] {
        const glm::dvec3 corner = detail::vec3(points[polygon[0]]);
        return glm::cross(detail::vec3(points[polygon[1]]) - corner, detail::vec3(points[polygon.back()]) - corner);
    };
    {
        int i = 0, j = 0;
        if (detail::plane_projection(detail::ExactSides{}, points[polygon[0]], points[polygon[1]], points[polygon.back()],
                                     &i, &j) < 0) {
            std::reverse(polygon.begin() + 1, polygon.end());
        }
    }
    Polygons faces;
    faces.add(polygon.begin(), polygon.end());
    fill_from_polygons(points.count, faces, hull);
    hull.vertices.assign(faces.vertices.begin(), faces.vertices.end());  // in order around the polygon
    double volume = 0.0, area = 0.0;
    detail::measure(points, faces, &volume, &area);
    unscale(exponent, 0.0, area, hull);  // flat: no volume, the area of one side
    const glm::dvec3 unit = glm::normalize(normal());
    std::copy(&unit.x, &unit.x + 3, hull.normal);
    return hull;
}


/// A hull with volume from its faces (counter-clockwise seen from outside) and their measures on
/// points scaled by 2^exponent. `lowest_first`: each face already starts at its lowest index
/// (canonical_order's faces).
Hull polytope(std::size_t point_count, Polygons faces, double volume, double area, int exponent, bool merge_coplanar,
              unsigned threads, bool lowest_first) {
    Hull result;
    result.dimension = 3;
    if (!lowest_first) rotate_to_lowest(faces, threads);
    fill_from_polygons(point_count, faces, result, threads);
    unscale(exponent, volume, area, result);
    if (merge_coplanar) {
        result.face_offsets.assign(faces.offsets.begin(), faces.offsets.end());
        result.face_vertices.assign(faces.vertices.begin(), faces.vertices.end());
    }
    return result;
}

/// The hull of points already in the predicates' range (scaled by 2^exponent from the caller's):
/// one quickhull (or gift wrap) whose passes over all the points (extremes, interior culling,
/// ordering, measures) use up to `threads` threads.
Hull hull_serial(PointSpan points, const HullOptions& options, int exponent, unsigned threads,
                 const Simplex* known = nullptr) {
    Polygons faces;
    double volume = 0.0, area = 0.0;
    std::string error;
    if (options.side_test == SideTest::Seed) {
        // The seed's own behaviour, for comparison: its epsilon also judges degeneracy.
        if (points.count < 4) return detail::failure("a 3D hull needs at least 4 points, got " + std::to_string(points.count));
        if (!detail::giftwrap_faces(points, options.giftwrap_scan, true, faces, error)) return detail::failure(error);
        detail::measure(points, faces, &volume, &area);
    } else {
        const Simplex simplex = known ? *known : detail::find_simplex(points, threads);
        if (simplex.dimension < 3) {
            Hull result = lower_dimensional(points, simplex, exponent);
            if (options.merge_coplanar && result.dimension == 2) {
                result.face_offsets = {0, static_cast<std::uint32_t>(result.vertices.size())};
                result.face_vertices = result.vertices;
            }
            return result;
        }
        if (options.algorithm == Algorithm::Giftwrap) {
            if (!detail::giftwrap_faces(points, options.giftwrap_scan, false, faces, error)) return detail::failure(error);
            detail::measure(points, faces, &volume, &area);
        } else if (!detail::quickhull_faces(points, simplex, faces, &volume, &area, error, threads)) {
            return detail::failure(error);
        }
    }
    // Quickhull's faces come in the canonical order, each from its lowest index; gift wrap's not.
    const bool lowest_first = options.side_test != SideTest::Seed && options.algorithm != Algorithm::Giftwrap;
    return polytope(points.count, std::move(faces), volume, area, exponent, options.merge_coplanar, threads, lowest_first);
}

/// Below this many points per thread, threads do not pay for themselves.
constexpr std::size_t kPointsPerThread = std::size_t{1} << 14;

/// Chunks pay when quickhull proper, which is serial, has much to do: when the interior culling
/// keeps at least this fraction of the points. Measured on 1e7 points: a ball keeps 36% (chunks
/// on 2 threads took 0.6x the serial time), a cube 1% (chunks were slower than the serial
/// quickhull, whose passes over all the points already run on the threads).
constexpr double kChunkWhenKept = 0.15;

}  // namespace

namespace detail {

/// For a large cloud with few hull vertices (a ball, a cube, a scan of a solid): the candidates
/// for the hull's vertices, found as the extreme points of chunks of the input hulled on
/// threads (every extreme point of the whole is extreme in its chunk, and of identical points
/// each chunk keeps its lowest index, so the lowest of all is among them). Ascending. Empty when
/// chunking would not pay: a small input, or one whose points are mostly on the hull (a sphere),
/// judged from a sample of about kSample points spread evenly over the input.
std::vector<std::uint32_t> chunk_candidates(PointSpan points, unsigned threads, bool* surface_like, Simplex* whole) {
    const std::size_t n = points.count;
    *surface_like = false;
    if (whole) whole->dimension = -2;  // not found
    if (threads < 2 || n < 2 * kPointsPerThread) return {};
    std::vector<Extremes> blocks;
    {
        // Enough for the two ratios below (a ball's sample of 8192 has a few hundred hull
        // vertices, a sphere's has all); a fixed size, because this runs on one thread before
        // the threads start: every 64th point of 1e7 (1.5e5 points) took 25 ms of a 150 ms hull.
        constexpr std::size_t kSample = 8192;
        const std::size_t stride = n / kSample;
        std::vector<double> sample;
        sample.reserve(3 * (n / stride + 1));
        for (std::size_t i = 0; i < n; i += stride) sample.insert(sample.end(), points[i], points[i] + 3);
        const PointSpan sampled(sample.data(), sample.size() / 3);
        if (8 * detail::extreme_points(sampled).size() > sampled.count) {
            *surface_like = true;
            return {};
        }
        // When the serial quickhull's interior culling leaves few points (a cube), its work is
        // a few passes over the points, on the threads, which chunks only repeat (see
        // kChunkWhenKept). The culling region comes from the whole cloud's extremes (a
        // sample's lie too far inside: they would keep half of a cube); the sample says how
        // many points it keeps. The extremes' pass is find_simplex's, kept by blocks: the
        // chunks below are whole blocks, and take their own extremes from them.
        blocks = block_extremes(points, threads);
        const Simplex simplex = simplex_from(points, merged_extremes(blocks, 0, blocks.size(), 0));
        if (culling_kept_fraction(points, simplex, sampled) < kChunkWhenKept) {
            if (whole) *whole = simplex;
            return {};
        }
    }
    // One chunk per thread: each chunk's hull has costs that do not shrink with the chunk (its
    // culling hull, sorting buffers, fresh pages), so more, smaller chunks were measured slower.
    // Chunks of whole blocks where there are enough blocks; else each finds its own extremes.
    const std::size_t chunks = std::size_t{threads};
    const bool by_blocks = blocks.size() >= chunks;
    std::vector<std::vector<std::uint32_t>> found(chunks);
    detail::parallel_for(threads, chunks, [&](std::size_t chunk) {
        std::size_t begin = n * chunk / chunks, end = n * (chunk + 1) / chunks;
        if (by_blocks) {
            const std::size_t first = blocks.size() * chunk / chunks, last = blocks.size() * (chunk + 1) / chunks;
            begin = first * kExtremesBlock;
            end = std::min(n, last * kExtremesBlock);
            const PointSpan part(points[begin], end - begin);
            const Simplex simplex = simplex_from(part, merged_extremes(blocks, first, last, static_cast<std::uint32_t>(begin)));
            found[chunk] = detail::extreme_points(part, &simplex);
        } else {
            found[chunk] = detail::extreme_points(PointSpan(points[begin], end - begin));
        }
        for (std::uint32_t& v : found[chunk]) v += static_cast<std::uint32_t>(begin);
    });
    std::vector<std::uint32_t> candidates;
    for (const auto& part : found) candidates.insert(candidates.end(), part.begin(), part.end());
    return candidates;
}


std::vector<std::uint32_t> extreme_points(PointSpan points, const Simplex* known) {
    const Simplex simplex = known ? *known : find_simplex(points);
    std::vector<std::uint32_t> vertices;
    if (simplex.dimension < 3) {
        vertices = lower_dimensional(points, simplex, 0).vertices;
    } else {
        Polygons faces;
        double volume = 0.0, area = 0.0;
        std::string error;
        if (!quickhull_faces(points, simplex, faces, &volume, &area, error)) throw std::logic_error(error);
        vertices.assign(faces.vertices.begin(), faces.vertices.end());
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    return vertices;
}

PointSpan scale_points(PointSpan points, int exponent, unsigned threads, std::vector<double>& storage) {
    if (exponent == 0) return points;
    storage.resize(3 * points.count);  // multiplying by a power of two is exact
    constexpr std::size_t kBlock = std::size_t{1} << 18;
    parallel_for(threads, (storage.size() + kBlock - 1) / kBlock, [&](std::size_t block) {
        const std::size_t end = std::min(storage.size(), (block + 1) * kBlock);
        for (std::size_t i = block * kBlock; i < end; ++i) storage[i] = std::ldexp(points.xyz[i], exponent);
    });
    return PointSpan(storage.data(), points.count);
}

Hull hull_in_range(PointSpan input, const HullOptions& options, int exponent) {
    const bool seed = options.side_test == SideTest::Seed;
    if (seed && options.algorithm != Algorithm::Giftwrap)
        return failure("the seed's epsilon side tests exist for gift wrapping only");
    const unsigned threads = resolve_threads(options.threads, input.count / kPointsPerThread);

    std::vector<double> scaled;
    const PointSpan points = scale_points(input, exponent, threads, scaled);
    if (seed || options.algorithm != Algorithm::Quickhull) return hull_serial(points, options, exponent, threads);

    bool surface_like = false;
    Simplex whole;
    const std::vector<std::uint32_t> candidates = chunk_candidates(points, threads, &surface_like, &whole);
    if (candidates.empty()) {
        // Few points inside the hull: quickhull split across the threads.
        Polygons faces;
        double volume = 0.0, area = 0.0;
        if (surface_like && quickhull_split_faces(points, threads, faces, &volume, &area)) {
            return polytope(points.count, std::move(faces), volume, area, exponent, options.merge_coplanar, threads, true);
        }
        return hull_serial(points, options, exponent, threads, whole.dimension == -2 ? nullptr : &whole);
    }
    // The hull of the candidates, in ascending index order, so that every tie-break (lowest
    // index) and the canonical order come out as for the whole cloud.
    std::vector<double> xyz(3 * candidates.size());
    for (std::size_t k = 0; k < candidates.size(); ++k) std::copy(points[candidates[k]], points[candidates[k]] + 3, &xyz[3 * k]);
    scaled = {};
    Hull result = hull_serial(PointSpan(xyz.data(), candidates.size()), options, exponent, threads);
    for (auto* list : {&result.triangles, &result.vertices, &result.face_vertices}) {
        for (std::uint32_t& v : *list) v = candidates[v];
    }
    return result;
}

}  // namespace detail

Hull hull(PointSpan input, const HullOptions& options) {
    detail::Magnitudes range;
    const unsigned threads = detail::resolve_threads(options.threads, input.count / kPointsPerThread);
    if (Hull invalid = check_input(input, threads, &range); !invalid.ok()) return invalid;
    int exponent = 0;
    if (Hull invalid = detail::scale_exponent(range, &exponent); !invalid.ok()) return invalid;
    return detail::hull_in_range(input, options, exponent);
}

Hull giftwrap(PointSpan points, GiftwrapScan scan) {
    HullOptions options;
    options.algorithm = Algorithm::Giftwrap;
    options.giftwrap_scan = scan;
    return hull(points, options);
}

const char* algorithm_name(Algorithm algorithm) {
    switch (algorithm) {
        case Algorithm::Quickhull:
            return "quickhull";
        case Algorithm::Giftwrap:
            return "giftwrap";
    }
    return "unknown";
}

bool parse_algorithm(const std::string& name, Algorithm* out) {
    if (name == "quickhull") {
        *out = Algorithm::Quickhull;
        return true;
    }
    if (name == "giftwrap") {
        *out = Algorithm::Giftwrap;
        return true;
    }
    return false;
}

}  // namespace hullkit
