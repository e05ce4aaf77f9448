// hullkit::verify: exact certification of a convex hull. See verify.hpp for what is checked and
// why it suffices. Nothing here is shared with the hull algorithms; only the predicates are.
#include "hullkit/verify.hpp"

#include <algorithm>
#include <array>
#include <iterator>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hullkit/predicates.hpp"
#include "point_key.hpp"

namespace hullkit {

std::vector<std::string> VerifyReport::lines() const {
    std::vector<std::string> out = problems;
    if (problem_count > problems.size()) {
        out.push_back("... and " + std::to_string(problem_count - problems.size()) + " more problems (" +
                      std::to_string(problem_count) + " in all)");
    }
    return out;
}

namespace {

using Index = std::uint32_t;
constexpr Index kNone = ~Index{0};

std::string num(std::size_t value) { return std::to_string(value); }

std::string coordinates(const double* p) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "(%.17g %.17g %.17g)", p[0], p[1], p[2]);
    return buffer;
}

/// Collects problems: counts all of them, keeps the first kVerifyMaxProblems.
class Problems {
public:
    explicit Problems(VerifyReport& report) : report_(report) {}
    void add(std::string line) {
        report_.ok = false;
        ++report_.problem_count;
        if (report_.problems.size() < kVerifyMaxProblems) report_.problems.push_back(std::move(line));
    }
    void note(std::string line) { report_.notes.push_back(std::move(line)); }
    std::size_t count() const { return report_.problem_count; }

private:
    VerifyReport& report_;
};

/// The input, checked for finite coordinates and brought into the predicates' exact range by a
/// power of two when needed (exact: the signs of all predicates are unchanged).
struct Prepared {
    std::vector<double> storage;
    PointSpan points;
    PointSpan original;  ///< unscaled, for messages
};

bool prepare(PointSpan input, Problems& out, Prepared& prepared) {
    prepared.points = input;
    prepared.original = input;
    if (input.count > std::numeric_limits<Index>::max()) {
        out.add("too many points: " + num(input.count) + " (32-bit indices reach 4294967295 points)");
        return false;
    }
    double largest = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
    bool finite = true;
    for (std::size_t i = 0; i < input.count; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            const double value = input[i][axis];
            if (!std::isfinite(value)) {
                static const char* const kAxis[] = {"x", "y", "z"};
                out.add("point " + num(i) + " has a non-finite " + kAxis[axis] + " coordinate");
                finite = false;
                break;
            }
            const double magnitude = std::fabs(value);
            largest = std::max(largest, magnitude);
            if (magnitude != 0.0) smallest = std::min(smallest, magnitude);
        }
    }
    if (!finite) return false;
    int exponent = 0;
    if (!predicates_range_ok(largest, smallest) && !predicates_scale_exponent(largest, smallest, &exponent)) {
        out.add("the nonzero |coordinates| span more than a factor of 2^585: no common power-of-two scale "
                "brings them into the exact predicates' range");
        return false;
    }
    if (exponent != 0) {
        prepared.storage.resize(3 * input.count);
        for (std::size_t i = 0; i < prepared.storage.size(); ++i)
            prepared.storage[i] = std::ldexp(input.xyz[i], exponent);
        prepared.points = PointSpan(prepared.storage.data(), input.count);
    }
    return true;
}

// ---- identical points ----

using detail::key_of;
using detail::PointKey;
using detail::PointKeyHash;

/// Reports vertices that are the same point as another vertex, and vertices standing for identical
/// input points that are not the lowest index of them. `vertices` must be in range.
void check_representatives(PointSpan points, PointSpan original, const std::vector<Index>& vertices,
                           Problems& out) {
    std::unordered_map<PointKey, Index, PointKeyHash> by_point;
    by_point.reserve(vertices.size() * 2 + 1);
    for (Index v : vertices) {
        auto [it, inserted] = by_point.emplace(key_of(points[v]), v);
        if (!inserted && it->second != v) {
            out.add("vertices " + num(std::min(it->second, v)) + " and " + num(std::max(it->second, v)) +
                    " are the same point " + coordinates(original[v]));
        }
    }
    for (std::size_t i = 0; i < points.count && !by_point.empty(); ++i) {
        auto it = by_point.find(key_of(points[i]));
        if (it == by_point.end()) continue;
        if (it->second > i) {
            out.add("vertex " + num(it->second) + " repeats point " + num(i) + " " + coordinates(original[i]) +
                    ": the lowest index must represent identical points");
        }
        by_point.erase(it);  // each vertex is judged by the first point equal to it
    }
}

/// An axis-aligned projection (kept axes i, j) in which a, b, c are not collinear; returns their
/// orientation there (never 0 unless a, b, c are collinear in space). Any such projection is
/// one-to-one on the plane of a, b, c, so orientations in it are exact orientations in the plane.
int projection(const double* a, const double* b, const double* c, int* i, int* j) {
    for (int dropped = 2; dropped >= 0; --dropped) {
        const int u = (dropped + 1) % 3, v = (dropped + 2) % 3;
        if (int s = orient2d(a[u], a[v], b[u], b[v], c[u], c[v]); s != 0) {
            *i = u;
            *j = v;
            return s;
        }
    }
    return 0;
}

class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), Index{0}); }
    Index find(Index x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(Index a, Index b) {
        a = find(a);
        b = find(b);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }

private:
    std::vector<Index> parent_;
};

