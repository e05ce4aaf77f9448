// Quickhull in 3D (Barber, Dobkin & Huhdanpaa 1996) with exact side tests.
//
// Layout: faces are triangles in one pooled array (dead faces are recycled), each with its three
// vertices, the three opposite half-edges (twin = 3 * face + edge) and the head of a singly linked
// list of the points outside it (links in one per-point array). A face's outside points are those
// strictly above it; a point above no face is inside the current hull and dropped for good.
//
// Before the main loop: points certified to lie strictly inside the hull of a few extreme points
// (a box inside that hull, then its planes, each decided exactly) are dropped in one pass on the
// threads, which also gives each survivor its space-filling-curve (Morton) key; repeats of a
// point are dropped (the lowest index stays), and the rest are copied in Morton order, so that
// the points above one face sit close in memory.
//
// Side tests: a rounded plane test with a proven error bound decides almost every case; only
// points within that bound of a plane go to the exact orient3d. Rounded distances are also used
// to pick the farthest point, which is a choice, not a decision about topology.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hull_internal.hpp"
#include "large_array.hpp"
#include "parallel.hpp"
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

/// The largest extent of the points' bounding box along an axis (the planes' error bounds scale
/// with it).
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

/// A face's plane in rounded arithmetic, with the bound under which its sign is not trusted.
struct Plane {
    double ax, ay, az;  // a vertex
    double nx, ny, nz;  // (b - a) x (c - a), rounded
    double bound;
    Index v[3];
};

/// The plane through a, b, c (indices va, vb, vc into `points`), for points whose coordinates
/// differ from a's by at most `extent` per axis.
Plane plane_through(PointSpan points, Index va, Index vb, Index vc, double extent) {
    const double* a = points[va];
    const double* b = points[vb];
    const double* c = points[vc];
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
    plane.bound = 0x1p-49 * permanent * extent;
    plane.v[0] = va;
    plane.v[1] = vb;
    plane.v[2] = vc;
    return plane;
}

inline double height(const Plane& plane, const double* p) {
    return plane.nx * (p[0] - plane.ax) + plane.ny * (p[1] - plane.ay) + plane.nz * (p[2] - plane.az);
}

/// Exact side of point p from the plane: +1 strictly above. *h: the rounded height.
inline int side_of(PointSpan points, const Plane& plane, const double* p, double* h) {
    *h = height(plane, p);
    if (*h > plane.bound) return 1;
    if (*h < -plane.bound) return -1;
    return orient3d(points[plane.v[0]], points[plane.v[1]], points[plane.v[2]], p);
}

/// A closed surface of triangles: triangle t has corners triangles[3t..3t+2] (counter-clockwise
/// seen from outside); twins[3t + k] is the half-edge (3 * triangle + edge) on the other side of
/// its edge k (corner k to corner k + 1); flat[3t + k] says whether that neighbour lies exactly in
/// t's plane.
struct Surface {
    LargeArray<Index> triangles;
    LargeArray<Index> twins;
    LargeArray<std::uint8_t> flat;

