// Private to RouteChecker's files: what they share. struct RouteChecker::Impl (the prepared scene
// and the declarations of its steps), a prepared traverse part and the connected components of a
// mesh, the coordinate limits, and the small helpers used by several of the steps (triangle boxes,
// offsets along a leg, the 8 triangles of a swept triangle, BVH box queries).
//
// The files: prepare.cpp (validation, part hulls, BVHs), static_contact.cpp (the exact test of one
// pose), sweep.cpp (the first contact over a leg), clearance.cpp (the minimum distance over a
// leg), turning.cpp (legs that turn: certified sub-intervals, first contact, clearance),
// checker.cpp (the legs, the public API, and how a leg is checked exactly).
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "bvh.hpp"
#include "convex_sweep.hpp"
#include "geometry.hpp"
#include "hullkit/route.hpp"
#include "motion.hpp"

namespace hullkit::route_detail {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Coordinates (and offsets) are limited so that every translated coordinate stays inside the exact
/// range of the predicates (see predicates.hpp) with room to spare.
constexpr double kMaxCoordinate = 0x1p+300;
constexpr double kMinCoordinate = 0x1p-200;

struct Component {
    Box box;
    Vec rep;                     ///< one vertex of the component
    std::uint32_t triangle = 0;  ///< one triangle of it (reported on containment)
    std::uint32_t mesh = 0;      ///< obstacle index (obstacle components)
};

/// One traverse part, in its own coordinates (offset 0).
struct Part {
    std::vector<Vec> tris;  ///< surface triangles, 3 points each, in BVH leaf order
    Bvh bvh;
    Box box;
    bool closed = false;
    bool hull_surface = false;  ///< closed and convex: its hull's triangles stand for its surface
    std::vector<Component> components;
    // Broad phase: the part's hull, as points, edge directions, and fixed axes with the hull's
    // extent along each.
    std::vector<Vec> hull_points;
    std::vector<Vec> hull_edges;
    std::vector<Vec> axes;
    std::vector<double> axis_lo, axis_hi;
    // The hull's distinct face normals and edge directions (convex_sweep.hpp).
    std::vector<Vec> face_normals, edge_directions;
};

inline Box triangle_box(const Vec* t) {
    Box b;
    for (int k = 0; k < 3; ++k) b.add(t[k]);
    return b;
}

/// The offset at fraction t of the leg a -> b; exactly b at t = 1 so that consecutive legs agree.
inline Vec offset_at(const Vec& a, const Vec& b, double t) {
    return t == 1.0 ? b : a + t * (b - a);
}

/// The 8 triangles whose union is the sweep of triangle p (local) from offset w0 to w1; the first
/// is p at w0 (the start cap). fraction_of() tells where along the sweep a point of piece k lies.
inline void sweep_pieces(const Vec* p, const Vec& w0, const Vec& w1, Vec pieces[8][3]) {
    const Vec a[3] = {p[0] + w0, p[1] + w0, p[2] + w0};
    const Vec b[3] = {p[0] + w1, p[1] + w1, p[2] + w1};
    for (int k = 0; k < 3; ++k) {
        pieces[0][k] = a[k];
        pieces[1][k] = b[k];
    }
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        Vec* first = pieces[2 + 2 * i];
        Vec* second = pieces[3 + 2 * i];
        first[0] = a[i], first[1] = a[j], first[2] = b[j];
        second[0] = a[i], second[1] = b[j], second[2] = b[i];
    }
}

/// Fixed, "generic" directions for parity rays; a ray found degenerate (exactly) is retried with
/// the next one (static_contact.cpp).
Vec ray_direction(int attempt);

/// What a turning leg keeps while its sub-intervals are certified (turning.cpp).
struct TurnState;

/// Visits visit(item) for the items in the BVH leaves whose boxes overlap `query`; stops when
/// visit returns true.
template <typename Visit>
void for_each_in_box(const Bvh& bvh, const Box& query, Visit&& visit) {
    walk_tree(bvh, [&](std::uint32_t n) { return !bvh.nodes[n].box.overlaps(query); },
              [&](std::uint32_t item) { return !visit(item); });
}

}  // namespace hullkit::route_detail

namespace hullkit {

// The route module's types and helpers by their short names in RouteChecker's files.
using namespace route_detail;

struct RouteChecker::Impl {
    Scene scene;
    std::string error;
    double build_seconds = 0.0;
    double margin = 0.0;
    double scale = 0.0;  ///< largest |coordinate| of the geometry
    Box world;           ///< box of all geometry (parts at offset 0 and obstacles)

    std::vector<Part> parts;

    // Obstacle triangles of every obstacle in one BVH, stored in its leaf order.
    std::vector<Vec> tris;
    std::vector<std::uint32_t> tri_obstacle, tri_index;
    Bvh bvh;
    std::vector<char> obstacle_closed;
    std::vector<Box> obstacle_box;
    std::vector<Component> obstacle_components;

    void build();
    void build_part(const TriangleMesh& mesh, Part& part) const;

    /// Absolute tolerance for floating-point filters around offsets up to `offset_scale`: far
    /// above the rounding of the few operations the filters do, far below anything geometric.
    double tolerance(double offset_scale) const {
        return 1e-12 * (scale + offset_scale + margin) + 1e-290;
    }

    struct Found {
        bool found = false;
        double lo = 1.0, hi = 1.0;
        std::int64_t obstacle = -1, triangle = -1, part = -1;
        std::uint32_t slot = 0;        ///< obstacle triangle (BVH slot)
        std::uint32_t part_slot = 0;   ///< part triangle (BVH slot)
        bool containment = false;
    };