/// Coarse lookup of a triangle by direction from the interior point: a cube map of g x g cells per
/// face, each holding a triangle seen in that direction (or kNone). Only a starting guess.
class DirectionGrid {
public:
    /// A grid of about `cells` cells in all.
    explicit DirectionGrid(std::size_t cells) {
        const double side = std::sqrt(static_cast<double>(cells) / 6.0);
        g_ = static_cast<int>(std::clamp(side, 1.0, 2048.0));
        cells_.assign(size(), kNone);
    }
    std::size_t size() const { return 6 * static_cast<std::size_t>(g_) * g_; }
    /// The cell of direction d, numbered so that consecutive numbers are neighbouring cells
    /// (rows of a cube face in alternating directions).
    std::size_t cell(const double* d) const {
        const double m[3] = {std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])};
        const int axis = m[0] >= m[1] ? (m[0] >= m[2] ? 0 : 2) : (m[1] >= m[2] ? 1 : 2);
        if (!(m[axis] > 0.0) || !std::isfinite(m[axis])) return 0;
        const int face = 2 * axis + (d[axis] < 0.0 ? 1 : 0);
        auto slot = [&](double c) {
            const double t = (c / m[axis] + 1.0) * 0.5 * g_;
            return std::clamp(static_cast<int>(t), 0, g_ - 1);
        };
        const int u = slot(d[(axis + 1) % 3]);
        int v = slot(d[(axis + 2) % 3]);
        if (u % 2 == 1) v = g_ - 1 - v;
        return (static_cast<std::size_t>(face) * g_ + u) * g_ + v;
    }
    Index& at(std::size_t cell) { return cells_[cell]; }

private:
    int g_ = 1;
    std::vector<Index> cells_;
};

// ---- dimension 3 ----

class SurfaceVerifier {
public:
    SurfaceVerifier(const Prepared& prepared, const Index* triangles, std::size_t count, VerifyReport& report)
        : points_(prepared.points),
          original_(prepared.original),
          t_(triangles),
          f_(count),
          report_(report),
          out_(report) {}

    void run() {
        report_.triangle_count = f_;
        if (f_ == 0) {
            out_.add("there are no triangles");
            return;
        }
        if (f_ > (std::numeric_limits<Index>::max() - 1) / 3) {
            out_.add("too many triangles: " + num(f_));
            return;
        }
        if (!check_indices()) {
            out_.note("nothing else was checked: the other checks need valid indices");
            return;
        }
        check_areas();
        if (!pair_edges()) {
            out_.note("convexity and containment were not checked: the triangles do not form a closed, "
                      "consistently oriented surface");
            return;
        }
        // All three run (each reports its own problems) before the verdict.
        const bool fans = check_fans();
        const bool connected = check_connected();
        const bool euler = check_euler();
        if (!(fans && connected && euler)) {
            out_.note("convexity and containment were not checked: the triangles do not form a sphere");
            return;
        }
        check_edges();
        merge_faces();
        const bool structure_ok = out_.count() == 0;
        const bool have_interior = structure_ok && find_interior_point();
        const bool winding_ok = check_vertices(have_interior);
        if (structure_ok && have_interior && winding_ok) {
            // The surface is then embedded: a point identical to a vertex is found as a corner of
            // the triangle it is located in, so no lookup table is needed.
            contain_by_walking();
        } else {
            check_representatives(points_, original_, vertices_, out_);
            contain_exhaustively(structure_ok);
        }
    }

private:
    const double* p(Index i) const { return points_[i]; }
    Index corner(std::size_t t, int k) const { return t_[3 * t + k]; }
    Index head(std::size_t h) const { return t_[3 * (h / 3) + (h % 3 + 1) % 3]; }  // target of half-edge h
    Index tail(std::size_t h) const { return t_[h]; }                               // source of half-edge h
    std::string triangle_name(std::size_t t) const {
        return "triangle " + num(t) + " (" + num(corner(t, 0)) + " " + num(corner(t, 1)) + " " + num(corner(t, 2)) +
               ")";
    }
    /// The next outgoing half-edge around the source of half-edge h (counter-clockwise seen from
    /// outside): h is u->w in triangle (u, w, x); the next is u->x.
    Index next_out(Index h) const { return twins_[3 * (h / 3) + (h % 3 + 2) % 3]; }

    bool check_indices() {
        bool ok = true;
        for (std::size_t t = 0; t < f_; ++t) {
            for (int k = 0; k < 3; ++k) {
                if (corner(t, k) >= points_.count) {
                    out_.add("triangle " + num(t) + ": index " + num(corner(t, k)) + " is out of range (" +
                             num(points_.count) + " points)");
                    ok = false;
                    break;
                }
            }
        }
        return ok;
    }

    void check_areas() {
        degenerate_.assign(f_, 0);
        for (std::size_t t = 0; t < f_; ++t) {
            if (collinear3d(p(corner(t, 0)), p(corner(t, 1)), p(corner(t, 2)))) {
                degenerate_[t] = 1;
                out_.add(triangle_name(t) + " has zero area: its corners are collinear or repeated");
            }
        }
    }

