// hullkit: Delaunay tetrahedralization of 3D points by lifting to the paraboloid in 4D.
//
// Lift each point (x, y, z) to (x, y, z, x^2 + y^2 + z^2): the lower facets of the 4D convex hull of
// the lifted points, projected back, are the Delaunay tetrahedra (the seed document's lifting, one
// dimension up). "Is the lifted point e below the lifted hyperplane of tetrahedron a, b, c, d" is
// exactly the in-sphere test, so every decision here is made by the exact predicates orient3d and
// insphere (predicates.hpp) on the input coordinates; no rounded lift decides anything.
//
// The construction is the incremental one of the lower 4D hull: Bowyer-Watson insertion (each
// point removes the tetrahedra whose circumsphere holds it and joins the cavity's boundary to it)
// in a biased randomized insertion order (BRIO, Amenta, Choi & Rote 2003; rounds growing eightfold,
// as Marot, Pellerin & Remacle's, each sorted along a Hilbert curve), each point located by a walk
// from the last new tetrahedron.
// Outside the hull "ghost" tetrahedra join each hull triangle to a vertex at infinity.
//
// Ties. Five or more cospherical points (grids, lattices, points on a sphere) have more than one
// Delaunay tetrahedralization. hullkit returns exactly one, which depends only on the points:
// the Delaunay tetrahedralization of the points symbolically perturbed as Devillers & Teillaud
// describe ("Perturbations for Delaunay and weighted Delaunay 3D triangulations", CGAL research
// report 2009 / CGTA 2011; after Edelsbrunner & Muecke's simulation of simplicity, 1990): each
// point's lift is raised by an infinitesimal that is larger the later the point comes in the
// lexicographic order of (x, y, z). An in-sphere test that is exactly 0 is decided by the first
// nonzero term of that perturbation, each an orient3d of the points involved. The result is a
// true tetrahedralization of the convex hull (no flat tetrahedron, every point a vertex, every face
// locally Delaunay) that is Delaunay for the unperturbed points, the same for every insertion
// order and thread count; it is the one CGAL's Delaunay_triangulation_3 builds with its default
// perturbation. Coplanar hull faces are triangulated by the same rule. On small lattices (every
// coordinate a multiple of one power of two u, no two points more than 659 u apart on an axis)
// orient3d and insphere are exact in plain doubles, and the filters and exact stages are skipped.
//
// Threads: large rounds of the insertion are cut into partitions inserted on their own threads
// (ranges of the Hilbert curve, then slabs across oblique directions for the points the ranges
// defer); the cuts depend only on the points, so every thread count builds the same mesh.
//
// Memory: the working mesh is one array of 32 bytes per tetrahedron (corners, then neighbours),
// about 6.75 slots per point for uniform points; the output moves the neighbours to the front of
// that array and appends the tetrahedra to their own, giving the pages between back as it goes
// (no higher peak). With the points' scaled copy (24 bytes), three 4-byte indices and two bytes
// (partition label, cavity number) per point: about 250 bytes per point at the peak, the input
// not counted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "hullkit/hull.hpp"  // PointSpan

