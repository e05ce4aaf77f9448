// RouteChecker: scene preparation (validation, part hulls, BVHs) and the per-leg check.
//
// The geometry tested is always the traverse's triangles with vertices v + w rounded to doubles
// (w the offset) against the obstacles' triangles; every "do they meet" decision on it is exact
// (geometry.hpp). Over a leg from offset a to offset b a part triangle P sweeps
//     conv(P + a, P + b) = (P + a) u (P + b) u  U_edges  parallelogram(e + a, e + b),
// (a point of the sweep either stays in P for the whole sub-interval it is swept over, so it lies
// in a cap, or leaves P through an edge), so the sweep is 8 triangles and the sweep-versus-obstacle
// test is 8 exact triangle tests: no separating-axis tolerance anywhere. The part's solid is swept
// too: a closed part or obstacle cannot start to contain the other without their surfaces meeting
// first, so containment is only tested at the leg's start (exact ray parity).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "../parallel.hpp"
#include "bvh.hpp"
#include "geometry.hpp"
#include "hullkit/hull.hpp"
#include "hullkit/predicates.hpp"
#include "hullkit/route.hpp"

namespace hullkit {

using namespace route_detail;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Coordinates (and offsets) are limited so that every translated coordinate stays inside the exact
/// range of the predicates (see predicates.hpp) with room to spare.
constexpr double kMaxCoordinate = 0x1p+300;
constexpr double kMinCoordinate = 0x1p-200;
/// Target width of a first-contact bracket (the contract promises 1e-9).
constexpr double kBracketWidth = 4e-10;

struct Component {
    Box box;
    Vec rep;                     ///< one vertex of the component
    std::uint32_t triangle = 0;  ///< one triangle of it (reported on containment)
    std::uint32_t mesh = 0;      ///< obstacle index (obstacle components)
};

struct Topology {
    bool closed = false;
    std::vector<Component> components;
};

Vec point_of(const TriangleMesh& m, std::uint32_t i) {
    return {m.xyz[3 * i], m.xyz[3 * i + 1], m.xyz[3 * i + 2]};
}

/// Closedness (every directed edge used once and its reverse once, vertices merged by exact
/// coordinates) and connected components of a validated mesh.
Topology analyze(const TriangleMesh& m) {
    // Merge points with identical coordinates: sort (x, y, z, index) records.
    const std::size_t n = m.xyz.size() / 3;
    struct Keyed {
        double x, y, z;
        std::uint32_t index;
    };
    std::vector<Keyed> keyed(n);
    for (std::size_t i = 0; i < n; ++i) {
        keyed[i] = {m.xyz[3 * i], m.xyz[3 * i + 1], m.xyz[3 * i + 2], static_cast<std::uint32_t>(i)};
    }
    std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
        return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
    });
    std::vector<std::uint32_t> id(n);
    for (std::size_t k = 0; k < n; ++k) {
        const bool same = k > 0 && keyed[k].x == keyed[k - 1].x && keyed[k].y == keyed[k - 1].y &&
                          keyed[k].z == keyed[k - 1].z;
        id[keyed[k].index] = same ? id[keyed[k - 1].index] : keyed[k].index;
    }
    // Directed edges bucketed by their first point (counting sort), so that "used once, and its
    // reverse once" is a scan of small buckets.
    const std::size_t t = m.triangles.size() / 3;
    std::vector<std::uint32_t> start(n + 1, 0), targets(3 * t);
    std::vector<std::uint32_t> parent(n);
    for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<std::uint32_t>(i);
    auto find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::size_t edge_count = 0;
    for (std::size_t f = 0; f < t; ++f) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t u = id[m.triangles[3 * f + k]];
            const std::uint32_t v = id[m.triangles[3 * f + (k + 1) % 3]];
            if (u != v) ++start[u + 1], ++edge_count;
            parent[find(u)] = find(v);
        }
    }
    for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < t; ++f) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t u = id[m.triangles[3 * f + k]];
            const std::uint32_t v = id[m.triangles[3 * f + (k + 1) % 3]];
            if (u != v) targets[fill[u]++] = v;
        }
    }
    auto count = [&](std::uint32_t u, std::uint32_t v) {
        int c = 0;
        for (std::uint32_t e = start[u]; e < start[u + 1]; ++e) c += targets[e] == v;
        return c;
    };
    Topology topo;
    topo.closed = edge_count > 0;
    for (std::uint32_t u = 0; u < n && topo.closed; ++u) {
        for (std::uint32_t e = start[u]; e < start[u + 1] && topo.closed; ++e) {
            const std::uint32_t v = targets[e];
            topo.closed = count(u, v) == 1 && count(v, u) == 1;
        }
    }
    std::vector<std::int64_t> component_of(n, -1);
    for (std::size_t f = 0; f < t; ++f) {
        const std::uint32_t root = find(id[m.triangles[3 * f]]);
        if (component_of[root] < 0) {
            component_of[root] = static_cast<std::int64_t>(topo.components.size());
            Component c;
            c.rep = point_of(m, m.triangles[3 * f]);
            c.triangle = static_cast<std::uint32_t>(f);
            topo.components.push_back(c);
        }
        Component& c = topo.components[component_of[root]];
        for (int k = 0; k < 3; ++k) c.box.add(point_of(m, m.triangles[3 * f + k]));
    }
    return topo;
}

/// One traverse part, in its own coordinates (offset 0).
struct Part {
    std::vector<Vec> tris;  ///< surface triangles, 3 points each, in BVH leaf order
    Bvh bvh;
    Box box;
    bool closed = false;
    bool hull_surface = false;  ///< closed and convex: its hull's triangles stand for its surface
    std::vector<Component> components;
    // Broad phase: the part's hull, as points, edge directions, and fixed axes with the hull's
    // extent along each.
    std::vector<Vec> hull_points;
    std::vector<Vec> hull_edges;
    std::vector<Vec> axes;
    std::vector<double> axis_lo, axis_hi;
};

/// An axis with the interval the swept hull covers along it.
struct Axis {
    Vec n;
    double lo, hi;
};

