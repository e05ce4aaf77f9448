// Private to the route module: an axis-aligned bounding-box tree over triangles, in flat arrays.
//
// Built once by median splits on the triangles' centroids along the widest axis (O(n log n) with
// nth_element); node i is internal when count == 0, its children are `first` and `first + 1`;
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

    void build(const std::vector<Vec>& triangles) {
        const std::size_t n = triangles.size() / 3;
        nodes.clear();
        order.resize(n);
        if (n == 0) return;
        std::vector<Box> boxes(n);
        std::vector<Vec> centroids(n);
        for (std::size_t i = 0; i < n; ++i) {
            for (int k = 0; k < 3; ++k) boxes[i].add(triangles[3 * i + k]);
            centroids[i] = (boxes[i].lo + boxes[i].hi) * 0.5;
            order[i] = static_cast<std::uint32_t>(i);
        }
        nodes.reserve(2 * n);
        nodes.emplace_back();
        split(0, 0, static_cast<std::uint32_t>(n), boxes, centroids);
    }

private:
    static constexpr std::uint32_t kLeafSize = 4;

    void split(std::size_t node, std::uint32_t begin, std::uint32_t end,
               const std::vector<Box>& boxes, const std::vector<Vec>& centroids) {
        Box box, spread;
        for (std::uint32_t i = begin; i < end; ++i) {
            box.add(boxes[order[i]]);
            spread.add(centroids[order[i]]);
        }
        nodes[node].box = box;
        if (end - begin <= kLeafSize) {
            nodes[node].first = begin;
            nodes[node].count = end - begin;
            return;
        }
        const Vec extent = spread.hi - spread.lo;
        const int axis = extent.x >= extent.y ? (extent.x >= extent.z ? 0 : 2)
                                              : (extent.y >= extent.z ? 1 : 2);
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             return centroids[a][axis] < centroids[b][axis];
                         });
        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes[node].first = left;
        nodes[node].count = 0;
        nodes.emplace_back();
        nodes.emplace_back();
        split(left, begin, mid, boxes, centroids);
        split(left + 1, mid, end, boxes, centroids);
    }
};

}  // namespace hullkit::route_detail
