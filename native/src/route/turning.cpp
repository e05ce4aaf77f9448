// Legs that turn: RouteChecker's check of a leg whose two orientations differ. motion.hpp has the
// motion (linear offset, slerp orientation, about the traverse's pivot) and the bound this rests
// on: over a sub-interval [t0, t1] every point of the traverse within r of the rotation axis stays
// within delta = r (theta (t1 - t0))^2 / 8 of the convex hull of its two end positions.
//
//   start      the exact static test at the leg's first pose (surfaces within the margin, then
//              containment by ray parity), as for a translation;
//   certify    [t0, t1] is clear when every obstacle triangle is kept more than the part's delta
//              plus the margin (plus the tolerance) from the part's hull's sweep (convex_sweep.hpp:
//              the hull's points at both poses) along some direction, the obstacles' BVH nodes
//              pruned by the sweep's separating axes. That is all for a convex part (its solid is
//              its hull). For any other part an obstacle triangle the hull's sweep does not clear
//              is checked against the part's own triangles: its BVH nodes placed at both poses,
//              each box grown by the node's delta, then each triangle's 6 end-pose vertices kept
//              more than the triangle's delta plus the margin away along some direction;
//   subdivide  an interval not certified is halved, earlier half first, down to kTurnStep; the
//              certified intervals form the clear prefix [0, lo]. The obstacle triangle that failed
//              is tried first in the next interval, a failed interval keeps the few obstacle
//              triangles that can come near any of its sub-intervals (a frame) so that its pieces
//              need not walk the BVH again, and it is split around where its failing pair seems
//              to meet (turn_guess) when that lies inside it;
//   bracket    at the first interval still uncertain at that width, the exact static test at its
//              end (and up to kTurnLookAhead steps further, while within 1e-7 of lo) finds a pose in
//              contact: hi. When none is, the traverse passes closer than the bounds can resolve
//              without a pose found in contact: reported as a hit with `grazing`, [lo, lo + step].
//   clearance  of a clear leg: branch and bound over sub-intervals; lower bounds from the same
//              separating directions minus delta, upper bounds from distances at exact poses
//              (obstacle triangles pruned by their gap from the part's placed hull).
// Every "contact" reported is a pose whose rounded coordinates the exact static test finds within
// the margin; "clear" is reported only when every sub-interval was certified.
#include <algorithm>
#include <cmath>
#include <functional>
#include <tuple>
#include <utility>
#include <vector>

#include "checker_internal.hpp"
#include "motion.hpp"

