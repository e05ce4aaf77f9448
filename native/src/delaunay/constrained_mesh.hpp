// Private to native/src/delaunay: the constrained triangulation's working mesh (constrained.cpp
// builds it, refine.cpp refines it). See hullkit/constrained.hpp for the method and the rules.
//
// The working mesh is the incremental algorithm's (incremental.cpp): counter-clockwise triangles
// (3 vertices each, y up) with twin half-edges, closed by ghost triangles whose third corner is the
// point at infinity (kGhost). Half-edge e = 3t + k goes from corner k to corner k + 1. Per half-edge
// two numbers describe the segments along it: count (how many input segments lie on it; the
// same for both halves, > 0 means constrained) and wind (those running the half-edge's way minus
// those running against it; opposite for the two halves) which decides a polygon's inside.
#pragma once

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "delaunay_internal.hpp"
#include "hull/large_array.hpp"
#include "hullkit/constrained.hpp"
#include "hullkit/predicates.hpp"

namespace hullkit {
namespace constrained_detail {


constexpr std::uint32_t kGhost = 0xFFFFFFFFu;
constexpr std::uint32_t kDead = 0xFFFFFFFEu;

inline std::uint32_t next_edge(std::uint32_t e) { return e % 3 == 2 ? e - 2 : e + 1; }
inline std::uint32_t prev_edge(std::uint32_t e) { return e % 3 == 0 ? e + 2 : e - 1; }

/// The crossing of the lines through a, b and c, d (which cross properly), rounded to the nearest
/// double per coordinate (constrained.cpp).
void rounded_crossing(const double* a, const double* b, const double* c, const double* d, double* out);

struct Segment {
    std::uint32_t a, b;
    std::int32_t wind;    ///< ring edges a->b minus b->a along it
    std::uint32_t count;  ///< input segments along it
    std::uint32_t input;  ///< the input segment it is a piece of (for errors)
};

class Refiner;

class Cdt {
    friend class Refiner;  // refine.cpp: Delaunay refinement works on the mesh directly

public:
    std::string error;
    std::int64_t error_segment = -1;
    std::size_t crossings = 0;

    /// Takes the incremental algorithm's Delaunay mesh (ghosts included, local indices mapped back
    /// to the input's by `original`) as the working mesh; `xy` the input points scaled by
    /// 2^exponent (write() divides added points by it again).
    Cdt(std::vector<double> xy, delaunay_detail::Mesh&& mesh, const std::vector<std::uint32_t>& original, std::size_t max_added,
        int exponent)
        : xy_(std::move(xy)), input_count_(xy_.size() / 2), max_added_(max_added), exponent_(exponent) {
        vertex_ = std::move(mesh.vertex);
        twin_ = std::move(mesh.twin);
        // The per-vertex and per-half-edge arrays with the room the others have (the points' and
        // the mesh's: Input::spare_points), so that refinement does not copy them as they grow.
        detail::reserve_populated(out_, xy_.capacity() / 2, input_count_);
        out_.assign(input_count_, kGhost);
        for (std::uint32_t e = 0; e < vertex_.size(); ++e) {
            const std::uint32_t v = vertex_[e];
            vertex_[e] = v == mesh.ghost ? kGhost : original[v];
            if (v != mesh.ghost) out_[vertex_[e]] = e;
        }
        detail::reserve_populated(edge_, vertex_.capacity(), vertex_.size());
        edge_.assign(vertex_.size(), 0);
        records_.assign(1, Record{0, 0, kGhost, kGhost});
        detail::reserve_populated(region_, vertex_.capacity() / 3, vertex_.size() / 3);
        region_.assign(vertex_.size() / 3, 0);
        // The marks start in the incremental mesh's (pages already touched), above its numbers.
        stamp_ = std::move(mesh.mark);
        generation_ = mesh.mark_limit;
    }

    /// Room for the records of `count` segments (one each, unless they cross or meet points), and
    /// of the pieces refinement may split them into (one per spare point).
    void reserve_segments(std::size_t count) {
        detail::reserve_populated(records_, records_.size() + count + (xy_.capacity() - xy_.size()) / 2, records_.size() + count);
    }

    /// Inserts a segment and everything it turns into; false on failure (error set).
    HULLKIT_STEP bool insert(const Segment& s) {
        pending_.clear();
        pending_.push_back(s);
        while (!pending_.empty()) {
            const Segment piece = pending_.back();
            pending_.pop_back();
            if (piece.a == piece.b) continue;
            if (!insert_piece(piece)) return false;
#ifdef HULLKIT_CDT_DEBUG
            check("after piece " + std::to_string(piece.a) + "-" + std::to_string(piece.b));
#endif
        }
        return true;
    }

