// Private pieces shared by the hull algorithms and hull.cpp, which runs them.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "hullkit/hull.hpp"
#include "large_array.hpp"

namespace hullkit::detail {

/// Convex polygons stored flat: polygon k is vertices[offsets[k]] ... vertices[offsets[k + 1] - 1].
struct Polygons {
    LargeArray<std::uint32_t> offsets{0};
    LargeArray<std::uint32_t> vertices;

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

/// The largest and the smallest nonzero |coordinate| of a point set (0 and infinity when empty).
struct Magnitudes {
    double largest = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
};

/// Adds the magnitudes of `points` to *range (on up to `threads` threads). Fails on the first
/// point, in input order, with a non-finite coordinate: "point I has a non-finite y coordinate
/// (nan)", I being indices[i] for point i, or first_index + i when `indices` is null.
Hull scan_magnitudes(PointSpan points, std::uint64_t first_index, const std::uint64_t* indices, unsigned threads,
                     Magnitudes* range);

/// The power of two that brings coordinates in `range` into the predicates' exact range (0 when
/// they are in it), or a failure when no single power of two can.
Hull scale_exponent(const Magnitudes& range, int* exponent);

/// `points` multiplied by 2^exponent (exact) into `storage`, on up to `threads` threads; the
/// points themselves when exponent is 0.
PointSpan scale_points(PointSpan points, int exponent, unsigned threads, std::vector<double>& storage);

/// The hull of points that passed the checks, scaled by 2^exponent while deciding (the exponent
/// comes from scale_exponent of a range that covers them; the result's volume and area are
/// given back in the caller's units). With threads > 1, large clouds are hulled in chunks on
/// threads and the hull of the chunks' vertices taken last; the result is the same bits.
Hull hull_in_range(PointSpan points, const HullOptions& options, int exponent);

/// The candidates for the vertices of the hull of `points` (in range), ascending: for a large
/// cloud the extreme points of chunks of it hulled on up to `threads` threads, when that pays
/// (see hull.cpp); otherwise empty, and every point is a candidate. *surface_like: empty because
/// most points are on the hull (judged from a sample), where quickhull_split_faces may pay.
/// *whole (if given): the simplex of all the points when it was found on the way (dimension -2
/// when not), for the serial quickhull to start from.
std::vector<std::uint32_t> chunk_candidates(PointSpan points, unsigned threads, bool* surface_like,
                                            Simplex* whole = nullptr);

/// The fraction of `points` that quickhull's interior culling (starting from their `simplex`)
/// keeps, estimated from `sample` (some of the points). 1 without volume.
double culling_kept_fraction(PointSpan points, const Simplex& simplex, PointSpan sample);

/// The extreme points of `points` (the vertices of their hull, whatever its dimension; of
/// identical points the lowest index), ascending. `points` must be in the predicates' range.
/// `simplex`: their find_simplex, when known.
std::vector<std::uint32_t> extreme_points(PointSpan points, const Simplex* simplex = nullptr);

/// A failed Hull carrying `message` (and the index of the point to blame, if any).
Hull failure(std::string message, std::int64_t point = -1);

/// Exact affine dimension of the points and a well-spread simplex (far-apart points, rounded
/// distances only choose among candidates; every decision about degeneracy is exact). Of
/// identical candidates the lowest index is chosen.
Simplex find_simplex(PointSpan points, unsigned threads = 1);

/// Simplex's 14 extremes and bounding box over some points, with the winning values.
struct Extremes {
    double best_value[14];
    std::uint32_t extreme_of[14];
    double lo[3], hi[3];
};

/// find_simplex's one pass over the points, by blocks of kExtremesBlock points (on up to
/// `threads` threads): each block's extremes, indices into `points`. At least one point.
inline constexpr std::size_t kExtremesBlock = std::size_t{1} << 18;
std::vector<Extremes> block_extremes(PointSpan points, unsigned threads = 1);

/// The extremes of blocks [first, last) together (ties to the lowest index), their indices less
/// `base`: those of a run of points starting at index `base`.
Extremes merged_extremes(const std::vector<Extremes>& blocks, std::size_t first, std::size_t last, std::uint32_t base);

/// find_simplex from the points' extremes (as merged_extremes gives them for all the points).
Simplex simplex_from(PointSpan points, const Extremes& extremes);

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
                     std::string& error, unsigned threads = 1);

/// Quickhull on threads for a cloud with volume whose points mostly lie on its hull: split in two
/// halves hulled on their own threads (recursively), joined along their seam (quickhull_split.cpp).
/// The faces as quickhull_faces gives them (the same polygons, in the canonical order, with the
/// same volume and area). False when the split does not apply; the caller then runs
/// quickhull_faces.
bool quickhull_split_faces(PointSpan points, unsigned threads, Polygons& faces, double* volume, double* area);

/// Two edge-adjacent triangles (indices into a triangle list) that lie in one plane.
struct CoplanarPair {
    std::uint32_t first, second;
};

/// Groups the triangles of a closed convex surface into planar faces, given which edge-adjacent
/// triangles are coplanar, and returns each face as its strictly convex polygon, so that only
/// extreme points remain corners.
Polygons merge_coplanar_triangles(PointSpan points, LargeArray<std::uint32_t> triangles,
                                  const std::vector<CoplanarPair>& coplanar);

/// Brings polygons into the one order every schedule agrees on: each polygon rotated to start at
/// its lowest index, the polygons sorted by their first two corners. `original` maps the
/// polygons' indices to the indices that decide (empty: the indices themselves); any order of the
/// same polygons comes out the same, so the result depends only on the hull, not on how it was
/// found (thread count, chunks, streaming).
void canonical_order(Polygons& faces, const std::vector<std::uint32_t>& original = {}, unsigned threads = 1);

/// Volume and area enclosed by closed polygons, counter-clockwise seen from outside, summed in an
/// order fixed by the faces alone (the same bits for any `threads`).
void measure(PointSpan points, const Polygons& faces, double* volume, double* area, unsigned threads = 1);

}  // namespace hullkit::detail