    std::size_t size() const { return triangles.size() / 3; }
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
            if (!faces_[f].alive || faces_[f].outside == kNone) continue;
            if (!add_point(f, error)) return false;
        }
        release(next_);
        release(pending_);
        // Number the live faces consecutively.
        LargeArray<Index> number(faces_.size(), kNone);
        Index live = 0;
        for (std::size_t f = 0; f < faces_.size(); ++f) {
            if (faces_[f].alive) number[f] = live++;
        }
        surface.triangles.resize(3 * std::size_t{live});
        surface.twins.resize(3 * std::size_t{live});
        surface.flat.assign(3 * std::size_t{live}, 0);
        for (std::size_t f = 0; f < faces_.size(); ++f) {
            const Face& face = faces_[f];
            if (!face.alive) continue;
            const std::size_t t = number[f];
            std::copy(face.v, face.v + 3, &surface.triangles[3 * t]);
            const Plane plane = plane_of(static_cast<Index>(f));
            for (int k = 0; k < 3; ++k) {
                const Index g = face.twin[k] / 3;
                const Index other = 3 * number[g] + face.twin[k] % 3;
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

/// Spreads the low 10 bits of v to every third bit.
std::uint32_t spread_bits(std::uint32_t v) {
    v &= 0x3ff;
    v = (v | (v << 16)) & 0x030000ff;
    v = (v | (v << 8)) & 0x0300f00f;
    v = (v | (v << 4)) & 0x030c30c3;
    v = (v | (v << 2)) & 0x09249249;
    return v;
}

/// Morton (Z-order) keys over a box, 10 bits per axis: key << 32 | id, so that sorting by key
/// puts points that are close in space close in memory.
class MortonKeys {
public:
    MortonKeys(const double* lo, const double* hi) {
        for (int axis = 0; axis < 3; ++axis) {
            lo_[axis] = lo[axis];
            scale_[axis] = hi[axis] > lo[axis] ? 1023.0 / (hi[axis] - lo[axis]) : 0.0;
        }
    }
    std::uint64_t operator()(const double* p, Index id) const {
        std::uint32_t key = 0;
        for (int axis = 0; axis < 3; ++axis) {
            // In the box, (p - lo) * scale is in [0, 1023] up to rounding; the mask keeps it there.
            key |= spread_bits(static_cast<std::uint32_t>((p[axis] - lo_[axis]) * scale_[axis])) << axis;
        }
        return std::uint64_t{key} << 32 | id;
    }

private:
    double lo_[3], scale_[3];
};

/// The ids of `keyed` (Morton keys of points in their box, any order) along the curve, with all
/// but the lowest index of identical points dropped. Only the memory order of the work changes,
/// never a result: identical points have one key, and within a key the ids are sorted by
/// coordinates.
std::vector<Index> spatial_order(PointSpan points, LargeArray<std::uint64_t>& keyed) {
    std::vector<Index> ids;
    ids.reserve(keyed.size());
    if (keyed.size() <= 4096) {  // small: coordinate order is good enough
        for (std::uint64_t k : keyed) ids.push_back(static_cast<Index>(k));
        ids.erase(sort_dropping_repeats(points, ids.begin(), ids.end()), ids.end());
        return ids;
    }
    // LSD radix sort on the 30-bit key, two 15-bit digits.
    LargeArray<std::uint64_t> buffer(keyed.size());
    for (int shift = 32; shift < 62; shift += 15) {
        std::vector<std::size_t> start(1u << 15, 0);
        for (std::uint64_t v : keyed) ++start[(v >> shift) & 0x7fff];
        std::size_t sum = 0;
        for (std::size_t& count : start) sum += std::exchange(count, sum);
        for (std::uint64_t v : keyed) buffer[start[(v >> shift) & 0x7fff]++] = v;
        keyed.swap(buffer);
    }
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
    return ids;
}

/// A region certified, exactly, to lie strictly inside the hull of a cloud: the interior of the
/// hull of its simplex and its extremes in 14 directions (the Akl-Toussaint heuristic). A point
/// inside it is never a vertex of the hull. The test is a box inside that region first (six
/// comparisons: most interior points of a ball or a cube), then the region's planes, each by the
/// rounded height with its error bound and orient3d where that does not decide.
class Interior {
public:
    /// False when the extremes have no volume (then nothing is certified inside).
    bool build(PointSpan points, const Simplex& simplex) {
        std::vector<Index> seeds(simplex.extreme, simplex.extreme + 14);
        seeds.insert(seeds.end(), simplex.p, simplex.p + 4);
        std::sort(seeds.begin(), seeds.end());
        seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
        for (Index i : seeds) xyz_.insert(xyz_.end(), points[i], points[i] + 3);
        const PointSpan local_points(xyz_.data(), seeds.size());
        Simplex local;
        local.dimension = 3;
        for (int k = 0; k < 4; ++k)
            local.p[k] = static_cast<Index>(std::lower_bound(seeds.begin(), seeds.end(), simplex.p[k]) - seeds.begin());
        std::vector<Index> identity(seeds.size());
        for (Index k = 0; k < identity.size(); ++k) identity[k] = k;
        Quickhull small(local_points, identity);
        Surface surface;
        std::string ignored;
        if (!small.run(local, surface, ignored)) return false;
        // Every point of the cloud lies in its bounding box, so differs from a corner by at most
        // the box's largest side per axis: the planes' error bounds hold for all of them.
        const double extent = std::max({simplex.hi[0] - simplex.lo[0], simplex.hi[1] - simplex.lo[1], simplex.hi[2] - simplex.lo[2]});
        for (std::size_t t = 0; t < surface.size(); ++t) {
            const Index* v = &surface.triangles[3 * t];
            planes_.push_back(plane_through(local_points, v[0], v[1], v[2], extent));
        }
        // The largest box about the bounding box's centre, shrunk in steps, whose corners are
        // all strictly below every plane; none (an empty box) if even the smallest is not.
        for (double shrink : {0.98, 0.9, 0.75, 0.55}) {
            for (int axis = 0; axis < 3; ++axis) {
                const double centre = 0.5 * (simplex.lo[axis] + simplex.hi[axis]);
                const double half = 0.5 * (simplex.hi[axis] - simplex.lo[axis]) * shrink;
                box_lo_[axis] = centre - half;
                box_hi_[axis] = centre + half;
            }
            bool fits = true;
            for (int corner = 0; corner < 8 && fits; ++corner) {
                const double q[3] = {corner & 1 ? box_hi_[0] : box_lo_[0], corner & 2 ? box_hi_[1] : box_lo_[1],
                                     corner & 4 ? box_hi_[2] : box_lo_[2]};
                fits = below_every_plane(q);
            }
            if (fits) return true;
        }
        for (int axis = 0; axis < 3; ++axis) box_lo_[axis] = 1.0, box_hi_[axis] = 0.0;
        return true;
    }

    /// Whether p lies strictly inside the region (exactly).
    bool contains(const double* p) const {
        return (p[0] >= box_lo_[0] && p[0] <= box_hi_[0] && p[1] >= box_lo_[1] && p[1] <= box_hi_[1] &&
                p[2] >= box_lo_[2] && p[2] <= box_hi_[2]) ||
               below_every_plane(p);
    }

private:
    bool below_every_plane(const double* p) const {
        const PointSpan local_points(xyz_.data(), xyz_.size() / 3);
        for (const Plane& plane : planes_) {
            double h;
            if (side_of(local_points, plane, p, &h) >= 0) return false;
        }
        return true;
    }

    std::vector<double> xyz_;  // the seeds' coordinates
    std::vector<Plane> planes_;
    double box_lo_[3] = {1.0, 1.0, 1.0}, box_hi_[3] = {0.0, 0.0, 0.0};
};

/// The points that may be on the hull, as Morton keys over the bounding box (see MortonKeys):
/// all but those inside a box that is certified (exactly) to lie strictly inside the hull of the
/// points extreme in 14 directions. One pass over the points, in blocks on up to `threads`
/// threads, both filters and keys them.
LargeArray<std::uint64_t> candidates(PointSpan points, const Simplex& simplex, unsigned threads = 1) {
    const auto n = static_cast<Index>(points.count);
    const MortonKeys morton(simplex.lo, simplex.hi);
    // Blocks keyed (those outside the box, when there is one) on the threads, joined in order.
    auto keyed_outside = [&](const Interior* interior) {
        constexpr Index kBlock = Index{1} << 18;
        const std::size_t blocks = (n + kBlock - 1) / kBlock;
        std::vector<std::vector<std::uint64_t>> kept(blocks);
        parallel_for(threads, blocks, [&](std::size_t block) {
            const Index first = static_cast<Index>(block) * kBlock, last = std::min(n, first + kBlock);
            std::vector<std::uint64_t>& out = kept[block];
            if (interior == nullptr) {
                out.resize(last - first);
                for (Index i = first; i < last; ++i) out[i - first] = morton(points[i], i);
                return;
            }
            out.reserve(kBlock / 8);
            for (Index i = first; i < last; ++i) {
                if (!interior->contains(points[i])) out.push_back(morton(points[i], i));
            }
        });
        std::size_t total = 0;
        for (const auto& part : kept) total += part.size();
        LargeArray<std::uint64_t> all;
        all.reserve(total + 4);
        for (auto& part : kept) {
            all.insert(all.end(), part.begin(), part.end());
            std::vector<std::uint64_t>().swap(part);
        }
        return all;
    };
    if (n < 1024) return keyed_outside(nullptr);  // not worth it
    Interior interior;
    if (!interior.build(points, simplex)) return keyed_outside(nullptr);
    LargeArray<std::uint64_t> all = keyed_outside(&interior);
    for (int k = 0; k < 4; ++k) {  // the starting simplex stays, even when inside
        const Index s = simplex.p[k];
        if (interior.contains(points[s]) && std::find(simplex.p, simplex.p + k, s) == simplex.p + k)
            all.push_back(morton(points[s], s));
    }
    return all;
}

/// The edge-adjacent pairs of a surface's triangles that lie in one plane, each pair once.
std::vector<CoplanarPair> coplanar_pairs(const Surface& surface) {
    std::vector<CoplanarPair> pairs;
    for (std::size_t h = 0; h < surface.twins.size(); ++h) {
        const Index t = static_cast<Index>(h / 3), u = surface.twins[h] / 3;
        if (surface.flat[h] && t < u) pairs.push_back({t, u});
    }
    return pairs;
}

/// Quickhull of a cloud with volume: its candidates (interior points culled, repeats dropped)
/// copied in spatial order into *xyz, ids[k] being the index in `points` of copy k, and the hull
/// as a surface over the copy.
bool run_quickhull(PointSpan points, const Simplex& simplex, std::vector<Index>& ids, LargeArray<double>& xyz,
                   Surface& surface, std::string& error, unsigned threads = 1) {
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
    Quickhull quickhull(PointSpan(xyz.data(), ids.size()), ids);
    return quickhull.run(local, surface, error);
}

}  // namespace

double culling_kept_fraction(PointSpan points, const Simplex& simplex, PointSpan sample) {
    Interior interior;
    if (simplex.dimension < 3 || sample.count == 0 || !interior.build(points, simplex)) return 1.0;
    std::size_t outside = 0;
    for (std::size_t i = 0; i < sample.count; ++i) outside += !interior.contains(sample[i]);
    return static_cast<double>(outside) / static_cast<double>(sample.count);
}

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

// ---------------------------------------------------------------------------------------------
// Clouds whose points mostly lie on their hull (a sphere, a scanned surface), on threads: the
// cloud is cut in two at the median of its widest axis, each half is hulled on its own thread
// (recursively, with more threads), and the two hulls are joined:
//   - a triangle of hull(A) is "dirty" when a point of B lies strictly above it (then it is not on
//     the hull of the union); the others are on it. The dirty triangles of A are connected (A and
//     B lie strictly on either side of a plane, so the faces visible from the points of hull(B)
//     form one region, and a face visible from a convex combination of points is visible from
//     one of them), so they are found by a search from one dirty triangle, each step asking a
//     bounding-box tree over B's hull vertices, exactly, whether any lies above;
//   - the triangles joining the two clean regions are the faces of the hull of the dirty
//     triangles' corners (the seam, a small set) that lie between the clean regions' rims: they
//     are found by a search in that hull from the rims' edges, never crossing them.
// Anything unexpected (a half without volume, a rim edge missing from the seam's hull, a surface
// that does not close) gives up, and the caller runs the serial quickhull: the answer is the same
// either way, only the time differs.
// ---------------------------------------------------------------------------------------------

/// A bounding-box tree over points (indices into a PointSpan), leaves of up to 8 points.
class PointTree {
public:
    PointTree(PointSpan points, std::vector<Index> ids) : points_(points), ids_(std::move(ids)) {
        nodes_.reserve(2 * (ids_.size() / 4 + 1));
        if (!ids_.empty()) build(0, ids_.size());
    }

    /// Whether any point of the tree lies strictly above `plane` (exactly). A node is skipped
    /// when the corner of its box highest above the plane is certainly below it: the rounded
    /// height is off by less than the plane's bound, doubled for choosing the corner by the
    /// rounded normal's signs.
    bool any_above(const Plane& plane) const {
        if (ids_.empty()) return false;
        Index stack[128];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = nodes_[stack[--top]];
            const double corner[3] = {plane.nx >= 0 ? node.hi[0] : node.lo[0], plane.ny >= 0 ? node.hi[1] : node.lo[1],
                                      plane.nz >= 0 ? node.hi[2] : node.lo[2]};
            if (height(plane, corner) < -2 * plane.bound) continue;
            if (node.left == kNone) {
                for (std::size_t k = node.begin; k < node.end; ++k) {
                    double h;
                    if (side_of(points_, plane, points_[ids_[k]], &h) > 0) return true;
                }
                continue;
            }
            stack[top++] = node.left;
            stack[top++] = node.left + 1;
        }
        return false;
    }

private:
    struct Node {
        double lo[3], hi[3];
        std::size_t begin, end;
        Index left;  // the children are left and left + 1; kNone for a leaf
    };

    void build(std::size_t begin, std::size_t end) {
        // Breadth-first, so that siblings are neighbours (left, left + 1), at most 128 levels deep.
        struct Job {
            Index node;
            std::size_t begin, end;
        };
        std::vector<Job> jobs{{0, begin, end}};
        nodes_.emplace_back();
        for (std::size_t j = 0; j < jobs.size(); ++j) {
            const Job job = jobs[j];
            Node& node = nodes_[job.node];
            node.begin = job.begin;
            node.end = job.end;
            node.left = kNone;
            for (int axis = 0; axis < 3; ++axis) node.lo[axis] = node.hi[axis] = points_[ids_[job.begin]][axis];
            for (std::size_t k = job.begin; k < job.end; ++k) {
                for (int axis = 0; axis < 3; ++axis) {
                    node.lo[axis] = std::min(node.lo[axis], points_[ids_[k]][axis]);
                    node.hi[axis] = std::max(node.hi[axis], points_[ids_[k]][axis]);
                }
            }
            if (job.end - job.begin <= 8) continue;
            int axis = 0;
            for (int a = 1; a < 3; ++a) {
                if (node.hi[a] - node.lo[a] > node.hi[axis] - node.lo[axis]) axis = a;
            }
            const std::size_t middle = job.begin + (job.end - job.begin) / 2;
            std::nth_element(ids_.begin() + static_cast<std::ptrdiff_t>(job.begin), ids_.begin() + static_cast<std::ptrdiff_t>(middle),
                             ids_.begin() + static_cast<std::ptrdiff_t>(job.end),
                             [&](Index p, Index q) { return points_[p][axis] < points_[q][axis]; });
            const Index left = static_cast<Index>(nodes_.size());
            nodes_[job.node].left = left;
            nodes_.emplace_back();
            nodes_.emplace_back();
            jobs.push_back({left, job.begin, middle});
            jobs.push_back({left + 1, middle, job.end});
        }
    }

    PointSpan points_;
    std::vector<Index> ids_;
    std::vector<Node> nodes_;
};

