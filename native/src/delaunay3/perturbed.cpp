// The perturbed predicates of the 3D Delaunay tetrahedralization (delaunay3.hpp, "Ties").
//
// Each point's lift |p|^2 is raised by delta(p) = eps^(rank), the later a point comes in the
// lexicographic (x, y, z) order the larger its infinitesimal. The in-sphere determinant G(e) of e
// against a positively oriented a, b, c, d (hullkit's sign: > 0 inside) is affine in each delta,
// with the partial derivatives
//     dG/d delta_e = -orient3d(a, b, c, d)            (raising e moves it outside),
//     dG/d delta_v =  orient3d(a, b, c, d with v replaced by e)   for each corner v,
// so when G is exactly 0 its perturbed sign is the sign of the first nonzero derivative taken in
// decreasing order of the five points' ranks (Devillers & Teillaud 2011, section 3). For distinct
// points one of the first three is nonzero. A ghost (a, b, c, infinity) is the limit of a
// tetrahedron whose fourth corner runs off to infinity beyond the hull face a, b, c: it holds e
// when e is strictly beyond the face's plane, and for e on the plane its perturbed sphere is the
// face's circumcircle in the plane, perturbed the same way. The corner at infinity has no term of
// its own there (its derivative orient3d(a, b, c, e) is 0 for coplanar e), and the others' terms
// depend on it only through its side, so any finite point q beyond the face stands in for it.
#include <algorithm>
#include <cmath>

#include "delaunay3_internal.hpp"
#include "exact/lattice.hpp"

