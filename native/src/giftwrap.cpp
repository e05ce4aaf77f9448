#include "hullkit/giftwrap.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "hull_internal.hpp"

namespace hullkit {
namespace {

using Index = std::uint32_t;
constexpr Index kNone = ~Index{0};

glm::dvec3 vec(const double* p) { return {p[0], p[1], p[2]}; }

/// The seed document's side tests: signed distances (unit normals) compared with an epsilon
/// scaled to the taxicab extent of the cloud. Signs: +1 above/left, -1 below/right, 0 within eps.
class SeedEpsilon {
public:
    explicit SeedEpsilon(PointSpan points) {
        glm::dvec3 lo(0.0), hi(0.0);
        if (points.count > 0) lo = hi = vec(points[0]);
        for (std::size_t i = 1; i < points.count; ++i) {
            lo = glm::min(lo, vec(points[i]));
            hi = glm::max(hi, vec(points[i]));
        }
        const glm::dvec3 extent = hi - lo;
        eps_2d_ = DBL_EPSILON * (extent.x + extent.y);
        eps_3d_ = DBL_EPSILON * (extent.x + extent.y + extent.z);
    }

    /// Step 2's test on the flattened points: side of c from the directed line a->b in x-y.
    int orient_xy(const double* a, const double* b, const double* c) const {
        return orient_projected(a, b, c, 0, 1, eps_2d_);
    }

    /// Side of c from a->b after dropping one axis, (i, j) the kept axes in cyclic order.
    int orient_in_plane(const double* a, const double* b, const double* c, int i, int j) const {
        return orient_projected(a, b, c, i, j, eps_3d_);
    }

    /// Side of d from the plane of a, b, c; "above" is where (b-a) x (c-a) points.
    int orient3d(const double* a, const double* b, const double* c, const double* d) const {
        const glm::dvec3 pa = vec(a);
        const glm::dvec3 n = glm::cross(vec(b) - pa, vec(c) - vec(b));
        const double length = glm::length(n);
        if (length == 0.0) return 0;
        return sign(glm::dot(n, vec(d) - pa) / length, eps_3d_);
    }

    /// Whether c lies on the line through a and b (within eps_3D).
    bool collinear(const double* a, const double* b, const double* c) const {
        const glm::dvec3 e = vec(b) - vec(a);
        const double length = glm::length(e);
        if (length == 0.0) return true;
        return glm::length(glm::cross(e, vec(c) - vec(a))) / length <= eps_3d_;
    }

private:
    static int sign(double distance, double eps) { return distance > eps ? 1 : (distance < -eps ? -1 : 0); }

    static int orient_projected(const double* a, const double* b, const double* c, int i, int j,
                                double eps) {
        const double ex = b[i] - a[i];
        const double ey = b[j] - a[j];
        const double length = std::hypot(ex, ey);
        if (length == 0.0) return 0;
        return sign((ex * (c[j] - a[j]) - ey * (c[i] - a[i])) / length, eps);
    }

    double eps_2d_ = 0.0;
    double eps_3d_ = 0.0;
};

std::uint64_t edge_key(Index a, Index b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t{a} << 32) | b;
}

/// One run of the wrap over the distinct input points `ids`.
template <class Predicates>
class GiftWrapper {
public:
    GiftWrapper(PointSpan points, std::vector<Index> ids, const Predicates& predicates, GiftwrapScan scan)
        : points_(points), ids_(std::move(ids)), pred_(predicates), scan_(scan) {}

    Hull run() {
        if (std::string why = volume_check(); !why.empty()) return detail::failure(why);

        std::vector<Index> polygon;
        if (!first_face(polygon) || !add_face(polygon)) return detail::failure(error_);
        // Step 4: pop an edge whose other side is unknown and wrap across it.
        while (!stack_.empty()) {
            const auto [u, v] = stack_.back();
            stack_.pop_back();
            if (edge_faces_[edge_key(u, v)] >= 2) continue;  // found meanwhile from another edge
            if (!face_across(u, v, polygon) || !add_face(polygon)) return detail::failure(error_);
        }
        if (std::string why = closure_check(); !why.empty()) return detail::failure(why);

        Hull result;
        result.triangles = std::move(triangles_);
        detail::finish_hull(points_, result);
        return result;
    }

private:
    const double* at(Index i) const { return points_[i]; }

