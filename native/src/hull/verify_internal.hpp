// Private pieces of hullkit::verify shared by its files: the problem collector, the prepared
// (finite, scaled) input, the identical-points check, the axis projection, the dimension-3
// SurfaceVerifier (defined in verify_solid.cpp and verify_containment.cpp) and the per-dimension
// checks that verify.cpp dispatches to.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "hullkit/predicates.hpp"
#include "hullkit/verify.hpp"
#include "point_key.hpp"

namespace hullkit::verify_detail {

using Index = std::uint32_t;
constexpr Index kNone = ~Index{0};

inline std::string num(std::size_t value) { return std::to_string(value); }

inline std::string coordinates(const double* p) {
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

bool prepare(PointSpan input, Problems& out, Prepared& prepared);

// ---- identical points ----

using detail::key_of;
using detail::PointKey;
using detail::PointKeyHash;

/// Reports vertices that are the same point as another vertex, and vertices standing for identical
/// input points that are not the lowest index of them. `vertices` must be in range.
void check_representatives(PointSpan points, PointSpan original, const std::vector<Index>& vertices,
                           Problems& out);

/// An axis-aligned projection (kept axes i, j) in which a, b, c are not collinear; returns their
/// orientation there (never 0 unless a, b, c are collinear in space). Any such projection is
/// one-to-one on the plane of a, b, c, so orientations in it are exact orientations in the plane.
inline int projection(const double* a, const double* b, const double* c, int* i, int* j) {
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

// ---- dimension 3 ----

/// Certifies a closed triangle surface as the boundary of the hull of the points (see verify.hpp).
/// The structure, convexity and winding checks are in verify_solid.cpp, the containment of the
/// points in verify_containment.cpp.
class SurfaceVerifier {
public:
    SurfaceVerifier(const Prepared& prepared, const Index* triangles, std::size_t count, VerifyReport& report)
        : points_(prepared.points),
          original_(prepared.original),
          t_(triangles),
          f_(count),
          report_(report),
          out_(report) {}
    void run();

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

    // verify_solid.cpp: the structure of the surface, its convexity, the interior point, the vertices.
    bool check_indices();
    void check_areas();
    bool pair_edges();
    bool check_fans();
    bool check_connected();
    bool check_euler();
    void check_edges();
    void merge_faces();
    bool strictly_inside(const double* o) const;
    bool find_interior_point();
    void fan_of(Index v, std::vector<Index>& fan) const;
    int winding_about_interior(Index v, const std::vector<Index>& fan) const;
    bool runs_distinct(const std::vector<Index>& fan, Index* repeated_a, Index* repeated_b) const;
    bool check_vertices(bool have_interior);

    // verify_containment.cpp: every input point in the hull.
    bool cone_contains(Index t, const double* q, int skip, int* negative, int* negatives) const;
    Index locate(const double* q, Index start, std::uint64_t& random);
    std::vector<char> vertex_mask() const;
    void report_outside(std::size_t i, Index t);
    bool inner_box(double lo[3], double hi[3]) const;
    void contain_by_walking();
    void contain_exhaustively(bool structure_ok);

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

/// The checks of a Hull by its dimension (verify_solid.cpp and verify_lower.cpp).
void verify_solid(const Prepared& prepared, const Hull& hull, VerifyReport& report, Problems& out);
void verify_polygon(const Prepared& prepared, const Hull& hull, VerifyReport& report, Problems& out);
void verify_segment(const Prepared& prepared, const Hull& hull, VerifyReport& report, Problems& out);
void verify_single_point(const Prepared& prepared, const Hull& hull, VerifyReport& report, Problems& out);

}  // namespace hullkit::verify_detail