namespace hullkit {

using namespace route_detail;

namespace {

/// The narrowest sub-interval (2.98e-8 of the leg): with kTurnLookAhead more steps a bracket stays
/// within the promised 1e-7.
constexpr double kTurnStep = 0x1p-25;
constexpr int kTurnLookAhead = 2;
/// A failed interval wider than kGuessWidest is split around the guessed contact (turn_guess),
/// with a window of kGuessWindow of its width on either side.
constexpr double kGuessWindow = 1.0 / 32;
constexpr double kGuessWidest = 0x1p-19;

/// The axis-aligned box of `body` (the traverse's own coordinates) placed at `pose`, before the
/// rounding allowance the caller adds.
Box placed_box(const Box& body, const Pose& pose, const Vec& pivot) {
    if (pose.rotation.identity) return body.shifted(pose.offset);
    const Vec c = (body.lo + body.hi) * 0.5, h = (body.hi - body.lo) * 0.5;
    const Vec centre = place(pose, pivot, c);
    const Rotation& r = pose.rotation;
    const Vec reach(glm::dot(glm::abs(r.row[0]), h), glm::dot(glm::abs(r.row[1]), h), glm::dot(glm::abs(r.row[2]), h));
    return {centre - reach, centre + reach};
}

double box_size2(const Box& b) {
    const Vec d = b.hi - b.lo;
    return glm::dot(d, d);
}

using NodePairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

/// Walks the part's BVH (node boxes placed by `node_box(n)`) against the obstacles' BVH, depth
/// first, opening the larger box of a pair; `keep(part_box, obstacle_box)` says whether a pair of
/// nodes may hold what is sought, `leaves(part_leaf, obstacle_leaf)` visits a pair of leaves and
/// returns true to stop the walk (then dual_walk returns true).
template <typename NodeBox, typename Keep, typename Leaves>
bool dual_walk(const Bvh& part_bvh, const Bvh& obstacles, NodePairs& stack, NodeBox&& node_box, Keep&& keep,
               Leaves&& leaves) {
    if (part_bvh.nodes.empty() || obstacles.nodes.empty()) return false;
    stack.clear();
    stack.emplace_back(0u, 0u);
    while (!stack.empty()) {
        const auto [pn, on] = stack.back();
        stack.pop_back();
        const Box& pb = node_box(pn);
        const BvhNode& onode = obstacles.nodes[on];
        if (!keep(pb, onode.box)) continue;
        const BvhNode& pnode = part_bvh.nodes[pn];
        if (pnode.count == 0 && (onode.count != 0 || box_size2(pb) >= box_size2(onode.box))) {
            stack.emplace_back(pnode.first, on);
            stack.emplace_back(pnode.first + 1, on);
        } else if (onode.count == 0) {
            stack.emplace_back(pn, onode.first);
            stack.emplace_back(pn, onode.first + 1);
        } else if (leaves(pnode, onode)) {
            return true;
        }
    }
    return false;
}

/// The largest gap found between the hull of p[0..6) (a triangle's two end poses, 3 points each)
/// and triangle q along the candidate directions: q's normal, the end poses' normals, and the
/// direction between the hull's and q's closest points (GJK). Any direction's gap is a lower
/// bound of the true distance. Stops as soon as a gap exceeds `enough`.
double hull_gap(const Vec* p, const Vec* q, double enough) {
    double best = -kInf;
    auto consider = [&](const Vec& n) {
        best = std::max(best, points_gap_along(n, p, 6, q));
        return best > enough;
    };
    if (consider(glm::cross(q[1] - q[0], q[2] - q[1]))) return best;
    if (consider(glm::cross(p[1] - p[0], p[2] - p[0]))) return best;
    if (consider(glm::cross(p[4] - p[3], p[5] - p[3]))) return best;
    consider(hull_closest_direction(p, 6, q));
    return best;
}

/// The box of a triangle's 6 end-pose vertices (p[0..6)).
Box swept_box(const Vec* p) {
    Box b = triangle_box(p);
    b.add(triangle_box(p + 3));
    return b;
}

/// Visits visit(slot) for the obstacle triangles in BVH leaves whose lower bound of the distance
/// from `sweep` is at most `cutoff` (read at every node: it may shrink as the visits go), nearer
/// child first; stops when visit returns false.
template <typename Visit>
void walk_near(const Bvh& obstacles, const ConvexSweep& sweep, const double& cutoff, Visit&& visit) {
    if (obstacles.nodes.empty()) return;
    std::pair<double, std::uint32_t> stack[128];
    int top = 0;
    stack[top++] = {sweep.box_gap(obstacles.nodes[0].box, cutoff), 0u};
    while (top > 0) {
        const auto [gap, index] = stack[--top];
        if (gap > cutoff) continue;
        const BvhNode& node = obstacles.nodes[index];
        if (node.count == 0) {
            const double a = sweep.box_gap(obstacles.nodes[node.first].box, cutoff);
            const double b = sweep.box_gap(obstacles.nodes[node.first + 1].box, cutoff);
            if (a > cutoff && b > cutoff) continue;
            if (a <= b) {
                stack[top++] = {b, node.first + 1};
                stack[top++] = {a, node.first};
            } else {
                stack[top++] = {a, node.first};
                stack[top++] = {b, node.first + 1};
            }
            continue;
        }
        for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
            if (!visit(s)) return;
        }
    }
}

/// Entries of a part's cache of separating directions (a power of two).
constexpr std::size_t kDirectionCache = 256;
/// A failed interval keeps its nearby obstacle triangles for its pieces when there are at most
/// this many.
constexpr std::size_t kFrameSlots = 24;

}  // namespace

namespace route_detail {

struct TurnState {
    struct PerPart {
        std::vector<double> node_radius;  ///< per BVH node: largest distance from the axis
        std::vector<double> tri_radius;   ///< per triangle slot
        std::vector<Box> boxes;           ///< per node: placed at both poses, grown
        std::vector<Vec> placed;          ///< per slot: 3 vertices at t0, then 3 at t1
        std::vector<std::uint32_t> box_stamp, tri_stamp;
        // Over an interval the part stays within `radius`'s delta of `sweep`, its hull's sweep
        // (convex_sweep.hpp); a convex part (Part::hull_surface, its solid its hull) needs no more.
        bool convex = false;
        double radius = 0.0;  ///< the hull points' largest distance from the rotation axis
        ConvexSweep sweep;
        std::uint32_t sweep_stamp = 0;
        /// The closest-points directions found lately, by obstacle slot (direct-mapped): the same
        /// triangles come back in every sub-interval of a bisection, and a direction that kept
        /// one apart over an interval often keeps it apart over the next.
        std::vector<std::pair<std::uint32_t, Vec>> directions;
        /// Obstacle triangles that may come near the sweep of any sub-interval of [t0, t1]: an
        /// interval that failed keeps them for its pieces (nested, innermost at depth - 1).
        struct Frame {
            double t0 = 0.0, t1 = 0.0;
            std::vector<std::uint32_t> slots;
        };
        std::vector<Frame> frames;
        std::size_t depth = 0;
        double frame_width = 1.0;  ///< the widest interval a frame is built for from the BVH
    };
    const LegMotion& motion;
    std::vector<PerPart> parts;
    double t0 = 0.0, t1 = 0.0, tol = 0.0;
    Pose p0, p1;
    std::uint32_t stamp = 0;
    // The obstacle triangle (and part triangle) that kept the last interval from being certified
    // (when `hint`).
    bool hint = false;
    std::size_t part = 0;
    std::uint32_t part_slot = 0, slot = 0;
    bool whole_part = false;  ///< a convex part's sweep failed: part_slot is not set

