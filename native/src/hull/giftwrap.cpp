#include "hullkit/giftwrap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "hull_internal.hpp"
#include "planar.hpp"
#include "sides.hpp"

namespace hullkit::detail {
namespace {

using Index = std::uint32_t;
constexpr Index kNone = ~Index{0};


std::uint64_t edge_key(Index a, Index b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t{a} << 32) | b;
}

/// One run of the wrap over the distinct input points `ids`. With kTraced every step is appended
/// to *trace (see GiftwrapTrace); the untraced instantiation has no recording code at all.
template <class Predicates, bool kTraced = false>
class GiftWrapper {
public:
    GiftWrapper(PointSpan points, std::vector<Index> ids, const Predicates& predicates, GiftwrapScan scan,
                GiftwrapTrace* trace = nullptr)
        : points_(points), ids_(std::move(ids)), pred_(predicates), scan_(scan), trace_(trace) {}

    /// The faces, or false with `error` set.
    bool run(Polygons& faces, std::string& error) {
        if (std::string why = volume_check(); !why.empty()) {
            error = why;
            return false;
        }
        std::vector<Index> polygon;
        bool ok = first_face(polygon) && add_face(polygon, faces);
        // Step 4: pop an edge whose other side is unknown and wrap across it.
        while (ok && !stack_.empty()) {
            const auto [u, v] = stack_.back();
            stack_.pop_back();
            if (edge_faces_[edge_key(u, v)] >= 2) {  // found meanwhile from another edge
                note(GiftwrapEvent::SkipEdge, u, v);
                continue;
            }
            note(GiftwrapEvent::PopEdge, u, v);
            ok = face_across(u, v, polygon) && add_face(polygon, faces);
        }
        if (ok) error_ = closure_check(faces);
        if (ok && error_.empty()) {
            note(GiftwrapEvent::Done, static_cast<Index>(faces.size()),
                 static_cast<Index>(faces.vertices.size() - 2 * faces.size()));
        }
        error = error_;
        return error.empty();
    }

private:
    const double* at(Index i) const { return points_[i]; }

    /// Records one event (traced wrap only).
    void note(GiftwrapEvent kind, Index a, Index b = 0, Index c = 0) {
        if constexpr (kTraced) {
            trace_->kinds.push_back(static_cast<std::uint8_t>(kind));
            trace_->args.insert(trace_->args.end(), {a, b, c});
        } else {
            (void)kind, (void)a, (void)b, (void)c;
        }
    }

    /// Reports input without volume, naming the case: identical, collinear or coplanar points.
    /// (With exact sides the caller has settled this; the seed's epsilon may see it differently.)
    std::string volume_check() const {
        const std::string all = "all " + std::to_string(points_.count) + " points ";
        if (ids_.size() == 1) return all + "are identical within the seed's epsilon";
        const Index p0 = ids_[0];
        const Index p1 = ids_[1];
        auto off_line = std::find_if(ids_.begin() + 2, ids_.end(),
                                     [&](Index q) { return !pred_.collinear(at(p0), at(p1), at(q)); });
        if (off_line == ids_.end()) return all + "are collinear within the seed's epsilon";
        const Index p2 = *off_line;
        auto off_plane = std::find_if(ids_.begin() + 2, ids_.end(), [&](Index q) {
            return pred_.orient3d(at(p0), at(p1), at(p2), at(q)) != 0;
        });
        if (off_plane == ids_.end()) return all + "are coplanar within the seed's epsilon";
        return {};
    }

