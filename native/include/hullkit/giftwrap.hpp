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

#include "hullkit/hull.hpp"

namespace hullkit {

/// Gift-wraps `points` with exact side tests: hullkit::hull() with Algorithm::Giftwrap.
Hull giftwrap(PointSpan points, GiftwrapScan scan = GiftwrapScan::SinglePass);

}  // namespace hullkit