    /// Every directed edge exactly once, its reverse exactly once; fills twins_. Also the outgoing
    /// half-edges of each vertex (out_start_, out_), and vertices_.
    bool pair_edges() {
        const std::size_t halves = 3 * f_;
        out_start_.assign(points_.count + 1, 0);
        for (std::size_t h = 0; h < halves; ++h) ++out_start_[tail(h) + 1];
        for (std::size_t v = 0; v < points_.count; ++v) out_start_[v + 1] += out_start_[v];
        outgoing_.assign(halves, {0, 0});
        {
            std::vector<Index> cursor(out_start_.begin(), out_start_.end() - 1);
            for (std::size_t h = 0; h < halves; ++h) outgoing_[cursor[tail(h)]++] = {head(h), static_cast<Index>(h)};
        }
        vertices_.clear();
        for (std::size_t v = 0; v < points_.count; ++v) {
            if (out_start_[v] == out_start_[v + 1]) continue;
            vertices_.push_back(static_cast<Index>(v));
            std::sort(outgoing_.begin() + out_start_[v], outgoing_.begin() + out_start_[v + 1]);
        }
        report_.vertex_count = vertices_.size();

        bool ok = true;
        for (Index v : vertices_) {
            for (Index e = out_start_[v] + 1; e < out_start_[v + 1]; ++e) {
                if (outgoing_[e].first == outgoing_[e - 1].first && outgoing_[e].first != v) {
                    out_.add("edge " + num(v) + "->" + num(outgoing_[e].first) + " is used in the same direction by " +
                             triangle_name(outgoing_[e - 1].second / 3) + " and " +
                             triangle_name(outgoing_[e].second / 3) +
                             " (a flipped or repeated triangle)");
                    ok = false;
                }
            }
        }
        twins_.assign(halves, kNone);
        for (std::size_t h = 0; h < halves; ++h) {
            const Index u = tail(h), v = head(h);
            if (u == v) {  // a repeated corner: reported as zero area
                ok = false;
                continue;
            }
            const auto first = outgoing_.begin() + out_start_[v];
            const auto last = outgoing_.begin() + out_start_[v + 1];
            const auto it = std::lower_bound(first, last, std::make_pair(u, Index{0}));
            if (it == last || it->first != u) {
                out_.add("edge " + num(u) + "->" + num(v) + " of " + triangle_name(h / 3) + " has no reverse edge " +
                         num(v) + "->" + num(u) + " (a hole, or a flipped triangle)");
                ok = false;
            } else {
                twins_[h] = it->second;
            }
        }
        return ok;
    }

    /// The triangles around each vertex form one fan (a single cycle), else the surface is pinched.
    /// The walk around a vertex is a cycle of a permutation of its outgoing half-edges: it is the
    /// only one when it covers all of them.
    bool check_fans() {
        bool ok = true;
        std::vector<char> seen;
        for (Index v : vertices_) {
            const std::size_t degree = out_start_[v + 1] - out_start_[v];
            const Index start = outgoing_[out_start_[v]].second;
            std::size_t steps = 0;
            Index h = start;
            do {
                ++steps;
                h = next_out(h);
            } while (h != start && steps <= degree);
            if (steps == degree && h == start) continue;
            // Count the fans, for the message.
            seen.assign(3 * f_, 0);
            std::size_t fans = 0;
            for (Index e = out_start_[v]; e < out_start_[v + 1]; ++e) {
                const Index first = outgoing_[e].second;
                if (seen[first]) continue;
                ++fans;
                Index g = first;
                do {
                    seen[g] = 1;
                    g = next_out(g);
                } while (g != first && !seen[g]);
            }
            out_.add("vertex " + num(v) + ": its triangles form " + num(fans) +
                     " separate fans (the surface is pinched there)");
            ok = false;
        }
        return ok;
    }

    bool check_connected() {
        std::vector<char> reached(f_, 0);
        std::vector<Index> stack = {0};
        reached[0] = 1;
        std::size_t count = 1;
        while (!stack.empty()) {
            const Index t = stack.back();
            stack.pop_back();
            for (int k = 0; k < 3; ++k) {
                const Index u = twins_[3 * t + k] / 3;
                if (!reached[u]) {
                    reached[u] = 1;
                    ++count;
                    stack.push_back(u);
                }
            }
        }
        if (count == f_) return true;
        const std::size_t missing = static_cast<std::size_t>(std::find(reached.begin(), reached.end(), 0) - reached.begin());
        out_.add("the triangles are not connected: " + triangle_name(missing) + " cannot be reached from triangle 0 (" +
                 num(count) + " of " + num(f_) + " can)");
        return false;
    }

    bool check_euler() {
        const long long v = static_cast<long long>(vertices_.size());
        const long long f = static_cast<long long>(f_);
        const long long e = 3 * f / 2;
        if (v - e + f == 2) return true;
        out_.add("Euler characteristic V - E + F = " + std::to_string(v) + " - " + std::to_string(e) + " + " +
                 std::to_string(f) + " = " + std::to_string(v - e + f) + ", not 2");
        return false;
    }

    /// Local convexity across every edge; coplanar neighbours must not fold; some edge must be
    /// strictly convex (else everything is flat). Fills flat_.
    void check_edges() {
        flat_.assign(3 * f_, 0);
        bool convex_edge = false;
        for (std::size_t h = 0; h < 3 * f_; ++h) {
            const Index g = twins_[h];
            if (g < h) continue;
            const std::size_t t = h / 3, s = g / 3;
            if (degenerate_[t] || degenerate_[s]) continue;  // no plane to judge by; reported already
            const Index u = tail(h), v = head(h);
            const Index c = corner(t, static_cast<int>((h % 3 + 2) % 3));
            const Index w = corner(s, static_cast<int>((g % 3 + 2) % 3));
            const int side = orient3d(p(u), p(v), p(c), p(w));
            if (side < 0) {
                convex_edge = true;
            } else if (side > 0) {
                out_.add("edge " + num(u) + "-" + num(v) + " is not convex: corner " + num(w) + " of " +
                         triangle_name(s) + " is above the plane of " + triangle_name(t));
            } else {
                flat_[h] = flat_[g] = 1;
                int i = 0, j = 0;
                const int sc = projection(p(u), p(v), p(c), &i, &j);
                const int sw = orient2d(p(u)[i], p(u)[j], p(v)[i], p(v)[j], p(w)[i], p(w)[j]);
                if (sw == sc) {
                    out_.add("edge " + num(u) + "-" + num(v) + ": the coplanar " + triangle_name(t) + " and " +
                             triangle_name(s) + " overlap (folded onto each other)");
                }
            }
        }
        const bool any_degenerate = std::find(degenerate_.begin(), degenerate_.end(), 1) != degenerate_.end();
        if (!convex_edge && !any_degenerate) {
            out_.add("the triangles enclose no volume: all of them lie in one plane");
        }
    }

