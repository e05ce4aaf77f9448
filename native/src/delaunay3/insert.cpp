// Bowyer-Watson insertion: the incremental construction of the lower 4D hull of the lifted points.
//
// Each point p is located by a walk from the last new tetrahedron (a stochastic visibility walk:
// cross a face that has p strictly on its far side, starting the scan at a varying face, never back
// through the face just crossed). The tetrahedron reached holds p, or is a ghost whose hull face p
// sees; either way it conflicts with p. The cavity, every tetrahedron whose (perturbed) circumsphere
// holds p, is grown from it over faces; it is star-shaped from p, so each of its boundary faces
// joined to p is a positively oriented new tetrahedron. The new tetrahedra take the cavity's slots
// first; their faces through p are paired by the cavity boundary edge they contain (a small hash
// table, cleared after each point).
#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

#include "delaunay3_internal.hpp"
#include "hull/large_array.hpp"

namespace hullkit {
namespace delaunay3_detail {
namespace {

/// The face opposite corner k of a positively oriented tetrahedron, counter-clockwise seen from
/// outside (its normal points away from corner k).
constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

class Inserter {
public:
    explicit Inserter(const Points& points) : points_(points), predicates_(points) {
        const std::size_t expected = 7 * points.size() + 64;  // ~6.7 per point for uniform points
        detail::reserve_large(mesh_.corner, 4 * expected);
        detail::reserve_large(mesh_.adjacent, 4 * expected);
        mark_.reserve(expected);
        resize_table(64);
    }

    /// The first tetrahedron from the first four affinely independent points in insertion order,
    /// its four ghosts, and the order in which the remaining points follow.
    std::vector<std::uint32_t> start() {
        const std::vector<std::uint32_t>& order = points_.order;
        const std::size_t m = order.size();
        std::size_t c = 2;
        while (c < m && collinear3d(predicates_.p(order[0]), predicates_.p(order[1]), predicates_.p(order[c]))) ++c;
        std::size_t d = c + 1;
        while (d < m && predicates_.orient(order[0], order[1], order[c], order[d]) == 0) ++d;
        if (d >= m) throw std::logic_error("delaunay3: the points are coplanar");
        std::uint32_t v[4] = {order[0], order[1], order[c], order[d]};
        if (predicates_.orient(v[0], v[1], v[2], v[3]) < 0) std::swap(v[0], v[1]);
        std::uint32_t corners[5][4];
        std::copy(v, v + 4, corners[0]);
        for (int k = 0; k < 4; ++k) {
            for (int i = 0; i < 3; ++i) corners[k + 1][i] = v[kFace[k][i]];
            corners[k + 1][3] = kGhost;
        }
        // Pair the five tetrahedra's faces by their corner sets (20 faces: a direct search).
        mesh_.corner.resize(20);
        mesh_.adjacent.resize(20);
        mark_.assign(5, 0);
        for (int t = 0; t < 5; ++t) std::copy(corners[t], corners[t] + 4, &mesh_.corner[4 * t]);
        auto face_set = [&](int t, int k) {
            std::array<std::uint32_t, 3> f{};
            for (int i = 0, n = 0; i < 4; ++i)
                if (i != k) f[n++] = corners[t][i];
            std::sort(f.begin(), f.end());
            return f;
        };
        for (int t = 0; t < 5; ++t)
            for (int k = 0; k < 4; ++k)
                for (int u = 0; u < 5; ++u)
                    for (int j = 0; j < 4; ++j)
                        if (u != t && face_set(t, k) == face_set(u, j)) mesh_.adjacent[4 * t + k] = 4 * u + j;
        last_ = 0;
        std::vector<std::uint32_t> rest;
        rest.reserve(m - 4);
        for (std::size_t i = 2; i < m; ++i)
            if (i != c && i != d) rest.push_back(order[i]);
        return rest;
    }

    void insert(std::uint32_t p) {
        const std::uint32_t t0 = walk(p);
        grow_cavity(t0, p);
        fill_cavity();
    }

