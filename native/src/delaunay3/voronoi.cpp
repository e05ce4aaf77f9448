// delaunay3_voronoi: the Voronoi diagram dual to the tetrahedralization. Vertices are circumcentres
// (one per Delaunay cell: tetrahedra across a face whose in-sphere test is exactly 0 share it),
// faces are the rings of tetrahedra around each edge, cells the faces around each point.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "delaunay3_internal.hpp"

namespace hullkit {
namespace {

/// The circumcentre of a, b, c, d (rounded), from differences to a:
/// a + (|ba|^2 (ca x da) + |ca|^2 (da x ba) + |da|^2 (ba x ca)) / (2 det[ba; ca; da]).
void circumcentre(const double* a, const double* b, const double* c, const double* d, double* out) {
    double ba[3], ca[3], da[3];
    for (int k = 0; k < 3; ++k) ba[k] = b[k] - a[k], ca[k] = c[k] - a[k], da[k] = d[k] - a[k];
    auto cross = [](const double* u, const double* v, double* w) {
        w[0] = u[1] * v[2] - u[2] * v[1];
        w[1] = u[2] * v[0] - u[0] * v[2];
        w[2] = u[0] * v[1] - u[1] * v[0];
    };
    auto dot = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
    double cd[3], db[3], bc[3];
    cross(ca, da, cd);
    cross(da, ba, db);
    cross(ba, ca, bc);
    const double denominator = 2.0 * dot(ba, cd);
    const double lb = dot(ba, ba), lc = dot(ca, ca), ld = dot(da, da);
    for (int k = 0; k < 3; ++k) out[k] = a[k] + (lb * cd[k] + lc * db[k] + ld * bc[k]) / denominator;
}

/// 6 x the signed volume of the tetrahedron p, a, b, c.
double volume6(const double* p, const double* a, const double* b, const double* c) {
    double u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k) u[k] = a[k] - p[k], v[k] = b[k] - p[k], w[k] = c[k] - p[k];
    return u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

}  // namespace

Voronoi3 delaunay3_voronoi(PointSpan points, const Delaunay3& d) {
    Voronoi3 out;
    const std::size_t n = points.count;
    out.cell_offsets.assign(n + 1, 0);
    out.volume.assign(n, std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < n && i < d.representative.size(); ++i)
        if (d.representative[i] != i) out.volume[i] = std::numeric_limits<double>::quiet_NaN();
    const std::size_t count = d.tetrahedron_count();
    int exponent = 0;
    if (d.dimension != 3 || count == 0 || !delaunay3_detail::scale_exponent_of(points, &exponent)) return out;
    const double scale = std::ldexp(1.0, exponent), unscale = std::ldexp(1.0, -exponent);
    auto scaled = [&](std::uint32_t i, double* p) {
        for (int k = 0; k < 3; ++k) p[k] = points[i][k] * scale;
        return p;
    };

    // Delaunay cells: tetrahedra joined across faces whose far corner is exactly on the sphere.
    std::vector<std::uint32_t> parent(count);
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t t) {
        while (parent[t] != t) t = parent[t] = parent[parent[t]];
        return t;
    };
    for (std::size_t t = 0; t < count; ++t) {
        double p[5][3];
        const std::uint32_t* v = &d.tetrahedra[4 * t];
        for (int k = 0; k < 4; ++k) {
            const std::int32_t u = d.neighbors[4 * t + k];
            if (u < static_cast<std::int32_t>(t)) continue;  // each interior face once (and not the hull's)
            const std::uint32_t* w = &d.tetrahedra[4 * static_cast<std::size_t>(u)];
            std::uint32_t far = w[0];
            for (int j = 0; j < 4; ++j)
                if (std::find(v, v + 4, w[j]) == v + 4) far = w[j];
            if (insphere(scaled(v[0], p[0]), scaled(v[1], p[1]), scaled(v[2], p[2]), scaled(v[3], p[3]),
                         scaled(far, p[4])) == 0) {
                const std::uint32_t a = find(static_cast<std::uint32_t>(t)), b = find(static_cast<std::uint32_t>(u));
                parent[std::max(a, b)] = std::min(a, b);
            }
        }
    }
    out.tetrahedron_vertex.resize(count);
    for (std::size_t t = 0; t < count; ++t) {
        const std::uint32_t root = find(static_cast<std::uint32_t>(t));
        if (root == t) {
            out.tetrahedron_vertex[t] = static_cast<std::uint32_t>(out.vertices.size() / 3);
            double p[4][3], c[3];
            const std::uint32_t* v = &d.tetrahedra[4 * t];
            circumcentre(scaled(v[0], p[0]), scaled(v[1], p[1]), scaled(v[2], p[2]), scaled(v[3], p[3]), c);
            for (int k = 0; k < 3; ++k) out.vertices.push_back(c[k] * unscale);
        } else {
            out.tetrahedron_vertex[t] = out.tetrahedron_vertex[root];  // the root has the lower index
        }
    }