    /// Planar faces: triangles joined across flat edges. One representative triangle per face.
    void merge_faces() {
        DisjointSets sets(f_);
        for (std::size_t h = 0; h < 3 * f_; ++h) {
            if (flat_[h] && twins_[h] > h) sets.unite(static_cast<Index>(h / 3), twins_[h] / 3);
        }
        face_reps_.clear();
        for (std::size_t t = 0; t < f_; ++t) {
            if (!degenerate_[t] && sets.find(static_cast<Index>(t)) == t) face_reps_.push_back(static_cast<Index>(t));
        }
        report_.face_count = face_reps_.size();
    }

    bool strictly_inside(const double* o) const {
        for (Index t : face_reps_) {
            if (orient3d(p(corner(t, 0)), p(corner(t, 1)), p(corner(t, 2)), o) >= 0) return false;
        }
        return true;
    }

    /// A point strictly below every face plane: rounded candidates, each confirmed exactly. Fails
    /// only for polytopes so thin that no double lies strictly inside near the candidates.
    bool find_interior_point() {
        if (face_reps_.empty() || vertices_.empty()) return false;
        std::vector<std::array<double, 3>> candidates;

        // The mean of the vertices (compensated sums), strictly inside in exact arithmetic.
        double sum[3] = {0.0, 0.0, 0.0}, carry[3] = {0.0, 0.0, 0.0};
        for (Index v : vertices_) {
            for (int axis = 0; axis < 3; ++axis) {
                const double x = p(v)[axis], s = sum[axis] + x;
                carry[axis] += std::fabs(sum[axis]) >= std::fabs(x) ? (sum[axis] - s) + x : (x - s) + sum[axis];
                sum[axis] = s;
            }
        }
        const double count = static_cast<double>(vertices_.size());
        candidates.push_back({(sum[0] + carry[0]) / count, (sum[1] + carry[1]) / count, (sum[2] + carry[2]) / count});

        // The centroid of one face's triangle and the vertex farthest from its plane (rounded).
        const Index t0 = face_reps_[0];
        const double* a = p(corner(t0, 0));
        const double* b = p(corner(t0, 1));
        const double* c = p(corner(t0, 2));
        const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double normal[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                  e1[0] * e2[1] - e1[1] * e2[0]};
        Index far = vertices_[0];
        double best = -1.0;
        for (Index v : vertices_) {
            const double* d = p(v);
            const double h = std::fabs(normal[0] * (d[0] - a[0]) + normal[1] * (d[1] - a[1]) + normal[2] * (d[2] - a[2]));
            if (h > best) {
                best = h;
                far = v;
            }
        }
        const double* d = p(far);
        std::array<double, 3> tetra_centroid{};
        for (int axis = 0; axis < 3; ++axis)
            tetra_centroid[axis] = a[axis] * 0.25 + b[axis] * 0.25 + c[axis] * 0.25 + d[axis] * 0.25;
        candidates.push_back(tetra_centroid);
        std::array<double, 3> middle{};
        for (int axis = 0; axis < 3; ++axis) middle[axis] = candidates[0][axis] * 0.5 + tetra_centroid[axis] * 0.5;
        candidates.push_back(middle);

        for (auto& o : candidates) {
            bool usable = true;
            for (double& x : o) {
                if (!std::isfinite(x)) usable = false;
                if (std::fabs(x) < kPredicateMinMagnitude) x = 0.0;  // keep the predicates exact
            }
            if (usable && strictly_inside(o.data())) {
                std::copy(o.begin(), o.end(), o_);
                return true;
            }
        }
        return false;
    }

    /// The outgoing half-edges of v in counter-clockwise order (seen from outside).
    void fan_of(Index v, std::vector<Index>& fan) const {
        fan.clear();
        const Index start = outgoing_[out_start_[v]].second;
        Index h = start;
        do {
            fan.push_back(h);
            h = next_out(h);
        } while (h != start);
    }

    /// How often the fan of v winds around the ray from o_ through v. Every step from w_i to
    /// w_{i+1} turns by an angle in (0, pi) about that ray (o_ is strictly below every triangle),
    /// so the turns past the half-plane through w_1 can be counted exactly with orient3d:
    /// the step i -> i+1 passes it iff orient3d(o, v, w_i, w_1) > 0 >= orient3d(o, v, w_{i+1}, w_1).
    int winding_about_interior(Index v, const std::vector<Index>& fan) const {
        const double* apex = p(v);
        const double* first = p(head(fan[0]));
        int previous = 0, crossings = 0;
        for (std::size_t i = 1; i < fan.size(); ++i) {
            const int r = orient3d(o_, apex, p(head(fan[i])), first);
            if (previous > 0 && r <= 0) ++crossings;
            previous = r;
        }
        if (previous > 0) ++crossings;  // the closing step back to w_1
        return crossings;
    }

    /// Without an interior point: the planar runs around v (maximal coplanar stretches of its fan)
    /// must lie in distinct planes; a fan winding k > 1 times visits every plane k times. It is
    /// enough to compare the first run's plane with the others.
    bool runs_distinct(const std::vector<Index>& fan, Index* repeated_a, Index* repeated_b) const {
        std::size_t first = fan.size();
        for (std::size_t i = 0; i < fan.size(); ++i) {
            if (!flat_[fan[i]]) {
                first = i;
                break;
            }
        }
        if (first == fan.size()) return true;
        const Index ref = fan[first] / 3;
        if (degenerate_[ref]) return true;
        const double* a = p(corner(ref, 0));
        const double* b = p(corner(ref, 1));
        const double* c = p(corner(ref, 2));
        for (std::size_t i = 0; i < fan.size(); ++i) {
            if (i == first || flat_[fan[i]]) continue;
            const Index s = fan[i] / 3;
            const Index x = head(fan[i]);
            const Index y = corner(s, static_cast<int>((fan[i] % 3 + 2) % 3));
            if (orient3d(a, b, c, p(x)) == 0 && orient3d(a, b, c, p(y)) == 0) {
                *repeated_a = ref;
                *repeated_b = s;
                return false;
            }
        }
        return true;
    }

