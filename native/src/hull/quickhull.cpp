// Quickhull in 3D (Barber, Dobkin & Huhdanpaa 1996) with exact side tests: the serial algorithm
// (the face pool, the outside sets, the horizon) and its entry quickhull_faces. The culling and
// spatial order of its input are in quickhull_candidates.cpp, the split on threads in
// quickhull_split.cpp, the plane and side tests in quickhull_internal.hpp.
//
// Layout: faces are triangles in one pooled array (dead faces are recycled), each with its three
// vertices, the three opposite half-edges (twin = 3 * face + edge) and the head of a singly linked
// list of the points outside it (links in one per-point array). A face's outside points are those
// strictly above it; a point above no face is inside the current hull and dropped for good.
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "hull_internal.hpp"
#include "large_array.hpp"
#include "parallel.hpp"
#include "hullkit/predicates.hpp"
#include "quickhull_internal.hpp"

namespace hullkit::detail {
namespace quickhull_detail {
namespace {

struct Face {
    Index v[3];     // counter-clockwise seen from outside
    Index twin[3];  // twin[k]: the half-edge (3 * face + edge) opposite edge v[k] -> v[k + 1]
    Index outside;  // the outside list's first point, the farthest (see push_outside); kNone if none
    Index mark;     // visit stamp of the current iteration; kDeadFace once the face is gone; at
                    // the end, the face's number among the live ones
    // 32 bytes a face (a sphere's hull has twice as many faces as points): no farthest point or
    // height beside the list, no flag beside the mark.

    bool alive() const { return mark != kDeadFace; }
    static constexpr Index kDeadFace = kNone;
};

class Quickhull {
public:
    /// `points` are the candidates, `original[i]` the caller's index of candidate i.
    Quickhull(PointSpan points, const std::vector<Index>& original)
        : points_(points), original_(original), next_(points.count, kNone) {
        faces_.reserve(2 * points.count + 16);  // a hull of n points has at most 2n - 4 faces
        extent_ = largest_span(points);
    }

    /// The hull as a closed surface of triangles (candidate indices) with their neighbours and
    /// which neighbours lie in the same plane (exactly).
    bool run(const Simplex& simplex, Surface& surface, std::string& error) {
        start(simplex);
        while (!pending_.empty()) {
            const Index f = pending_.back();
            pending_.pop_back();
            if (!faces_[f].alive() || faces_[f].outside == kNone) continue;
            if (!add_point(f, error)) return false;
        }
        release(next_);
        release(pending_);
        // Number the live faces consecutively (in their marks: the search is over).
        Index live = 0;
        for (std::size_t f = 0; f < faces_.size(); ++f) {
            if (faces_[f].alive()) faces_[f].mark = live++;
        }
        surface.triangles.resize(3 * std::size_t{live});
        surface.twins.resize(3 * std::size_t{live});
        surface.flat.assign(3 * std::size_t{live}, 0);
        for (std::size_t f = 0; f < faces_.size(); ++f) {
            const Face& face = faces_[f];
            if (!face.alive()) continue;
            const std::size_t t = face.mark;
            std::copy(face.v, face.v + 3, &surface.triangles[3 * t]);
            const Plane plane = plane_of(static_cast<Index>(f));
            for (int k = 0; k < 3; ++k) {
                const Index g = face.twin[k] / 3;
                const Index other = 3 * faces_[g].mark + face.twin[k] % 3;
                surface.twins[3 * t + k] = other;
                if (g < f) {  // each pair once
                    surface.flat[3 * t + k] = surface.flat[other];
                    continue;
                }
                const Index apex = faces_[g].v[(face.twin[k] % 3 + 2) % 3];  // g's corner off the shared edge
                double h;
                surface.flat[3 * t + k] = side(plane, apex, &h) == 0;
            }
        }
        return true;
    }

private:
    const double* at(Index i) const { return points_[i]; }

    template <class Vector>
    static void release(Vector& v) {
        Vector().swap(v);
    }

    Plane plane_of(Index f) const {
        const Face& face = faces_[f];
        return plane_through(points_, face.v[0], face.v[1], face.v[2], extent_);
    }

    /// Exact side of point `p` from `plane`: +1 strictly above.
    int side(const Plane& plane, Index p, double* h) const { return side_of(points_, plane, at(p), h); }

    Index new_face(Index a, Index b, Index c) {
        Index f;
        if (!free_.empty()) {
            f = free_.back();
            free_.pop_back();
        } else {
            f = static_cast<Index>(faces_.size());
            faces_.emplace_back();
        }
        Face& face = faces_[f];
        face.v[0] = a;
        face.v[1] = b;
        face.v[2] = c;
        face.outside = kNone;
        face.mark = 0;
        return f;
    }

    void link(Index half_edge, Index other) {
        faces_[half_edge / 3].twin[half_edge % 3] = other;
        faces_[other / 3].twin[other % 3] = half_edge;
    }

