// Quickhull in 3D (Barber, Dobkin & Huhdanpaa 1996) with exact side tests.
//
// Layout: faces are triangles in one pooled array (dead faces are recycled), each with its three
// vertices, the three opposite half-edges (twin = 3 * face + edge) and the head of a singly linked
// list of the points outside it (links in one per-point array). A face's outside points are those
// strictly above it; a point above no face is inside the current hull and dropped for good.
//
// Before the main loop: points certified to lie strictly inside the hull of a few extreme points
// (a box shown, exactly, to be inside that hull) are dropped, so are repeats of a point (the
// lowest index stays), and the rest are copied in a space-filling-curve (Morton) order, so that
// the points above one face sit close in memory.
//
// Side tests: a rounded plane test with a proven error bound decides almost every case; only
// points within that bound of a plane go to the exact orient3d. Rounded distances are also used
// to pick the farthest point, which is a choice, not a decision about topology.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "hull_internal.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit::detail {
namespace {

using Index = std::uint32_t;
constexpr Index kNone = ~Index{0};

struct Face {
    Index v[3];     // counter-clockwise seen from outside
    Index twin[3];  // twin[k]: the half-edge (3 * face + edge) opposite edge v[k] -> v[k + 1]
    Index outside;  // first outside point, kNone if none
    Index farthest; // the outside point with the largest (rounded) height
    double far_height;
    Index mark;     // visit stamp of the current iteration
    bool alive;
};

/// A face's plane in rounded arithmetic, with the bound under which its sign is not trusted.
struct Plane {
    double ax, ay, az;  // a vertex
    double nx, ny, nz;  // (b - a) x (c - a), rounded
    double bound;
    Index v[3];
};

class Quickhull {
public:
    /// `points` are the candidates, `original[i]` the caller's index of candidate i.
    Quickhull(PointSpan points, const std::vector<Index>& original)
        : points_(points), original_(original), next_(points.count, kNone) {
        faces_.reserve(2 * points.count + 16);  // a hull of n points has at most 2n - 4 faces
        double lo[3], hi[3];
        for (int axis = 0; axis < 3; ++axis) lo[axis] = hi[axis] = points[0][axis];
        for (std::size_t i = 1; i < points.count; ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                lo[axis] = std::min(lo[axis], points[i][axis]);
                hi[axis] = std::max(hi[axis], points[i][axis]);
            }
        }
        extent_ = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    }

    /// The hull's triangles (candidate indices) and the pairs of edge-adjacent triangles that lie
    /// in one plane (exactly), which merge_coplanar_triangles() needs.
    bool run(const Simplex& simplex, std::vector<Index>& triangles, std::vector<CoplanarPair>& coplanar,
             std::string& error) {
        start(simplex);
        while (!pending_.empty()) {
            const Index f = pending_.back();
            pending_.pop_back();
            if (!faces_[f].alive || faces_[f].outside == kNone) continue;
            if (!add_point(f, error)) return false;
        }
        release(next_);
        release(pending_);
        // Number the live faces consecutively.
        std::vector<Index> number(faces_.size(), kNone);
        Index live = 0;
        for (std::size_t f = 0; f < faces_.size(); ++f) {
            if (faces_[f].alive) number[f] = live++;
        }
        triangles.resize(3 * std::size_t{live});
        coplanar.clear();
        for (std::size_t f = 0; f < faces_.size(); ++f) {
            const Face& face = faces_[f];
            if (!face.alive) continue;
            std::copy(face.v, face.v + 3, &triangles[3 * std::size_t{number[f]}]);
            const Plane plane = plane_of(static_cast<Index>(f));
            for (int k = 0; k < 3; ++k) {
                const Index g = face.twin[k] / 3;
                if (g < f) continue;  // each pair once
                const Index apex = faces_[g].v[(face.twin[k] % 3 + 2) % 3];  // g's corner off the shared edge
                double h;
                if (side(plane, apex, &h) == 0) coplanar.push_back({number[f], number[g]});
            }
        }
        return true;
    }

private:
    const double* at(Index i) const { return points_[i]; }

    template <class T>
    static void release(std::vector<T>& v) {
        std::vector<T>().swap(v);
    }

