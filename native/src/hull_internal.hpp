// Private pieces shared by the hull algorithms and hull.cpp, which runs them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hullkit/hull.hpp"

namespace hullkit::detail {

/// Convex polygons stored flat: polygon k is vertices[offsets[k]] ... vertices[offsets[k + 1] - 1].
struct Polygons {
    std::vector<std::uint32_t> offsets{0};
    std::vector<std::uint32_t> vertices;

    std::size_t size() const { return offsets.size() - 1; }
    template <class It>
    void add(It first, It last) {
        vertices.insert(vertices.end(), first, last);
        offsets.push_back(static_cast<std::uint32_t>(vertices.size()));
    }
};

/// Four points spanning the cloud's affine hull (`dimension` + 1 of them are meaningful), found
/// among the points extreme in 14 directions, which are kept for the hull algorithms.
struct Simplex {
    int dimension = -1;
    std::uint32_t p[4] = {0, 0, 0, 0};
    /// The points with the largest and the smallest x, y, z, x+y+z, x+y-z, x-y+z, x-y-z (in that
    /// order, largest first; lowest index on ties), and the bounding box.
    std::uint32_t extreme[14] = {};
    double lo[3] = {0.0, 0.0, 0.0};
    double hi[3] = {0.0, 0.0, 0.0};
};

/// A failed Hull carrying `message` (and the index of the point to blame, if any).
Hull failure(std::string message, std::int64_t point = -1);

/// Exact affine dimension of the points and a well-spread simplex (far-apart points, rounded
/// distances only choose among candidates; every decision about degeneracy is exact). Of
/// identical candidates the lowest index is chosen.
Simplex find_simplex(PointSpan points);

/// Indices of the distinct points (exact coordinate equality), the lowest index of each group of
/// identical points, in ascending order.
std::vector<std::uint32_t> distinct_points(PointSpan points);

/// Sorts the point indices in [first, last) by coordinates and drops all but the lowest index of
/// each group of identical points; returns the new end.
std::vector<std::uint32_t>::iterator sort_dropping_repeats(PointSpan points, std::vector<std::uint32_t>::iterator first,
                                                           std::vector<std::uint32_t>::iterator last);

/// Gift wrapping of a cloud with volume: the hull's faces as convex polygons, counter-clockwise
/// seen from outside. Exact sides unless `seed_epsilon`. False with `error` set on failure
/// (only possible with the seed's epsilon).
bool giftwrap_faces(PointSpan points, GiftwrapScan scan, bool seed_epsilon, Polygons& faces, std::string& error);

/// Quickhull of a cloud with volume, starting from `simplex`: the hull's faces as strictly convex
/// polygons (coplanar triangles merged, so that only extreme points are corners), counter-clockwise
/// seen from outside, with the enclosed volume and the surface area.
bool quickhull_faces(PointSpan points, const Simplex& simplex, Polygons& faces, double* volume, double* area,
                     std::string& error);

/// Two edge-adjacent triangles (indices into a triangle list) that lie in one plane.
struct CoplanarPair {
    std::uint32_t first, second;
};

/// Groups the triangles of a closed convex surface into planar faces, given which edge-adjacent
/// triangles are coplanar, and returns each face as its strictly convex polygon, so that only
/// extreme points remain corners.
Polygons merge_coplanar_triangles(PointSpan points, std::vector<std::uint32_t> triangles,
                                  const std::vector<CoplanarPair>& coplanar);

/// Volume and area enclosed by closed polygons, counter-clockwise seen from outside.
void measure(PointSpan points, const Polygons& faces, double* volume, double* area);

}  // namespace hullkit::detail