    /// Extreme vertices and the winding of every fan. Returns false if some fan winds wrongly.
    bool check_vertices(bool have_interior) {
        bool winding_ok = true;
        std::vector<Index> fan;
        for (Index v : vertices_) {
            fan_of(v, fan);
            std::size_t breaks = 0;
            for (Index h : fan) breaks += flat_[h] ? 0 : 1;
            if (breaks <= 2) {
                out_.add("vertex " + num(v) + " is not extreme: its triangles lie in only " + num(std::max<std::size_t>(breaks, 1)) +
                         (breaks <= 1 ? " plane (it lies inside a face of the hull)" : " planes (it lies on an edge of the hull)"));
            }
            if (have_interior) {
                const int turns = winding_about_interior(v, fan);
                if (turns != 1) {
                    out_.add("vertex " + num(v) + ": its triangles wind " + std::to_string(turns) +
                             " times around it (a convex surface winds once)");
                    winding_ok = false;
                }
            } else if (breaks >= 3) {
                Index a = 0, b = 0;
                if (!runs_distinct(fan, &a, &b)) {
                    out_.add("vertex " + num(v) + ": its triangles wind around it more than once (" + triangle_name(a) +
                             " and " + triangle_name(b) + " lie in one plane but are separated by other planes)");
                    winding_ok = false;
                }
            }
        }
        return winding_ok;
    }

    bool cone_contains(Index t, const double* q, int skip, int* negative, int* negatives) const {
        *negatives = 0;
        for (int k = 0; k < 3; ++k) {
            if (k == skip) continue;
            if (orient3d(o_, p(corner(t, k)), p(corner(t, (k + 1) % 3)), q) < 0) negative[(*negatives)++] = k;
        }
        return *negatives == 0;
    }

    /// The triangle whose cone from o_ contains q: a randomized visibility walk from `start`,
    /// then, if it does not arrive within its budget, a scan of all triangles.
    Index locate(const double* q, Index start, std::uint64_t& random) {
        const std::size_t budget = 64 + 4 * static_cast<std::size_t>(std::sqrt(static_cast<double>(f_)));
        Index t = start;
        int skip = -1;  // the edge just crossed: q is known to be on t's side of it
        int negative[3];
        int negatives = 0;
        for (std::size_t step = 0; step < budget; ++step) {
            if (cone_contains(t, q, skip, negative, &negatives)) return t;
            int k = negative[0];
            if (negatives > 1) {
                random ^= random << 13;
                random ^= random >> 7;
                random ^= random << 17;
                k = negative[random % static_cast<std::uint64_t>(negatives)];
            }
            const Index g = twins_[3 * t + k];
            t = g / 3;
            skip = static_cast<int>(g % 3);
        }
        ++report_.exhaustive_points;
        for (std::size_t u = 0; u < f_; ++u) {
            if (cone_contains(static_cast<Index>(u), q, -1, negative, &negatives)) return static_cast<Index>(u);
        }
        return kNone;
    }

    std::vector<char> vertex_mask() const {
        std::vector<char> mask(points_.count, 0);
        for (Index v : vertices_) mask[v] = 1;
        return mask;
    }

    void report_outside(std::size_t i, Index t) {
        out_.add("point " + num(i) + " " + coordinates(original_[i]) + " is outside the hull: above the plane of " +
                 triangle_name(t));
    }

    /// An axis-aligned box around o_ shown exactly to lie in the hull (its 8 corners are on or below
    /// every face plane; the hull is convex): points in it need no further test. Rounded geometry
    /// sizes the box; false when it cannot be certified.
    bool inner_box(double lo[3], double hi[3]) const {
        double low[3], high[3];
        for (int axis = 0; axis < 3; ++axis) low[axis] = high[axis] = p(vertices_[0])[axis];
        for (Index v : vertices_) {
            for (int axis = 0; axis < 3; ++axis) {
                low[axis] = std::min(low[axis], p(v)[axis]);
                high[axis] = std::max(high[axis], p(v)[axis]);
            }
        }
        const double half[3] = {(high[0] - low[0]) * 0.5, (high[1] - low[1]) * 0.5, (high[2] - low[2]) * 0.5};
        double scale = std::numeric_limits<double>::infinity();
        for (Index t : face_reps_) {
            const double* a = p(corner(t, 0));
            const double* b = p(corner(t, 1));
            const double* c = p(corner(t, 2));
            const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
            const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
            const double reach = std::fabs(n[0]) * half[0] + std::fabs(n[1]) * half[1] + std::fabs(n[2]) * half[2];
            const double room = n[0] * (a[0] - o_[0]) + n[1] * (a[1] - o_[1]) + n[2] * (a[2] - o_[2]);
            if (reach > 0.0) scale = std::min(scale, room / reach);
        }
        for (double shrink : {0.9, 0.25}) {
            const double s = scale * shrink;
            if (!(s > 0.0) || !std::isfinite(s)) return false;
            for (int axis = 0; axis < 3; ++axis) {
                lo[axis] = o_[axis] - s * half[axis];
                hi[axis] = o_[axis] + s * half[axis];
                for (double* x : {&lo[axis], &hi[axis]}) {
                    if (std::fabs(*x) < kPredicateMinMagnitude) *x = 0.0;  // keep the predicates exact
                }
                if (!(lo[axis] <= hi[axis])) return false;
            }
            bool inside = true;
            for (int k = 0; k < 8 && inside; ++k) {
                const double q[3] = {(k & 1 ? hi : lo)[0], (k & 2 ? hi : lo)[1], (k & 4 ? hi : lo)[2]};
                for (Index t : face_reps_) {
                    if (orient3d(p(corner(t, 0)), p(corner(t, 1)), p(corner(t, 2)), q) > 0) {
                        inside = false;
                        break;
                    }
                }
            }
            if (inside) return true;
        }
        return false;
    }

