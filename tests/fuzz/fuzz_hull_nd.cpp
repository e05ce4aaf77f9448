// libFuzzer target: hullkit::hull_nd, delaunay_nd, locate_nd and voronoi_nd_volumes in 2 to 6
// dimensions. The first byte picks the dimension, the second how the rest is read: little-endian
// doubles (NaN, infinities, huge and tiny magnitudes) or small signed integers (grids, repeats,
// cospherical and flat sets). A hull must hold every point on the inner side of (or on) every
// facet, each facet with a point strictly inside, neighbours across the right ridges and the
// vertices its corners; a triangulation positively oriented simplices, neighbours sharing all
// corners but one, its faces without neighbour supporting the hull, and each input point located
// in a simplex that has it (or its representative) as a corner; the Voronoi volumes inf on the
// hull and NaN for repeated points. Errors are one line.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <set>
#include <vector>

#include "hullkit/hull_nd.hpp"

namespace {

void check_message(const std::string& error) {
    if (error.empty() || error.find('\n') != std::string::npos) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const int d = 2 + data[0] % 5;
    const bool integers = data[1] & 1;
    data += 2;
    size -= 2;
    std::vector<double> p;
    if (integers) {
        for (std::size_t k = 0; k < size; ++k) p.push_back(static_cast<double>(static_cast<std::int8_t>(data[k]) % 4));
    } else {
        p.resize(size / 8);
        if (!p.empty()) std::memcpy(p.data(), data, 8 * p.size());
    }
    const std::size_t count = p.size() / static_cast<std::size_t>(d);
    if (count > (d <= 4 ? 40u : 16u)) return 0;  // each input fast: structure matters, not size
    const std::size_t D = static_cast<std::size_t>(d);
    auto point = [&](std::size_t i) { return &p[i * D]; };

    const hullkit::HullNd h = hullkit::hull_nd(p.data(), count, d);
    if (!h.ok()) {
        check_message(h.error);
    } else {
        std::set<std::uint32_t> corners;
        for (std::size_t f = 0; f < h.facet_count(); ++f) {
            std::vector<double> rows(D * (D + 1));
            for (std::size_t k = 0; k < D; ++k) {
                corners.insert(h.facets[f * D + k]);
                std::copy(point(h.facets[f * D + k]), point(h.facets[f * D + k]) + D, &rows[k * D]);
            }
            bool strict = false;
            for (std::size_t q = 0; q < count; ++q) {
                std::copy(point(q), point(q) + D, &rows[D * D]);
                const int s = hullkit::orient_nd(rows.data(), d);
                if (s > 0) std::abort();
                strict = strict || s < 0;
            }
            if (!strict) std::abort();
            for (std::size_t k = 0; k < D; ++k) {
                const std::int32_t g = h.neighbors[f * D + k];
                if (g < 0 || static_cast<std::size_t>(g) >= h.facet_count()) std::abort();
                const std::uint32_t* theirs = &h.facets[static_cast<std::size_t>(g) * D];
                for (std::size_t j = 0; j < D; ++j)
                    if (j != k && std::count(theirs, theirs + D, h.facets[f * D + j]) != 1) std::abort();
            }
        }
        if (std::vector<std::uint32_t>(corners.begin(), corners.end()) != h.vertices) std::abort();
    }

    const hullkit::DelaunayNd t = hullkit::delaunay_nd(p.data(), count, d);
    if (!t.ok()) {
        check_message(t.error);
        if (h.ok() && t.error.find("distinct") == std::string::npos) std::abort();  // full-dimensional: must triangulate
        return 0;
    }
    if (!h.ok()) std::abort();
    const std::size_t c = D + 1, m = t.simplex_count();
    std::vector<std::uint32_t> faces;
    for (std::size_t s = 0; s < m; ++s) {
        std::vector<double> rows;
        for (std::size_t k = 0; k < c; ++k) rows.insert(rows.end(), point(t.simplices[s * c + k]), point(t.simplices[s * c + k]) + D);
        if (hullkit::orient_nd(rows.data(), d) <= 0) std::abort();
        for (std::size_t k = 0; k < c; ++k) {
            const std::int32_t u = t.neighbors[s * c + k];
            if (u < 0) {
                for (std::size_t j = 0; j < c; ++j)
                    if (j != k) faces.push_back(t.simplices[s * c + j]);
                continue;
            }
            const std::uint32_t* theirs = &t.simplices[static_cast<std::size_t>(u) * c];
            for (std::size_t j = 0; j < c; ++j)
                if (j != k && std::count(theirs, theirs + c, t.simplices[s * c + j]) != 1) std::abort();
        }
    }
    // Each face without a neighbour supports the hull: no point strictly on both of its sides.
    // (With coplanar points, its faces are not the hull's facets: those leave such points out.)
    for (std::size_t k = 0; k < faces.size(); k += D) {
        std::vector<double> rows(D * (D + 1));
        for (std::size_t j = 0; j < D; ++j) std::copy(point(faces[k + j]), point(faces[k + j]) + D, &rows[j * D]);
        bool above = false, below = false;
        for (std::size_t q = 0; q < count; ++q) {
            std::copy(point(q), point(q) + D, &rows[D * D]);
            const int s = hullkit::orient_nd(rows.data(), d);
            above = above || s > 0;
            below = below || s < 0;
        }
        if (above && below) std::abort();
    }
    // At least as many pieces as the hull's facets: the Delaunay boundary triangulates each flat
    // piece of the hull with all its points, the hull with its vertices only. Only up to 3D: a
    // flat piece of a 4D hull is a 3D polytope, whose triangulations need not have the same
    // number of tetrahedra (a cube: 5 or 6), and more points can mean fewer (a fuzz find).
    if (d <= 3 && faces.size() < h.facets.size()) std::abort();
    const std::vector<std::int32_t> found = hullkit::locate_nd(p.data(), t, p.data(), count);
    for (std::size_t q = 0; q < count; ++q) {
        if (found[q] < 0) std::abort();
        const std::uint32_t* s = &t.simplices[static_cast<std::size_t>(found[q]) * c];
        if (std::count(s, s + c, t.representative[q]) != 1) std::abort();
    }
    // Voronoi volumes: inf for every point on the hull (a corner of a face without neighbour), NaN
    // for a repeated point (in no simplex); the rest in floating point, only computed.
    const std::vector<double> volume = hullkit::voronoi_nd_volumes(p.data(), count, d, t.simplices.data(), m);
    if (volume.size() != count) std::abort();
    for (const std::uint32_t v : faces)
        if (!(volume[v] > 1e308)) std::abort();
    for (std::size_t q = 0; q < count; ++q)
        if (t.representative[q] != q && volume[q] == volume[q]) std::abort();
    return 0;
}