    /// Steps 1 and 2: the point with the largest x (then y, z) and the edge of the flattened
    /// points' hull leaving it; then the first face, found by turning the vertical plane through
    /// that edge about it (or the vertical plane itself when it holds a face).
    bool first_face(std::vector<Index>& polygon) {
        auto lexicographic_less = [&](Index p, Index q) {
            const double* a = at(p);
            const double* b = at(q);
            return std::lexicographical_compare(a, a + 3, b, b + 3);
        };
        const Index a = *std::max_element(ids_.begin(), ids_.end(), lexicographic_less);
        note(GiftwrapEvent::FirstPoint, a);

        Index b = kNone;  // all flattened points end up left of (or on) a -> b
        for (Index q : ids_) {
            if (at(q)[0] == at(a)[0] && at(q)[1] == at(a)[1]) continue;
            if (b == kNone || pred_.orient_xy(at(a), at(b), at(q)) < 0) b = q;
        }
        if (b == kNone) return fail("no first edge: the flattened points do not span a plane");
        note(GiftwrapEvent::FirstEdge, a, b);

        std::vector<Index> on_vertical;  // points of the vertical plane through a and b
        Index apart = kNone;             // one of them off the line a-b, if any
        Index inside = kNone;            // a point strictly inside the vertical plane's half-space
        for (Index q : ids_) {
            if (pred_.orient_xy(at(a), at(b), at(q)) != 0) {
                if (inside == kNone) inside = q;
                continue;
            }
            on_vertical.push_back(q);
            if (apart == kNone && !pred_.collinear(at(a), at(b), at(q))) apart = q;
        }
        if (inside == kNone) return fail("all points lie in one vertical plane");

        if (apart != kNone) {
            // The vertical plane is a supporting plane holding a 2D face.
            Index u = a, v = b;
            if (pred_.orient3d(at(u), at(v), at(apart), at(inside)) > 0) std::swap(u, v);
            if (pred_.orient3d(at(u), at(v), at(apart), at(inside)) >= 0)
                return fail("inconsistent side tests on the first face");
            note(GiftwrapEvent::VerticalFace, u, v, apart);
            return polygon_of(on_vertical, u, v, apart, polygon);
        }
        // The vertical plane touches the hull along a segment: its two end points form a hull edge.
        const glm::dvec3 direction = glm::abs(vec3(at(b)) - vec3(at(a)));
        const int axis = direction.x >= direction.y ? (direction.x >= direction.z ? 0 : 2)
                                                    : (direction.y >= direction.z ? 1 : 2);
        auto along = [&](Index p, Index q) { return at(p)[axis] < at(q)[axis]; };
        const Index u = *std::min_element(on_vertical.begin(), on_vertical.end(), along);
        const Index v = *std::max_element(on_vertical.begin(), on_vertical.end(), along);
        note(GiftwrapEvent::WrapFirst, u, v);
        return face_across(u, v, polygon);
    }

    /// Step 4 for the hull edge u -> v: the face holding u -> v counter-clockwise, as a convex
    /// polygon starting u, v, ...
    bool face_across(Index u, Index v, std::vector<Index>& polygon) {
        coplanar_.clear();
        const Index c = scan_ == GiftwrapScan::SinglePass ? apex_single_pass(u, v) : apex_restart(u, v);
        if (c == kNone) return fail("no face found across edge " + edge_name(u, v));
        coplanar_.push_back(u);
        coplanar_.push_back(v);
        coplanar_.push_back(c);
        if (!polygon_of(coplanar_, u, v, c, polygon)) return false;
        const auto start = std::find(polygon.begin(), polygon.end(), u);
        if (start == polygon.end()) return fail("edge " + edge_name(u, v) + " fell off its face");
        std::rotate(polygon.begin(), start, polygon.end());
        if (polygon[1] != v) return fail("edge " + edge_name(u, v) + " is not an edge of its face");
        return true;
    }

    /// The refined scan: one pass; a point above the candidate plane becomes the candidate.
    /// Points tied with the final candidate (coplanar with u, v, c) are left in coplanar_.
    Index apex_single_pass(Index u, Index v) {
        Index c = kNone;
        for (Index q : ids_) {
            if (q == u || q == v) continue;
            if (c == kNone) {
                if (!pred_.collinear(at(u), at(v), at(q))) {
                    c = q;
                    note(GiftwrapEvent::Candidate, u, v, c);
                }
                continue;
            }
            const int side = pred_.orient3d(at(u), at(v), at(c), at(q));
            if (side > 0) {
                c = q;
                coplanar_.clear();
                note(GiftwrapEvent::Replace, u, v, q);
            } else if (side == 0 && !pred_.collinear(at(u), at(v), at(q))) {
                coplanar_.push_back(q);
                note(GiftwrapEvent::Coplanar, u, v, q);
            }
        }
        return c;
    }

