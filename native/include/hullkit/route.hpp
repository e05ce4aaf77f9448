// hullkit: route checking with swept traverses (the seed document's first paragraph).
//
// A traverse (one or more triangle meshes, its "parts") moves along a route of straight
// translations; waypoint k to waypoint k + 1 is leg k. For each leg one check answers whether the
// traverse stays more than `margin` away from every obstacle over the whole leg:
//   broad phase   the convex hull of each part's vertices at both ends of the leg (everything the
//                 part sweeps lies inside it): clear of every obstacle by more than the margin
//                 means clear, with no false negatives by construction;
//   narrow phase  where the broad phase hits, each triangle of the part sweeps the convex hull of
//                 itself at both ends (a prism of at most 6 points); the part sweeps the union of
//                 those plus its own volume at the start, so a non-convex part gives no false hit;
//   first contact the smallest fraction of the leg at which the traverse comes within the margin,
//                 bracketed in [lo, hi] with lo never after the true contact.
// Intersection decisions use exact predicates; a method that cannot certify "clear" reports a hit.
//
// What is exact, precisely. The geometry tested is the traverse's triangles with vertices v + w
// rounded to doubles (w the offset: a waypoint, or a + t (b - a) rounded for a fraction t inside a
// leg) and the obstacles' triangles as given. The sweep of a triangle from offset w0 to w1 is the
// union of 8 triangles (its two copies and, per edge, the parallelogram the edge sweeps), so
// "does the sweep meet this obstacle triangle" is 8 triangle-triangle tests, each decided by exact
// orient3d / orient2d on those doubles, every degenerate case included (touching, coplanar,
// collinear, zero-area triangles, zero-length legs). Margin 0 verdicts and brackets are therefore
// exact for the rounded translated coordinates; near 1e6 a rounding step is about 1e-10 there.
// Containment (a closed part inside a closed obstacle or the reverse) is ray parity with exact
// orientation signs; rays found degenerate (exactly) are retried in other directions, and a point
// never certified outside counts as inside (a hit). Surfaces must meet before one closed solid can
// enter another, so containment is tested at the start of each leg only.
// With margin > 0 "within the margin" compares a floating-point squared distance (closest points
// by region clamping, relative error ~1e-15) with margin^2: the bracket is exact for that computed
// distance; at a tangential approach hi may precede the true moment by ~1e-10 of the leg.
// Floating-point filters (box windows, separating axes) only ever discard what they prove apart by
// a tolerance far above their rounding, so they never turn a contact into "clear".
// A closed part that is convex (every triangle in a supporting plane of its hull) is represented
// by its hull's triangles (same solid, usually far fewer triangles).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace hullkit {

/// A triangle mesh: points x0 y0 z0 x1 ... and 3 indices per triangle. Triangle soups and open
/// surfaces are allowed; a closed mesh (every edge shared by exactly two triangles with opposite
/// directions) also counts its inside.
struct TriangleMesh {
    std::string name;
    std::vector<double> xyz;
    std::vector<std::uint32_t> triangles;
};

/// What a route check needs: the traverse's parts, the obstacles, the waypoints (translation
/// offsets applied to every traverse vertex, and optionally orientations) and the required
/// clearance.
///
/// Orientations (legs that turn). With `rotations` a traverse vertex v is placed at waypoint k at
/// c + R_k (v - c) + o_k (c the pivot, o_k the waypoint, R_k the rotation of the unit quaternion
/// rotations[4k .. 4k + 4) = w x y z); between two waypoints the offset moves linearly and the
/// orientation turns at constant angular speed along the shorter arc (slerp), both over the same
/// fraction t in [0, 1]. A leg whose two orientations are equal (the same quaternion or its
/// negative, bit for bit) is a translation of the rotated traverse, checked exactly as before;
/// without rotations, or with identity orientations, the results are those of a plain route.
struct Scene {
    std::vector<TriangleMesh> parts;
    std::vector<TriangleMesh> obstacles;
    std::vector<double> route;  ///< waypoints, flat x y z; at least 2
    /// Empty (no rotations) or 4 numbers w x y z per waypoint: unit quaternions (within 1e-9;
    /// normalized before use).
    std::vector<double> rotations;
    double pivot[3] = {0.0, 0.0, 0.0};  ///< the point the traverse turns about, own coordinates
    double margin = 0.0;        ///< required clearance, >= 0
};