    Plane plane_of(Index f) const {
        const Face& face = faces_[f];
        const double* a = at(face.v[0]);
        const double* b = at(face.v[1]);
        const double* c = at(face.v[2]);
        const double ex = b[0] - a[0], ey = b[1] - a[1], ez = b[2] - a[2];
        const double fx = c[0] - a[0], fy = c[1] - a[1], fz = c[2] - a[2];
        const double p1 = ey * fz, p2 = ez * fy, p3 = ez * fx, p4 = ex * fz, p5 = ex * fy, p6 = ey * fx;
        Plane plane;
        plane.ax = a[0];
        plane.ay = a[1];
        plane.az = a[2];
        plane.nx = p1 - p2;
        plane.ny = p3 - p4;
        plane.nz = p5 - p6;
        // The rounded height n . (p - a) is off by at most 8u * sum|monomials| (u = 2^-53, 8 rounding
        // steps per monomial), and sum|monomials| <= extent * permanent(n), |p - a| <= extent per
        // axis. 2^-49 = 16u doubles that for the rounding of the bound itself.
        const double permanent = std::fabs(p1) + std::fabs(p2) + std::fabs(p3) + std::fabs(p4) + std::fabs(p5) + std::fabs(p6);
        plane.bound = 0x1p-49 * permanent * extent_;
        std::copy(face.v, face.v + 3, plane.v);
        return plane;
    }

    double height(const Plane& plane, const double* p) const {
        return plane.nx * (p[0] - plane.ax) + plane.ny * (p[1] - plane.ay) + plane.nz * (p[2] - plane.az);
    }

    /// Exact side of point `p` from `plane`: +1 strictly above.
    int side(const Plane& plane, Index p, double* h) const {
        *h = height(plane, at(p));
        if (*h > plane.bound) return 1;
        if (*h < -plane.bound) return -1;
        return orient3d(at(plane.v[0]), at(plane.v[1]), at(plane.v[2]), at(p));
    }

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
        face.farthest = kNone;
        face.far_height = 0.0;
        face.mark = 0;
        face.alive = true;
        return f;
    }

    void link(Index half_edge, Index other) {
        faces_[half_edge / 3].twin[half_edge % 3] = other;
        faces_[other / 3].twin[other % 3] = half_edge;
    }

    /// Puts point p on face f's outside list (h: its rounded height, to pick the farthest;
    /// ties go to the lower index so that of identical points the lowest index is chosen).
    void push_outside(Index f, Index p, double h) {
        Face& face = faces_[f];
        if (face.outside == kNone) pending_.push_back(f);
        next_[p] = face.outside;
        face.outside = p;
        if (face.farthest == kNone || h > face.far_height ||
            (h == face.far_height && original_[p] < original_[face.farthest])) {
            face.farthest = p;
            face.far_height = h;
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
                push_outside(owners[k], p, h);
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
        const Index eye = faces_[f].farthest;
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
            face.alive = false;
            free_.push_back(v);
        }
        return true;
    }

    PointSpan points_;
    const std::vector<Index>& original_;
    double extent_ = 0.0;
    std::vector<Face> faces_;
    std::vector<Index> free_;
    std::vector<Index> next_;     // outside-list links, one per point
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

/// Spreads the low 10 bits of v to every third bit.
std::uint32_t spread_bits(std::uint32_t v) {
    v &= 0x3ff;
    v = (v | (v << 16)) & 0x030000ff;
    v = (v | (v << 8)) & 0x0300f00f;
    v = (v | (v << 4)) & 0x030c30c3;
    v = (v | (v << 2)) & 0x09249249;
    return v;
}

/// Sorts `ids` along a Morton curve through the bounding box (10 bits per axis) and drops all
/// but the lowest index of identical points. Only the memory order of the work changes, never a
/// result: identical points have one key, and within a key the ids are sorted by coordinates.
void spatial_order(PointSpan points, std::vector<Index>& ids) {
    if (ids.size() <= 4096) {  // small: coordinate order is good enough
        ids.erase(sort_dropping_repeats(points, ids.begin(), ids.end()), ids.end());
        return;
    }
    double lo[3], scale[3];
    for (int axis = 0; axis < 3; ++axis) {
        double low = points[ids[0]][axis], high = low;
        for (Index i : ids) {
            low = std::min(low, points[i][axis]);
            high = std::max(high, points[i][axis]);
        }
        lo[axis] = low;
        scale[axis] = high > low ? 1023.0 / (high - low) : 0.0;
    }
    std::vector<std::uint64_t> keyed(ids.size());  // key << 32 | id
    for (std::size_t k = 0; k < ids.size(); ++k) {
        const double* p = points[ids[k]];
        std::uint32_t key = 0;
        for (int axis = 0; axis < 3; ++axis) {
            key |= spread_bits(static_cast<std::uint32_t>((p[axis] - lo[axis]) * scale[axis])) << axis;
        }
        keyed[k] = (std::uint64_t{key} << 32) | ids[k];
    }
    // LSD radix sort on the 30-bit key, two 15-bit digits.
    std::vector<std::uint64_t> buffer(keyed.size());
    for (int shift = 32; shift < 62; shift += 15) {
        std::vector<std::size_t> start(1u << 15, 0);
        for (std::uint64_t v : keyed) ++start[(v >> shift) & 0x7fff];
        std::size_t sum = 0;
        for (std::size_t& count : start) sum += std::exchange(count, sum);
        for (std::uint64_t v : keyed) buffer[start[(v >> shift) & 0x7fff]++] = v;
        keyed.swap(buffer);
    }
    ids.clear();
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
}