namespace hullkit {
namespace delaunay3_detail {

Predicates::Predicates(const Points& points, bool furthest, bool in_doubles)
    : xyz_(points.xyz.data()),
      span_(points.span),
      exact_in_doubles_(in_doubles && lattice_exact(PointSpan(points.xyz.data(), points.size()), &lattice_)),
      orient_bound_(exact_in_doubles_ ? 0.0 : detail::orient3d_static_bound(points.span)),
      insphere_bound_(exact_in_doubles_ ? 0.0 : detail::insphere_static_bound(points.span)),
      furthest_(furthest) {}

bool lattice_exact(PointSpan points, Lattice* lattice) {
    constexpr double kMaxUnits = 659;  // 72 * 659^5 < 2^53 < 72 * 660^5
    int unit = 0;
    double lo[3];
    if (!detail::small_lattice(points.xyz, points.count, 3, kMaxUnits, 5, &unit, lo)) return false;
    std::copy(lo, lo + 3, lattice->lo);
    lattice->inverse_unit = std::ldexp(1.0, -unit);
    return true;
}

namespace {

/// The positions 0..count-1 of `points` in decreasing lexicographic order (count <= 5): each
/// point's rank counted over the pairs, without branches (the comparisons of cospherical points
/// are as good as random, and a sort's branches mispredicted). Equal points, which distinct points
/// are not, would go by position.
template <int count>
void by_decreasing_rank(const double* const* points, int* rank_order) {
    int rank[count] = {};
    for (int i = 0; i < count; ++i) {
        for (int j = i + 1; j < count; ++j) {
            const bool less = lexicographically_less(points[i], points[j]);
            rank[j] += less;
            rank[i] += !less;
        }
    }
    for (int i = 0; i < count; ++i) rank_order[count - 1 - rank[i]] = i;
}

/// The perturbation's decision for corners w[0..3] (positively oriented, w[3] possibly a stand-in
/// for infinity that takes part in no ranking: `ranked` corners are w[0..ranked-1]) and the query e,
/// when the unperturbed in-sphere sign is 0.
int perturbation(const double* const* w, int ranked, const double* e) {
    const double* points[5];
    for (int i = 0; i < ranked; ++i) points[i] = w[i];
    points[ranked] = e;
    int order[5];
    if (ranked == 4) {
        by_decreasing_rank<5>(points, order);
    } else {
        by_decreasing_rank<4>(points, order);
    }
    for (int r = 0; r <= ranked; ++r) {
        const int i = order[r];
        if (i == ranked) return -1;  // e itself is raised most: outside
        const double* replaced[4] = {w[0], w[1], w[2], w[3]};
        replaced[i] = e;
        if (const int o = orient3d(replaced[0], replaced[1], replaced[2], replaced[3]); o != 0) return o;
    }
    return -1;  // not reached for distinct points: e's own term is nonzero
}

/// perturbation() for four finite corners when Predicates::exact_in_doubles(): the same decision,
/// without branches on the points (ties on lattices are common, and their outcomes as good as
/// random). All four orientations with a corner replaced by e, from the corners relative to e
/// (corner k replaced: the determinant of the other three, + for k = 0 and 2, - for 1 and 3),
/// exact in doubles; the answer is the sign of the one of the highest-ranked corner ranked above e
/// that is not 0, or -1 (e's own term) when there is none. The ranks compare as the lattice's
/// keys (Lattice::key), one number per point.
int perturbation_in_doubles(const double* const* w, const double* e, const Lattice& lattice) {
    double d[4][3];
    for (int i = 0; i < 4; ++i)
        for (int a = 0; a < 3; ++a) d[i][a] = w[i][a] - e[a];
    auto det = [&](int i, int j, int k) {
        const double* a = d[i];
        const double* b = d[j];
        const double* c = d[k];
        return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    };
    const double replaced[4] = {det(1, 2, 3), -det(0, 2, 3), det(0, 1, 3), -det(0, 1, 2)};
    int answer = -1;
    double best = lattice.key(e);
    for (int k = 0; k < 4; ++k) {  // (arithmetic, not branches: keys are never negative)
        const double key = lattice.key(w[k]);
        const int decides = (replaced[k] != 0) & (key > best);
        const int sign = (replaced[k] > 0) - (replaced[k] < 0);
        answer += decides * (sign - answer);
        best = std::max(best, key * decides);
    }
    return answer;
}

}  // namespace

int Predicates::insphere_perturbed(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d,
                                   std::uint32_t e) const {
    if (exact_in_doubles_) {
        const double det = detail::insphere_stage_a_det(p(a), p(b), p(c), p(d), p(e));
        if (det != 0) return det > 0 ? 1 : -1;
    } else if (const int s = detail::insphere_semi_static(insphere_bound_, p(a), p(b), p(c), p(d), p(e)); s != 0) {
        return s;
    }
    const double* w[4] = {p(a), p(b), p(c), p(d)};
    return exact_in_doubles_ ? perturbation_in_doubles(w, p(e), lattice_) : perturbation(w, 4, p(e));
}

int Predicates::coplanar_perturbed(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t e) const {
    const double* pa = p(a);
    const double* pb = p(b);
    const double* pc = p(c);
    // q beyond the face: a moved along the axis where the face's normal n = (b-a) x (c-a) is largest,
    // in the direction of that component's exact sign; then orient3d(a, b, c, q) = n_k (q_k - a_k) > 0.
    // The move is at least |a_k| and at least the points' span, so q_k != a_k, and |q_k| stays
    // within 3 times the largest coordinate (delaunay3() leaves room for that in the exact range).
    const double n[3] = {(pb[1] - pa[1]) * (pc[2] - pa[2]) - (pb[2] - pa[2]) * (pc[1] - pa[1]),
                         (pb[2] - pa[2]) * (pc[0] - pa[0]) - (pb[0] - pa[0]) * (pc[2] - pa[2]),
                         (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0])};
    int axes[3] = {0, 1, 2};
    std::stable_sort(axes, axes + 3, [&](int i, int j) { return std::fabs(n[i]) > std::fabs(n[j]); });
    double q[3] = {pa[0], pa[1], pa[2]};
    for (const int k : axes) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const int sign = orient2d(pa[i], pa[j], pb[i], pb[j], pc[i], pc[j]);  // the exact sign of n_k
        if (sign == 0) continue;
        const double move = std::max(span_, std::fabs(pa[k]));
        q[k] = pa[k] + (sign > 0 ? move : -move);
        break;
    }
    if (const int s = insphere(pa, pb, pc, q, p(e)); s != 0) return s;
    const double* w[4] = {pa, pb, pc, q};
    return perturbation(w, 3, p(e));  // (q may lie off the lattice's range: orient3d in full)
}

// Furthest-site (the upper hull of the same perturbed lifted points): a finite tetrahedron's answer
// is negated, and so is a ghost's for e on its plane: the ghost is then the limit of a sphere
// through a, b, c whose centre runs off to infinity on the hull's side, which still meets the plane
// in the face's circumcircle; e strictly beyond the face is outside every such sphere either way.
bool Predicates::conflict_exact(const std::uint32_t* t, std::uint32_t e) const {
    const int inside = furthest_ ? -1 : 1;
    if (t[3] == kGhost) {
        const int side = orient(t[0], t[1], t[2], e);
        if (side != 0) return side > 0;
        return coplanar_perturbed(t[0], t[1], t[2], e) == inside;
    }
    // (On a lattice a finite tetrahedron never gets here: conflict() decided it or found the tie.)
    if (const int s = insphere(p(t[0]), p(t[1]), p(t[2]), p(t[3]), p(e)); s != 0) return s == inside;
    return conflict_tie(t, e);
}

bool Predicates::conflict_tie(const std::uint32_t* t, std::uint32_t e) const {
    const double* w[4] = {p(t[0]), p(t[1]), p(t[2]), p(t[3])};
    const int sign = exact_in_doubles_ ? perturbation_in_doubles(w, p(e), lattice_) : perturbation(w, 4, p(e));
    return sign == (furthest_ ? -1 : 1);
}

}  // namespace delaunay3_detail
}  // namespace hullkit
