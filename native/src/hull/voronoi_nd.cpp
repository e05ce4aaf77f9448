// hullkit::voronoi_nd_volumes: every Voronoi cell's volume from the Delaunay triangulation, by the
// signed flag decomposition over the triangulation's faces.
//
// Each face s of the triangulation (k + 1 corners) has a dual face D(s) in the Voronoi diagram, of
// dimension d - k: the points equidistant from s's corners and no nearer any other point. Its
// affine hull is orthogonal to s's and meets it in c(s), the centre of s's smallest circumsphere.
// D(s) is a pyramid sum from the apex c(s) over its facets, the duals D(t) of the faces t = s + v
// one corner larger: vol(D(s)) = 1/(d - k) * sum over t of sign * |c(s) - c(t)| * vol(D(t)), since
// c(t) is the foot of c(s) on D(t)'s affine hull. The sign is + when c(s) lies on D(s)'s side of
// D(t)'s hyperplane, which is when the new corner v lies outside the sphere about c(s) through s's
// corners; a term whose sign is in doubt is near 0 (v on that sphere makes c(t) = c(s)), so
// floating-point signs are harmless. A point's cell is D({p}); the simplices' duals are vertices
// (volume 1, the empty product). A face on the triangulation's boundary (in a facet with one
// simplex) has an unbounded dual: inf.
//
// Faces are found level by level, from the simplices down: each face's subfaces (one corner
// dropped) listed, sorted and merged, so each face and its circumcentre are computed once.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "hullkit/hull_nd.hpp"

