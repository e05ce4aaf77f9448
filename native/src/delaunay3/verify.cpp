// verify_delaunay3: an exact check of a tetrahedralization, independent of how it was built. It uses
// only the tetrahedra and the points (not neighbours or hull from the algorithm), exact orient3d
// and insphere (and, for ties, the perturbed predicates), and sorting; see delaunay3.hpp.
//
// Why these properties suffice: positively oriented tetrahedra whose faces are each shared by at
// most two, lying on opposite sides, cover every point of space the same number of times on both
// sides of each interior face; with a boundary that is one closed, connected, locally convex
// surface (a convex polytope's boundary), that number is 1 inside and 0 outside, so they
// triangulate a convex polytope; every point being a vertex makes it the convex hull. Euler's
// V - E + F - T = 1 confirms a ball. Every interior face passing the empty-sphere test makes it
// Delaunay (locally Delaunay implies globally Delaunay); under the perturbation, the unique one.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "delaunay3_internal.hpp"

namespace hullkit {
namespace {

using delaunay3_detail::kFaceCorners;
using delaunay3_detail::kGhost;

constexpr std::size_t kMaxListedProblems = 40;

struct Reporter {
    Delaunay3VerifyReport& report;
    void operator()(const std::string& message) {
        report.ok = false;
        if (report.problems.size() < kMaxListedProblems) report.problems.push_back(message);
        ++report.problem_count;
    }
};

std::string tet_text(std::size_t t, const std::uint32_t* v) {
    return "tetrahedron " + std::to_string(t) + " (" + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " +
           std::to_string(v[2]) + " " + std::to_string(v[3]) + ")";
}

/// One face of one tetrahedron, by its sorted corners.
struct FaceRecord {
    std::array<std::uint32_t, 3> key;
    std::uint32_t tet;
    std::uint32_t face;
    bool operator<(const FaceRecord& o) const {
        return key < o.key || (key == o.key && (tet < o.tet || (tet == o.tet && face < o.face)));
    }
};

}  // namespace

Delaunay3VerifyReport verify_delaunay3(PointSpan points, const std::uint32_t* tets, std::size_t count, bool perturbed) {
    Delaunay3VerifyReport report;
    Reporter problem{report};
    const std::size_t n = points.count;
    for (std::size_t e = 0; e < 4 * count; ++e) {
        if (tets[e] >= n) {
            problem(tet_text(e / 4, tets + 4 * (e / 4)) + " has index " + std::to_string(tets[e]) + " but there are " +
                    std::to_string(n) + " points");
        }
    }
    if (!report.ok) return report;

    // The same exact power-of-two rescaling as delaunay3().
    for (std::size_t i = 0; i < 3 * n; ++i) {
        if (!(std::fabs(points.xyz[i]) <= std::numeric_limits<double>::max())) {
            problem("point " + std::to_string(i / 3) + " has a non-finite coordinate");
            return report;
        }
    }
    int exponent = 0;
    if (!delaunay3_detail::scale_exponent_of(points, &exponent)) {
        problem("coordinates span too many orders of magnitude for exact in-sphere tests");
        return report;
    }
    delaunay3_detail::Points scaled;
    scaled.xyz.resize(3 * n);
    double lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis) lo[axis] = std::numeric_limits<double>::infinity(), hi[axis] = -lo[axis];
    for (std::size_t i = 0; i < 3 * n; ++i) {
        scaled.xyz[i] = std::ldexp(points.xyz[i], exponent);
        lo[i % 3] = std::min(lo[i % 3], scaled.xyz[i]);
        hi[i % 3] = std::max(hi[i % 3], scaled.xyz[i]);
    }
    for (int axis = 0; axis < 3 && n > 0; ++axis) scaled.span = std::max(scaled.span, hi[axis] - lo[axis]);
    const delaunay3_detail::Predicates predicates(scaled, false, false);  // not the lattice shortcut: an independent check