    /// The seed's literal scan: the first candidate with no point above its plane.
    Index apex_restart(Index u, Index v) {
        for (Index c : ids_) {
            if (c == u || c == v || pred_.collinear(at(u), at(v), at(c))) continue;
            coplanar_.clear();
            note(GiftwrapEvent::Candidate, u, v, c);
            bool accepted = true;
            for (Index q : ids_) {
                const int side = pred_.orient3d(at(u), at(v), at(c), at(q));
                if (side > 0) {
                    note(GiftwrapEvent::Restart, u, v, q);
                    accepted = false;
                    break;
                }
                if (side == 0 && q != u && q != v && q != c && !pred_.collinear(at(u), at(v), at(q))) {
                    coplanar_.push_back(q);
                    note(GiftwrapEvent::Coplanar, u, v, q);
                }
            }
            if (accepted) return c;
        }
        return kNone;
    }

    bool polygon_of(const std::vector<Index>& members, Index a, Index b, Index c, std::vector<Index>& polygon) {
        if (convex_polygon(points_, pred_, members, a, b, c, polygon)) return true;
        return fail("degenerate face at edge " + edge_name(a, b));
    }

    /// Records a face, and for each of its edges whose other side is still
    /// unknown, that edge reversed on the stack (step 4's "two new edges", for a whole polygon).
    bool add_face(const std::vector<Index>& polygon, Polygons& faces) {
        const std::size_t m = polygon.size();
        if constexpr (kTraced) {
            // The triangles as hull() reports them: fanned from the polygon's lowest index.
            const std::size_t low = static_cast<std::size_t>(std::min_element(polygon.begin(), polygon.end()) - polygon.begin());
            for (std::size_t k = 1; k + 1 < m; ++k)
                note(GiftwrapEvent::Accept, polygon[low], polygon[(low + k) % m], polygon[(low + k + 1) % m]);
        }
        for (std::size_t k = 0; k < m; ++k) {
            const Index p = polygon[k];
            const Index q = polygon[(k + 1) % m];
            const int faces = ++edge_faces_[edge_key(p, q)];
            if (faces > 2) return fail("edge " + edge_name(p, q) + " found on a third face");
            if (faces == 1) {
                stack_.emplace_back(q, p);
                note(GiftwrapEvent::PushEdge, q, p);
            }
        }
        faces.add(polygon.begin(), polygon.end());
        return true;
    }

    /// Every edge must border exactly two faces and the surface must be a sphere (V - E + F = 2).
    std::string closure_check(const Polygons& faces) const {
        for (const auto& [key, faces] : edge_faces_) {
            if (faces != 2) {
                return "gift wrapping did not close: edge " +
                       edge_name(static_cast<Index>(key >> 32), static_cast<Index>(key)) + " has " +
                       std::to_string(faces) + " face(s)";
            }
        }
        std::vector<Index> used(faces.vertices.begin(), faces.vertices.end());
        std::sort(used.begin(), used.end());
        const auto v = static_cast<long long>(std::unique(used.begin(), used.end()) - used.begin());
        const auto f = static_cast<long long>(faces.size());
        const auto e = static_cast<long long>(edge_faces_.size());
        if (v - e + f != 2)
            return "gift wrapping produced a surface that is not a sphere (V - E + F = " +
                   std::to_string(v - e + f) + ")";
        return {};
    }

    static std::string edge_name(Index a, Index b) { return std::to_string(a) + "-" + std::to_string(b); }

    bool fail(std::string message) {
        error_ = "near-degenerate input defeats the seed's epsilon side tests: " + std::move(message);
        return false;
    }

    PointSpan points_;
    std::vector<Index> ids_;
    const Predicates& pred_;
    GiftwrapScan scan_;
    GiftwrapTrace* trace_;  // where the traced wrap records its events; unused otherwise

