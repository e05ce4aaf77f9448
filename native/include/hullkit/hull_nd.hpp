// hullkit: exact convex hulls and Delaunay triangulations in any dimension up to 10 (hulls) and
// 9 (Delaunay), for the dimensions above 3 that scipy.spatial serves with Qhull.
//
// The hull is built by quickhull (Barber, Dobkin & Huhdanpaa 1996) on simplicial facets: each point
// is kept in the outside set of one facet it lies strictly beyond; the facet's furthest point (in
// floating point: a choice of order, not a decision) is added by removing every facet it sees
// strictly (a search over neighbours) and joining the horizon's ridges to it. Every decision, "is
// q strictly beyond this facet", is the exact sign of the (D + 1) x (D + 1) determinant of the rows
// [corner, 1] and [q, 1]: a floating-point evaluation with an error bound first, big-integer
// arithmetic on the coordinates converted exactly when the bound cannot tell. Points on a facet's
// hyperplane that see no facet strictly are not vertices (as Qhull's coplanar points).
//
// Delaunay: each point x is lifted to (x, |x|^2), its last coordinate exact in the big-integer
// evaluation; the lower facets of the hull of the lifted points (those whose projection is a
// positively oriented simplex, decided exactly) are the Delaunay simplices, the upper ones the
// furthest-site simplices. Every distinct point is a vertex of the lifted hull (the paraboloid is
// strictly convex), so every distinct point is a vertex of the triangulation; repeated points are
// merged first (the lowest index represents them). Cospherical points (grids) get one of their
// triangulations, which depends only on the points and their order; `group` tells which simplices
// share a circumsphere exactly.
//
// Points that do not span all D dimensions (flat input) are an error naming the dimension they
// span, as are non-finite coordinates and dimensions outside the range.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace hullkit {

/// Largest dimension hull_nd takes (the exact predicates cost about D 2^D operations each).
constexpr int kMaxHullNdDimension = 10;

struct HullNd {
    int dimension = 0;                  ///< D, the points' dimension
    std::vector<std::uint32_t> facets;  ///< D corners per facet; a point q is strictly outside facet f
                                        ///< when det[[c_0, 1], ..., [c_{D-1}, 1], [q, 1]] > 0
    std::vector<std::int32_t> neighbors;  ///< D per facet: the facet sharing all corners but corner k
    std::vector<std::uint32_t> vertices;  ///< the hull's vertices, ascending
    std::vector<std::int32_t> group;      ///< per facet: the lowest facet of its flat piece of the
                                          ///< boundary (neighbours in one hyperplane, exactly)
    std::string error;                    ///< empty on success
    std::int64_t error_point = -1;        ///< the offending point, -1 if none
    bool ok() const { return error.empty(); }
    std::size_t facet_count() const { return dimension ? facets.size() / static_cast<std::size_t>(dimension) : 0; }
};

/// The convex hull of `count` points of `dimension` (2 .. kMaxHullNdDimension) coordinates each,
/// row after row. Needs D + 1 points not in one hyperplane.
HullNd hull_nd(const double* points, std::size_t count, int dimension);

/// The volume of the convex hull of `count` points of `dimension` coordinates (hull_nd's facets
/// fanned from the vertices' centroid, each simplex's determinant in floating point); NaN when
/// hull_nd reports an error (flat or too few points).
double hull_nd_volume(const double* points, std::size_t count, int dimension);

/// The volume of each of `count` points' Voronoi cells (dimension 1 .. kMaxHullNdDimension - 1),
/// from the Delaunay triangulation `simplices` (dimension + 1 corners each, as delaunay_nd gives
/// them): the signed flag decomposition over the triangulation's faces (voronoi_nd.cpp), in
/// floating point; inf for an unbounded cell (a point on the hull), NaN for a point in no simplex
/// (a repeated one). Every face of the triangulation is visited once; exactly cospherical points
/// are handled too (their simplices' shared circumcentres make the flags between them vanish).
std::vector<double> voronoi_nd_volumes(const double* points, std::size_t count, int dimension,
                                       const std::uint32_t* simplices, std::size_t simplex_count);

struct DelaunayNd {
    int dimension = 0;                     ///< d, the points' dimension
    std::vector<std::uint32_t> simplices;  ///< d + 1 corners per simplex, each positively oriented:
                                           ///< det[[c_0, 1], ..., [c_d, 1]] > 0
    std::vector<std::int32_t> neighbors;   ///< d + 1 per simplex: across from corner k, -1 on the hull
    std::vector<std::int32_t> group;       ///< per simplex: the lowest simplex with exactly the same
                                           ///< circumsphere reachable through neighbours sharing it
    std::vector<std::uint32_t> representative;  ///< per point: the lowest index of an equal point
    std::size_t duplicate_count = 0;            ///< points whose representative is another
    std::string error;
    std::int64_t error_point = -1;
    bool ok() const { return error.empty(); }
    std::size_t simplex_count() const {
        return dimension ? simplices.size() / static_cast<std::size_t>(dimension + 1) : 0;
    }
};

/// The Delaunay triangulation (or with `furthest_site` the furthest-site one: the upper facets of
/// the lifted hull) of `count` points of `dimension` (1 .. kMaxHullNdDimension - 1) coordinates.
DelaunayNd delaunay_nd(const double* points, std::size_t count, int dimension, bool furthest_site = false);

/// The simplex of `triangulation` (built from `points`) holding each query (closed: on a shared
/// face or corner, the lowest-indexed simplex holding it), -1 outside; exact. `queries` holds
/// `query_count` rows of `dimension` coordinates; a non-finite query gets -1.
std::vector<std::int32_t> locate_nd(const double* points, const DelaunayNd& triangulation, const double* queries,
                                    std::size_t query_count);

/// The exact sign of det[[p_0, 1], ..., [p_D, 1]] for D + 1 points of D coordinates (rows of
/// `rows`), D in 1 .. kMaxHullNdDimension. For tests and the bindings.
int orient_nd(const double* rows, int dimension);

}  // namespace hullkit
