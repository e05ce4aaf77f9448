// hullkit::delaunay: input checks, exact duplicates, dimension, then one algorithm's Delaunay faces
// turned into delaunator-style output by one rule shared by every algorithm.
//
// The canonical rule (documented in delaunay.hpp and the README):
//  * every Delaunay face (a maximal set of cocircular points with an empty circle; a triangle for
//    points in general position) is fanned from its LOWEST index: with corners c_0 (the lowest)
//    ... c_m-1 in order around the face, the triangles are (c_0, c_k, c_k+1). Corners of a face lie
//    on one circle, so they are in strictly convex position and no fan triangle has zero area;
//  * each triangle is written clockwise with y up (delaunator's orientation), starting at its
//    lowest index;
//  * triangles are ordered by the position of their first corner, then of their second, along a
//    Hilbert curve over the input's bounding box (ties between points with one curve key by
//    index); this order depends only on the input and keeps neighbouring triangles near each other
//    in memory, which is what makes the output stage fast;
//  * `hull` starts at its lowest index and follows the boundary half-edges' direction.
// The faces are unique, so every algorithm returns identical arrays.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <system_error>
#include <thread>

#include "delaunay_internal.hpp"
#include "hull/large_array.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit {
namespace {

using delaunay_detail::Faces;

Delaunay failure(std::string message, std::int64_t point = -1) {
    Delaunay d;
    d.error = std::move(message);
    d.error_point = point;
    return d;
}

/// The input's extent, found while checking it.
struct Extent {
    double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
    int exponent = 0;  ///< power of two bringing the coordinates into incircle's exact range
};

/// Rejects non-finite coordinates and too many points; finds the bounding box and the scale.
Delaunay check_input(PointSpan2 points, Extent* extent) {
    if (points.count > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / 6)) {
        return failure("too many points: " + std::to_string(points.count) +
                       " (at most 357913941, so that half-edge indices fit in 32 bits)");
    }
    double largest = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
    std::size_t largest_at = 0, smallest_at = 0;
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
    for (std::size_t i = 0; i < points.count; ++i) {
        for (int axis = 0; axis < 2; ++axis) {
            const double value = points[i][axis];
            const double magnitude = std::fabs(value);
            if (!(magnitude <= std::numeric_limits<double>::max())) {  // inf or nan
                const char* what = std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
                return failure("point " + std::to_string(i) + " has a non-finite " + (axis == 0 ? "x" : "y") +
                                   " coordinate (" + what + ")",
                               static_cast<std::int64_t>(i));
            }
            if (magnitude > largest) largest = magnitude, largest_at = i;
            if (magnitude != 0.0 && magnitude < smallest) smallest = magnitude, smallest_at = i;
        }
        xmin = std::min(xmin, points[i][0]), xmax = std::max(xmax, points[i][0]);
        ymin = std::min(ymin, points[i][1]), ymax = std::max(ymax, points[i][1]);
    }
    *extent = Extent{xmin, xmax, ymin, ymax, 0};
    if (!incircle_range_ok(largest, smallest) && !incircle_scale_exponent(largest, smallest, &extent->exponent)) {
        return failure("coordinates span too many orders of magnitude for exact in-circle tests: point " +
                           std::to_string(smallest_at) + " (smallest nonzero |coordinate|) and point " +
                           std::to_string(largest_at) + " (largest) must be within a factor of 2^410 (about 1e123)",
                       static_cast<std::int64_t>(smallest_at));
    }
    return Delaunay{};
}

/// Index along a Hilbert curve on a 2^16 x 2^16 grid, 4 levels per step from a table. The curve:
/// at each level (from the top bit), with rx, ry the bits of the current (transformed) x and y, the
/// digit is (3 * rx) ^ ry, and when ry == 0 the quadrant is rotated for the levels below (both
/// coordinates complemented when rx == 1, then swapped). The transform so far is one of 4 (swap or
/// not, complement or not; they commute): the table's state. Checked against the bit-by-bit loop
/// (the curve fixes the canonical output order, so it must not change).
struct HilbertTable {
    std::uint16_t entry[4 * 256];  ///< [state * 256 + (4 bits of x) << 4 | (4 of y)]: digits << 2 | next state
};
constexpr HilbertTable make_hilbert_table() {
    HilbertTable table{};
    for (std::uint32_t state = 0; state < 4; ++state) {
        for (std::uint32_t bits = 0; bits < 256; ++bits) {
            std::uint32_t swap = state & 1, complement = state >> 1, digits = 0;
            for (int level = 3; level >= 0; --level) {
                const std::uint32_t bx = (bits >> (4 + level)) & 1, by = (bits >> level) & 1;
                const std::uint32_t rx = (swap ? by : bx) ^ complement;
                const std::uint32_t ry = (swap ? bx : by) ^ complement;
                digits = (digits << 2) | ((3 * rx) ^ ry);
                if (ry == 0) complement ^= rx, swap ^= 1;
            }
            table.entry[state * 256 + bits] = static_cast<std::uint16_t>(digits << 2 | complement << 1 | swap);
        }
    }
    return table;
}
constexpr HilbertTable kHilbertTable = make_hilbert_table();
std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y) {
    std::uint32_t d = 0, state = 0;
    for (int shift = 12; shift >= 0; shift -= 4) {
        const std::uint32_t bits = ((x >> shift) & 15u) << 4 | ((y >> shift) & 15u);
        const std::uint32_t e = kHilbertTable.entry[state * 256 + bits];
        d = d << 8 | e >> 2;
        state = e & 3u;
    }
    return d;
}

