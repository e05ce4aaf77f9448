// hullkit::delaunay3: input checks, exact duplicates, the Hilbert and insertion orders, the
// dimension, then the tetrahedralization (insert.cpp) written out in the canonical order of
// delaunay3.hpp.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <thread>

#include "delaunay3_internal.hpp"
#include "hull/large_array.hpp"
#include "hull/parallel.hpp"

namespace hullkit {
namespace {

using delaunay3_detail::kGhost;
using delaunay3_detail::Mesh;
using delaunay3_detail::Points;

Delaunay3 failure(std::string message, std::int64_t point = -1) {
    Delaunay3 d;
    d.error = std::move(message);
    d.error_point = point;
    return d;
}

struct Extent {
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    int exponent = 0;  ///< power of two bringing the coordinates into insphere's exact range
};

/// Rejects non-finite coordinates and too many points; finds the bounding box and the scale. The
/// scale leaves a factor of 4 of room below insphere's largest magnitude: the perturbed coplanar
/// test places a point up to 3 times the largest coordinate away (perturbed.cpp).
Delaunay3 check_input(PointSpan points, Extent* extent) {
    if (points.count >= 0x7fffffffu) {
        return failure("too many points: " + std::to_string(points.count) + " (at most 2147483646)");
    }
    double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
    std::size_t largest_at = 0, smallest_at = 0;
    for (int axis = 0; axis < 3; ++axis) {
        extent->lo[axis] = std::numeric_limits<double>::infinity();
        extent->hi[axis] = -std::numeric_limits<double>::infinity();
    }
    for (std::size_t i = 0; i < points.count; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            const double value = points[i][axis];
            const double magnitude = std::fabs(value);
            if (!(magnitude <= std::numeric_limits<double>::max())) {
                const char* what = std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
                return failure("point " + std::to_string(i) + " has a non-finite " + "xyz"[axis] + " coordinate (" +
                                   what + ")",
                               static_cast<std::int64_t>(i));
            }
            if (magnitude > largest) largest = magnitude, largest_at = i;
            if (magnitude != 0.0 && magnitude < smallest) smallest = magnitude, smallest_at = i;
            extent->lo[axis] = std::min(extent->lo[axis], value);
            extent->hi[axis] = std::max(extent->hi[axis], value);
        }
    }
    if (!insphere_scale_exponent(4.0 * largest, smallest, &extent->exponent)) {
        return failure("coordinates span too many orders of magnitude for exact in-sphere tests: point " +
                           std::to_string(smallest_at) + " (smallest nonzero |coordinate|) and point " +
                           std::to_string(largest_at) + " (largest) must be within a factor of 2^313 (about 1e94)",
                       static_cast<std::int64_t>(smallest_at));
    }
    return Delaunay3{};
}

}  // namespace

namespace delaunay3_detail {

bool scale_exponent_of(PointSpan points, int* exponent) {
    double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < 3 * points.count; ++i) {
        const double magnitude = std::fabs(points.xyz[i]);
        if (!(magnitude <= std::numeric_limits<double>::max())) return false;
        largest = std::max(largest, magnitude);
        if (magnitude != 0.0) smallest = std::min(smallest, magnitude);
    }
    *exponent = 0;
    return insphere_scale_exponent(4.0 * largest, smallest, exponent);
}

}  // namespace delaunay3_detail

