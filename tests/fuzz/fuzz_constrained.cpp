// libFuzzer target: hullkit::constrained_delaunay and hullkit::triangulate_polygon on arbitrary
// bytes. The first byte picks how points are read (as fuzz_delaunay: (0) doubles, NaN and extreme
// magnitudes included; (1) int8 pairs: grids, collinear runs, repeats and crossings; (2) int8 pairs
// scaled by 2^-30 far from the origin; (3) int16 pairs), whether they form rings (bit 2), the
// fill rule (bit 3), Delaunay refinement (bit 4: a minimum angle of 0 to 30 degrees from the
// second byte, at most 3000 added points; bit 5 conforming; bits 6-7 keep_segments 0, 1, 2, 0);
// the second byte also how rings split
// or which pairs are segments. Checked:
//  - a returned triangulation passes the exact verify_constrained (valid, no overlap, unflagged
//    edges locally Delaunay; polygons and refined meshes: every boundary edge flagged; graphs:
//    covers the hull);
//  - graphs: the ends of every segment are joined by a chain of flagged edges (one component);
//  - representatives are the lowest index with the same coordinates; triangles name only them or
//    added points; an error is one line and leaves no triangles;
//  - refine_mesh (Triangle's -r) on a result of up to 2000 triangles: with a zero bound per
//    triangle and nothing else it gives back exactly those triangles, each naming its source;
//    refined (bit 0 of the second byte: a 20 degree angle and an area bound) it passes the
//    verifier with every boundary edge flagged, or stops at the point cap.
// Built by scripts/fuzz.sh (clang++ -fsanitize=fuzzer,address,undefined).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "hullkit/constrained.hpp"
#include "points2d_bytes.hpp"

namespace {

/// Dense arrangements (a thousand long segments crossing 10^5 times) are valid input but take
/// seconds under the sanitizers; past this many crossing points they stop with their error.
constexpr std::size_t kMaxCrossingPoints = 20000;

void check(bool condition) {
    if (!condition) std::abort();
}

/// Components of the graph of flagged edges (union-find): two points are joined by a chain of
/// flagged edges exactly when they are in one component.
struct Components {
    std::vector<std::uint32_t> parent;
    explicit Components(const hullkit::ConstrainedDelaunay& d) : parent(d.coords.size() / 2) {
        for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<std::uint32_t>(i);
        for (std::size_t e = 0; e < d.triangles.size(); ++e)
            if (d.constrained[e]) parent[find(d.triangles[e])] = find(d.triangles[e % 3 == 2 ? e - 2 : e + 1]);
    }
    std::uint32_t find(std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const int mode = data[0] & 3;
    const bool polygon = data[0] & 4;
    const hullkit::FillRule fill = data[0] & 8 ? hullkit::FillRule::NonZero : hullkit::FillRule::EvenOdd;
    const unsigned pick = data[1];
    hullkit::QualityOptions quality;
    if (data[0] & 16) {
        quality.min_angle = 2.0 * (pick >> 4);
        quality.conforming = (data[0] & 32) != 0;
        quality.keep_segments = static_cast<unsigned>(data[0] >> 6) % 3;
        quality.max_steiner_points = 3000;
    }
    const std::vector<double> xy = fuzz_input::points2d(data + 2, size - 2, mode);
    const hullkit::PointSpan2 points(xy);
    const std::uint32_t n = static_cast<std::uint32_t>(points.count);
    hullkit::ConstrainedDelaunay d;
    std::vector<std::uint32_t> segments;
    if (polygon) {
        std::vector<std::uint32_t> starts;
        const std::uint32_t ring = pick % 9 + 3;
        for (std::uint32_t s = ring; s < n; s += ring) starts.push_back(s);
        hullkit::PolygonOptions options;
        options.fill = fill;
        options.threads = 1;
        options.quality = quality;
        options.max_added_points = kMaxCrossingPoints;
        d = hullkit::triangulate_polygon(points, starts.data(), starts.size(), options);
    } else if (n > 0) {
        const std::uint32_t step = pick % 7 + 1;
        for (std::uint32_t i = 0; i < n; i += 2) segments.insert(segments.end(), {i, static_cast<std::uint32_t>((i * step + pick) % n)});
        hullkit::ConstrainedOptions options;
        options.threads = 1;
        options.quality = quality;
        options.max_added_points = kMaxCrossingPoints;
        d = hullkit::constrained_delaunay(points, segments.data(), segments.size() / 2, options);
    }
    if (!d.ok()) {
        check(d.error.find('\n') == std::string::npos);
        check(d.triangles.empty());
        return 0;
    }
    check(d.representative.size() == n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t r = d.representative[i];
        check(r <= i && xy[2 * r] == xy[2 * i] && xy[2 * r + 1] == xy[2 * i + 1]);
    }
    for (std::uint32_t v : d.triangles) check(v >= n || d.representative[v] == v);
    const hullkit::ConstrainedVerifyReport report = hullkit::verify_constrained(
        hullkit::PointSpan2(d.coords), d.triangles.data(), d.triangle_count(), d.halfedges.data(), d.constrained.data(), polygon || quality.active());
    check(report.ok);
    if (!polygon && d.dimension == 2) {
        Components components(d);
        for (std::size_t k = 0; k < segments.size(); k += 2)
            check(components.find(d.representative[segments[k]]) == components.find(d.representative[segments[k + 1]]));
    }
    const std::size_t t_count = d.triangle_count();
    if (t_count == 0 || t_count > 2000) return 0;
    const hullkit::PointSpan2 mesh_points(d.coords);
    hullkit::RefineMeshOptions same;
    same.threads = 1;
    same.triangle_max_area.assign(t_count, 0.0);
    const hullkit::ConstrainedDelaunay again = hullkit::refine_mesh(mesh_points, d.triangles.data(), t_count, nullptr, 0, same);
    check(again.ok() && again.triangle_count() == t_count && again.triangle_region.size() == t_count);
    for (std::size_t t = 0; t < t_count; ++t) {
        const std::uint32_t* got = &again.triangles[3 * t];
        const std::uint32_t* want = &d.triangles[3 * static_cast<std::size_t>(again.triangle_region[t])];
        check((got[0] == want[0] && got[1] == want[1] && got[2] == want[2]) || (got[0] == want[1] && got[1] == want[2] && got[2] == want[0]) ||
              (got[0] == want[2] && got[1] == want[0] && got[2] == want[1]));
    }
    if (pick & 1) {
        hullkit::RefineMeshOptions finer;
        finer.threads = 1;
        finer.quality.min_angle = 20;
        finer.quality.max_steiner_points = 3000;
        double largest = 0;
        for (std::size_t t = 0; t < t_count; ++t) {
            const double* a = &d.coords[2 * d.triangles[3 * t]];
            const double* b = &d.coords[2 * d.triangles[3 * t + 1]];
            const double* c = &d.coords[2 * d.triangles[3 * t + 2]];
            largest = std::max(largest, std::fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2);
        }
        if (std::isfinite(largest)) finer.quality.max_area = largest / 4;
        const hullkit::ConstrainedDelaunay m = hullkit::refine_mesh(mesh_points, d.triangles.data(), t_count, nullptr, 0, finer);
        if (!m.ok()) {
            check(m.error.find("quality refinement added") == 0 && m.triangles.empty());
            return 0;
        }
        const hullkit::ConstrainedVerifyReport refined = hullkit::verify_constrained(
            hullkit::PointSpan2(m.coords), m.triangles.data(), m.triangle_count(), m.halfedges.data(), m.constrained.data(), true);
        check(refined.ok);
    }
    return 0;
}