/// The distinct corners of a surface's triangles (of those marked in `only`, if given),
/// ascending; `point_count` bounds the indices.
std::vector<Index> corners_of(const Surface& surface, std::size_t point_count,
                              const std::vector<std::uint8_t>* only = nullptr) {
    std::vector<std::uint8_t> used(point_count, 0);
    for (std::size_t t = 0; t < surface.size(); ++t) {
        if (only && !(*only)[t]) continue;
        for (int k = 0; k < 3; ++k) used[surface.triangles[3 * t + k]] = 1;
    }
    std::vector<Index> corners;
    for (std::size_t i = 0; i < point_count; ++i) {
        if (used[i]) corners.push_back(static_cast<Index>(i));
    }
    return corners;
}

/// Climbs a closed convex surface towards the vertex highest above a plane. A position is a
/// half-edge out of the current vertex; the vertex's neighbours are found by turning about it
/// through the twins, so nothing is built: asking costs only the vertices visited.
class Climber {
public:
    Climber(PointSpan points, const Surface& surface) : points_(points), surface_(surface) {}

    /// A place to start: a half-edge out of some vertex.
    static Index start() { return 0; }
    /// The vertex a half-edge leaves.
    Index vertex(Index h) const { return surface_.triangles[h]; }

    enum class Verdict { Above, NoneAbove, Unsure };

