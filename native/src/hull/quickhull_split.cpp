// Quickhull on threads by split and join (quickhull_split_faces; see quickhull.cpp for the serial
// algorithm).
//
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
//
// The pieces of the serial quickhull it uses (the planes, the surface, run_quickhull) are in
// quickhull_internal.hpp.
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
#include "quickhull_internal.hpp"

namespace hullkit::detail {
namespace quickhull_detail {
namespace {

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

/// The distinct corners of a surface's triangles, ascending; `point_count` bounds the indices.
std::vector<Index> corners_of(const Surface& surface, std::size_t point_count) {
    std::vector<std::uint8_t> used(point_count, 0);
    for (Index v : surface.triangles) used[v] = 1;
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
    /// vertex *from leaves (updated to a half-edge out of where the climb ended: the first vertex
    /// found certainly above, or the top). Unsure when rounding leaves it open: then the caller
    /// asks exhaustively.
    Verdict any_above(const Plane& plane, Index* from) const {
        Index h = *from;
        bool certain = false;
        for (;;) {
            // Move to the neighbour certainly highest along the rounded normal n; stop where no
            // neighbour is certainly higher (the rounding of n . (w - v) is below 8u of its
            // permanent, so `slack` = 2^-50 of it is safe).
            const double* p = points_[vertex(h)];
            if (height(plane, p) > plane.bound) {  // certainly above (side_of's first test): done
                *from = h;
                return Verdict::Above;
            }
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
    if (!run_quickhull(local, simplex, ids, copy, surface, error, 1, &xyz)) return false;
    for (Index& v : surface.triangles) v = members[ids[v]];
    return true;
}

/// Marks the triangles of `surface` that some vertex of `other` (the other half's hull) lies
/// strictly above, and lists them in `found`: by climbing the other hull from one triangle's
/// answer to the next, and where rounding leaves that open, by a box tree over the other hull's
/// vertices (built on first need). The dirty triangles are connected, so the search starts from
/// one of them and only the dirty ones and their neighbours are asked. False if no triangle has
/// `other`'s first vertex above it, which cannot happen for halves strictly apart.
bool mark_dirty(PointSpan points, const Surface& surface, const Surface& other, double extent,
                std::vector<std::uint8_t>& dirty, std::vector<std::size_t>& found) {
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
    // A climb starts where its dirty neighbour's ended (a vertex above that triangle's plane),
    // or at the top found for the last clean triangle, whichever is higher above this plane: the
    // clean ones ring the dirty region, and a clean triangle's top is near its clean
    // neighbours'. (Measured on a sphere of 1e6 points: 15 000 steps, from 96 000 with every
    // climb going to the top from its neighbour's.)
    Index last_clean = kNone;
    for (std::size_t q = 0; q < queue.size(); ++q) {
        const auto [t, from] = queue[q];
        for (int k = 0; k < 3; ++k) {
            const std::size_t u = surface.twins[3 * t + k] / 3;
            if (seen[u]) continue;
            seen[u] = 1;
            const Plane p = plane(u);
            Index start = from;
            if (last_clean != kNone &&
                height(p, points[climber.vertex(last_clean)]) > height(p, points[climber.vertex(from)])) {
                start = last_clean;
            }
            if (above(p, &start)) {
                dirty[u] = 1;
                queue.emplace_back(u, start);
            } else {
                last_clean = start;
            }
        }
    }
    found.clear();
    found.reserve(queue.size());
    for (const auto& entry : queue) found.push_back(entry.first);
    return true;
}

/// Joins the hulls of two halves that lie strictly on either side of a plane (indices into
/// `points`) into the hull of their union. False when it cannot (the caller falls back). With
/// `pairs`, the result's coplanar neighbours go there and out's twins and flags stay empty (what
/// the last join's caller needs); else they are in `out`. The passes over each half's triangles
/// run on a thread per half (they write disjoint rows of `out`).
bool join(PointSpan points, const Surface (&half)[2], double extent, unsigned threads, Surface& out,
          std::vector<CoplanarPair>* pairs) {
    std::vector<std::uint8_t> dirty[2];
    std::vector<std::size_t> dirty_list[2];
    bool found[2] = {false, false};
    parallel_for(threads, 2, [&](std::size_t s) {
        found[s] = mark_dirty(points, half[s], half[1 - s], extent, dirty[s], dirty_list[s]);
    });
    if (!found[0] || !found[1]) return false;

    // The seam: the corners of the dirty triangles of both halves (apart, so no repeats), and
    // their hull.
    std::vector<Index> seam;
    for (int s = 0; s < 2; ++s) {
        for (std::size_t t : dirty_list[s]) seam.insert(seam.end(), &half[s].triangles[3 * t], &half[s].triangles[3 * t] + 3);
    }
    std::sort(seam.begin(), seam.end());
    seam.erase(std::unique(seam.begin(), seam.end()), seam.end());
    Surface cap;
    if (!member_surface(points, seam, cap)) return false;
    std::unordered_map<std::uint64_t, Index> cap_edge;  // directed edge u -> v: its half-edge in cap
    cap_edge.reserve(3 * cap.size());
    for (std::size_t h = 0; h < cap.triangles.size(); ++h) {
        const std::size_t t = h / 3;
        const Index u = cap.triangles[h], v = cap.triangles[3 * t + (h + 1) % 3];
        cap_edge.emplace(std::uint64_t{u} << 32 | v, static_cast<Index>(h));
    }

    // The kept triangles: the clean ones of half 0, of half 1, then the cap's between the rims.
    // Each half, on its own thread, numbers its clean triangles and writes their rows; a rim
    // edge (a clean triangle's edge whose neighbour is dirty) is left open and listed with the
    // cap half-edge that is its reverse, whose triangle lies between the rims. Each half marks
    // its corners in its own array (the halves share no point), for the count of vertices.
    const bool links = pairs == nullptr;
    const Index base[2] = {0, static_cast<Index>(half[0].size() - dirty_list[0].size())};
    const std::size_t clean = base[1] + (half[1].size() - dirty_list[1].size());
    out.triangles.resize(3 * (clean + cap.size()));
    out.twins.resize(links ? 3 * (clean + cap.size()) : 0);
    out.flat.resize(links ? 3 * (clean + cap.size()) : 0);
    std::vector<std::pair<Index, Index>> rims[2];  // (cap half-edge, the clean half-edge of out)
    std::vector<CoplanarPair> half_pairs[2];
    std::vector<std::uint8_t> corner[2];
    bool rims_found[2] = {true, true};
    parallel_for(threads, 2, [&](std::size_t s) {
        const Surface& surface = half[s];
        const std::vector<std::uint8_t>& is_dirty = dirty[s];
        std::vector<Index> number(surface.size(), kNone);
        Index next = base[s];
        for (std::size_t t = 0; t < surface.size(); ++t) {
            if (!is_dirty[t]) number[t] = next++;
        }
        corner[s].assign(points.count, 0);
        for (std::size_t t = 0; t < surface.size(); ++t) {
            if (is_dirty[t]) continue;
            const std::size_t at = 3 * std::size_t{number[t]};
            for (std::size_t k = 0; k < 3; ++k) {
                const std::size_t h = 3 * t + k;
                const Index u = surface.triangles[h];
                out.triangles[at + k] = u;
                corner[s][u] = 1;
                const Index other = surface.twins[h];
                if (is_dirty[other / 3]) {  // a rim edge: linked from the cap below
                    const Index v = surface.triangles[3 * t + (k + 1) % 3];
                    const auto it = cap_edge.find(std::uint64_t{v} << 32 | u);
                    if (it == cap_edge.end()) {
                        rims_found[s] = false;
                        return;
                    }
                    rims[s].emplace_back(it->second, static_cast<Index>(at + k));
                    if (links) {
                        out.twins[at + k] = kNone;
                        out.flat[at + k] = 0;
                    }
                    continue;
                }
                if (links) {
                    out.twins[at + k] = 3 * number[other / 3] + other % 3;
                    out.flat[at + k] = surface.flat[h];
                } else if (surface.flat[h] && number[t] < number[other / 3]) {
                    half_pairs[s].push_back({number[t], number[other / 3]});
                }
            }
        }
    });
    if (!rims_found[0] || !rims_found[1]) return false;
    std::vector<Index> rim_of_cap(cap.triangles.size(), kNone);  // cap half-edge -> the clean half-edge of out
    std::vector<std::uint8_t> in_bridge(cap.size(), 0);
    std::vector<std::size_t> queue;
    for (int s = 0; s < 2; ++s) {
        for (const auto& [cap_half_edge, clean_half_edge] : rims[s]) {
            if (rim_of_cap[cap_half_edge] != kNone) return false;
            rim_of_cap[cap_half_edge] = clean_half_edge;
            const std::size_t g = cap_half_edge / 3;
            if (!in_bridge[g]) {
                in_bridge[g] = 1;
                queue.push_back(g);
            }
        }
    }
    Index kept = static_cast<Index>(clean);
    if (queue.empty()) {  // nothing clean on either side: the hull is the cap itself
        if (kept != 0) return false;
        std::fill(in_bridge.begin(), in_bridge.end(), 1);
        for (std::size_t g = 0; g < cap.size(); ++g) queue.push_back(g);
    }
    // The cap's triangles between the rims: a search from the rims' cap edges, never crossing one.
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
    // The cap's rows. The result is closed: the halves are, their clean triangles keep their
    // neighbours, each rim edge has its own cap half-edge (checked above), and each other
    // half-edge of the bridge has a twin in the bridge that is no rim's (checked here).
    std::vector<CoplanarPair> cap_pairs;
    std::vector<Index> cap_only;  // bridge corners that no clean triangle has
    for (std::size_t g = 0; g < cap.size(); ++g) {
        if (!in_bridge[g]) continue;
        const std::size_t at = 3 * std::size_t{cap_number[g]};
        for (int k = 0; k < 3; ++k) {
            const std::size_t h = 3 * g + k;
            out.triangles[at + k] = cap.triangles[h];
            if (!corner[0][cap.triangles[h]] && !corner[1][cap.triangles[h]]) cap_only.push_back(cap.triangles[h]);
            if (const Index rim = rim_of_cap[h]; rim != kNone) {
                // Across a rim: coplanar when the cap triangle's far corner is in the clean
                // triangle's plane (exactly).
                const Index* clean_corners = &out.triangles[3 * (rim / 3)];
                const Index apex = cap.triangles[3 * g + (k + 2) % 3];
                const std::uint8_t flat =
                    orient3d(points[clean_corners[0]], points[clean_corners[1]], points[clean_corners[2]], points[apex]) == 0;
                if (links) {
                    out.twins[at + k] = rim;
                    out.twins[rim] = static_cast<Index>(at + k);
                    out.flat[at + k] = flat;
                    out.flat[rim] = flat;
                } else if (flat) {
                    cap_pairs.push_back({rim / 3, cap_number[g]});
                }
                continue;
            }
            const Index other = cap.twins[h];
            if (!in_bridge[other / 3] || rim_of_cap[other] != kNone) return false;
            if (links) {
                out.twins[at + k] = 3 * cap_number[other / 3] + other % 3;
                out.flat[at + k] = cap.flat[h];
            } else if (cap.flat[h] && cap_number[g] < cap_number[other / 3]) {
                cap_pairs.push_back({cap_number[g], cap_number[other / 3]});
            }
        }
    }
    out.triangles.resize(3 * std::size_t{kept});
    if (links) {
        out.twins.resize(3 * std::size_t{kept});
        out.flat.resize(3 * std::size_t{kept});
    } else {
        pairs->clear();
        for (const auto* list : {&half_pairs[0], &half_pairs[1], &cap_pairs}) pairs->insert(pairs->end(), list->begin(), list->end());
    }
    // And a sphere: V - E + F = 2.
    std::sort(cap_only.begin(), cap_only.end());
    cap_only.erase(std::unique(cap_only.begin(), cap_only.end()), cap_only.end());
    const std::size_t vertices = static_cast<std::size_t>(std::count(corner[0].begin(), corner[0].end(), 1)) +
                                 static_cast<std::size_t>(std::count(corner[1].begin(), corner[1].end(), 1)) + cap_only.size();
    const std::size_t faces = out.size(), edges = 3 * faces / 2;
    return vertices + faces == edges + 2;
}

/// The hull of `members` (ascending indices into `points`) as a surface, on up to `threads`
/// threads: split in two while there are threads to share and points to split, else quickhull.
/// With `pairs`, the coplanar neighbours go there and out's twins and flags may be left empty.
bool split_surface(PointSpan points, const std::vector<Index>& members, unsigned threads, double extent,
                   Surface& out, std::vector<CoplanarPair>* pairs = nullptr) {
    constexpr std::size_t kLeaf = std::size_t{1} << 14;
    auto whole = [&] {
        if (!member_surface(points, members, out)) return false;
        if (pairs) *pairs = coplanar_pairs(out);
        return true;
    };
    if (threads < 2 || members.size() < 2 * kLeaf) return whole();
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
    // The cut: the median of an evenly spread sample of the coordinates (close enough to
    // balance the halves; any cut that leaves both halves large enough gives the same hull).
    constexpr std::size_t kSample = std::size_t{1} << 12;
    const std::size_t stride = std::max<std::size_t>(1, members.size() / kSample);
    std::vector<double> values;
    values.reserve(members.size() / stride + 1);
    for (std::size_t k = 0; k < members.size(); k += stride) values.push_back(points[members[k]][axis]);
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    const double cut = *middle;  // below: the first half; at or above: the second
    std::vector<Index> part[2];
    part[0].reserve(members.size());  // the pages beyond a half's size are never touched
    part[1].reserve(members.size());
    for (Index i : members) part[points[i][axis] < cut ? 0 : 1].push_back(i);
    if (part[0].size() < kLeaf || part[1].size() < kLeaf) return whole();
    Surface half[2];
    bool ok[2] = {false, false};
    const unsigned shares[2] = {(threads + 1) / 2, threads / 2};
    parallel_for(2, 2, [&](std::size_t s) { ok[s] = split_surface(points, part[s], shares[s], extent, half[s]); });
    if (!ok[0] || !ok[1]) return false;
    return join(points, half, extent, threads, out, pairs);
}

}  // namespace
}  // namespace quickhull_detail

using quickhull_detail::Index;
using quickhull_detail::kNone;
using quickhull_detail::largest_span;
using quickhull_detail::split_surface;
using quickhull_detail::Surface;

bool quickhull_split_faces(PointSpan points, unsigned threads, Polygons& faces, double* volume, double* area) {
    if (points.count > kNone) return false;
    const double extent = largest_span(points);
    std::vector<Index> all(points.count);
    for (std::size_t i = 0; i < points.count; ++i) all[i] = static_cast<Index>(i);
    Surface surface;
    std::vector<CoplanarPair> pairs;
    if (!split_surface(points, all, threads, extent, surface, &pairs)) return false;
    faces = merge_coplanar_triangles(points, std::move(surface.triangles), pairs);
    canonical_order(faces, {}, threads);
    measure(points, faces, volume, area, threads);
    return true;
}

}  // namespace hullkit::detail
