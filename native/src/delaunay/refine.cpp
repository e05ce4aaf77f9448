// Delaunay refinement of a constrained triangulation (hullkit/constrained.hpp, QualityOptions):
// the domain to mesh is marked per triangle (region ids), then encroached segments are split and
// bad triangles get their circumcentres until nothing is left to do. Every decision that changes
// the mesh is an exact orient2d, incircle or sign of a dot product; the points themselves are
// computed in floating point (plain +, -, *, /, sqrt and a fixed cosine series: the same bits on
// every platform).
#include "refine.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "../exact/expansion.hpp"

namespace hullkit {
namespace constrained_detail {
namespace {

/// cos(x) for |x| <= 1 by its Taylor series (16 terms: exact to the last bit or so), with the
/// same operations everywhere (libm's cos may differ between platforms by an ulp).
double cosine(double x) {
    double term = 1.0, sum = 1.0;
    const double x2 = x * x;
    for (int k = 1; k <= 16; ++k) {
        term = -term * x2 / ((2.0 * k - 1.0) * (2.0 * k));
        sum += term;
    }
    return sum;
}

/// The exact sign of (a - w) . (b - w): negative when w is strictly inside the circle with a-b as
/// diameter (the angle a w b is obtuse).
int dot_sign(const double* a, const double* b, const double* w) {
    using namespace exact_detail;
    // In floating point first: each difference and product rounds by at most a unit roundoff, the
    // sum once more, so the computed value is within 4 (+ tiny) roundoffs of the products' sizes
    // of the exact one; 8 leaves room.
    const double p1 = (a[0] - w[0]) * (b[0] - w[0]), p2 = (a[1] - w[1]) * (b[1] - w[1]);
    const double size = std::fabs(p1) + std::fabs(p2), dot = p1 + p2, bound = 8 * kEpsilon * size;
    if (size > 0x1p-900) {  // no underflow in the products: the bound holds
        if (dot > bound) return 1;
        if (dot < -bound) return -1;
    }
    double ax[2], ay[2], bx[2], by[2], h[16];
    const int axl = exact_diff(a[0], w[0], ax), ayl = exact_diff(a[1], w[1], ay);
    const int bxl = exact_diff(b[0], w[0], bx), byl = exact_diff(b[1], w[1], by);
    for (int i = 0; i < ayl; ++i) ay[i] = -ay[i];
    // ax * bx - (-ay) * by
    return expansion_sign(exact_minor(axl, ax, bxl, bx, ayl, ay, byl, by, h), h);
}

double squared_distance(const double* a, const double* b) {
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    return dx * dx + dy * dy;
}

}  // namespace

void Refiner::flood(std::vector<std::uint32_t>& stack, std::uint32_t region) {
    while (!stack.empty()) {
        const std::uint32_t t = stack.back();
        stack.pop_back();
        for (std::uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
            if (m_.edge_[e] != 0) continue;
            const std::uint32_t u = m_.twin_[e] / 3;
            if (m_.is_ghost(u) || m_.region_[u] == region || m_.region_[u] == 0) continue;
            m_.region_[u] = region;
            stack.push_back(u);
        }
    }
}

void Refiner::seed_at(const double* p, std::uint32_t start, std::vector<std::uint32_t>& seeds) {
    const std::uint32_t t0 = m_.locate(p, start);
    if (m_.is_ghost(t0)) return;  // outside the hull: nothing
    for (std::uint32_t e = 3 * t0; e < 3 * t0 + 3; ++e) {
        const double* v = m_.pt(m_.vertex_[e]);
        if (v[0] == p[0] && v[1] == p[1]) {
            // On a corner: every triangle around it.
            const std::uint32_t first = e;
            std::uint32_t h = first;
            do {
                if (!m_.is_ghost(h / 3)) seeds.push_back(h / 3);
                h = m_.twin_[prev_edge(h)];
            } while (h != first);
            return;
        }
    }
    seeds.push_back(t0);
    for (std::uint32_t e = 3 * t0; e < 3 * t0 + 3; ++e) {
        if (m_.orient_at(m_.vertex_[e], m_.vertex_[next_edge(e)], p) == 0 && !m_.is_ghost(m_.twin_[e] / 3))
            seeds.push_back(m_.twin_[e] / 3);
    }
}

std::int64_t Refiner::mark_triangles(const std::vector<std::uint32_t>& corners) {
    mark_polygon(FillRule::EvenOdd);
    auto key = [](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (a > b) std::swap(a, b);
        if (b > c) std::swap(b, c);
        if (a > b) std::swap(a, b);
        return std::make_tuple(a, b, c);
    };
    using Key = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;
    std::vector<std::pair<Key, std::uint32_t>> wanted;
    wanted.reserve(corners.size() / 3);
    for (std::size_t k = 0; 3 * k + 2 < corners.size(); ++k)
        wanted.push_back({key(corners[3 * k], corners[3 * k + 1], corners[3 * k + 2]), static_cast<std::uint32_t>(k)});
    std::sort(wanted.begin(), wanted.end());
    std::vector<std::uint8_t> found(wanted.size(), 0);  // per triple k
    bool left_over = false;
    for (std::uint32_t t = 0; t < m_.region_.size(); ++t) {
        if (m_.region_[t] == 0) continue;
        const std::uint32_t* v = &m_.vertex_[3 * t];
        const Key own = key(v[0], v[1], v[2]);
        const auto at = std::lower_bound(wanted.begin(), wanted.end(), std::make_pair(own, std::uint32_t{0}));
        if (at == wanted.end() || at->first != own) {
            left_over = true;
            continue;
        }
        m_.region_[t] = kDomain + 1 + at->second;
        found[at->second] = 1;
    }
    const auto missing = std::find(found.begin(), found.end(), 0);
    if (missing != found.end()) return missing - found.begin();
    return left_over ? static_cast<std::int64_t>(wanted.size()) : -1;
}

std::uint32_t Refiner::alive_triangle() const {
    for (std::uint32_t t = 0; t < m_.vertex_.size() / 3; ++t)
        if (m_.vertex_[3 * t] != kDead) return t;
    return 0;
}

void Refiner::mark_polygon(FillRule fill) {
    m_.mark_inside(fill, kDomain);
}

void Refiner::mark_graph(bool exterior, const std::vector<double>& holes, const std::vector<double>& regions) {
    const std::uint32_t t_count = static_cast<std::uint32_t>(m_.vertex_.size() / 3);
    for (std::uint32_t t = 0; t < t_count; ++t)
        m_.region_[t] = m_.vertex_[3 * t] != kDead && !m_.is_ghost(t) ? kDomain : 0;
    std::vector<std::uint32_t> seeds, stack;
    auto remove = [&](std::uint32_t t) {
        if (m_.region_[t] != 0) m_.region_[t] = 0, stack.push_back(t);
    };
    if (exterior) {
        for (std::uint32_t e = 0; e < m_.vertex_.size(); ++e) {
            const std::uint32_t t = e / 3;
            if (m_.region_[t] != 0 && m_.edge_[e] == 0 && m_.is_ghost(m_.twin_[e] / 3)) remove(t);
        }
    }
    // Removing is flooding with region 0: everything reached without crossing a segment.
    flood(stack, 0);
    const std::uint32_t start = alive_triangle();  // where point location starts
    for (std::size_t h = 0; h + 1 < holes.size(); h += 2) {
        seeds.clear();
        seed_at(&holes[h], start, seeds);
        for (std::uint32_t t : seeds) remove(t);
        flood(stack, 0);
    }
    for (std::size_t r = 0; 2 * r + 1 < regions.size(); ++r) {
        seeds.clear();
        seed_at(&regions[2 * r], start, seeds);
        const std::uint32_t id = kDomain + 1 + static_cast<std::uint32_t>(r);
        for (std::uint32_t t : seeds) {
            if (m_.region_[t] != 0 && m_.region_[t] != id) m_.region_[t] = id, stack.push_back(t);
        }
        flood(stack, id);
    }
}

int Refiner::flaw(std::uint32_t t, int* shortest) const {
    const std::uint32_t* v = &m_.vertex_[3 * t];
    const double *a = m_.pt(v[0]), *b = m_.pt(v[1]), *c = m_.pt(v[2]);
    const double limit = area2_[m_.region_[t]];
    if (limit > 0) {
        const double area2 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if (area2 > limit) return kTooLarge;
    }
    if (unsuitable_) {
        // In the input's units (exact: a power of two), as the caller gave the points.
        const double ua[2] = {a[0] * unscale_, a[1] * unscale_}, ub[2] = {b[0] * unscale_, b[1] * unscale_},
                     uc[2] = {c[0] * unscale_, c[1] * unscale_};
        const double area = 0.5 * ((ub[0] - ua[0]) * (uc[1] - ua[1]) - (ub[1] - ua[1]) * (uc[0] - ua[0]));
        if (unsuitable_(ua, ub, uc, area)) return kTooLarge;
    }
    if (cos2_ >= 1.0) return kFine;
    // The smallest angle is opposite the shortest edge (edge k runs from corner k to k + 1).
    const double* p[3] = {a, b, c};
    double len[3];
    for (int k = 0; k < 3; ++k) len[k] = squared_distance(p[k], p[(k + 1) % 3]);
    int s = 0;
    if (len[1] < len[s]) s = 1;
    if (len[2] < len[s]) s = 2;
    const double *u = p[s], *w = p[(s + 2) % 3], *x = p[(s + 1) % 3];
    const double dot = (u[0] - w[0]) * (x[0] - w[0]) + (u[1] - w[1]) * (x[1] - w[1]);
    *shortest = s;
    // cos^2 of the angle at w against cos^2 of the bound (the angle is acute: dot > 0).
    return dot > 0 && dot * dot > cos2_ * len[(s + 2) % 3] * len[(s + 1) % 3] ? kSmallAngle : kFine;
}

bool Refiner::bad(std::uint32_t t, int kind, int s) const {
    // Below the resolution refinement works at, nothing is refined (see refine()).
    const std::uint32_t* v = &m_.vertex_[3 * t];
    if (kind != kFine && squared_distance(m_.pt(v[s]), m_.pt(v[(s + 1) % 3])) < tiny2_) return false;
    if (kind != kSmallAngle) return kind == kTooLarge;
    // The angle at w (opposite the shortest edge u-x) is small. Leave it when it is an input angle
    // (both its edges on segments) or the triangle sits between two points on segments at the
    // same distance from their common end (splitting it would start a cascade down the small
    // angle: Shewchuk's rule).
    const std::uint32_t e_in = 3 * t + (s + 1) % 3, e_out = 3 * t + (s + 2) % 3;  // x -> w, w -> u
    if (m_.edge_[e_in] != 0 && m_.edge_[e_out] != 0) return false;
    const std::uint32_t vu = v[s], vx = v[(s + 1) % 3];
    if (vu < on_segment_.size() && vx < on_segment_.size()) {
        const std::uint32_t s1 = on_segment_[vu], s2 = on_segment_[vx];
        if (s1 != kGhost && s2 != kGhost && s1 != s2) {
            const Parent &p1 = parents_[s1], &p2 = parents_[s2];
            std::uint32_t join = kGhost;
            if (p1.a == p2.a || p1.a == p2.b) join = p1.a;
            else if (p1.b == p2.a || p1.b == p2.b) join = p1.b;
            if (join != kGhost) {
                const double d1 = squared_distance(m_.pt(join), m_.pt(vu)), d2 = squared_distance(m_.pt(join), m_.pt(vx));
                if (d1 < 1.001 * d2 && d2 < 1.001 * d1) return false;
            }
        }
    }
    return true;
}

bool Refiner::encroached_from(std::uint32_t h) const {
    const std::uint32_t t = h / 3;
    if (m_.is_ghost(t) || (!conforming_ && m_.region_[t] == 0)) return false;
    return dot_sign(m_.pt(m_.vertex_[h]), m_.pt(m_.vertex_[next_edge(h)]), m_.pt(m_.vertex_[prev_edge(h)])) < 0;
}

bool Refiner::encroached(std::uint32_t e) const { return encroached_from(e) || encroached_from(m_.twin_[e]); }

void Refiner::retest() {
    for (std::uint32_t t : m_.touched_) {
        const std::uint32_t* v = &m_.vertex_[3 * t];
        if (v[0] == kDead || m_.is_ghost(t)) continue;
        if (m_.region_[t] != 0) {
            int s = 0;
            const int kind = flaw(t, &s);
            if (kind != kFine) {
                const BadTriangle item{t, v[0], v[1], v[2], kind};
                flawed_.push_back(item);
                if (bad(t, kind, s)) bad_.push_back(item);
            }
        }
        // t's segments from t's side only; the other side is tested with the triangle there
        // (every triangle is retested when it gets new corners).
        for (std::uint32_t e = 3 * t; e < 3 * t + 3; ++e)
            if (m_.edge_[e] != 0 && !kept_whole(e) && encroached_from(e)) split_.push_back({m_.vertex_[e], m_.vertex_[next_edge(e)], false});
    }
    m_.touched_.clear();
}

bool Refiner::count_point() {
    ++steiner_count;
    if (cap_ != 0 && steiner_count > cap_) {
        error = "quality refinement added " + std::to_string(cap_) +
                " points without meeting the bounds (max_steiner_points; a smaller min_angle or a larger max_area "
                "needs fewer)";
        return false;
    }
    return true;
}

bool Refiner::kept_whole(std::uint32_t e) const {
    if (keep_segments_ == 0 || m_.edge_[e] == 0) return false;
    if (keep_segments_ >= 2) return true;
    const auto outside = [&](std::uint32_t t) { return m_.is_ghost(t) || m_.region_[t] == 0; };
    return outside(e / 3) || outside(m_.twin_[e] / 3);
}

bool Refiner::split_segment(std::uint32_t e) {
    const std::uint32_t a = m_.vertex_[e], b = m_.vertex_[next_edge(e)];
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    if (m_.edge_[e] == 0 || kept_whole(e) || unsplittable_.count(key)) return false;
    const Cdt::Record record = m_.records_[m_.edge_[e]];
    const Parent& parent = parents_[record.parent];
    const double *pa = m_.pt(a), *pb = m_.pt(b);
    // Where to split: the middle, or (one end being an end of the whole segment, the other a point
    // added on it) at the power of two nearest half the length from that end: points near a
    // segment's end then sit on circles shared by every segment there (concentric shells).
    const bool a_end = a == parent.a || a == parent.b, b_end = b == parent.a || b == parent.b;
    double m[2];
    if (a_end != b_end) {
        const double* from = a_end ? pa : pb;
        const double* to = a_end ? pb : pa;
        const double length = std::sqrt(squared_distance(from, to));
        int exponent = 0;
        std::frexp(length / 2, &exponent);  // length / 2 in [2^(exponent-1), 2^exponent)
        double shell = std::ldexp(1.0, exponent - 1);
        if (length / 2 >= 1.5 * shell) shell *= 2;
        const double f = shell / length;  // in [1/3, 2/3]
        m[0] = from[0] + f * (to[0] - from[0]);
        m[1] = from[1] + f * (to[1] - from[1]);
    } else {
        m[0] = pa[0] + 0.5 * (pb[0] - pa[0]);
        m[1] = pa[1] + 0.5 * (pb[1] - pa[1]);
    }
    m_.representable(m);
    // Both new triangles on each side must turn the right way (a point within rounding of the
    // segment always does unless a third point is as close to it); if not, or the segment is too
    // short to hold a point between its ends, it stays whole.
    const std::uint32_t f = m_.twin_[e];
    const std::uint32_t c = m_.vertex_[prev_edge(e)], d = m_.vertex_[prev_edge(f)];
    const bool fits = squared_distance(pa, pb) >= 4 * tiny2_ && !(m[0] == pa[0] && m[1] == pa[1]) && !(m[0] == pb[0] && m[1] == pb[1]) &&
                      (c == kGhost || (m_.orient_at(a, c, m) < 0 && m_.orient_at(b, c, m) > 0)) &&
                      (d == kGhost || (m_.orient_at(b, d, m) < 0 && m_.orient_at(a, d, m) > 0)) &&
                      std::isfinite(m[0]) && std::isfinite(m[1]);
    if (!fits) {
        unsplittable_.insert(key);
        return false;
    }
    if (!count_point()) return false;
    const std::int32_t wind = m_.wind(e);
    const std::uint32_t t1 = e / 3, t2 = f / 3;
    const std::uint32_t o_bc = m_.twin_[next_edge(e)], o_ca = m_.twin_[prev_edge(e)];
    const std::uint32_t o_ad = m_.twin_[next_edge(f)], o_db = m_.twin_[prev_edge(f)];
    const std::uint32_t r_bc = m_.edge_[next_edge(e)], r_ca = m_.edge_[prev_edge(e)];
    const std::uint32_t r_ad = m_.edge_[next_edge(f)], r_db = m_.edge_[prev_edge(f)];
    const std::uint32_t q = static_cast<std::uint32_t>(m_.xy_.size() / 2);
    m_.xy_.push_back(m[0]), m_.xy_.push_back(m[1]);
    m_.out_.push_back(kGhost);
    on_segment_.resize(q + 1, kGhost);
    on_segment_[q] = record.parent;
    // (a, b, c) becomes (a, q, c) and (q, b, c); (b, a, d) becomes (b, q, d) and (q, a, d).
    const std::uint32_t t3 = m_.add_triangle(q, b, c), t4 = m_.add_triangle(q, a, d);
    m_.region_[t3] = m_.region_[t1], m_.region_[t4] = m_.region_[t2];
    auto set = [&](std::uint32_t t, std::uint32_t x, std::uint32_t y, std::uint32_t z) {
        m_.vertex_[3 * t] = x, m_.vertex_[3 * t + 1] = y, m_.vertex_[3 * t + 2] = z;
        m_.edge_[3 * t] = m_.edge_[3 * t + 1] = m_.edge_[3 * t + 2] = 0;
    };
    set(t1, a, q, c);
    set(t2, b, q, d);
    auto outer = [&](std::uint32_t h, std::uint32_t outside, std::uint32_t r) {
        m_.link(h, outside);
        m_.edge_[h] = r;
    };
    outer(3 * t1 + 2, o_ca, r_ca);
    outer(3 * t3 + 1, o_bc, r_bc);
    outer(3 * t2 + 2, o_db, r_db);
    outer(3 * t4 + 1, o_ad, r_ad);
    m_.link(3 * t1, 3 * t4);          // a -> q, q -> a
    m_.link(3 * t3, 3 * t2);          // q -> b, b -> q
    m_.link(3 * t1 + 1, 3 * t3 + 2);  // q -> c, c -> q
    m_.link(3 * t2 + 1, 3 * t4 + 2);  // q -> d, d -> q
    m_.out_[a] = 3 * t1, m_.out_[q] = 3 * t1 + 1, m_.out_[b] = 3 * t2;
    if (c != kGhost) m_.out_[c] = 3 * t1 + 2;
    if (d != kGhost) m_.out_[d] = 3 * t2 + 2;
    m_.touched_.push_back(t1), m_.touched_.push_back(t2);
    // The two halves keep the segment's records (a new one each) and its parent.
    m_.set_flags(3 * t1, wind, record.count, record.origin);
    m_.set_flags(3 * t3, wind, record.count, record.origin);
    m_.records_[m_.edge_[3 * t1]].parent = record.parent;
    m_.records_[m_.edge_[3 * t3]].parent = record.parent;
    // Lawson's flips from the four outer edges and, as q may lie off the segment's line (then
    // outside one old triangle's circumcircle), from the two new spokes too.
    for (const Cdt::Edge edge : {Cdt::Edge{c, a}, Cdt::Edge{b, c}, Cdt::Edge{d, b}, Cdt::Edge{a, d}, Cdt::Edge{q, c}, Cdt::Edge{q, d}})
        if (edge.from != kGhost && edge.to != kGhost) m_.fresh_.push_back(edge);
    m_.legalize();
    return true;
}

std::uint32_t Refiner::walk(const double* p, std::uint32_t t, std::uint32_t* wall) {
    // A visibility walk that never crosses a segment: blocked when p is beyond segments only.
    const std::size_t limit = 4 * m_.vertex_.size() + 64;
    for (std::size_t step = 0; step < limit; ++step) {
        m_.seed_ = m_.seed_ * 1103515245u + 12345u;
        const std::uint32_t r = (m_.seed_ >> 16) % 3;
        std::uint32_t cross = kGhost, blocked = kGhost;
        for (std::uint32_t k = 0; k < 3 && cross == kGhost; ++k) {
            const std::uint32_t e = 3 * t + (r + k) % 3;
            if (m_.orient_at(m_.vertex_[e], m_.vertex_[next_edge(e)], p) >= 0) continue;
            if (m_.edge_[e] == 0 && !m_.is_ghost(m_.twin_[e] / 3)) cross = e;
            else if (blocked == kGhost) blocked = e;
        }
        if (cross == kGhost) {
            *wall = blocked;
            return blocked == kGhost ? t : kGhost;
        }
        t = m_.twin_[cross] / 3;
    }
    *wall = kGhost;
    return kGhost;
}

bool Refiner::split_triangle(const BadTriangle& item) {
    const std::uint32_t t = item.t;
    // The shortest edge a-b (corners k, k + 1), the third corner c.
    const std::uint32_t* v = &m_.vertex_[3 * t];
    const double* p[3] = {m_.pt(v[0]), m_.pt(v[1]), m_.pt(v[2])};
    int k = 0;
    double shortest = squared_distance(p[0], p[1]);
    for (int j = 1; j < 3; ++j) {
        const double l = squared_distance(p[j], p[(j + 1) % 3]);
        if (l < shortest) shortest = l, k = j;
    }
    const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
    // The circumcentre, from a: (|ab|^2 (ac)perp - |ac|^2 (ab)perp) / (2 ab x ac).
    const double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    const double lb = bx * bx + by * by, lc = cx * cx + cy * cy;
    const double den = 2 * (bx * cy - by * cx);
    double centre[2] = {(cy * lb - by * lc) / den, (bx * lc - cx * lb) / den};  // from a
    // Ungor's off-centre: when the circumcentre is farther from the shortest edge's middle than
    // the apex of the isosceles triangle on that edge with the angle bound at its apex, that apex
    // instead (slightly nearer, 0.95 of the way): fewer points for the same bound.
    if (off_centre_ > 0) {
        const double dx = centre[0] - bx / 2, dy = centre[1] - by / 2;
        const double reach = std::sqrt(dx * dx + dy * dy), limit = off_centre_ * std::sqrt(lb);
        if (reach > limit) centre[0] = bx / 2 + dx * (limit / reach), centre[1] = by / 2 + dy * (limit / reach);
    }
    centre[0] += a[0], centre[1] += a[1];
    m_.representable(centre);
    if (!std::isfinite(centre[0]) || !std::isfinite(centre[1])) return true;
    std::uint32_t wall = kGhost;
    std::uint32_t at = walk(centre, t, &wall);
    if (at == kGhost && wall != kGhost && kept_whole(wall)) {
        // Beyond a segment kept whole (keep_segments): a triangle too large takes its centroid
        // (inside it, so the area bound is still met); one with only a small angle is left.
        if (item.kind != kTooLarge) return true;
        centre[0] = (p[0][0] + p[1][0] + p[2][0]) / 3, centre[1] = (p[0][1] + p[1][1] + p[2][1]) / 3;
        m_.representable(centre);
        at = walk(centre, t, &wall);
        if (at == kGhost) return true;  // (rounding put it across an edge onto a segment: left)
    }
    if (at == kGhost) {
        // The centre is beyond a segment: that segment is split instead (Ruppert).
        if (wall != kGhost && split_segment(wall)) bad_.push_back(item);
        return error.empty();
    }
    for (std::uint32_t e = 3 * at; e < 3 * at + 3; ++e) {
        const double* p = m_.pt(m_.vertex_[e]);
        if (p[0] == centre[0] && p[1] == centre[1]) return true;  // no room: left as it is
    }
    // The segments the new point would encroach: those on the boundary of its cavity (the
    // triangles whose circumcircle holds it, reached without crossing a segment).
    // Gathered in the mesh's own cavity list, which insert_at fills as it is.
    std::vector<std::uint32_t>& cavity = m_.cavity_;
    cavity.assign(1, at);
    m_.new_mark();
    m_.mark(at);
    walls_.clear();
    for (std::size_t k = 0; k < cavity.size(); ++k) {
        for (std::uint32_t e = 3 * cavity[k]; e < 3 * cavity[k] + 3; ++e) {
            if (m_.edge_[e] != 0) {
                walls_.push_back(e);
                continue;
            }
            const std::uint32_t u = m_.twin_[e] / 3;
            if (!m_.marked(u) && m_.conflicts(u, centre)) cavity.push_back(u), m_.mark(u);
        }
    }
    // The encroached ones, by their ends (splitting one changes the mesh's half-edges).
    encroached_.clear();
    bool deferred = false, on_wall = false;
    for (std::uint32_t e : walls_) {
        const std::uint32_t u = m_.vertex_[e], v = m_.vertex_[next_edge(e)];
        if (dot_sign(m_.pt(u), m_.pt(v), centre) >= 0) continue;
        if (m_.orient_at(u, v, centre) == 0) on_wall = true;
        encroached_.push_back({u, v});
    }
    for (const Cdt::Edge& wall : encroached_) {
        const std::uint32_t e = m_.find_edge(wall.from, wall.to);
        if (e == kGhost || m_.edge_[e] == 0) continue;
        if (split_segment(e)) deferred = true;
        else if (!error.empty()) return false;
    }
    if (deferred) {
        bad_.push_back(item);
        return true;
    }
    if (on_wall) return true;  // on a segment that cannot be split: left as it is
    if (!count_point()) return false;
    m_.insert_at(centre, at, true);  // p's whole conflict region, filled as it is (Bowyer-Watson)
    if (m_.internal_error_) {
        error = "internal error: a refinement point could not be inserted (please report this input)";
        return false;
    }
    on_segment_.resize(m_.xy_.size() / 2, kGhost);
    return true;
}

bool Refiner::refine(const QualityOptions& options, std::vector<double> area2, int exponent) {
    area2_ = std::move(area2);
    unsuitable_ = options.unsuitable;
    unscale_ = std::ldexp(1.0, -exponent);
    conforming_ = options.conforming;
    keep_segments_ = options.keep_segments;
    const double pi = 3.14159265358979323846;
    const double cosine_bound = options.min_angle > 0 ? cosine(options.min_angle * (pi / 180)) : 1.0;
    cos2_ = cosine_bound * cosine_bound;
    // The apex of the isosceles triangle with the bound at its apex is cot(bound / 2) / 2 of its
    // base from the base's middle; 0.95 of that (Ungor's off-centres, as Triangle places them).
    off_centre_ = options.min_angle > 0 ? 0.475 * std::sqrt((1 + cosine_bound) / (1 - cosine_bound)) : 0.0;
    cap_ = options.max_steiner_points;
    // The resolution: 2^-40 of the points' extent or of their largest coordinate, whichever is
    // larger (4096 units in the last place at least). Features smaller than that (two chains of
    // segments a rounding apart where overlapping segments met rounded crossings, a point a few
    // ulps from a segment) would need points at that scale all along them; segments shorter than
    // twice it are not split and triangles whose shortest edge is shorter are left as they are
    // (counted in unrefined_count).
    {
        // Far from the origin the doubles are coarser: the largest magnitude counts too.
        double magnitude = 0;
        for (double v : m_.xy_) magnitude = std::max(magnitude, std::fabs(v));
        const double extent = delaunay_detail::coordinate_span(PointSpan2(m_.xy_));
        const double tiny = std::ldexp(std::max(extent, magnitude), -40);
        tiny2_ = tiny * tiny;
    }
    if (cap_ == 0 && (options.min_angle > 28.6 || keep_segments_ != 0 || unsuitable_)) cap_ = 16 * m_.input_count_ + 1000000;
    // Every edge between the domain and the rest is kept as a segment; every segment is its own
    // parent (the whole segment, whose ends decide where its pieces are split).
    for (std::uint32_t e = 0; e < m_.vertex_.size(); ++e) {
        const std::uint32_t t = e / 3;
        if (m_.vertex_[3 * t] == kDead || m_.is_ghost(t) || m_.region_[t] == 0 || m_.edge_[e] != 0) continue;
        const std::uint32_t u = m_.twin_[e] / 3;
        if (m_.is_ghost(u) || m_.region_[u] == 0) m_.set_flags(e, 0, 1, kGhost);
    }
    for (std::uint32_t e = 0; e < m_.vertex_.size(); ++e) {
        if (m_.vertex_[e] == kDead || m_.edge_[e] == 0) continue;
        Cdt::Record& record = m_.records_[m_.edge_[e]];
        if (record.parent != kGhost) continue;
        record.parent = static_cast<std::uint32_t>(parents_.size());
        parents_.push_back({m_.vertex_[e], m_.vertex_[next_edge(e)]});
    }
    // The room the points have (Input::spare_points); the pages of those there are mapped at once.
    detail::reserve_populated(on_segment_, m_.xy_.capacity() / 2, m_.xy_.size() / 2);
    on_segment_.assign(m_.xy_.size() / 2, kGhost);
    m_.track_ = true;
    m_.touched_.clear();
    detail::reserve_populated(m_.touched_, m_.vertex_.size() / 3, m_.vertex_.size() / 3);
    // Room for every triangle in the flawed and bad lists before they reallocate: reserved
    // address space costs nothing until used, where growing by copies touches twice the pages.
    // The bad list is a queue: its consumed front is dropped once it is more than half the list
    // (and 256 entries), so that it stays in that room (footprint-1e3: 137 -> 127 page faults).
    flawed_.reserve(m_.vertex_.size() / 3);
    bad_.reserve(m_.vertex_.size() / 3);
    for (std::uint32_t t = 0; t < m_.vertex_.size() / 3; ++t) m_.touched_.push_back(t);
    retest();
    std::size_t split_head = 0, bad_head = 0;
    while (error.empty()) {
        if (split_head < split_.size()) {
            const SplitItem item = split_[split_head++];
            const std::uint32_t e = m_.find_edge(item.a, item.b);
            if (e != kGhost && m_.edge_[e] != 0 && (item.forced || encroached(e))) split_segment(e);
        } else if (bad_head < bad_.size()) {
            const BadTriangle item = bad_[bad_head++];
            const std::uint32_t* v = &m_.vertex_[3 * item.t];
            // Unchanged since it was found bad (same corners: same shape, edges and region).
            if (v[0] != item.a || v[1] != item.b || v[2] != item.c) continue;
            if (!split_triangle(item)) break;
        } else {
            break;
        }
#ifdef HULLKIT_CDT_DEBUG
        m_.check("refinement point " + std::to_string(steiner_count));
#endif
        retest();
        if (split_head == split_.size()) split_.clear(), split_head = 0;
        if (bad_head > 256 && bad_head * 2 > bad_.size()) bad_.erase(bad_.begin(), bad_.begin() + bad_head), bad_head = 0;
    }
    m_.track_ = false;
    if (!error.empty()) return false;
    if (conforming_) {
        // A segment still encroached (too short to split) leaves its triangles possibly not
        // Delaunay: every triangle is looked at.
        int shortest = 0;
        for (std::uint32_t t = 0; t < m_.vertex_.size() / 3; ++t) {
            if (m_.vertex_[3 * t] == kDead || m_.is_ghost(t) || m_.region_[t] == 0) continue;
            bool missed = flaw(t, &shortest) != kFine;
            for (std::uint32_t e = 3 * t; e < 3 * t + 3 && !missed; ++e) missed = m_.edge_[e] != 0 && encroached(e);
            unrefined_count += missed;
        }
    } else {
        // A flaw depends on the corners alone (the region goes with them), and every triangle was
        // retested when it got its corners: the ones left below a bound are those found flawed that still have the same
        // corners (each counted once).
        m_.new_mark();
        for (const BadTriangle& item : flawed_) {
            const std::uint32_t* v = &m_.vertex_[3 * item.t];
            if (v[0] != item.a || v[1] != item.b || v[2] != item.c || m_.marked(item.t)) continue;
            m_.mark(item.t);
            ++unrefined_count;
        }
    }
    return true;
}

}  // namespace constrained_detail
}  // namespace hullkit
