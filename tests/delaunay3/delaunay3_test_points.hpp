// Inputs and comparisons the 3D Delaunay tests share: integer grids, shuffled copies of a cloud and
// the set of tetrahedra (corners sorted, optionally relabelled back to the original indices).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "hullkit/delaunay3.hpp"

namespace hullkit_test {

using Tet = std::array<std::uint32_t, 4>;

/// The integer grid {0..n-1}^3, x slowest.
inline std::vector<double> grid3(int n) {
    std::vector<double> xyz;
    for (int x = 0; x < n; ++x)
        for (int y = 0; y < n; ++y)
            for (int z = 0; z < n; ++z) xyz.insert(xyz.end(), {double(x), double(y), double(z)});
    return xyz;
}

/// n points in `clusters` Gaussian clusters (standard deviation `sigma`) around centres uniform in
/// the unit cube: large rounds of these leave enough points along the first pass's partition
/// boundaries for the later (slab) passes of the threaded insertion to run.
inline std::vector<double> clustered3(std::size_t n, int clusters, double sigma, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    std::normal_distribution<double> normal(0, sigma);
    std::vector<double> centres(3 * static_cast<std::size_t>(clusters));
    for (double& c : centres) c = unit(rng);
    std::vector<double> xyz(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t c = static_cast<std::size_t>(unit(rng) * clusters) % static_cast<std::size_t>(clusters);
        for (int k = 0; k < 3; ++k) xyz[3 * i + k] = centres[3 * c + k] + normal(rng);
    }
    return xyz;
}

/// The points of `xyz` in a random order: point i of the result is point perm[i] of `xyz`.
inline std::vector<double> shuffled3(const std::vector<double>& xyz, std::vector<std::uint32_t>& perm, std::uint64_t seed) {
    perm.resize(xyz.size() / 3);
    std::iota(perm.begin(), perm.end(), 0u);
    std::mt19937_64 rng(seed);
    std::shuffle(perm.begin(), perm.end(), rng);
    std::vector<double> out(xyz.size());
    for (std::size_t i = 0; i < perm.size(); ++i)
        for (int k = 0; k < 3; ++k) out[3 * i + k] = xyz[3 * perm[i] + k];
    return out;
}

/// The tetrahedra as sorted corner quadruples, each corner relabelled[corner] when given.
inline std::set<Tet> tetrahedron_set(const hullkit::Delaunay3& d, const std::vector<std::uint32_t>* relabel = nullptr) {
    std::set<Tet> out;
    for (std::size_t t = 0; t < d.tetrahedron_count(); ++t) {
        Tet v;
        for (int k = 0; k < 4; ++k) v[k] = relabel ? (*relabel)[d.tetrahedra[4 * t + k]] : d.tetrahedra[4 * t + k];
        std::sort(v.begin(), v.end());
        out.insert(v);
    }
    return out;
}

}  // namespace hullkit_test