/// From the Hilbert order: merges exact duplicates (filling `representative`, `duplicate_count`)
/// and stores the distinct points contiguously in that order, scaled by 2^exponent.
void gather_distinct(PointSpan2 p, const Extent& box, Delaunay& out, std::vector<double>& local_xy,
                     std::vector<std::uint32_t>& original) {
    const double lo[2] = {box.xmin, box.ymin}, hi[2] = {box.xmax, box.ymax};
    std::vector<std::uint64_t> keyed = delaunay_detail::hilbert_order(p, lo, hi);
    const std::size_t n = p.count;
    // Every point's coordinates in curve order (one pass of scattered reads), then all work is
    // sequential. Distinct points are compacted into the front of the same arrays.
    std::vector<std::uint32_t> order;
    detail::resize_large(order, n);
    detail::resize_large(local_xy, 2 * n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t i = static_cast<std::uint32_t>(keyed[k]);
        order[k] = i;
        local_xy[2 * k] = p[i][0];
        local_xy[2 * k + 1] = p[i][1];
    }
    // Every point represents itself (a sequential fill) unless the loop below finds it a duplicate:
    // writing each entry there would scatter a write per point across the input-ordered array.
    detail::resize_large(out.representative, n);
    std::iota(out.representative.begin(), out.representative.end(), 0u);
    original.clear();
    detail::reserve_populated(original, n, n);
    std::size_t distinct = 0;  // distinct points so far, at the front of local_xy
    auto same_as = [&](std::size_t k, std::size_t j) {  // point at curve position k vs distinct j
        return local_xy[2 * k] == local_xy[2 * j] && local_xy[2 * k + 1] == local_xy[2 * j + 1];
    };
    for (std::size_t begin = 0; begin < n;) {
        std::size_t end = begin + 1;
        while (end < n && (keyed[end] >> 32) == (keyed[begin] >> 32)) ++end;
        const std::size_t first_distinct = distinct;
        if (end - begin > 16) {
            // A long run of one key (many duplicates or a very dense spot): sort it by
            // (x, y, index) so that duplicates are adjacent.
            std::vector<std::size_t> run(end - begin);
            std::iota(run.begin(), run.end(), begin);
            std::sort(run.begin(), run.end(), [&](std::size_t a, std::size_t b) {
                const double ax = local_xy[2 * a], ay = local_xy[2 * a + 1], bx = local_xy[2 * b], by = local_xy[2 * b + 1];
                return ax < bx || (ax == bx && (ay < by || (ay == by && order[a] < order[b])));
            });
            std::vector<double> xy(2 * run.size());
            std::vector<std::uint32_t> ids(run.size());
            for (std::size_t r = 0; r < run.size(); ++r) {
                xy[2 * r] = local_xy[2 * run[r]], xy[2 * r + 1] = local_xy[2 * run[r] + 1];
                ids[r] = order[run[r]];
            }
            for (std::size_t r = 0; r < run.size(); ++r) {
                local_xy[2 * (begin + r)] = xy[2 * r], local_xy[2 * (begin + r) + 1] = xy[2 * r + 1];
                order[begin + r] = ids[r];
            }
        }
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t i = order[k];
            std::size_t match = distinct;
            for (std::size_t j = end - begin > 16 ? (distinct > first_distinct ? distinct - 1 : distinct) : first_distinct;
                 j < distinct; ++j) {
                if (same_as(k, j)) {
                    match = j;
                    break;
                }
            }
            if (match < distinct) {  // indices ascend within a run, so the first one represents
                out.representative[i] = original[match];
                ++out.duplicate_count;
            } else {
                local_xy[2 * distinct] = local_xy[2 * k];
                local_xy[2 * distinct + 1] = local_xy[2 * k + 1];
                original.push_back(i);
                ++distinct;
            }
        }
        begin = end;
    }
    local_xy.resize(2 * distinct);
    delaunay_detail::scale_by_power_of_two(local_xy, box.exponent);
}