/// Time window [t0, t1] within [0, limit] in which the box `moving` (local coordinates) translated
/// by a + t d overlaps `target`; false when there is none. Conservative when `moving` was inflated
/// by the tolerance (the tolerance dominates the rounding of these few operations).
bool overlap_window(const Box& moving, const Vec& a, const Vec& d, const Box& target, double limit,
                    double* t0_out, double* t1_out) {
    double t0 = 0.0, t1 = limit;
    for (int k = 0; k < 3; ++k) {
        const double lo = moving.lo[k] + a[k], hi = moving.hi[k] + a[k];
        if (d[k] == 0.0) {
            if (target.lo[k] > hi || lo > target.hi[k]) return false;
            continue;
        }
        const double ta = (target.lo[k] - hi) / d[k], tb = (target.hi[k] - lo) / d[k];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
        if (!(t0 <= t1)) return false;
    }
    *t0_out = t0;
    *t1_out = t1;
    return true;
}

Box triangle_box(const Vec* t) {
    Box b;
    for (int k = 0; k < 3; ++k) b.add(t[k]);
    return b;
}

/// The offset at fraction t of the leg a -> b; exactly b at t = 1 so that consecutive legs agree.
Vec offset_at(const Vec& a, const Vec& b, double t) { return t == 1.0 ? b : a + t * (b - a); }

/// The 8 triangles whose union is the sweep of triangle p (local) from offset w0 to w1; the first
/// is p at w0 (the start cap). fraction_of() tells where along the sweep a point of piece k lies.
void sweep_pieces(const Vec* p, const Vec& w0, const Vec& w1, Vec pieces[8][3]) {
    const Vec a[3] = {p[0] + w0, p[1] + w0, p[2] + w0};
    const Vec b[3] = {p[0] + w1, p[1] + w1, p[2] + w1};
    for (int k = 0; k < 3; ++k) {
        pieces[0][k] = a[k];
        pieces[1][k] = b[k];
    }
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        Vec* first = pieces[2 + 2 * i];
        Vec* second = pieces[3 + 2 * i];
        first[0] = a[i], first[1] = a[j], first[2] = b[j];
        second[0] = a[i], second[1] = b[j], second[2] = b[i];
    }
}

/// Where along the sweep (0 at w0, 1 at w1) the point with barycentric weights w of piece k lies.
double fraction_of(int piece, const double w[3]) {
    if (piece == 0) return 0.0;
    if (piece == 1) return 1.0;
    return piece % 2 == 0 ? w[2] : w[1] + w[2];
}

/// The separating-axis picture of triangle p (local) moving by a + t d against triangle q, in
/// floating point, over t in [0, limit]. Returns false when one axis keeps them apart by more than
/// `tol` (times the axis length) over the whole window: a proof of no contact, since rounding is
/// far below tol. Otherwise true, with *estimate the first t at which no axis separates them (the
/// exact first contact up to rounding; NaN when the axes cannot tell).
bool sat_window(const Vec* p, const Vec* q, const Vec& a, const Vec& d, double limit, double tol,
                double* estimate) {
    const Vec ep[3] = {p[1] - p[0], p[2] - p[1], p[0] - p[2]};
    const Vec eq[3] = {q[1] - q[0], q[2] - q[1], q[0] - q[2]};
    const Vec np = glm::cross(ep[0], ep[1]), nq = glm::cross(eq[0], eq[1]);
    Vec axes[17];
    int count = 0;
    axes[count++] = np;
    axes[count++] = nq;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) axes[count++] = glm::cross(ep[i], eq[j]);
        axes[count++] = glm::cross(np, ep[i]);
        axes[count++] = glm::cross(nq, eq[i]);
    }
    double t_lo = 0.0, t_hi = limit;
    for (int k = 0; k < count; ++k) {
        const Vec& n = axes[k];
        const double len = glm::length(n);
        if (!(len > 0.0)) continue;
        const double pa = glm::dot(n, p[0]), pb = glm::dot(n, p[1]), pc = glm::dot(n, p[2]);
        const double qa = glm::dot(n, q[0]), qb = glm::dot(n, q[1]), qc = glm::dot(n, q[2]);
        const double shift = glm::dot(n, a), s = glm::dot(n, d);
        const double pmin = std::min({pa, pb, pc}) + shift, pmax = std::max({pa, pb, pc}) + shift;
        const double qmin = std::min({qa, qb, qc}), qmax = std::max({qa, qb, qc});
        const double gap = tol * len;
        const double end_shift = s * limit;
        // Apart along n at both ends of the window (hence throughout: the motion is linear).
        if (pmax < qmin - gap && pmax + end_shift < qmin - gap) return false;
        if (pmin > qmax + gap && pmin + end_shift > qmax + gap) return false;
        if (s == 0.0) continue;
        const double t1 = (qmin - pmax) / s, t2 = (qmax - pmin) / s;
        t_lo = std::max(t_lo, std::min(t1, t2));
        t_hi = std::min(t_hi, std::max(t1, t2));
    }
    *estimate = t_lo <= t_hi ? t_lo : std::numeric_limits<double>::quiet_NaN();
    return true;
}

/// Fixed, "generic" directions for parity rays; a ray found degenerate (exactly) is retried with
/// the next one.
Vec ray_direction(int attempt) {
    static const Vec fixed[] = {{0.5377, 0.2971, 0.7891},  {-0.3119, 0.8263, 0.4705},
                                {0.6827, -0.5473, 0.4843}, {-0.4211, -0.3389, -0.8413}};
    if (attempt < 4) return fixed[attempt];
    // Beyond those, a deterministic pseudo-random sequence.
    std::uint64_t s = 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(attempt + 1);
    auto next = [&] {
        s ^= s >> 33;
        s *= 0xff51afd7ed558ccdull;
        s ^= s >> 33;
        return static_cast<double>(s >> 11) * 0x1p-53 * 2.0 - 1.0;
    };
    return {next(), next(), next() + 0.1};
}

/// Segment o -> f against a box (slab test); the caller passes the box inflated by its tolerance.
bool segment_hits_box(const Vec& o, const Vec& f, const Box& box) {
    double t0 = 0.0, t1 = 1.0;
    const Vec d = f - o;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0.0) {
            if (o[k] < box.lo[k] || o[k] > box.hi[k]) return false;
            continue;
        }
        const double ta = (box.lo[k] - o[k]) / d[k], tb = (box.hi[k] - o[k]) / d[k];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
        if (t0 > t1) return false;
    }
    return true;
}

template <typename Visit>
void for_each_in_box(const Bvh& bvh, const Box& query, Visit&& visit) {
    if (bvh.nodes.empty()) return;
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const BvhNode& node = bvh.nodes[stack[--top]];
        if (!node.box.overlaps(query)) continue;
        if (node.count) {
            for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
                if (visit(s)) return;
            }
        } else {
            stack[top++] = node.first;
            stack[top++] = node.first + 1;
        }
    }
}

