// The seed document's 3D gift wrapping ("Obtaining the Convex Hull from a Set of Points using
// the Gift Wrapping Algorithm"), steps 1-4, with two refinements:
//  - one pass per hull edge: when a point lies above the current candidate plane it becomes the
//    candidate and the scan goes on (every point already passed lies below the new plane too, as
//    all points sit in the wedge of less than 180 degrees around a hull edge), so the whole wrap
//    is O(n*h) as the document claims; GiftwrapScan::Restart keeps the literal O(n^2)-per-edge
//    search for comparison;
//  - faces are wrapped whole: the points coplanar with the winning plane form one convex polygon
//    (its 2D hull inside the plane), which is then fanned into triangles. Every edge the wrap pivots
//    on is therefore a true hull edge, and coplanar points (a cube's faces) cannot produce
//    overlapping or inconsistent triangles.
// Side tests are exact by default. HullOptions::side_test = SideTest::Seed uses the seed's epsilon
// instead: a point counts as above a plane only when its signed distance exceeds
// eps_3D = DBL_EPSILON * (dx + dy + dz) (taxicab extent of the cloud), and as off a line in 2D only
// beyond eps_2D = DBL_EPSILON * (dx + dy); near-degenerate input can then fail (reported as such).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "hullkit/hull.hpp"

namespace hullkit {

/// Gift-wraps `points` with exact side tests: hullkit::hull() with Algorithm::Giftwrap.
Hull giftwrap(PointSpan points, GiftwrapScan scan = GiftwrapScan::SinglePass);

/// What happened at one step of a recorded gift wrap (GiftwrapTrace). Each event has three
/// arguments a, b, c (point indices into the input; unused ones are 0). "Above" a candidate's
/// plane means on the side where (b - a) x (c - a) points, i.e. outside the would-be face.
enum class GiftwrapEvent : std::uint8_t {
    FirstPoint = 0,  ///< a: step 1, the point with the largest x (then y, then z)
    FirstEdge,       ///< a b: step 2, the edge a -> b of the flattened points' hull leaving a
    VerticalFace,    ///< a b c: the vertical plane through the first edge holds a face (a, b, c span
                     ///< it); its Accept events follow, no candidate search
    WrapFirst,       ///< a b: the vertical plane touches the hull along the segment a-b; the first
                     ///< face is wrapped across a -> b (not from the stack): Candidate... follow
    PushEdge,        ///< a b: a -> b pushed onto the edge stack (the face on its left is unknown)
    PopEdge,         ///< a b: a -> b popped to be wrapped: the face holding a -> b is searched next
    SkipEdge,        ///< a b: a -> b popped, but both its faces are known already: discarded
    Candidate,       ///< a b c: candidate triangle a, b, c for the edge a -> b
    Replace,         ///< a b p: single pass: p lies above the candidate's plane and becomes the
                     ///< candidate (the new candidate triangle is a, b, p)
    Restart,         ///< a b p: restart (the seed's literal step 4): p lies above the plane of the
                     ///< current candidate, which is rejected; the next Candidate starts over
    Coplanar,        ///< a b p: p lies exactly on the current candidate's plane (off the line a-b):
                     ///< it belongs to the face if the candidate stands (a Replace forgets it)
    Accept,          ///< a b c: a triangle of the hull, counter-clockwise seen from outside; a face
                     ///< with more corners gives consecutive Accepts fanned from its lowest index
    Done,            ///< f t: the wrap closed with f faces (convex polygons) and t triangles
};
inline constexpr int kGiftwrapEventKinds = 13;

/// "first_point", "first_edge", "vertical_face", "wrap_first", "push_edge", "pop_edge",
/// "skip_edge", "candidate", "replace", "restart", "coplanar", "accept", "done".
const char* giftwrap_event_name(GiftwrapEvent kind);

/// The recorded events of one gift wrap: event i is kinds[i] with arguments
/// args[3i], args[3i + 1], args[3i + 2].
///
/// Replaying it: the edge stack is exactly the PushEdge events minus the PopEdge / SkipEdge events,
/// each of which removes the top of the stack and names it; the Accept events, in order, are
/// `triangles`, which are those of hull(points, Algorithm::Giftwrap, same scan) in the same order.
/// The stack is empty at Done.
///
/// Per face: (PopEdge a b or WrapFirst a b) Candidate a b c, then Replace/Coplanar events (single
/// pass) or, for the restart scan, Coplanar events and either Restart a b p followed by the next
/// Candidate or the end of the search; then the face's Accepts and the PushEdges of its edges
/// whose other face is still unknown. The first face may instead come from VerticalFace.
///
/// Input without volume (dimension < 3: identical, collinear or coplanar points) is not gift
/// wrapped (hull() handles it without the wrap): the trace holds the single event Done 0 t, with
/// `triangles` and `dimension` as hull() gives them (a flat polygon's fan, or nothing).
/// Invalid input (non-finite coordinates, ...) gives no events and hull()'s `error`.
struct GiftwrapTrace {
    std::vector<std::uint8_t> kinds;   ///< one GiftwrapEvent per event
    std::vector<std::uint32_t> args;   ///< 3 per event
    std::vector<std::uint32_t> triangles;  ///< the hull's triangles (3 indices each)
    int dimension = -1;                ///< as Hull::dimension
    std::string error;                 ///< empty on success
    std::int64_t error_point = -1;     ///< as Hull::error_point