namespace {

/// Spreads the low 10 bits of v to every third bit.
std::uint32_t spread3(std::uint32_t v) {
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

}  // namespace

namespace delaunay3_detail {

/// Index along a 3D Hilbert curve on a 1024^3 grid (Skilling, "Programming the Hilbert curve",
/// AIP Conf. Proc. 707, 2004: the coordinates turned into the curve's "transpose" by its
/// inverse-undo and Gray-code steps, then interleaved, x's bit most significant).
std::uint32_t hilbert3(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    std::uint32_t axes[3] = {x & 0x3ffu, y & 0x3ffu, z & 0x3ffu};
    for (std::uint32_t q = 1u << 9; q > 1; q >>= 1) {
        const std::uint32_t p = q - 1;
        for (int i = 0; i < 3; ++i) {
            // Bit q of axis i set: invert the low bits of axis 0; else exchange them with axis i's.
            // Without branches (the bits are random: branches mispredicted half the time).
            const std::uint32_t set = 0u - ((axes[i] & q) != 0);
            const std::uint32_t t = (axes[0] ^ axes[i]) & p & ~set;
            axes[0] ^= (p & set) ^ t;
            axes[i] ^= t;
        }
    }
    axes[1] ^= axes[0];
    axes[2] ^= axes[1];
    std::uint32_t t = 0;
    for (std::uint32_t q = 1u << 9; q > 1; q >>= 1)
        if (axes[2] & q) t ^= q - 1;
    for (std::uint32_t& a : axes) a ^= t;
    return spread3(axes[0]) << 2 | spread3(axes[1]) << 1 | spread3(axes[2]);
}

}  // namespace delaunay3_detail

namespace {

}  // namespace

namespace delaunay3_detail {

std::vector<std::uint64_t> hilbert_order(PointSpan p, const double* lo, const double* hi, unsigned threads) {
    const std::size_t n = p.count;
    double scale[3];
    for (int axis = 0; axis < 3; ++axis) {
        const double width = hi[axis] - lo[axis];
        scale[axis] = width > 0 ? 1023.0 / width : 0.0;
    }
    std::vector<std::uint64_t> keyed, swap;  // on huge pages where they are large (large_array.hpp)
    detail::resize_large(keyed, n);
    detail::resize_large(swap, n);
    constexpr std::size_t kBlock = std::size_t{1} << 16;
    detail::parallel_for(threads, (n + kBlock - 1) / kBlock, [&](std::size_t block) {
        for (std::size_t i = block * kBlock; i < std::min(n, (block + 1) * kBlock); ++i) {
            std::uint32_t cell[3];
            for (int axis = 0; axis < 3; ++axis) {
                // A box narrower than 1023 / DBL_MAX makes the scale infinite, one wider than
                // DBL_MAX the width infinite: NaN and negatives go to 0 (the order only affects speed).
                double f = (p[i][axis] - lo[axis]) * scale[axis];
                f = f > 0.0 ? std::min(f, 1023.0) : 0.0;
                cell[axis] = static_cast<std::uint32_t>(f);
            }
            const std::uint32_t key = delaunay3_detail::hilbert3(cell[0], cell[1], cell[2]);
            keyed[i] = (std::uint64_t{key} << 32) | i;
        }
    });
    std::vector<std::uint32_t> count(1025);
    for (int shift = 32; shift < 62; shift += 10) {
        std::fill(count.begin(), count.end(), 0u);
        for (std::size_t i = 0; i < n; ++i) ++count[((keyed[i] >> shift) & 0x3ffu) + 1];
        for (std::size_t d = 0; d < 1024; ++d) count[d + 1] += count[d];
        for (std::size_t k = 0; k < n; ++k) swap[count[(keyed[k] >> shift) & 0x3ffu]++] = keyed[k];
        keyed.swap(swap);
    }
    return keyed;
}

}  // namespace delaunay3_detail

namespace {

/// From the Hilbert order: merges exact duplicates (filling `representative`, `duplicate_count`)
/// and stores the distinct points contiguously in that order, scaled by 2^exponent. On the
/// threads in blocks that start at a new key (duplicates share a key, so each block decides its own
/// alone): first each block sorts its runs of one key and counts its distinct points, then, at
/// offsets from those counts, writes them; the same arrays for every thread count.
void gather_distinct(PointSpan p, const Extent& box, unsigned threads, Delaunay3& out, Points& points) {
    std::vector<std::uint64_t> keyed = delaunay3_detail::hilbert_order(p, box.lo, box.hi, threads);
    const std::size_t n = p.count;
    auto index = [&](std::size_t k) { return static_cast<std::uint32_t>(keyed[k]); };
    auto same_point = [&](std::uint32_t a, std::uint32_t b) {
        return p[a][0] == p[b][0] && p[a][1] == p[b][1] && p[a][2] == p[b][2];
    };
    constexpr std::size_t kBlock = std::size_t{1} << 15;
    const std::size_t blocks = (n + kBlock - 1) / kBlock;
    std::vector<std::size_t> first(blocks + 1, n);
    for (std::size_t b = 0; b < blocks; ++b) {
        std::size_t k = b * kBlock;
        while (k > 0 && k < n && (keyed[k] >> 32) == (keyed[k - 1] >> 32)) ++k;
        first[b] = k;
    }
    std::vector<std::size_t> distinct_before(blocks + 1, 0);
    detail::parallel_for(threads, blocks, [&](std::size_t b) {
        std::size_t distinct = 0;
        for (std::size_t begin = first[b]; begin < first[b + 1];) {
            std::size_t end = begin + 1;
            while (end < n && (keyed[end] >> 32) == (keyed[begin] >> 32)) ++end;
            // Within a run of one key, points sorted by (x, y, z, index) so that duplicates are
            // adjacent and the lowest index comes first; a run of one point needs nothing.
            if (end - begin > 1) {
                std::sort(keyed.begin() + static_cast<std::ptrdiff_t>(begin), keyed.begin() + static_cast<std::ptrdiff_t>(end),
                          [&](std::uint64_t ka, std::uint64_t kb) {
                              const auto a = static_cast<std::uint32_t>(ka), b2 = static_cast<std::uint32_t>(kb);
                              if (p[a][0] != p[b2][0]) return p[a][0] < p[b2][0];
                              if (p[a][1] != p[b2][1]) return p[a][1] < p[b2][1];
                              if (p[a][2] != p[b2][2]) return p[a][2] < p[b2][2];
                              return a < b2;
                          });
                for (std::size_t k = begin; k < end; ++k) distinct += k == begin || !same_point(index(k), index(k - 1));
            } else {
                ++distinct;
            }
            begin = end;
        }
        distinct_before[b + 1] = distinct;
    });
    for (std::size_t b = 0; b < blocks; ++b) distinct_before[b + 1] += distinct_before[b];
    const std::size_t distinct = distinct_before[blocks];
    out.representative.resize(n);
    points.xyz.resize(3 * distinct);
    points.original.resize(distinct);
    // 2^exponent as a factor when it is a double (the product is then exactly ldexp's, rounding
    // included); ldexp beyond.
    const bool factor_ok = box.exponent >= -1022 && box.exponent <= 1023;
    const double factor = factor_ok ? std::ldexp(1.0, box.exponent) : 1.0;
    detail::parallel_for(threads, blocks, [&](std::size_t b) {
        std::size_t d = distinct_before[b];
        for (std::size_t k = first[b]; k < first[b + 1]; ++k) {
            constexpr std::size_t kAhead = 8;  // the points are read in curve order: random places
#if defined(__GNUC__) || defined(__clang__)
            if (k + kAhead < n) __builtin_prefetch(p[index(k + kAhead)]);
#endif
            const std::uint32_t i = index(k);
            const bool repeat = k > first[b] && (keyed[k] >> 32) == (keyed[k - 1] >> 32) && same_point(i, index(k - 1));
            if (repeat) {
                out.representative[i] = points.original[d - 1];
                continue;
            }
            out.representative[i] = i;
            for (int axis = 0; axis < 3; ++axis)
                points.xyz[3 * d + axis] = factor_ok ? p[i][axis] * factor : std::ldexp(p[i][axis], box.exponent);
            points.original[d++] = i;
        }
    });
    out.duplicate_count = n - distinct;
    double span = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = std::ldexp(box.lo[axis], box.exponent), hi = std::ldexp(box.hi[axis], box.exponent);
        span = std::max(span, hi - lo);
    }
    points.span = span;
}

/// The biased randomized insertion order: rounds that shrink eightfold from the last (7/8 of the
/// points) back to a first round of a few hundred, a hash of each point's input index choosing
/// its round (so the order depends only on the input); within a round, Hilbert order. (Rounds that
/// halved made the walks longer: a round's consecutive points were farther apart, measured in the
/// tetrahedra between them; Marot, Pellerin & Remacle's rounds shrink 7.5-fold. 1e6 uniform points:
/// 5 % less time on one thread, 8 % on two.)
void insertion_order(Points& points) {
    const std::size_t m = points.size();
    constexpr int kBits = 3;  // log2 of the ratio of consecutive rounds
    int top = 0;              // rounds above this merge into the first
    while ((m >> (kBits * top + 9)) > 0 && top < 12) ++top;
    std::vector<std::uint8_t> round(m);
    std::vector<std::size_t> count(top + 2, 0);
    for (std::size_t i = 0; i < m; ++i) {
        std::uint64_t h = points.original[i] + 0x9e3779b97f4a7c15ull;  // splitmix64
        h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
        h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
        h ^= h >> 31;
        int level = 0;
        while (level < top && (h >> (64 - kBits * (level + 1)) & ((1u << kBits) - 1)) == 0) ++level;  // 8^-level
        round[i] = static_cast<std::uint8_t>(top - level);  // 0 = inserted first
        ++count[round[i] + 1];
    }
    for (int r = 0; r <= top; ++r) count[r + 1] += count[r];
    points.rounds.assign(count.begin(), count.end());
    points.order.resize(m);
    for (std::size_t i = 0; i < m; ++i) points.order[count[round[i]]++] = static_cast<std::uint32_t>(i);
}

/// The canonical corner order of a positively oriented tetrahedron: the lowest original index
/// first, then the second lowest, the other two in the order that keeps the orientation; as the
/// positions (0-3) of the corners in that order, packed 2 bits each. Tabulated by the corners'
/// ranks (which corner is lowest, second, third), since this runs once per tetrahedron.
struct RotationTable {
    std::uint8_t by_ranks[256];  ///< [rank of corner 0 | rank of corner 1 << 2 | ... << 6]
};
constexpr RotationTable make_rotation_table() {
    RotationTable table{};
    for (int code = 0; code < 256; ++code) {
        int at[4] = {-1, -1, -1, -1};
        bool permutation = true;
        for (int i = 0; i < 4; ++i) {
            const int rank = (code >> (2 * i)) & 3;
            if (at[rank] != -1) permutation = false;
            at[rank] = i;
        }
        if (!permutation) continue;
        int second = at[2], third = at[3];
        if (second > third) {
            const int swap = second;
            second = third;
            third = swap;
        }
        at[2] = second;
        at[3] = third;
        int inversions = 0;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) inversions += at[i] > at[j];
        if (inversions & 1) {
            at[2] = third;
            at[3] = second;
        }
        table.by_ranks[code] = static_cast<std::uint8_t>(at[0] | at[1] << 2 | at[2] << 4 | at[3] << 6);
    }
    return table;
}
constexpr RotationTable kRotations = make_rotation_table();

