// Delaunay by the seed's gift wrapping on the lifted points (z = x^2 + y^2): from a known edge of
// the lower hull, the face beyond it is found in one pass over the points, replacing the candidate
// whenever a point lies strictly below the candidate's lifted plane, i.e. strictly inside its
// circumcircle (exact incircle), among the points on the correct side of the edge (exact orient2d).
// The points exactly on the final circle complete the face (a Delaunay polygon); its edges go on a
// stack until every face is found. O(n) per face, O(n^2) in all: for teaching and cross-checking.
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "delaunay_internal.hpp"
#include "hullkit/giftwrap.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit {
namespace delaunay_detail {
namespace {

inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
    return (static_cast<std::uint64_t>(a) << 32) | b;
}

/// Records one event (traced wrap only); the arguments are input indices.
template <bool kTraced>
inline void note(GiftwrapTrace* trace, GiftwrapEvent kind, std::uint32_t a, std::uint32_t b = 0, std::uint32_t c = 0) {
    if constexpr (kTraced) {
        trace->kinds.push_back(static_cast<std::uint8_t>(kind));
        trace->args.insert(trace->args.end(), {a, b, c});
    } else {
        (void)trace, (void)kind, (void)a, (void)b, (void)c;
    }
}

/// The wrap; with kTraced every step goes to *trace (see delaunay_giftwrap_trace).
template <bool kTraced>
Faces wrap_lifted(const Input& input, GiftwrapTrace* trace) {
    const PointSpan2 p = input.points;
    const std::uint32_t count = static_cast<std::uint32_t>(p.count);
    auto orient = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        return orient2d(p[a][0], p[a][1], p[b][0], p[b][1], p[c][0], p[c][1]);
    };
    auto in = [&](std::uint32_t local) { return input.original[local]; };  // input index, for the trace
    (void)in;
    auto lex_less = [&](std::uint32_t a, std::uint32_t b) {
        return p[a][0] < p[b][0] || (p[a][0] == p[b][0] && p[a][1] < p[b][1]);
    };

    // First edge: from the lowest point in (x, y) order, which is a hull vertex, to the hull vertex
    // that follows it counter-clockwise: no point strictly to the right, and of the points on the
    // line the nearest (the line's points all come after the first one in (x, y) order).
    std::uint32_t first = 0;
    for (std::uint32_t q = 1; q < count; ++q)
        if (lex_less(q, first)) first = q;
    std::uint32_t second = first == 0 ? 1 : 0;
    for (std::uint32_t q = 0; q < count; ++q) {
        if (q == first || q == second) continue;
        const int o = orient(first, second, q);
        if (o < 0 || (o == 0 && lex_less(q, second))) second = q;
    }
    note<kTraced>(trace, GiftwrapEvent::FirstPoint, in(first));
    note<kTraced>(trace, GiftwrapEvent::FirstEdge, in(first), in(second));
    note<kTraced>(trace, GiftwrapEvent::PushEdge, in(first), in(second));