    explicit TurnState(const LegMotion& m) : motion(m) {}

    /// The part's hull's sweep over the interval (cached per interval).
    const ConvexSweep& sweep_of(const Part& part, PerPart& pp) {
        if (pp.sweep_stamp != stamp) {
            pp.sweep_stamp = stamp;
            const Pose poses[2] = {p0, p1};
            pp.sweep.place(part.hull_points, part.face_normals, part.edge_directions, poses, 2, motion.pivot,
                           motion.theta * (t1 - t0));
        }
        return pp.sweep;
    }

    /// The sweep's gap from obstacle triangle q (slot `slot`), with the slot's cached direction.
    static double sweep_gap(PerPart& pp, std::uint32_t slot, const Vec* q, double enough) {
        auto& cached = pp.directions[slot & (pp.directions.size() - 1)];
        const bool known = cached.first == slot;
        cached.first = slot;
        return pp.sweep.gap(q, enough, &cached.second, known);
    }

    /// Part triangle slot ps's vertices placed at t0 (3), then at t1 (3); cached for the interval.
    const Vec* placed(const Part& part, PerPart& pp, std::uint32_t ps) {
        Vec* out = &pp.placed[6 * ps];
        if (pp.tri_stamp[ps] != stamp) {
            for (int k = 0; k < 3; ++k) {
                out[k] = place(p0, motion.pivot, part.tris[3 * ps + k]);
                out[3 + k] = place(p1, motion.pivot, part.tris[3 * ps + k]);
            }
            pp.tri_stamp[ps] = stamp;
        }
        return out;
    }

    /// Part node n's box placed at both poses of the interval, grown by the node's delta, the
    /// tolerance and `extra`; cached for the interval (which uses one `extra` throughout).
    const Box& node_box(const Part& part, PerPart& pp, std::uint32_t n, double extra) {
        if (pp.box_stamp[n] != stamp) {
            Box b = placed_box(part.bvh.nodes[n].box, p0, motion.pivot);
            b.add(placed_box(part.bvh.nodes[n].box, p1, motion.pivot));
            pp.boxes[n] = b.inflated(motion.deviation(pp.node_radius[n], t1 - t0) + tol + extra);
            pp.box_stamp[n] = stamp;
        }
        return pp.boxes[n];
    }
};

}  // namespace route_detail

void RouteChecker::Impl::turn_prepare(TurnState& st) const {
    st.parts.resize(parts.size());
    for (std::size_t pi = 0; pi < parts.size(); ++pi) {
        const Part& part = parts[pi];
        TurnState::PerPart& pp = st.parts[pi];
        pp.node_radius.resize(part.bvh.nodes.size());
        for (std::size_t n = 0; n < part.bvh.nodes.size(); ++n) {
            pp.node_radius[n] = st.motion.radius(part.bvh.nodes[n].box.lo, part.bvh.nodes[n].box.hi);
        }
        const std::size_t slots = part.tris.size() / 3;
        pp.tri_radius.resize(slots);
        for (std::size_t s = 0; s < slots; ++s) {
            double r = 0.0;
            for (int k = 0; k < 3; ++k) r = std::max(r, st.motion.radius(part.tris[3 * s + k]));
            pp.tri_radius[s] = r * (1.0 + 1e-12);
        }
        pp.boxes.resize(part.bvh.nodes.size());
        pp.box_stamp.assign(part.bvh.nodes.size(), 0);
        pp.placed.resize(2 * part.tris.size());
        pp.tri_stamp.assign(slots, 0);
        pp.convex = part.hull_surface;
        pp.directions.assign(kDirectionCache, {~std::uint32_t{0}, Vec(0.0)});
        for (const Vec& v : part.hull_points) pp.radius = std::max(pp.radius, st.motion.radius(v));
        pp.radius *= 1.0 + 1e-12;
    }
}

void RouteChecker::Impl::turn_interval(TurnState& st, double t0, double t1) const {
    st.t0 = t0;
    st.t1 = t1;
    st.p0 = st.motion.at(t0);
    st.p1 = st.motion.at(t1);
    const Vec m = glm::max(glm::abs(st.p0.offset), glm::abs(st.p1.offset));
    st.tol = tolerance(std::max({m.x, m.y, m.z}) + glm::length(st.motion.pivot));
    ++st.stamp;
}