/// Output triangles in local indices, one fan per face from the corner with the lowest ORIGINAL
/// index, each clockwise and starting at that corner. When the faces are triangles with known
/// twins, also returns the output twins in *twins (otherwise leaves it empty).
std::vector<std::uint32_t> fan_faces(const Faces& faces, const std::vector<std::uint32_t>& original,
                                     std::vector<std::int32_t>* twins) {
    std::size_t triangle_count = 0;
    for (std::size_t f = 0; f < faces.size(); ++f) triangle_count += faces.corners(f) - 2;
    std::vector<std::uint32_t> triangles(3 * triangle_count);
    std::vector<std::uint8_t> low_of;
    if (!faces.twin.empty()) low_of.resize(faces.size());
    std::size_t t = 0;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const std::uint32_t* c = &faces.vertices[faces.begin(f)];
        const std::size_t m = faces.corners(f);
        std::size_t low = 0;
        for (std::size_t k = 1; k < m; ++k)
            if (original[c[k]] < original[c[low]]) low = k;
        if (!low_of.empty()) low_of[f] = static_cast<std::uint8_t>(low);
        for (std::size_t k = 1; k + 1 < m; ++k, ++t) {
            // Counter-clockwise fan triangle (c_low, c_k, c_k+1) written clockwise.
            triangles[3 * t] = c[low];
            triangles[3 * t + 1] = c[(low + k + 1) % m];
            triangles[3 * t + 2] = c[(low + k) % m];
        }
    }
    twins->clear();
    if (!low_of.empty()) {
        // Output edge j of face f runs backwards along the face's edge (low + 2 - j) mod 3, so
        // face edge k is output edge (low + 2 - k) mod 3.
        twins->resize(triangles.size());
        for (std::size_t f = 0; f < faces.size(); ++f) {
            for (std::size_t j = 0; j < 3; ++j) {
                const std::int32_t g = faces.twin[3 * f + (low_of[f] + 2 - j) % 3];
                if (g < 0) {
                    (*twins)[3 * f + j] = -1;
                    continue;
                }
                const std::size_t h = static_cast<std::size_t>(g) / 3;
                const std::size_t k = static_cast<std::size_t>(g) % 3;
                (*twins)[3 * f + j] = static_cast<std::int32_t>(3 * h + (low_of[h] + 5 - k) % 3);
            }
        }
    }
    return triangles;
}

/// Half-edge twins: each half-edge is matched with its reverse among the half-edges leaving its end
/// vertex (grouped by start vertex with a counting sort). Local indices keep this cache-friendly.
std::vector<std::int32_t> match_halfedges(std::size_t point_count, const std::vector<std::uint32_t>& triangles) {
    const std::size_t edges = triangles.size();
    std::vector<std::uint32_t> start(point_count + 1, 0);
    for (std::size_t e = 0; e < edges; ++e) ++start[triangles[e] + 1];
    for (std::size_t i = 0; i < point_count; ++i) start[i + 1] += start[i];
    std::vector<std::uint32_t> by_start(edges);
    for (std::size_t e = 0; e < edges; ++e) by_start[start[triangles[e]]++] = static_cast<std::uint32_t>(e);
    // start[i] now is the end of i's group, i.e. the beginning of group i + 1.
    auto next = [](std::size_t e) { return e % 3 == 2 ? e - 2 : e + 1; };
    std::vector<std::int32_t> halfedges(edges, -1);
    for (std::size_t e = 0; e < edges; ++e) {
        if (halfedges[e] != -1) continue;
        const std::uint32_t from = triangles[e], to = triangles[next(e)];
        for (std::uint32_t k = to == 0 ? 0 : start[to - 1]; k < start[to]; ++k) {
            const std::uint32_t f = by_start[k];
            if (triangles[next(f)] == from) {
                halfedges[e] = static_cast<std::int32_t>(f);
                halfedges[f] = static_cast<std::int32_t>(e);
                break;
            }
        }
    }
    return halfedges;
}