std::uint8_t canonical_rotation(const std::uint32_t* original_of_corner) {
    const std::uint32_t* o = original_of_corner;
    const int r0 = (o[1] < o[0]) + (o[2] < o[0]) + (o[3] < o[0]);
    const int r1 = (o[0] < o[1]) + (o[2] < o[1]) + (o[3] < o[1]);
    const int r2 = (o[0] < o[2]) + (o[1] < o[2]) + (o[3] < o[2]);
    const int r3 = 6 - r0 - r1 - r2;
    return kRotations.by_ranks[r0 | r1 << 2 | r2 << 4 | r3 << 6];
}

/// The number of bits set (SWAR: a library call on x86-64 without -mpopcnt otherwise).
inline std::uint32_t ones(std::uint64_t v) {
    v = v - ((v >> 1) & 0x5555555555555555ull);
    v = (v & 0x3333333333333333ull) + ((v >> 2) & 0x3333333333333333ull);
    v = (v + (v >> 4)) & 0x0f0f0f0f0f0f0f0full;
    return static_cast<std::uint32_t>((v * 0x0101010101010101ull) >> 56);
}

/// Rewrites the kept rows among slots [from, to) where they are (kept[t / 64] has bit t % 64 set;
/// before[b]: the kept slots before block b of 64): the corners as original indices in canonical
/// order, the links as the neighbours' positions among the kept slots (-1 across the hull). Two
/// versions on x86-64, as grow_cavity: the AVX2 one counts the bits with POPCNT (every AVX2
/// machine has it; the baseline's is a library call).
HULLKIT_AVX2_CLONE void rewrite_rows(std::uint32_t* words, std::size_t from, std::size_t to,
                                     const std::uint32_t* original, const std::uint64_t* kept,
                                     const std::uint32_t* before) {
    using delaunay3_detail::kRow;
    constexpr std::uint32_t kNone = 0xffffffffu;
    auto position = [&](std::uint32_t t) -> std::uint32_t {
        const std::uint64_t word = kept[t >> 6], bit = std::uint64_t{1} << (t & 63);
        if (!(word & bit)) return kNone;
        return before[t >> 6] + static_cast<std::uint32_t>(__builtin_popcountll(word & (bit - 1)));
    };
    for (std::size_t t = from; t < to; ++t) {
        if (!((kept[t >> 6] >> (t & 63)) & 1u)) continue;
        std::uint32_t* row = words + kRow * t;
        const std::uint32_t orig[4] = {original[row[0]], original[row[1]], original[row[2]], original[row[3]]};
        const std::uint32_t r = canonical_rotation(orig);
        std::uint32_t n[4];
        for (int j = 0; j < 4; ++j) n[j] = position(row[4 + ((r >> (2 * j)) & 3u)] >> 3);
        for (int j = 0; j < 4; ++j) row[j] = orig[(r >> (2 * j)) & 3u];
        std::copy(n, n + 4, row + 4);
    }
}