    /// Whether some vertex lies strictly above `plane` (exactly), starting the climb at the
    /// vertex *from leaves (updated to a half-edge out of where the climb ended, a good start for
    /// a nearby plane). Unsure when rounding leaves it open: then the caller asks exhaustively.
    Verdict any_above(const Plane& plane, Index* from) const {
        Index h = *from;
        bool certain = false;
        for (;;) {
            // Move to the neighbour certainly highest along the rounded normal n; stop where no
            // neighbour is certainly higher (the rounding of n . (w - v) is below 8u of its
            // permanent, so `slack` = 2^-50 of it is safe).
            const double* p = points_[vertex(h)];
            Index best = kNone;
            double best_rise = 0.0;
            bool unsure = false;
            Index e = h;
            do {
                const double* q = points_[head(e)];
                const double dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2];
                const double rise = plane.nx * dx + plane.ny * dy + plane.nz * dz;
                const double slack = 0x1p-50 * (std::fabs(plane.nx * dx) + std::fabs(plane.ny * dy) + std::fabs(plane.nz * dz));
                if (rise > slack) {
                    if (rise > best_rise) best_rise = rise, best = e;
                } else if (rise >= -slack) {
                    unsure = true;
                }
                e = next_out(e);
            } while (e != h);
            if (best == kNone) {
                certain = !unsure;
                break;
            }
            h = surface_.twins[best];  // out of the higher neighbour
        }
        *from = h;
        const double* top = points_[vertex(h)];
        double height_of_top;
        const int s = side_of(points_, plane, top, &height_of_top);
        if (s > 0) return Verdict::Above;
        if (s == 0) {
            // The vertex is on the plane: it is the highest exactly when no neighbour is above.
            Index e = h;
            do {
                double ignored;
                if (side_of(points_, plane, points_[head(e)], &ignored) > 0) return Verdict::Above;
                e = next_out(e);
            } while (e != h);
            return Verdict::NoneAbove;
        }
        // The vertex is the highest along the rounded normal; below the plane by more than the
        // plane's bound, which covers both the rounding of its height and the rounded normal's
        // error times the extent, nothing is above the exact plane.
        if (certain && height(plane, top) < -plane.bound) return Verdict::NoneAbove;
        return Verdict::Unsure;
    }

