// Private to the route module: an axis-aligned bounding-box tree over triangles, in flat arrays.
//
// Built once as a linear BVH (Morton order of the triangles' box centres); node i is internal when count == 0, its children are `first` and `first + 1`;
// a leaf holds the items order[first .. first + count). Boxes are the exact min/max of the
// coordinates, so any box test made with an outward tolerance is conservative.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <vector>

#include "geometry.hpp"

namespace hullkit::route_detail {

struct Box {
    Vec lo{std::numeric_limits<double>::infinity()};
    Vec hi{-std::numeric_limits<double>::infinity()};

    void add(const Vec& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void add(const Box& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    Box inflated(double r) const { return {lo - r, hi + r}; }
    Box shifted(const Vec& w) const { return {lo + w, hi + w}; }
    bool overlaps(const Box& b) const {
        return lo.x <= b.hi.x && b.lo.x <= hi.x && lo.y <= b.hi.y && b.lo.y <= hi.y &&
               lo.z <= b.hi.z && b.lo.z <= hi.z;
    }
    bool contains(const Box& b) const {
        return lo.x <= b.lo.x && lo.y <= b.lo.y && lo.z <= b.lo.z && b.hi.x <= hi.x &&
               b.hi.y <= hi.y && b.hi.z <= hi.z;
    }
    /// Euclidean distance between the boxes (0 when they overlap); a lower bound for any two
    /// points inside them.
    double distance(const Box& b) const {
        const Vec gap = glm::max(glm::max(lo - b.hi, b.lo - hi), Vec(0.0));
        return std::sqrt(glm::dot(gap, gap));
    }
};

struct BvhNode {
    Box box;
    std::uint32_t first = 0;
    std::uint32_t count = 0;  // 0: internal node
};

/// The tree over `triangles` (3 points per triangle). order[] maps leaf slots to triangle ids;
/// the triangles are usually stored again in that order by the owner for locality.
struct Bvh {
    std::vector<BvhNode> nodes;
    std::vector<std::uint32_t> order;

    /// Builds the tree: triangles sorted along a Morton (Z-order) curve of their box centres,
    /// then split where the codes' highest differing bit changes (a linear BVH: one sort, then
    /// O(n)); runs of equal codes are halved.
    void build(const std::vector<Vec>& triangles) {
        build(triangles.size() / 3, [&](std::size_t i) {
            Box b;
            for (int k = 0; k < 3; ++k) b.add(triangles[3 * i + k]);
            return b;
        });
    }

    /// The same over n items whose boxes box_of(i) gives.
    template <typename BoxOf>
    void build(std::size_t n, BoxOf&& box_of) {
        nodes.clear();
        order.resize(n);
        if (n == 0) return;
        boxes_.resize(n);
        Box world;
        for (std::size_t i = 0; i < n; ++i) {
            const Box b = box_of(i);
            boxes_[i] = b;
            world.add((b.lo + b.hi) * 0.5);
        }
        const Vec extent = world.hi - world.lo;
        const double size = std::max({extent.x, extent.y, extent.z});
        const double scale = size > 0.0 ? 1023.0 / size : 0.0;
        keyed_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const Vec c = ((boxes_[i].lo + boxes_[i].hi) * 0.5 - world.lo) * scale;
            keyed_[i] = (std::uint64_t{morton(c)} << 32) | i;
        }
        std::sort(keyed_.begin(), keyed_.end());
        for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(keyed_[i]);
        nodes.reserve(2 * n);
        nodes.emplace_back();
        split(0, 0, static_cast<std::uint32_t>(n));
        boxes_.clear();
        boxes_.shrink_to_fit();
        keyed_.clear();
        keyed_.shrink_to_fit();
    }

private:
    static constexpr std::uint32_t kLeafSize = 4;
    std::vector<Box> boxes_;            // per triangle, during the build
    std::vector<std::uint64_t> keyed_;  // Morton code << 32 | triangle, during the build

    /// Spreads the low 10 bits of x to every third bit.
    static std::uint32_t spread(std::uint32_t x) {
        x &= 0x3ff;
        x = (x | (x << 16)) & 0x030000ff;
        x = (x | (x << 8)) & 0x0300f00f;
        x = (x | (x << 4)) & 0x030c30c3;
        x = (x | (x << 2)) & 0x09249249;
        return x;
    }
    static std::uint32_t morton(const Vec& c) {
        auto q = [](double v) { return static_cast<std::uint32_t>(std::clamp(v, 0.0, 1023.0)); };
        return (spread(q(c.x)) << 2) | (spread(q(c.y)) << 1) | spread(q(c.z));
    }

    void split(std::size_t node, std::uint32_t begin, std::uint32_t end) {
        if (end - begin <= kLeafSize) {
            Box box;
            for (std::uint32_t i = begin; i < end; ++i) box.add(boxes_[order[i]]);
            nodes[node].box = box;
            nodes[node].first = begin;
            nodes[node].count = end - begin;
            return;
        }
        const std::uint32_t first_code = static_cast<std::uint32_t>(keyed_[begin] >> 32);
        const std::uint32_t last_code = static_cast<std::uint32_t>(keyed_[end - 1] >> 32);
        std::uint32_t mid = begin + (end - begin) / 2;
        if (first_code != last_code) {
            // The first item whose code has the highest differing bit set.
            int bit = 31;
            while (!(((first_code ^ last_code) >> bit) & 1u)) --bit;
            const std::uint64_t threshold =
                (std::uint64_t{(last_code >> bit) << bit}) << 32;
            mid = static_cast<std::uint32_t>(
                std::lower_bound(keyed_.begin() + begin, keyed_.begin() + end, threshold) -
                keyed_.begin());
        }
        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes[node].first = left;
        nodes[node].count = 0;
        nodes.emplace_back();
        nodes.emplace_back();
        split(left, begin, mid);
        split(left + 1, mid, end);
        Box box = nodes[left].box;
        box.add(nodes[left + 1].box);
        nodes[node].box = box;
    }
};

/// Visits visit(item) for the items in the leaves of `tree` under nodes that skip(node index)
/// does not rule out (skip is asked again at every node: its bound may change as the visits go);
/// stops when visit returns false.
template <typename Skip, typename Visit>
void walk_tree(const Bvh& tree, Skip&& skip, Visit&& visit) {
    if (tree.nodes.empty()) return;
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const std::uint32_t n = stack[--top];
        if (skip(n)) continue;
        const BvhNode& node = tree.nodes[n];
        if (node.count == 0) {
            stack[top++] = node.first;
            stack[top++] = node.first + 1;
            continue;
        }
        for (std::uint32_t item = node.first; item < node.first + node.count; ++item) {
            if (!visit(item)) return;
        }
    }
}

}  // namespace hullkit::route_detail