/// Writes the tetrahedra into the mesh's own arrays and moves them into `out` (the output costs no
/// second copy of the mesh): the finite tetrahedra in slot order (the insertion's order, the same
/// for every thread count), each row rewritten as original indices in canonical corner order and
/// its neighbours' new positions; the hull triangles from the ghosts.
void write_tetrahedra(Mesh& mesh, Points& points, unsigned threads, Delaunay3& out) {
    using delaunay3_detail::kRow;
    const std::size_t slots = mesh.size();
    std::uint32_t* words = mesh.data();
    const std::uint32_t* original = points.original.data();
    points.xyz = detail::LargeArray<double>();  // the coordinates are not needed any more: room for the rest
    // Each slot's new position, as a bit per slot (kept or not) and the count of kept slots before
    // each block of 64: 0.56 bytes a slot instead of 4, and small enough to stay in the caches for
    // the random lookups of the neighbours' positions.
    const std::size_t blocks = (slots + 63) / 64;
    std::vector<std::uint64_t> kept(blocks, 0);
    std::vector<std::uint32_t> before(blocks + 1, 0);
    // On the threads in chunks of kRows slots (whole words of `kept`), each collecting its ghosts'
    // hull faces (sorted together afterwards).
    constexpr std::size_t kRows = std::size_t{1} << 16;
    const std::size_t chunks = (slots + kRows - 1) / kRows;
    std::vector<std::vector<std::array<std::uint32_t, 3>>> faces(chunks);
    detail::parallel_for(threads, chunks, [&](std::size_t chunk) {
        for (std::size_t t = chunk * kRows; t < std::min(slots, (chunk + 1) * kRows); ++t) {
            const std::uint32_t* c = words + kRow * t;
            if (c[3] < delaunay3_detail::kFree) kept[t >> 6] |= std::uint64_t{1} << (t & 63);
            if (c[3] == kGhost) {
                std::array<std::uint32_t, 3> f = {original[c[0]], original[c[1]], original[c[2]]};
                std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
                faces[chunk].push_back(f);
            }
        }
    });
    std::vector<std::array<std::uint32_t, 3>> hull;
    for (const auto& list : faces) hull.insert(hull.end(), list.begin(), list.end());
    for (std::size_t b = 0; b < blocks; ++b) before[b + 1] = before[b] + ones(kept[b]);
    const std::uint32_t finite = before[blocks];
    std::sort(hull.begin(), hull.end());
    out.hull.reserve(3 * hull.size());
    for (const auto& f : hull) out.hull.insert(out.hull.end(), f.begin(), f.end());
    auto is_kept = [&](std::size_t t) { return (kept[t >> 6] >> (t & 63)) & 1u; };
    auto rewrite = [&](std::size_t from, std::size_t to) {
        rewrite_rows(words, from, to, original, kept.data(), before.data());
    };
    // On more threads, first every kept row rewritten where it is (a row reads only itself and the
    // shared positions); on one, a step at a time in the pass below.
    constexpr std::size_t kStep = std::size_t{1} << 14;  // slots
    const bool rewritten = detail::resolve_threads(threads) > 1;
    if (rewritten) {
        detail::parallel_for(threads, chunks, [&](std::size_t block) {
            rewrite(block * kRows, std::min(slots, (block + 1) * kRows));
        });
    }
    // Then, in slot order, the corners appended to the tetrahedra and the links moved down to the
    // front of the mesh's own array (position(t) <= t: the front is read before it is written),
    // which becomes the neighbours. The pages between the two fronts, read and not yet written,
    // are given back as the pass goes, so the memory peaks no higher than the mesh.
    std::vector<std::uint32_t>& tetrahedra = out.tetrahedra;
    detail::reserve_large(tetrahedra, 4 * std::size_t{finite});
    constexpr std::size_t kReleaseEvery = std::size_t{1} << 20;  // words (4 MiB: whole huge pages)
    // Corners appended to the tetrahedra (grown a chunk at a time: their pages are touched as they
    // are filled).
    std::size_t corners_front = 0;
    auto append = [&](const std::uint32_t* corners) {
        if (corners_front == tetrahedra.size())
            tetrahedra.resize(std::min(4 * std::size_t{finite}, corners_front + kReleaseEvery));
        std::copy(corners, corners + 4, tetrahedra.data() + corners_front);
        corners_front += 4;
    };
    auto append_corners = [&](std::size_t from, std::size_t to) {
        for (std::size_t t = from; t < to; ++t)
            if (is_kept(t)) append(words + kRow * t);
    };
    // The links of the kept slots in [from, to) moved down (after their corners are appended), and
    // the pages read behind them given back. (The front is at most 4 t, before row t's links.)
    std::size_t front = 0;     // words of neighbours written (4 per tetrahedron so far)
    std::size_t released = 0;  // the pages between the fronts are given back up to here
    auto move_links = [&](std::size_t from, std::size_t to) {
        for (std::size_t t = from; t < to; ++t) {
            if (is_kept(t)) {
                std::copy(words + kRow * t + 4, words + kRow * (t + 1), words + front);
                front += 4;
            }
            const std::size_t read = kRow * (t + 1), behind = std::max(front, released);
            if (read >= behind + kReleaseEvery || t + 1 == slots) {
                released = static_cast<std::size_t>(
                    static_cast<std::uint32_t*>(detail::release_pages(words + behind, words + read)) - words);
            }
        }
    };
    if (!rewritten) {
        for (std::size_t from = 0; from < slots; from += kStep) {
            const std::size_t to = std::min(slots, from + kStep);
            rewrite(from, to);
            append_corners(from, to);
            move_links(from, to);
        }
    } else {
        // Two tasks at once: one appends the corners (the tetrahedra's fresh pages are mapped on
        // its thread), the other moves the links behind it, never past the slots whose corners
        // are appended (the rows it overwrites and the pages it gives back are read by then). Once
        // the second has started, the first keeps at most kAhead slots ahead of it (the pages the
        // first maps and the second has not given back yet: the memory's peak); before that it
        // does not wait, so one thread also finishes both, one after the other. (Neither can
        // throw and leave the other waiting: the tetrahedra's room is reserved whole above.)
        constexpr std::size_t kAhead = 4 * kStep;  // slots
        std::atomic<std::size_t> appended{0}, moved{0};
        std::atomic<bool> moving{false};
        detail::parallel_for(threads, 2, [&](std::size_t task) {
            if (task == 1) moving.store(true, std::memory_order_release);
            for (std::size_t from = 0; from < slots; from += kStep) {
                const std::size_t to = std::min(slots, from + kStep);
                if (task == 0) {
                    while (moving.load(std::memory_order_acquire) && moved.load(std::memory_order_acquire) + kAhead < to)
                        std::this_thread::yield();
                    append_corners(from, to);
                    appended.store(to, std::memory_order_release);
                } else {
                    while (appended.load(std::memory_order_acquire) < to) std::this_thread::yield();
                    move_links(from, to);
                    moved.store(to, std::memory_order_release);
                }
            }
        });
    }
    mesh.words.resize(4 * std::size_t{finite});
    out.neighbors = std::move(mesh.words);
}