    /// Reports input without volume, naming the case: identical, collinear or coplanar points.
    std::string volume_check() const {
        const std::string all = "all " + std::to_string(points_.count) + " points ";
        if (ids_.size() == 1) return all + "are identical: the hull has no volume";
        const Index p0 = ids_[0];
        const Index p1 = ids_[1];
        auto off_line = std::find_if(ids_.begin() + 2, ids_.end(),
                                     [&](Index q) { return !pred_.collinear(at(p0), at(p1), at(q)); });
        if (off_line == ids_.end()) return all + "are collinear: the hull has no volume";
        const Index p2 = *off_line;
        auto off_plane = std::find_if(ids_.begin() + 2, ids_.end(), [&](Index q) {
            return pred_.orient3d(at(p0), at(p1), at(p2), at(q)) != 0;
        });
        if (off_plane == ids_.end()) return all + "are coplanar: the hull has no volume";
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

        Index b = kNone;  // all flattened points end up left of (or on) a -> b
        for (Index q : ids_) {
            if (at(q)[0] == at(a)[0] && at(q)[1] == at(a)[1]) continue;
            if (b == kNone || pred_.orient_xy(at(a), at(b), at(q)) < 0) b = q;
        }
        if (b == kNone) return fail("no first edge: the flattened points do not span a plane");

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
            return planar_polygon(on_vertical, u, v, apart, polygon);
        }
        // The vertical plane touches the hull along a segment: its two end points form a hull edge.
        const glm::dvec3 direction = glm::abs(vec(at(b)) - vec(at(a)));
        const int axis = direction.x >= direction.y ? (direction.x >= direction.z ? 0 : 2)
                                                    : (direction.y >= direction.z ? 1 : 2);
        auto along = [&](Index p, Index q) { return at(p)[axis] < at(q)[axis]; };
        const Index u = *std::min_element(on_vertical.begin(), on_vertical.end(), along);
        const Index v = *std::max_element(on_vertical.begin(), on_vertical.end(), along);
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
        if (!planar_polygon(coplanar_, u, v, c, polygon)) return false;
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
                if (!pred_.collinear(at(u), at(v), at(q))) c = q;
                continue;
            }
            const int side = pred_.orient3d(at(u), at(v), at(c), at(q));
            if (side > 0) {
                c = q;
                coplanar_.clear();
            } else if (side == 0 && !pred_.collinear(at(u), at(v), at(q))) {
                coplanar_.push_back(q);
            }
        }
        return c;
    }

    /// The seed's literal scan: the first candidate with no point above its plane.
    Index apex_restart(Index u, Index v) {
        for (Index c : ids_) {
            if (c == u || c == v || pred_.collinear(at(u), at(v), at(c))) continue;
            coplanar_.clear();
            bool accepted = true;
            for (Index q : ids_) {
                const int side = pred_.orient3d(at(u), at(v), at(c), at(q));
                if (side > 0) {
                    accepted = false;
                    break;
                }
                if (side == 0 && q != u && q != v && q != c && !pred_.collinear(at(u), at(v), at(q)))
                    coplanar_.push_back(q);
            }
            if (accepted) return c;
        }
        return kNone;
    }

    /// The strictly convex polygon (2D hull) of the coplanar `members`, counter-clockwise seen
    /// from the side (b - a) x (c - a) points to.
    bool planar_polygon(std::vector<Index> members, Index a, Index b, Index c, std::vector<Index>& polygon) {
        // Drop the axis along which the plane's normal is largest; its sign orients the result.
        const glm::dvec3 normal = glm::abs(glm::cross(vec(at(b)) - vec(at(a)), vec(at(c)) - vec(at(a))));
        int order[3] = {0, 1, 2};
        std::sort(order, order + 3, [&](int p, int q) { return normal[p] > normal[q]; });
        int i = 0, j = 0, orientation = 0;
        for (int dropped : order) {
            i = (dropped + 1) % 3;
            j = (dropped + 2) % 3;
            orientation = pred_.orient_in_plane(at(a), at(b), at(c), i, j);
            if (orientation != 0) break;
        }
        if (orientation == 0) return fail("degenerate face at edge " + edge_name(a, b));

        std::sort(members.begin(), members.end(), [&](Index p, Index q) {
            if (at(p)[i] != at(q)[i]) return at(p)[i] < at(q)[i];
            if (at(p)[j] != at(q)[j]) return at(p)[j] < at(q)[j];
            return p < q;
        });
        members.erase(std::unique(members.begin(), members.end()), members.end());
        // Andrew's monotone chain, dropping points on polygon edges (strict turns only).
        polygon.clear();
        auto turns_left = [&](Index p, Index q, Index r) { return pred_.orient_in_plane(at(p), at(q), at(r), i, j) > 0; };
        auto chain = [&](auto first, auto last) {
            const std::size_t floor = polygon.size();
            for (auto it = first; it != last; ++it) {
                while (polygon.size() >= floor + 2 &&
                       !turns_left(polygon[polygon.size() - 2], polygon.back(), *it))
                    polygon.pop_back();
                polygon.push_back(*it);
            }
            polygon.pop_back();  // the chain's last point starts the other chain
        };
        chain(members.begin(), members.end());
        chain(members.rbegin(), members.rend());
        if (polygon.size() < 3) return fail("degenerate face at edge " + edge_name(a, b));
        if (orientation < 0) std::reverse(polygon.begin(), polygon.end());
        return true;
    }

    /// Records a face: its triangles (a fan), and for each of its edges whose other side is still
    /// unknown, that edge reversed on the stack (step 4's "two new edges", for a whole polygon).
    bool add_face(const std::vector<Index>& polygon) {
        const std::size_t m = polygon.size();
        for (std::size_t k = 0; k < m; ++k) {
            const Index p = polygon[k];
            const Index q = polygon[(k + 1) % m];
            const int faces = ++edge_faces_[edge_key(p, q)];
            if (faces > 2) return fail("edge " + edge_name(p, q) + " found on a third face");
            if (faces == 1) stack_.emplace_back(q, p);
        }
        for (std::size_t k = 1; k + 1 < m; ++k) {
            triangles_.push_back(polygon[0]);
            triangles_.push_back(polygon[k]);
            triangles_.push_back(polygon[k + 1]);
        }
        return true;
    }

    /// Every edge must border exactly two faces and the surface must be a sphere (V - E + F = 2).
    std::string closure_check() const {
        for (const auto& [key, faces] : edge_faces_) {
            if (faces != 2) {
                return "gift wrapping did not close: edge " +
                       edge_name(static_cast<Index>(key >> 32), static_cast<Index>(key)) + " has " +
                       std::to_string(faces) + " face(s)";
            }
        }
        std::vector<Index> used(triangles_);
        std::sort(used.begin(), used.end());
        const auto vertices = static_cast<long long>(std::unique(used.begin(), used.end()) - used.begin());
        const auto faces = static_cast<long long>(triangles_.size() / 3);
        const long long edges = faces * 3 / 2;
        if (vertices - edges + faces != 2)
            return "gift wrapping produced a surface that is not a sphere (V - E + F = " +
                   std::to_string(vertices - edges + faces) + ")";
        return {};
    }

    static std::string edge_name(Index a, Index b) { return std::to_string(a) + "-" + std::to_string(b); }

    bool fail(std::string message) {
        error_ = "near-degenerate input defeats the epsilon side tests: " + std::move(message);
        return false;
    }

    PointSpan points_;
    std::vector<Index> ids_;
    const Predicates& pred_;
    GiftwrapScan scan_;

    std::vector<std::pair<Index, Index>> stack_;           // directed edges u -> v to wrap across
    std::unordered_map<std::uint64_t, int> edge_faces_;    // unordered edge -> faces found on it
    std::vector<Index> coplanar_;                          // scratch: ties of the current apex
    std::vector<Index> triangles_;
    std::string error_;
};

}  // namespace

Hull giftwrap(PointSpan points, GiftwrapScan scan) {
    if (Hull invalid = detail::validate_input(points); !invalid.ok()) return invalid;
    const SeedEpsilon predicates(points);
    return GiftWrapper<SeedEpsilon>(points, detail::distinct_points(points), predicates, scan).run();
}

}  // namespace hullkit
