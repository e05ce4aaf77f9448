// Bit-for-bit equality of two scenes (-0 and +0 differ), for the tests and the scene fuzzer,
// which require the scene reader's fast path and its tree-only reading to agree.
#pragma once

#include <cstring>
#include <vector>

#include "hullkit/route.hpp"

namespace hullkit_test {

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

inline bool same_mesh_bits(const std::vector<hullkit::TriangleMesh>& a, const std::vector<hullkit::TriangleMesh>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t m = 0; m < a.size(); ++m) {
        if (a[m].name != b[m].name || !same_bytes(a[m].xyz, b[m].xyz) || !same_bytes(a[m].triangles, b[m].triangles)) return false;
    }
    return true;
}

inline bool same_scene_bits(const hullkit::Scene& a, const hullkit::Scene& b) {
    return same_mesh_bits(a.parts, b.parts) && same_mesh_bits(a.obstacles, b.obstacles) && same_bytes(a.route, b.route) &&
           same_bytes(a.rotations, b.rotations) && std::memcmp(a.pivot, b.pivot, sizeof a.pivot) == 0 &&
           std::memcmp(&a.margin, &b.margin, sizeof a.margin) == 0;
}

}  // namespace hullkit_test