    /// Sets region_ to `id` on the triangles inside the rings by the fill rule, to 0 elsewhere
    /// (ghosts, free slots). The winding numbers spread from the ghosts (outside: 0) across edges,
    /// changed by the segments each edge carries, and are kept in region_ itself meanwhile (as
    /// 32-bit two's complement, like each edge's Record::wind: none exceeds the number of segments,
    /// so the lowest value is free to say "not reached yet").
    void mark_inside(FillRule fill, std::uint32_t id) {
        constexpr std::uint32_t kUnreached = 0x80000000u;
        const std::uint32_t t_count = static_cast<std::uint32_t>(vertex_.size() / 3);
        std::uint32_t* winding = region_.data();
        std::vector<std::uint32_t> stack;
        for (std::uint32_t t = 0; t < t_count; ++t) {
            const bool ghost = is_ghost(t);
            winding[t] = ghost || vertex_[3 * t] == kDead ? 0 : kUnreached;
            if (ghost) stack.push_back(t);
        }
        const bool even_odd = fill == FillRule::EvenOdd;
        while (!stack.empty()) {
            const std::uint32_t t = stack.back();
            stack.pop_back();
            const std::uint32_t own = winding[t];
            for (std::uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
                const std::uint32_t u = twin_[e] / 3;
                if (winding[u] != kUnreached) continue;
                winding[u] = even_odd ? own ^ (count(e) & 1u) : own - static_cast<std::uint32_t>(wind(e));
                stack.push_back(u);
            }
        }
        for (std::uint32_t t = 0; t < t_count; ++t) winding[t] = winding[t] != 0 && winding[t] != kUnreached ? id : 0;
    }

