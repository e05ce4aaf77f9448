// hullkit::HullBuilder: the hull of a cloud given in pieces, holding only the running hull's
// vertices. Hulls compose, hull(A u B) = hull(vertices of hull(A) u B), and quickhull's results
// are in a canonical order that depends only on the points (hull.hpp), so the result is the one
// hull() gives for the whole cloud, bit for bit.
//
// Ties among identical points go to the lowest index: the kept points are held in ascending
// global index, and the hull of each union is taken in that order, so "lowest local index" is
// "lowest global index" at every step. The coordinates are checked as they arrive (the first
// non-finite one is reported with its global index), and the range of magnitudes of every point
// seen, kept or not, decides the power-of-two scaling of the last hull, as it would for the whole.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "hull_internal.hpp"
#include "hullkit/hull.hpp"
#include "parallel.hpp"

namespace hullkit {

HullBuilder::HullBuilder(const HullOptions& options) : options_(options) {
    if (options_.side_test != SideTest::Exact || options_.algorithm != Algorithm::Quickhull) {
        error_ = "HullBuilder runs quickhull with exact side tests only";
    }
}

bool HullBuilder::add(PointSpan points, std::uint64_t first_index) { return add_points(points, first_index, nullptr); }

bool HullBuilder::add_indexed(PointSpan points, const std::uint64_t* indices) { return add_points(points, 0, indices); }

namespace {

/// On one thread, a large piece is taken this many points at a time, so that the hull of each
/// step's union stays in the caches: 6.25e6 points in a ball took 2.2-2.8 s as one piece and
/// 0.8-1.1 s in steps of 2^19. On threads, a piece's candidates already come from chunks hulled
/// on the threads, and steps only repeat their fixed costs (16 files of 6e6 points streamed on
/// 2 threads: 9.4-12.5 s whole, 12.3-14 s in steps of 2^20).
constexpr std::size_t kStep = std::size_t{1} << 19;

}  // namespace

bool HullBuilder::add_points(PointSpan points, std::uint64_t first_index, const std::uint64_t* indices) {
    if (!error_.empty()) return false;
    if (points.count == 0) return true;
    const unsigned threads = detail::resolve_threads(options_.threads);
    if (threads == 1 && points.count >= 2 * kStep) {
        // Steps, while the hull keeps few of the points. A cloud whose points are mostly on its
        // hull (a sphere) keeps them all, and every step would hull everything kept so far
        // again: once a step adds more than an eighth of its size to the kept points, the rest
        // is taken at once. The result is the same either way (the hull of everything added).
        std::size_t begin = 0;
        while (begin < points.count) {
            const std::size_t kept_before = ids_.size();
            const std::size_t size = points.count - begin < 2 * kStep ? points.count - begin : kStep;
            const PointSpan part(points[begin], size);
            if (!add_step(part, indices ? 0 : first_index + begin, indices ? indices + begin : nullptr, threads)) return false;
            begin += size;
            if (begin < points.count && 8 * (ids_.size() - std::min(ids_.size(), kept_before)) > size) {
                return add_step(PointSpan(points[begin], points.count - begin), indices ? 0 : first_index + begin,
                                indices ? indices + begin : nullptr, threads);
            }
        }
        return true;
    }
    return add_step(points, first_index, indices, threads);
}

bool HullBuilder::add_step(PointSpan points, std::uint64_t first_index, const std::uint64_t* indices, unsigned threads) {
    detail::Magnitudes range{largest_, smallest_};
    Hull check = detail::scan_magnitudes(points, first_index, indices, threads, &range);
    int exponent = 0;
    if (check.ok()) check = detail::scale_exponent(range, &exponent);
    if (!check.ok()) {
        error_ = std::move(check.error);
        error_point_ = check.error_point;
        return false;
    }
    largest_ = range.largest;
    smallest_ = range.smallest;
    added_ += points.count;

    // The piece's own candidates (on threads, for a large piece with few hull vertices), scaled
    // into the predicates' range when it has to be (a copy only then).
    std::vector<double> scaled;
    const PointSpan piece = detail::scale_points(points, exponent, threads, scaled);
    bool surface_like = false;  // then every point of the piece is a candidate
    std::vector<std::uint32_t> candidates = detail::chunk_candidates(piece, threads, &surface_like);
    const bool all = candidates.empty();
    const std::size_t count = all ? points.count : candidates.size();
    auto local = [&](std::size_t k) { return all ? k : std::size_t{candidates[k]}; };
    auto global = [&](std::size_t i) { return indices ? indices[i] : first_index + i; };

    // Candidates and kept points merged in ascending global index (kept points first on a tie,
    // which is an error reported below).
    std::vector<std::size_t> order(count);
    for (std::size_t k = 0; k < count; ++k) order[k] = local(k);
    if (indices) std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return indices[a] < indices[b]; });
    auto added_twice = [&](std::uint64_t index) {
        error_ = "point index " + std::to_string(index) + " was added twice";
        error_point_ = static_cast<std::int64_t>(index);
        return false;
    };
    std::vector<double> xyz;
    std::vector<std::uint64_t> ids;
    xyz.reserve(3 * (ids_.size() + count));
    ids.reserve(ids_.size() + count);
    std::size_t kept = 0, next = 0;
    while (kept < ids_.size() || next < count) {
        if (next == count || (kept < ids_.size() && ids_[kept] <= global(order[next]))) {
            if (next < count && ids_[kept] == global(order[next])) return added_twice(ids_[kept]);
            ids.push_back(ids_[kept]);
            xyz.insert(xyz.end(), &xyz_[3 * kept], &xyz_[3 * kept] + 3);
            ++kept;
        } else {
            if (!ids.empty() && ids.back() == global(order[next])) return added_twice(ids.back());
            ids.push_back(global(order[next]));
            xyz.insert(xyz.end(), points[order[next]], points[order[next]] + 3);
            ++next;
        }
    }
    scaled = {};
    candidates = {};

    // Keep the extreme points of the union (decided on scaled copies when scaling is needed).
    const std::vector<std::uint32_t> extreme =
        detail::extreme_points(detail::scale_points(PointSpan(xyz.data(), ids.size()), exponent, threads, scaled));
    xyz_.clear();
    ids_.clear();
    xyz_.reserve(3 * extreme.size());
    ids_.reserve(extreme.size());
    for (std::uint32_t v : extreme) {
        xyz_.insert(xyz_.end(), &xyz[3 * std::size_t{v}], &xyz[3 * std::size_t{v}] + 3);
        ids_.push_back(ids[v]);
    }
    return true;
}

StreamedHull HullBuilder::finish() const {
    StreamedHull result;
    result.point_count = added_;
    if (!error_.empty()) {
        result.hull = detail::failure(error_, error_point_);
        return result;
    }
    int exponent = 0;
    if (Hull invalid = detail::scale_exponent(detail::Magnitudes{largest_, smallest_}, &exponent); !invalid.ok()) {
        result.hull = std::move(invalid);
        return result;
    }
    result.hull = detail::hull_in_range(PointSpan(xyz_.data(), ids_.size()), options_, exponent);
    result.points = xyz_;
    result.index = ids_;
    return result;
}

}  // namespace hullkit