    std::vector<std::pair<Index, Index>> stack_;           // directed edges u -> v to wrap across
    std::unordered_map<std::uint64_t, int> edge_faces_;    // unordered edge -> faces found on it
    std::vector<Index> coplanar_;                          // scratch: ties of the current apex
    std::string error_;
};

}  // namespace

bool giftwrap_faces(PointSpan points, GiftwrapScan scan, bool seed_epsilon, Polygons& faces, std::string& error) {
    const std::vector<Index> ids = distinct_points(points);
    if (seed_epsilon) {
        const SeedEpsilon sides(points);
        return GiftWrapper<SeedEpsilon>(points, ids, sides, scan).run(faces, error);
    }
    const ExactSides sides;
    return GiftWrapper<ExactSides>(points, ids, sides, scan).run(faces, error);
}

}  // namespace hullkit::detail

namespace hullkit {

const char* giftwrap_event_name(GiftwrapEvent kind) {
    static const char* const kNames[kGiftwrapEventKinds] = {
        "first_point", "first_edge", "vertical_face", "wrap_first", "push_edge", "pop_edge", "skip_edge",
        "candidate",   "replace",    "restart",       "coplanar",   "accept",    "done"};
    const auto k = static_cast<int>(kind);
    return k < kGiftwrapEventKinds ? kNames[k] : "unknown";
}

GiftwrapTrace giftwrap_trace(PointSpan input, GiftwrapScan scan) {
    GiftwrapTrace trace;
    HullOptions options;
    options.algorithm = Algorithm::Giftwrap;
    options.giftwrap_scan = scan;
    // hull() runs the same wrap on the same (rescaled) points; it is asked here only for what it
    // settles without wrapping: invalid input, and input without volume.
    auto from_hull = [&]() {
        Hull hull = hullkit::hull(input, options);
        trace.error = std::move(hull.error);
        trace.error_point = hull.error_point;
        trace.dimension = hull.dimension;
        trace.triangles = std::move(hull.triangles);
        if (trace.ok()) {
            trace.kinds.push_back(static_cast<std::uint8_t>(GiftwrapEvent::Done));
            trace.args.insert(trace.args.end(), {0u, static_cast<std::uint32_t>(trace.triangles.size() / 3), 0u});
        }
        return trace;
    };
    // The checks and the power-of-two rescaling of hull() (which fails the same way when they fail).
    if (input.count > std::numeric_limits<std::uint32_t>::max()) return from_hull();
    double largest = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < 3 * input.count; ++i) {
        const double magnitude = std::fabs(input.xyz[i]);
        if (!(magnitude <= std::numeric_limits<double>::max())) return from_hull();
        largest = std::max(largest, magnitude);
        if (magnitude != 0.0) smallest = std::min(smallest, magnitude);
    }
    int exponent = 0;
    if (!predicates_range_ok(largest, smallest) && !predicates_scale_exponent(largest, smallest, &exponent))
        return from_hull();
    std::vector<double> scaled;
    PointSpan points = input;
    if (exponent != 0) {
        scaled.resize(3 * input.count);
        for (std::size_t i = 0; i < scaled.size(); ++i) scaled[i] = std::ldexp(input.xyz[i], exponent);
        points = PointSpan(scaled.data(), input.count);
    }
    if (detail::find_simplex(points).dimension < 3) return from_hull();

    detail::Polygons faces;
    std::string error;
    const detail::ExactSides sides;
    detail::GiftWrapper<detail::ExactSides, true> wrapper(points, detail::distinct_points(points), sides, scan, &trace);
    if (!wrapper.run(faces, error)) {  // not expected with exact sides
        trace = GiftwrapTrace{};
        trace.error = error;
        return trace;
    }
    trace.dimension = 3;
    for (std::size_t i = 0; i < trace.size(); ++i) {
        if (trace.kind(i) == GiftwrapEvent::Accept)
            trace.triangles.insert(trace.triangles.end(), trace.arguments(i), trace.arguments(i) + 3);
    }
    return trace;
}

}  // namespace hullkit