/// Writes triangles and half-edges in the canonical order: sorted by the Hilbert position (local
/// index) of their first corner, then of their second (a counting sort by the first, then each
/// small bucket by the second). The positions depend only on the input, so every algorithm gets
/// the same order, and neighbouring triangles stay near each other in memory.
void write_canonical(const std::vector<std::uint32_t>& local, const std::vector<std::int32_t>& twins,
                     const std::vector<std::uint32_t>& original, Delaunay& out) {
    const std::size_t count = local.size() / 3;
    const std::size_t m = original.size();
    std::vector<std::uint32_t> start(m + 1, 0);
    for (std::size_t t = 0; t < count; ++t) ++start[local[3 * t] + 1];
    for (std::size_t i = 0; i < m; ++i) start[i + 1] += start[i];
    std::vector<std::uint32_t> slot_of(count);  // canonical slot -> local triangle
    for (std::size_t t = 0; t < count; ++t) slot_of[start[local[3 * t]]++] = static_cast<std::uint32_t>(t);
    // start[i] is now the end of bucket i. Buckets hold about two triangles: insertion sort.
    std::uint32_t bucket_begin = 0;
    for (std::size_t i = 0; i < m; ++i) {
        const std::uint32_t bucket_end = start[i];
        for (std::uint32_t q = bucket_begin + 1; q < bucket_end; ++q) {
            for (std::uint32_t s = q; s > bucket_begin && local[3 * slot_of[s] + 1] < local[3 * slot_of[s - 1] + 1]; --s)
                std::swap(slot_of[s], slot_of[s - 1]);
        }
        bucket_begin = bucket_end;
    }
    std::vector<std::uint32_t> position(count);
    for (std::size_t q = 0; q < count; ++q) position[slot_of[q]] = static_cast<std::uint32_t>(q);
    detail::resize_large(out.triangles, local.size());
    detail::resize_large(out.halfedges, local.size());
    for (std::size_t q = 0; q < count; ++q) {
        const std::size_t t = slot_of[q];
        for (int k = 0; k < 3; ++k) {
            out.triangles[3 * q + k] = original[local[3 * t + k]];
            const std::int32_t f = twins[3 * t + k];
            out.halfedges[3 * q + k] = f < 0 ? -1 : static_cast<std::int32_t>(3 * position[f / 3] + f % 3);
        }
    }
}

/// Runs `first` on a second thread while `second` runs on this one when `parallel` is true and
/// the platform has threads (not the single-threaded WebAssembly build), otherwise one after the
/// other. `first` must not throw.
template <class First, class Second>
void run_both(bool parallel, First&& first, Second&& second) {
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    parallel = false;
#endif
    std::thread helper;
    if (parallel) {
        try {
            helper = std::thread(std::ref(first));
        } catch (const std::system_error&) {  // no thread to be had: do it here
        }
    }
    if (!helper.joinable()) {
        first();
        second();
        return;
    }
    try {
        second();
    } catch (...) {
        helper.join();
        throw;
    }
    helper.join();
}

/// Whether an interior edge of the mesh has an exactly cocircular neighbour (incircle == 0 across
/// it), i.e. whether some Delaunay face is not a triangle.
bool has_cocircular_edge(PointSpan2 p, const delaunay_detail::Mesh& mesh) {
    const std::uint32_t* vertex = mesh.vertex.data();
    const std::uint32_t* twin = mesh.twin.data();
    const std::uint32_t ghost = mesh.ghost;
    const std::size_t count = mesh.vertex.size() / 3;
    const double bound = detail::incircle_static_bound(mesh.span);
    for (std::size_t t = 0; t < count; ++t) {
        const std::uint32_t* v = vertex + 3 * t;
        if (v[0] == ghost || v[1] == ghost || v[2] == ghost) continue;
        const double* a = p[v[0]];
        const double* b = p[v[1]];
        const double* c = p[v[2]];
        for (std::uint32_t k = 0; k < 3; ++k) {
            const std::uint32_t e = static_cast<std::uint32_t>(3 * t) + k;
            const std::uint32_t f = twin[e];
            if (f < e) continue;  // each interior edge once (a hull edge's twin is in a ghost)
            const std::uint32_t opposite = vertex[f % 3 == 0 ? f + 2 : f - 1];  // f's corner off the edge
            if (opposite == ghost) continue;
            const double* d = p[opposite];
            if (detail::incircle_semi_static(bound, a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1], mesh.lattice) == 0)
                return true;
        }
    }
    return false;
}