private:
    /// The vertex a half-edge enters.
    Index head(Index h) const { return surface_.triangles[h - h % 3 + (h % 3 + 1) % 3]; }
    /// The next half-edge out of the same vertex, turning about it: the twin of the half-edge
    /// that enters the vertex in h's triangle.
    Index next_out(Index h) const { return surface_.twins[h - h % 3 + (h % 3 + 2) % 3]; }

    PointSpan points_;
    const Surface& surface_;
};

/// The hull of the points `members` (indices into `points`, ascending) as a surface in those
/// indices, on the calling thread. False when they have no volume.
bool member_surface(PointSpan points, const std::vector<Index>& members, Surface& surface) {
    LargeArray<double> xyz(3 * members.size());
    for (std::size_t k = 0; k < members.size(); ++k) std::copy(points[members[k]], points[members[k]] + 3, &xyz[3 * k]);
    const PointSpan local(xyz.data(), members.size());
    const Simplex simplex = find_simplex(local);
    if (simplex.dimension < 3) return false;
    std::vector<Index> ids;
    LargeArray<double> copy;
    std::string error;
    if (!run_quickhull(local, simplex, ids, copy, surface, error)) return false;
    for (Index& v : surface.triangles) v = members[ids[v]];
    return true;
}

/// Marks the triangles of `surface` that some vertex of `other` (the other half's hull) lies
/// strictly above: by climbing the other hull from one triangle's answer to the next, and where
/// rounding leaves that open, by a box tree over the other hull's vertices (built on first need).
/// The dirty triangles are connected, so the search starts from one of them and only the dirty
/// ones and their neighbours are asked. False if no triangle has `other`'s first vertex above it,
/// which cannot happen for halves strictly apart.
bool mark_dirty(PointSpan points, const Surface& surface, const Surface& other, double extent,
                std::vector<std::uint8_t>& dirty) {
    const std::size_t count = surface.size();
    dirty.assign(count, 0);
    const Climber climber(points, other);
    std::unique_ptr<PointTree> tree;
    auto plane = [&](std::size_t t) {
        const Index* v = &surface.triangles[3 * t];
        return plane_through(points, v[0], v[1], v[2], extent);
    };
    auto above = [&](const Plane& p, Index* from) {
        const Climber::Verdict verdict = climber.any_above(p, from);
        if (verdict != Climber::Verdict::Unsure) return verdict == Climber::Verdict::Above;
        if (!tree) tree = std::make_unique<PointTree>(points, corners_of(other, points.count));
        return tree->any_above(p);
    };
    // A first dirty triangle: one that a vertex of the other hull is above. Walk towards it,
    // each step to the unvisited neighbour with the vertex highest above it (rounded heights
    // choose, the exact side decides); if the walk gets stuck, look at every triangle.
    const Index probe = climber.vertex(Climber::start());
    std::vector<std::uint8_t> seen(count, 0);
    std::size_t seed = count;
    for (std::size_t t = 0, steps = 0; steps < 4096 && seed == count; ++steps) {
        seen[t] = 1;
        double h;
        if (side_of(points, plane(t), points[probe], &h) > 0) {
            seed = t;
            break;
        }
        std::size_t next = count;
        double best = -std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; ++k) {
            const std::size_t u = surface.twins[3 * t + k] / 3;
            if (seen[u]) continue;
            if (const double up = height(plane(u), points[probe]); up > best) best = up, next = u;
        }
        if (next == count) break;
        t = next;
    }
    for (std::size_t t = 0; t < count && seed == count; ++t) {
        double h;
        if (side_of(points, plane(t), points[probe], &h) > 0) seed = t;
    }
    if (seed == count) return false;
    std::fill(seen.begin(), seen.end(), 0);
    std::vector<std::pair<std::size_t, Index>> queue{{seed, Climber::start()}};  // a dirty triangle, where to climb from
    seen[seed] = 1;
    dirty[seed] = 1;
    for (std::size_t q = 0; q < queue.size(); ++q) {
        const auto [t, from] = queue[q];
        for (int k = 0; k < 3; ++k) {
            const std::size_t u = surface.twins[3 * t + k] / 3;
            if (seen[u]) continue;
            seen[u] = 1;
            Index start = from;
            if (above(plane(u), &start)) {
                dirty[u] = 1;
                queue.emplace_back(u, start);
            }
        }
    }
    return true;
}