    /// The last step: writes the domain's triangles (those with a region, see Refiner) and the
    /// points (the input's `points`, then those added, back in the input's units: exact, a power of
    /// two), with `regions` each triangle's region seed too (ids first_seed + r; -1 below
    /// first_seed). The mesh is used up: what only insertion needs goes first, region_ becomes the
    /// triangles' new numbers and xy_ becomes out.coords, so the outputs take the room they leave
    /// rather than adding to the peak (WebAssembly memory never shrinks).
    void write_and_release(PointSpan2 points, ConstrainedDelaunay& out, bool regions, std::uint32_t first_seed) {
        records_ = std::vector<Record>();
        out_ = std::vector<std::uint32_t>();
        free_ = std::vector<std::uint32_t>();
        touched_ = std::vector<std::uint32_t>();
        stamp_ = std::vector<std::uint32_t>();
        pair_crossings_.clear();
        const std::size_t t_count = vertex_.size() / 3;
        // Which triangles are written, decided once: the others' regions become kGhost (no region
        // id is), then each written one's region becomes its number in the output.
        std::size_t kept = 0;
        for (std::size_t t = 0; t < t_count; ++t) {
            const bool written = region_[t] != 0 && vertex_[3 * t] != kDead && !is_ghost(static_cast<std::uint32_t>(t));
            if (!written) region_[t] = kGhost;
            kept += written;
        }
        detail::resize_large(out.triangles, 3 * kept);
        detail::resize_large(out.halfedges, out.triangles.size());
        detail::resize_large(out.constrained, out.triangles.size());
        if (regions) detail::resize_large(out.triangle_region, kept);
        std::uint32_t next = 0;
        for (std::size_t t = 0; t < t_count; ++t) {
            if (region_[t] == kGhost) continue;
            if (regions) {
                const std::uint32_t id = region_[t];
                out.triangle_region[next] = id >= first_seed ? static_cast<std::int32_t>(id - first_seed) : -1;
            }
            region_[t] = next++;
        }
        for (std::size_t t = 0; t < t_count; ++t) {
            const std::uint32_t k = region_[t];
            if (k == kGhost) continue;
            const std::size_t base = 3 * static_cast<std::size_t>(k);
            out.triangles[base] = vertex_[3 * t];
            out.triangles[base + 1] = vertex_[3 * t + 2];
            out.triangles[base + 2] = vertex_[3 * t + 1];
            for (std::uint32_t j = 0; j < 3; ++j) {
                const std::uint32_t e = static_cast<std::uint32_t>(3 * t) + 2 - j;
                const std::uint32_t f = twin_[e], u = region_[f / 3];
                out.halfedges[base + j] = u == kGhost ? -1 : static_cast<std::int32_t>(3 * u + 2 - f % 3);
                out.constrained[base + j] = edge_[e] != 0;
            }
        }
        vertex_ = std::vector<std::uint32_t>();
        twin_ = std::vector<std::uint32_t>();
        edge_ = std::vector<std::uint32_t>();
        region_ = std::vector<std::uint32_t>();
        out.coords = std::move(xy_);
        std::copy(points.xy, points.xy + 2 * points.count, out.coords.begin());
        for (std::size_t i = 2 * points.count; i < out.coords.size(); ++i) out.coords[i] = std::ldexp(out.coords[i], -exponent_);
    }

private:
#ifdef HULLKIT_CDT_DEBUG
    /// With -DHULLKIT_CDT_DEBUG: the whole mesh checked after every step (twins, flags, orientation,
    /// local Delaunay away from segments, each vertex's half-edge); aborts on the first problem.
    void check(const std::string& where) const {
        for (std::uint32_t e = 0; e < vertex_.size(); ++e) {
            if (vertex_[e] == kDead) continue;
            const std::uint32_t f = twin_[e];
            if (f >= vertex_.size() || vertex_[f] == kDead || twin_[f] != e || vertex_[f] != vertex_[next_edge(e)] ||
                vertex_[next_edge(f)] != vertex_[e]) {
                std::fprintf(stderr, "%s: bad twin at %u (%u->%u) twin %u\n", where.c_str(), e, vertex_[e], vertex_[next_edge(e)], f);
                std::abort();
            }
            if (edge_[e] != edge_[f]) {
                std::fprintf(stderr, "%s: flags differ at %u\n", where.c_str(), e);
                std::abort();
            }
        }
        for (std::uint32_t t = 0; t < vertex_.size() / 3; ++t) {
            if (vertex_[3 * t] == kDead || is_ghost(t)) continue;
            if (orient(vertex_[3 * t], vertex_[3 * t + 1], vertex_[3 * t + 2]) <= 0) {
                std::fprintf(stderr, "%s: triangle %u (%u %u %u) not counter-clockwise\n", where.c_str(), t, vertex_[3 * t],
                             vertex_[3 * t + 1], vertex_[3 * t + 2]);
                std::abort();
            }
        }
        for (std::uint32_t e = 0; e < vertex_.size(); ++e) {
            if (vertex_[e] == kDead || edge_[e] != 0) continue;
            const std::uint32_t f = twin_[e];
            const std::uint32_t u = vertex_[e], v = vertex_[next_edge(e)], p = vertex_[prev_edge(e)], q = vertex_[prev_edge(f)];
            if (u == kGhost || v == kGhost || p == kGhost || q == kGhost) continue;
            const double *pu = pt(u), *pv = pt(v), *pp = pt(p), *pq = pt(q);
            if (incircle(pu[0], pu[1], pv[0], pv[1], pp[0], pp[1], pq[0], pq[1]) > 0) {
                std::fprintf(stderr, "%s: edge %u-%u not locally Delaunay\n", where.c_str(), u, v);
                std::abort();
            }
        }
        for (std::uint32_t v = 0; v < out_.size(); ++v) {
            if (out_[v] == kGhost) continue;
            if (vertex_[out_[v]] != v) {
                std::fprintf(stderr, "%s: out of %u stale\n", where.c_str(), v);
                std::abort();
            }
        }
    }
#endif
    const double* pt(std::uint32_t v) const { return &xy_[2 * static_cast<std::size_t>(v)]; }
    int orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
        const double *p = pt(a), *q = pt(b), *r = pt(c);
        return orient2d(p[0], p[1], q[0], q[1], r[0], r[1]);
    }
    int orient_at(std::uint32_t a, std::uint32_t b, const double* r) const {
        const double *p = pt(a), *q = pt(b);
        return orient2d(p[0], p[1], q[0], q[1], r[0], r[1]);
    }
    bool is_ghost(std::uint32_t t) const {
        return vertex_[3 * t] == kGhost || vertex_[3 * t + 1] == kGhost || vertex_[3 * t + 2] == kGhost;
    }
    void link(std::uint32_t e, std::uint32_t f) { twin_[e] = f, twin_[f] = e; }
    /// Marks on triangles that last until the next new_mark() (a generation count: no clearing).
    void new_mark() {
        if (++generation_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), generation_ = 1;
        // Grown a page at a time (the vector reallocates geometrically past its capacity): the
        // marks start in the incremental mesh's, reserved for the spare points, whose pages are
        // only touched as triangles come.
        if (stamp_.size() < vertex_.size() / 3) stamp_.resize(vertex_.size() / 3 + 1024, 0);
    }
    void mark(std::uint32_t t) { stamp_[t] = generation_; }
    bool marked(std::uint32_t t) const { return stamp_[t] == generation_; }
    std::uint32_t add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        std::uint32_t t;
        if (!free_.empty()) {
            t = free_.back();
            free_.pop_back();
        } else {
            t = static_cast<std::uint32_t>(vertex_.size() / 3);
            for (int k = 0; k < 3; ++k) vertex_.push_back(0), twin_.push_back(0), edge_.push_back(0);
            region_.push_back(0);
        }
        if (track_) touched_.push_back(t);
        vertex_[3 * t] = a, vertex_[3 * t + 1] = b, vertex_[3 * t + 2] = c;
        edge_[3 * t] = edge_[3 * t + 1] = edge_[3 * t + 2] = 0;
        return t;
    }
    void remove_triangle(std::uint32_t t) {
        vertex_[3 * t] = vertex_[3 * t + 1] = vertex_[3 * t + 2] = kDead;
        free_.push_back(t);
    }
    /// The segments along half-edge e: how many, their winding the way of e, one of them (kGhost: none).
    std::uint32_t count(std::uint32_t e) const { return records_[edge_[e]].count; }
    std::int32_t wind(std::uint32_t e) const {
        const Record& r = records_[edge_[e]];
        return vertex_[e] == r.from ? r.wind : -r.wind;
    }
    std::uint32_t origin(std::uint32_t e) const { return records_[edge_[e]].origin; }
    /// Sets the segments along e (and its twin): `wind` the way of e; count 0 clears them.
    void set_flags(std::uint32_t e, std::int32_t wind, std::uint32_t count, std::uint32_t origin) {
        const std::uint32_t f = twin_[e];
        if (count == 0) {
            edge_[e] = edge_[f] = 0;
            return;
        }
        std::uint32_t r = edge_[e];
        if (r == 0) {
            r = static_cast<std::uint32_t>(records_.size());
            records_.push_back(Record{0, 0, origin, vertex_[e]});
            edge_[e] = edge_[f] = r;
        }
        Record& record = records_[r];
        record.wind = vertex_[e] == record.from ? wind : -wind;
        record.count = count;
        if (record.origin == kGhost) record.origin = origin;
    }