/// Coplanar points: their Delaunay triangulation in the plane is the restriction of the 3D one of
/// the points and one more point q off the plane (the hull face on the plane is a face of the
/// Delaunay subdivision, and the spheres through a triangle and q meet the plane in its
/// circumcircle; q's own perturbation term vanishes for points on the plane). q goes on the side
/// the hull's polygon is counter-clockwise from (the side `normal` points to, as hull() decides
/// it), so the tetrahedra's faces opposite q are the triangles, counter-clockwise from there.
void planar_triangles(PointSpan input, Points& points, const Delaunay3Options& options, Delaunay3& out) {
    const Hull polygon = hull(input, HullOptions{});
    std::copy(polygon.normal, polygon.normal + 3, out.normal);
    const std::size_t m = points.size();
    std::uint32_t corner[3] = {0, 0, 0};  // three consecutive corners of the polygon, as local indices
    for (int k = 0; k < 3; ++k)
        corner[k] = static_cast<std::uint32_t>(std::find(points.original.begin(), points.original.end(),
                                                         polygon.vertices[k]) - points.original.begin());
    const double* a = points[corner[0]];
    const double* b = points[corner[1]];
    const double* c = points[corner[2]];
    const double n[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                         (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                         (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    int axes[3] = {0, 1, 2};
    std::stable_sort(axes, axes + 3, [&](int i, int j) { return std::fabs(n[i]) > std::fabs(n[j]); });
    double q[3] = {a[0], a[1], a[2]};
    for (const int k : axes) {  // orient3d(a, b, c, q) = n_k (q_k - a_k) > 0, exactly
        const int sign = orient2d(a[(k + 1) % 3], a[(k + 2) % 3], b[(k + 1) % 3], b[(k + 2) % 3], c[(k + 1) % 3],
                                  c[(k + 2) % 3]);
        if (sign == 0) continue;
        const double move = std::max(points.span, std::fabs(a[k]));
        q[k] = a[k] + (sign > 0 ? move : -move);
        break;
    }
    const std::uint32_t extra = static_cast<std::uint32_t>(m);
    points.xyz.insert(points.xyz.end(), q, q + 3);
    points.original.push_back(kGhost);
    points.order.insert(points.order.begin(), extra);  // q first: it is in the first tetrahedron
    for (std::size_t r = 1; r < points.rounds.size(); ++r) ++points.rounds[r];
    Mesh mesh = delaunay3_detail::tetrahedralize(points, options.threads, options.progress, options.furthest_site);

    const std::size_t slots = mesh.size();
    constexpr std::uint32_t kNone = 0xffffffffu;
    std::vector<std::uint32_t> position(slots, kNone);
    std::uint32_t count = 0;
    for (std::size_t t = 0; t < slots; ++t) {
        const std::uint32_t* w = mesh.corners(t);
        if (w[3] < delaunay3_detail::kFree && std::find(w, w + 4, extra) != w + 4) position[t] = count++;
    }
    out.triangles.resize(3 * std::size_t{count});
    out.neighbors.resize(3 * std::size_t{count});
    for (std::size_t t = 0; t < slots; ++t) {
        if (position[t] == kNone) continue;
        const std::uint32_t* w = mesh.corners(t);
        const int k = static_cast<int>(std::find(w, w + 4, extra) - w);
        // The face opposite q turned towards q; the triangle's corner j is tetrahedron corner at[j],
        // and the edge opposite it lies in the face opposite that corner.
        const int at[3] = {delaunay3_detail::kFaceCorners[k][0], delaunay3_detail::kFaceCorners[k][2],
                           delaunay3_detail::kFaceCorners[k][1]};
        int first = 0;
        for (int j = 1; j < 3; ++j)
            if (points.original[w[at[j]]] < points.original[w[at[first]]]) first = j;
        const std::size_t q3 = 3 * std::size_t{position[t]};
        for (int j = 0; j < 3; ++j) {
            const int corner_at = at[(first + j) % 3];
            out.triangles[q3 + j] = points.original[w[corner_at]];
            const std::uint32_t across = position[w[4 + corner_at] >> 3];
            out.neighbors[q3 + j] = across == kNone ? -1 : static_cast<std::int32_t>(across);
        }
    }
}

/// Furthest-site: keeps only the distinct points that are vertices of the input's convex hull (its
/// extreme points, exactly), in the same (Hilbert) order. Only they have furthest-site cells: a
/// point inside the hull, or inside one of its faces or edges, is in no tetrahedron.
void keep_extreme_points(PointSpan input, unsigned threads, Points& points) {
    HullOptions hull_options;
    hull_options.threads = threads;
    const Hull h = hull(input, hull_options);
    std::vector<std::uint8_t> extreme(input.count, 0);
    for (const std::uint32_t v : h.vertices) extreme[v] = 1;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!extreme[points.original[i]]) continue;
        std::copy(points[i], points[i] + 3, points.xyz.begin() + static_cast<std::ptrdiff_t>(3 * kept));
        points.original[kept++] = points.original[i];
    }
    points.xyz.resize(3 * kept);
    points.original.resize(kept);
}

}  // namespace