std::string label(const char* kind, std::size_t index, const std::string& name) {
    std::string s = std::string(kind) + " " + std::to_string(index);
    if (!name.empty()) s += " ('" + name + "')";
    return s;
}

std::string validate_mesh(const TriangleMesh& m, const char* kind, std::size_t index) {
    const std::string who = label(kind, index, m.name);
    if (m.xyz.size() % 3 != 0) {
        return who + ": " + std::to_string(m.xyz.size()) + " coordinates are not whole points";
    }
    if (m.triangles.size() % 3 != 0) {
        return who + ": " + std::to_string(m.triangles.size()) +
               " triangle indices are not whole triangles";
    }
    for (std::size_t i = 0; i < m.xyz.size(); ++i) {
        const double x = m.xyz[i];
        if (!std::isfinite(x)) {
            return who + ": point " + std::to_string(i / 3) + " has a non-finite coordinate";
        }
        if (std::fabs(x) > kMaxCoordinate || (x != 0.0 && std::fabs(x) < kMinCoordinate)) {
            return who + ": point " + std::to_string(i / 3) +
                   " has a coordinate outside the supported range (0 or 2^-200..2^300 in "
                   "magnitude)";
        }
    }
    const std::size_t points = m.xyz.size() / 3;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        if (m.triangles[i] >= points) {
            return who + ": triangle " + std::to_string(i / 3) + " refers to point " +
                   std::to_string(m.triangles[i]) + ", but there are only " +
                   std::to_string(points) + " points";
        }
    }
    return {};
}

}  // namespace

// ---------------------------------------------------------------------------------------------

struct RouteChecker::Impl {
    Scene scene;
    std::string error;
    double build_seconds = 0.0;
    double margin = 0.0;
    double scale = 0.0;  ///< largest |coordinate| of the geometry
    Box world;           ///< box of all geometry (parts at offset 0 and obstacles)

    std::vector<Part> parts;

    // Obstacle triangles of every obstacle in one BVH, stored in its leaf order.
    std::vector<Vec> tris;
    std::vector<std::uint32_t> tri_obstacle, tri_index;
    Bvh bvh;
    std::vector<char> obstacle_closed;
    std::vector<Box> obstacle_box;
    std::vector<Component> obstacle_components;

    void build();
    void build_part(const TriangleMesh& mesh, Part& part);

    /// Absolute tolerance for floating-point filters around offsets up to `offset_scale`: far
    /// above the rounding of the few operations the filters do, far below anything geometric.
    double tolerance(double offset_scale) const {
        return 1e-12 * (scale + offset_scale + margin) + 1e-290;
    }

    struct Found {
        bool found = false;
        double lo = 1.0, hi = 1.0;
        std::int64_t obstacle = -1, triangle = -1, part = -1;
        std::uint32_t slot = 0;        ///< obstacle triangle (BVH slot)
        std::uint32_t part_slot = 0;   ///< part triangle (BVH slot)
        bool containment = false;
    };

    bool pair_static(const Vec* p, const Vec& w, const Vec* q) const {
        const Vec pw[3] = {p[0] + w, p[1] + w, p[2] + w};
        if (margin == 0.0) return triangles_meet(pw, q);
        double weights[3];
        return triangle_distance2(pw, q, weights) <= margin * margin;
    }

    /// Contact of p swept from w0 to w1 with q, p at w0 being known clear.
    bool pair_sweep(const Vec* p, const Vec& w0, const Vec& w1, const Vec* q) const {
        Vec pieces[8][3];
        sweep_pieces(p, w0, w1, pieces);
        for (int k = 1; k < 8; ++k) {
            if (margin == 0.0) {
                if (triangles_meet(pieces[k], q)) return true;
            } else {
                double weights[3];
                if (triangle_distance2(pieces[k], q, weights) <= margin * margin) return true;
            }
        }
        return false;
    }

    bool inside_part(const Part& part, const Vec& w, const Vec& x, double tol) const;
    bool inside_obstacle(std::uint32_t o, const Vec& x, double tol) const;
    bool static_touch(std::size_t pi, const Vec& w, Found* found) const;
    void sweep_part(std::size_t pi, const Vec& a, const Vec& b, Found* found) const;

    struct Nearest {
        double distance = kInf;
        double fraction = 0.0;
        std::int64_t obstacle = -1, triangle = -1, part = -1;
    };
    void nearest_over_leg(std::size_t pi, const Vec& a, const Vec& b, Nearest* best) const;

    bool check_offsets(const double* xyz, std::size_t count, std::string* error) const;
    LegReport check_leg(const Vec& a, const Vec& b, const RouteOptions& options) const;
    void check_legs(const double* xyz, std::size_t count, const RouteOptions& options,
                    LegReport* legs) const;
    StaticContact contact_at(const Vec& w, bool want_distance) const;
};

