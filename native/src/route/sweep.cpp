// RouteChecker's first-contact search over a translated leg: the broad phase (the swept hull's
// axes, best-first over the obstacle BVH by the earliest time a box can be reached), the
// separating-axis estimate, and the exact sweep tests that bracket the first contact.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "checker_internal.hpp"

namespace hullkit {

namespace {

/// Target width of a first-contact bracket (the contract promises 1e-9).
constexpr double kBracketWidth = 4e-10;

/// An axis with the interval the swept hull covers along it.
struct Axis {
    Vec n;
    double lo, hi;
};

/// Time window [t0, t1] within [0, limit] in which the box `moving` (local coordinates) translated
/// by a + t d overlaps `target`; false when there is none. Conservative when `moving` was inflated
/// by the tolerance (the tolerance dominates the rounding of these few operations).
bool overlap_window(const Box& moving, const Vec& a, const Vec& d, const Box& target, double limit,
                    double* t0_out, double* t1_out) {
    double t0 = 0.0, t1 = limit;
    for (int k = 0; k < 3; ++k) {
        const double lo = moving.lo[k] + a[k], hi = moving.hi[k] + a[k];
        if (d[k] == 0.0) {
            if (target.lo[k] > hi || lo > target.hi[k]) return false;
            continue;
        }
        const double ta = (target.lo[k] - hi) / d[k], tb = (target.hi[k] - lo) / d[k];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
        if (!(t0 <= t1)) return false;
    }
    *t0_out = t0;
    *t1_out = t1;
    return true;
}

/// The separating-axis picture of triangle p (local) moving by a + t d against triangle q, in
/// floating point, over t in [0, limit]. Returns false when one axis keeps them apart by more than
/// `tol` (times the axis length) over the whole window: a proof of no contact, since rounding is
/// far below tol. Otherwise true, with *estimate the first t at which no axis separates them (the
/// exact first contact up to rounding; NaN when the axes cannot tell).
bool sat_window(const Vec* p, const Vec* q, const Vec& a, const Vec& d, double limit, double tol,
                double* estimate) {
    const Vec ep[3] = {p[1] - p[0], p[2] - p[1], p[0] - p[2]};
    const Vec eq[3] = {q[1] - q[0], q[2] - q[1], q[0] - q[2]};
    const Vec np = glm::cross(ep[0], ep[1]), nq = glm::cross(eq[0], eq[1]);
    Vec axes[17];
    int count = 0;
    axes[count++] = np;
    axes[count++] = nq;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) axes[count++] = glm::cross(ep[i], eq[j]);
        axes[count++] = glm::cross(np, ep[i]);
        axes[count++] = glm::cross(nq, eq[i]);
    }
    double t_lo = 0.0, t_hi = limit;
    for (int k = 0; k < count; ++k) {
        const Vec& n = axes[k];
        const double len = glm::length(n);
        if (!(len > 0.0)) continue;
        const double pa = glm::dot(n, p[0]), pb = glm::dot(n, p[1]), pc = glm::dot(n, p[2]);
        const double qa = glm::dot(n, q[0]), qb = glm::dot(n, q[1]), qc = glm::dot(n, q[2]);
        const double shift = glm::dot(n, a), s = glm::dot(n, d);
        const double pmin = std::min({pa, pb, pc}) + shift, pmax = std::max({pa, pb, pc}) + shift;
        const double qmin = std::min({qa, qb, qc}), qmax = std::max({qa, qb, qc});
        const double gap = tol * len;
        const double end_shift = s * limit;
        // Apart along n at both ends of the window (hence throughout: the motion is linear).
        if (pmax < qmin - gap && pmax + end_shift < qmin - gap) return false;
        if (pmin > qmax + gap && pmin + end_shift > qmax + gap) return false;
        if (s == 0.0) continue;
        const double t1 = (qmin - pmax) / s, t2 = (qmax - pmin) / s;
        t_lo = std::max(t_lo, std::min(t1, t2));
        t_hi = std::min(t_hi, std::max(t1, t2));
    }
    *estimate = t_lo <= t_hi ? t_lo : std::numeric_limits<double>::quiet_NaN();
    return true;
}

}  // namespace