/// The fast path of the incremental algorithm, straight from its working mesh: when no interior
/// edge of the mesh has an exactly cocircular neighbour, every Delaunay face is a triangle and the
/// mesh's finite triangles are the faces. Then writes the same arrays as fan_faces +
/// write_canonical would (each triangle from its lowest original index, clockwise, sorted by first
/// then second local corner) and returns true. Otherwise returns false, leaving `out`'s triangles
/// and half-edges empty: the caller then merges the faces and takes the general path. With
/// `parallel`, the cocircularity check, and later the two output arrays, take two threads.
bool write_canonical_mesh(PointSpan2 p, const delaunay_detail::Mesh& mesh,
                          const std::vector<std::uint32_t>& original, bool parallel, Delaunay& out) {
    const std::uint32_t* vertex = mesh.vertex.data();
    const std::uint32_t* twin = mesh.twin.data();
    const std::uint32_t ghost = mesh.ghost;
    const std::size_t count = mesh.vertex.size() / 3;  // ghosts included
    const std::size_t m = original.size();
    constexpr std::uint8_t kGhostTriangle = 3;
    // Set by the check as soon as it finds a cocircular edge; the other work then stops early.
    std::atomic<bool> cocircular{false};
    std::vector<std::uint8_t> low_of(count);
    std::vector<std::uint32_t> slot_of;  // canonical slot -> mesh triangle
    std::vector<std::uint32_t> position(count);
    std::size_t finite = 0;
    run_both(
        parallel, [&] { cocircular.store(has_cocircular_edge(p, mesh)); },
        [&] {
            // Pass 1: ghosts, the lowest corner, and the bucket sizes.
            std::vector<std::uint32_t> start(m + 1, 0);
            for (std::size_t t = 0; t < count; ++t) {
                if (t % 65536 == 0 && cocircular.load(std::memory_order_relaxed)) return;
                const std::uint32_t* v = vertex + 3 * t;
                if (v[0] == ghost || v[1] == ghost || v[2] == ghost) {
                    low_of[t] = kGhostTriangle;
                    continue;
                }
                const std::uint32_t o0 = original[v[0]], o1 = original[v[1]], o2 = original[v[2]];
                const std::uint8_t low = o0 < o1 ? (o0 < o2 ? 0 : 2) : (o1 < o2 ? 1 : 2);
                low_of[t] = low;
                ++start[v[low] + 1];
                ++finite;
            }
            for (std::size_t i = 0; i < m; ++i) start[i + 1] += start[i];
            // Pass 2: counting sort by the first output corner (the lowest), then insertion sort of
            // each small bucket by the second output corner (corner low + 2 of the counter-clockwise
            // triangle).
            slot_of.resize(finite);
            for (std::size_t t = 0; t < count; ++t) {
                const std::uint8_t low = low_of[t];
                if (low == kGhostTriangle) continue;
                slot_of[start[vertex[3 * t + low]]++] = static_cast<std::uint32_t>(t);
            }
            auto second = [&](std::uint32_t t) {
                const std::uint32_t low = low_of[t];
                return vertex[3 * t + (low == 0 ? 2 : low - 1)];
            };
            std::uint32_t bucket_begin = 0;
            for (std::size_t i = 0; i < m; ++i) {
                const std::uint32_t bucket_end = start[i];
                for (std::uint32_t q = bucket_begin + 1; q < bucket_end; ++q) {
                    const std::uint32_t moving = slot_of[q];
                    const std::uint32_t key = second(moving);
                    std::uint32_t s = q;
                    for (; s > bucket_begin && key < second(slot_of[s - 1]); --s) slot_of[s] = slot_of[s - 1];
                    slot_of[s] = moving;
                }
                bucket_begin = bucket_end;
            }
            for (std::size_t q = 0; q < finite; ++q) position[slot_of[q]] = static_cast<std::uint32_t>(q);
        });
    if (cocircular.load()) return false;
    // Pass 3: output corner j is mesh corner (low - j) mod 3 (clockwise from the lowest); output
    // half-edge j runs backwards along mesh half-edge (low + 2 - j) mod 3, so a mesh half-edge k of
    // triangle h is output half-edge (low_h + 5 - k) mod 3.
    detail::resize_large(out.triangles, 3 * finite);
    detail::resize_large(out.halfedges, 3 * finite);
    std::uint32_t* tri_out = out.triangles.data();
    std::int32_t* half_out = out.halfedges.data();
    run_both(
        parallel,
        [&] {
            for (std::size_t q = 0; q < finite; ++q) {
                const std::uint32_t t = slot_of[q];
                const std::uint32_t low = low_of[t];
                const std::uint32_t* v = vertex + 3 * t;
                for (std::uint32_t j = 0; j < 3; ++j) tri_out[3 * q + j] = original[v[(low + 3 - j) % 3]];
            }
        },
        [&] {
            for (std::size_t q = 0; q < finite; ++q) {
                const std::uint32_t t = slot_of[q];
                const std::uint32_t low = low_of[t];
                for (std::uint32_t j = 0; j < 3; ++j) {
                    const std::uint32_t g = twin[3 * t + (low + 2 - j) % 3];
                    const std::uint32_t h = g / 3;
                    const std::uint32_t low_h = low_of[h];
                    half_out[3 * q + j] = low_h == kGhostTriangle
                                              ? -1
                                              : static_cast<std::int32_t>(3 * position[h] + (low_h + 5 - g % 3) % 3);
                }
            }
        });
    return true;
}