enum class LegStatus {
    Clear,         ///< more than `margin` from every obstacle over the whole leg
    Hit,           ///< comes within `margin` of an obstacle during the leg
    StartOverlap,  ///< already within `margin` of an obstacle at the leg's start
};

/// "clear", "hit", "start-overlap"
const char* leg_status_name(LegStatus status);

struct LegReport {
    LegStatus status = LegStatus::Clear;
    /// Hit / StartOverlap: the obstacle, its triangle and the traverse part in contact.
    /// Clear: the nearest obstacle over the leg (when clearance was computed), else -1.
    std::int64_t obstacle = -1;
    std::int64_t triangle = -1;
    std::int64_t part = -1;
    /// Hit: [lo, hi] brackets the first moment the traverse comes within the margin; hi - lo <= 1e-9
    /// (1e-7 on a turning leg) and lo is never after the true first contact. StartOverlap: [0, 0].
    /// Clear: both are the fraction at which the minimum clearance occurs.
    double fraction_lo = 0.0;
    double fraction_hi = 0.0;
    double position[3] = {0.0, 0.0, 0.0};  ///< the traverse offset at fraction_lo
    /// The traverse's orientation at fraction_lo (w x y z; the identity without rotations).
    double rotation[4] = {1.0, 0.0, 0.0, 0.0};
    /// Hit on a turning leg only: the bounds could neither separate the traverse from the obstacle
    /// over [fraction_lo, fraction_hi] nor find the pose at fraction_hi in contact (a tangential
    /// graze, closer than the bounds resolve). The leg is not certified clear, so it is reported
    /// as a hit; fraction_lo is still never after a true first contact.
    bool grazing = false;
    /// Clear: the minimum distance over the leg, correct to 1e-9 relative (infinity without
    /// obstacles; NaN when RouteOptions::clearance is off). Hit: the distance of the contact pair
    /// at fraction_hi (at most the margin; 0 at margin 0). StartOverlap: the distance of the pair
    /// at the start, 0 when one solid contains the other (then `triangle` is one triangle of the
    /// contained obstacle piece, or 0 when the obstacle contains the part).
    double clearance = std::numeric_limits<double>::quiet_NaN();
    /// With RouteOptions::samples = N > 0: what checking the traverse statically at N + 1 evenly
    /// spaced poses (fractions 0, 1/N, ..., 1) finds: whether any pose is within the margin, and the
    /// first such fraction (NaN when none is).
    bool sampled_hit = false;
    double sampled_fraction = std::numeric_limits<double>::quiet_NaN();
};

struct RouteOptions {
    /// Compute the clearance of clear legs (minimum distance, where it occurs and to what).
    bool clearance = true;
    /// Also run N-step discrete sampling per leg, for comparison (0: off).
    std::uint32_t samples = 0;
    /// Threads checking legs: 0 every hardware thread, 1 the calling thread only, N at most N
    /// (never more than there are legs). Legs are independent, so the report (every field of every
    /// leg, `clear`, `min_clearance`; not the timings) is bit for bit the same for every value.
    /// The WebAssembly build is single-threaded and ignores it.
    unsigned threads = 0;
    /// Optional: called as legs finish with the number of legs done so far. It may be called from
    /// any of the worker threads, and calls are not guaranteed never to overlap: the receiver must
    /// be thread-safe. The counts passed increase, and the last call, before check() returns,
    /// passes the leg count (exactly once). Not called when the check fails before its first leg.
    /// An exception thrown by it stops the check and leaves check().
    std::function<void(std::size_t legs_done)> progress;
};