    /// Puts point p on face f's outside list, whose first point is the farthest from f's plane
    /// (`plane`; h: p's rounded height above it, compared with the first point's computed again
    /// the same way); ties go to the lower index so that of identical points the lowest index is
    /// chosen. Any other point goes second.
    void push_outside(Index f, const Plane& plane, Index p, double h) {
        Face& face = faces_[f];
        const Index first = face.outside;
        if (first == kNone) {
            pending_.push_back(f);
            next_[p] = kNone;
            face.outside = p;
            return;
        }
        const double first_height = height(plane, at(first));
        if (h > first_height || (h == first_height && original_[p] < original_[first])) {
            next_[p] = first;
            face.outside = p;
        } else {
            next_[p] = next_[first];
            next_[first] = p;
        }
    }

    /// The point goes to the first plane it is strictly above, trying first the plane that took
    /// the previous point (outside lists are in spatial order, so neighbours tend to share one).
    void assign(const std::vector<Plane>& planes, const std::vector<Index>& owners, Index p) {
        const std::size_t m = planes.size();
        std::size_t k = last_hit_ < m ? last_hit_ : 0;
        for (std::size_t tried = 0; tried < m; ++tried, k = k + 1 == m ? 0 : k + 1) {
            double h;
            if (side(planes[k], p, &h) > 0) {
                push_outside(owners[k], planes[k], p, h);
                last_hit_ = k;
                return;
            }
        }
    }

    void start(const Simplex& s) {
        // Orient the tetrahedron so that d is below (a, b, c); then every face below is
        // counter-clockwise seen from outside (its fourth point lies below it).
        Index a = s.p[0], b = s.p[1], c = s.p[2], d = s.p[3];
        if (orient3d(at(a), at(b), at(c), at(d)) > 0) std::swap(b, c);
        const Index f0 = new_face(a, b, c);  // a->b, b->c, c->a
        const Index f1 = new_face(a, d, b);  // a->d, d->b, b->a
        const Index f2 = new_face(b, d, c);  // b->d, d->c, c->b
        const Index f3 = new_face(c, d, a);  // c->d, d->a, a->c
        link(3 * f0 + 0, 3 * f1 + 2);  // a->b | b->a
        link(3 * f0 + 1, 3 * f2 + 2);  // b->c | c->b
        link(3 * f0 + 2, 3 * f3 + 2);  // c->a | a->c
        link(3 * f1 + 0, 3 * f3 + 1);  // a->d | d->a
        link(3 * f1 + 1, 3 * f2 + 0);  // d->b | b->d
        link(3 * f2 + 1, 3 * f3 + 0);  // d->c | c->d

        std::vector<Plane> planes;
        std::vector<Index> owners = {f0, f1, f2, f3};
        for (Index f : owners) planes.push_back(plane_of(f));
        for (Index q = 0; q < points_.count; ++q) {
            if (q == a || q == b || q == c || q == d) continue;
            assign(planes, owners, q);
        }
    }

    /// One quickhull step: the farthest point above face f joins the hull.
    bool add_point(Index f, std::string& error) {
        const Index eye = faces_[f].outside;  // the farthest
        ++stamp_;
        // Visible faces by depth-first search; the horizon comes out as a counter-clockwise cycle
        // of half-edges on the visible side.
        visible_.clear();
        horizon_.clear();
        faces_[f].mark = stamp_;
        visible_.push_back(f);
        dfs_.clear();
        dfs_.push_back({f, 0, 0});
        while (!dfs_.empty()) {
            Frame& top = dfs_.back();
            if (top.done == 3) {
                dfs_.pop_back();
                continue;
            }
            const int k = (top.first + top.done) % 3;
            ++top.done;
            const Index here = top.face;
            const Index opposite = faces_[here].twin[k];
            const Index g = opposite / 3;
            if (faces_[g].mark == stamp_) continue;  // visible, seen already
            double h;
            if (side(plane_of(g), eye, &h) > 0) {
                faces_[g].mark = stamp_;
                visible_.push_back(g);
                dfs_.push_back({g, static_cast<int>(opposite % 3 + 1) % 3, 0});
            } else {
                horizon_.push_back(3 * here + static_cast<Index>(k));
            }
        }

        // The cone of new faces from the eye over the horizon.
        new_faces_.clear();
        for (Index half_edge : horizon_) {
            const Face& old = faces_[half_edge / 3];
            const int k = static_cast<int>(half_edge % 3);
            const Index outer = old.twin[k];
            const Index nf = new_face(old.v[k], old.v[(k + 1) % 3], eye);
            link(3 * nf + 0, outer);
            new_faces_.push_back(nf);
        }
        const std::size_t m = new_faces_.size();
        for (std::size_t i = 0; i < m; ++i) {
            const Index here = new_faces_[i];
            const Index next = new_faces_[(i + 1) % m];
            if (faces_[here].v[1] != faces_[next].v[0]) {
                error = "quickhull: the horizon is not a cycle (internal error)";
                return false;
            }
            link(3 * here + 1, 3 * next + 2);
        }

        // Hand the visible faces' outside points to the new faces; the rest are inside now.
        planes_.clear();
        for (Index nf : new_faces_) planes_.push_back(plane_of(nf));
        for (Index v : visible_) {
            Face& face = faces_[v];
            for (Index q = face.outside; q != kNone;) {
                const Index after = next_[q];
                if (q != eye) assign(planes_, new_faces_, q);
                q = after;
            }
            face.outside = kNone;
            face.mark = Face::kDeadFace;
            free_.push_back(v);
        }
        return true;
    }