void RouteChecker::Impl::build_part(const TriangleMesh& mesh, Part& part) {
    const Topology topo = analyze(mesh);
    part.closed = topo.closed;
    part.components = topo.components;

    // The hull of the referenced points (unreferenced points are not part of the geometry).
    std::vector<char> used(mesh.xyz.size() / 3, 0);
    for (std::uint32_t i : mesh.triangles) used[i] = 1;
    std::vector<double> pts;
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (used[i]) pts.insert(pts.end(), &mesh.xyz[3 * i], &mesh.xyz[3 * i + 3]);
    }
    for (std::size_t i = 0; i < pts.size(); i += 3) part.box.add(Vec(pts[i], pts[i + 1], pts[i + 2]));
    HullOptions options;
    options.merge_coplanar = true;
    const Hull h = hull(PointSpan(pts), options);
    auto hp = [&](std::uint32_t i) { return Vec(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]); };
    for (std::uint32_t v : h.vertices) part.hull_points.push_back(hp(v));
    // Edges of the hull (of its polygon faces when it is a polytope) and the fixed axes: the
    // faces' normals and the coordinate axes.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    if (h.dimension == 3) {
        for (std::size_t f = 0; f + 1 < h.face_offsets.size(); ++f) {
            const std::uint32_t* v = &h.face_vertices[h.face_offsets[f]];
            const std::uint32_t count = h.face_offsets[f + 1] - h.face_offsets[f];
            for (std::uint32_t k = 0; k < count; ++k) {
                const std::uint32_t u = v[k], w = v[(k + 1) % count];
                if (u < w) edges.emplace_back(u, w);
            }
            const Vec n = glm::cross(hp(v[1]) - hp(v[0]), hp(v[2]) - hp(v[0]));
            part.axes.push_back(glm::normalize(n));
        }
    } else {
        for (std::size_t k = 0; k < h.vertices.size(); ++k) {
            for (std::size_t j = k + 1; j < h.vertices.size() && j < k + 2 + (h.dimension == 2); ++j) {
                edges.emplace_back(h.vertices[k], h.vertices[j]);
            }
        }
        if (h.dimension == 2 && h.vertices.size() > 2) {
            edges.emplace_back(h.vertices.back(), h.vertices.front());
            part.axes.push_back(Vec(h.normal[0], h.normal[1], h.normal[2]));
        }
    }
    for (const auto& e : edges) part.hull_edges.push_back(hp(e.second) - hp(e.first));
    part.axes.push_back(Vec(1, 0, 0));
    part.axes.push_back(Vec(0, 1, 0));
    part.axes.push_back(Vec(0, 0, 1));
    for (const Vec& n : part.axes) {
        double lo = kInf, hi = -kInf;
        for (const Vec& p : part.hull_points) {
            lo = std::min(lo, glm::dot(n, p));
            hi = std::max(hi, glm::dot(n, p));
        }
        part.axis_lo.push_back(lo);
        part.axis_hi.push_back(hi);
    }

    // A closed part whose every triangle lies in a supporting plane of its hull (all with the same
    // orientation) and which does not cover the hull twice is its hull: its solid is the hull's,
    // so the hull's (usually far fewer) triangles stand for its surface.
    if (part.closed && h.dimension == 3) {
        int orientation = 0;
        bool convex = true;
        double area = 0.0;
        for (std::size_t f = 0; convex && f < mesh.triangles.size() / 3; ++f) {
            const Vec a = point_of(mesh, mesh.triangles[3 * f]);
            const Vec b = point_of(mesh, mesh.triangles[3 * f + 1]);
            const Vec c = point_of(mesh, mesh.triangles[3 * f + 2]);
            area += 0.5 * glm::length(glm::cross(b - a, c - a));
            for (const Vec& p : part.hull_points) {
                const int s = orient3d(ptr(a), ptr(b), ptr(c), ptr(p));
                if (s == 0) continue;
                if (orientation == 0) orientation = s;
                if (s != orientation) {
                    convex = false;
                    break;
                }
            }
        }
        if (convex && area <= 1.5 * h.area) {
            part.hull_surface = true;
            for (std::uint32_t v : h.triangles) part.tris.push_back(hp(v));
            Component c;
            c.rep = part.hull_points.front();
            c.box = part.box;
            part.components.assign(1, c);
        }
    }
    if (!part.hull_surface) {
        for (std::uint32_t v : mesh.triangles) part.tris.push_back(point_of(mesh, v));
    }
    part.bvh.build(part.tris);
    std::vector<Vec> ordered(part.tris.size());
    for (std::size_t s = 0; s < part.bvh.order.size(); ++s) {
        for (int k = 0; k < 3; ++k) ordered[3 * s + k] = part.tris[3 * part.bvh.order[s] + k];
    }
    part.tris.swap(ordered);
}

void RouteChecker::Impl::build() {
    if (scene.parts.empty()) {
        error = "the traverse has no parts";
        return;
    }
    if (!std::isfinite(scene.margin) || scene.margin < 0.0 || scene.margin > kMaxCoordinate) {
        error = "margin must be a finite number >= 0 (got " + std::to_string(scene.margin) + ")";
        return;
    }
    margin = scene.margin;
    for (std::size_t i = 0; i < scene.parts.size(); ++i) {
        error = validate_mesh(scene.parts[i], "part", i);
        if (!error.empty()) return;
        if (scene.parts[i].triangles.empty()) {
            error = label("part", i, scene.parts[i].name) + ": no triangles";
            return;
        }
    }
    for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
        error = validate_mesh(scene.obstacles[i], "obstacle", i);
        if (!error.empty()) return;
    }
    for (const auto* meshes : {&scene.parts, &scene.obstacles}) {
        for (const TriangleMesh& m : *meshes) {
            for (double x : m.xyz) scale = std::max(scale, std::fabs(x));
        }
    }

    parts.resize(scene.parts.size());
    for (std::size_t i = 0; i < parts.size(); ++i) {
        build_part(scene.parts[i], parts[i]);
        world.add(parts[i].box);
    }

    // Every obstacle triangle in one BVH; first[o] numbers obstacle o's triangles globally.
    std::vector<std::size_t> first(scene.obstacles.size() + 1, 0);
    for (std::size_t o = 0; o < scene.obstacles.size(); ++o) {
        const TriangleMesh& m = scene.obstacles[o];
        first[o + 1] = first[o] + m.triangles.size() / 3;
        Topology topo = analyze(m);
        obstacle_closed.push_back(topo.closed);
        Box box;
        for (Component& c : topo.components) {
            c.mesh = static_cast<std::uint32_t>(o);
            box.add(c.box);
            obstacle_components.push_back(c);
        }
        obstacle_box.push_back(box);
        world.add(box);
    }
    const std::size_t n = first.back();
    std::vector<std::uint32_t> owner(n);
    for (std::size_t o = 0; o < scene.obstacles.size(); ++o) {
        std::fill(owner.begin() + first[o], owner.begin() + first[o + 1], static_cast<std::uint32_t>(o));
    }
    auto corner = [&](std::size_t t, int k) {
        const TriangleMesh& m = scene.obstacles[owner[t]];
        return point_of(m, m.triangles[3 * (t - first[owner[t]]) + k]);
    };
    bvh.build(n, [&](std::size_t t) {
        Box b;
        for (int k = 0; k < 3; ++k) b.add(corner(t, k));
        return b;
    });
    tris.resize(3 * n);
    tri_obstacle.resize(n);
    tri_index.resize(n);
    for (std::size_t s = 0; s < n; ++s) {
        const std::uint32_t t = bvh.order[s];
        for (int k = 0; k < 3; ++k) tris[3 * s + k] = corner(t, k);
        tri_obstacle[s] = owner[t];
        tri_index[s] = static_cast<std::uint32_t>(t - first[owner[t]]);
    }
}