struct RouteReport {
    bool clear = true;  ///< every leg clear
    bool turned = false;  ///< the route checked had orientations (LegReport::rotation is meaningful)
    double min_clearance = std::numeric_limits<double>::infinity();  ///< over all legs
    std::vector<LegReport> legs;
    double build_seconds = 0.0;  ///< preparing the scene (hulls, BVH) after reading it
    double seconds = 0.0;        ///< checking all legs
    std::string error;           ///< empty on success; then nothing in the report means anything

    bool ok() const { return error.empty(); }
};

/// What the traverse touches at one fixed offset (the static check behind RouteOptions::samples,
/// also an oracle for tests). Same geometry and exactness as RouteChecker::check.
struct StaticContact {
    /// Within the margin of an obstacle: touching at margin 0, or one inside a closed other.
    bool contact = false;
    /// With want_distance: the minimum distance between the traverse's and the obstacles'
    /// surfaces (0 when they meet or one is inside the other; infinity without obstacles).
    /// NaN otherwise.
    double distance = std::numeric_limits<double>::quiet_NaN();
    /// The obstacle, its triangle and the part in contact (contact) or nearest (distance), else -1.
    std::int64_t obstacle = -1;
    std::int64_t triangle = -1;
    std::int64_t part = -1;
};

/// Keeps what a scene needs between checks: the parts' geometry and hulls, and the obstacles'
/// bounding-volume hierarchy, built once. check() may be called many times (interactive dragging).
class RouteChecker {
public:
    /// Builds the acceleration structures. A bad scene (an index out of range, a non-finite
    /// coordinate, a negative or non-finite margin, no parts) leaves error() non-empty, naming the
    /// part or obstacle and the triangle or point; check() then returns that error.
    explicit RouteChecker(Scene scene);
    ~RouteChecker();
    RouteChecker(RouteChecker&&) noexcept;
    RouteChecker& operator=(RouteChecker&&) noexcept;

    const std::string& error() const;
    const Scene& scene() const;
    double build_seconds() const;

    /// Checks `waypoint_count` waypoints (flat x y z) against the scene's obstacles with the
    /// scene's margin. Fewer than 2 waypoints or a non-finite one is an error in the report.
    RouteReport check(const double* route_xyz, std::size_t waypoint_count,
                      const RouteOptions& options = {}) const;
    /// The same with an orientation per waypoint: `rotations_wxyz` holds 4 numbers per waypoint
    /// (unit quaternions w x y z, within 1e-9), or is null for none. See Scene::rotations.
    RouteReport check(const double* route_xyz, const double* rotations_wxyz, std::size_t waypoint_count,
                      const RouteOptions& options = {}) const;
    /// Checks the scene's own route.
    RouteReport check(const RouteOptions& options = {}) const;

    /// The traverse translated by `offset` (x y z), checked statically against the obstacles with
    /// the scene's margin; `want_distance` also computes the minimum distance (costlier). On a bad
    /// scene or a non-finite offset: contact true, distance NaN.
    StaticContact static_contact(const double offset[3], bool want_distance = false) const;
    /// The same at a turned pose: the traverse turned by the unit quaternion `rotation_wxyz` about
    /// the scene's pivot, then translated by `offset` (see Scene). A non-unit rotation (beyond
    /// 1e-9) counts as a bad offset.
    StaticContact static_contact(const double offset[3], const double rotation_wxyz[4],
                                 bool want_distance = false) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// The pose at fraction t in [0, 1] of a leg from (offset o0, orientation q0) to (o1, q1), as the
/// checker moves the traverse: offset o0 + t (o1 - o0), orientation turning at constant angular
/// speed along the shorter arc (slerp); exactly the end poses at t = 0 and t = 1. Orientations are
/// unit quaternions w x y z (normalized here).
void leg_pose(const double o0[3], const double q0[4], const double o1[3], const double q1[4], double t,
              double offset[3], double rotation[4]);

/// Same as checker.static_contact(offset, want_distance).
StaticContact static_contact(const RouteChecker& checker, const double offset[3],
                             bool want_distance = false);

/// One-shot: builds a RouteChecker for `scene` and checks its route.
RouteReport check_route(Scene scene, const RouteOptions& options = {});

}  // namespace hullkit
