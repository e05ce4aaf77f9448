// Private pieces shared by the quickhull files: the index type, a face's plane with its exact side
// test, the closed triangle surface the algorithms produce, and the steps one file calls in another.
//
// The files: quickhull.cpp (the serial quickhull: face pool, outside sets, horizon; its entry
// quickhull_faces), quickhull_candidates.cpp (the interior culling and the spatial order of the
// candidates), quickhull_split.cpp (quickhull on threads for surface-like clouds: split in halves,
// joined along their seam).
//
// Side tests: a rounded plane test with a proven error bound decides almost every case; only
// points within that bound of a plane go to the exact orient3d. Rounded distances are also used
// to pick the farthest point, which is a choice, not a decision about topology.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "hull_internal.hpp"
#include "hullkit/predicates.hpp"
#include "large_array.hpp"

namespace hullkit::detail::quickhull_detail {

using Index = std::uint32_t;
constexpr Index kNone = ~Index{0};

/// A face's plane in rounded arithmetic, with the bound under which its sign is not trusted.
struct Plane {
    double ax, ay, az;  // a vertex
    double nx, ny, nz;  // (b - a) x (c - a), rounded
    double bound;
    Index v[3];
};

/// The plane through a, b, c (indices va, vb, vc into `points`), for points whose coordinates
/// differ from a's by at most `extent` per axis.
inline Plane plane_through(PointSpan points, Index va, Index vb, Index vc, double extent) {
    const double* a = points[va];
    const double* b = points[vb];
    const double* c = points[vc];
    const double ex = b[0] - a[0], ey = b[1] - a[1], ez = b[2] - a[2];
    const double fx = c[0] - a[0], fy = c[1] - a[1], fz = c[2] - a[2];
    const double p1 = ey * fz, p2 = ez * fy, p3 = ez * fx, p4 = ex * fz, p5 = ex * fy, p6 = ey * fx;
    Plane plane;
    plane.ax = a[0];
    plane.ay = a[1];
    plane.az = a[2];
    plane.nx = p1 - p2;
    plane.ny = p3 - p4;
    plane.nz = p5 - p6;
    // The rounded height n . (p - a) is off by at most 8u * sum|monomials| (u = 2^-53, 8 rounding
    // steps per monomial), and sum|monomials| <= extent * permanent(n), |p - a| <= extent per
    // axis. 2^-49 = 16u doubles that for the rounding of the bound itself.
    const double permanent = std::fabs(p1) + std::fabs(p2) + std::fabs(p3) + std::fabs(p4) + std::fabs(p5) + std::fabs(p6);
    plane.bound = 0x1p-49 * permanent * extent;
    plane.v[0] = va;
    plane.v[1] = vb;
    plane.v[2] = vc;
    return plane;
}

inline double height(const Plane& plane, const double* p) {
    return plane.nx * (p[0] - plane.ax) + plane.ny * (p[1] - plane.ay) + plane.nz * (p[2] - plane.az);
}

/// Exact side of point p from the plane: +1 strictly above. *h: the rounded height.
inline int side_of(PointSpan points, const Plane& plane, const double* p, double* h) {
    *h = height(plane, p);
    if (*h > plane.bound) return 1;
    if (*h < -plane.bound) return -1;
    return orient3d(points[plane.v[0]], points[plane.v[1]], points[plane.v[2]], p);
}

/// A closed surface of triangles: triangle t has corners triangles[3t..3t+2] (counter-clockwise
/// seen from outside); twins[3t + k] is the half-edge (3 * triangle + edge) on the other side of
/// its edge k (corner k to corner k + 1); flat[3t + k] says whether that neighbour lies exactly in
/// t's plane.
struct Surface {
    LargeArray<Index> triangles;
    LargeArray<Index> twins;
    LargeArray<std::uint8_t> flat;

    std::size_t size() const { return triangles.size() / 3; }
};

/// The largest extent of the points' bounding box along an axis (the planes' error bounds scale
/// with it).
double largest_span(PointSpan points);

/// The hull of `points` (a cloud with volume) as a closed surface, by the serial quickhull from
/// `simplex` (quickhull.cpp); `original[i]` is the caller's index of point i (of identical points
/// the lowest is chosen). False with `error` set on an internal error.
bool quickhull_surface(PointSpan points, const std::vector<Index>& original, const Simplex& simplex,
                       Surface& surface, std::string& error);

/// The edge-adjacent pairs of a surface's triangles that lie in one plane, each pair once.
std::vector<CoplanarPair> coplanar_pairs(const Surface& surface);

/// Quickhull of a cloud with volume: its candidates (interior points culled, repeats dropped)
/// copied in spatial order into *xyz, ids[k] being the index in `points` of copy k, and the hull
/// as a surface over the copy.
/// `storage`, when given, is the array `points` views: it is released once the candidates are
/// copied, before the hull is built (a caller's own copy of the points need not live beside the
/// candidates' copy and the surface; on a sphere both are every point).
bool run_quickhull(PointSpan points, const Simplex& simplex, std::vector<Index>& ids, LargeArray<double>& xyz,
                   Surface& surface, std::string& error, unsigned threads = 1, LargeArray<double>* storage = nullptr);

// ---- quickhull_candidates.cpp ----

/// The points that may be on the hull, as Morton keys over the bounding box (see MortonKeys):
/// all but those inside a box that is certified (exactly) to lie strictly inside the hull of the
/// points extreme in 14 directions. One pass over the points, in blocks on up to `threads`
/// threads, both filters and keys them.
LargeArray<std::uint64_t> candidates(PointSpan points, const Simplex& simplex, unsigned threads = 1);

/// The ids of `keyed` (Morton keys of points in their box, any order) along the curve, with all
/// but the lowest index of identical points dropped. Only the memory order of the work changes,
/// never a result: identical points have one key, and within a key the ids are sorted by
/// coordinates.
std::vector<Index> spatial_order(PointSpan points, LargeArray<std::uint64_t>& keyed);

}  // namespace hullkit::detail::quickhull_detail
