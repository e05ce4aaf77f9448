// Private to native/src/delaunay: marking the domain of a constrained triangulation (a polygon's
// inside, a graph's regions) and refining it (refine.cpp; QualityOptions in hullkit/constrained.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "constrained_mesh.hpp"

namespace hullkit {
namespace constrained_detail {

class Refiner {
public:
    /// Region ids per triangle: 0 outside the domain, kDomain inside, kDomain + 1 + r in the region
    /// of RegionSeed r.
    static constexpr std::uint32_t kDomain = 1;

    explicit Refiner(Cdt& mesh) : m_(mesh) {}

    /// The domain is the inside by the fill rule.
    void mark_polygon(FillRule fill);
    /// The domain is the hull, less the exterior (when asked) and the regions around the hole
    /// points; the regions around `regions` points get their own ids (x y pairs, scaled).
    void mark_graph(bool exterior, const std::vector<double>& holes, const std::vector<double>& regions);
    /// The domain is the inside by even-odd (mark_polygon), and each domain triangle whose corners
    /// are a triple of `corners` (3 per input triangle, any order) gets region kDomain + 1 + k for
    /// triple k. Returns the first triple that is no domain triangle, or -1 when every one is and
    /// every domain triangle is one (else the count of triples, for a domain triangle left over).
    std::int64_t mark_triangles(const std::vector<std::uint32_t>& corners);

    /// Refines the domain. `area2` per region id: twice the largest area allowed (scaled units), 0
    /// for none. False with `error` set on failure (the cap, or an internal error).
    bool refine(const QualityOptions& options, std::vector<double> area2, int exponent = 0);

    std::string error;
    std::size_t steiner_count = 0;
    std::size_t unrefined_count = 0;

private:
    struct BadTriangle {
        std::uint32_t t, a, b, c;  ///< the triangle and its corners (stale once they change)
        int kind;                  ///< its flaw (kTooLarge or kSmallAngle), found with those corners
    };
    struct SplitItem {
        std::uint32_t a, b;
        bool forced;  ///< split even if no corner of its triangles encroaches it now
    };
    /// A whole segment, as it was when refinement began.
    struct Parent {
        std::uint32_t a, b;
    };

    /// Gives `region` to every triangle reached from those on the stack without crossing a
    /// segment, stopping at ghosts and at triangles outside the domain or already in `region`
    /// (with region 0: removes what is reached from the domain).
    void flood(std::vector<std::uint32_t>& stack, std::uint32_t region);
    /// The triangles a hole or region point picks (all around it on a corner, both on an edge),
    /// located from triangle `start`; none outside the hull.
    void seed_at(const double* p, std::uint32_t start, std::vector<std::uint32_t>& seeds);
    std::uint32_t alive_triangle() const;
    /// kTooLarge, kSmallAngle (with the shortest edge's index in the triangle) or kFine: the
    /// bounds alone, before the exemptions of bad().
    static constexpr int kFine = 0, kTooLarge = 1, kSmallAngle = 2;
    int flaw(std::uint32_t t, int* shortest) const;
    /// To be refined: t's flaw `kind` (not kFine; `shortest` from flaw()) not exempt (small input
    /// angles, Shewchuk's rule).
    bool bad(std::uint32_t t, int kind, int shortest) const;
    /// Half-edge h's segment has the third corner of h's triangle strictly inside its diametral
    /// circle (that triangle in the domain, or any finite one when conforming).
    bool encroached_from(std::uint32_t h) const;
    /// From either side.
    bool encroached(std::uint32_t e) const;
    void retest();
    bool count_point();
    /// Whether the segment at half-edge e stays whole (QualityOptions::keep_segments).
    bool kept_whole(std::uint32_t e) const;
    bool split_segment(std::uint32_t e);
    bool split_triangle(const BadTriangle& item);
    std::uint32_t walk(const double* p, std::uint32_t t, std::uint32_t* wall);

    Cdt& m_;
    std::vector<double> area2_;
    double cos2_ = 1.0;
    double off_centre_ = 0.0;  ///< see split_triangle (0: plain circumcentres)
    double tiny2_ = 0.0;       ///< the square of the smallest length refinement works at (refine())
    bool conforming_ = false;
    unsigned keep_segments_ = 0;
    std::function<bool(const double*, const double*, const double*, double)> unsuitable_;
    double unscale_ = 1.0;  ///< from the mesh's coordinates to the input's (a power of two)
    std::size_t cap_ = 0;
    std::vector<Parent> parents_;
    std::vector<std::uint32_t> on_segment_;  ///< per vertex: the parent segment it was added on, or kGhost
    std::set<std::pair<std::uint32_t, std::uint32_t>> unsplittable_;
    std::vector<BadTriangle> bad_;
    std::vector<BadTriangle> flawed_;  ///< every domain triangle retested with a flaw (for unrefined_count)
    std::vector<SplitItem> split_;
    std::vector<std::uint32_t> walls_;
    std::vector<Cdt::Edge> encroached_;
};

}  // namespace constrained_detail
}  // namespace hullkit