/// Joins the hulls of two halves that lie strictly on either side of a plane (indices into
/// `points`) into the hull of their union. False when it cannot (the caller falls back).
bool join(PointSpan points, const Surface (&half)[2], double extent, unsigned threads, Surface& out) {
    std::vector<std::uint8_t> dirty[2];
    bool found[2] = {false, false};
    parallel_for(threads, 2, [&](std::size_t s) { found[s] = mark_dirty(points, half[s], half[1 - s], extent, dirty[s]); });
    if (!found[0] || !found[1]) return false;

    // The seam: the corners of the dirty triangles of both halves (apart, so no repeats), and
    // their hull.
    std::vector<Index> seam = corners_of(half[0], points.count, &dirty[0]);
    {
        const std::vector<Index> more = corners_of(half[1], points.count, &dirty[1]);
        std::vector<Index> both;
        std::merge(seam.begin(), seam.end(), more.begin(), more.end(), std::back_inserter(both));
        seam = std::move(both);
    }
    Surface cap;
    if (!member_surface(points, seam, cap)) return false;
    std::unordered_map<std::uint64_t, Index> cap_edge;  // directed edge u -> v: its half-edge in cap
    cap_edge.reserve(3 * cap.size());
    for (std::size_t h = 0; h < cap.triangles.size(); ++h) {
        const std::size_t t = h / 3;
        const Index u = cap.triangles[h], v = cap.triangles[3 * t + (h + 1) % 3];
        cap_edge.emplace(std::uint64_t{u} << 32 | v, static_cast<Index>(h));
    }

    // Number the kept triangles: clean ones of each half, then the cap's between the rims.
    const std::size_t n0 = half[0].size(), n1 = half[1].size();
    std::vector<Index> number[2] = {std::vector<Index>(n0, kNone), std::vector<Index>(n1, kNone)};
    Index kept = 0;
    for (int s = 0; s < 2; ++s) {
        for (std::size_t t = 0; t < half[s].size(); ++t) {
            if (!dirty[s][t]) number[s][t] = kept++;
        }
    }
    // Rim edges: a clean triangle's edge whose neighbour is dirty. Its reverse is a cap edge,
    // whose triangle lies between the rims; the search from there never crosses a rim edge.
    std::vector<Index> rim_of_cap(cap.triangles.size(), kNone);  // cap half-edge -> the clean half-edge (global numbering)
    std::vector<std::uint8_t> in_bridge(cap.size(), 0);
    std::vector<std::size_t> queue;
    for (int s = 0; s < 2; ++s) {
        const Surface& surface = half[s];
        for (std::size_t h = 0; h < surface.triangles.size(); ++h) {
            const std::size_t t = h / 3;
            if (dirty[s][t] || !dirty[s][surface.twins[h] / 3]) continue;
            const Index u = surface.triangles[h], v = surface.triangles[3 * t + (h + 1) % 3];
            const auto it = cap_edge.find(std::uint64_t{v} << 32 | u);
            if (it == cap_edge.end() || rim_of_cap[it->second] != kNone) return false;
            rim_of_cap[it->second] = 3 * number[s][t] + static_cast<Index>(h % 3);
            const std::size_t g = it->second / 3;
            if (!in_bridge[g]) {
                in_bridge[g] = 1;
                queue.push_back(g);
            }
        }
    }
    if (queue.empty()) {  // nothing clean on either side: the hull is the cap itself
        if (kept != 0) return false;
        std::fill(in_bridge.begin(), in_bridge.end(), 1);
        for (std::size_t g = 0; g < cap.size(); ++g) queue.push_back(g);
    }
    for (std::size_t q = 0; q < queue.size(); ++q) {
        const std::size_t g = queue[q];
        for (int k = 0; k < 3; ++k) {
            const std::size_t h = 3 * g + k;
            if (rim_of_cap[h] != kNone) continue;
            const std::size_t u = cap.twins[h] / 3;
            if (!in_bridge[u]) {
                in_bridge[u] = 1;
                queue.push_back(u);
            }
        }
    }
    std::vector<Index> cap_number(cap.size(), kNone);
    for (std::size_t g = 0; g < cap.size(); ++g) {
        if (in_bridge[g]) cap_number[g] = kept++;
    }

    // The joined surface, its neighbours and which are coplanar.
    out.triangles.assign(3 * std::size_t{kept}, kNone);
    out.twins.assign(3 * std::size_t{kept}, kNone);
    out.flat.assign(3 * std::size_t{kept}, 0);
    for (int s = 0; s < 2; ++s) {
        const Surface& surface = half[s];
        for (std::size_t t = 0; t < surface.size(); ++t) {
            if (dirty[s][t]) continue;
            const std::size_t at = 3 * std::size_t{number[s][t]};
            for (int k = 0; k < 3; ++k) {
                out.triangles[at + k] = surface.triangles[3 * t + k];
                const Index other = surface.twins[3 * t + k];
                if (dirty[s][other / 3]) continue;  // a rim edge: linked from the cap below
                out.twins[at + k] = 3 * number[s][other / 3] + other % 3;
                out.flat[at + k] = surface.flat[3 * t + k];
            }
        }
    }
    for (std::size_t g = 0; g < cap.size(); ++g) {
        if (!in_bridge[g]) continue;
        const std::size_t at = 3 * std::size_t{cap_number[g]};
        for (int k = 0; k < 3; ++k) {
            const std::size_t h = 3 * g + k;
            out.triangles[at + k] = cap.triangles[h];
            if (const Index rim = rim_of_cap[h]; rim != kNone) {
                // Across a rim: coplanar when the cap triangle's far corner is in the clean
                // triangle's plane (exactly).
                out.twins[at + k] = rim;
                out.twins[rim] = static_cast<Index>(at + k);
                const Index* clean = &out.triangles[3 * (rim / 3)];
                const Index apex = cap.triangles[3 * g + (k + 2) % 3];
                const std::uint8_t flat = orient3d(points[clean[0]], points[clean[1]], points[clean[2]], points[apex]) == 0;
                out.flat[at + k] = flat;
                out.flat[rim] = flat;
                continue;
            }
            const Index other = cap.twins[h];
            if (!in_bridge[other / 3]) return false;  // the search cannot stop at a non-rim edge
            out.twins[at + k] = 3 * cap_number[other / 3] + other % 3;
            out.flat[at + k] = cap.flat[h];
        }
    }
    // A closed surface: every half-edge paired both ways, and a sphere (V - E + F = 2).
    for (std::size_t h = 0; h < out.twins.size(); ++h) {
        const Index other = out.twins[h];
        if (other == kNone || out.twins[other] != h) return false;
    }
    const std::size_t vertices = corners_of(out, points.count).size();
    const std::size_t faces = out.size(), edges = 3 * faces / 2;
    return vertices + faces == edges + 2;
}