bool RouteChecker::Impl::turn_certify(TurnState& st, std::size_t pi) const {
    const Part& part = parts[pi];
    TurnState::PerPart& pp = st.parts[pi];
    if (bvh.nodes.empty() || part.bvh.nodes.empty()) return true;
    const ConvexSweep& sweep = st.sweep_of(part, pp);
    const double span = st.t1 - st.t0;
    const double grow = st.motion.deviation(pp.radius, span) + margin + st.tol;
    // Obstacle triangle s against the part: its hull's sweep first; a part that is not its hull
    // then by its own triangles near s (its BVH nodes placed at both poses and grown by their
    // delta, then each triangle's 6 end-pose vertices grown by the triangle's).
    auto apart = [&](std::uint32_t s) {
        const Vec* q = &tris[3 * s];
        if (TurnState::sweep_gap(pp, s, q, grow) > grow) return true;
        st.hint = true;
        st.part = pi;
        st.slot = s;
        if (pp.convex) {
            st.whole_part = true;
            return false;
        }
        st.whole_part = false;
        const Box qbox = triangle_box(q);
        bool kept_apart = true;
        walk_tree(part.bvh, [&](std::uint32_t n) { return !st.node_box(part, pp, n, margin).overlaps(qbox); },
                  [&](std::uint32_t ps) {
            const Vec* p = st.placed(part, pp, ps);
            const double g = st.motion.deviation(pp.tri_radius[ps], span) + margin + st.tol;
            if (!swept_box(p).inflated(g).overlaps(qbox) || hull_gap(p, q, g) > g) return true;
            st.part_slot = ps;
            return kept_apart = false;
        });
        return kept_apart;
    };
    // The frames of enclosing intervals that failed: the innermost that holds this one.
    while (pp.depth > 0 && !(pp.frames[pp.depth - 1].t0 <= st.t0 && st.t1 <= pp.frames[pp.depth - 1].t1)) --pp.depth;
    // The triangle that kept the enclosing interval uncertain usually keeps this one uncertain
    // too: trying it first makes a failing certification cheap (the answer is the same either way).
    bool clear = !(st.hint && st.part == pi && !apart(st.slot));
    if (clear && pp.depth > 0) {
        for (std::uint32_t s : pp.frames[pp.depth - 1].slots) {
            if (!(clear = apart(s))) break;
        }
    } else if (clear) {
        walk_near(bvh, sweep, grow, [&](std::uint32_t s) { return clear = apart(s); });
    }
    if (!clear) turn_frame(st, pi);
    return clear;
}

void RouteChecker::Impl::turn_frame(TurnState& st, std::size_t pi) const {
    // Every sub-interval's sweep lies within delta of this interval's (its end poses do, by the
    // bound) and is grown by at most delta again (plus the margin): what is farther than twice
    // delta plus the margin (and the roundings of the end poses, a few tolerances) stays apart.
    TurnState::PerPart& pp = st.parts[pi];
    const double reach = 2.0 * st.motion.deviation(pp.radius, st.t1 - st.t0) + margin + 3.0 * st.tol;
    if (pp.frames.size() <= pp.depth) pp.frames.resize(pp.depth + 1);
    TurnState::PerPart::Frame& frame = pp.frames[pp.depth];
    frame.t0 = st.t0;
    frame.t1 = st.t1;
    frame.slots.clear();
    auto near = [&](std::uint32_t s) {
        if (pp.sweep.axes_gap(&tris[3 * s], reach) <= reach) frame.slots.push_back(s);
        return frame.slots.size() <= kFrameSlots;
    };
    if (pp.depth > 0) {
        for (std::uint32_t s : pp.frames[pp.depth - 1].slots) near(s);
    } else {
        // After a walk that found too many, the next tries a quarter of that width.
        if (st.t1 - st.t0 > pp.frame_width) return;
        walk_near(bvh, pp.sweep, reach, [&](std::uint32_t s) { return near(s); });
        if (frame.slots.size() > kFrameSlots) {
            pp.frame_width = 0.25 * (st.t1 - st.t0);
            return;  // too many to be worth keeping
        }
    }
    ++pp.depth;
}

std::vector<Part> RouteChecker::Impl::turned_parts(const Quat& q) const {
    Pose pose;
    pose.rotation = rotation_of(q);
    std::vector<Part> out(parts.size());
    for (std::size_t pi = 0; pi < parts.size(); ++pi) {
        // The turned vertices without the offset: a translation by w then adds it, giving place().
        TriangleMesh mesh = scene.parts[pi];
        for (std::size_t i = 0; i < mesh.xyz.size(); i += 3) {
            const Vec v(mesh.xyz[i], mesh.xyz[i + 1], mesh.xyz[i + 2]);
            const Vec turned = pivot + pose.rotation.apply(v - pivot);
            mesh.xyz[i] = turned.x, mesh.xyz[i + 1] = turned.y, mesh.xyz[i + 2] = turned.z;
        }
        build_part(mesh, out[pi]);
    }
    return out;
}

