// Delaunay by incremental insertion (Bowyer-Watson) in Hilbert-curve order with a walking locate.
//
// The triangulation is kept closed like a sphere: every hull edge has a "ghost" triangle on its
// outer side whose third vertex is the point at infinity (kGhost). A new point p removes the
// triangles in conflict with it (the cavity) and is joined to the cavity's boundary:
//  * a finite triangle a, b, c (counter-clockwise) conflicts when p is strictly inside its
//    circumcircle: incircle(a, b, c, p) > 0, i.e. the lifted p is strictly below its lifted plane;
//  * a ghost triangle on hull edge x->y (interior on the right of x->y here, ghost on the left)
//    conflicts when p is strictly outside that edge, or exactly on the line strictly between x
//    and y (the limit of a circle through x, y and a point far away).
// The cavity is star-shaped from p, so the new triangles are never degenerate, and every
// decision is an exact orient2d / incircle on the original coordinates (a semi-static filter with
// one bound for the whole point set first, detail::incircle_static_bound; the adaptive predicate
// when it cannot tell; on a small lattice, exact/lattice.hpp, the plain floating-point determinant
// is exact, ties included, and decides alone). Points collinear with a
// hull edge become hull vertices. The result is a Delaunay triangulation; cocircular faces are
// merged afterwards (merge_cocircular_triangles) so that the shared canonical rule applies.
#include <algorithm>

#include "delaunay_internal.hpp"
#include "exact/lattice.hpp"
#include "hull/large_array.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit {
namespace delaunay_detail {
namespace {

class Triangulation {
public:
    Triangulation(PointSpan2 points, double span, bool lattice, std::size_t spare_points)
        : p_(points),
          ghost_(static_cast<std::uint32_t>(points.count)),
          incircle_bound_(detail::incircle_static_bound(span)),
          orient_bound_(detail::orient2d_static_bound(span)),
          lattice_(lattice) {
        const std::size_t capacity = 2 * (points.count + spare_points) + 4;  // finite + ghost triangles
        // Large arrays go on huge pages; smaller ones have the pages that a triangulation without
        // added points fills mapped in one call (large_array.hpp). The spare points' room stays
        // unmapped until used.
        const std::size_t filled = 2 * points.count + 4;
        detail::reserve_large(vertex_, 3 * capacity);
        detail::reserve_large(twin_, 3 * capacity);
        detail::populate(vertex_.data(), 3 * filled * sizeof(std::uint32_t));
        detail::populate(twin_.data(), 3 * filled * sizeof(std::uint32_t));
        detail::reserve_populated(mark_, capacity, filled);
        detail::reserve_populated(start_of_, points.count + 1, points.count + 1);
        start_of_.assign(points.count + 1, 0);
    }

    /// The first triangle a, b, c (counter-clockwise) and its three ghosts.
    void start(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        add(a, b, c);             // t0: edges a->b, b->c, c->a
        add(b, a, ghost_);        // t1: b->a, a->G, G->b
        add(c, b, ghost_);        // t2: c->b, b->G, G->c
        add(a, c, ghost_);        // t3: a->c, c->G, G->a
        link(0, 3);
        link(1, 6);
        link(2, 9);
        link(4, 11);   // a->G with G->a
        link(5, 7);    // G->b with b->G
        link(8, 10);   // G->c with c->G
        last_ = 0;
    }