    bool pair_static(const Vec* p, const Vec& w, const Vec* q) const {
        const Vec pw[3] = {p[0] + w, p[1] + w, p[2] + w};
        if (margin == 0.0) return triangles_meet(pw, q);
        double weights[3];
        return triangle_distance2(pw, q, weights) <= margin * margin;
    }

    /// Contact of p swept from w0 to w1 with q, p at w0 being known clear.
    bool pair_sweep(const Vec* p, const Vec& w0, const Vec& w1, const Vec* q) const {
        Vec pieces[8][3];
        sweep_pieces(p, w0, w1, pieces);
        for (int k = 1; k < 8; ++k) {
            if (margin == 0.0) {
                if (triangles_meet(pieces[k], q)) return true;
            } else {
                double weights[3];
                if (triangle_distance2(pieces[k], q, weights) <= margin * margin) return true;
            }
        }
        return false;
    }

    bool inside_part(const Part& part, const Vec& w, const Vec& x, double tol) const;
    bool inside_obstacle(std::uint32_t o, const Vec& x, double tol) const;
    // The steps take the part (scene part pi, or its turned copy for a leg of one orientation).
    bool static_touch(const Part& part, std::size_t pi, const Vec& w, Found* found) const;
    void sweep_part(const Part& part, std::size_t pi, const Vec& a, const Vec& b, Found* found) const;

    struct Nearest {
        double distance = kInf;
        double fraction = 0.0;
        std::int64_t obstacle = -1, triangle = -1, part = -1;
    };
    void nearest_over_leg(const Part& part, std::size_t pi, const Vec& a, const Vec& b, Nearest* best) const;

    bool check_offsets(const double* xyz, std::size_t count, std::string* error) const;
    /// A translation of `with` (the scene's parts, or their copies turned to the leg's orientation).
    LegReport check_leg(const std::vector<Part>& with, const Vec& a, const Vec& b, const RouteOptions& options) const;
    /// legs[k] = leg(k) for k < count, on the threads of `options`, with progress reports.
    void check_legs(std::size_t count, const RouteOptions& options, const std::function<LegReport(std::size_t)>& leg,
                    LegReport* legs) const;
    StaticContact contact_at(const Vec& w, bool want_distance) const;
    /// The static contact over the parts from `touch(pi, Found*)` (true on contact) and, for the
    /// distance, `nearest(pi, Nearest*)`.
    template <typename Touch, typename NearestOf>
    StaticContact contact_with(bool want_distance, Touch&& touch, NearestOf&& nearest) const {
        StaticContact result;
        Found found;
        for (std::size_t pi = 0; pi < parts.size() && !result.contact; ++pi) {
            if (touch(pi, &found)) {
                result.contact = true;
                result.obstacle = found.obstacle;
                result.triangle = found.triangle;
                result.part = found.part;
            }
        }
        if (!want_distance) return result;
        if (result.contact && (found.containment || margin == 0.0)) {
            result.distance = 0.0;
            return result;
        }
        Nearest best;
        for (std::size_t pi = 0; pi < parts.size(); ++pi) nearest(pi, &best);
        result.distance = best.distance;
        if (!result.contact) {
            result.obstacle = best.obstacle;
            result.triangle = best.triangle;
            result.part = best.part;
        }
        return result;
    }

    // Legs that turn (turning.cpp; motion.hpp has the motion and its bound).
    Vec pivot{0.0};  ///< the scene's pivot
    /// Copies of the parts turned by q about the pivot (build_part on the turned meshes).
    std::vector<Part> turned_parts(const Quat& q) const;
    LegReport check_turning_leg(const LegMotion& motion, const RouteOptions& options) const;
    /// Part pi at a pose: its triangles, and its BVH nodes' boxes (not grown).
    struct PlacedPart {
        std::vector<Vec> tris;
        std::vector<Box> boxes;
    };
    void place_part(std::size_t pi, const Pose& pose, PlacedPart* out) const;
    /// The exact static test of part pi at a pose (the translation test when it is not turned);
    /// `placed`: the part already placed there (else it is placed here).
    bool posed_touch(std::size_t pi, const Pose& pose, Found* found, const PlacedPart* placed = nullptr) const;
    void posed_nearest(std::size_t pi, const Pose& pose, double t, Nearest* best, const PlacedPart* placed = nullptr) const;
    StaticContact posed_contact(const Pose& pose, bool want_distance) const;
    bool inside_placed(const std::vector<Vec>& placed, const Vec& x, const Box& box, double tol) const;
    double placed_pair_distance(std::size_t pi, std::uint32_t part_slot, std::uint32_t slot, const Pose& pose) const;
    void turn_prepare(TurnState& st) const;
    void turn_interval(TurnState& st, double t0, double t1) const;
    /// Whether part pi stays clear over st's interval: its hull's sweep against the obstacles'
    /// BVH, then (a part that is not its hull) its own triangles near the obstacle triangles left.
    bool turn_certify(TurnState& st, std::size_t pi) const;
    /// After turn_certify failed on an interval: keeps the obstacle triangles its pieces must
    /// check (when few).
    void turn_frame(TurnState& st, std::size_t pi) const;
    /// After an interval failed: the fraction where the pair that failed it (st's hint) seems to
    /// come within the margin, from its gap at both ends along one direction; -1 when that gives
    /// nothing. Only a place to split the search: it decides nothing.
    double turn_guess(TurnState& st) const;
    /// The triangle of part pi nearest to obstacle slot `slot` at `pose`.
    std::uint32_t nearest_part_slot(std::size_t pi, std::uint32_t slot, const Pose& pose) const;
    double turn_lower_bound(TurnState& st, std::size_t pi, double cutoff) const;
    void turn_clearance(const LegMotion& motion, LegReport* leg) const;
};

}  // namespace hullkit
