// RouteChecker's minimum clearance over a leg: the distance between the swept part triangles and
// the obstacle triangles, best-first over the obstacle BVH and depth-first over the part's, pruned
// by lower bounds on the distance between a fixed box and a moving one.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "checker_internal.hpp"

namespace hullkit {

namespace {

/// Where along the sweep (0 at w0, 1 at w1) the point with barycentric weights w of piece k lies.
double fraction_of(int piece, const double w[3]) {
    if (piece == 0) return 0.0;
    if (piece == 1) return 1.0;
    return piece % 2 == 0 ? w[2] : w[1] + w[2];
}

/// Lower bounds on the distance between a fixed box and a box moving from offset a to offset b:
/// the distance between the segment [a, b] and the box `target - moving` (Minkowski difference),
/// bounded below by its box distance to the segment's box and by the gap seen in the plane
/// perpendicular to the leg (unit u, v span that plane).
struct SweptBound {
    Vec a, b, u, v;
    double au, av;

    SweptBound(const Vec& a_, const Vec& b_) : a(a_), b(b_) {
        const Vec d = b - a;
        const double len = glm::length(d);
        const Vec n = len > 0.0 ? d / len : Vec(1, 0, 0);
        const Vec helper = std::fabs(n.x) < 0.6 ? Vec(1, 0, 0) : Vec(0, 1, 0);
        u = glm::normalize(glm::cross(n, helper));
        v = glm::cross(n, u);
        au = glm::dot(a, u);
        av = glm::dot(a, v);
    }

    double operator()(const Box& target, const Box& moving) const {
        const Box m{target.lo - moving.hi, target.hi - moving.lo};
        Box segment;
        segment.add(a);
        segment.add(b);
        const double axis_aligned = m.distance(segment);
        const Vec c = (m.lo + m.hi) * 0.5, h = (m.hi - m.lo) * 0.5;
        const double ru = std::fabs(u.x) * h.x + std::fabs(u.y) * h.y + std::fabs(u.z) * h.z;
        const double rv = std::fabs(v.x) * h.x + std::fabs(v.y) * h.y + std::fabs(v.z) * h.z;
        const double gu = std::max(0.0, std::fabs(au - glm::dot(c, u)) - ru);
        const double gv = std::max(0.0, std::fabs(av - glm::dot(c, v)) - rv);
        return std::max(axis_aligned, std::sqrt(gu * gu + gv * gv));
    }
};

}  // namespace

void RouteChecker::Impl::nearest_over_leg(const Part& part, std::size_t pi, const Vec& a, const Vec& b,
                                          Nearest* best) const {
    if (bvh.nodes.empty()) return;
    const SweptBound bound(a, b);
    std::vector<std::pair<double, std::uint32_t>> heap;
    heap.emplace_back(bound(bvh.nodes[0].box, part.box), 0u);
    std::vector<std::pair<double, std::uint32_t>> part_stack;
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), std::greater<>());
        const auto [lower, index] = heap.back();
        heap.pop_back();
        if (lower >= best->distance) break;
        const BvhNode& node = bvh.nodes[index];
        if (node.count == 0) {
            for (std::uint32_t c = node.first; c < node.first + 2; ++c) {
                const double lb = bound(bvh.nodes[c].box, part.box);
                if (lb < best->distance) {
                    heap.emplace_back(lb, c);
                    std::push_heap(heap.begin(), heap.end(), std::greater<>());
                }
            }
            continue;
        }
        for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
            const Vec* q = &tris[3 * s];
            const Box qbox = triangle_box(q);
            if (bound(qbox, part.box) >= best->distance) continue;
            // Depth-first over the part's BVH, nearer child first.
            part_stack.clear();
            part_stack.emplace_back(bound(qbox, part.bvh.nodes[0].box), 0u);
            while (!part_stack.empty()) {
                const auto [pb, pn] = part_stack.back();
                part_stack.pop_back();
                if (pb >= best->distance) continue;
                const BvhNode& pnode = part.bvh.nodes[pn];
                if (pnode.count == 0) {
                    const double l0 = bound(qbox, part.bvh.nodes[pnode.first].box);
                    const double l1 = bound(qbox, part.bvh.nodes[pnode.first + 1].box);
                    if (l0 <= l1) {
                        part_stack.emplace_back(l1, pnode.first + 1);
                        part_stack.emplace_back(l0, pnode.first);
                    } else {
                        part_stack.emplace_back(l0, pnode.first);
                        part_stack.emplace_back(l1, pnode.first + 1);
                    }
                    continue;
                }
                for (std::uint32_t ps = pnode.first; ps < pnode.first + pnode.count; ++ps) {
                    const Vec* p = &part.tris[3 * ps];
                    if (bound(qbox, triangle_box(p)) >= best->distance) continue;
                    Vec pieces[8][3];
                    sweep_pieces(p, a, b, pieces);
                    for (int k = 0; k < 8; ++k) {
                        if (k > 0 && a == b) break;  // a leg of length zero: the start cap alone
                        if (triangle_box(pieces[k]).distance(qbox) >= best->distance) continue;
                        double w[3];
                        const double dist = triangle_distance(pieces[k], q, w);
                        if (dist < best->distance) {
                            best->distance = dist;
                            best->fraction = fraction_of(k, w);
                            best->obstacle = tri_obstacle[s];
                            best->triangle = tri_index[s];
                            best->part = static_cast<std::int64_t>(pi);
                        }
                    }
                }
            }
        }
    }
}

}  // namespace hullkit
