// hullkit: an exact, independent check that a triangle mesh is the convex hull of a point set.
//
// verify() decides, with exact predicates only (hullkit/predicates.hpp), whether `triangles` is a
// correct result of hullkit::hull for `points` in the sense of hull.hpp: the boundary of the
// convex hull, triangulated, counter-clockwise seen from outside, without zero-area triangles,
// whose corners are exactly the extreme points (the lowest index standing for identical points).
// It shares no code with the hull algorithms. Coordinates outside the predicates' exact range are
// first multiplied by a common power of two, as hullkit::hull does (exact).
//
// ---- What is checked, and why that is enough (dimension 3) ----
//  1. structure: indices in range; no zero-area triangle (collinear3d); every directed edge used
//     exactly once and its reverse exactly once; the triangles around every vertex form a single
//     fan; the triangles are edge-connected; V - E + F = 2. So the mesh is a closed, oriented,
//     triangulated sphere.
//  2. local convexity: for every edge the far corner of the neighbouring triangle is on or below
//     the triangle's plane; where both are coplanar they must lie on opposite sides of the edge
//     (no fold); at least one edge is strictly convex (positive volume).
//  3. a point o is found (a rounded centroid, then confirmed exactly) strictly below every face
//     plane, and around every vertex v the fan winds exactly once about the ray from o through v
//     (exact count of crossings of a reference half-plane). Then the central projection from o
//     maps the mesh onto the sphere of directions locally homeomorphically everywhere, hence (the
//     mesh being a connected closed surface and the sphere simply connected) bijectively: the mesh
//     is the boundary of a region star-shaped about o, and that region is locally convex at every
//     point (edges by 2; vertices because a simple, locally convex spherical link bounds a convex
//     cone), hence convex (Tietze-Nakajima). It is the convex polytope Q spanned by the corners.
//  4. containment: every input point lies in Q. Points in an axis-aligned box around o whose 8
//     corners are shown (exactly) to be in Q need nothing more. For any other point p the triangle t
//     whose cone from o contains p is found by a walk on the triangles, and p is then certified
//     exactly: inside iff p is on or below t's plane (p then lies on the segment from o to a point
//     of t). The cones from o cover space, so such a t always exists. The rounded geometry only
//     guides the search: points are taken in the order of a grid of directions from o, each walk
//     starting where the previous one ended; a walk that does not arrive within a step budget falls
//     back to scanning all triangles for that point. Q's corners being input points, Q is the hull.
//     A point on t's plane lies in the closed triangle t, so it is identical to a vertex only if to
//     a corner of t: that is where "the lowest index represents identical points" is checked.
//  5. extreme vertices: a vertex whose triangles lie in at most two distinct planes sits inside a
//     face or an edge of Q and is reported.
// When no exact interior point exists in doubles (polytopes thinner than a rounding unit of their
// coordinates), or steps 1-3 already failed, step 4 instead tests each point against every planar
// face (coplanar neighbours merged). Then every triangle lies in a facet of the hull, facing out,
// so the mesh covers the hull's boundary, possibly several times around some vertices; that is
// excluded by checking that no plane repeats among the planar runs of triangles around each vertex
// (a fan winding k times visits every plane k times). Identical points are then checked with a
// hash table of the vertices.
//
// ---- Cost ----
// O(F log F) to pair the edges (F triangles), O(F) for the local and winding checks and for
// confirming o, O(n) to sort the points by direction, then per point an expected O(1) walk for
// well-spread input (about one step per point on 1e6-point clouds; O(sqrt F) in bad cases, O(F) for
// a point whose walk gives up). The fallback of the last paragraph is O(n * faces) and is counted
// in VerifyReport::exhaustive_points.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "hullkit/hull.hpp"

namespace hullkit {

/// How many problems a VerifyReport keeps; problem_count says how many were found in all.
inline constexpr std::size_t kVerifyMaxProblems = 20;

struct VerifyReport {
    bool ok = true;
    /// The first kVerifyMaxProblems problems, each one line naming what is wrong and where
    /// (triangle, edge, vertex or point indices into the input).
    std::vector<std::string> problems;
    std::size_t problem_count = 0;  ///< all problems found (may exceed problems.size())
    /// Remarks that are not problems, e.g. checks skipped because earlier ones failed.
    std::vector<std::string> notes;

    std::size_t checked_points = 0;    ///< input points shown to lie in the hull
    std::size_t exhaustive_points = 0; ///< of those, how many needed a test against every face
    std::size_t triangle_count = 0;
    std::size_t vertex_count = 0;      ///< distinct triangle corners (dimension < 3: Hull::vertices)
    std::size_t face_count = 0;        ///< planar faces: edge-connected coplanar triangles merged
    int dimension = -1;                ///< the dimension that was checked

    /// One line per kept problem, then "... and N more problems" when some were not kept.
    std::vector<std::string> lines() const;
};

/// Checks that `triangle_count` triangles (3 indices each into `points`) are the boundary of the
/// convex hull of `points` with volume, as described above.
VerifyReport verify(PointSpan points, const std::uint32_t* triangles, std::size_t triangle_count);

/// Checks a hullkit::hull result against `points` according to its dimension:
///   3   verify(points, triangles) and Hull::vertices == the triangles' corners, ascending;
///       Hull::volume not negative (it is rounded and may underflow far from unit scale; positive
///       volume is checked exactly on the triangles); with merged faces, one face per planar face.
///   2   Hull::vertices is a strictly convex polygon traversed once, every point lies in its plane
///       and inside it (exact orient3d / orient2d in an axis projection); the triangles fan it
///       from vertices[0].
///   1   two distinct end points, every point on the segment between them.
///   0   one vertex, every point identical to it.
///  -1   no points.
/// For every dimension: indices in range, and the lowest index represents identical points.
VerifyReport verify(PointSpan points, const Hull& hull);

}  // namespace hullkit
