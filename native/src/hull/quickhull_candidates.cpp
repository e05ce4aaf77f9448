// Quickhull's input (see quickhull.cpp): the interior culling, the Morton keys and the spatial
// order of the candidates.
//
// Before the main loop: points certified to lie strictly inside the hull of a few extreme points
// (a box inside that hull, then its planes, each decided exactly) are dropped in one pass on the
// threads, which also gives each survivor its space-filling-curve (Morton) key; repeats of a
// point are dropped (the lowest index stays), and the rest are copied in Morton order, so that
// the points above one face sit close in memory.
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "hull_internal.hpp"
#include "large_array.hpp"
#include "parallel.hpp"
#include "quickhull_internal.hpp"

namespace hullkit::detail {
namespace quickhull_detail {
namespace {

/// Spreads the low 10 bits of v to every third bit.
std::uint32_t spread_bits(std::uint32_t v) {
    v &= 0x3ff;
    v = (v | (v << 16)) & 0x030000ff;
    v = (v | (v << 8)) & 0x0300f00f;
    v = (v | (v << 4)) & 0x030c30c3;
    v = (v | (v << 2)) & 0x09249249;
    return v;
}

/// Morton (Z-order) keys over a box, 10 bits per axis: key << 32 | id, so that sorting by key
/// puts points that are close in space close in memory.
class MortonKeys {
public:
    MortonKeys(const double* lo, const double* hi) {
        for (int axis = 0; axis < 3; ++axis) {
            lo_[axis] = lo[axis];
            scale_[axis] = hi[axis] > lo[axis] ? 1023.0 / (hi[axis] - lo[axis]) : 0.0;
        }
    }
    std::uint64_t operator()(const double* p, Index id) const {
        std::uint32_t key = 0;
        for (int axis = 0; axis < 3; ++axis) {
            // In the box, (p - lo) * scale is in [0, 1023] up to rounding; the mask keeps it there.
            key |= spread_bits(static_cast<std::uint32_t>((p[axis] - lo_[axis]) * scale_[axis])) << axis;
        }
        return std::uint64_t{key} << 32 | id;
    }

private:
    double lo_[3], scale_[3];
};

/// A region certified, exactly, to lie strictly inside the hull of a cloud: the interior of the
/// hull of its simplex and its extremes in 14 directions (the Akl-Toussaint heuristic). A point
/// inside it is never a vertex of the hull. The test is a box inside that region first (six
/// comparisons: most interior points of a ball or a cube), then the region's planes, each by the
/// rounded height with its error bound and orient3d where that does not decide.
class Interior {
public:
    /// False when the extremes have no volume (then nothing is certified inside).
    bool build(PointSpan points, const Simplex& simplex) {
        std::vector<Index> seeds(simplex.extreme, simplex.extreme + 14);
        seeds.insert(seeds.end(), simplex.p, simplex.p + 4);
        std::sort(seeds.begin(), seeds.end());
        seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
        for (Index i : seeds) xyz_.insert(xyz_.end(), points[i], points[i] + 3);
        const PointSpan local_points(xyz_.data(), seeds.size());
        Simplex local;
        local.dimension = 3;
        for (int k = 0; k < 4; ++k)
            local.p[k] = static_cast<Index>(std::lower_bound(seeds.begin(), seeds.end(), simplex.p[k]) - seeds.begin());
        std::vector<Index> identity(seeds.size());
        for (Index k = 0; k < identity.size(); ++k) identity[k] = k;
        Surface surface;
        std::string ignored;
        if (!quickhull_surface(local_points, identity, local, surface, ignored)) return false;
        // Every point of the cloud lies in its bounding box, so differs from a corner by at most
        // the box's largest side per axis: the planes' error bounds hold for all of them.
        const double extent = std::max({simplex.hi[0] - simplex.lo[0], simplex.hi[1] - simplex.lo[1], simplex.hi[2] - simplex.lo[2]});
        for (std::size_t t = 0; t < surface.size(); ++t) {
            const Index* v = &surface.triangles[3 * t];
            planes_.push_back(plane_through(local_points, v[0], v[1], v[2], extent));
        }
        // The largest box about the bounding box's centre, shrunk in steps, whose corners are
        // all strictly below every plane; none (an empty box) if even the smallest is not.
        for (double shrink : {0.98, 0.9, 0.75, 0.55}) {
            for (int axis = 0; axis < 3; ++axis) {
                const double centre = 0.5 * (simplex.lo[axis] + simplex.hi[axis]);
                const double half = 0.5 * (simplex.hi[axis] - simplex.lo[axis]) * shrink;
                box_lo_[axis] = centre - half;
                box_hi_[axis] = centre + half;
            }
            bool fits = true;
            for (int corner = 0; corner < 8 && fits; ++corner) {
                const double q[3] = {corner & 1 ? box_hi_[0] : box_lo_[0], corner & 2 ? box_hi_[1] : box_lo_[1],
                                     corner & 4 ? box_hi_[2] : box_lo_[2]};
                fits = below_every_plane(q);
            }
            if (fits) return true;
        }
        for (int axis = 0; axis < 3; ++axis) box_lo_[axis] = 1.0, box_hi_[axis] = 0.0;
        return true;
    }