    // Distinct points: each index stands for the lowest index with the same coordinates.
    std::vector<std::uint32_t> order(n), representative(n);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const double* p = points[a];
        const double* q = points[b];
        if (p[0] != q[0]) return p[0] < q[0];
        if (p[1] != q[1]) return p[1] < q[1];
        if (p[2] != q[2]) return p[2] < q[2];
        return a < b;
    });
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t i = order[k];
        const bool same = k > 0 && points[i][0] == points[order[k - 1]][0] && points[i][1] == points[order[k - 1]][1] &&
                          points[i][2] == points[order[k - 1]][2];
        representative[i] = same ? representative[order[k - 1]] : i;
        if (!same) ++report.distinct_points;
    }

    // Each tetrahedron: distinct points (representatives), positively oriented.
    std::vector<std::uint8_t> used(n, 0);
    for (std::size_t t = 0; t < count; ++t) {
        const std::uint32_t* v = tets + 4 * t;
        bool fine = true;
        for (int i = 0; i < 4; ++i) {
            used[v[i]] = 1;
            if (representative[v[i]] != v[i]) {
                problem(tet_text(t, v) + " uses point " + std::to_string(v[i]) + ", a duplicate of point " +
                        std::to_string(representative[v[i]]));
                fine = false;
            }
            for (int j = i + 1; j < 4; ++j)
                if (v[i] == v[j]) {
                    problem(tet_text(t, v) + " repeats a corner");
                    fine = false;
                }
        }
        if (fine && predicates.orient(v[0], v[1], v[2], v[3]) <= 0) {
            problem(tet_text(t, v) + (predicates.orient(v[0], v[1], v[2], v[3]) == 0 ? " is flat" : " is negatively oriented"));
        }
    }
    for (std::size_t i = 0; i < n; ++i)
        if (representative[i] == i && !used[i]) problem("point " + std::to_string(i) + " is in no tetrahedron");
    if (!report.ok) return report;

    // Faces: shared by at most two tetrahedra on opposite sides, interior ones locally Delaunay.
    std::vector<FaceRecord> faces(4 * count);
    for (std::size_t t = 0; t < count; ++t)
        for (std::uint32_t k = 0; k < 4; ++k) {
            std::array<std::uint32_t, 3> key;
            for (int i = 0; i < 3; ++i) key[i] = tets[4 * t + kFaceCorners[k][i]];
            std::sort(key.begin(), key.end());
            faces[4 * t + k] = {key, static_cast<std::uint32_t>(t), k};
        }
    std::sort(faces.begin(), faces.end());
    std::vector<std::array<std::uint32_t, 3>> boundary;  // outward triangles
    std::size_t interior_faces = 0;
    for (std::size_t i = 0; i < faces.size();) {
        std::size_t j = i + 1;
        while (j < faces.size() && faces[j].key == faces[i].key) ++j;
        const FaceRecord& a = faces[i];
        const std::uint32_t* ta = tets + 4 * std::size_t{a.tet};
        if (j - i == 1) {
            boundary.push_back({ta[kFaceCorners[a.face][0]], ta[kFaceCorners[a.face][1]], ta[kFaceCorners[a.face][2]]});
        } else if (j - i > 2) {
            problem("face (" + std::to_string(a.key[0]) + " " + std::to_string(a.key[1]) + " " + std::to_string(a.key[2]) +
                    ") is in " + std::to_string(j - i) + " tetrahedra");
        } else {
            ++interior_faces;
            const FaceRecord& b = faces[i + 1];
            const std::uint32_t* tb = tets + 4 * std::size_t{b.tet};
            const std::uint32_t opposite_b = tb[b.face];
            // b's far corner must lie beyond a's face (a's face turned outward from a).
            const std::uint32_t* f = ta;
            if (predicates.orient(f[kFaceCorners[a.face][0]], f[kFaceCorners[a.face][1]], f[kFaceCorners[a.face][2]], opposite_b) <= 0) {
                problem(tet_text(a.tet, ta) + " and " + tet_text(b.tet, tb) + " overlap across a face");
            } else {
                const int inside = perturbed ? predicates.insphere_perturbed(ta[0], ta[1], ta[2], ta[3], opposite_b)
                                             : insphere(predicates.p(ta[0]), predicates.p(ta[1]), predicates.p(ta[2]),
                                                        predicates.p(ta[3]), predicates.p(opposite_b));
                if (inside > 0 || (perturbed && inside == 0)) {
                    problem("point " + std::to_string(opposite_b) + " is inside the circumsphere of " + tet_text(a.tet, ta) +
                            (inside == 0 ? " (a tie broken the other way)" : ""));
                }
            }
        }
        i = j;
    }
    report.hull_triangles = boundary.size();

    // The boundary: a closed oriented surface (each edge in two triangles, opposite directions),
    // locally convex (and Delaunay within coplanar hull faces under the perturbation), connected,
    // a sphere by Euler's formula.
    struct EdgeRecord {
        std::uint32_t from, to, triangle;
        bool operator<(const EdgeRecord& o) const {
            return from < o.from || (from == o.from && (to < o.to || (to == o.to && triangle < o.triangle)));
        }
    };
    std::vector<EdgeRecord> edges;
    edges.reserve(3 * boundary.size());
    for (std::size_t f = 0; f < boundary.size(); ++f)
        for (int k = 0; k < 3; ++k) edges.push_back({boundary[f][k], boundary[f][(k + 1) % 3], static_cast<std::uint32_t>(f)});
    std::sort(edges.begin(), edges.end());
    std::vector<std::uint32_t> parent(boundary.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::size_t boundary_vertices = 0;
    for (std::size_t e = 0; e < edges.size(); ++e) {
        if (e == 0 || edges[e].from != edges[e - 1].from) ++boundary_vertices;
        const EdgeRecord& edge = edges[e];
        if (e + 1 < edges.size() && edges[e + 1].from == edge.from && edges[e + 1].to == edge.to) {
            problem("hull edge " + std::to_string(edge.from) + "-" + std::to_string(edge.to) + " is in two hull triangles the same way");
            continue;
        }
        const auto twin = std::lower_bound(edges.begin(), edges.end(), EdgeRecord{edge.to, edge.from, 0});
        if (twin == edges.end() || twin->from != edge.to || twin->to != edge.from) {
            problem("hull edge " + std::to_string(edge.from) + "-" + std::to_string(edge.to) + " has no hull triangle beyond it");
            continue;
        }
        parent[find(edge.triangle)] = find(twin->triangle);
        if (edge.from > edge.to) continue;  // each edge once below
        const auto& a = boundary[edge.triangle];
        const auto& b = boundary[twin->triangle];
        std::uint32_t beyond = kGhost;
        for (const std::uint32_t v : b)
            if (v != edge.from && v != edge.to) beyond = v;
        const int side = predicates.orient(a[0], a[1], a[2], beyond);
        if (side > 0) {
            problem("the hull is not convex at edge " + std::to_string(edge.from) + "-" + std::to_string(edge.to));
        } else if (side == 0 && perturbed && predicates.coplanar_perturbed(a[0], a[1], a[2], beyond) >= 0) {
            problem("hull triangles (" + std::to_string(a[0]) + " " + std::to_string(a[1]) + " " + std::to_string(a[2]) +
                    ") and its coplanar neighbour break the tie rule at edge " + std::to_string(edge.from) + "-" +
                    std::to_string(edge.to));
        }
    }
    std::size_t components = 0;
    for (std::size_t f = 0; f < boundary.size(); ++f) components += find(static_cast<std::uint32_t>(f)) == f;
    if (components != 1) problem("the hull surface has " + std::to_string(components) + " pieces");
    if (boundary.size() + 4 != 2 * boundary_vertices) {
        problem("the hull surface has " + std::to_string(boundary.size()) + " triangles on " +
                std::to_string(boundary_vertices) + " vertices, not a sphere's 2V - 4");
    }

    // Euler: V - E + F - T = 1 for a ball.
    std::vector<std::uint64_t> all_edges;
    all_edges.reserve(6 * count);
    for (std::size_t t = 0; t < count; ++t)
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                const std::uint32_t a = tets[4 * t + i], b = tets[4 * t + j];
                all_edges.push_back(a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a));
            }
    std::sort(all_edges.begin(), all_edges.end());
    const std::size_t edge_count = std::unique(all_edges.begin(), all_edges.end()) - all_edges.begin();
    const std::size_t face_count = interior_faces + boundary.size();
    const long long euler = static_cast<long long>(report.distinct_points) - static_cast<long long>(edge_count) +
                            static_cast<long long>(face_count) - static_cast<long long>(count);
    if (report.ok && euler != 1) problem("V - E + F - T = " + std::to_string(euler) + ", not 1 (not a ball)");
    return report;
}

}  // namespace hullkit