    // Faces: the ring of tetrahedra around each edge p < q, walked counter-clockwise about p -> q
    // (right-handed). In a positively oriented tetrahedron whose corners in an even order are
    // p, q, c, d, the turn about p -> q goes from c to d; the next tetrahedron is across the face
    // opposite c. Each edge is taken from the lowest-index tetrahedron around it.
    std::vector<std::uint32_t> ring;
    std::vector<std::int32_t> ring_tets;
    out.face_offsets.push_back(0);
    for (std::size_t t = 0; t < count; ++t) {
        const std::uint32_t* v = &d.tetrahedra[4 * t];
        for (int i = 0; i < 4; ++i) {
            for (int j = i + 1; j < 4; ++j) {
                int a = i, b = j;
                if (v[b] < v[a]) std::swap(a, b);
                int rest[2], r = 0;
                for (int k = 0; k < 4; ++k)
                    if (k != i && k != j) rest[r++] = k;
                // Parity of (a, b, rest0, rest1) as a permutation of 0..3.
                const int perm[4] = {a, b, rest[0], rest[1]};
                int inversions = 0;
                for (int x = 0; x < 4; ++x)
                    for (int y = x + 1; y < 4; ++y) inversions += perm[x] > perm[y];
                if (inversions & 1) std::swap(rest[0], rest[1]);
                const std::uint32_t p = v[a], q = v[b];
                // Walk forward (across the face opposite c) until back at t or off the hull.
                ring_tets.assign(1, static_cast<std::int32_t>(t));
                std::uint32_t c = v[rest[0]], dd = v[rest[1]];
                bool owner = true, closed = false;
                auto step = [&](std::int32_t from, std::uint32_t across_corner, std::uint32_t keep, std::uint32_t* next_far) {
                    const std::uint32_t* w = &d.tetrahedra[4 * static_cast<std::size_t>(from)];
                    const int k = static_cast<int>(std::find(w, w + 4, across_corner) - w);
                    const std::int32_t u = d.neighbors[4 * static_cast<std::size_t>(from) + k];
                    if (u >= 0) {
                        const std::uint32_t* x = &d.tetrahedra[4 * static_cast<std::size_t>(u)];
                        for (int m = 0; m < 4; ++m)
                            if (x[m] != p && x[m] != q && x[m] != keep) *next_far = x[m];
                    }
                    return u;
                };
                std::int32_t cur = static_cast<std::int32_t>(t);
                for (;;) {
                    std::uint32_t far = 0;
                    const std::int32_t u = step(cur, c, dd, &far);
                    if (u < 0) break;
                    if (u == static_cast<std::int32_t>(t)) {
                        closed = true;
                        break;
                    }
                    if (u < static_cast<std::int32_t>(t)) {
                        owner = false;
                        break;
                    }
                    ring_tets.push_back(u);
                    c = dd;
                    dd = far;
                    cur = u;
                }
                if (!owner) continue;
                if (!closed) {
                    // A hull edge: walk backwards from t too (across the face opposite d), and
                    // put that part first so the chain runs counter-clockwise.
                    std::vector<std::int32_t> back;
                    std::uint32_t bc = v[rest[0]], bd = v[rest[1]];
                    cur = static_cast<std::int32_t>(t);
                    for (;;) {
                        std::uint32_t far = 0;
                        const std::int32_t u = step(cur, bd, bc, &far);
                        if (u < 0) break;
                        if (u < static_cast<std::int32_t>(t)) {
                            owner = false;
                            break;
                        }
                        back.push_back(u);
                        bd = bc;
                        bc = far;
                        cur = u;
                    }
                    if (!owner) continue;
                    // Both rays from one vertex, perpendicular to two coplanar hull triangles
                    // (p q bc, p q dd): one ray, p q a diagonal of a cocircular hull polygon, and
                    // the "face" only a half-line: none (a cube's face diagonals have none).
                    bool one_vertex = true;
                    const std::uint32_t only = out.tetrahedron_vertex[t];
                    for (const std::int32_t u : ring_tets) one_vertex = one_vertex && out.tetrahedron_vertex[static_cast<std::size_t>(u)] == only;
                    for (const std::int32_t u : back) one_vertex = one_vertex && out.tetrahedron_vertex[static_cast<std::size_t>(u)] == only;
                    double a[3], b[3], e[3], f[3];
                    if (one_vertex && orient3d(scaled(p, a), scaled(q, b), scaled(bc, e), scaled(dd, f)) == 0) continue;
                    std::reverse(back.begin(), back.end());
                    back.insert(back.end(), ring_tets.begin(), ring_tets.end());
                    ring_tets.swap(back);
                }
                // Voronoi vertices around the face, repeats (tetrahedra of one cell) collapsed.
                ring.clear();
                for (const std::int32_t u : ring_tets) {
                    const std::uint32_t vertex = out.tetrahedron_vertex[static_cast<std::size_t>(u)];
                    if (ring.empty() || ring.back() != vertex) ring.push_back(vertex);
                }
                if (closed && ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
                if (closed && ring.size() < 3) continue;  // inside one Delaunay cell: no face
                out.face_points.push_back(p);
                out.face_points.push_back(q);
                out.face_vertices.insert(out.face_vertices.end(), ring.begin(), ring.end());
                out.face_offsets.push_back(static_cast<std::uint32_t>(out.face_vertices.size()));
                out.face_bounded.push_back(closed ? 1 : 0);
            }
        }
    }

    // Cells: the faces around each point; volumes of the bounded ones (pyramids from the point over
    // each face's fan: the faces turn counter-clockwise seen from outside p's cell, and clockwise
    // seen from outside q's).
    const std::size_t faces = out.face_count();
    for (std::size_t f = 0; f < faces; ++f) {
        ++out.cell_offsets[out.face_points[2 * f] + 1];
        ++out.cell_offsets[out.face_points[2 * f + 1] + 1];
    }
    for (std::size_t i = 0; i < n; ++i) out.cell_offsets[i + 1] += out.cell_offsets[i];
    out.cell_faces.resize(2 * faces);
    {
        std::vector<std::uint32_t> fill(out.cell_offsets.begin(), out.cell_offsets.end() - 1);
        for (std::size_t f = 0; f < faces; ++f) {
            out.cell_faces[fill[out.face_points[2 * f]]++] = static_cast<std::uint32_t>(f);
            out.cell_faces[fill[out.face_points[2 * f + 1]]++] = static_cast<std::uint32_t>(f);
        }
    }
    std::vector<double> sum(n, 0.0);
    std::vector<std::uint8_t> open(n, 0);
    for (std::size_t f = 0; f < faces; ++f) {
        const std::uint32_t p = out.face_points[2 * f], q = out.face_points[2 * f + 1];
        if (!out.face_bounded[f]) {
            open[p] = open[q] = 1;
            continue;
        }
        const std::uint32_t* ring_v = &out.face_vertices[out.face_offsets[f]];
        const std::size_t m = out.face_offsets[f + 1] - out.face_offsets[f];
        double sp = 0, sq = 0;
        const double* v0 = &out.vertices[3 * ring_v[0]];
        for (std::size_t k = 1; k + 1 < m; ++k) {
            const double* v1 = &out.vertices[3 * ring_v[k]];
            const double* v2 = &out.vertices[3 * ring_v[k + 1]];
            sp += volume6(points[p], v0, v1, v2);
            sq -= volume6(points[q], v0, v1, v2);
        }
        sum[p] += sp;
        sum[q] += sq;
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (d.representative[i] != i) continue;
        out.volume[i] = open[i] ? std::numeric_limits<double>::infinity() : sum[i] / 6.0;
    }
    return out;
}

}  // namespace hullkit