    /// Whether p lies strictly inside the region (exactly).
    bool contains(const double* p) const {
        return (p[0] >= box_lo_[0] && p[0] <= box_hi_[0] && p[1] >= box_lo_[1] && p[1] <= box_hi_[1] &&
                p[2] >= box_lo_[2] && p[2] <= box_hi_[2]) ||
               below_every_plane(p);
    }

private:
    bool below_every_plane(const double* p) const {
        const PointSpan local_points(xyz_.data(), xyz_.size() / 3);
        for (const Plane& plane : planes_) {
            double h;
            if (side_of(local_points, plane, p, &h) >= 0) return false;
        }
        return true;
    }

    std::vector<double> xyz_;  // the seeds' coordinates
    std::vector<Plane> planes_;
    double box_lo_[3] = {1.0, 1.0, 1.0}, box_hi_[3] = {0.0, 0.0, 0.0};
};

}  // namespace

std::vector<Index> spatial_order(PointSpan points, LargeArray<std::uint64_t>& keyed) {
    std::vector<Index> ids;
    ids.reserve(keyed.size());
    if (keyed.size() <= 4096) {  // small: coordinate order is good enough
        for (std::uint64_t k : keyed) ids.push_back(static_cast<Index>(k));
        ids.erase(sort_dropping_repeats(points, ids.begin(), ids.end()), ids.end());
        return ids;
    }
    // LSD radix sort on the 30-bit key, two 15-bit digits.
    LargeArray<std::uint64_t> buffer(keyed.size());
    for (int shift = 32; shift < 62; shift += 15) {
        std::vector<std::size_t> start(1u << 15, 0);
        for (std::uint64_t v : keyed) ++start[(v >> shift) & 0x7fff];
        std::size_t sum = 0;
        for (std::size_t& count : start) sum += std::exchange(count, sum);
        for (std::uint64_t v : keyed) buffer[start[(v >> shift) & 0x7fff]++] = v;
        keyed.swap(buffer);
    }
    for (std::size_t begin = 0; begin < keyed.size();) {
        std::size_t end = begin + 1;
        while (end < keyed.size() && keyed[end] >> 32 == keyed[begin] >> 32) ++end;
        const std::size_t first = ids.size();
        for (std::size_t k = begin; k < end; ++k) ids.push_back(static_cast<Index>(keyed[k]));
        if (end - begin > 1) {  // a shared cell: identical points, if any, are here
            ids.erase(sort_dropping_repeats(points, ids.begin() + static_cast<std::ptrdiff_t>(first), ids.end()), ids.end());
        }
        begin = end;
    }
    return ids;
}

LargeArray<std::uint64_t> candidates(PointSpan points, const Simplex& simplex, unsigned threads) {
    const auto n = static_cast<Index>(points.count);
    const MortonKeys morton(simplex.lo, simplex.hi);
    // Blocks keyed (those outside the box, when there is one) on the threads, joined in order.
    auto keyed_outside = [&](const Interior* interior) {
        constexpr Index kBlock = Index{1} << 18;
        const std::size_t blocks = (n + kBlock - 1) / kBlock;
        std::vector<std::vector<std::uint64_t>> kept(blocks);
        parallel_for(threads, blocks, [&](std::size_t block) {
            const Index first = static_cast<Index>(block) * kBlock, last = std::min(n, first + kBlock);
            std::vector<std::uint64_t>& out = kept[block];
            if (interior == nullptr) {
                out.resize(last - first);
                for (Index i = first; i < last; ++i) out[i - first] = morton(points[i], i);
                return;
            }
            out.reserve(kBlock / 8);
            for (Index i = first; i < last; ++i) {
                if (!interior->contains(points[i])) out.push_back(morton(points[i], i));
            }
        });
        std::size_t total = 0;
        for (const auto& part : kept) total += part.size();
        LargeArray<std::uint64_t> all;
        all.reserve(total + 4);
        for (auto& part : kept) {
            all.insert(all.end(), part.begin(), part.end());
            std::vector<std::uint64_t>().swap(part);
        }
        return all;
    };
    if (n < 1024) return keyed_outside(nullptr);  // not worth it
    Interior interior;
    if (!interior.build(points, simplex)) return keyed_outside(nullptr);
    LargeArray<std::uint64_t> all = keyed_outside(&interior);
    for (int k = 0; k < 4; ++k) {  // the starting simplex stays, even when inside
        const Index s = simplex.p[k];
        if (interior.contains(points[s]) && std::find(simplex.p, simplex.p + k, s) == simplex.p + k)
            all.push_back(morton(points[s], s));
    }
    return all;
}

}  // namespace quickhull_detail

double culling_kept_fraction(PointSpan points, const Simplex& simplex, PointSpan sample) {
    quickhull_detail::Interior interior;
    if (simplex.dimension < 3 || sample.count == 0 || !interior.build(points, simplex)) return 1.0;
    std::size_t outside = 0;
    for (std::size_t i = 0; i < sample.count; ++i) outside += !interior.contains(sample[i]);
    return static_cast<double>(outside) / static_cast<double>(sample.count);
}

}  // namespace hullkit::detail