    HULLKIT_STEP void insert(std::uint32_t i) {
        const double px = p_[i][0], py = p_[i][1];
        const std::uint32_t t0 = locate(px, py);
        // Collect the cavity by a search from t0 over conflicting neighbours. Each triangle tested
        // is marked with the verdict (stamp_: in the cavity, stamp_ + 1: not), so that one next
        // to two cavity triangles is tested once.
        stamp_ += 2;
        const std::uint32_t inside = stamp_, outside = stamp_ + 1;
        cavity_.clear();
        edges_.clear();
        // (Only cavity_ and edges_ grow during the search: the mesh's arrays stay where they are.)
        const std::uint32_t* const vertex = vertex_.data();
        const std::uint32_t* const twin = twin_.data();
        std::uint32_t* const marks = mark_.data();
        marks[t0] = inside;
        cavity_.push_back(t0);
        for (std::size_t k = 0; k < cavity_.size(); ++k) {
            const std::uint32_t t = cavity_[k];
            const std::uint32_t corner[3] = {vertex[3 * t], vertex[3 * t + 1], vertex[3 * t + 2]};
            for (std::uint32_t j = 0; j < 3; ++j) {
                const std::uint32_t f = twin[3 * t + j];
                const std::uint32_t u = f / 3;
                const std::uint32_t mark = marks[u];
                if (mark == inside) continue;
                if (mark != outside && conflicts(vertex + 3 * u, px, py)) {
                    marks[u] = inside;
                    cavity_.push_back(u);
                } else {
                    // A boundary edge: read (from, to, outside twin) now, before cavity slots are reused.
                    marks[u] = outside;
                    edges_.push_back({corner[j], corner[j == 2 ? 0 : j + 1], f, 0});
                }
            }
        }
        // One new triangle (from, to, i) per boundary edge, in the cavity's slots first.
        for (std::size_t k = 0; k < edges_.size(); ++k) {
            BoundaryEdge& edge = edges_[k];
            std::uint32_t t;
            if (k < cavity_.size()) {
                t = cavity_[k];
                vertex_[3 * t] = edge.from, vertex_[3 * t + 1] = edge.to, vertex_[3 * t + 2] = i;
            } else {
                t = add(edge.from, edge.to, i);
            }
            edge.slot = t;
            start_of_[edge.from] = t;
            twin_[3 * t] = edge.outside;
            twin_[edge.outside] = 3 * t;
        }
        for (const BoundaryEdge& edge : edges_) {
            const std::uint32_t t = edge.slot, u = start_of_[edge.to];
            twin_[3 * t + 1] = 3 * u + 2;
            twin_[3 * u + 2] = 3 * t + 1;
        }
        last_ = edges_[0].slot;
    }

    /// Hands over the mesh (ghost triangles included; with `marks` the marks too); the
    /// triangulation is left empty.
    void release(Mesh& mesh, bool marks) {
        mesh.ghost = ghost_;
        mesh.vertex = std::move(vertex_);
        mesh.twin = std::move(twin_);
        if (marks) mesh.mark = std::move(mark_), mesh.mark_limit = stamp_ + 2;
        vertex_ = {}, twin_ = {}, mark_ = {}, start_of_ = {};
    }

private:
    std::uint32_t add(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        vertex_.push_back(a), vertex_.push_back(b), vertex_.push_back(c);
        twin_.push_back(0), twin_.push_back(0), twin_.push_back(0);  // (set by the caller; inline, unlike resize)
        mark_.push_back(0);
        return static_cast<std::uint32_t>(vertex_.size() / 3 - 1);
    }
    void link(std::uint32_t e, std::uint32_t f) { twin_[e] = f, twin_[f] = e; }
    bool is_ghost(std::uint32_t t) const {
        return vertex_[3 * t] == ghost_ || vertex_[3 * t + 1] == ghost_ || vertex_[3 * t + 2] == ghost_;
    }

    /// Whether the triangle with these corners conflicts with p.
    bool conflicts(const std::uint32_t* corners, double px, double py) const {
        const std::uint32_t a = corners[0], b = corners[1], c = corners[2];
        if (a != ghost_ && b != ghost_ && c != ghost_) {
            return detail::incircle_semi_static(incircle_bound_, p_[a][0], p_[a][1], p_[b][0], p_[b][1], p_[c][0],
                                                p_[c][1], px, py, lattice_) > 0;
        }
        std::uint32_t x, y;
        ghost_edge(corners, ghost_, &x, &y);
        const double p[2] = {px, py};
        return beyond_hull_edge(p_[x], p_[y], p);
    }