    void contain_by_walking() {
        const std::vector<char> is_vertex = vertex_mask();
        // The inner box costs 8 tests per face; worth it when many points are not vertices.
        double lo[3] = {0, 0, 0}, hi[3] = {-1, -1, -1};
        if (points_.count - vertices_.size() > 4 * face_reps_.size() && !inner_box(lo, hi)) {
            hi[0] = -1;  // empty box
            lo[0] = 0;
        }
        // Points to locate, sorted by direction cell so that consecutive walks are short; each
        // walk starts where the previous one ended, or, in a cell no point visited yet, at a
        // triangle seen in that direction.
        std::vector<Index> pending;
        for (std::size_t i = 0; i < points_.count; ++i) {
            const double* q = p(static_cast<Index>(i));
            if (is_vertex[i] ||
                (lo[0] <= q[0] && q[0] <= hi[0] && lo[1] <= q[1] && q[1] <= hi[1] && lo[2] <= q[2] && q[2] <= hi[2])) {
                ++report_.checked_points;
            } else {
                pending.push_back(static_cast<Index>(i));
            }
        }
        DirectionGrid grid(std::max(f_, pending.size() / 2));
        for (std::size_t t = 0; t < f_; ++t) {
            double d[3];
            for (int axis = 0; axis < 3; ++axis) {
                d[axis] = (p(corner(t, 0))[axis] + p(corner(t, 1))[axis] + p(corner(t, 2))[axis]) / 3.0 - o_[axis];
            }
            grid.at(grid.cell(d)) = static_cast<Index>(t);
        }
        std::vector<Index> cell_of(pending.size());
        std::vector<Index> bucket(grid.size() + 1, 0);
        for (std::size_t k = 0; k < pending.size(); ++k) {
            const double* q = p(pending[k]);
            const double d[3] = {q[0] - o_[0], q[1] - o_[1], q[2] - o_[2]};
            cell_of[k] = static_cast<Index>(grid.cell(d));
            ++bucket[cell_of[k] + 1];
        }
        for (std::size_t c = 0; c < grid.size(); ++c) bucket[c + 1] += bucket[c];
        std::vector<Index> order(pending.size());
        for (std::size_t k = 0; k < pending.size(); ++k) order[bucket[cell_of[k]]++] = pending[k];
        pending.clear();
        pending.shrink_to_fit();

        Index previous = kNone;
        std::size_t previous_cell = grid.size();
        std::uint64_t random = 0x243f6a8885a308d3ull;
        for (const Index i : order) {
            const double* q = p(i);
            const double d[3] = {q[0] - o_[0], q[1] - o_[1], q[2] - o_[2]};
            const std::size_t cell = grid.cell(d);
            Index start = previous;
            if (cell != previous_cell && grid.at(cell) != kNone && (previous == kNone || cell != previous_cell + 1)) {
                start = grid.at(cell);
            }
            if (start == kNone) start = 0;
            previous_cell = cell;
            const Index t = locate(q, start, random);
            if (t == kNone) {
                out_.add("point " + num(i) + " could not be located on the surface (verify is inconsistent)");
                continue;
            }
            previous = t;
            const int side = orient3d(p(corner(t, 0)), p(corner(t, 1)), p(corner(t, 2)), q);
            if (side > 0) {
                report_outside(i, t);
                continue;
            }
            ++report_.checked_points;
            if (side == 0) {
                // On the surface, hence in the closed triangle t: identical to a vertex only if to
                // one of t's corners (the surface is embedded).
                const PointKey key = key_of(q);
                for (int k = 0; k < 3; ++k) {
                    const Index c = corner(t, k);
                    if (c > i && key_of(p(c)) == key) {
                        out_.add("vertex " + num(c) + " repeats point " + num(i) + " " + coordinates(original_[i]) +
                                 ": the lowest index must represent identical points");
                    }
                }
            }
        }
    }

    void contain_exhaustively(bool structure_ok) {
        if (face_reps_.empty()) return;
        if (!structure_ok) {
            const double work = static_cast<double>(points_.count) * static_cast<double>(face_reps_.size());
            if (work > 2e8) {
                out_.note("containment was not checked: the surface already failed, and testing every point "
                          "against every face would take too long");
                return;
            }
        } else {
            out_.note("no point strictly inside the hull is representable in doubles (the hull is too thin): "
                      "every point was tested against every face");
        }
        const std::vector<char> is_vertex = vertex_mask();
        std::size_t last = 0;  // the face that rejected the previous point is tried first
        for (std::size_t i = 0; i < points_.count; ++i) {
            if (is_vertex[i]) {
                ++report_.checked_points;
                continue;
            }
            const double* q = p(static_cast<Index>(i));
            bool outside = false;
            for (std::size_t k = 0; k < face_reps_.size(); ++k) {
                const std::size_t r = (last + k) % face_reps_.size();
                const Index t = face_reps_[r];
                if (orient3d(p(corner(t, 0)), p(corner(t, 1)), p(corner(t, 2)), q) > 0) {
                    report_outside(i, t);
                    outside = true;
                    last = r;
                    break;
                }
            }
            if (!outside) {
                ++report_.checked_points;
                ++report_.exhaustive_points;
            }
        }
    }

    PointSpan points_;
    PointSpan original_;
    const Index* t_;
    std::size_t f_;
    VerifyReport& report_;
    Problems out_;

    std::vector<char> degenerate_;
    std::vector<Index> out_start_;
    std::vector<std::pair<Index, Index>> outgoing_;  // per vertex, sorted: (target, half-edge)
    std::vector<Index> vertices_;
    std::vector<Index> twins_;
    std::vector<char> flat_;
    std::vector<Index> face_reps_;
    double o_[3] = {0.0, 0.0, 0.0};
};