/// Indices of the points that may be on the hull: all but those inside a box that is certified
/// (exactly) to lie strictly inside the hull of the points extreme in 14 directions.
std::vector<Index> candidates(PointSpan points, const Simplex& simplex) {
    const auto n = static_cast<Index>(points.count);
    std::vector<Index> all;
    const Index* extreme = simplex.extreme;
    const double* lo = simplex.lo;
    const double* hi = simplex.hi;
    auto everything = [&] {
        all.resize(n);
        for (Index i = 0; i < n; ++i) all[i] = i;
        return all;
    };
    if (n < 1024) return everything();  // not worth it

    // The hull of the extremes (and the simplex, which has volume), by this same quickhull.
    std::vector<Index> seeds(extreme, extreme + 14);
    seeds.insert(seeds.end(), simplex.p, simplex.p + 4);
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
    std::vector<double> seed_xyz;
    for (Index i : seeds) seed_xyz.insert(seed_xyz.end(), points[i], points[i] + 3);
    Simplex local;
    local.dimension = 3;
    for (int k = 0; k < 4; ++k)
        local.p[k] = static_cast<Index>(std::lower_bound(seeds.begin(), seeds.end(), simplex.p[k]) - seeds.begin());
    std::vector<Index> identity(seeds.size()), triangles;
    std::vector<CoplanarPair> coplanar;
    for (Index k = 0; k < identity.size(); ++k) identity[k] = k;
    Quickhull small(PointSpan(seed_xyz.data(), seeds.size()), identity);
    std::string ignored;
    if (!small.run(local, triangles, coplanar, ignored)) return everything();

    // The largest box about the bounding box's centre, shrunk in steps, whose corners are all
    // strictly below every face of that hull.
    auto inside = [&](const double* q) {
        for (std::size_t t = 0; t < triangles.size(); t += 3) {
            if (orient3d(&seed_xyz[3 * triangles[t]], &seed_xyz[3 * triangles[t + 1]], &seed_xyz[3 * triangles[t + 2]], q) >= 0)
                return false;
        }
        return true;
    };
    for (double shrink : {0.98, 0.9, 0.75, 0.55}) {
        double box_lo[3], box_hi[3];
        for (int axis = 0; axis < 3; ++axis) {
            const double centre = 0.5 * (lo[axis] + hi[axis]);
            const double half = 0.5 * (hi[axis] - lo[axis]) * shrink;
            box_lo[axis] = centre - half;
            box_hi[axis] = centre + half;
        }
        bool fits = true;
        for (int corner = 0; corner < 8 && fits; ++corner) {
            const double q[3] = {corner & 1 ? box_hi[0] : box_lo[0], corner & 2 ? box_hi[1] : box_lo[1],
                                 corner & 4 ? box_hi[2] : box_lo[2]};
            fits = inside(q);
        }
        if (!fits) continue;
        // The closed box is inside the open hull: its points are interior, never on the hull.
        all.reserve(n / 8);
        for (Index i = 0; i < n; ++i) {
            const double* p = points[i];
            const bool in_box = p[0] >= box_lo[0] && p[0] <= box_hi[0] && p[1] >= box_lo[1] && p[1] <= box_hi[1] &&
                                p[2] >= box_lo[2] && p[2] <= box_hi[2];
            if (!in_box) all.push_back(i);
        }
        for (Index s : simplex.p) {  // the starting simplex stays, even when inside the box
            if (!std::binary_search(all.begin(), all.end(), s)) all.insert(std::lower_bound(all.begin(), all.end(), s), s);
        }
        return all;
    }
    return everything();
}

}  // namespace

bool quickhull_faces(PointSpan points, const Simplex& simplex, Polygons& faces, double* volume, double* area,
                     std::string& error) {
    std::vector<Index> ids = candidates(points, simplex);
    spatial_order(points, ids);
    std::vector<double> xyz(3 * ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k) std::copy(points[ids[k]], points[ids[k]] + 3, &xyz[3 * k]);
    const PointSpan local_points(xyz.data(), ids.size());
    Simplex local;
    local.dimension = 3;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        for (int corner = 0; corner < 4; ++corner) {
            if (ids[k] == simplex.p[corner]) local.p[corner] = static_cast<Index>(k);
        }
    }
    std::vector<Index> triangles;
    std::vector<CoplanarPair> coplanar;
    {
        Quickhull quickhull(local_points, ids);
        if (!quickhull.run(local, triangles, coplanar, error)) return false;
    }
    // Merging and measuring touch every corner: done on the local copy, which is in spatial order.
    faces = merge_coplanar_triangles(local_points, std::move(triangles), coplanar);
    measure(local_points, faces, volume, area);
    for (Index& v : faces.vertices) v = ids[v];
    return true;
}

}  // namespace hullkit::detail