    /// The half-edge a -> b, or kGhost when a and b are not joined.
    /// Searches round a both ways at once from out_[a] (two independent chains of loads, each
    /// half as long as one round), until the two searches meet.
    std::uint32_t find_edge(std::uint32_t a, std::uint32_t b) const {
        const std::uint32_t first = out_[a];
        if (vertex_[next_edge(first)] == b) return first;
        std::uint32_t one = first, other = first;
        for (;;) {
            one = twin_[prev_edge(one)];  // the next half-edge out of a one way round
            if (one == other) return kGhost;
            if (vertex_[next_edge(one)] == b) return one;
            other = next_edge(twin_[other]);  // and the other way
            if (other == one) return kGhost;
            if (vertex_[next_edge(other)] == b) return other;
        }
    }

    /// True when vertex v lies on the segment a-b's ray beyond a (v collinear with a and b).
    bool ahead(std::uint32_t a, std::uint32_t b, std::uint32_t v) const {
        const double *p = pt(a), *q = pt(b), *r = pt(v);
        return (q[0] - p[0]) * (r[0] - p[0]) > 0 || (q[1] - p[1]) * (r[1] - p[1]) > 0;
    }

    bool insert_piece(const Segment& s) {
        const std::uint32_t a = s.a, b = s.b;
        const std::uint32_t existing = find_edge(a, b);
        if (existing != kGhost) {
            set_flags(existing, wind(existing) + s.wind, count(existing) + s.count, s.input);
            return true;
        }
        // The triangle at a whose wedge holds the direction to b, or a vertex on the way.
        const std::uint32_t first = out_[a];
        std::uint32_t e = first, crossed = kGhost;
        do {
            const std::uint32_t x = vertex_[next_edge(e)], y = vertex_[prev_edge(e)];
            if (x != kGhost && orient(a, b, x) == 0 && ahead(a, b, x)) return split_at(s, x, e);
            if (x != kGhost && y != kGhost && orient(a, x, b) > 0 && orient(a, y, b) < 0) {
                crossed = next_edge(e);  // x -> y
                break;
            }
            e = twin_[prev_edge(e)];
        } while (e != first);
        if (crossed == kGhost) return fail(s, "segment " + std::to_string(s.input) + " leaves the triangulation");
        // Walk over the crossed edges: each goes from the right of a -> b to its left.
        crossed_.clear();
        for (;;) {
            if (edge_[crossed] != 0) return cross(s, crossed);
            crossed_.push_back(crossed);
            const std::uint32_t f = twin_[crossed];  // y -> x in the next triangle (y, x, w)
            const std::uint32_t w = vertex_[prev_edge(f)];
            if (w == b) break;
            const int o = orient(a, b, w);
            if (o == 0) {
                // w lies on the segment: triangulate up to it, then continue from it.
                pending_.push_back({w, b, s.wind, s.count, s.input});
                return retriangulate({a, w, s.wind, s.count, s.input});
            }
            crossed = o > 0 ? next_edge(f) : prev_edge(f);  // x -> w (w left) or w -> y (w right)
        }
        return retriangulate(s);
    }