Delaunay3 delaunay3(PointSpan input, const Delaunay3Options& options) {
    Extent extent;
    Delaunay3 out = check_input(input, &extent);
    if (!out.ok()) return out;
    out.furthest_site = options.furthest_site;
    Points points;
    gather_distinct(input, extent, options.threads, out, points);
    const std::size_t m = points.size();
    if (m == 0) {
        out.dimension = -1;
        return out;
    }
    if (m == 1) {
        out.dimension = 0;
        out.vertices.assign(points.original.begin(), points.original.end());
        return out;
    }
    std::size_t c = 2;
    while (c < m && collinear3d(points[0], points[1], points[c])) ++c;
    if (c == m) {  // collinear: the lexicographic order is the order along the line
        out.dimension = 1;
        std::vector<std::uint32_t> along(m);
        std::iota(along.begin(), along.end(), 0u);
        std::sort(along.begin(), along.end(), [&](std::uint32_t a, std::uint32_t b) {
            return delaunay3_detail::lexicographically_less(points[a], points[b]);
        });
        for (std::uint32_t i : along) out.vertices.push_back(points.original[i]);
        if (options.furthest_site) out.vertices = {out.vertices.front(), out.vertices.back()};
        return out;
    }
    std::size_t d = 0;
    while (d < m && orient3d(points[0], points[1], points[c], points[d]) == 0) ++d;
    if (options.furthest_site) keep_extreme_points(input, options.threads, points);
    insertion_order(points);
    try {
        if (d == m) {
            out.dimension = 2;
            planar_triangles(input, points, options, out);
            return out;
        }
        out.dimension = 3;
        Mesh mesh = delaunay3_detail::tetrahedralize(points, options.threads, options.progress, options.furthest_site);
        write_tetrahedra(mesh, points, options.threads, out);
    } catch (const std::bad_alloc&) {
        return failure("out of memory tetrahedralizing " + std::to_string(m) + " points");
    } catch (const std::length_error&) {
        return failure("too many tetrahedra for " + std::to_string(m) + " points (at most 2^29)");
    }
    return out;
}

}  // namespace hullkit