/// The hull of `members` (ascending indices into `points`) as a surface, on up to `threads`
/// threads: split in two while there are threads to share and points to split, else quickhull.
bool split_surface(PointSpan points, const std::vector<Index>& members, unsigned threads, double extent,
                   Surface& out) {
    constexpr std::size_t kLeaf = std::size_t{1} << 14;
    if (threads < 2 || members.size() < 2 * kLeaf) return member_surface(points, members, out);
    double lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis) lo[axis] = hi[axis] = points[members[0]][axis];
    for (Index i : members) {
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = std::min(lo[axis], points[i][axis]);
            hi[axis] = std::max(hi[axis], points[i][axis]);
        }
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a) {
        if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    }
    std::vector<double> values(members.size());
    for (std::size_t k = 0; k < members.size(); ++k) values[k] = points[members[k]][axis];
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    const double cut = *middle;  // below: the first half; at or above: the second
    std::vector<Index> part[2];
    for (Index i : members) part[points[i][axis] < cut ? 0 : 1].push_back(i);
    if (part[0].size() < kLeaf || part[1].size() < kLeaf) return member_surface(points, members, out);
    values = {};
    Surface half[2];
    bool ok[2] = {false, false};
    const unsigned shares[2] = {(threads + 1) / 2, threads / 2};
    parallel_for(2, 2, [&](std::size_t s) { ok[s] = split_surface(points, part[s], shares[s], extent, half[s]); });
    if (!ok[0] || !ok[1]) return false;
    return join(points, half, extent, threads, out);
}

bool quickhull_split_faces(PointSpan points, unsigned threads, Polygons& faces, double* volume, double* area) {
    if (points.count > kNone) return false;
    const double extent = largest_span(points);
    std::vector<Index> all(points.count);
    for (std::size_t i = 0; i < points.count; ++i) all[i] = static_cast<Index>(i);
    Surface surface;
    if (!split_surface(points, all, threads, extent, surface)) return false;
    faces = merge_coplanar_triangles(points, std::move(surface.triangles), coplanar_pairs(surface));
    canonical_order(faces, {}, threads);
    measure(points, faces, volume, area, threads);
    return true;
}

}  // namespace hullkit::detail