    /// The segment passes through vertex v (joined to a by half-edge e = a -> v): a-v is an edge.
    bool split_at(const Segment& s, std::uint32_t v, std::uint32_t e) {
        set_flags(e, wind(e) + s.wind, count(e) + s.count, s.input);
        pending_.push_back({v, s.b, s.wind, s.count, s.input});
        return true;
    }

    bool fail(const Segment& s, std::string message) {
        error = std::move(message);
        error_segment = s.input;
        return false;
    }

    /// The segment crosses the constrained edge `e` (x -> y): add the rounded crossing point, make
    /// both into chains through it.
    bool cross(const Segment& s, std::uint32_t e) {
        ++crossings;
        const std::uint32_t x = vertex_[e], y = vertex_[next_edge(e)];
        const Segment other{x, y, wind(e), count(e), origin(e)};
        // Iterated rounding settles after one or two points per crossing pair; a pair that keeps
        // crossing (or a total past the caller's cap) is an error rather than a long run.
        const auto pair = std::make_pair(std::min(s.input, other.input), std::max(s.input, other.input));
        if (++pair_crossings_[pair] > kMaxPairCrossings) {
            return fail(s, "segments " + std::to_string(pair.first) + " and " + std::to_string(pair.second) +
                               " still cross after " + std::to_string(kMaxPairCrossings) + " rounded crossing points");
        }
        if (max_added_ != 0 && xy_.size() / 2 - input_count_ >= max_added_) {
            return fail(s, "segments cross too often: " + std::to_string(max_added_) +
                               " points added at crossings (max_added_points) and segment " + std::to_string(s.input) +
                               " still crosses another");
        }
        double p[2];
        rounded_crossing(pt(s.a), pt(s.b), pt(x), pt(y), p);
        representable(p);
        const std::uint32_t q = insert_point(p, e / 3);
#ifdef HULLKIT_CDT_DEBUG
        check("after the crossing point");
#endif
        if (internal_error_) {
            return fail(s, "internal error: the crossing of segment " + std::to_string(s.input) +
                               " with another could not be inserted (please report this input)");
        }
        // x-y stayed a segment while q went in (so no flip could remove it); unless q split it
        // exactly or is one of its ends, it now becomes the chain x-q-y.
        if (q != x && q != y) {
            const std::uint32_t old = find_edge(x, y);
            if (old != kGhost) {
                set_flags(old, 0, 0, kGhost);
                fresh_.push_back({x, y});
                legalize();
                pending_.push_back({other.a, q, other.wind, other.count, other.input});
                pending_.push_back({q, other.b, other.wind, other.count, other.input});
            }
        }
        pending_.push_back({q, s.b, s.wind, s.count, s.input});
        pending_.push_back({s.a, q, s.wind, s.count, s.input});
        return true;
    }