namespace hullkit {
namespace {

/// The centre of the smallest sphere through the `corners` (k + 1 of them, affinely independent)
/// of points with d coordinates: a0 + sum l_i (a_i - a0) with the Gram system
/// (a_i - a0).(a_j - a0) l = |a_i - a0|^2 / 2, solved with partial pivoting.
void circumcentre(const double* points, int d, const std::uint32_t* corners, int k, double* out) {
    const double* a0 = points + static_cast<std::size_t>(corners[0]) * static_cast<std::size_t>(d);
    double e[kMaxHullNdDimension][kMaxHullNdDimension];
    double g[kMaxHullNdDimension][kMaxHullNdDimension + 1];
    for (int i = 0; i < k; ++i) {
        const double* a = points + static_cast<std::size_t>(corners[i + 1]) * static_cast<std::size_t>(d);
        for (int c = 0; c < d; ++c) e[i][c] = a[c] - a0[c];
    }
    for (int i = 0; i < k; ++i) {
        for (int j = 0; j <= i; ++j) {
            double dot = 0;
            for (int c = 0; c < d; ++c) dot += e[i][c] * e[j][c];
            g[i][j] = g[j][i] = dot;
        }
        g[i][k] = 0.5 * g[i][i];
    }
    for (int col = 0; col < k; ++col) {
        int pivot = col;
        for (int r = col + 1; r < k; ++r)
            if (std::fabs(g[r][col]) > std::fabs(g[pivot][col])) pivot = r;
        if (pivot != col)
            for (int c = col; c <= k; ++c) std::swap(g[col][c], g[pivot][c]);
        for (int r = col + 1; r < k; ++r) {
            const double f = g[r][col] / g[col][col];
            for (int c = col; c <= k; ++c) g[r][c] -= f * g[col][c];
        }
    }
    double l[kMaxHullNdDimension];
    for (int r = k - 1; r >= 0; --r) {
        double v = g[r][k];
        for (int c = r + 1; c < k; ++c) v -= g[r][c] * l[c];
        l[r] = v / g[r][r];
    }
    for (int c = 0; c < d; ++c) {
        double v = a0[c];
        for (int i = 0; i < k; ++i) v += l[i] * e[i][c];
        out[c] = v;
    }
}

double squared_distance(const double* a, const double* b, int d) {
    double s = 0;
    for (int c = 0; c < d; ++c) s += (a[c] - b[c]) * (a[c] - b[c]);
    return s;
}

/// The faces of one level: `width` sorted corners each, their circumcentres and duals' volumes.
struct Level {
    int width = 0;
    std::vector<std::uint32_t> corners;
    std::vector<double> centre;
    std::vector<double> volume;  ///< inf: unbounded
    std::size_t size() const { return width ? corners.size() / static_cast<std::size_t>(width) : 0; }
};

}  // namespace

std::vector<double> voronoi_nd_volumes(const double* points, std::size_t count, int dimension,
                                       const std::uint32_t* simplices, std::size_t simplex_count) {
    const int d = dimension;
    if (d < 1 || d > kMaxHullNdDimension - 1) throw std::invalid_argument("voronoi_nd_volumes: dimension out of range");
    const auto D = static_cast<std::size_t>(d);
    const double inf = std::numeric_limits<double>::infinity();
    // Level d: the simplices, corners sorted, each dual a vertex.
    Level upper;
    upper.width = d + 1;
    upper.corners.assign(simplices, simplices + simplex_count * (D + 1));
    for (std::size_t s = 0; s < simplex_count; ++s) {
        std::uint32_t* c = &upper.corners[s * (D + 1)];
        for (std::size_t k = 0; k <= D; ++k)
            if (c[k] >= count) throw std::invalid_argument("voronoi_nd_volumes: a corner out of range");
        std::sort(c, c + D + 1);
    }
    upper.centre.resize(simplex_count * D);
    for (std::size_t s = 0; s < simplex_count; ++s) circumcentre(points, d, &upper.corners[s * (D + 1)], d, &upper.centre[s * D]);
    upper.volume.assign(simplex_count, 1.0);
    for (int width = d; width >= 1; --width) {
        // Every face of the level above with one corner dropped: (its position, the dropped one).
        const auto w = static_cast<std::size_t>(width);
        const std::size_t faces = upper.size();
        std::vector<std::uint64_t> entry(faces * (w + 1));
        for (std::size_t f = 0; f < faces; ++f)
            for (std::size_t j = 0; j <= w; ++j) entry[f * (w + 1) + j] = (std::uint64_t{f} << 4) | j;
        auto sub = [&](std::uint64_t e, std::size_t i) {  // corner i of the face entry e names
            const std::size_t f = e >> 4, j = e & 15u;
            return upper.corners[f * (w + 1) + (i < j ? i : i + 1)];
        };
        auto less = [&](std::uint64_t a, std::uint64_t b) {
            for (std::size_t i = 0; i < w; ++i) {
                const std::uint32_t x = sub(a, i), y = sub(b, i);
                if (x != y) return x < y;
            }
            return a < b;
        };
        auto same = [&](std::uint64_t a, std::uint64_t b) {
            for (std::size_t i = 0; i < w; ++i)
                if (sub(a, i) != sub(b, i)) return false;
            return true;
        };
        std::sort(entry.begin(), entry.end(), less);
        Level lower;
        lower.width = width;
        for (std::size_t at = 0; at < entry.size();) {
            std::size_t end = at + 1;
            while (end < entry.size() && same(entry[at], entry[end])) ++end;
            const std::size_t g = lower.size();
            for (std::size_t i = 0; i < w; ++i) lower.corners.push_back(sub(entry[at], i));
            lower.centre.resize((g + 1) * D);
            double* c = &lower.centre[g * D];
            circumcentre(points, d, &lower.corners[g * w], width - 1, c);
            const double* a0 = points + static_cast<std::size_t>(lower.corners[g * w]) * D;
            const double radius2 = squared_distance(c, a0, d);
            // A facet (width d) in one simplex only is on the boundary: its dual is a ray.
            double sum = (width == d && end - at == 1) ? inf : 0.0;
            for (std::size_t k = at; k < end && sum != inf; ++k) {
                const std::size_t f = entry[k] >> 4, j = entry[k] & 15u;
                if (upper.volume[f] == inf) {
                    sum = inf;
                    break;
                }
                const double* v = points + static_cast<std::size_t>(upper.corners[f * (w + 1) + j]) * D;
                const double sign = squared_distance(c, v, d) > radius2 ? 1.0 : -1.0;
                sum += sign * std::sqrt(squared_distance(c, &upper.centre[f * D], d)) * upper.volume[f];
            }
            lower.volume.push_back(sum == inf ? inf : sum / static_cast<double>(d - width + 1));
            at = end;
        }
        upper = std::move(lower);
    }
    // Level 0: the points, each its cell's volume; NaN for a point in no simplex.
    std::vector<double> volume(count, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t f = 0; f < upper.size(); ++f) volume[upper.corners[f]] = upper.volume[f];
    return volume;
}

}  // namespace hullkit