    Faces faces;
    faces.offsets.push_back(0);
    std::unordered_set<std::uint64_t> done;  // directed edges whose left face is known
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{first, second}};
    std::vector<std::uint32_t> on_circle;
    while (!stack.empty()) {
        const std::uint32_t a = stack.back().first;
        const std::uint32_t b = stack.back().second;
        stack.pop_back();
        if (done.count(edge_key(a, b))) {
            note<kTraced>(trace, GiftwrapEvent::SkipEdge, in(a), in(b));
            continue;
        }
        note<kTraced>(trace, GiftwrapEvent::PopEdge, in(a), in(b));
        // The candidate: a point strictly left of a->b; replaced by any point strictly inside the
        // circle through a, b and the candidate (a, b, candidate counter-clockwise).
        std::uint32_t c = UINT32_MAX;
        for (std::uint32_t q = 0; q < count; ++q) {
            if (orient(a, b, q) <= 0) continue;
            if (c == UINT32_MAX) {
                c = q;
                note<kTraced>(trace, GiftwrapEvent::Candidate, in(a), in(b), in(c));
            } else if (incircle(p[a][0], p[a][1], p[b][0], p[b][1], p[c][0], p[c][1], p[q][0], p[q][1]) > 0) {
                c = q;
                note<kTraced>(trace, GiftwrapEvent::Replace, in(a), in(b), in(c));
            }
        }
        if (c == UINT32_MAX) continue;  // a->b is a hull edge seen from outside
        // The face: every point on the left exactly on the (empty) circle, in counter-clockwise
        // order, which seen from a is increasing angle.
        on_circle.clear();
        for (std::uint32_t q = 0; q < count; ++q) {
            if (orient(a, b, q) <= 0) continue;
            if (q == c ||
                incircle(p[a][0], p[a][1], p[b][0], p[b][1], p[c][0], p[c][1], p[q][0], p[q][1]) == 0) {
                on_circle.push_back(q);
                if (q != c) note<kTraced>(trace, GiftwrapEvent::Coplanar, in(a), in(b), in(q));
            }
        }
        std::sort(on_circle.begin(), on_circle.end(),
                  [&](std::uint32_t u, std::uint32_t v) { return orient(a, u, v) > 0; });
        const std::size_t begin = faces.vertices.size();
        faces.vertices.push_back(a);
        faces.vertices.push_back(b);
        faces.vertices.insert(faces.vertices.end(), on_circle.begin(), on_circle.end());
        const std::size_t m = faces.vertices.size() - begin;
        faces.offsets.push_back(static_cast<std::uint32_t>(faces.vertices.size()));
        if constexpr (kTraced) {
            // The projected triangles as delaunay() reports them: fanned from the corner with the
            // lowest input index, clockwise (y up), starting at that corner.
            const std::uint32_t* corner = &faces.vertices[begin];
            std::size_t low = 0;
            for (std::size_t k = 1; k < m; ++k)
                if (input.original[corner[k]] < input.original[corner[low]]) low = k;
            for (std::size_t k = 1; k + 1 < m; ++k)
                note<kTraced>(trace, GiftwrapEvent::Accept, in(corner[low]), in(corner[(low + k + 1) % m]),
                              in(corner[(low + k) % m]));
        }
        for (std::size_t k = 0; k < m; ++k) {
            const std::uint32_t u = faces.vertices[begin + k];
            const std::uint32_t v = faces.vertices[begin + (k + 1) % m];
            done.insert(edge_key(u, v));
            if (!done.count(edge_key(v, u))) {
                stack.emplace_back(v, u);
                note<kTraced>(trace, GiftwrapEvent::PushEdge, in(v), in(u));
            }
        }
    }
    if constexpr (kTraced) {
        note<kTraced>(trace, GiftwrapEvent::Done, static_cast<std::uint32_t>(faces.size()),
                      static_cast<std::uint32_t>(faces.vertices.size() - 2 * faces.size()));
    }
    return faces;
}

}  // namespace

Faces giftwrap_faces(const Input& input) { return wrap_lifted<false>(input, nullptr); }

}  // namespace delaunay_detail

GiftwrapTrace delaunay_giftwrap_trace(PointSpan2 points) {
    GiftwrapTrace trace;
    // delaunay() settles invalid input and input without area, and gives the triangles (every
    // algorithm returns identical arrays).
    Delaunay result = delaunay(points);
    trace.error = std::move(result.error);
    trace.error_point = result.error_point;
    trace.dimension = result.dimension;
    trace.triangles = std::move(result.triangles);
    if (!trace.ok()) return trace;
    if (result.dimension < 2) {
        trace.kinds.push_back(static_cast<std::uint8_t>(GiftwrapEvent::Done));
        trace.args.insert(trace.args.end(), {0u, 0u, 0u});
        return trace;
    }
    // The distinct points in input order, rescaled by a power of two into incircle's exact range.
    delaunay_detail::Input input;
    double largest = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
    for (std::uint32_t i = 0; i < points.count; ++i) {
        if (result.representative[i] != i) continue;
        input.original.push_back(i);
        for (int axis = 0; axis < 2; ++axis) {
            const double magnitude = std::fabs(points[i][axis]);
            largest = std::max(largest, magnitude);
            if (magnitude != 0.0) smallest = std::min(smallest, magnitude);
        }
    }
    int exponent = 0;
    if (!incircle_range_ok(largest, smallest)) incircle_scale_exponent(largest, smallest, &exponent);
    std::vector<double> xy;
    xy.reserve(2 * input.original.size());
    for (std::uint32_t i : input.original) {
        xy.push_back(std::ldexp(points[i][0], exponent));
        xy.push_back(std::ldexp(points[i][1], exponent));
    }
    input.points = PointSpan2(xy.data(), input.original.size());
    delaunay_detail::wrap_lifted<true>(input, &trace);
    return trace;
}

}  // namespace hullkit