    /// A triangle in conflict with p: the finite triangle containing it (closed), or the ghost of a
    /// hull edge that p is strictly outside of. Visibility walk with a varying first edge.
    std::uint32_t locate(double px, double py) {
        return visibility_walk(vertex_, twin_, ghost_, last_, seed_, [&](std::uint32_t a, std::uint32_t b) {
            const double* u = p_[a];
            const double* v = p_[b];
            return detail::orient2d_semi_static(orient_bound_, u[0], u[1], v[0], v[1], px, py, lattice_) < 0;
        });
    }

    PointSpan2 p_;
    std::uint32_t ghost_;
    double incircle_bound_, orient_bound_;  // semi-static filters for this point set
    bool lattice_;                          // stage A is exact: it decides inside the bounds too
    std::vector<std::uint32_t> vertex_;
    std::vector<std::uint32_t> twin_;
    std::vector<std::uint32_t> mark_;
    std::vector<std::uint32_t> start_of_;  // per vertex: the new triangle whose first edge leaves it
    std::vector<std::uint32_t> cavity_;
    struct BoundaryEdge {
        std::uint32_t from, to, outside;
        std::uint32_t slot;  // the new triangle on it
    };
    std::vector<BoundaryEdge> edges_;
    std::uint32_t stamp_ = 0;
    std::uint32_t last_ = 0;
    std::uint32_t seed_ = 1;
};

}  // namespace

Mesh incremental_mesh(const Input& input, const std::function<void(std::size_t, std::size_t)>& progress) {
    const PointSpan2 p = input.points;  // already in Hilbert order: insert them as they come
    const std::uint32_t count = static_cast<std::uint32_t>(p.count);
    // The first triangle: the first two points and the first point off their line.
    std::uint32_t k = 2;
    int o = 0;
    while ((o = orient2d(p[0][0], p[0][1], p[1][0], p[1][1], p[k][0], p[k][1])) == 0) ++k;
    Mesh mesh;
    {
        mesh.span = coordinate_span(p);
        mesh.lattice = detail::plane_lattice_exact(p.xy, p.count, mesh.span);
        Triangulation tri(p, mesh.span, mesh.lattice, input.spare_points);
        if (o > 0)
            tri.start(0, 1, k);
        else
            tri.start(1, 0, k);
        constexpr std::uint32_t kProgressEvery = 1u << 16;
        for (std::uint32_t j = 2; j < count; ++j) {
            if (j != k) tri.insert(j);
            if (progress && (j + 1) % kProgressEvery == 0) progress(j + 1, count);
        }
        if (progress) progress(count, count);
        tri.release(mesh, input.keep_marks);
    }
    return mesh;
}

Faces mesh_faces(PointSpan2 p, Mesh mesh) {
    // Finite triangles (counter-clockwise) with their twins (-1 across hull edges).
    const std::size_t count = mesh.vertex.size() / 3;
    const std::uint32_t ghost = mesh.ghost;
    std::vector<std::int32_t> index(count, -1);
    std::int32_t finite_count = 0;
    for (std::size_t t = 0; t < count; ++t) {
        const std::uint32_t* v = &mesh.vertex[3 * t];
        if (v[0] != ghost && v[1] != ghost && v[2] != ghost) index[t] = finite_count++;
    }
    std::vector<std::uint32_t> triangles(3 * static_cast<std::size_t>(finite_count));
    std::vector<std::int32_t> twin(triangles.size());
    for (std::size_t t = 0; t < count; ++t) {
        if (index[t] < 0) continue;
        for (int k = 0; k < 3; ++k) {
            const std::size_t e = 3 * static_cast<std::size_t>(index[t]) + k;
            triangles[e] = mesh.vertex[3 * t + k];
            const std::uint32_t f = mesh.twin[3 * t + k];
            twin[e] = index[f / 3] < 0 ? -1 : 3 * index[f / 3] + static_cast<std::int32_t>(f % 3);
        }
    }
    const bool lattice = mesh.lattice;
    mesh = Mesh();  // release the working mesh before merging
    return merge_cocircular_triangles(p, std::move(triangles), std::move(twin), lattice);
}

Faces incremental_faces(const Input& input) { return mesh_faces(input.points, incremental_mesh(input)); }

}  // namespace delaunay_detail
}  // namespace hullkit
