// Small lattices: point sets whose orientation and in-circle / in-sphere determinants are computed
// exactly by the plain floating-point formulas (stage A), zero included, so that the predicates
// need neither an error bound nor the adaptive stages. Integer grids, points on circles or spheres
// of integer radius, pixel and voxel centres: exactly the inputs whose ties (cocircular or
// cospherical points) would otherwise send every tied test to exact expansion arithmetic.
#pragma once

#include <cstddef>

namespace hullkit {
namespace detail {

/// Whether every coordinate of `count` points (`dim` interleaved coordinates each, dim <= 4) is an
/// integer multiple of one power of two u with no two points more than `max_units` u apart on any
/// axis. Then every coordinate difference is an exact integer times u, and a determinant of degree
/// `degree` in the differences whose partial results are bounded by B max_units^degree <= 2^53 times
/// u^degree is computed without a rounding error in doubles (u is also required to keep u^degree a
/// normal double and 2^53 u^degree finite). u is the smallest power of two with the points' span
/// at most max_units u; when true, writes its exponent to `unit` and the lowest coordinate on each
/// axis to `lo` (`dim` values). Two passes over the coordinates, without branches.
bool small_lattice(const double* coords, std::size_t count, int dim, double max_units, int degree, int* unit,
                   double* lo);

/// small_lattice's steps, for callers that know the span (the largest difference of two points'
/// coordinates on one axis, as computed) of finite points: the exponent of u (false when the
/// span is 0 or u is out of range), and whether all `size` coordinates are multiples of 2^unit.
bool lattice_unit(double span, double max_units, int degree, int* unit);
bool all_multiples(const double* coords, std::size_t size, int unit);

/// The 2D limit: orient2d's partial results are below 2 M^2 and incircle's below 12 M^4 for points
/// at most M u apart on each axis (see incircle_static_bound), and 12 * 5234^4 < 2^53 < 12 * 5235^4.
constexpr double kPlaneLatticeUnits = 5234;

/// small_lattice with the 2D limits for finite points whose span is known: orient2d and incircle of
/// these points (in any roles) are exact in doubles.
inline bool plane_lattice_exact(const double* xy, std::size_t count, double span) {
    int unit = 0;
    return lattice_unit(span, kPlaneLatticeUnits, 4, &unit) && all_multiples(xy, 2 * count, unit);
}

}  // namespace detail
}  // namespace hullkit
