// hullkit::verify in dimension 3, step 4 of verify.hpp: every input point lies in the hull bounded
// by the certified surface. Points in an exactly certified inner box pass at once; the others are
// located by walks on the triangles (ordered by a cube map of directions from the interior point)
// and tested against the plane of the triangle they are found in; without an interior point, every
// point is tested against every planar face.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "hullkit/predicates.hpp"
#include "hullkit/verify.hpp"
#include "verify_internal.hpp"

namespace hullkit::verify_detail {

namespace {

/// Coarse lookup of a triangle by direction from the interior point: a cube map of g x g cells per
/// face, each holding a triangle seen in that direction (or kNone). Only a starting guess.
class DirectionGrid {
public:
    /// A grid of about `cells` cells in all.
    explicit DirectionGrid(std::size_t cells) {
        const double side = std::sqrt(static_cast<double>(cells) / 6.0);
        g_ = static_cast<int>(std::clamp(side, 1.0, 2048.0));
        cells_.assign(size(), kNone);
    }
    std::size_t size() const { return 6 * static_cast<std::size_t>(g_) * g_; }
    /// The cell of direction d, numbered so that consecutive numbers are neighbouring cells
    /// (rows of a cube face in alternating directions).
    std::size_t cell(const double* d) const {
        const double m[3] = {std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])};
        const int axis = m[0] >= m[1] ? (m[0] >= m[2] ? 0 : 2) : (m[1] >= m[2] ? 1 : 2);
        if (!(m[axis] > 0.0) || !std::isfinite(m[axis])) return 0;
        const int face = 2 * axis + (d[axis] < 0.0 ? 1 : 0);
        auto slot = [&](double c) {
            const double t = (c / m[axis] + 1.0) * 0.5 * g_;
            return std::clamp(static_cast<int>(t), 0, g_ - 1);
        };
        const int u = slot(d[(axis + 1) % 3]);
        int v = slot(d[(axis + 2) % 3]);
        if (u % 2 == 1) v = g_ - 1 - v;
        return (static_cast<std::size_t>(face) * g_ + u) * g_ + v;
    }
    Index& at(std::size_t cell) { return cells_[cell]; }

private:
    int g_ = 1;
    std::vector<Index> cells_;
};

}  // namespace

bool SurfaceVerifier::cone_contains(Index t, const double* q, int skip, int* negative, int* negatives) const {
    *negatives = 0;
    for (int k = 0; k < 3; ++k) {
        if (k == skip) continue;
        if (orient3d(o_, p(corner(t, k)), p(corner(t, (k + 1) % 3)), q) < 0) negative[(*negatives)++] = k;
    }
    return *negatives == 0;
}

/// The triangle whose cone from o_ contains q: a randomized visibility walk from `start`,
/// then, if it does not arrive within its budget, a scan of all triangles.
Index SurfaceVerifier::locate(const double* q, Index start, std::uint64_t& random) {
    const std::size_t budget = 64 + 4 * static_cast<std::size_t>(std::sqrt(static_cast<double>(f_)));
    Index t = start;
    int skip = -1;  // the edge just crossed: q is known to be on t's side of it
    int negative[3];
    int negatives = 0;
    for (std::size_t step = 0; step < budget; ++step) {
        if (cone_contains(t, q, skip, negative, &negatives)) return t;
        int k = negative[0];
        if (negatives > 1) {
            random ^= random << 13;
            random ^= random >> 7;
            random ^= random << 17;
            k = negative[random % static_cast<std::uint64_t>(negatives)];
        }
        const Index g = twins_[3 * t + k];
        t = g / 3;
        skip = static_cast<int>(g % 3);
    }
    ++report_.exhaustive_points;
    for (std::size_t u = 0; u < f_; ++u) {
        if (cone_contains(static_cast<Index>(u), q, -1, negative, &negatives)) return static_cast<Index>(u);
    }
    return kNone;
}

std::vector<char> SurfaceVerifier::vertex_mask() const {
    std::vector<char> mask(points_.count, 0);
    for (Index v : vertices_) mask[v] = 1;
    return mask;
}