StaticContact RouteChecker::Impl::posed_contact(const Pose& pose, bool want_distance) const {
    // Each part placed once, for the contact test and the distance.
    std::vector<PlacedPart> placed(parts.size());
    for (std::size_t pi = 0; pi < parts.size(); ++pi) place_part(pi, pose, &placed[pi]);
    return contact_with(
        want_distance, [&](std::size_t pi, Found* found) { return posed_touch(pi, pose, found, &placed[pi]); },
        [&](std::size_t pi, Nearest* best) { posed_nearest(pi, pose, 0.0, best, &placed[pi]); });
}

void RouteChecker::Impl::place_part(std::size_t pi, const Pose& pose, PlacedPart* out) const {
    const Part& part = parts[pi];
    out->tris.resize(part.tris.size());
    for (std::size_t k = 0; k < part.tris.size(); ++k) out->tris[k] = place(pose, pivot, part.tris[k]);
    out->boxes.resize(part.bvh.nodes.size());
    for (std::size_t n = 0; n < out->boxes.size(); ++n) out->boxes[n] = placed_box(part.bvh.nodes[n].box, pose, pivot);
}

bool RouteChecker::Impl::posed_touch(std::size_t pi, const Pose& pose, Found* found, const PlacedPart* given) const {
    if (pose.rotation.identity) return static_touch(parts[pi], pi, pose.offset, found);
    const Part& part = parts[pi];
    const Vec m = glm::abs(pose.offset);
    const double tol = tolerance(std::max({m.x, m.y, m.z}) + glm::length(pivot));
    PlacedPart own;
    if (!given) place_part(pi, pose, &own);
    const std::vector<Vec>& placed = (given ? given : &own)->tris;
    const std::vector<Box>& boxes = (given ? given : &own)->boxes;
    const Box placed_all = placed_box(part.box, pose, pivot).inflated(tol);
    // Surfaces within the margin: the part's nodes placed (grown by the margin and the
    // tolerance), against the obstacles' BVH.
    NodePairs stack;
    const bool hit = dual_walk(part.bvh, bvh, stack, [&](std::uint32_t n) { return boxes[n].inflated(margin + tol); },
                               [](const Box& a, const Box& b) { return a.overlaps(b); },
                               [&](const BvhNode& pnode, const BvhNode& onode) {
        for (std::uint32_t ps = pnode.first; ps < pnode.first + pnode.count; ++ps) {
            const Vec* p = &placed[3 * ps];
            const Box pbox = triangle_box(p).inflated(margin + tol);
            for (std::uint32_t s = onode.first; s < onode.first + onode.count; ++s) {
                const Vec* q = &tris[3 * s];
                if (!pbox.overlaps(triangle_box(q))) continue;
                double w[3];
                if (margin == 0.0 ? !triangles_meet(p, q) : triangle_distance2(p, q, w) > margin * margin) continue;
                found->slot = s;
                found->part_slot = ps;
                found->obstacle = tri_obstacle[s];
                found->triangle = tri_index[s];
                return true;
            }
        }
        return false;
    });
    if (hit) {
        found->containment = false;
        found->part = static_cast<std::int64_t>(pi);
        return true;
    }
    // No surfaces meet: one vertex per connected piece decides containment.
    auto contained = [&](std::int64_t obstacle, std::int64_t triangle) {
        *found = Found{};
        found->containment = true;
        found->obstacle = obstacle;
        found->triangle = triangle;
        found->part = static_cast<std::int64_t>(pi);
        return true;
    };
    if (part.closed) {
        for (const Component& c : obstacle_components) {
            if (placed_all.contains(c.box) && inside_placed(placed, c.rep, placed_all, tol)) return contained(c.mesh, c.triangle);
        }
    }
    for (std::uint32_t o = 0; o < obstacle_closed.size(); ++o) {
        if (!obstacle_closed[o] || !obstacle_box[o].inflated(tol).contains(placed_all)) continue;
        for (const Component& c : part.components) {
            if (inside_obstacle(o, place(pose, pivot, c.rep), tol)) return contained(o, 0);
        }
    }
    return false;
}