    /// Makes a -> b an edge by flipping the edges it crosses (crossed_), then restores the
    /// empty-circle property around the new edges by flipping (Sloan, "A fast algorithm for
    /// generating constrained Delaunay triangulations", Computers & Structures 47, 1993). A crossed
    /// edge whose quadrilateral is not strictly convex waits until its neighbours have moved; every
    /// decision is an exact orient2d or incircle. Nothing here depends on a vertex between a and b:
    /// there is none (the walk stopped there).
    bool retriangulate(const Segment& s) {
        const std::uint32_t a = s.a, b = s.b;
        queue_.clear();
        for (std::uint32_t e : crossed_) queue_.push_back({vertex_[e], vertex_[next_edge(e)]});
        fresh_.clear();
        std::size_t head = 0, stalled = 0;
        while (head < queue_.size()) {
            const Edge edge = queue_[head++];
            const std::uint32_t e = find_edge(edge.from, edge.to);
            const std::uint32_t p = vertex_[prev_edge(e)], q = vertex_[prev_edge(twin_[e])];
            // The diagonal p-q must cross u-v properly for the flip to keep both triangles positive.
            if (orient(p, q, edge.from) * orient(p, q, edge.to) >= 0) {
                queue_.push_back(edge);
                if (++stalled > 2 * (queue_.size() - head) + 8) return fail(s, "internal error: segment insertion stalled");
                continue;
            }
            stalled = 0;
            flip(e);
            const int op = orient(a, b, p), oq = orient(a, b, q);
            if (op * oq < 0) queue_.push_back({p, q});
            else fresh_.push_back({p, q});
        }
        const std::uint32_t ab = find_edge(a, b);
        set_flags(ab, wind(ab) + s.wind, count(ab) + s.count, s.input);
        // Restore the empty-circle property across the new edges (never across a segment).
        legalize();
        return true;
    }

    /// Lawson's flips from the edges in fresh_ (a stack) until every edge reached is locally
    /// Delaunay or on a segment: a flipped edge's four outer edges are checked again.
    void legalize() {
        while (!fresh_.empty()) {
            const Edge edge = fresh_.back();
            fresh_.pop_back();
            const std::uint32_t e = find_edge(edge.from, edge.to);
            if (e == kGhost || edge_[e] != 0) continue;
            const std::uint32_t p = vertex_[prev_edge(e)], q = vertex_[prev_edge(twin_[e])];
            if (p == kGhost || q == kGhost) continue;
            const double *pu = pt(edge.from), *pv = pt(edge.to), *pp = pt(p), *pq = pt(q);
            if (incircle(pu[0], pu[1], pv[0], pv[1], pp[0], pp[1], pq[0], pq[1]) > 0) {
                flip(e);
                fresh_.push_back({p, edge.from});
                fresh_.push_back({edge.from, q});
                fresh_.push_back({q, edge.to});
                fresh_.push_back({edge.to, p});
            }
        }
    }

    /// Flips half-edge e = u -> v between triangles (u, v, p) and (v, u, q) into p -> q... as the
    /// triangles (p, u, q) and (q, v, p); the four outer edges keep their twins and flags.
    void flip(std::uint32_t e) {
        const std::uint32_t f = twin_[e];
        const std::uint32_t t = e / 3, t2 = f / 3;
        const std::uint32_t u = vertex_[e], v = vertex_[next_edge(e)], p = vertex_[prev_edge(e)], q = vertex_[prev_edge(f)];
        const std::uint32_t vp = twin_[next_edge(e)], pu = twin_[prev_edge(e)];  // outside twins
        const std::uint32_t uq = twin_[next_edge(f)], qv = twin_[prev_edge(f)];
        vertex_[3 * t] = p, vertex_[3 * t + 1] = u, vertex_[3 * t + 2] = q;
        vertex_[3 * t2] = q, vertex_[3 * t2 + 1] = v, vertex_[3 * t2 + 2] = p;
        auto outer = [&](std::uint32_t h, std::uint32_t outside) {
            link(h, outside);
            edge_[h] = edge_[outside];
        };
        outer(3 * t, pu);
        outer(3 * t + 1, uq);
        outer(3 * t2, qv);
        outer(3 * t2 + 1, vp);
        link(3 * t + 2, 3 * t2 + 2);
        edge_[3 * t + 2] = edge_[3 * t2 + 2] = 0;
        out_[p] = 3 * t, out_[u] = 3 * t + 1, out_[q] = 3 * t2, out_[v] = 3 * t2 + 1;
        if (track_) touched_.push_back(t), touched_.push_back(t2);
    }

    /// Links an inner half-edge of the new triangles with its reverse (whichever comes first waits).
    void attach(std::uint32_t h) {
        const std::uint32_t from = vertex_[h], to = vertex_[next_edge(h)];
        for (std::size_t k = 0; k < inner_.size(); ++k) {
            const std::uint32_t g = inner_[k];
            if (vertex_[g] == to && vertex_[next_edge(g)] == from) {
                link(h, g);
                inner_[k] = inner_.back();
                inner_.pop_back();
                return;
            }
        }
        inner_.push_back(h);
    }

