// Private to native/src/delaunay: what the algorithms share with the driver in delaunay.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <vector>

#include "hullkit/delaunay.hpp"
#include "hullkit/predicates.hpp"

/// On the work done once per point or segment in a loop that runs once per call. In WebAssembly,
/// V8 starts with baseline code and swaps in optimised code for a function at its next call; a
/// loop inside one call never gets it. Kept out of line, the step is a function called thousands
/// of times and runs optimised code within a first call too (about 4% off the 10^5-vertex lake's
/// first wasm call; hullkit.js warms the code up at load, and most of what a first call still
/// costs over later ones is fresh memory). A call per step costs nothing measurable natively.
#if defined(__GNUC__)
#define HULLKIT_STEP __attribute__((noinline))
#else
#define HULLKIT_STEP
#endif

namespace hullkit {
namespace delaunay_detail {

/// Multiplies each of `values` by 2^exponent. A product by a normal power of two is the correctly
/// rounded value, as std::ldexp's is (exact unless it leaves the normal range): one multiplication
/// instead of a call per value. Exponents beyond a normal power of two go through std::ldexp.
inline void scale_by_power_of_two(std::vector<double>& values, int exponent) {
    if (exponent == 0) return;
    if (exponent >= -1022 && exponent <= 1023) {
        const double factor = std::ldexp(1.0, exponent);
        for (double& v : values) v *= factor;
    } else {
        for (double& v : values) v = std::ldexp(v, exponent);
    }
}

/// Convex polygons given as index cycles, COUNTER-clockwise with y up (the algorithms' internal
/// orientation; the driver turns them round for the output). `offsets` empty means every face is
/// a triangle (the common case, stored without offsets).
struct Faces {
    std::vector<std::uint32_t> offsets;
    std::vector<std::uint32_t> vertices;
    /// Optional, only with every face a triangle: twin[e] the opposite half-edge of half-edge e
    /// (3 * face + k, from corner k to corner k + 1), -1 on the hull. Saves matching them again.
    std::vector<std::int32_t> twin;
    std::size_t size() const { return offsets.empty() ? vertices.size() / 3 : offsets.size() - 1; }
    std::size_t begin(std::size_t f) const { return offsets.empty() ? 3 * f : offsets[f]; }
    std::size_t corners(std::size_t f) const { return offsets.empty() ? 3 : offsets[f + 1] - offsets[f]; }
};

/// The input of an algorithm: the distinct points (duplicates merged), in the predicates' exact
/// range, stored contiguously in Hilbert-curve order (nearby points nearby in memory); point i here
/// is input point original[i]. At least 3 of them, not all collinear. Algorithms work with these
/// local indices.
struct Input {
    PointSpan2 points;
    std::vector<std::uint32_t> original;
    int exponent = 0;  ///< the power of two the points were scaled by (prepare(): incircle's range)
    /// Room the mesh's arrays reserve for this many points more (constrained refinement adds
    /// points to the mesh: reserved, the arrays are not copied as they grow, and the room is only
    /// address space until used).
    std::size_t spare_points = 0;
    /// Whether the mesh keeps the triangles' marks (Mesh::mark) for a later user.
    bool keep_marks = false;
};

/// The larger of the points' computed width and height: no coordinate difference of two of them,
/// as computed in floating point, is larger (rounding is monotone). For the predicates' static
/// bounds (detail::incircle_static_bound).
inline double coordinate_span(PointSpan2 p) {
    double xmin = p[0][0], xmax = xmin, ymin = p[0][1], ymax = ymin;
    for (std::size_t i = 1; i < p.count; ++i) {
        xmin = std::min(xmin, p[i][0]), xmax = std::max(xmax, p[i][0]);
        ymin = std::min(ymin, p[i][1]), ymax = std::max(ymax, p[i][1]);
    }
    return std::max(xmax - xmin, ymax - ymin);
}

/// The power of two delaunay() scales these points by before its exact tests, in *exponent (0 when
/// they are in incircle's range); false for points delaunay() refuses: non-finite, or spanning too
/// much.
inline bool scale_exponent(PointSpan2 p, int* exponent) {
    double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < 2 * p.count; ++i) {
        const double m = std::fabs(p.xy[i]);
        if (!(m <= std::numeric_limits<double>::max())) return false;
        largest = std::max(largest, m);
        if (m != 0.0) smallest = std::min(smallest, m);
    }
    *exponent = 0;
    return incircle_range_ok(largest, smallest) || incircle_scale_exponent(largest, smallest, exponent);
}

/// scale_exponent's power of two, and 0 for points delaunay() refuses.
inline int incircle_exponent(PointSpan2 p) {
    int exponent = 0;
    return scale_exponent(p, &exponent) ? exponent : 0;
}

/// For the points `indices` (finite coordinates; sorted here by x, y, index): lowest[i] = the
/// lowest of them with exactly point i's coordinates. Returns the distinct ones, in that order.
/// `lowest` must have room for every index.
inline std::vector<std::uint32_t> lowest_copies(PointSpan2 p, std::vector<std::uint32_t> indices,
                                                std::vector<std::uint32_t>& lowest) {
    std::sort(indices.begin(), indices.end(), [&](std::uint32_t a, std::uint32_t b) {
        return p[a][0] < p[b][0] || (p[a][0] == p[b][0] && (p[a][1] < p[b][1] || (p[a][1] == p[b][1] && a < b)));
    });
    std::vector<std::uint32_t> distinct;
    for (const std::uint32_t i : indices) {
        if (!distinct.empty() && p[i][0] == p[distinct.back()][0] && p[i][1] == p[distinct.back()][1]) {
            lowest[i] = distinct.back();
        } else {
            lowest[i] = i;
            distinct.push_back(i);
        }
    }
    return distinct;
}

/// The incremental algorithm's working mesh: counter-clockwise triangles (3 vertices each) with
/// their twin half-edges (twin[e] opposite half-edge of e = 3 * t + k, from corner k to k + 1),
/// closed by "ghost" triangles on the outer side of every hull edge, which have the vertex `ghost`
/// (the point count) as one corner. Every finite triangle is Delaunay; cocircular faces are not
/// merged yet.
struct Mesh {
    std::vector<std::uint32_t> vertex;
    std::vector<std::uint32_t> twin;
    std::uint32_t ghost = 0;
    double span = 0;  ///< coordinate_span of the points
    /// The points lie on a small lattice (detail::plane_lattice_exact): orient2d and incircle are
    /// exact in doubles, and the semi-static tests take `exact_in_doubles`.
    bool lattice = false;
    /// With Input::keep_marks: a number per triangle (slot), each below mark_limit, in memory
    /// already touched (the constrained triangulation's marks start there instead of in fresh
    /// pages); empty otherwise.
    std::vector<std::uint32_t> mark;
    std::uint32_t mark_limit = 0;
};
/// The ghost triangle (x, y, G) of hull edge x -> y (the outside on its left) is in conflict with
/// point p when p is strictly outside that edge, or exactly on its line strictly between x and y
/// (the limit of a circle through x, y and a point far away). Exact.
inline bool beyond_hull_edge(const double* x, const double* y, const double* p) {
    const int o = orient2d(x[0], x[1], y[0], y[1], p[0], p[1]);
    if (o != 0) return o > 0;
    // On the line: compare along an axis on which x and y differ (exact, the three are collinear).
    if (x[0] != y[0]) return (x[0] < p[0] && p[0] < y[0]) || (y[0] < p[0] && p[0] < x[0]);
    return (x[1] < p[1] && p[1] < y[1]) || (y[1] < p[1] && p[1] < x[1]);
}

/// The corners of the ghost triangle t (one corner is `ghost`) as its hull edge x -> y.
inline void ghost_edge(const std::uint32_t* corners, std::uint32_t ghost, std::uint32_t* x, std::uint32_t* y) {
    const std::uint32_t a = corners[0], b = corners[1], c = corners[2];
    *x = a == ghost ? b : (b == ghost ? c : a);
    *y = a == ghost ? c : (b == ghost ? a : b);
}

/// The visibility walk over a ghosted mesh (counter-clockwise triangles `vertex`, `twin`, corner
/// `ghost` for the point at infinity) from triangle `start` towards a point: at each triangle the
/// edges are tried from a pseudo-random first one (`seed`, a linear congruential state, which makes
/// the walk terminate in any triangulation) and the walk crosses the first edge a -> b with
/// `right_of(a, b)` (the point strictly on its right). Returns the finite triangle that holds the
/// point (closed), or the first ghost reached (the point is outside that hull edge).
template <class RightOf>
std::uint32_t visibility_walk(const std::vector<std::uint32_t>& vertex, const std::vector<std::uint32_t>& twin,
                              std::uint32_t ghost, std::uint32_t start, std::uint32_t& seed, RightOf right_of) {
    const auto next = [](std::uint32_t e) { return e % 3 == 2 ? e - 2 : e + 1; };
    const auto is_ghost = [&](std::uint32_t t) {
        return vertex[3 * t] == ghost || vertex[3 * t + 1] == ghost || vertex[3 * t + 2] == ghost;
    };
    std::uint32_t t = start;
    if (is_ghost(t)) {
        std::uint32_t e = 3 * t;
        while (vertex[e] == ghost || vertex[next(e)] == ghost) ++e;
        t = twin[e] / 3;  // the finite triangle across the ghost's hull edge
    }
    // The edges in the order r, r + 1, r + 2 (mod 3) from a random first edge r, each from corner
    // kCycle[r + k] to kCycle[r + k + 1]: a table rather than remainders in the loop.
    static constexpr std::uint8_t kCycle[6] = {0, 1, 2, 0, 1, 2};
    for (;;) {
        seed = seed * 1103515245u + 12345u;
        const std::uint32_t r = (seed >> 16) % 3;
        bool moved = false;
        for (std::uint32_t k = 0; k < 3; ++k) {
            const std::uint32_t e = 3 * t + kCycle[r + k];
            if (right_of(vertex[e], vertex[3 * t + kCycle[r + k + 1]])) {
                t = twin[e] / 3;
                moved = true;
                break;
            }
        }
        if (!moved || is_ghost(t)) return t;
    }
}

/// `progress` (may be empty): see DelaunayOptions::progress.
Mesh incremental_mesh(const Input& input,
                      const std::function<void(std::size_t, std::size_t)>& progress = nullptr);
/// The Delaunay faces of an incremental mesh (finite triangles, then merge_cocircular_triangles).
Faces mesh_faces(PointSpan2 points, Mesh mesh);

/// The points as (Hilbert key << 32 | index), sorted along the curve over the box [lo, hi] (a
/// 2^16 x 2^16 grid), equal keys by index (stable LSD radix sort on the key): the order delaunay()
/// inserts points in, and delaunay_locate walks its queries in. The order only affects speed and
/// memory locality, never a result, so the rounding in the keys is harmless; exact duplicates get
/// equal keys.
std::vector<std::uint64_t> hilbert_order(PointSpan2 p, const double* lo, const double* hi);

/// delaunay()'s first steps, shared with the constrained triangulation (constrained.cpp): checks the
/// points (errors in out.error, out.error_point), merges duplicates (out.representative,
/// out.duplicate_count) and gathers the distinct points, scaled into incircle's range, in Hilbert
/// order into local_xy (`in` views them; in.original maps back). Returns true when they span the
/// plane (out.dimension 2); otherwise fills out.dimension (and out.hull as delaunay() does) and
/// returns false.
bool prepare(PointSpan2 input, Delaunay& out, std::vector<double>& local_xy, Input& in);

/// Both algorithms return the Delaunay faces: the lower faces of the lifted hull, each a maximal set
/// of cocircular points whose circle is empty, as a counter-clockwise cycle.
Faces incremental_faces(const Input& input);
Faces giftwrap_faces(const Input& input);

/// Merges a Delaunay triangulation (counter-clockwise triangles, `twin[e]` the opposite half-edge or
/// -1) into its Delaunay faces: triangles joined across every edge whose in-circle test is exactly 0.
/// `lattice`: the points are on a small lattice (Mesh::lattice), where the floating-point
/// determinant is the exact one.
Faces merge_cocircular_triangles(PointSpan2 points, std::vector<std::uint32_t> triangles,
                                 std::vector<std::int32_t> twin, bool lattice = false);

}  // namespace delaunay_detail
}  // namespace hullkit