namespace hullkit {

struct Delaunay3Options {
    /// Threads: 0 (the default) every hardware thread, 1 the calling thread only. The result is
    /// the same bits for every value (it depends only on the points). The WebAssembly build runs
    /// on the calling thread.
    unsigned threads = 0;
    /// Called on the calling thread as points are inserted: points_done of total after each round
    /// of the insertion order (rounds grow eightfold; the last holds 7/8 of the points), the last call
    /// with points_done == total. Leave empty for none.
    std::function<void(std::size_t points_done, std::size_t total)> progress;
    /// The furthest-site Delaunay tetrahedralization instead (Qhull's and scipy's furthest_site):
    /// the upper convex hull of the lifted points, projected. Its tetrahedra are those whose
    /// circumspheres hold every point (inside or on); its vertices are the extreme points of the
    /// convex hull (exactly: a point inside the hull or inside one of its faces or edges is in no
    /// tetrahedron, though it keeps its `representative`), and it covers the same convex hull
    /// (`hull` the same faces, coplanar ones triangulated by the tie rule). Ties as above, with the
    /// same perturbation (cospherical corners get one answer, no flat tetrahedron). Built by the same
    /// insertion with each in-sphere answer negated: every point is inserted from outside the hull
    /// of those before it (they are in convex position). Coplanar input: the furthest-site
    /// triangulation of the polygon's corners in the plane; collinear: the two end points.
    bool furthest_site = false;
};

/// A Delaunay tetrahedralization. On failure `error` says what is wrong and, where one point is to
/// blame, `error_point` is its index; the other fields are then empty.
///
/// What the fields hold depends on `dimension`, the dimension of the points' affine hull:
///   3  `tetrahedra`: 4 indices per tetrahedron into the input points, positively oriented
///      (orient3d(t0, t1, t2, t3) > 0: t3 on the side the normal (t1 - t0) x (t2 - t0) points to);
///      `neighbors`: 4 per tetrahedron, neighbors[4t + k] the tetrahedron sharing the face opposite
///      corner k, -1 on the hull (scipy's convention); `hull`: the convex hull's triangles,
///      3 indices each, counter-clockwise seen from outside (every hull face, coplanar ones
///      triangulated by the tie rule above).
///   2  all points on one plane: `triangles` their 2D Delaunay triangulation in that plane, 3 indices
///      each, counter-clockwise seen from the side `normal` points to (the side where the normal's
///      largest component, x before y before z on ties, is positive); `neighbors`: 3 per triangle,
///      the triangle across the edge opposite corner k, -1 on the boundary.
///   1  all points on one line: `vertices` the distinct points in order along it (the segments
///      join consecutive ones).
///   0  one distinct point: `vertices` holds it.  -1  no points.
///
/// Order (it depends only on the input: the same arrays for every thread count and platform):
/// each tetrahedron (triangle) starts at its lowest index, then its second lowest, the others in
/// the order that keeps the orientation; tetrahedra come in the order the insertion leaves them in
/// memory (nearby tetrahedra mostly near each other); hull triangles start at their lowest index
/// and are sorted by their corners' indices. The set of tetrahedra does not depend on the order of
/// the input points either (only their indices follow them).
struct Delaunay3 {
    int dimension = -1;
    std::vector<std::uint32_t> tetrahedra;  ///< dimension 3: 4 per tetrahedron
    std::vector<std::int32_t> neighbors;    ///< dimension 3: 4 per tetrahedron; dimension 2: 3 per triangle
    std::vector<std::uint32_t> hull;        ///< dimension 3: 3 per hull triangle, outward
    std::vector<std::uint32_t> triangles;   ///< dimension 2: 3 per triangle
    std::vector<std::uint32_t> vertices;    ///< dimension 1: the points along the line; dimension 0: the point
    double normal[3] = {0.0, 0.0, 0.0};     ///< dimension 2: unit normal of the plane (rounded)
    /// For each input point, the index of the point that represents it: itself, or the lowest
    /// index with exactly the same coordinates (duplicates are merged, never dropped silently).
    std::vector<std::uint32_t> representative;
    std::size_t duplicate_count = 0;  ///< points whose representative is not themselves
    /// Made with Delaunay3Options::furthest_site (then delaunay3_locate finds no nearest points:
    /// the points inside the hull are in no tetrahedron).
    bool furthest_site = false;

    std::string error;              ///< empty on success
    std::int64_t error_point = -1;  ///< index of the offending point, -1 if none

    bool ok() const { return error.empty(); }
    std::size_t tetrahedron_count() const { return tetrahedra.size() / 4; }
};

/// Tetrahedralizes `points` exactly. Fails only on a non-finite coordinate (naming the point), more
/// than 2^31 - 1 points, or coordinates whose nonzero magnitudes span more than a factor of about
/// 2^313 (insphere's exact range after a power-of-two rescaling, see predicates.hpp; the error
/// names the smallest and largest point).
Delaunay3 delaunay3(PointSpan points, const Delaunay3Options& options = {});

/// Point location in a tetrahedralization (dimension 3), exact: which tetrahedron holds a point,
/// its barycentric coordinates there, and the nearest input point.
///
/// A point on a face, edge or vertex is held by every tetrahedron around it: the one with the
/// lowest index is reported, so the answer depends only on the point (not on where a walk began,
/// nor on threads). Every decision is made by orient3d and compare_distance3d on the coordinates
/// scaled as delaunay3() scales them; a query coordinate that is not finite, or outside the range
/// in which they are exact after that scaling (kPredicateMinMagnitude .. kPredicateMaxMagnitude,
/// about 1e-75 .. 1e100 at unit scale), is an error naming the query.
struct Delaunay3QueryOptions {
    bool barycentric = false;  ///< also the barycentric coordinates (4 per query)
    bool nearest = false;      ///< also the nearest input point
    /// Threads: 0 every hardware thread, 1 the calling thread; the answers are the same.
    unsigned threads = 0;
};
struct Delaunay3Queries {
    /// Per query: the tetrahedron holding it, -1 outside the convex hull.
    std::vector<std::int32_t> tetrahedron;
    /// With `barycentric`: 4 per query, the weights of the tetrahedron's corners (in its corner
    /// order) that give the query point; they sum to 1 up to rounding, are exactly 0 for a corner
    /// whose opposite face holds the point and exactly 1 at a corner; NaN outside the hull.
    std::vector<double> barycentric;
    /// With `nearest`: per query, the nearest input point (exact distances; ties: the lowest index).
    std::vector<std::int32_t> nearest;
    std::string error;            ///< empty on success; on failure the arrays are empty
    std::int64_t error_query = -1;