namespace {

/// Ray parity of x against the triangles `bvh` holds: `crossing(slot, far)` classifies one
/// triangle (ray_crossing), `shift` maps world points into the BVH's coordinates (for culling
/// only). A ray found degenerate (exactly) is retried in another direction; a point never
/// certified outside counts as inside, so that doubt becomes a hit, never a false "clear".
template <typename Crossing>
bool parity_inside(const Bvh& bvh, const Vec& x, const Vec& shift, const Box& box, double tol,
                   Crossing&& crossing) {
    if (bvh.nodes.empty()) return false;
    const double reach = 4.0 * (glm::length(box.hi - box.lo) + glm::length(x - box.lo)) + 1.0;
    for (int attempt = 0; attempt < 64; ++attempt) {
        const Vec far = x + reach * ray_direction(attempt);
        const Vec local_x = x - shift, local_far = far - shift;
        int crossings = 0;
        bool degenerate = false;
        std::uint32_t stack[128];
        int top = 0;
        stack[top++] = 0;
        while (top > 0 && !degenerate) {
            const BvhNode& node = bvh.nodes[stack[--top]];
            if (!segment_hits_box(local_x, local_far, node.box.inflated(tol))) continue;
            if (node.count == 0) {
                stack[top++] = node.first;
                stack[top++] = node.first + 1;
                continue;
            }
            for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
                const int r = crossing(s, far);
                if (r < 0) {
                    degenerate = true;
                    break;
                }
                crossings += r;
            }
        }
        if (!degenerate) return crossings % 2 == 1;
    }
    return true;
}

}  // namespace

bool RouteChecker::Impl::inside_part(const Part& part, const Vec& w, const Vec& x,
                                     double tol) const {
    return parity_inside(part.bvh, x, w, part.box.shifted(w), tol,
                         [&](std::uint32_t s, const Vec& far) {
                             const Vec* p = &part.tris[3 * s];
                             const Vec q[3] = {p[0] + w, p[1] + w, p[2] + w};
                             return ray_crossing(x, far, q);
                         });
}

bool RouteChecker::Impl::inside_obstacle(std::uint32_t o, const Vec& x, double tol) const {
    return parity_inside(bvh, x, Vec(0.0), obstacle_box[o], tol,
                         [&](std::uint32_t s, const Vec& far) {
                             return tri_obstacle[s] == o ? ray_crossing(x, far, &tris[3 * s]) : 0;
                         });
}

bool RouteChecker::Impl::static_touch(std::size_t pi, const Vec& w, Found* found) const {
    const Part& part = parts[pi];
    const double tol = tolerance(std::max({std::fabs(w.x), std::fabs(w.y), std::fabs(w.z)}));
    const Box placed = part.box.shifted(w);
    const Box query = placed.inflated(margin + tol);
    // Surfaces within the margin.
    bool hit = false;
    for_each_in_box(bvh, query, [&](std::uint32_t s) {
        const Vec* q = &tris[3 * s];
        const Box qbox = triangle_box(q);
        if (!qbox.overlaps(query)) return false;
        const Box local = qbox.shifted(-w).inflated(margin + tol);
        for_each_in_box(part.bvh, local, [&](std::uint32_t ps) {
            if (!pair_static(&part.tris[3 * ps], w, q)) return false;
            hit = true;
            found->slot = s;
            found->part_slot = ps;
            found->obstacle = tri_obstacle[s];
            found->triangle = tri_index[s];
            return true;
        });
        return hit;
    });
    if (hit) {
        found->containment = false;
        found->part = static_cast<std::int64_t>(pi);
        return true;
    }
    // No surfaces meet, so each connected piece is entirely inside or outside the other's solid:
    // one vertex per piece decides. A piece inside the other lies inside its box.
    const Box loose = placed.inflated(tol);
    if (part.closed) {
        for (const Component& c : obstacle_components) {
            if (loose.contains(c.box) && inside_part(part, w, c.rep, tol)) {
                *found = Found{};
                found->containment = true;
                found->obstacle = c.mesh;
                found->triangle = c.triangle;
                found->part = static_cast<std::int64_t>(pi);
                return true;
            }
        }
    }
    for (std::uint32_t o = 0; o < obstacle_closed.size(); ++o) {
        if (!obstacle_closed[o] || !obstacle_box[o].inflated(tol).contains(placed)) continue;
        for (const Component& c : part.components) {
            if (inside_obstacle(o, c.rep + w, tol)) {
                *found = Found{};
                found->containment = true;
                found->obstacle = o;
                found->triangle = 0;
                found->part = static_cast<std::int64_t>(pi);
                return true;
            }
        }
    }
    return false;
}