/// The hull cycle: from the lowest hull index along the boundary half-edges. Every hull vertex
/// starts exactly one boundary half-edge, so `successor` (indexed by input point; only hull
/// vertices' entries are written and read) is the cycle.
std::vector<std::uint32_t> hull_cycle(const std::vector<std::uint32_t>& triangles,
                                      const std::vector<std::int32_t>& halfedges, std::size_t point_count) {
    std::unique_ptr<std::uint32_t[]> successor(new std::uint32_t[point_count]);
    std::uint32_t first = std::numeric_limits<std::uint32_t>::max();
    std::size_t length = 0;
    for (std::size_t e = 0; e < triangles.size(); ++e) {
        if (halfedges[e] != -1) continue;
        const std::uint32_t from = triangles[e];
        successor[from] = triangles[e % 3 == 2 ? e - 2 : e + 1];
        first = std::min(first, from);
        ++length;
    }
    std::vector<std::uint32_t> hull(length);
    std::uint32_t v = first;
    for (std::size_t k = 0; k < length; ++k, v = successor[v]) hull[k] = v;
    return hull;
}

/// merge_cocircular's polygons: `flat` holds faces of `corners(f)` corners each (from `begin`,
/// 3 each when `begin` is empty), every face already clockwise from its lowest original index;
/// written sorted as sequences (lexicographically, a prefix first) into out.polygon_*. A counting
/// sort by the first corner, then each small bucket by the rest.
void write_polygons(const std::vector<std::uint32_t>& flat, const std::vector<std::uint32_t>& begin,
                    std::size_t point_count, Delaunay& out) {
    const std::size_t count = begin.empty() ? flat.size() / 3 : begin.size() - 1;
    auto first = [&](std::size_t f) { return begin.empty() ? 3 * f : begin[f]; };
    auto last = [&](std::size_t f) { return begin.empty() ? 3 * f + 3 : begin[f + 1]; };
    std::vector<std::uint32_t> start(point_count + 1, 0);
    for (std::size_t f = 0; f < count; ++f) ++start[flat[first(f)] + 1];
    for (std::size_t i = 0; i < point_count; ++i) start[i + 1] += start[i];
    std::vector<std::uint32_t> order(count);
    {
        std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
        for (std::size_t f = 0; f < count; ++f) order[next[flat[first(f)]]++] = static_cast<std::uint32_t>(f);
    }
    auto before = [&](std::uint32_t u, std::uint32_t v) {
        return std::lexicographical_compare(flat.begin() + first(u), flat.begin() + last(u), flat.begin() + first(v),
                                            flat.begin() + last(v));
    };
    for (std::size_t i = 0; i < point_count; ++i) {
        std::uint32_t* lo = order.data() + start[i];
        std::uint32_t* hi = order.data() + start[i + 1];
        if (hi - lo > 16) {  // the lowest corner of many faces (the centre of a fan)
            std::sort(lo, hi, before);
            continue;
        }
        for (std::uint32_t* q = lo + 1; q < hi; ++q) {  // insertion sort: a handful each
            const std::uint32_t f = *q;
            std::uint32_t* r = q;
            for (; r > lo && before(f, r[-1]); --r) *r = r[-1];
            *r = f;
        }
    }
    out.polygon_offsets.assign(1, 0);
    out.polygon_offsets.reserve(count + 1);
    out.polygon_vertices.reserve(flat.size());
    for (std::uint32_t f : order) {
        out.polygon_vertices.insert(out.polygon_vertices.end(), flat.begin() + first(f), flat.begin() + last(f));
        out.polygon_offsets.push_back(static_cast<std::uint32_t>(out.polygon_vertices.size()));
    }
}

/// merge_cocircular: the faces turned clockwise, each from its lowest index, sorted as sequences.
void fill_polygons(const Faces& faces, const std::vector<std::uint32_t>& original, std::size_t point_count,
                   Delaunay& out) {
    std::vector<std::uint32_t> flat(faces.vertices.size());
    std::vector<std::uint32_t> begin(faces.size() + 1, 0);
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const std::uint32_t* c = &faces.vertices[faces.begin(f)];
        const std::size_t m = faces.corners(f);
        std::uint32_t* polygon = flat.data() + begin[f];
        for (std::size_t k = 0; k < m; ++k) polygon[k] = original[c[m - 1 - k]];
        std::rotate(polygon, std::min_element(polygon, polygon + m), polygon + m);
        begin[f + 1] = static_cast<std::uint32_t>(begin[f] + m);
    }
    write_polygons(flat, begin, point_count, out);
}

}  // namespace