void SurfaceVerifier::report_outside(std::size_t i, Index t) {
    out_.add("point " + num(i) + " " + coordinates(original_[i]) + " is outside the hull: above the plane of " +
             triangle_name(t));
}

/// An axis-aligned box around o_ shown exactly to lie in the hull (its 8 corners are on or below
/// every face plane; the hull is convex): points in it need no further test. Rounded geometry
/// sizes the box; false when it cannot be certified.
bool SurfaceVerifier::inner_box(double lo[3], double hi[3]) const {
    double low[3], high[3];
    for (int axis = 0; axis < 3; ++axis) low[axis] = high[axis] = p(vertices_[0])[axis];
    for (Index v : vertices_) {
        for (int axis = 0; axis < 3; ++axis) {
            low[axis] = std::min(low[axis], p(v)[axis]);
            high[axis] = std::max(high[axis], p(v)[axis]);
        }
    }
    const double half[3] = {(high[0] - low[0]) * 0.5, (high[1] - low[1]) * 0.5, (high[2] - low[2]) * 0.5};
    double scale = std::numeric_limits<double>::infinity();
    for (Index t : face_reps_) {
        const double* a = p(corner(t, 0));
        const double* b = p(corner(t, 1));
        const double* c = p(corner(t, 2));
        const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        const double reach = std::fabs(n[0]) * half[0] + std::fabs(n[1]) * half[1] + std::fabs(n[2]) * half[2];
        const double room = n[0] * (a[0] - o_[0]) + n[1] * (a[1] - o_[1]) + n[2] * (a[2] - o_[2]);
        if (reach > 0.0) scale = std::min(scale, room / reach);
    }
    for (double shrink : {0.9, 0.25}) {
        const double s = scale * shrink;
        if (!(s > 0.0) || !std::isfinite(s)) return false;
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = o_[axis] - s * half[axis];
            hi[axis] = o_[axis] + s * half[axis];
            for (double* x : {&lo[axis], &hi[axis]}) {
                if (std::fabs(*x) < kPredicateMinMagnitude) *x = 0.0;  // keep the predicates exact
            }
            if (!(lo[axis] <= hi[axis])) return false;
        }
        bool inside = true;
        for (int k = 0; k < 8 && inside; ++k) {
            const double q[3] = {(k & 1 ? hi : lo)[0], (k & 2 ? hi : lo)[1], (k & 4 ? hi : lo)[2]};
            for (Index t : face_reps_) {
                if (orient3d(p(corner(t, 0)), p(corner(t, 1)), p(corner(t, 2)), q) > 0) {
                    inside = false;
                    break;
                }
            }
        }
        if (inside) return true;
    }
    return false;
}