void RouteChecker::Impl::sweep_part(std::size_t pi, const Vec& a, const Vec& b,
                                    Found* found) const {
    const Part& part = parts[pi];
    if (bvh.nodes.empty()) return;
    const Vec d = b - a;
    const double offset_scale = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z),
                                          std::fabs(b.x), std::fabs(b.y), std::fabs(b.z)});
    const double tol = tolerance(offset_scale);
    const double reach = margin + tol;
    const Box moving = part.box.inflated(reach);

    // Broad-phase axes: the fixed ones, and d x (hull edge), the swept hull's side planes.
    std::vector<Axis> axes;
    axes.reserve(part.axes.size() + part.hull_edges.size());
    for (std::size_t k = 0; k < part.axes.size(); ++k) {
        const double da = glm::dot(part.axes[k], a), db = glm::dot(part.axes[k], b);
        axes.push_back({part.axes[k], part.axis_lo[k] + std::min(da, db),
                        part.axis_hi[k] + std::max(da, db)});
    }
    const bool small_hull = part.hull_points.size() <= 64;
    if (small_hull && part.hull_edges.size() * part.hull_points.size() <= 8192) {
        for (const Vec& e : part.hull_edges) {
            const Vec c = glm::cross(d, e);
            const double len = glm::length(c);
            if (!(len > 1e-9 * glm::length(d) * glm::length(e))) continue;
            const Vec n = c / len;
            double lo = kInf, hi = -kInf;
            for (const Vec& p : part.hull_points) {
                lo = std::min(lo, glm::dot(n, p));
                hi = std::max(hi, glm::dot(n, p));
            }
            const double da = glm::dot(n, a), db = glm::dot(n, b);
            axes.push_back({n, lo + std::min(da, db), hi + std::max(da, db)});
        }
    }
    // True when q is certainly farther than the margin from the swept hull.
    auto separated = [&](const Vec* q) {
        for (const Axis& axis : axes) {
            const double p0 = glm::dot(axis.n, q[0]), p1 = glm::dot(axis.n, q[1]),
                         p2 = glm::dot(axis.n, q[2]);
            if (std::min({p0, p1, p2}) > axis.hi + reach) return true;
            if (std::max({p0, p1, p2}) < axis.lo - reach) return true;
        }
        if (!small_hull) return false;
        const Vec c = glm::cross(q[1] - q[0], q[2] - q[0]);
        const double len = glm::length(c);
        if (!(len > 0.0) || !std::isfinite(len)) return false;
        const Vec n = c / len;
        double lo = kInf, hi = -kInf;
        for (const Vec& p : part.hull_points) {
            lo = std::min(lo, glm::dot(n, p));
            hi = std::max(hi, glm::dot(n, p));
        }
        const double da = glm::dot(n, a), db = glm::dot(n, b);
        lo += std::min(da, db);
        hi += std::max(da, db);
        const double p0 = glm::dot(n, q[0]), p1 = glm::dot(n, q[1]), p2 = glm::dot(n, q[2]);
        return std::min({p0, p1, p2}) > hi + reach || std::max({p0, p1, p2}) < lo - reach;
    };

    auto limit = [&] { return found->found ? found->lo : 1.0; };

    // The narrow phase for one obstacle triangle: the part triangles whose sweep can reach it,
    // earliest possible contact first; each one that touches it before the current bracket
    // moves the bracket (bisection on sub-leg sweeps: sweeping further only adds contact).
    std::vector<std::pair<double, std::uint32_t>> pairs;
    auto narrow = [&](std::uint32_t s, const Box& qbox) {
        const Vec* q = &tris[3 * s];
        const Vec e = offset_at(a, b, limit());
        const Box local = Box{qbox.lo - glm::max(a, e), qbox.hi - glm::min(a, e)}.inflated(reach);
        pairs.clear();
        for_each_in_box(part.bvh, local, [&](std::uint32_t ps) {
            double t0, t1;
            const Box pbox = triangle_box(&part.tris[3 * ps]).inflated(reach);
            if (overlap_window(pbox, a, d, qbox, limit(), &t0, &t1)) pairs.emplace_back(t0, ps);
            return false;
        });
        std::sort(pairs.begin(), pairs.end());
        for (const auto& pr : pairs) {
            double hi = limit();
            if (pr.first > hi) break;
            const Vec* p = &part.tris[3 * pr.second];
            double estimate;
            if (!sat_window(p, q, a, d, hi, reach, &estimate)) continue;
            if (!pair_sweep(p, a, offset_at(a, b, hi), q)) continue;
            double lo = 0.0;  // the start pose is known clear
            if (margin == 0.0 && estimate >= 0.0 && estimate <= hi) {
                // Margin 0: the separating axes give the first contact up to rounding; two exact
                // sweeps certify a bracket around it (else they narrow the bisection).
                const double below = estimate - 0.25 * kBracketWidth;
                const double above = std::min(hi, estimate + 0.25 * kBracketWidth);
                if (below > 0.0) {
                    if (pair_sweep(p, a, offset_at(a, b, below), q)) {
                        hi = below;
                    } else {
                        lo = below;
                    }
                }
                if (above > lo && above < hi) {
                    if (pair_sweep(p, a, offset_at(a, b, above), q)) {
                        hi = above;
                    } else {
                        lo = above;
                    }
                }
            }
            while (hi - lo > kBracketWidth) {
                const double mid = 0.5 * (lo + hi);
                if (pair_sweep(p, a, offset_at(a, b, mid), q)) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            found->found = true;
            found->lo = lo;
            found->hi = hi;
            found->slot = s;
            found->part_slot = pr.second;
            found->obstacle = tri_obstacle[s];
            found->triangle = tri_index[s];
            found->part = static_cast<std::int64_t>(pi);
        }
    };

    // Best-first over the obstacle BVH by the earliest time the part's box can reach a node.
    std::vector<std::pair<double, std::uint32_t>> heap;
    auto push = [&](std::uint32_t node) {
        double t0, t1;
        if (overlap_window(moving, a, d, bvh.nodes[node].box, limit(), &t0, &t1)) {
            heap.emplace_back(t0, node);
            std::push_heap(heap.begin(), heap.end(), std::greater<>());
        }
    };
    push(0);
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), std::greater<>());
        const auto [t, index] = heap.back();
        heap.pop_back();
        if (t > limit()) break;
        const BvhNode& node = bvh.nodes[index];
        if (node.count == 0) {
            push(node.first);
            push(node.first + 1);
            continue;
        }
        for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
            const Vec* q = &tris[3 * s];
            const Box qbox = triangle_box(q);
            double t0, t1;
            if (!overlap_window(moving, a, d, qbox, limit(), &t0, &t1)) continue;
            if (separated(q)) continue;
            narrow(s, qbox);
        }
    }
}

namespace {

/// Lower bounds on the distance between a fixed box and a box moving from offset a to offset b:
/// the distance between the segment [a, b] and the box `target - moving` (Minkowski difference),
/// bounded below by its box distance to the segment's box and by the gap seen in the plane
/// perpendicular to the leg (unit u, v span that plane).
struct SweptBound {
    Vec a, b, u, v;
    double au, av;

    SweptBound(const Vec& a_, const Vec& b_) : a(a_), b(b_) {
        const Vec d = b - a;
        const double len = glm::length(d);
        const Vec n = len > 0.0 ? d / len : Vec(1, 0, 0);
        const Vec helper = std::fabs(n.x) < 0.6 ? Vec(1, 0, 0) : Vec(0, 1, 0);
        u = glm::normalize(glm::cross(n, helper));
        v = glm::cross(n, u);
        au = glm::dot(a, u);
        av = glm::dot(a, v);
    }

    double operator()(const Box& target, const Box& moving) const {
        const Box m{target.lo - moving.hi, target.hi - moving.lo};
        Box segment;
        segment.add(a);
        segment.add(b);
        const double axis_aligned = m.distance(segment);
        const Vec c = (m.lo + m.hi) * 0.5, h = (m.hi - m.lo) * 0.5;
        const double ru = std::fabs(u.x) * h.x + std::fabs(u.y) * h.y + std::fabs(u.z) * h.z;
        const double rv = std::fabs(v.x) * h.x + std::fabs(v.y) * h.y + std::fabs(v.z) * h.z;
        const double gu = std::max(0.0, std::fabs(au - glm::dot(c, u)) - ru);
        const double gv = std::max(0.0, std::fabs(av - glm::dot(c, v)) - rv);
        return std::max(axis_aligned, std::sqrt(gu * gu + gv * gv));
    }
};

}  // namespace