bool RouteChecker::Impl::inside_placed(const std::vector<Vec>& placed, const Vec& x, const Box& box, double tol) const {
    // Ray parity over every placed triangle (a static test at a turned pose is rare: a leg's start,
    // a bracket's end, samples), with the same rays and the same doubt rule as parity_inside.
    const double reach = 4.0 * (glm::length(box.hi - box.lo) + glm::length(x - box.lo)) + 1.0;
    for (int attempt = 0; attempt < 64; ++attempt) {
        const Vec far = x + reach * ray_direction(attempt);
        Box ray;
        ray.add(x);
        ray.add(far);
        ray = ray.inflated(tol);
        int crossings = 0;
        bool degenerate = false;
        for (std::size_t s = 0; s < placed.size() && !degenerate; s += 3) {
            if (!ray.overlaps(triangle_box(&placed[s]))) continue;
            const int r = ray_crossing(x, far, &placed[s]);
            if (r < 0) degenerate = true;
            crossings += std::max(r, 0);
        }
        if (!degenerate) return crossings % 2 == 1;
    }
    return true;
}

double RouteChecker::Impl::placed_pair_distance(std::size_t pi, std::uint32_t part_slot, std::uint32_t slot,
                                                const Pose& pose) const {
    const Vec* p = &parts[pi].tris[3 * part_slot];
    const Vec placed[3] = {place(pose, pivot, p[0]), place(pose, pivot, p[1]), place(pose, pivot, p[2])};
    double w[3];
    return triangle_distance(placed, &tris[3 * slot], w);
}

std::uint32_t RouteChecker::Impl::nearest_part_slot(std::size_t pi, std::uint32_t slot, const Pose& pose) const {
    std::uint32_t best_slot = 0;
    double best = kInf;
    for (std::uint32_t ps = 0; ps < parts[pi].tris.size() / 3; ++ps) {
        const double d = placed_pair_distance(pi, ps, slot, pose);
        if (d < best) best = d, best_slot = ps;
    }
    return best_slot;
}

void RouteChecker::Impl::posed_nearest(std::size_t pi, const Pose& pose, double t, Nearest* best,
                                       const PlacedPart* given) const {
    const Part& part = parts[pi];
    if (bvh.nodes.empty() || part.bvh.nodes.empty()) return;
    PlacedPart own;
    if (!given) place_part(pi, pose, &own);
    const std::vector<Vec>& placed = (given ? given : &own)->tris;
    const std::vector<Box>& boxes = (given ? given : &own)->boxes;
    auto consider = [&](std::uint32_t ps, std::uint32_t s) {
        double w[3];
        const double d = triangle_distance(&placed[3 * ps], &tris[3 * s], w);
        if (d < best->distance) {
            best->distance = d;
            best->fraction = t;
            best->obstacle = tri_obstacle[s];
            best->triangle = tri_index[s];
            best->part = static_cast<std::int64_t>(pi);
        }
    };
    // The placed boxes are short of the rounded vertices by a few ulps at most, and the gaps are
    // floating point: a lower bound slightly too high only costs a pair whose distance ties the
    // best to the last bits. Obstacle triangles by their gap from the placed hull (its face
    // normals as axes; the hull holds the part), then the part's triangles near each.
    ConvexSweep hull;
    hull.place(part.hull_points, part.face_normals, part.edge_directions, &pose, 1, pivot);
    walk_near(bvh, hull, best->distance, [&](std::uint32_t s) {
        const Vec* q = &tris[3 * s];
        Vec direction;
        if (hull.gap(q, best->distance, &direction, false) >= best->distance) return true;
        const Box qbox = triangle_box(q);
        walk_tree(part.bvh, [&](std::uint32_t n) { return boxes[n].distance(qbox) >= best->distance; },
                  [&](std::uint32_t ps) {
            if (triangle_box(&placed[3 * ps]).distance(qbox) < best->distance) consider(ps, s);
            return true;
        });
        return true;
    });
}

double RouteChecker::Impl::turn_lower_bound(TurnState& st, std::size_t pi, double cutoff) const {
    const Part& part = parts[pi];
    TurnState::PerPart& pp = st.parts[pi];
    if (bvh.nodes.empty() || part.bvh.nodes.empty()) return kInf;
    // The hull's sweep gap less delta (and the tolerance) bounds every pose's distance from below;
    // a part that is not its hull takes the larger bound of its own triangles where that one is
    // below the best so far.
    const ConvexSweep& sweep = st.sweep_of(part, pp);
    const double span = st.t1 - st.t0;
    const double grow = st.motion.deviation(pp.radius, span) + st.tol;
    double lowest = cutoff, reach = cutoff + grow;
    auto triangles_bound = [&](const Vec* q) {
        // The least of the part's triangles' bounds below `lowest` (else `lowest`); the nodes'
        // boxes are grown by delta and the tolerance only, so their distance is a lower bound.
        const Box qbox = triangle_box(q);
        double least = lowest;
        walk_tree(part.bvh, [&](std::uint32_t n) { return st.node_box(part, pp, n, 0.0).distance(qbox) >= least; },
                  [&](std::uint32_t ps) {
            const Vec* p = st.placed(part, pp, ps);
            const double g = st.motion.deviation(pp.tri_radius[ps], span) + st.tol;
            const double box_bound = swept_box(p).inflated(g).distance(qbox);
            if (box_bound < least) least = std::min(least, std::max({box_bound, hull_gap(p, q, least + g) - g, 0.0}));
            return true;
        });
        return least;
    };
    walk_near(bvh, sweep, reach, [&](std::uint32_t s) {
        const Vec* q = &tris[3 * s];
        double bound = std::max(TurnState::sweep_gap(pp, s, q, reach) - grow, 0.0);
        if (!pp.convex && bound < lowest) bound = std::max(bound, triangles_bound(q));
        lowest = std::min(lowest, bound);
        reach = lowest + grow;
        return true;
    });
    return lowest;
}