    bool ok() const { return error.empty(); }
};
/// Locates every query (a flat x y z array) in `triangulation`, the delaunay3() result for `points`.
/// Queries are sorted along a Hilbert curve and each walk starts where the previous one ended, so
/// many queries cost little more than one walk each; they are spread over the threads.
Delaunay3Queries delaunay3_locate(PointSpan points, const Delaunay3& triangulation, PointSpan queries,
                                  const Delaunay3QueryOptions& options = {});

/// The Voronoi diagram of the points, dual to their tetrahedralization (dimension 3).
///
/// Vertices are the circumcentres of the Delaunay cells: tetrahedra whose circumspheres coincide
/// exactly (cospherical ties, decided by the exact in-sphere test) share one vertex. Each face
/// separates two input points p < q and is dual to a Delaunay edge; edges inside a cospherical cell
/// have no face. A bounded face is a convex polygon of vertices, counter-clockwise seen from q's
/// side (its normal points from p to q, out of p's cell). An unbounded face (dual to a hull edge)
/// lists the chain of vertices between its two rays, in the same orientation. A point's cell is
/// bounded when it is not on the hull. Coordinates and volumes are rounded (floating point);
/// which faces and vertices exist is exact.
struct Voronoi3 {
    std::vector<double> vertices;                 ///< x y z per Voronoi vertex
    std::vector<std::uint32_t> tetrahedron_vertex;  ///< per tetrahedron: its Voronoi vertex
    std::vector<std::uint32_t> face_points;       ///< 2 per face: the points p < q it separates
    std::vector<std::uint32_t> face_offsets;      ///< face f: face_vertices[face_offsets[f] .. face_offsets[f + 1])
    std::vector<std::uint32_t> face_vertices;
    std::vector<std::uint8_t> face_bounded;       ///< per face: 1 bounded, 0 unbounded
    std::vector<std::uint32_t> cell_offsets;      ///< point i's faces: cell_faces[cell_offsets[i] .. cell_offsets[i + 1])
    std::vector<std::uint32_t> cell_faces;
    /// Per point: the volume of its cell; +inf for an unbounded cell, NaN for a duplicate point
    /// (its representative has the cell).
    std::vector<double> volume;

    std::size_t face_count() const { return face_points.size() / 2; }
};
/// The Voronoi diagram of `points` from `triangulation` (their delaunay3()). For input that is not
/// 3D (dimension below 3) every cell is unbounded: no vertices or faces, volumes +inf.
Voronoi3 delaunay3_voronoi(PointSpan points, const Delaunay3& triangulation);

/// An exact check that `tetrahedra` (count index quadruples) is the Delaunay tetrahedralization
/// of the distinct points of `points`: indices in range, every tetrahedron positively oriented
/// (none flat), each face shared by at most two tetrahedra with opposite orientations, the boundary
/// faces exactly a triangulation of the convex hull's boundary (every boundary face on a hull
/// plane with every point on its inner side, the boundary a closed surface), every distinct point
/// a vertex, the total volume equal to the hull's (exactly, as a sum of exact determinants), and
/// every interior face locally Delaunay by the exact in-sphere test. With `perturbed` (the default)
/// each interior face must also be locally Delaunay under the tie rule of delaunay3(), which makes
/// the tetrahedralization unique; without, cospherical ties may go either way.
struct Delaunay3VerifyReport {
    bool ok = true;
    std::vector<std::string> problems;  ///< one line each, at most a few dozen, then a count
    std::size_t problem_count = 0;
    std::size_t distinct_points = 0;
    std::size_t hull_triangles = 0;
};
Delaunay3VerifyReport verify_delaunay3(PointSpan points, const std::uint32_t* tetrahedra, std::size_t count,
                                       bool perturbed = true);

}  // namespace hullkit