void SurfaceVerifier::contain_by_walking() {
    const std::vector<char> is_vertex = vertex_mask();
    // The inner box costs 8 tests per face; worth it when many points are not vertices.
    double lo[3] = {0, 0, 0}, hi[3] = {-1, -1, -1};
    if (points_.count - vertices_.size() > 4 * face_reps_.size() && !inner_box(lo, hi)) {
        hi[0] = -1;  // empty box
        lo[0] = 0;
    }
    // Points to locate, sorted by direction cell so that consecutive walks are short; each
    // walk starts where the previous one ended, or, in a cell no point visited yet, at a
    // triangle seen in that direction.
    std::vector<Index> pending;
    for (std::size_t i = 0; i < points_.count; ++i) {
        const double* q = p(static_cast<Index>(i));
        if (is_vertex[i] ||
            (lo[0] <= q[0] && q[0] <= hi[0] && lo[1] <= q[1] && q[1] <= hi[1] && lo[2] <= q[2] && q[2] <= hi[2])) {
            ++report_.checked_points;
        } else {
            pending.push_back(static_cast<Index>(i));
        }
    }
    DirectionGrid grid(std::max(f_, pending.size() / 2));
    for (std::size_t t = 0; t < f_; ++t) {
        double d[3];
        for (int axis = 0; axis < 3; ++axis) {
            d[axis] = (p(corner(t, 0))[axis] + p(corner(t, 1))[axis] + p(corner(t, 2))[axis]) / 3.0 - o_[axis];
        }
        grid.at(grid.cell(d)) = static_cast<Index>(t);
    }
    std::vector<Index> cell_of(pending.size());
    std::vector<Index> bucket(grid.size() + 1, 0);
    for (std::size_t k = 0; k < pending.size(); ++k) {
        const double* q = p(pending[k]);
        const double d[3] = {q[0] - o_[0], q[1] - o_[1], q[2] - o_[2]};
        cell_of[k] = static_cast<Index>(grid.cell(d));
        ++bucket[cell_of[k] + 1];
    }
    for (std::size_t c = 0; c < grid.size(); ++c) bucket[c + 1] += bucket[c];
    std::vector<Index> order(pending.size());
    for (std::size_t k = 0; k < pending.size(); ++k) order[bucket[cell_of[k]]++] = pending[k];
    pending.clear();
    pending.shrink_to_fit();

    Index previous = kNone;
    std::size_t previous_cell = grid.size();
    std::uint64_t random = 0x243f6a8885a308d3ull;
    for (const Index i : order) {
        const double* q = p(i);
        const double d[3] = {q[0] - o_[0], q[1] - o_[1], q[2] - o_[2]};
        const std::size_t cell = grid.cell(d);
        Index start = previous;
        if (cell != previous_cell && grid.at(cell) != kNone && (previous == kNone || cell != previous_cell + 1)) {
            start = grid.at(cell);
        }
        if (start == kNone) start = 0;
        previous_cell = cell;
        const Index t = locate(q, start, random);
        if (t == kNone) {
            out_.add("point " + num(i) + " could not be located on the surface (verify is inconsistent)");
            continue;
        }
        previous = t;
        const int side = orient3d(p(corner(t, 0)), p(corner(t, 1)), p(corner(t, 2)), q);
        if (side > 0) {
            report_outside(i, t);
            continue;
        }
        ++report_.checked_points;
        if (side == 0) {
            // On the surface, hence in the closed triangle t: identical to a vertex only if to
            // one of t's corners (the surface is embedded).
            const PointKey key = key_of(q);
            for (int k = 0; k < 3; ++k) {
                const Index c = corner(t, k);
                if (c > i && key_of(p(c)) == key) {
                    out_.add("vertex " + num(c) + " repeats point " + num(i) + " " + coordinates(original_[i]) +
                             ": the lowest index must represent identical points");
                }
            }
        }
    }
}

void SurfaceVerifier::contain_exhaustively(bool structure_ok) {
    if (face_reps_.empty()) return;
    if (!structure_ok) {
        const double work = static_cast<double>(points_.count) * static_cast<double>(face_reps_.size());
        if (work > 2e8) {
            out_.note("containment was not checked: the surface already failed, and testing every point "
                      "against every face would take too long");
            return;
        }
    } else {
        out_.note("no point strictly inside the hull is representable in doubles (the hull is too thin): "
                  "every point was tested against every face");
    }
    const std::vector<char> is_vertex = vertex_mask();
    std::size_t last = 0;  // the face that rejected the previous point is tried first
    for (std::size_t i = 0; i < points_.count; ++i) {
        if (is_vertex[i]) {
            ++report_.checked_points;
            continue;
        }
        const double* q = p(static_cast<Index>(i));
        bool outside = false;
        for (std::size_t k = 0; k < face_reps_.size(); ++k) {
            const std::size_t r = (last + k) % face_reps_.size();
            const Index t = face_reps_[r];
            if (orient3d(p(corner(t, 0)), p(corner(t, 1)), p(corner(t, 2)), q) > 0) {
                report_outside(i, t);
                outside = true;
                last = r;
                break;
            }
        }
        if (!outside) {
            ++report_.checked_points;
            ++report_.exhaustive_points;
        }
    }
}

}  // namespace hullkit::verify_detail