void RouteChecker::Impl::turn_clearance(const LegMotion& motion, LegReport* leg) const {
    // Branch and bound over sub-intervals: the best distance found at exact poses is an upper
    // bound of the minimum, each interval's hull bound a lower bound; intervals whose lower bound
    // cannot improve the best by more than 1e-6 of it are dropped, the lowest one is split next.
    Nearest best;
    auto sample = [&](double t) {
        const Pose pose = motion.at(t);
        for (std::size_t pi = 0; pi < parts.size(); ++pi) posed_nearest(pi, pose, t, &best);
    };
    // Exact poses first, so that the bounds prune from the start.
    constexpr int kFirstIntervals = 16;
    for (int k = 0; k <= kFirstIntervals; ++k) sample(k == kFirstIntervals ? 1.0 : static_cast<double>(k) / kFirstIntervals);
    TurnState st(motion);
    turn_prepare(st);
    auto bound = [&](double t0, double t1) {
        turn_interval(st, t0, t1);
        double lowest = best.distance;
        for (std::size_t pi = 0; pi < parts.size(); ++pi) lowest = std::min(lowest, turn_lower_bound(st, pi, lowest));
        return lowest;
    };
    auto settled = [&](double lower) { return lower * (1.0 + 1e-6) >= best.distance; };
    // (lower bound, t0, t1), lowest bound on top.
    std::vector<std::tuple<double, double, double>> heap;
    auto push = [&](double t0, double t1) {
        const double lower = bound(t0, t1);
        if (settled(lower)) return;
        heap.emplace_back(lower, t0, t1);
        std::push_heap(heap.begin(), heap.end(), std::greater<>());
    };
    for (int k = 0; k < kFirstIntervals; ++k) {
        push(static_cast<double>(k) / kFirstIntervals, k + 1 == kFirstIntervals ? 1.0 : static_cast<double>(k + 1) / kFirstIntervals);
    }
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), std::greater<>());
        const auto [lower, t0, t1] = heap.back();
        heap.pop_back();
        if (settled(lower)) break;
        if (t1 - t0 <= kTurnStep) continue;  // as fine as the bounds go: the best stands
        const double mid = 0.5 * (t0 + t1);
        sample(mid);
        push(t0, mid);
        push(mid, t1);
    }
    leg->clearance = best.distance;
    leg->obstacle = best.obstacle;
    leg->triangle = best.triangle;
    leg->part = best.part;
    leg->fraction_lo = leg->fraction_hi = best.obstacle >= 0 ? best.fraction : 0.0;
    const Pose pose = motion.at(leg->fraction_lo);
    const Quat q = motion.orientation(leg->fraction_lo);
    leg->position[0] = pose.offset.x, leg->position[1] = pose.offset.y, leg->position[2] = pose.offset.z;
    leg->rotation[0] = q.w, leg->rotation[1] = q.x, leg->rotation[2] = q.y, leg->rotation[3] = q.z;
}

double RouteChecker::Impl::turn_guess(TurnState& st) const {
    if (!st.hint) return -1.0;
    // The failing pair's points at t0 and at t1: a convex part's hull points, else the part
    // triangle's vertices.
    const Vec* at0;
    const Vec* at1;
    int count;
    if (st.whole_part) {
        const std::vector<Vec>& points = st.parts[st.part].sweep.points;
        count = static_cast<int>(points.size() / 2);
        at0 = points.data();
        at1 = at0 + count;
    } else {
        at0 = st.placed(parts[st.part], st.parts[st.part], st.part_slot);
        at1 = at0 + 3;
        count = 3;
    }
    const Vec* q = &tris[3 * st.slot];
    // Their gap along the direction that separates them at t0, at both ends, interpolated.
    const Vec n = hull_closest_direction(at0, count, q);
    const double len = glm::length(n);
    if (!(len > 0.0) || !std::isfinite(len)) return -1.0;
    auto gap = [&](const Vec* a) {
        double lo = kInf;
        for (int k = 0; k < count; ++k) lo = std::min(lo, glm::dot(n, a[k]));
        return (lo - std::max({glm::dot(n, q[0]), glm::dot(n, q[1]), glm::dot(n, q[2])})) / len - margin;
    };
    const double h0 = gap(at0), h1 = gap(at1);
    if (!(h0 > 0.0 && h1 < 0.0)) return -1.0;
    return st.t0 + (st.t1 - st.t0) * (h0 / (h0 - h1));
}