    bool ok() const { return error.empty(); }
    std::size_t size() const { return kinds.size(); }
    GiftwrapEvent kind(std::size_t i) const { return static_cast<GiftwrapEvent>(kinds[i]); }
    const std::uint32_t* arguments(std::size_t i) const { return args.data() + 3 * i; }
};

/// Gift-wraps `points` with exact side tests like giftwrap(points, scan), recording every step.
/// Deterministic: the same input gives the same trace. The recording costs nothing when not asked
/// for (the untraced wrap is compiled separately). Trace length: O(faces + candidates replaced)
/// for the single pass, up to 2 events per candidate tried (O(n) per edge) for the restart scan.
GiftwrapTrace giftwrap_trace(PointSpan points, GiftwrapScan scan = GiftwrapScan::SinglePass);

struct PointSpan2;  // hullkit/delaunay.hpp

/// The Delaunay view's gift wrap, recorded: delaunay(points) with DelaunayAlgorithm::Giftwrap
/// wraps the lower hull of the points lifted to z = x^2 + y^2 ("below the lifted plane of a, b, c"
/// is exactly "inside the circle through a, b, c"), and its faces projected back are the Delaunay
/// polygons. Defined in the hullkit_delaunay library (native/src/delaunay/giftwrap.cpp); the same
/// wrap code, run on the distinct points in input order (the library's run uses a Hilbert order,
/// so its steps come in another order; the faces are the same).
/// Events (input indices): FirstPoint p (the lowest point in (x, y) order), FirstEdge a b (the
/// convex hull edge leaving it, counter-clockwise), then the edge stack as for the 3D wrap, starting
/// with PushEdge a b of that edge. PopEdge a b: the face left of a -> b is searched (a PopEdge not
/// followed by a Candidate: a -> b is a convex hull edge, nothing lies beyond it); Candidate a b c:
/// the first point left of a -> b; Replace a b p: p lies strictly inside the circle through a, b
/// and the candidate (below its lifted plane) and becomes the candidate; Coplanar a b p: p lies
/// exactly on the final circle and joins the face. Accept a b c: the projected triangles exactly as
/// delaunay() reports them (fanned from the polygon's lowest input index, clockwise with y up, each
/// starting at its lowest index), so that the Accepts as a set of triangles are delaunay()'s
/// `triangles` (which come in another order). Done f t. `triangles` is delaunay(points).triangles.
/// Input without area (collinear, fewer than three distinct points) gives the single event Done
/// 0 0 and `dimension` as delaunay() gives it; invalid input its error.
GiftwrapTrace delaunay_giftwrap_trace(PointSpan2 points);

}  // namespace hullkit