void RouteChecker::Impl::nearest_over_leg(std::size_t pi, const Vec& a, const Vec& b,
                                          Nearest* best) const {
    const Part& part = parts[pi];
    if (bvh.nodes.empty()) return;
    const SweptBound bound(a, b);
    std::vector<std::pair<double, std::uint32_t>> heap;
    heap.emplace_back(bound(bvh.nodes[0].box, part.box), 0u);
    std::vector<std::pair<double, std::uint32_t>> part_stack;
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), std::greater<>());
        const auto [lower, index] = heap.back();
        heap.pop_back();
        if (lower >= best->distance) break;
        const BvhNode& node = bvh.nodes[index];
        if (node.count == 0) {
            for (std::uint32_t c = node.first; c < node.first + 2; ++c) {
                const double lb = bound(bvh.nodes[c].box, part.box);
                if (lb < best->distance) {
                    heap.emplace_back(lb, c);
                    std::push_heap(heap.begin(), heap.end(), std::greater<>());
                }
            }
            continue;
        }
        for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
            const Vec* q = &tris[3 * s];
            const Box qbox = triangle_box(q);
            if (bound(qbox, part.box) >= best->distance) continue;
            // Depth-first over the part's BVH, nearer child first.
            part_stack.clear();
            part_stack.emplace_back(bound(qbox, part.bvh.nodes[0].box), 0u);
            while (!part_stack.empty()) {
                const auto [pb, pn] = part_stack.back();
                part_stack.pop_back();
                if (pb >= best->distance) continue;
                const BvhNode& pnode = part.bvh.nodes[pn];
                if (pnode.count == 0) {
                    const double l0 = bound(qbox, part.bvh.nodes[pnode.first].box);
                    const double l1 = bound(qbox, part.bvh.nodes[pnode.first + 1].box);
                    if (l0 <= l1) {
                        part_stack.emplace_back(l1, pnode.first + 1);
                        part_stack.emplace_back(l0, pnode.first);
                    } else {
                        part_stack.emplace_back(l0, pnode.first);
                        part_stack.emplace_back(l1, pnode.first + 1);
                    }
                    continue;
                }
                for (std::uint32_t ps = pnode.first; ps < pnode.first + pnode.count; ++ps) {
                    const Vec* p = &part.tris[3 * ps];
                    if (bound(qbox, triangle_box(p)) >= best->distance) continue;
                    Vec pieces[8][3];
                    sweep_pieces(p, a, b, pieces);
                    for (int k = 0; k < 8; ++k) {
                        if (k > 0 && a == b) break;  // a leg of length zero: the start cap alone
                        if (triangle_box(pieces[k]).distance(qbox) >= best->distance) continue;
                        double w[3];
                        const double dist = triangle_distance(pieces[k], q, w);
                        if (dist < best->distance) {
                            best->distance = dist;
                            best->fraction = fraction_of(k, w);
                            best->obstacle = tri_obstacle[s];
                            best->triangle = tri_index[s];
                            best->part = static_cast<std::int64_t>(pi);
                        }
                    }
                }
            }
        }
    }
}

LegReport RouteChecker::Impl::check_leg(const Vec& a, const Vec& b,
                                        const RouteOptions& options) const {
    LegReport leg;
    Found found;
    for (std::size_t pi = 0; pi < parts.size() && !found.found; ++pi) {
        if (static_touch(pi, a, &found)) found.found = true;
    }
    if (found.found) {
        leg.status = LegStatus::StartOverlap;
        leg.fraction_lo = leg.fraction_hi = 0.0;
        leg.position[0] = a.x, leg.position[1] = a.y, leg.position[2] = a.z;
        double w[3];
        leg.clearance = 0.0;
        if (!found.containment) {
            const Vec* p = &parts[found.part].tris[3 * found.part_slot];
            const Vec pa[3] = {p[0] + a, p[1] + a, p[2] + a};
            leg.clearance = triangle_distance(pa, &tris[3 * found.slot], w);
        }
    } else {
        for (std::size_t pi = 0; pi < parts.size(); ++pi) sweep_part(pi, a, b, &found);
        if (found.found) {
            leg.status = LegStatus::Hit;
            leg.fraction_lo = found.lo;
            leg.fraction_hi = found.hi;
            const Vec at = offset_at(a, b, found.lo);
            leg.position[0] = at.x, leg.position[1] = at.y, leg.position[2] = at.z;
            // The distance of the contact pair at the bracket's end: at most the margin.
            const Vec* p = &parts[found.part].tris[3 * found.part_slot];
            const Vec wh = offset_at(a, b, found.hi);
            Vec pieces[8][3];
            sweep_pieces(p, a, wh, pieces);
            double best = kInf, w[3];
            for (int k = 1; k < 8; ++k) best = std::min(best, triangle_distance(pieces[k], &tris[3 * found.slot], w));
            leg.clearance = std::min(best, margin);
        }
    }
    if (found.found) {
        leg.obstacle = found.obstacle;
        leg.triangle = found.triangle;
        leg.part = found.part;
    } else if (options.clearance) {
        Nearest best;
        for (std::size_t pi = 0; pi < parts.size(); ++pi) nearest_over_leg(pi, a, b, &best);
        leg.clearance = best.distance;
        leg.obstacle = best.obstacle;
        leg.triangle = best.triangle;
        leg.part = best.part;
        leg.fraction_lo = leg.fraction_hi = best.obstacle >= 0 ? best.fraction : 0.0;
        const Vec at = offset_at(a, b, leg.fraction_lo);
        leg.position[0] = at.x, leg.position[1] = at.y, leg.position[2] = at.z;
    } else {
        leg.position[0] = a.x, leg.position[1] = a.y, leg.position[2] = a.z;
    }
    if (options.samples > 0) {
        for (std::uint32_t k = 0; k <= options.samples; ++k) {
            const double t = k == options.samples ? 1.0 : static_cast<double>(k) / options.samples;
            const Vec w = offset_at(a, b, t);
            Found f;
            bool touch = false;
            for (std::size_t pi = 0; pi < parts.size() && !touch; ++pi) touch = static_touch(pi, w, &f);
            if (touch) {
                leg.sampled_hit = true;
                leg.sampled_fraction = t;
                break;
            }
        }
    }
    return leg;
}