    Mesh take() { return std::move(mesh_); }

private:
    std::uint32_t next_random() {
        random_ ^= random_ << 13;
        random_ ^= random_ >> 17;
        random_ ^= random_ << 5;
        return random_;
    }

    /// A tetrahedron that conflicts with p: one holding it, or a ghost whose hull face p sees.
    std::uint32_t walk(std::uint32_t p) {
        const std::uint32_t* corner = mesh_.corner.data();
        const std::uint32_t* adjacent = mesh_.adjacent.data();
        std::uint32_t t = last_;
        if (corner[4 * t + 3] == kGhost) t = adjacent[4 * t + 3] >> 2;  // the finite side of its hull face
        std::uint32_t entered = 4;                                     // the face we came in by
        for (;;) {
            const std::uint32_t* c = corner + 4 * t;
            const std::uint32_t first = next_random() & 3u;
            std::uint32_t exit = 4;
            for (std::uint32_t i = 0; i < 4; ++i) {
                const std::uint32_t k = (first + i) & 3u;
                if (k == entered) continue;
                std::uint32_t w[4] = {c[0], c[1], c[2], c[3]};
                w[k] = p;
                if (predicates_.orient(w[0], w[1], w[2], w[3]) < 0) {
                    exit = k;
                    break;
                }
            }
            if (exit == 4) return t;
            const std::uint32_t next = adjacent[4 * t + exit];
            t = next >> 2;
            entered = next & 3u;
            if (corner[4 * t + 3] == kGhost) return t;
        }
    }

    /// Collects the cavity (marked 1) from t0 and its boundary faces, each with the new
    /// tetrahedron's corners (p in place of the corner opposite the face) and the neighbour outside.
    void grow_cavity(std::uint32_t t0, std::uint32_t p) {
        const std::uint32_t* corner = mesh_.corner.data();
        const std::uint32_t* adjacent = mesh_.adjacent.data();
        cavity_.clear();
        checked_.clear();
        boundary_.clear();
        mark_[t0] = 1;
        cavity_.push_back(t0);
        for (std::size_t i = 0; i < cavity_.size(); ++i) {
            const std::uint32_t t = cavity_[i];
            for (std::uint32_t k = 0; k < 4; ++k) {
                const std::uint32_t across = adjacent[4 * t + k];
                const std::uint32_t u = across >> 2;
                if (mark_[u] == 1) continue;
                if (mark_[u] == 0) {
                    if (predicates_.conflict(corner + 4 * u, p)) {
                        mark_[u] = 1;
                        cavity_.push_back(u);
                        continue;
                    }
                    mark_[u] = 2;
                    checked_.push_back(u);
                }
                Boundary b;
                std::memcpy(b.corner, corner + 4 * t, sizeof b.corner);
                b.corner[k] = p;
                b.outside = across;
                b.face = k;
                boundary_.push_back(b);
            }
        }
    }

