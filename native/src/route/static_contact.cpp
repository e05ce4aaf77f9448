// RouteChecker's exact static test of one pose: surfaces within the margin (exact triangle tests
// through both BVHs), then containment of one solid in the other by exact ray parity; and the
// static contact (with its distance on request) that RouteChecker::static_contact reports.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "checker_internal.hpp"

namespace hullkit {

Vec route_detail::ray_direction(int attempt) {
    static const Vec fixed[] = {{0.5377, 0.2971, 0.7891},  {-0.3119, 0.8263, 0.4705},
                                {0.6827, -0.5473, 0.4843}, {-0.4211, -0.3389, -0.8413}};
    if (attempt < 4) return fixed[attempt];
    // Beyond those, a deterministic pseudo-random sequence.
    std::uint64_t s = 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(attempt + 1);
    auto next = [&] {
        s ^= s >> 33;
        s *= 0xff51afd7ed558ccdull;
        s ^= s >> 33;
        return static_cast<double>(s >> 11) * 0x1p-53 * 2.0 - 1.0;
    };
    return {next(), next(), next() + 0.1};
}

namespace {

/// Segment o -> f against a box (slab test); the caller passes the box inflated by its tolerance.
bool segment_hits_box(const Vec& o, const Vec& f, const Box& box) {
    double t0 = 0.0, t1 = 1.0;
    const Vec d = f - o;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0.0) {
            if (o[k] < box.lo[k] || o[k] > box.hi[k]) return false;
            continue;
        }
        const double ta = (box.lo[k] - o[k]) / d[k], tb = (box.hi[k] - o[k]) / d[k];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
        if (t0 > t1) return false;
    }
    return true;
}

/// Ray parity of x against the triangles `bvh` holds: `crossing(slot, far)` classifies one
/// triangle (ray_crossing), `shift` maps world points into the BVH's coordinates (for culling
/// only). A ray found degenerate (exactly) is retried in another direction; a point never
/// certified outside counts as inside, so that doubt becomes a hit, never a false "clear".
template <typename Crossing>
bool parity_inside(const Bvh& bvh, const Vec& x, const Vec& shift, const Box& box, double tol,
                   Crossing&& crossing) {
    if (bvh.nodes.empty()) return false;
    const double reach = 4.0 * (glm::length(box.hi - box.lo) + glm::length(x - box.lo)) + 1.0;
    for (int attempt = 0; attempt < 64; ++attempt) {
        const Vec far = x + reach * ray_direction(attempt);
        const Vec local_x = x - shift, local_far = far - shift;
        int crossings = 0;
        bool degenerate = false;
        std::uint32_t stack[128];
        int top = 0;
        stack[top++] = 0;
        while (top > 0 && !degenerate) {
            const BvhNode& node = bvh.nodes[stack[--top]];
            if (!segment_hits_box(local_x, local_far, node.box.inflated(tol))) continue;
            if (node.count == 0) {
                stack[top++] = node.first;
                stack[top++] = node.first + 1;
                continue;
            }
            for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
                const int r = crossing(s, far);
                if (r < 0) {
                    degenerate = true;
                    break;
                }
                crossings += r;
            }
        }
        if (!degenerate) return crossings % 2 == 1;
    }
    return true;
}

}  // namespace

bool RouteChecker::Impl::inside_part(const Part& part, const Vec& w, const Vec& x,
                                     double tol) const {
    return parity_inside(part.bvh, x, w, part.box.shifted(w), tol,
                         [&](std::uint32_t s, const Vec& far) {
                             const Vec* p = &part.tris[3 * s];
                             const Vec q[3] = {p[0] + w, p[1] + w, p[2] + w};
                             return ray_crossing(x, far, q);
                         });
}

bool RouteChecker::Impl::inside_obstacle(std::uint32_t o, const Vec& x, double tol) const {
    return parity_inside(bvh, x, Vec(0.0), obstacle_box[o], tol,
                         [&](std::uint32_t s, const Vec& far) {
                             return tri_obstacle[s] == o ? ray_crossing(x, far, &tris[3 * s]) : 0;
                         });
}

bool RouteChecker::Impl::static_touch(const Part& part, std::size_t pi, const Vec& w, Found* found) const {
    const double tol = tolerance(std::max({std::fabs(w.x), std::fabs(w.y), std::fabs(w.z)}));
    const Box placed = part.box.shifted(w);
    const Box query = placed.inflated(margin + tol);
    // Surfaces within the margin.
    bool hit = false;
    for_each_in_box(bvh, query, [&](std::uint32_t s) {
        const Vec* q = &tris[3 * s];
        const Box qbox = triangle_box(q);
        if (!qbox.overlaps(query)) return false;
        const Box local = qbox.shifted(-w).inflated(margin + tol);
        for_each_in_box(part.bvh, local, [&](std::uint32_t ps) {
            if (!pair_static(&part.tris[3 * ps], w, q)) return false;
            hit = true;
            found->slot = s;
            found->part_slot = ps;
            found->obstacle = tri_obstacle[s];
            found->triangle = tri_index[s];
            return true;
        });
        return hit;
    });
    if (hit) {
        found->containment = false;
        found->part = static_cast<std::int64_t>(pi);
        return true;
    }
    // No surfaces meet, so each connected piece is entirely inside or outside the other's solid:
    // one vertex per piece decides. A piece inside the other lies inside its box.
    const Box loose = placed.inflated(tol);
    if (part.closed) {
        for (const Component& c : obstacle_components) {
            if (loose.contains(c.box) && inside_part(part, w, c.rep, tol)) {
                *found = Found{};
                found->containment = true;
                found->obstacle = c.mesh;
                found->triangle = c.triangle;
                found->part = static_cast<std::int64_t>(pi);
                return true;
            }
        }
    }
    for (std::uint32_t o = 0; o < obstacle_closed.size(); ++o) {
        if (!obstacle_closed[o] || !obstacle_box[o].inflated(tol).contains(placed)) continue;
        for (const Component& c : part.components) {
            if (inside_obstacle(o, c.rep + w, tol)) {
                *found = Found{};
                found->containment = true;
                found->obstacle = o;
                found->triangle = 0;
                found->part = static_cast<std::int64_t>(pi);
                return true;
            }
        }
    }
    return false;
}

StaticContact RouteChecker::Impl::contact_at(const Vec& w, bool want_distance) const {
    // The minimum over a leg of length zero is the static distance.
    return contact_with(
        want_distance, [&](std::size_t pi, Found* found) { return static_touch(parts[pi], pi, w, found); },
        [&](std::size_t pi, Nearest* best) { nearest_over_leg(parts[pi], pi, w, w, best); });
}

}  // namespace hullkit