// ---- dimensions 2, 1, 0, -1 ----

bool vertices_in_range(PointSpan points, const std::vector<Index>& vertices, Problems& out) {
    bool ok = true;
    for (Index v : vertices) {
        if (v >= points.count) {
            out.add("vertex index " + num(v) + " is out of range (" + num(points.count) + " points)");
            ok = false;
        }
    }
    std::vector<Index> sorted(vertices);
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t k = 1; k < sorted.size(); ++k) {
        if (sorted[k] == sorted[k - 1]) {
            out.add("vertex " + num(sorted[k]) + " is listed twice");
            ok = false;
        }
    }
    return ok;
}

void verify_polygon(const Prepared& prepared, const Hull& hull, VerifyReport& report, Problems& out) {
    const PointSpan points = prepared.points;
    const std::vector<Index>& v = hull.vertices;
    const std::size_t m = v.size();
    report.face_count = 1;
    if (m < 3) {
        out.add("a polygon needs at least 3 vertices, Hull::vertices has " + num(m));
        return;
    }
    if (!vertices_in_range(points, v, out)) return;
    int i = 0, j = 0;
    const int s = projection(points[v[0]], points[v[1]], points[v[2]], &i, &j);
    if (s == 0) {
        out.add("polygon vertices " + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + " are collinear");
        return;
    }
    // Orientation in the polygon's plane, positive towards the polygon's interior side.
    auto side = [&](Index a, Index b, std::size_t q) {
        const double* pa = points[a];
        const double* pb = points[b];
        const double* pq = points[q];
        return s * orient2d(pa[i], pa[j], pb[i], pb[j], pq[i], pq[j]);
    };

    bool shape_ok = true;
    for (std::size_t k = 0; k < m; ++k) {
        const Index a = v[k], b = v[(k + 1) % m], c = v[(k + 2) % m];
        if (side(a, b, c) <= 0) {
            out.add("polygon corner " + num(b) + " is not strictly convex: " + num(a) + ", " + num(b) + ", " + num(c) +
                    (side(a, b, c) == 0 ? " are collinear" : " turn the wrong way"));
            shape_ok = false;
        }
    }
    // Traversed once: seen from v[0], the other corners come in strictly increasing angle within a
    // half-turn (each strictly left of v[0] -> v[1] and of the previous one).
    for (std::size_t k = 2; k < m && shape_ok; ++k) {
        if (side(v[0], v[1], v[k]) <= 0 || side(v[0], v[k - 1], v[k]) <= 0) {
            out.add("the polygon is not simple: corner " + num(v[k]) + " is out of angular order around corner " +
                    num(v[0]) + " (it winds around more than once)");
            shape_ok = false;
        }
    }

    const double* a = points[v[0]];
    const double* b = points[v[1]];
    const double* c = points[v[2]];
    bool planar = true;
    for (std::size_t q = 0; q < points.count; ++q) {
        if (orient3d(a, b, c, points[q]) != 0) {
            out.add("point " + num(q) + " " + coordinates(prepared.original[q]) + " is not in the polygon's plane");
            planar = false;
        }
    }
    check_representatives(points, prepared.original, v, out);

    // The triangles fan the polygon from vertices[0].
    std::vector<Index> fan;
    for (std::size_t k = 1; k + 1 < m; ++k) fan.insert(fan.end(), {v[0], v[k], v[k + 1]});
    if (hull.triangles != fan) out.add("Hull::triangles is not the fan of the polygon from vertices[0]");
    if (!hull.face_offsets.empty() &&
        (hull.face_offsets != std::vector<Index>{0, static_cast<Index>(m)} || hull.face_vertices != v)) {
        out.add("the merged face is not the polygon");
    }

    if (!shape_ok || !planar) {
        out.note("containment in the polygon was not checked: the polygon or the plane is wrong");
        return;
    }
    for (std::size_t q = 0; q < points.count; ++q) {
        std::size_t edge = m;  // the edge q is beyond (its first corner's position), m if inside
        if (side(v[0], v[1], q) < 0) {
            edge = 0;
        } else if (side(v[0], v[m - 1], q) > 0) {
            edge = m - 1;
        } else {
            std::size_t lo = 1, hi = m - 1;  // side(v[0], v[lo], q) >= 0
            while (lo < hi) {
                const std::size_t mid = (lo + hi + 1) / 2;
                if (side(v[0], v[mid], q) >= 0) {
                    lo = mid;
                } else {
                    hi = mid - 1;
                }
            }
            const std::size_t k = std::min(lo, m - 2);
            if (side(v[k], v[k + 1], q) < 0) edge = k;
        }
        if (edge == m) {
            ++report.checked_points;
        } else {
            out.add("point " + num(q) + " " + coordinates(prepared.original[q]) + " is outside the polygon: beyond its edge " +
                    num(v[edge]) + "-" + num(v[(edge + 1) % m]));
        }
    }
}

