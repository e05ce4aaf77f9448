// libFuzzer target: hullkit::delaunay3 on arbitrary bytes read as 3D points. The first byte picks
// how the rest is read: (0) little-endian doubles x y z (NaN, infinities, huge and tiny
// magnitudes); (1) int8 triples (grids, cospherical, coplanar and collinear sets, repeats); (2)
// int8 triples scaled by 2^-30 around (1e6, -1e6, 3) (the same, exactly, far from the origin);
// (3) int16 triples. Checked:
//  - a tetrahedralization that is returned passes the exact verify_delaunay3 (the tie rule
//    included); neighbours are symmetric and share the faces they claim; the hull triangles are
//    exactly the faces without a neighbour; each representative is the lowest index with the same
//    coordinates; coplanar input gives triangles whose neighbours are symmetric;
//  - the reversed input gives the same tetrahedra (relabelled): ties depend only on the points;
//  - delaunay3_locate answers a query at an input point with a tetrahedron holding it (the
//    barycentric weight of that corner exactly 1) and with its representative as the nearest point;
//  - an error is one line, with no tetrahedra;
//  - the furthest-site tetrahedralization (up to 150 points): every tetrahedron positive, every point
//    inside or on every circumsphere (exact orient3d and insphere, on the points scaled by a power
//    of two into insphere's exact range), neighbours symmetric, the open faces the hull's, the corners
//    exactly the hull's vertices, and the volume the ordinary tetrahedralization's (as a sum).
// Built by scripts/fuzz.sh (clang++ -fsanitize=fuzzer,address,undefined).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <set>
#include <vector>

#include "hullkit/delaunay3.hpp"
#include "hullkit/hull.hpp"
#include "hullkit/predicates.hpp"

namespace {

std::vector<double> read_points(const std::uint8_t* data, std::size_t size) {
    std::vector<double> xyz;
    if (size == 0) return xyz;
    const int mode = data[0] & 3;
    ++data;
    --size;
    if (mode == 0) {
        xyz.resize(size / 24 * 3);
        if (!xyz.empty()) std::memcpy(xyz.data(), data, 8 * xyz.size());
    } else if (mode == 1 || mode == 2) {
        for (std::size_t i = 0; i + 2 < size; i += 3) {
            for (int k = 0; k < 3; ++k) {
                const double v = static_cast<std::int8_t>(data[i + k]);
                const double offset[3] = {1e6, -1e6, 3.0};
                xyz.push_back(mode == 1 ? v : offset[k] + std::ldexp(v, -30));
            }
        }
    } else {
        for (std::size_t i = 0; i + 5 < size; i += 6)
            for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<std::int16_t>(data[i + 2 * k] | data[i + 2 * k + 1] << 8));
    }
    return xyz;
}

void check(bool condition) {
    if (!condition) std::abort();
}

std::set<std::array<std::uint32_t, 4>> tetrahedron_set(const hullkit::Delaunay3& d, std::size_t n, bool reversed) {
    std::set<std::array<std::uint32_t, 4>> out;
    for (std::size_t t = 0; t < d.tetrahedron_count(); ++t) {
        std::array<std::uint32_t, 4> v;
        for (int k = 0; k < 4; ++k) {
            const std::uint32_t i = d.tetrahedra[4 * t + k];
            v[k] = reversed ? static_cast<std::uint32_t>(n - 1 - i) : i;
        }
        std::sort(v.begin(), v.end());
        out.insert(v);
    }
    return out;
}

/// Neighbours share the faces they claim and name each other back; the faces without one are
/// exactly the hull triangles.
void check_neighbours_and_hull(const hullkit::Delaunay3& d) {
    std::multiset<std::array<std::uint32_t, 3>> open, hull;
    for (std::size_t t = 0; t < d.tetrahedron_count(); ++t) {
        for (int j = 0; j < 4; ++j) {
            std::array<std::uint32_t, 3> face;
            for (int i = 0, k = 0; i < 4; ++i)
                if (i != j) face[k++] = d.tetrahedra[4 * t + i];
            std::sort(face.begin(), face.end());
            const std::int32_t u = d.neighbors[4 * t + j];
            if (u < 0) {
                open.insert(face);
                continue;
            }
            const std::uint32_t* w = &d.tetrahedra[4 * static_cast<std::size_t>(u)];
            for (const std::uint32_t c : face) check(std::find(w, w + 4, c) != w + 4);
            bool back = false;
            for (int k = 0; k < 4; ++k) back = back || d.neighbors[4 * static_cast<std::size_t>(u) + k] == static_cast<std::int32_t>(t);
            check(back);
        }
    }
    for (std::size_t f = 0; f < d.hull.size() / 3; ++f) {
        std::array<std::uint32_t, 3> face = {d.hull[3 * f], d.hull[3 * f + 1], d.hull[3 * f + 2]};
        std::sort(face.begin(), face.end());
        hull.insert(face);
    }
    check(open == hull);
}