LegReport RouteChecker::Impl::check_turning_leg(const LegMotion& motion, const RouteOptions& options) const {
    LegReport leg;
    auto set_pose = [&](double t) {
        const Pose pose = motion.at(t);
        const Quat q = motion.orientation(t);
        leg.position[0] = pose.offset.x, leg.position[1] = pose.offset.y, leg.position[2] = pose.offset.z;
        leg.rotation[0] = q.w, leg.rotation[1] = q.x, leg.rotation[2] = q.y, leg.rotation[3] = q.z;
    };
    auto touch_at = [&](const Pose& pose, Found* found) {
        for (std::size_t pi = 0; pi < parts.size(); ++pi) {
            if (posed_touch(pi, pose, found)) return true;
        }
        return false;
    };

    Found found;
    const Pose start = motion.at(0.0);
    if (touch_at(start, &found)) {
        leg.status = LegStatus::StartOverlap;
        leg.fraction_lo = leg.fraction_hi = 0.0;
        set_pose(0.0);
        leg.clearance = found.containment ? 0.0 : placed_pair_distance(found.part, found.part_slot, found.slot, start);
    } else {
        TurnState st(motion);
        turn_prepare(st);
        double lo = 0.0;
        std::vector<std::pair<double, double>> intervals{{0.0, 1.0}};
        while (!intervals.empty()) {
            const auto [t0, t1] = intervals.back();
            intervals.pop_back();
            turn_interval(st, t0, t1);
            bool clear = true;
            for (std::size_t pi = 0; pi < parts.size() && clear; ++pi) clear = turn_certify(st, pi);
            if (clear) {
                lo = t1;
                continue;
            }
            if (t1 - t0 > kTurnStep) {
                // Around where the pair that failed seems to meet, a window of 1/32 of the
                // interval: when the guess is good the search skips five halvings; when it is not,
                // the pieces are searched as any other.
                const double w = (t1 - t0) * kGuessWindow, guess = t1 - t0 > kGuessWidest ? turn_guess(st) : -1.0;
                if (guess - w > t0 && guess + w < t1) {
                    intervals.emplace_back(guess + w, t1);
                    intervals.emplace_back(guess - w, guess + w);
                    intervals.emplace_back(t0, guess - w);
                    continue;
                }
                const double mid = 0.5 * (t0 + t1);
                intervals.emplace_back(mid, t1);
                intervals.emplace_back(t0, mid);
                continue;
            }
            // Uncertain at the finest step: a pose in contact at its end, or a little further.
            leg.status = LegStatus::Hit;
            leg.fraction_lo = lo;
            bool touch = false;
            for (int k = 0; k <= kTurnLookAhead && !touch; ++k) {
                const double t = std::min(1.0, t1 + k * kTurnStep);
                const Pose pose = motion.at(t);
                Found f;
                if (touch_at(pose, &f)) {
                    touch = true;
                    found = f;
                    leg.fraction_hi = t;
                    leg.clearance = f.containment ? 0.0 : std::min(margin, placed_pair_distance(f.part, f.part_slot, f.slot, pose));
                }
                if (t == 1.0) break;
            }
            if (!touch) {
                leg.grazing = true;
                leg.fraction_hi = t1;
                if (st.whole_part) st.part_slot = nearest_part_slot(st.part, st.slot, motion.at(t1));
                found.part = static_cast<std::int64_t>(st.part);
                found.part_slot = st.part_slot;
                found.slot = st.slot;
                found.obstacle = tri_obstacle[st.slot];
                found.triangle = tri_index[st.slot];
                leg.clearance = placed_pair_distance(st.part, st.part_slot, st.slot, motion.at(t1));
            }
            found.found = true;
            set_pose(lo);
            break;
        }
    }
    if (found.found || leg.status == LegStatus::StartOverlap) {
        leg.obstacle = found.obstacle;
        leg.triangle = found.triangle;
        leg.part = found.part;
    } else if (options.clearance) {
        turn_clearance(motion, &leg);
    } else {
        set_pose(0.0);
    }
    if (options.samples > 0) {
        for (std::uint32_t k = 0; k <= options.samples; ++k) {
            const double t = k == options.samples ? 1.0 : static_cast<double>(k) / options.samples;
            Found f;
            if (touch_at(motion.at(t), &f)) {
                leg.sampled_hit = true;
                leg.sampled_fraction = t;
                break;
            }
        }
    }
    return leg;
}

}  // namespace hullkit