    PointSpan points_;
    const std::vector<Index>& original_;
    double extent_ = 0.0;
    LargeArray<Face> faces_;
    std::vector<Index> free_;
    LargeArray<Index> next_;      // outside-list links, one per point
    std::vector<Index> pending_;  // faces that got outside points
    Index stamp_ = 0;
    std::size_t last_hit_ = 0;  // the plane index that took the last assigned point

    // Scratch of one step, kept to avoid reallocation.
    std::vector<Index> visible_, horizon_, new_faces_;
    std::vector<Plane> planes_;
    struct Frame {
        Index face;
        int first;  // the edge to look across first
        int done;   // edges looked across so far
    };
    std::vector<Frame> dfs_;
};

}  // namespace

double largest_span(PointSpan points) {
    double lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis) lo[axis] = hi[axis] = points[0][axis];
    for (std::size_t i = 1; i < points.count; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = std::min(lo[axis], points[i][axis]);
            hi[axis] = std::max(hi[axis], points[i][axis]);
        }
    }
    return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
}

bool quickhull_surface(PointSpan points, const std::vector<Index>& original, const Simplex& simplex,
                       Surface& surface, std::string& error) {
    Quickhull quickhull(points, original);
    return quickhull.run(simplex, surface, error);
}

std::vector<CoplanarPair> coplanar_pairs(const Surface& surface) {
    std::vector<CoplanarPair> pairs;
    for (std::size_t h = 0; h < surface.twins.size(); ++h) {
        const Index t = static_cast<Index>(h / 3), u = surface.twins[h] / 3;
        if (surface.flat[h] && t < u) pairs.push_back({t, u});
    }
    return pairs;
}

bool run_quickhull(PointSpan points, const Simplex& simplex, std::vector<Index>& ids, LargeArray<double>& xyz,
                   Surface& surface, std::string& error, unsigned threads, LargeArray<double>* storage) {
    {
        LargeArray<std::uint64_t> keyed = candidates(points, simplex, threads);
        ids = spatial_order(points, keyed);
    }
    xyz.resize(3 * ids.size());
    constexpr std::size_t kBlock = std::size_t{1} << 16;
    parallel_for(threads, (ids.size() + kBlock - 1) / kBlock, [&](std::size_t block) {
        const std::size_t end = std::min(ids.size(), (block + 1) * kBlock);
        for (std::size_t k = block * kBlock; k < end; ++k) std::copy(points[ids[k]], points[ids[k]] + 3, &xyz[3 * k]);
    });
    Simplex local;
    local.dimension = 3;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        for (int corner = 0; corner < 4; ++corner) {
            if (ids[k] == simplex.p[corner]) local.p[corner] = static_cast<Index>(k);
        }
    }
    if (storage) *storage = LargeArray<double>();  // `points` is not read again: the copy is
    Quickhull quickhull(PointSpan(xyz.data(), ids.size()), ids);
    return quickhull.run(local, surface, error);
}

}  // namespace quickhull_detail

using quickhull_detail::coplanar_pairs;
using quickhull_detail::Index;
using quickhull_detail::run_quickhull;
using quickhull_detail::Surface;

bool quickhull_faces(PointSpan points, const Simplex& simplex, Polygons& faces, double* volume, double* area,
                     std::string& error, unsigned threads) {
    std::vector<Index> ids;
    LargeArray<double> xyz;
    Surface surface;
    if (!run_quickhull(points, simplex, ids, xyz, surface, error, threads)) return false;
    const PointSpan local_points(xyz.data(), ids.size());
    // Merging and measuring touch every corner: done on the local copy, which is in spatial order.
    // The faces are put in the canonical order first, so that the volume and area are summed in
    // an order that depends on the hull alone, not on the run that found it.
    faces = merge_coplanar_triangles(local_points, std::move(surface.triangles), coplanar_pairs(surface));
    canonical_order(faces, ids, threads);
    measure(local_points, faces, volume, area, threads);
    for (Index& v : faces.vertices) v = ids[v];
    return true;
}

}  // namespace hullkit::detail