namespace delaunay_detail {

std::vector<std::uint64_t> hilbert_order(PointSpan2 p, const double* lo, const double* hi) {
    const std::size_t n = p.count;
    const double width = hi[0] - lo[0], height = hi[1] - lo[1];
    const double sx = width > 0 ? 65535.0 / width : 0.0, sy = height > 0 ? 65535.0 / height : 0.0;
    std::vector<std::uint64_t> keyed, swap;  // on huge pages where they are large (large_array.hpp)
    detail::resize_large(keyed, n);
    detail::resize_large(swap, n);
    for (std::size_t i = 0; i < n; ++i) {
        double fx = (p[i][0] - lo[0]) * sx, fy = (p[i][1] - lo[1]) * sy;
        // A box narrower than 65535 / DBL_MAX makes the scale infinite (0 * inf at the low corner),
        // one wider than DBL_MAX the width infinite and the scale 0 (inf * 0 at the far side): NaN
        // must not reach the integer cast (found by fuzz_delaunay). NaN and negatives go to 0; the
        // order only affects speed.
        fx = fx > 0.0 ? std::min(fx, 65535.0) : 0.0;
        fy = fy > 0.0 ? std::min(fy, 65535.0) : 0.0;
        const std::uint32_t key = hilbert_index(static_cast<std::uint32_t>(fx), static_cast<std::uint32_t>(fy));
        keyed[i] = (std::uint64_t{key} << 32) | i;
    }
    // Three passes of 11-bit digits: 2048 buckets keep the scatter's write streams in cache.
    std::vector<std::uint32_t> count(2049);
    for (int shift = 32; shift < 64; shift += 11) {
        std::fill(count.begin(), count.end(), 0u);
        for (std::size_t i = 0; i < n; ++i) ++count[((keyed[i] >> shift) & 0x7ffu) + 1];
        for (std::size_t d = 0; d < 2048; ++d) count[d + 1] += count[d];
        for (std::size_t k = 0; k < n; ++k) swap[count[(keyed[k] >> shift) & 0x7ffu]++] = keyed[k];
        keyed.swap(swap);
    }
    return keyed;
}

Faces merge_cocircular_triangles(PointSpan2 p, std::vector<std::uint32_t> triangles,
                                 std::vector<std::int32_t> twin, bool lattice) {
    const std::size_t count = triangles.size() / 3;
    // Union-find over triangles joined across edges with an exactly cocircular neighbour.
    std::vector<std::uint32_t> parent;
    auto find = [&](std::uint32_t t) {
        while (parent[t] != t) t = parent[t] = parent[parent[t]];
        return t;
    };
    for (std::size_t e = 0; e < triangles.size(); ++e) {
        const std::int32_t f = twin[e];
        if (f < 0 || static_cast<std::size_t>(f) < e) continue;
        const std::size_t t = e / 3;
        const std::uint32_t opposite = triangles[f % 3 == 0 ? f + 2 : f - 1];  // f's corner off the edge
        const double* a = p[triangles[3 * t]];
        const double* b = p[triangles[3 * t + 1]];
        const double* c = p[triangles[3 * t + 2]];
        const double* d = p[opposite];
        if (lattice ? detail::incircle_stage_a(a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]).det != 0
                    : detail::incircle_inline(a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]) != 0)
            continue;
        if (parent.empty()) {
            parent.resize(count);
            std::iota(parent.begin(), parent.end(), 0u);
        }
        const std::uint32_t r1 = find(static_cast<std::uint32_t>(t)), r2 = find(static_cast<std::uint32_t>(f / 3));
        if (r1 != r2) parent[std::max(r1, r2)] = std::min(r1, r2);
    }
    Faces faces;
    if (parent.empty()) {  // general position: every triangle is a face
        faces.vertices = std::move(triangles);
        faces.twin = std::move(twin);
        return faces;
    }
    // Group the triangles by root (counting sort); walk each group's boundary, a convex cycle on
    // one circle.
    std::vector<std::uint32_t> start(count + 1, 0);
    for (std::uint32_t t = 0; t < count; ++t) ++start[find(t) + 1];
    for (std::size_t r = 0; r < count; ++r) start[r + 1] += start[r];
    std::vector<std::uint32_t> members(count);
    {
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::uint32_t t = 0; t < count; ++t) members[fill[find(t)]++] = t;
    }
    faces.offsets.push_back(0);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary;
    for (std::uint32_t root = 0; root < count; ++root) {
        const std::uint32_t begin = start[root], end = start[root + 1];
        if (begin == end) continue;
        if (end - begin == 1) {
            faces.vertices.insert(faces.vertices.end(), &triangles[3 * root], &triangles[3 * root + 3]);
            faces.offsets.push_back(static_cast<std::uint32_t>(faces.vertices.size()));
            continue;
        }
        boundary.clear();
        for (std::uint32_t m = begin; m < end; ++m) {
            const std::uint32_t t = members[m];
            for (std::uint32_t k = 0; k < 3; ++k) {
                const std::size_t e = 3 * t + k;
                const std::int32_t f = twin[e];
                if (f >= 0 && find(static_cast<std::uint32_t>(f / 3)) == root) continue;
                boundary.emplace_back(triangles[e], triangles[k == 2 ? e - 2 : e + 1]);
            }
        }
        std::sort(boundary.begin(), boundary.end());
        auto next_of = [&](std::uint32_t v) {
            return std::lower_bound(boundary.begin(), boundary.end(), std::make_pair(v, 0u))->second;
        };
        std::uint32_t v = boundary.front().first;
        for (std::size_t k = 0; k < boundary.size(); ++k, v = next_of(v)) faces.vertices.push_back(v);
        faces.offsets.push_back(static_cast<std::uint32_t>(faces.vertices.size()));
    }
    return faces;
}

}  // namespace delaunay_detail