void RouteChecker::Impl::sweep_part(const Part& part, std::size_t pi, const Vec& a, const Vec& b,
                                    Found* found) const {
    if (bvh.nodes.empty()) return;
    const Vec d = b - a;
    const double offset_scale = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z),
                                          std::fabs(b.x), std::fabs(b.y), std::fabs(b.z)});
    const double tol = tolerance(offset_scale);
    const double reach = margin + tol;
    const Box moving = part.box.inflated(reach);

    // Broad-phase axes: the fixed ones, and d x (hull edge), the swept hull's side planes.
    std::vector<Axis> axes;
    axes.reserve(part.axes.size() + part.hull_edges.size());
    for (std::size_t k = 0; k < part.axes.size(); ++k) {
        const double da = glm::dot(part.axes[k], a), db = glm::dot(part.axes[k], b);
        axes.push_back({part.axes[k], part.axis_lo[k] + std::min(da, db),
                        part.axis_hi[k] + std::max(da, db)});
    }
    const bool small_hull = part.hull_points.size() <= 64;
    if (small_hull && part.hull_edges.size() * part.hull_points.size() <= 8192) {
        for (const Vec& e : part.hull_edges) {
            const Vec c = glm::cross(d, e);
            const double len = glm::length(c);
            if (!(len > 1e-9 * glm::length(d) * glm::length(e))) continue;
            const Vec n = c / len;
            const auto [lo, hi] = extent_along(n, part.hull_points);
            const double da = glm::dot(n, a), db = glm::dot(n, b);
            axes.push_back({n, lo + std::min(da, db), hi + std::max(da, db)});
        }
    }
    // True when q is certainly farther than the margin from the swept hull.
    auto separated = [&](const Vec* q) {
        for (const Axis& axis : axes) {
            const double p0 = glm::dot(axis.n, q[0]), p1 = glm::dot(axis.n, q[1]),
                         p2 = glm::dot(axis.n, q[2]);
            if (std::min({p0, p1, p2}) > axis.hi + reach) return true;
            if (std::max({p0, p1, p2}) < axis.lo - reach) return true;
        }
        if (!small_hull) return false;
        const Vec c = glm::cross(q[1] - q[0], q[2] - q[0]);
        const double len = glm::length(c);
        if (!(len > 0.0) || !std::isfinite(len)) return false;
        const Vec n = c / len;
        auto [lo, hi] = extent_along(n, part.hull_points);
        const double da = glm::dot(n, a), db = glm::dot(n, b);
        lo += std::min(da, db);
        hi += std::max(da, db);
        const double p0 = glm::dot(n, q[0]), p1 = glm::dot(n, q[1]), p2 = glm::dot(n, q[2]);
        return std::min({p0, p1, p2}) > hi + reach || std::max({p0, p1, p2}) < lo - reach;
    };

    auto limit = [&] { return found->found ? found->lo : 1.0; };

    // The narrow phase for one obstacle triangle: the part triangles whose sweep can reach it,
    // earliest possible contact first; each one that touches it before the current bracket
    // moves the bracket (bisection on sub-leg sweeps: sweeping further only adds contact).
    std::vector<std::pair<double, std::uint32_t>> pairs;
    auto narrow = [&](std::uint32_t s, const Box& qbox) {
        const Vec* q = &tris[3 * s];
        const Vec e = offset_at(a, b, limit());
        const Box local = Box{qbox.lo - glm::max(a, e), qbox.hi - glm::min(a, e)}.inflated(reach);
        pairs.clear();
        for_each_in_box(part.bvh, local, [&](std::uint32_t ps) {
            double t0, t1;
            const Box pbox = triangle_box(&part.tris[3 * ps]).inflated(reach);
            if (overlap_window(pbox, a, d, qbox, limit(), &t0, &t1)) pairs.emplace_back(t0, ps);
            return false;
        });
        std::sort(pairs.begin(), pairs.end());
        for (const auto& pr : pairs) {
            double hi = limit();
            if (pr.first > hi) break;
            const Vec* p = &part.tris[3 * pr.second];
            double estimate;
            if (!sat_window(p, q, a, d, hi, reach, &estimate)) continue;
            if (!pair_sweep(p, a, offset_at(a, b, hi), q)) continue;
            double lo = 0.0;  // the start pose is known clear
            if (margin == 0.0 && estimate >= 0.0 && estimate <= hi) {
                // Margin 0: the separating axes give the first contact up to rounding; two exact
                // sweeps certify a bracket around it (else they narrow the bisection).
                const double below = estimate - 0.25 * kBracketWidth;
                const double above = std::min(hi, estimate + 0.25 * kBracketWidth);
                if (below > 0.0) {
                    if (pair_sweep(p, a, offset_at(a, b, below), q)) {
                        hi = below;
                    } else {
                        lo = below;
                    }
                }
                if (above > lo && above < hi) {
                    if (pair_sweep(p, a, offset_at(a, b, above), q)) {
                        hi = above;
                    } else {
                        lo = above;
                    }
                }
            }
            while (hi - lo > kBracketWidth) {
                const double mid = 0.5 * (lo + hi);
                if (pair_sweep(p, a, offset_at(a, b, mid), q)) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            found->found = true;
            found->lo = lo;
            found->hi = hi;
            found->slot = s;
            found->part_slot = pr.second;
            found->obstacle = tri_obstacle[s];
            found->triangle = tri_index[s];
            found->part = static_cast<std::int64_t>(pi);
        }
    };

    // Best-first over the obstacle BVH by the earliest time the part's box can reach a node.
    std::vector<std::pair<double, std::uint32_t>> heap;
    auto push = [&](std::uint32_t node) {
        double t0, t1;
        if (overlap_window(moving, a, d, bvh.nodes[node].box, limit(), &t0, &t1)) {
            heap.emplace_back(t0, node);
            std::push_heap(heap.begin(), heap.end(), std::greater<>());
        }
    };
    push(0);
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), std::greater<>());
        const auto [t, index] = heap.back();
        heap.pop_back();
        if (t > limit()) break;
        const BvhNode& node = bvh.nodes[index];
        if (node.count == 0) {
            push(node.first);
            push(node.first + 1);
            continue;
        }
        for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
            const Vec* q = &tris[3 * s];
            const Box qbox = triangle_box(q);
            double t0, t1;
            if (!overlap_window(moving, a, d, qbox, limit(), &t0, &t1)) continue;
            if (separated(q)) continue;
            narrow(s, qbox);
        }
    }
}

}  // namespace hullkit
