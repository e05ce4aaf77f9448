// Planar faces from the triangles of a convex surface.
#include <algorithm>
#include <utility>
#include <numeric>

#include "hull_internal.hpp"
#include "parallel.hpp"
#include "hullkit/predicates.hpp"
#include "planar.hpp"
#include "sides.hpp"

namespace hullkit::detail {
namespace {

class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
    std::uint32_t find(std::uint32_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }

private:
    std::vector<std::uint32_t> parent_;
};

}  // namespace

Polygons merge_coplanar_triangles(PointSpan points, LargeArray<std::uint32_t> triangles,
                                  const std::vector<CoplanarPair>& coplanar) {
    const std::size_t count = triangles.size() / 3;
    Polygons faces;
    faces.offsets.resize(count + 1);
    for (std::size_t t = 0; t <= count; ++t) faces.offsets[t] = static_cast<std::uint32_t>(3 * t);
    if (coplanar.empty()) {  // every triangle is a face of its own: the common case
        faces.vertices = std::move(triangles);
        return faces;
    }
    faces.offsets.assign(1, 0);
    faces.vertices.reserve(triangles.size());

    DisjointSets sets(count);
    for (const CoplanarPair& pair : coplanar) sets.unite(pair.first, pair.second);
    // Triangles grouped by face (the group's lowest triangle index names it), in triangle order.
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    std::vector<std::uint32_t> root(count);
    for (std::uint32_t t = 0; t < count; ++t) root[t] = sets.find(t);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return root[a] < root[b]; });

    const ExactSides sides;
    std::vector<std::uint32_t> members, polygon;
    for (std::size_t begin = 0; begin < count;) {
        std::size_t end = begin + 1;
        while (end < count && root[order[end]] == root[order[begin]]) ++end;
        const std::uint32_t first = order[begin];
        if (end - begin == 1) {
            faces.add(&triangles[3 * first], &triangles[3 * first] + 3);
        } else {
            members.clear();
            for (std::size_t g = begin; g < end; ++g)
                members.insert(members.end(), &triangles[3 * order[g]], &triangles[3 * order[g]] + 3);
            std::sort(members.begin(), members.end());
            members.erase(std::unique(members.begin(), members.end()), members.end());
            const std::uint32_t* abc = &triangles[3 * first];
            convex_polygon(points, sides, members, abc[0], abc[1], abc[2], polygon);
            faces.add(polygon.begin(), polygon.end());
        }
        begin = end;
    }
    return faces;
}

void measure(PointSpan points, const Polygons& faces, double* volume, double* area, unsigned threads) {
    // Tetrahedra from one corner to every fan triangle: faces through that corner add zero, and by
    // convexity no tetrahedron has a negative volume, so a rounded one below zero counts as zero.
    // Summed per block of faces, the blocks' sums then added in order: the same bits for every
    // thread count.
    const glm::dvec3 origin = faces.vertices.empty() ? glm::dvec3(0.0) : vec3(points[faces.vertices.front()]);
    constexpr std::size_t kBlock = 4096;
    const std::size_t blocks = (faces.size() + kBlock - 1) / kBlock;
    std::vector<double> six_volume(blocks, 0.0), twice_area(blocks, 0.0);
    parallel_for(threads, blocks, [&](std::size_t block) {
        double v = 0.0, s = 0.0;
        const std::size_t end = std::min(faces.size(), (block + 1) * kBlock);
        for (std::size_t f = block * kBlock; f < end; ++f) {
            const std::uint32_t* corners = &faces.vertices[faces.offsets[f]];
            const std::size_t m = faces.offsets[f + 1] - faces.offsets[f];
            const glm::dvec3 a = vec3(points[corners[0]]) - origin;
            for (std::size_t k = 1; k + 1 < m; ++k) {
                const glm::dvec3 b = vec3(points[corners[k]]) - origin;
                const glm::dvec3 c = vec3(points[corners[k + 1]]) - origin;
                v += std::max(0.0, glm::dot(a, glm::cross(b, c)));
                s += glm::length(glm::cross(b - a, c - a));
            }
        }
        six_volume[block] = v;
        twice_area[block] = s;
    });
    double v = 0.0, s = 0.0;
    for (std::size_t block = 0; block < blocks; ++block) v += six_volume[block], s += twice_area[block];
    *volume = v / 6.0;
    *area = s / 2.0;
}

}  // namespace hullkit::detail