namespace delaunay_detail {

bool prepare(PointSpan2 input, Delaunay& out, std::vector<double>& local_xy, Input& in) {
    Extent extent;
    out = check_input(input, &extent);
    if (!out.ok()) return false;
    gather_distinct(input, extent, out, local_xy, in.original);
    in.exponent = extent.exponent;
    in.points = PointSpan2(local_xy.data(), in.original.size());
    const PointSpan2 p = in.points;
    const std::size_t m = p.count;
    if (m == 0) {
        out.dimension = -1;
        return false;
    }
    if (m == 1) {
        out.dimension = 0;
        out.hull = in.original;
        return false;
    }
    std::size_t k = 2;
    while (k < m && orient2d(p[0][0], p[0][1], p[1][0], p[1][1], p[k][0], p[k][1]) == 0) ++k;
    if (k == m) {  // all collinear: the (x, y) order is the order along the line
        out.dimension = 1;
        std::vector<std::uint32_t> along(m);
        std::iota(along.begin(), along.end(), 0u);
        std::sort(along.begin(), along.end(), [&](std::uint32_t a, std::uint32_t b) {
            return p[a][0] < p[b][0] || (p[a][0] == p[b][0] && p[a][1] < p[b][1]);
        });
        for (std::uint32_t i : along) out.hull.push_back(in.original[i]);
        return false;
    }
    out.dimension = 2;
    return true;
}

}  // namespace delaunay_detail

Delaunay delaunay(PointSpan2 input, const DelaunayOptions& options) {
    Delaunay out;
    std::vector<double> local_xy;
    delaunay_detail::Input in;
    if (!delaunay_detail::prepare(input, out, local_xy, in)) return out;
    const PointSpan2 p = in.points;
    const std::size_t m = p.count;
    Faces faces;
    if (options.algorithm == DelaunayAlgorithm::Giftwrap) {
        faces = delaunay_detail::giftwrap_faces(in);
    } else {
        delaunay_detail::Mesh mesh = delaunay_detail::incremental_mesh(in, options.progress);
        const bool parallel = options.threads != 1 && m >= 50000;
        if (write_canonical_mesh(p, mesh, in.original, parallel, out)) {
            // General position: every face is a triangle, already clockwise from its lowest index.
            mesh = delaunay_detail::Mesh();
            out.hull = hull_cycle(out.triangles, out.halfedges, input.count);
            if (options.merge_cocircular) write_polygons(out.triangles, {}, input.count, out);
            return out;
        }
        faces = delaunay_detail::mesh_faces(p, std::move(mesh));
    }
    {
        std::vector<std::int32_t> twins;
        const std::vector<std::uint32_t> local = fan_faces(faces, in.original, &twins);
        if (twins.empty()) twins = match_halfedges(m, local);
        write_canonical(local, twins, in.original, out);
    }
    out.hull = hull_cycle(out.triangles, out.halfedges, input.count);
    if (options.merge_cocircular) fill_polygons(faces, in.original, input.count, out);
    return out;
}

}  // namespace hullkit
