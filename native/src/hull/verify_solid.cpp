// hullkit::verify in dimension 3: the structure of the triangle surface (indices, areas, edge
// pairing, fans, connectivity, Euler characteristic), local convexity, the planar faces, the exact
// interior point and the winding of every vertex's fan (SurfaceVerifier, steps 1-3 and 5 of
// verify.hpp), and the checks of a Hull's dimension-3 fields (verify_solid). The containment of
// the points (step 4) is in verify_containment.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "hullkit/predicates.hpp"
#include "hullkit/verify.hpp"
#include "verify_internal.hpp"

namespace hullkit::verify_detail {

namespace {

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

}  // namespace

// ---- dimension 3 ----

void SurfaceVerifier::run() {
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

bool SurfaceVerifier::check_indices() {
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

void SurfaceVerifier::check_areas() {
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
bool SurfaceVerifier::pair_edges() {
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
bool SurfaceVerifier::check_fans() {
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

bool SurfaceVerifier::check_connected() {
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

bool SurfaceVerifier::check_euler() {
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
void SurfaceVerifier::check_edges() {
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
void SurfaceVerifier::merge_faces() {
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

bool SurfaceVerifier::strictly_inside(const double* o) const {
    for (Index t : face_reps_) {
        if (orient3d(p(corner(t, 0)), p(corner(t, 1)), p(corner(t, 2)), o) >= 0) return false;
    }
    return true;
}

/// A point strictly below every face plane: rounded candidates, each confirmed exactly. Fails
/// only for polytopes so thin that no double lies strictly inside near the candidates.
bool SurfaceVerifier::find_interior_point() {
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
void SurfaceVerifier::fan_of(Index v, std::vector<Index>& fan) const {
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
int SurfaceVerifier::winding_about_interior(Index v, const std::vector<Index>& fan) const {
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
bool SurfaceVerifier::runs_distinct(const std::vector<Index>& fan, Index* repeated_a, Index* repeated_b) const {
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
bool SurfaceVerifier::check_vertices(bool have_interior) {
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

}  // namespace hullkit::verify_detail