    /// Locates p (scaled) by a visibility walk from triangle `start`: a finite triangle holding it
    /// (closed) or a ghost whose hull edge it is strictly outside of.
    std::uint32_t locate(const double* p, std::uint32_t start) {
        return delaunay_detail::visibility_walk(vertex_, twin_, kGhost, start, seed_,
                                                [&](std::uint32_t a, std::uint32_t b) { return orient_at(a, b, p) < 0; });
    }

    bool conflicts(std::uint32_t t, const double* p) const {
        const std::uint32_t a = vertex_[3 * t], b = vertex_[3 * t + 1], c = vertex_[3 * t + 2];
        if (a != kGhost && b != kGhost && c != kGhost) {
            const double *pa = pt(a), *pb = pt(b), *pc = pt(c);
            return incircle(pa[0], pa[1], pb[0], pb[1], pc[0], pc[1], p[0], p[1]) > 0;
        }
        std::uint32_t x, y;
        delaunay_detail::ghost_edge(&vertex_[3 * t], kGhost, &x, &y);
        return delaunay_detail::beyond_hull_edge(pt(x), pt(y), p);
    }

    /// Inserts point p (scaled) by Bowyer-Watson without crossing a constrained edge, except the one
    /// p lies on (which is split, both halves keeping its flags). Returns its vertex: an existing one
    /// with the same coordinates, or the new one.
    /// Rounds a new point (scaled) to one that write() gives back unchanged in the input's units.
    /// Scaling is exact except where the input's units make a coordinate subnormal (inputs near
    /// 1e-310): there the trip back would drop bits, and the output would not be the point
    /// triangulated (a flat triangle, even). Elsewhere it changes nothing.
    void representable(double* p) const {
        if (exponent_ == 0) return;
        for (int k = 0; k < 2; ++k) p[k] = std::ldexp(std::ldexp(p[k], -exponent_), exponent_);
    }

    std::uint32_t insert_point(const double* p, std::uint32_t start) { return insert_at(p, locate(p, start)); }

    /// insert_point with the triangle holding p already found (as locate() finds it). With
    /// `whole_cavity` the caller has put p's whole conflict region in cavity_ (Bowyer-Watson:
    /// the triangles whose circumcircle holds p, reached from t0 without crossing a segment, p on
    /// no segment and no vertex): the cavity is filled as it is and no flips are needed.
    std::uint32_t insert_at(const double* p, std::uint32_t t0, bool whole_cavity = false) {
        std::uint32_t on_edge = kGhost;
        if (!is_ghost(t0) && !whole_cavity) {
            for (std::uint32_t e = 3 * t0; e < 3 * t0 + 3; ++e) {
                const double* v = pt(vertex_[e]);
                if (v[0] == p[0] && v[1] == p[1]) return vertex_[e];
            }
            for (std::uint32_t e = 3 * t0; e < 3 * t0 + 3; ++e)
                if (orient_at(vertex_[e], vertex_[next_edge(e)], p) == 0) on_edge = e;
        }
        // The cavity: conflicting triangles reachable without crossing a constrained edge.
        std::vector<std::uint32_t>& cavity = cavity_;
        if (!whole_cavity) cavity.assign(1, t0);
        new_mark();
        for (std::uint32_t t : cavity) mark(t);
        auto in_cavity = [&](std::uint32_t t) { return marked(t); };
        Segment split{kGhost, kGhost, 0, 0, 0};
        if (on_edge != kGhost) {
            cavity.push_back(twin_[on_edge] / 3);
            mark(cavity.back());
            if (edge_[on_edge] != 0)
                split = {vertex_[on_edge], vertex_[next_edge(on_edge)], wind(on_edge), count(on_edge), origin(on_edge)};
        }
        boundary_.clear();
        // Outside the hull, the ghosts (and triangles) in conflict, as Bowyer-Watson finds them;
        // inside, only the triangle or the two triangles holding p: Lawson's flips do the rest.
        const bool outside = !whole_cavity && (is_ghost(t0) || is_ghost(cavity.back()));
        for (std::size_t k = 0; outside && k < cavity.size(); ++k) {
            const std::uint32_t t = cavity[k];
            for (std::uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
                const std::uint32_t u = twin_[e] / 3;
                if (in_cavity(u)) continue;
                if (edge_[e] == 0 && conflicts(u, p)) {
                    cavity.push_back(u);
                    mark(u);
                    continue;
                }
            }
        }
        for (std::uint32_t t : cavity) {
            for (std::uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
                if (!in_cavity(twin_[e] / 3))
                    boundary_.push_back({vertex_[e], vertex_[next_edge(e)], twin_[e], edge_[e], region_[t]});
            }
        }
        // The cavity must be star-shaped from p and keep every segment but the one p splits; with
        // exact tests it is (a CDT's conflict region), and this check makes sure of it.
        for (const BoundaryEdge& b : boundary_) {
            if (b.from != kGhost && b.to != kGhost && orient_at(b.from, b.to, p) <= 0) {
                internal_error_ = true;
                return kGhost;
            }
        }
        for (std::uint32_t t : cavity) {
            for (std::uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
                const bool split_edge = split.a != kGhost && ((vertex_[e] == split.a && vertex_[next_edge(e)] == split.b) ||
                                                              (vertex_[e] == split.b && vertex_[next_edge(e)] == split.a));
                if (edge_[e] != 0 && !split_edge && in_cavity(twin_[e] / 3)) {
                    internal_error_ = true;
                    return kGhost;
                }
            }
        }
        for (std::uint32_t t : cavity) remove_triangle(t);
        const std::uint32_t q = static_cast<std::uint32_t>(xy_.size() / 2);
        xy_.push_back(p[0]), xy_.push_back(p[1]);
        out_.push_back(kGhost);
        // One triangle (from, to, q) per boundary edge.
        inner_.clear();
        for (const BoundaryEdge& b : boundary_) {
            const std::uint32_t t = add_triangle(b.from, b.to, q);
            region_[t] = b.region;
            const std::uint32_t h = 3 * t;
            link(h, b.outside);
            edge_[h] = b.record;
            attach(h + 1);
            attach(h + 2);
            for (std::uint32_t k = 0; k < 3; ++k)
                if (vertex_[h + k] != kGhost) out_[vertex_[h + k]] = h + k;
        }
        if (split.a != kGhost) {
            // The halves of the split edge a -> b: a -> q and q -> b run its way.
            const std::uint32_t aq = find_edge(split.a, q), qb = find_edge(q, split.b);
            set_flags(aq, split.wind, split.count, split.input);
            set_flags(qb, split.wind, split.count, split.input);
        }
        if (whole_cavity) return q;
        for (const BoundaryEdge& b : boundary_)
            if (b.from != kGhost && b.to != kGhost) fresh_.push_back({b.from, b.to});
        legalize();
        return q;
    }