void verify_segment(const Prepared& prepared, const Hull& hull, VerifyReport& report, Problems& out) {
    const PointSpan points = prepared.points;
    const std::vector<Index>& v = hull.vertices;
    if (v.size() != 2) {
        out.add("a segment has 2 end points, Hull::vertices has " + num(v.size()));
        return;
    }
    if (!vertices_in_range(points, v, out)) return;
    const double* a = points[v[0]];
    const double* b = points[v[1]];
    if (key_of(a) == key_of(b)) {
        out.add("the end points " + num(v[0]) + " and " + num(v[1]) + " are the same point");
        return;
    }
    for (std::size_t q = 0; q < points.count; ++q) {
        const double* x = points[q];
        if (!collinear3d(a, b, x)) {
            out.add("point " + num(q) + " " + coordinates(prepared.original[q]) + " is not on the line through " +
                    num(v[0]) + " and " + num(v[1]));
            continue;
        }
        bool between = true;
        for (int axis = 0; axis < 3; ++axis) {
            between = between && std::min(a[axis], b[axis]) <= x[axis] && x[axis] <= std::max(a[axis], b[axis]);
        }
        if (between) {
            ++report.checked_points;
        } else {
            out.add("point " + num(q) + " " + coordinates(prepared.original[q]) + " is beyond the segment's ends " +
                    num(v[0]) + " and " + num(v[1]));
        }
    }
    check_representatives(points, prepared.original, v, out);
    if (!hull.triangles.empty()) out.add("a segment has no triangles, Hull::triangles has " + num(hull.face_count()));
}

void verify_single_point(const Prepared& prepared, const Hull& hull, VerifyReport& report, Problems& out) {
    const PointSpan points = prepared.points;
    const std::vector<Index>& v = hull.vertices;
    if (v.size() != 1) {
        out.add("a single point has 1 vertex, Hull::vertices has " + num(v.size()));
        return;
    }
    if (!vertices_in_range(points, v, out)) return;
    const PointKey only = key_of(points[v[0]]);
    for (std::size_t q = 0; q < points.count; ++q) {
        if (key_of(points[q]) == only) {
            ++report.checked_points;
        } else {
            out.add("point " + num(q) + " " + coordinates(prepared.original[q]) + " differs from the single vertex " +
                    num(v[0]));
        }
    }
    check_representatives(points, prepared.original, v, out);
    if (!hull.triangles.empty()) out.add("a single point has no triangles, Hull::triangles has " + num(hull.face_count()));
}

void verify_solid(const Prepared& prepared, const Hull& hull, VerifyReport& report, Problems& out) {
    if (hull.triangles.size() % 3 != 0) {
        out.add("Hull::triangles has " + num(hull.triangles.size()) + " indices, not a multiple of 3");
        return;
    }
    SurfaceVerifier(prepared, hull.triangles.data(), hull.face_count(), report).run();
    std::vector<Index> corners;  // ascending, without repeats (indices out of range are reported already)
    {
        std::vector<char> used(prepared.points.count, 0);
        for (Index i : hull.triangles) {
            if (i < used.size()) used[i] = 1;
        }
        for (std::size_t i = 0; i < used.size(); ++i) {
            if (used[i]) corners.push_back(static_cast<Index>(i));
        }
    }
    if (corners != hull.vertices) {
        std::vector<Index> listed(hull.vertices);
        std::sort(listed.begin(), listed.end());
        std::vector<Index> extra, missing;
        std::set_difference(listed.begin(), listed.end(), corners.begin(), corners.end(), std::back_inserter(extra));
        std::set_difference(corners.begin(), corners.end(), listed.begin(), listed.end(), std::back_inserter(missing));
        std::string what = "Hull::vertices is not the ascending list of the triangles' corners";
        if (!extra.empty()) what += ": vertex " + num(extra[0]) + " is no triangle's corner";
        else if (!missing.empty()) what += ": corner " + num(missing[0]) + " is not listed";
        else what += ": it is out of order or repeats an index";
        out.add(what);
    }
    // The volume is rounded and may underflow to 0 (or overflow) far from unit scale; the exact
    // check of positive volume is on the triangles.
    if (!(hull.volume >= 0.0)) {
        char text[64];
        std::snprintf(text, sizeof text, "%.17g", hull.volume);
        out.add(std::string("Hull::volume is ") + text + ", negative");
    }
    if (!hull.face_offsets.empty()) {
        const std::size_t faces = hull.face_offsets.size() - 1;
        bool shaped = hull.face_offsets.front() == 0 && hull.face_offsets.back() == hull.face_vertices.size();
        for (std::size_t f = 0; f < faces && shaped; ++f) shaped = hull.face_offsets[f + 1] >= hull.face_offsets[f] + 3;
        if (!shaped) {
            out.add("the merged faces (Hull::face_offsets) are malformed");
        } else if (report.problem_count == 0 && faces != report.face_count) {
            out.add("merge_coplanar reported " + num(faces) + " faces, but the triangles form " + num(report.face_count) +
                    " planar faces");
        }
    }
}

}  // namespace

VerifyReport verify(PointSpan points, const std::uint32_t* triangles, std::size_t triangle_count) {
    VerifyReport report;
    report.dimension = 3;
    Problems out(report);
    Prepared prepared;
    if (!prepare(points, out, prepared)) return report;
    SurfaceVerifier(prepared, triangles, triangle_count, report).run();
    return report;
}

VerifyReport verify(PointSpan points, const Hull& hull) {
    VerifyReport report;
    report.dimension = hull.dimension;
    report.triangle_count = hull.face_count();
    report.vertex_count = hull.vertices.size();
    Problems out(report);
    if (!hull.ok()) {
        out.add("the hull computation failed: " + hull.error);
        return report;
    }
    Prepared prepared;
    if (!prepare(points, out, prepared)) return report;
    switch (hull.dimension) {
        case 3:
            verify_solid(prepared, hull, report, out);
            break;
        case 2:
            verify_polygon(prepared, hull, report, out);
            break;
        case 1:
            verify_segment(prepared, hull, report, out);
            break;
        case 0:
            verify_single_point(prepared, hull, report, out);
            break;
        case -1:
            if (points.count != 0) out.add("dimension -1 means no points, but there are " + num(points.count));
            if (!hull.vertices.empty() || !hull.triangles.empty()) out.add("an empty hull has no vertices or triangles");
            break;
        default:
            out.add("Hull::dimension " + std::to_string(hull.dimension) + " is not one of 3, 2, 1, 0, -1");
    }
    return report;
}

}  // namespace hullkit
