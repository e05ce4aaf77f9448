// Randomized oracle for the route checker: random convex and non-convex traverses and obstacles,
// each leg sampled at 10 000 fractions with a static test written here independently of the
// library: triangle pairs by the separating-axis theorem (complete axis set, a double filter with
// an exact GMP rational decision in the ambiguous band), containment by ray parity with exact
// rational orientations, distances by plain closest points in long double.
//   * whenever a sample is in contact, hullkit reports a hit (or start overlap) no later;
//   * whenever the sampled clearance exceeds margin + (half the sample spacing x leg length),
//     hullkit reports clear, with a clearance between that bound and the sampled minimum.
#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "hullkit/route.hpp"
#include "random_scenes.hpp"
#include "sanitized.hpp"

using namespace hullkit;

namespace {

constexpr int kSamples = 10000;

using route_test::D3;
using route_test::Mesh;
using Q3 = std::array<mpq_class, 3>;

D3 dsub(const D3& a, const D3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
D3 dcross(const D3& a, const D3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double ddot(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Q3 qsub(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Q3 qcross(const Q3& a, const Q3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
mpq_class qdot(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// The separating-axis candidates for two triangles: both normals, the 9 edge cross products and
/// the in-plane edge normals (complete for non-degenerate triangles, parallel planes included).
template <typename V, typename Sub, typename Cross>
std::vector<V> axes_of(const V* p, const V* q, Sub sub, Cross cross) {
    const V ep[3] = {sub(p[1], p[0]), sub(p[2], p[1]), sub(p[0], p[2])};
    const V eq[3] = {sub(q[1], q[0]), sub(q[2], q[1]), sub(q[0], q[2])};
    const V np = cross(ep[0], ep[1]), nq = cross(eq[0], eq[1]);
    std::vector<V> axes = {np, nq};
    for (const V& e : ep) {
        for (const V& f : eq) axes.push_back(cross(e, f));
        axes.push_back(cross(np, e));
    }
    for (const V& f : eq) axes.push_back(cross(nq, f));
    return axes;
}

/// Exact: do the closed triangles p and q share a point?
bool exact_meet(const Q3* p, const Q3* q) {
    for (const Q3& n : axes_of(p, q, qsub, qcross)) {
        if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) continue;
        mpq_class pmin = qdot(n, p[0]), pmax = pmin, qmin = qdot(n, q[0]), qmax = qmin;
        for (int i = 1; i < 3; ++i) {
            const mpq_class a = qdot(n, p[i]), b = qdot(n, q[i]);
            if (a < pmin) pmin = a;
            if (a > pmax) pmax = a;
            if (b < qmin) qmin = b;
            if (b > qmax) qmax = b;
        }
        if (pmax < qmin || qmax < pmin) return false;
    }
    return true;
}

/// Double filter for exact_meet: -1 certainly apart, +1 certainly meeting, 0 undecided. *gap gets
/// the widest separation found along an axis (a lower bound on the distance, up to rounding).
int filtered_meet(const D3* p, const D3* q, double tol, double* gap) {
    double least = HUGE_VAL;
    *gap = -HUGE_VAL;
    for (const D3& n : axes_of(p, q, dsub, dcross)) {
        const double len = std::sqrt(ddot(n, n));
        if (!(len > 1e-12)) return 0;  // a (nearly) vanishing axis: let the exact test decide
        double pmin = HUGE_VAL, pmax = -HUGE_VAL, qmin = HUGE_VAL, qmax = -HUGE_VAL;
        for (int i = 0; i < 3; ++i) {
            const double a = ddot(n, p[i]) / len, b = ddot(n, q[i]) / len;
            pmin = std::min(pmin, a), pmax = std::max(pmax, a);
            qmin = std::min(qmin, b), qmax = std::max(qmax, b);
        }
        const double overlap = std::min(pmax - qmin, qmax - pmin);
        *gap = std::max(*gap, -overlap);
        least = std::min(least, overlap);
    }
    if (*gap > tol) return -1;
    return least > tol ? 1 : 0;
}

// ---- distances in long double (plain closest points) ----
using L3 = std::array<long double, 3>;
L3 lsub(const L3& a, const L3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
long double ldot(const L3& a, const L3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
L3 lcross(const L3& a, const L3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
L3 lerp(const L3& a, const L3& b, long double s) {
    return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
}
long double ldist(const L3& a, const L3& b) { return std::sqrt(ldot(lsub(a, b), lsub(a, b))); }

long double point_segment(const L3& x, const L3& a, const L3& b) {
    const L3 ab = lsub(b, a);
    const long double len2 = ldot(ab, ab);
    const long double s = len2 > 0 ? std::clamp(ldot(lsub(x, a), ab) / len2, 0.0L, 1.0L) : 0.0L;
    return ldist(x, lerp(a, b, s));
}

long double point_triangle(const L3& x, const L3* t) {
    const L3 n = lcross(lsub(t[1], t[0]), lsub(t[2], t[0]));
    const long double n2 = ldot(n, n);
    if (n2 > 0) {
        // Inside the prism over the triangle: the distance to its plane.
        bool inside = true;
        for (int i = 0; i < 3; ++i) {
            const L3 c = lcross(lsub(t[(i + 1) % 3], t[i]), lsub(x, t[i]));
            inside = inside && ldot(c, n) >= 0;
        }
        if (inside) return std::fabs(ldot(lsub(x, t[0]), n)) / std::sqrt(n2);
    }
    return std::min({point_segment(x, t[0], t[1]), point_segment(x, t[1], t[2]),
                     point_segment(x, t[2], t[0])});
}

long double segment_segment(const L3& a, const L3& b, const L3& c, const L3& d) {
    long double best = std::min({point_segment(a, c, d), point_segment(b, c, d),
                                 point_segment(c, a, b), point_segment(d, a, b)});
    // An interior critical point of |a + s (b - a) - c - t (d - c)|^2, if any.
    const L3 u = lsub(b, a), v = lsub(d, c), w = lsub(a, c);
    const long double uu = ldot(u, u), uv = ldot(u, v), vv = ldot(v, v);
    const long double uw = ldot(u, w), vw = ldot(v, w);
    const long double det = uu * vv - uv * uv;
    if (det > 1e-18L * uu * vv) {
        const long double s = (uv * vw - vv * uw) / det, t = (uu * vw - uv * uw) / det;
        if (s >= 0 && s <= 1 && t >= 0 && t <= 1) best = std::min(best, ldist(lerp(a, b, s), lerp(c, d, t)));
    }
    return best;
}

/// Distance between disjoint triangles.
long double triangle_triangle(const L3* p, const L3* q) {
    long double best = HUGE_VALL;
    for (int i = 0; i < 3; ++i) {
        best = std::min({best, point_triangle(p[i], q), point_triangle(q[i], p)});
        for (int j = 0; j < 3; ++j) {
            best = std::min(best, segment_segment(p[i], p[(i + 1) % 3], q[j], q[(j + 1) % 3]));
        }
    }
    return best;
}

// ---- the sampled oracle ----

struct Sampled {
    int first_contact = -1;         ///< first sample in contact, -1 if none
    long double clearance = HUGE_VALL;  ///< minimum over samples (when no contact)
};

struct Oracle {
    const std::vector<Mesh>& parts;
    const std::vector<Mesh>& obstacles;
    double margin;

    /// Exact point of part vertex v at sample k of the leg a -> b: v + a + (k / N)(b - a).
    static Q3 exact_at(const D3& v, const D3& a, const D3& b, int k) {
        mpq_class t(k, kSamples);
        t.canonicalize();
        Q3 r;
        for (int i = 0; i < 3; ++i) {
            r[i] = mpq_class(v[i]) + mpq_class(a[i]) + t * (mpq_class(b[i]) - mpq_class(a[i]));
        }
        return r;
    }

    static Q3 exact(const D3& v) { return {mpq_class(v[0]), mpq_class(v[1]), mpq_class(v[2])}; }

    /// A point known in double (for the filter) and exactly (computed only when needed).
    struct Pt {
        D3 d;
        std::function<Q3()> exact;
    };

    /// Orientation sign of d against the plane a b c: a double filter whose bound far exceeds the
    /// rounding of the double coordinates, else exact rationals.
    static int orient(const Pt& a, const Pt& b, const Pt& c, const Pt& d) {
        const D3 ab = dsub(b.d, a.d), ac = dsub(c.d, a.d), ad = dsub(d.d, a.d);
        const double det = ddot(dcross(ab, ac), ad);
        const double bound = 1e-10 * std::sqrt(ddot(ab, ab) * ddot(ac, ac) * ddot(ad, ad)) + 1e-12;
        if (std::fabs(det) > bound) return det > 0 ? 1 : -1;
        const Q3 qa = a.exact(), qb = b.exact(), qc = c.exact(), qd = d.exact();
        return sgn(qdot(qcross(qsub(qb, qa), qsub(qc, qa)), qsub(qd, qa)));
    }

    /// Ray parity of x against the triangles (exact decisions; degenerate rays retried).
    static bool inside(const Pt& x, const std::vector<std::array<Pt, 3>>& tris, std::mt19937_64& rng) {
        std::uniform_int_distribution<int> u(-1000, 1000);
        for (;;) {
            const D3 fd = {x.d[0] + 1000 + u(rng), x.d[1] + 977 + u(rng), x.d[2] + 1013 + u(rng)};
            const D3 offset = dsub(fd, x.d);  // exact: small integers plus x
            const Pt far{fd, [&x, offset] {
                             Q3 q = x.exact();
                             for (int i = 0; i < 3; ++i) q[i] += mpq_class(offset[i]);
                             return q;
                         }};
            int crossings = 0;
            bool degenerate = false;
            for (const auto& t : tris) {
                const int sx = orient(t[0], t[1], t[2], x), sf = orient(t[0], t[1], t[2], far);
                if (sx == sf) continue;
                if (sx == 0 || sf == 0) { degenerate = true; break; }
                const int o1 = orient(x, far, t[0], t[1]), o2 = orient(x, far, t[1], t[2]),
                          o3 = orient(x, far, t[2], t[0]);
                if (o1 == 0 || o2 == 0 || o3 == 0) {
                    if ((o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0)) {
                        degenerate = true;
                        break;
                    }
                    continue;
                }
                crossings += (o1 == o2 && o2 == o3);
            }
            if (!degenerate) return crossings % 2 == 1;
        }
    }

    static Pt fixed_point(const D3& v) {
        return {v, [v] { return exact(v); }};
    }
    static Pt moving_point(const D3& v, const D3& a, const D3& b, int k) {
        const double t = static_cast<double>(k) / kSamples;
        D3 d;
        for (int i = 0; i < 3; ++i) d[i] = v[i] + (a[i] + t * (b[i] - a[i]));
        return {d, [v, a, b, k] { return exact_at(v, a, b, k); }};
    }

    Sampled run(const D3& a, const D3& b, double threshold, std::mt19937_64& rng) const {
        // contact[k]: sample k in contact; near[k]: least distance at sample k.
        std::vector<char> contact(kSamples + 1, 0);
        std::vector<long double> least(kSamples + 1, HUGE_VALL);
        const double scale = 10.0, tol = 1e-9 * scale;
        for (std::size_t pi = 0; pi < parts.size(); ++pi) {
            const Mesh& part = parts[pi];
            for (const auto& pt : part.tris) {
                for (const Mesh& obstacle : obstacles) {
                    for (const auto& qt : obstacle.tris) {
                        const D3 q[3] = {obstacle.points[qt[0]], obstacle.points[qt[1]], obstacle.points[qt[2]]};
                        // Samples where the pair's boxes come within the threshold, per axis.
                        double t0 = 0, t1 = 1;
                        for (int k = 0; k < 3 && t0 <= t1; ++k) {
                            double plo = HUGE_VAL, phi = -HUGE_VAL, qlo = HUGE_VAL, qhi = -HUGE_VAL;
                            for (int i = 0; i < 3; ++i) {
                                plo = std::min(plo, part.points[pt[i]][k] + a[k]);
                                phi = std::max(phi, part.points[pt[i]][k] + a[k]);
                                qlo = std::min(qlo, q[i][k]);
                                qhi = std::max(qhi, q[i][k]);
                            }
                            const double d = b[k] - a[k], pad = threshold + 1e-6;
                            if (d == 0) {
                                if (qlo > phi + pad || plo > qhi + pad) t1 = -1;
                                continue;
                            }
                            const double ta = (qlo - phi - pad) / d, tb = (qhi - plo + pad) / d;
                            t0 = std::max(t0, std::min(ta, tb));
                            t1 = std::min(t1, std::max(ta, tb));
                        }
                        if (t0 > t1) continue;
                        const int k0 = std::max(0, static_cast<int>(std::floor(t0 * kSamples)) - 1);
                        const int k1 = std::min(kSamples, static_cast<int>(std::ceil(t1 * kSamples)) + 1);
                        for (int k = k0; k <= k1; ++k) {
                            const double t = static_cast<double>(k) / kSamples;
                            D3 p[3];
                            L3 lp[3], lq[3];
                            for (int i = 0; i < 3; ++i) {
                                for (int c = 0; c < 3; ++c) {
                                    p[i][c] = part.points[pt[i]][c] + (a[c] + t * (b[c] - a[c]));
                                    lp[i][c] = static_cast<long double>(part.points[pt[i]][c]) + a[c] +
                                               static_cast<long double>(k) / kSamples * (static_cast<long double>(b[c]) - a[c]);
                                    lq[i][c] = q[i][c];
                                }
                            }
                            double gap;
                            int meet = filtered_meet(p, q, tol, &gap);
                            // Distances beyond the threshold (or the sample's least) do not matter.
                            if (meet < 0 && gap - tol > std::min<long double>(least[k], threshold)) continue;
                            if (meet == 0) {
                                Q3 ep[3], eq[3];
                                for (int i = 0; i < 3; ++i) {
                                    ep[i] = exact_at(part.points[pt[i]], a, b, k);
                                    eq[i] = exact(q[i]);
                                }
                                meet = exact_meet(ep, eq) ? 1 : -1;
                            }
                            if (meet > 0) {
                                contact[k] = 1;
                                least[k] = 0;
                                continue;
                            }
                            const long double d = triangle_triangle(lp, lq);
                            least[k] = std::min(least[k], d);
                            if (d < margin * (1 - 1e-9)) contact[k] = 1;
                        }
                    }
                }
            }
        }
        // Containment where no surfaces meet: a closed mesh around a vertex of the other.
        for (int k = 0; k <= kSamples; ++k) {
            if (contact[k]) continue;
            const double t = static_cast<double>(k) / kSamples;
            for (const Mesh& part : parts) {
                for (const Mesh& obstacle : obstacles) {
                    if (part.closed && box_inside(obstacle.points, D3{}, part.points, offset(a, b, t))) {
                        std::vector<std::array<Pt, 3>> tris;
                        for (const auto& f : part.tris) {
                            tris.push_back({moving_point(part.points[f[0]], a, b, k),
                                            moving_point(part.points[f[1]], a, b, k),
                                            moving_point(part.points[f[2]], a, b, k)});
                        }
                        if (inside(fixed_point(obstacle.points[0]), tris, rng)) contact[k] = 1;
                    }
                    if (obstacle.closed && box_inside(part.points, offset(a, b, t), obstacle.points, D3{})) {
                        std::vector<std::array<Pt, 3>> tris;
                        for (const auto& f : obstacle.tris) {
                            tris.push_back({fixed_point(obstacle.points[f[0]]), fixed_point(obstacle.points[f[1]]),
                                            fixed_point(obstacle.points[f[2]])});
                        }
                        if (inside(moving_point(part.points[0], a, b, k), tris, rng)) contact[k] = 1;
                    }
                }
            }
        }
        Sampled s;
        for (int k = 0; k <= kSamples; ++k) {
            if (contact[k]) {
                if (s.first_contact < 0) s.first_contact = k;
                s.clearance = 0;
            } else {
                s.clearance = std::min(s.clearance, least[k]);
            }
        }
        return s;
    }

    static D3 offset(const D3& a, const D3& b, double t) {
        return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    }

    /// The box of `inner` (shifted) lies within the box of `outer` (shifted), with a little slack.
    static bool box_inside(const std::vector<D3>& inner, const D3& wi, const std::vector<D3>& outer,
                           const D3& wo) {
        for (int k = 0; k < 3; ++k) {
            double ilo = HUGE_VAL, ihi = -HUGE_VAL, olo = HUGE_VAL, ohi = -HUGE_VAL;
            for (const D3& p : inner) ilo = std::min(ilo, p[k] + wi[k]), ihi = std::max(ihi, p[k] + wi[k]);
            for (const D3& p : outer) olo = std::min(olo, p[k] + wo[k]), ohi = std::max(ohi, p[k] + wo[k]);
            if (ilo < olo - 1e-9 || ihi > ohi + 1e-9) return false;
        }
        return true;
    }
};

}  // namespace

TEST_CASE("route: randomized oracle, 10 000 exact static samples per leg") {
    std::mt19937_64 rng(route_test::kRandomSceneSeed);
    int hits = 0, clears = 0, starts = 0, checked_clearances = 0;
    // Under the sanitizers 4 of the 40 scenes (tests/sanitized.hpp); the plain build checks the
    // answers on all 40.
    const int scenes = hullkit_test::kSanitized ? 4 : 40;
    for (int scene_index = 0; scene_index < scenes; ++scene_index) {
        // The oracle draws its rays from the same generator, so each scene follows the oracle's
        // run on the one before.
        const route_test::RandomScene random = route_test::random_scene(rng, scene_index);
        const Scene& scene = random.scene;
        const std::vector<D3>& waypoints = random.waypoints;
        const RouteReport report = check_route(scene);
        REQUIRE(report.ok());
        const Oracle oracle{random.parts, random.obstacles, scene.margin};
        for (std::size_t leg_index = 0; leg_index + 1 < waypoints.size(); ++leg_index) {
            const D3& a = waypoints[leg_index];
            const D3& b = waypoints[leg_index + 1];
            const double length = std::sqrt(ddot(dsub(b, a), dsub(b, a)));
            const double bound = scene.margin + 0.5 * length / kSamples;
            const double threshold = bound + 0.2;  // distances above it are not computed
            const Sampled sampled = oracle.run(a, b, threshold, rng);
            const LegReport& leg = report.legs[leg_index];
            CAPTURE(scene_index, leg_index, scene.margin, sampled.first_contact,
                    static_cast<double>(sampled.clearance), leg_status_name(leg.status),
                    leg.fraction_lo, leg.fraction_hi, leg.clearance);
            if (sampled.first_contact >= 0) {
                REQUIRE(leg.status != LegStatus::Clear);
                if (sampled.first_contact == 0) CHECK(leg.status == LegStatus::StartOverlap);
                if (leg.status == LegStatus::Hit) {
                    CHECK(leg.fraction_lo <= static_cast<double>(sampled.first_contact) / kSamples);
                }
            }
            if (sampled.first_contact < 0 && sampled.clearance > bound) {
                REQUIRE(leg.status == LegStatus::Clear);
            }
            if (sampled.first_contact < 0 && sampled.clearance > bound && sampled.clearance <= threshold) {
                // Between samples the distance changes by at most the distance travelled.
                CHECK(leg.clearance <= static_cast<double>(sampled.clearance) * (1 + 1e-9));
                CHECK(leg.clearance >= static_cast<double>(sampled.clearance) - 0.5 * length / kSamples - 1e-9);
                ++checked_clearances;
            }
            hits += leg.status == LegStatus::Hit;
            clears += leg.status == LegStatus::Clear;
            starts += leg.status == LegStatus::StartOverlap;
        }
    }
    // The scenes must exercise every outcome for the oracle to mean something.
    CAPTURE(hits, clears, starts, checked_clearances);
    CHECK(hits >= 5 * scenes / 40);
    CHECK(clears >= 5 * scenes / 40);
    CHECK(checked_clearances >= 8 * scenes / 40);
}