    struct BoundaryEdge {
        std::uint32_t from, to, outside;
        std::uint32_t record;  ///< its segments (edge_)
        std::uint32_t region;  ///< the region of the cavity triangle it bounded
    };
    /// The segments along one edge: their number, their winding the way of the half-edge leaving
    /// `from`, and one of them (for messages).
    struct Record {
        std::int32_t wind;
        std::uint32_t count;
        std::uint32_t origin;
        std::uint32_t from;
        std::uint32_t parent = kGhost;  ///< refinement: the segment this edge is a piece of (refine.cpp)
    };
    struct Edge {
        std::uint32_t from, to;
    };

    std::vector<double> xy_;
    std::size_t input_count_;
    std::size_t max_added_;
    int exponent_;  ///< the points are the input's times 2^exponent_
    std::vector<std::uint32_t> vertex_, twin_;
    /// Per half-edge, its Record in records_ (the same for both halves), 0 when no segment lies on it:
    /// one number per half-edge, the records only for the few edges on segments.
    std::vector<std::uint32_t> edge_;
    std::vector<Record> records_;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> pair_crossings_;
    static constexpr std::uint32_t kMaxPairCrossings = 16;
    std::vector<std::uint32_t> out_;  ///< per vertex: a half-edge leaving it
    std::vector<std::uint32_t> free_;
    std::vector<Segment> pending_;
    std::vector<std::uint32_t> crossed_, inner_, cavity_;
    std::vector<Edge> queue_, fresh_;
    std::vector<BoundaryEdge> boundary_;
    std::uint32_t seed_ = 1;
    bool internal_error_ = false;
    /// Per triangle: the region it belongs to (refine.cpp; 0 until a domain is marked). Split and
    /// flipped triangles keep their region (no cavity or flip crosses a segment).
    std::vector<std::uint32_t> region_;
    /// With track_ set, every triangle made or changed is appended to touched_ (refine.cpp).
    bool track_ = false;
    std::vector<std::uint32_t> touched_;
    std::vector<std::uint32_t> stamp_;  ///< see new_mark()
    std::uint32_t generation_ = 0;
};

}  // namespace constrained_detail
}  // namespace hullkit