namespace hullkit::detail {

void canonical_order(Polygons& faces, const std::vector<std::uint32_t>& original, unsigned threads) {
    const std::size_t count = faces.size();
    auto id = [&](std::uint32_t v) { return original.empty() ? v : original[v]; };
    // Rotate each polygon to its lowest index; its key is (first, second) corner, unique because
    // each directed edge of a closed surface belongs to one face.
    struct Keyed {
        std::uint64_t key;
        std::uint32_t begin, size;  // where the polygon's corners are in faces.vertices, and how many
    };
    LargeArray<Keyed> keyed(count);
    constexpr std::size_t kBlock = std::size_t{1} << 16;
    const std::size_t blocks = (count + kBlock - 1) / kBlock;
    std::vector<std::uint64_t> block_bits(blocks, 0);
    parallel_for(threads, blocks, [&](std::size_t block) {
        const std::size_t end = std::min(count, (block + 1) * kBlock);
        for (std::size_t f = block * kBlock; f < end; ++f) {
            const auto first = faces.vertices.begin() + faces.offsets[f];
            const auto last = faces.vertices.begin() + faces.offsets[f + 1];
            auto lowest = first;
            for (auto it = first + 1; it != last; ++it) {
                if (id(*it) < id(*lowest)) lowest = it;
            }
            std::rotate(first, lowest, last);
            keyed[f] = {std::uint64_t{id(first[0])} << 32 | id(first[1]), faces.offsets[f],
                        faces.offsets[f + 1] - faces.offsets[f]};
            block_bits[block] |= keyed[f].key;
        }
    });
    std::uint64_t all_bits = 0;
    for (std::uint64_t bits : block_bits) all_bits |= bits;
    const std::uint64_t first_ids = (all_bits >> 32) + 1;  // a bound on the first corners' ids
    if (count >= 512 && first_ids <= 4 * std::uint64_t{count}) {
        // Dense ids (a hull with most points as vertices, a sphere): counting sort by the first
        // corner, then each group (the faces starting at one vertex: a few) by the second. Keys
        // are unique, so the result is the same however the work is split: each of a few chunks
        // of faces counts its first corners, and scatters into the slots the chunk-major prefix
        // sums give it; the groups are then sorted in ranges of first corners.
        const std::size_t ids = static_cast<std::size_t>(first_ids);
        const std::size_t chunks = std::min<std::size_t>(resolve_threads(threads, count / kBlock), 8);
        LargeArray<std::uint32_t> start(chunks * ids, 0);  // chunk c's counts, then slots, at c * ids
        parallel_for(threads, chunks, [&](std::size_t c) {
            std::uint32_t* counts = &start[c * ids];
            for (std::size_t f = count * c / chunks; f < count * (c + 1) / chunks; ++f) ++counts[keyed[f].key >> 32];
        });
        LargeArray<std::uint32_t> group(ids + 1);  // where the faces starting at each id begin
        std::uint32_t sum = 0;
        for (std::size_t v = 0; v < ids; ++v) {
            group[v] = sum;
            for (std::size_t c = 0; c < chunks; ++c) sum += std::exchange(start[c * ids + v], sum);
        }
        group[ids] = sum;
        LargeArray<Keyed> buffer(count);
        parallel_for(threads, chunks, [&](std::size_t c) {
            std::uint32_t* next = &start[c * ids];
            for (std::size_t f = count * c / chunks; f < count * (c + 1) / chunks; ++f) buffer[next[keyed[f].key >> 32]++] = keyed[f];
        });
        constexpr std::size_t kIdsPerTask = std::size_t{1} << 16;
        parallel_for(threads, (ids + kIdsPerTask - 1) / kIdsPerTask, [&](std::size_t task) {
            const std::size_t last = std::min(ids, (task + 1) * kIdsPerTask);
            for (std::size_t v = task * kIdsPerTask; v < last; ++v) {
                const std::size_t begin = group[v], end = group[v + 1];
                for (std::size_t i = begin + 1; i < end; ++i) {  // insertion sort of a handful
                    const Keyed k = buffer[i];
                    std::size_t j = i;
                    for (; j > begin && buffer[j - 1].key > k.key; --j) buffer[j] = buffer[j - 1];
                    buffer[j] = k;
                }
            }
        });
        keyed.swap(buffer);
    } else if (count < 512) {
        std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) { return a.key < b.key; });
    } else {
        // LSD radix sort, 11-bit digits, skipping digits no key uses (indices are usually far
        // below 2^32, so most of the high digits of both halves are zero). Each pass counts and
        // scatters per block of keys on threads; stable, so the order is the same for any split.
        constexpr int kDigits = 2048;
        LargeArray<Keyed> buffer(count);
        std::vector<std::size_t> start(blocks * kDigits);
        for (int shift = 0; shift < 64; shift += 11) {
            if (((all_bits >> shift) & (kDigits - 1)) == 0) continue;
            std::fill(start.begin(), start.end(), 0);
            parallel_for(threads, blocks, [&](std::size_t block) {
                std::size_t* counts = &start[block * kDigits];
                const std::size_t end = std::min(count, (block + 1) * kBlock);
                for (std::size_t k = block * kBlock; k < end; ++k) ++counts[(keyed[k].key >> shift) & (kDigits - 1)];
            });
            std::size_t sum = 0;  // digit-major, then block: where each block's keys of a digit go
            for (int d = 0; d < kDigits; ++d) {
                for (std::size_t block = 0; block < blocks; ++block) sum += std::exchange(start[block * kDigits + d], sum);
            }
            parallel_for(threads, blocks, [&](std::size_t block) {
                std::size_t* next = &start[block * kDigits];
                const std::size_t end = std::min(count, (block + 1) * kBlock);
                for (std::size_t k = block * kBlock; k < end; ++k) buffer[next[(keyed[k].key >> shift) & (kDigits - 1)]++] = keyed[k];
            });
            keyed.swap(buffer);
        }
    }
    // The new offsets from the sizes alone (sequential reads); unchanged order: nothing to move.
    Polygons ordered;
    ordered.offsets.resize(count + 1);
    ordered.offsets[0] = 0;
    bool sorted = true;
    for (std::size_t f = 0; f < count; ++f) {
        sorted = sorted && keyed[f].begin == ordered.offsets[f];
        ordered.offsets[f + 1] = ordered.offsets[f] + keyed[f].size;
    }
    if (sorted) return;
    ordered.vertices.resize(faces.vertices.size());
    parallel_for(threads, blocks, [&](std::size_t block) {
        const std::size_t end = std::min(count, (block + 1) * kBlock);
        for (std::size_t f = block * kBlock; f < end; ++f) {
            const auto from = faces.vertices.begin() + keyed[f].begin;
            std::copy(from, from + keyed[f].size, ordered.vertices.begin() + ordered.offsets[f]);
        }
    });
    faces = std::move(ordered);
}

}  // namespace hullkit::detail
