// Private to native/src/delaunay3: the working mesh, the perturbed predicates, and what the
// insertion shares with the driver (delaunay3.cpp) and the checks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "hullkit/delaunay3.hpp"
#include "hull/large_array.hpp"
#include "hullkit/predicates.hpp"

// HULLKIT_AVX2_CLONE: on x86-64 ELF builds, a function compiled twice, for AVX2 and for the
// baseline, the one for the machine chosen when the library is loaded (GCC's and clang's
// target_clones, an ifunc). Only the encoding changes (three-operand VEX forms, no register copies
// for the packed insphere): no FMA (the build keeps -ffp-contract=off, and AVX2 does not include
// FMA), so every value, and so every mesh, has the same bits on either. Not in sanitizer builds
// (ThreadSanitizer's run time is not ready when ifunc resolvers run).
#include "hull/sanitizer_build.hpp"
#if defined(__x86_64__) && defined(__ELF__) && (defined(__GNUC__) || defined(__clang__)) && !defined(HULLKIT_SANITIZED)
#define HULLKIT_AVX2_CLONE __attribute__((target_clones("avx2", "default")))
#else
#define HULLKIT_AVX2_CLONE
#endif

namespace hullkit {
namespace delaunay3_detail {

/// The vertex at infinity of the ghost tetrahedra; always their corner 3.
constexpr std::uint32_t kGhost = 0xffffffffu;
/// Corner 3 of a slot that holds no tetrahedron (freed and not reused).
constexpr std::uint32_t kFree = 0xfffffffeu;

/// The distinct points (duplicates merged), scaled into insphere's exact range, stored in
/// Hilbert-curve order (local index = position along the curve); point i is input point original[i].
/// `order` is the insertion order (BRIO: rounds growing eightfold, each along the curve).
struct Points {
    // Each array is as long as the input: mapped on its own, on huge pages (large_array.hpp).
    detail::LargeArray<double> xyz;
    detail::LargeArray<std::uint32_t> original;
    detail::LargeArray<std::uint32_t> order;
    /// The rounds of `order`: round r is order[rounds[r]] ... order[rounds[r + 1] - 1].
    std::vector<std::size_t> rounds;
    double span = 0;  ///< no coordinate difference of two points, as computed, is larger