/// The furthest-site checks (see the top).
void check_furthest(const std::vector<double>& xyz, const hullkit::Delaunay3& nearest) {
    const std::size_t n = xyz.size() / 3;
    const hullkit::PointSpan points(xyz.data(), n);
    hullkit::Delaunay3Options options;
    options.furthest_site = true;
    const hullkit::Delaunay3 d = hullkit::delaunay3(points, options);
    check(d.ok() && d.dimension == nearest.dimension && d.furthest_site);
    if (d.dimension != 3) return;
    check_neighbours_and_hull(d);
    // The points scaled by one power of two into insphere's exact range (as delaunay3 scales them).
    double largest = 0, smallest = HUGE_VAL;
    for (const double v : xyz) {
        largest = std::max(largest, std::fabs(v));
        if (v != 0) smallest = std::min(smallest, std::fabs(v));
    }
    int exponent = 0;
    if (!hullkit::insphere_range_ok(largest, smallest)) check(hullkit::insphere_scale_exponent(largest, smallest, &exponent));
    std::vector<double> scaled(xyz.size());
    for (std::size_t i = 0; i < xyz.size(); ++i) scaled[i] = std::ldexp(xyz[i], exponent);
    const auto at = [&](std::uint32_t i) { return &scaled[3 * i]; };
    const auto six_volume = [&](const std::uint32_t* v) {
        double e[3][3];
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) e[r][k] = xyz[3 * v[r + 1] + k] - xyz[3 * v[0] + k];
        return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
               e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    };
    std::set<std::uint32_t> corners;
    double volume = 0, nearest_volume = 0, extent = 0;
    for (std::size_t t = 0; t < d.tetrahedron_count(); ++t) {
        const std::uint32_t* v = &d.tetrahedra[4 * t];
        corners.insert(v, v + 4);
        check(hullkit::orient3d(at(v[0]), at(v[1]), at(v[2]), at(v[3])) > 0);
        for (std::uint32_t i = 0; i < n; ++i) check(hullkit::insphere(at(v[0]), at(v[1]), at(v[2]), at(v[3]), at(i)) >= 0);
        volume += six_volume(v);
    }
    const hullkit::Hull h = hullkit::hull(points);
    check(corners == std::set<std::uint32_t>(h.vertices.begin(), h.vertices.end()));
    for (std::size_t t = 0; t < nearest.tetrahedron_count(); ++t) nearest_volume += six_volume(&nearest.tetrahedra[4 * t]);
    for (const double v : xyz) extent = std::max(extent, std::fabs(v));
    // Both fill the hull; rounded sums (a loose bound, and none where they overflow).
    const double margin = 1e-9 * std::fabs(nearest_volume) + 1e-10 * extent * extent * extent;
    if (std::isfinite(volume) && std::isfinite(nearest_volume) && std::isfinite(margin))
        check(std::fabs(volume - nearest_volume) <= margin);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<double> xyz = read_points(data, size);
    const std::size_t n = xyz.size() / 3;
    if (n > 600) return 0;  // keep each run short: the verifier sorts every face
    const hullkit::PointSpan points(xyz.data(), n);
    const hullkit::Delaunay3 d = hullkit::delaunay3(points);
    if (!d.ok()) {
        check(d.tetrahedra.empty() && d.error.find('\n') == std::string::npos);
        return 0;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t r = d.representative[i];
        check(r <= i && xyz[3 * r] == xyz[3 * i] && xyz[3 * r + 1] == xyz[3 * i + 1] && xyz[3 * r + 2] == xyz[3 * i + 2]);
    }
    if (d.dimension == 2) {
        const std::size_t count = d.triangles.size() / 3;
        check(d.neighbors.size() == 3 * count);
        for (std::size_t t = 0; t < count; ++t)
            for (int j = 0; j < 3; ++j) {
                const std::int32_t u = d.neighbors[3 * t + j];
                if (u < 0) continue;
                bool back = false;
                for (int k = 0; k < 3; ++k) back = back || d.neighbors[3 * static_cast<std::size_t>(u) + k] == static_cast<std::int32_t>(t);
                check(back);
            }
    }
    if (n <= 150) check_furthest(xyz, d);
    if (d.dimension != 3) return 0;
    const hullkit::Delaunay3VerifyReport report = hullkit::verify_delaunay3(points, d.tetrahedra.data(), d.tetrahedron_count());
    check(report.ok);
    check_neighbours_and_hull(d);
    // The reversed input: the same tetrahedra, relabelled (where no duplicates change which index
    // represents a point).
    if (d.duplicate_count == 0) {
        std::vector<double> reversed(xyz.size());
        for (std::size_t i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) reversed[3 * (n - 1 - i) + k] = xyz[3 * i + k];
        const hullkit::Delaunay3 e = hullkit::delaunay3(hullkit::PointSpan(reversed.data(), n));
        check(e.ok() && tetrahedron_set(e, n, true) == tetrahedron_set(d, n, false));
    }
    // Queries at the input points.
    hullkit::Delaunay3QueryOptions options;
    options.barycentric = options.nearest = true;
    const hullkit::Delaunay3Queries q = hullkit::delaunay3_locate(points, d, points, options);
    check(q.ok());
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t t = q.tetrahedron[i];
        check(t >= 0);
        const std::uint32_t r = d.representative[i];
        bool corner = false;
        for (int k = 0; k < 4; ++k) {
            if (d.tetrahedra[4 * static_cast<std::size_t>(t) + k] == r) {
                corner = true;
                check(q.barycentric[4 * i + k] == 1.0);
            } else {
                check(q.barycentric[4 * i + k] == 0.0);
            }
        }
        check(corner);
        check(q.nearest[i] == static_cast<std::int32_t>(r));
    }
    return 0;
}