void RouteChecker::Impl::check_legs(const double* xyz, std::size_t count,
                                    const RouteOptions& options, LegReport* legs) const {
    // Each leg's report is a function of its two waypoints, the options and this Impl, which
    // check() never modifies (every scratch buffer of the check path is local to check_leg and
    // what it calls), and goes to its own slot: how legs are spread over threads cannot change a
    // bit of it. New threads inherit the caller's floating-point environment (POSIX), so the
    // rounding is the same on every thread.
    const unsigned threads = detail::resolve_threads(options.threads, count);
    // Blocks of consecutive legs: a clear verdict takes a few microseconds, so handing out legs
    // one by one would be mostly overhead; about 8 blocks per thread (at most 64 legs each) keep
    // uneven legs balanced (a leg with clearance can cost 100 times a clear verdict) and the
    // progress reports frequent. The split depends on the leg and thread counts only.
    const std::size_t per_block =
        std::clamp<std::size_t>((count + 8 * std::size_t{threads} - 1) / (8 * std::size_t{threads}), 1, 64);
    const std::size_t blocks = (count + per_block - 1) / per_block;

    std::atomic<std::size_t> done{0};
    std::mutex progress_mutex;
    std::size_t reported = 0;  // guarded by progress_mutex
    auto legs_finished = [&](std::size_t finished) {
        const std::size_t total = done.fetch_add(finished, std::memory_order_acq_rel) + finished;
        if (!options.progress) return;
        // One report at a time, so that the counts arrive in increasing order. A thread that finds
        // another one reporting skips its turn (its legs are in the count the next report reads),
        // except the one finishing the last legs: the final count must be reported.
        std::unique_lock<std::mutex> lock(progress_mutex, std::defer_lock);
        if (total == count) {
            lock.lock();
        } else if (!lock.try_lock()) {
            return;
        }
        const std::size_t latest = done.load(std::memory_order_acquire);
        if (latest <= reported) return;  // a later report already covered these legs
        reported = latest;
        options.progress(latest);
    };
    detail::parallel_for(threads, blocks, [&](std::size_t block) {
        const std::size_t first = block * per_block, last = std::min(count, first + per_block);
        for (std::size_t k = first; k < last; ++k) {
            const double* p = xyz + 3 * k;
            legs[k] = check_leg(Vec(p[0], p[1], p[2]), Vec(p[3], p[4], p[5]), options);
        }
        legs_finished(last - first);
    });
}

StaticContact RouteChecker::Impl::contact_at(const Vec& w, bool want_distance) const {
    StaticContact result;
    Found found;
    for (std::size_t pi = 0; pi < parts.size() && !result.contact; ++pi) {
        if (static_touch(pi, w, &found)) {
            result.contact = true;
            result.obstacle = found.obstacle;
            result.triangle = found.triangle;
            result.part = found.part;
        }
    }
    if (want_distance) {
        if (result.contact && (found.containment || margin == 0.0)) {
            result.distance = 0.0;
        } else {
            // The minimum over a leg of length zero is the static distance.
            Nearest best;
            for (std::size_t pi = 0; pi < parts.size(); ++pi) nearest_over_leg(pi, w, w, &best);
            result.distance = best.distance;
            if (!result.contact) {
                result.obstacle = best.obstacle;
                result.triangle = best.triangle;
                result.part = best.part;
            }
        }
    }
    return result;
}

bool RouteChecker::Impl::check_offsets(const double* xyz, std::size_t count,
                                       std::string* message) const {
    for (std::size_t i = 0; i < 3 * count; ++i) {
        const double x = xyz[i];
        if (!std::isfinite(x)) {
            *message = "route: waypoint " + std::to_string(i / 3) + " has a non-finite coordinate";
            return false;
        }
        if (std::fabs(x) > kMaxCoordinate || (x != 0.0 && std::fabs(x) < kMinCoordinate)) {
            *message = "route: waypoint " + std::to_string(i / 3) +
                       " has a coordinate outside the supported range (0 or 2^-200..2^300 in "
                       "magnitude)";
            return false;
        }
    }
    return true;
}

// ---------------------------------------------------------------------------------------------

RouteChecker::RouteChecker(Scene scene) : impl_(std::make_unique<Impl>()) {
    const auto start = std::chrono::steady_clock::now();
    impl_->scene = std::move(scene);
    impl_->build();
    impl_->build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

RouteChecker::~RouteChecker() = default;
RouteChecker::RouteChecker(RouteChecker&&) noexcept = default;
RouteChecker& RouteChecker::operator=(RouteChecker&&) noexcept = default;

const std::string& RouteChecker::error() const { return impl_->error; }
const Scene& RouteChecker::scene() const { return impl_->scene; }
double RouteChecker::build_seconds() const { return impl_->build_seconds; }

RouteReport RouteChecker::check(const double* route_xyz, std::size_t waypoint_count,
                                const RouteOptions& options) const {
    RouteReport report;
    report.build_seconds = impl_->build_seconds;
    report.clear = false;
    if (!impl_->error.empty()) {
        report.error = impl_->error;
        return report;
    }
    if (waypoint_count < 2) {
        report.error = "route: at least 2 waypoints are needed (got " +
                       std::to_string(waypoint_count) + ")";
        return report;
    }
    if (!impl_->check_offsets(route_xyz, waypoint_count, &report.error)) return report;
    const auto start = std::chrono::steady_clock::now();
    report.legs.resize(waypoint_count - 1);
    impl_->check_legs(route_xyz, report.legs.size(), options, report.legs.data());
    // The aggregates in leg order, after the parallel loop: the same operations in the same order
    // for every thread count.
    report.clear = true;
    for (const LegReport& leg : report.legs) {
        report.clear = report.clear && leg.status == LegStatus::Clear;
        if (!std::isnan(leg.clearance)) report.min_clearance = std::min(report.min_clearance, leg.clearance);
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

RouteReport RouteChecker::check(const RouteOptions& options) const {
    const std::vector<double>& route = impl_->scene.route;
    if (route.size() % 3 != 0 && impl_->error.empty()) {
        RouteReport report;
        report.clear = false;
        report.error = "route: " + std::to_string(route.size()) + " coordinates are not whole waypoints";
        return report;
    }
    return check(route.data(), route.size() / 3, options);
}

StaticContact RouteChecker::static_contact(const double offset[3], bool want_distance) const {
    std::string message;
    if (!impl_->error.empty() || !impl_->check_offsets(offset, 1, &message)) {
        StaticContact bad;
        bad.contact = true;
        return bad;
    }
    return impl_->contact_at(Vec(offset[0], offset[1], offset[2]), want_distance);
}

StaticContact static_contact(const RouteChecker& checker, const double offset[3],
                             bool want_distance) {
    return checker.static_contact(offset, want_distance);
}

RouteReport check_route(Scene scene, const RouteOptions& options) {
    return RouteChecker(std::move(scene)).check(options);
}

}  // namespace hullkit