    std::size_t size() const { return original.size(); }
    const double* operator[](std::size_t i) const { return xyz.data() + 3 * i; }
};

/// The face opposite corner k of a positively oriented tetrahedron, counter-clockwise seen from
/// outside (its normal points away from corner k).
constexpr int kFaceCorners[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

/// Lexicographic order of (x, y, z): the tie-breaking rank of the perturbation (later = raised more).
/// Without branches (bitwise operators: the perturbation's comparisons are unpredictable).
inline bool lexicographically_less(const double* a, const double* b) {
    return (a[0] < b[0]) | ((a[0] == b[0]) & ((a[1] < b[1]) | ((a[1] == b[1]) & (a[2] < b[2]))));
}

/// The tetrahedra, a row of 8 words per slot (corners and links side by side: the cavity's
/// growth reads both of a tetrahedron, and one row is one cache line's half): the 4 corners
/// (positively oriented; ghosts have kGhost as corner 3 and their finite face, corners 0-2,
/// counter-clockwise seen from outside), then for face k (opposite corner k) the link to the
/// neighbour across it: the index of the neighbour's word that links back, 8 u + 4 + j for face j
/// of tetrahedron u (so neighbour = link >> 3, its face = link & 3, and words[link] is the way
/// back). Stored as int32, the type of the output's neighbours (written into the same array at the
/// end), and used as uint32 through data(): at most kMaxTetrahedra slots keep every link within
/// 32 bits.
constexpr std::size_t kMaxTetrahedra = std::size_t{1} << 29;
constexpr std::size_t kRow = 8;
struct Mesh {
    std::vector<std::int32_t> words;
    std::uint32_t* data() { return reinterpret_cast<std::uint32_t*>(words.data()); }
    const std::uint32_t* data() const { return reinterpret_cast<const std::uint32_t*>(words.data()); }
    std::size_t size() const { return words.size() / kRow; }
    const std::uint32_t* corners(std::size_t t) const { return data() + kRow * t; }
};
/// The link of face k of tetrahedron t (see Mesh).
constexpr std::uint32_t link_of(std::size_t t, std::uint32_t k) { return static_cast<std::uint32_t>(kRow * t + 4 + k); }

/// The lattice of lattice_exact: its lowest corner and 1/u.
struct Lattice {
    double lo[3] = {0, 0, 0};
    double inverse_unit = 1;
    /// A point's lattice coordinates (each an integer from 0 to 659) as one number that orders
    /// the points lexicographically (x first), exactly: (X 1024 + Y) 1024 + Z, below 2^30.
    double key(const double* p) const {
        const double x = (p[0] - lo[0]) * inverse_unit, y = (p[1] - lo[1]) * inverse_unit;
        const double z = (p[2] - lo[2]) * inverse_unit;
        return (x * 1024 + y) * 1024 + z;
    }
};

/// Whether the coordinates `xyz` (x, y, z triples) lie on a lattice small enough for orient3d and
/// insphere to be computed exactly in doubles: every coordinate an integer multiple of one power
/// of two u (from 2^-204 to 2^194: u^5 normal, 2^53 u^5 finite), and no two points more than 659 u
/// apart on any axis (exact/lattice.hpp's small_lattice, shared with the 2D triangulation). Every
/// difference is then an integer times u; every product and partial sum in the stage A formulas an
/// integer times a power of u, at most 6 (659 u)^3 for orient3d and 72 (659 u)^5 < 2^53 u^5 for
/// insphere (their permanents' bounds): no rounding anywhere, so the value is the exact
/// determinant. Integer grids up to 660 points a side, and points on spheres of integer radius up
/// to 329, among others. When they do, the lattice goes to `lattice`.
bool lattice_exact(PointSpan points, Lattice* lattice);

/// The exact predicates with the symbolic perturbation (delaunay3.hpp, "Ties").
class Predicates {
public:
    /// `furthest`: the furthest-site conflicts (every answer of conflict() negated: e conflicts
    /// with a tetrahedron whose perturbed circumsphere leaves it outside, the upper 4D hull).
    /// `in_doubles`: evaluate in doubles alone when lattice_exact(points.xyz, ...) (the verifier says
    /// false, to stay independent of that shortcut).
    explicit Predicates(const Points& points, bool furthest = false, bool in_doubles = true);

    /// orient3d of four finite points.
    int orient(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const {
        if (exact_in_doubles_) {
            const double det = detail::orient3d_stage_a(p(a), p(b), p(c), p(d));
            return (det > 0) - (det < 0);
        }
        return detail::orient3d_semi_static(orient_bound_, p(a), p(b), p(c), p(d));
    }
    /// Whether e conflicts with tetrahedron `t` (its circumsphere, or for a ghost the open half-space
    /// beyond its hull face, holds e), perturbed: never 0 for distinct points. Furthest-site: the
    /// circumsphere leaves e outside; a ghost conflicts when e is strictly beyond its hull face or,
    /// on its plane, outside the face's (perturbed) circumcircle. The common case, a
    /// finite tetrahedron the semi-static bound decides, inline; the rest in conflict_exact.
    bool conflict(const std::uint32_t* t, std::uint32_t e) const {
        if (t[3] != kGhost) {
            const double det = detail::insphere_stage_a_det(p(t[0]), p(t[1]), p(t[2]), p(t[3]), p(e));
            if (det > insphere_bound_) return !furthest_;
            if (-det > insphere_bound_) return furthest_;
            if (exact_in_doubles_) return conflict_tie(t, e);  // the value is exactly 0
            const double local = detail::insphere_local_bound(p(t[0]), p(t[1]), p(t[2]), p(t[3]), p(e));
            if (det > local) return !furthest_;
            if (-det > local) return furthest_;
        }
        return conflict_exact(t, e);
    }
    bool conflict_exact(const std::uint32_t* t, std::uint32_t e) const;
    /// conflict() for a finite tetrahedron whose in-sphere value is known to be exactly 0.
    bool conflict_tie(const std::uint32_t* t, std::uint32_t e) const;
    /// The perturbed in-sphere sign of e against the positively oriented finite a, b, c, d.
    int insphere_perturbed(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d,
                           std::uint32_t e) const;
    /// The perturbed sign of e, coplanar with the hull face a, b, c (counter-clockwise seen from
    /// outside), against that face's circumcircle: what the ghost a, b, c, infinity answers.
    int coplanar_perturbed(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t e) const;

    const double* p(std::uint32_t i) const { return xyz_ + 3 * static_cast<std::size_t>(i); }
    /// orient3d's semi-static bound for these points (detail::orient3d_static_bound), 0 when
    /// exact_in_doubles().
    double orient_bound() const { return orient_bound_; }
    /// Whether the floating-point values of orient3d's and insphere's stage A formulas are the
    /// exact determinants for these points, zero included (lattice_exact): then their sign is the
    /// answer and no exact stage runs; the bounds are 0.
    bool exact_in_doubles() const { return exact_in_doubles_; }

private:
    const double* xyz_;
    double span_;
    Lattice lattice_;  // (before exact_in_doubles_, which fills it)
    bool exact_in_doubles_;
    double orient_bound_;
    double insphere_bound_;
    bool furthest_;
};

/// Index along a 3D Hilbert curve on a 1024^3 grid (each coordinate below 1024).
std::uint32_t hilbert3(std::uint32_t x, std::uint32_t y, std::uint32_t z);
/// The points as (Hilbert key << 32 | index), sorted along the curve over the box [lo, hi] (a
/// 1024^3 grid; stable LSD radix sort on the 30-bit key, so equal keys keep index order). The keys
/// on the threads; the order only affects speed, so NaN or out-of-box coordinates are harmless.
std::vector<std::uint64_t> hilbert_order(PointSpan p, const double* lo, const double* hi, unsigned threads);

/// The power of two delaunay3() scales `points` by (insphere's exact range, with room for the
/// perturbation's helper point); false when there is none or a coordinate is not finite.
bool scale_exponent_of(PointSpan points, int* exponent);

/// Bowyer-Watson insertion of every point of `points` (round by round of points.order) into one
/// mesh; the points must not be all coplanar. `threads` as Delaunay3Options::threads: the mesh is
/// the same for every value. Returns the mesh, ghosts included (free slots have kFree as corner 3).
/// `furthest`: the furthest-site tetrahedralization (the upper 4D hull) by the same insertion with
/// the conflicts negated; then the points must be in convex position (each a vertex of their hull),
/// so that each one inserted lies outside the hull of those before it.
Mesh tetrahedralize(const Points& points, unsigned threads,
                    const std::function<void(std::size_t, std::size_t)>& progress, bool furthest = false);

}  // namespace delaunay3_detail
}  // namespace hullkit