    /// Replaces the cavity by its boundary faces joined to the point (already in their corners).
    void fill_cavity() {
        const std::size_t count = boundary_.size();
        slots_.clear();
        for (std::size_t i = 0; i < count; ++i) {
            std::uint32_t slot;
            if (i < cavity_.size()) {
                slot = cavity_[i];
            } else if (!free_.empty()) {
                slot = free_.back();
                free_.pop_back();
            } else {
                slot = static_cast<std::uint32_t>(mesh_.size());
                grow(slot + 1);
            }
            slots_.push_back(slot);
        }
        for (std::size_t i = count; i < cavity_.size(); ++i) {  // a cavity with more cells than faces
            mesh_.corner[4 * cavity_[i] + 3] = kFree;
            free_.push_back(cavity_[i]);
        }
        for (const std::uint32_t t : cavity_) mark_[t] = 0;
        for (const std::uint32_t t : checked_) mark_[t] = 0;

        std::uint32_t* corner = mesh_.corner.data();
        std::uint32_t* adjacent = mesh_.adjacent.data();
        if (4 * 3 * count > table_keys_.size()) resize_table(4 * 3 * count);
        const std::size_t mask = table_keys_.size() - 1;
        for (std::size_t i = 0; i < count; ++i) {
            const Boundary& b = boundary_[i];
            const std::uint32_t n = slots_[i];
            std::memcpy(corner + 4 * n, b.corner, sizeof b.corner);
            adjacent[4 * n + b.face] = b.outside;
            adjacent[b.outside] = 4 * n + b.face;
            // Faces j != face contain p and the boundary edge of the other two corners.
            for (std::uint32_t j = 0; j < 4; ++j) {
                if (j == b.face) continue;
                std::uint32_t e0 = 0, e1 = 0;
                bool first = true;
                for (std::uint32_t i2 = 0; i2 < 4; ++i2) {
                    if (i2 == j || i2 == b.face) continue;
                    (first ? e0 : e1) = b.corner[i2];
                    first = false;
                }
                const std::uint64_t key = e0 < e1 ? (std::uint64_t{e0} << 32 | e1) : (std::uint64_t{e1} << 32 | e0);
                std::size_t h = static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> 40) & mask;
                for (;; h = (h + 1) & mask) {
                    if (table_keys_[h] == kEmpty) {
                        table_keys_[h] = key;
                        table_values_[h] = 4 * n + j;
                        used_.push_back(h);
                        break;
                    }
                    if (table_keys_[h] == key) {
                        const std::uint32_t other = table_values_[h];
                        adjacent[4 * n + j] = other;
                        adjacent[other] = 4 * n + j;
                        break;
                    }
                }
            }
        }
        for (const std::size_t h : used_) table_keys_[h] = kEmpty;
        used_.clear();
        last_ = slots_[0];
        for (std::size_t i = 0; i < count; ++i)
            if (boundary_[i].corner[3] != kGhost) {
                last_ = slots_[i];
                break;
            }
    }

    void grow(std::size_t tetrahedra) {
        if (4 * tetrahedra > mesh_.corner.capacity()) {
            // Beyond the estimate (rare: non-uniform inputs): grow by half again.
            const std::size_t room = 4 * (tetrahedra + tetrahedra / 2);
            mesh_.corner.reserve(room);
            mesh_.adjacent.reserve(room);
        }
        mesh_.corner.resize(4 * tetrahedra);
        mesh_.adjacent.resize(4 * tetrahedra);
        mark_.resize(tetrahedra, 0);
    }

    void resize_table(std::size_t at_least) {
        std::size_t size = 64;
        while (size < at_least) size *= 2;
        table_keys_.assign(size, kEmpty);
        table_values_.assign(size, 0);
    }

    struct Boundary {
        std::uint32_t corner[4];
        std::uint32_t outside;
        std::uint32_t face;
    };
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

    const Points& points_;
    Predicates predicates_;
    Mesh mesh_;
    std::vector<std::uint8_t> mark_;  ///< per tetrahedron: 0, 1 in the cavity, 2 checked and not
    std::vector<std::uint32_t> cavity_, checked_, slots_, free_;
    std::vector<Boundary> boundary_;
    std::vector<std::uint64_t> table_keys_;
    std::vector<std::uint32_t> table_values_;
    std::vector<std::size_t> used_;
    std::uint32_t last_ = 0;
    std::uint32_t random_ = 0x9e3779b9u;
};

}  // namespace

Mesh tetrahedralize(const Points& points, unsigned threads,
                    const std::function<void(std::size_t, std::size_t)>& progress) {
    (void)threads;
    Inserter inserter(points);
    const std::vector<std::uint32_t> rest = inserter.start();
    const std::size_t total = points.size();
    for (std::size_t i = 0; i < rest.size(); ++i) {
        inserter.insert(rest[i]);
        if (progress && (i + 5) % 65536 == 0) progress(i + 5, total);
    }
    if (progress) progress(total, total);
    return inserter.take();
}

}  // namespace delaunay3_detail
}  // namespace hullkit
