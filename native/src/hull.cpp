// hullkit::hull: checks and scales the input, settles its dimension exactly, runs the chosen 3D
// algorithm and brings every result into one canonical form.
#include "hullkit/hull.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/glm.hpp>

#include "hull_internal.hpp"
#include "hullkit/giftwrap.hpp"
#include "hullkit/predicates.hpp"
#include "planar.hpp"
#include "sides.hpp"

namespace hullkit {

namespace detail {

Hull failure(std::string message, std::int64_t point) {
    Hull result;
    result.error = std::move(message);
    result.error_point = point;
    return result;
}

std::vector<std::uint32_t>::iterator sort_dropping_repeats(PointSpan points, std::vector<std::uint32_t>::iterator first,
                                                           std::vector<std::uint32_t>::iterator last) {
    std::sort(first, last, [&](std::uint32_t a, std::uint32_t b) {
        const double* p = points[a];
        const double* q = points[b];
        if (p[0] != q[0]) return p[0] < q[0];
        if (p[1] != q[1]) return p[1] < q[1];
        if (p[2] != q[2]) return p[2] < q[2];
        return a < b;
    });
    return std::unique(first, last, [&](std::uint32_t a, std::uint32_t b) {  // keeps the first: the lowest index
        const double* p = points[a];
        const double* q = points[b];
        return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
    });
}

std::vector<std::uint32_t> distinct_points(PointSpan points) {
    std::vector<std::uint32_t> kept(points.count);
    std::iota(kept.begin(), kept.end(), 0u);
    kept.erase(sort_dropping_repeats(points, kept.begin(), kept.end()), kept.end());
    std::sort(kept.begin(), kept.end());
    return kept;
}

Simplex find_simplex(PointSpan points) {
    Simplex s;
    const auto n = static_cast<std::uint32_t>(points.count);
    if (n == 0) return s;
    auto at = [&](std::uint32_t i) { return vec3(points[i]); };

    // One pass: the extremes in 14 directions (lowest index on ties) and the bounding box.
    double best_value[14];
    for (int k = 0; k < 14; ++k) best_value[k] = -std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) s.lo[axis] = s.hi[axis] = points[0][axis];
    for (std::uint32_t i = 0; i < n; ++i) {
        const double* p = points[i];
        const double value[7] = {p[0], p[1], p[2], p[0] + p[1] + p[2], p[0] + p[1] - p[2], p[0] - p[1] + p[2], p[0] - p[1] - p[2]};
        for (int k = 0; k < 7; ++k) {
            if (value[k] > best_value[2 * k]) best_value[2 * k] = value[k], s.extreme[2 * k] = i;
            if (-value[k] > best_value[2 * k + 1]) best_value[2 * k + 1] = -value[k], s.extreme[2 * k + 1] = i;
        }
        for (int axis = 0; axis < 3; ++axis) {
            s.lo[axis] = std::min(s.lo[axis], p[axis]);
            s.hi[axis] = std::max(s.hi[axis], p[axis]);
        }
    }
    const std::uint32_t* extreme = s.extreme;

    // The farthest pair of extremes (rounded distances choose; equality of points is exact).
    double best = -1.0;
    for (int i = 0; i < 14; ++i) {
        for (int j = i + 1; j < 14; ++j) {
            const glm::dvec3 d = at(extreme[j]) - at(extreme[i]);
            if (const double d2 = glm::dot(d, d); d2 > best) {
                best = d2;
                s.p[0] = std::min(extreme[i], extreme[j]);
                s.p[1] = std::max(extreme[i], extreme[j]);
            }
        }
    }
    s.dimension = 0;
    const double* a = points[s.p[0]];
    const double* b = points[s.p[1]];
    if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) {  // the bounding box is a point
        s.p[0] = 0;
        return s;
    }
    s.dimension = 1;

    // The extreme farthest from the line a-b, else the first point off it (exactly).
    const glm::dvec3 pa = at(s.p[0]);
    const glm::dvec3 ab = at(s.p[1]) - pa;
    best = -1.0;
    for (std::uint32_t e : s.extreme) {
        const glm::dvec3 c = glm::cross(ab, at(e) - pa);
        if (const double c2 = glm::dot(c, c); c2 > best || (c2 == best && e < s.p[2])) {
            best = c2;
            s.p[2] = e;
        }
    }
    if (collinear3d(a, b, points[s.p[2]])) {
        std::uint32_t i = 0;
        while (i < n && collinear3d(a, b, points[i])) ++i;
        if (i == n) return s;
        s.p[2] = i;
    }
    s.dimension = 2;

    // The extreme farthest from the plane a, b, c, else the first point off it (exactly).
    const double* c = points[s.p[2]];
    const glm::dvec3 normal = glm::cross(ab, at(s.p[2]) - pa);
    best = -1.0;
    for (std::uint32_t e : s.extreme) {
        if (const double h = std::fabs(glm::dot(normal, at(e) - pa)); h > best || (h == best && e < s.p[3])) {
            best = h;
            s.p[3] = e;
        }
    }
    if (orient3d(a, b, c, points[s.p[3]]) == 0) {
        std::uint32_t i = 0;
        while (i < n && orient3d(a, b, c, points[i]) == 0) ++i;
        if (i == n) return s;
        s.p[3] = i;
    }
    s.dimension = 3;
    return s;
}

}  // namespace detail

namespace {

using detail::Polygons;
using detail::Simplex;

/// Non-finite coordinates and too many points; else an ok() Hull and, in *exponent, the power of
/// two that brings the coordinates into the predicates' exact range (0 if they are in it). Fails
/// when no single power of two can.
Hull check_input(PointSpan points, int* exponent) {
    if (points.count > std::numeric_limits<std::uint32_t>::max()) {
        return detail::failure("too many points: " + std::to_string(points.count) +
                               " (at most 4294967295 fit 32-bit indices)");
    }
    double largest = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < points.count; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            const double value = points[i][axis];
            const double magnitude = std::fabs(value);
            if (!(magnitude <= std::numeric_limits<double>::max())) {  // inf or nan
                static const char* const kAxis[] = {"x", "y", "z"};
                const char* what = std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
                return detail::failure("point " + std::to_string(i) + " has a non-finite " + kAxis[axis] +
                                           " coordinate (" + what + ")",
                                       static_cast<std::int64_t>(i));
            }
            largest = std::max(largest, magnitude);
            if (magnitude != 0.0) smallest = std::min(smallest, magnitude);
        }
    }
    *exponent = 0;
    if (!predicates_range_ok(largest, smallest) && !predicates_scale_exponent(largest, smallest, exponent)) {
        return detail::failure(
            "coordinates span too many orders of magnitude: the nonzero |coordinates| must fit within "
            "a factor of 2^585 (about 1e176) of each other for exact predicates");
    }
    return Hull{};
}

/// Rotates each polygon to start at its lowest index.
void rotate_to_lowest(Polygons& faces) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto first = faces.vertices.begin() + faces.offsets[f];
        const auto last = faces.vertices.begin() + faces.offsets[f + 1];
        std::rotate(first, std::min_element(first, last), last);
    }
}

/// Triangles fanned from each polygon's first corner and the sorted vertex list.
void fill_from_polygons(std::size_t point_count, const Polygons& faces, Hull& hull) {
    hull.triangles.clear();
    hull.triangles.reserve(3 * (faces.vertices.size() - 2 * faces.size()));
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const std::uint32_t* corners = &faces.vertices[faces.offsets[f]];
        const std::size_t m = faces.offsets[f + 1] - faces.offsets[f];
        for (std::size_t k = 1; k + 1 < m; ++k) {
            hull.triangles.insert(hull.triangles.end(), {corners[0], corners[k], corners[k + 1]});
        }
    }
    if (faces.vertices.size() < point_count / 16) {  // few corners: sorting them is cheaper
        hull.vertices = faces.vertices;
        std::sort(hull.vertices.begin(), hull.vertices.end());
        hull.vertices.erase(std::unique(hull.vertices.begin(), hull.vertices.end()), hull.vertices.end());
        return;
    }
    std::vector<std::uint8_t> is_vertex(point_count, 0);
    for (std::uint32_t v : faces.vertices) is_vertex[v] = 1;
    hull.vertices.clear();
    for (std::uint32_t i = 0; i < point_count; ++i) {
        if (is_vertex[i]) hull.vertices.push_back(i);
    }
}

/// Volume and area measured on points scaled by 2^exponent, given back in the caller's units.
void unscale(int exponent, double volume, double area, Hull& hull) {
    hull.volume = std::ldexp(volume, -3 * exponent);
    hull.area = std::ldexp(area, -2 * exponent);
}

Hull lower_dimensional(PointSpan points, const Simplex& s, int exponent) {
    Hull hull;
    hull.dimension = s.dimension;
    if (s.dimension < 0) return hull;  // no points
    if (s.dimension == 0) {
        hull.vertices = {s.p[0]};
        return hull;
    }
    if (s.dimension == 1) {
        // Along the axis where the segment moves most, coordinates order the points on the line.
        const glm::dvec3 d = glm::abs(detail::vec3(points[s.p[1]]) - detail::vec3(points[s.p[0]]));
        const int axis = d.x >= d.y ? (d.x >= d.z ? 0 : 2) : (d.y >= d.z ? 1 : 2);
        std::uint32_t lo = 0, hi = 0;
        for (std::uint32_t i = 1; i < points.count; ++i) {
            if (points[i][axis] < points[lo][axis]) lo = i;
            if (points[i][axis] > points[hi][axis]) hi = i;
        }
        hull.vertices = {std::min(lo, hi), std::max(lo, hi)};
        return hull;
    }
    // A convex polygon in the plane of the simplex's first three points, seen from the side where
    // the normal's largest component is positive (so the orientation does not depend on which
    // three points span the plane): the sign of that component is an exact orient2d.
    std::uint32_t a = s.p[0], b = s.p[1], c = s.p[2];
    int i = 0, j = 0;
    if (detail::plane_projection(detail::ExactSides{}, points[a], points[b], points[c], &i, &j) < 0) std::swap(b, c);
    std::vector<std::uint32_t> all(points.count), polygon;
    std::iota(all.begin(), all.end(), 0u);
    detail::convex_polygon(points, detail::ExactSides{}, std::move(all), a, b, c, polygon);
    Polygons faces;
    faces.add(polygon.begin(), polygon.end());
    rotate_to_lowest(faces);
    fill_from_polygons(points.count, faces, hull);
    hull.vertices = faces.vertices;  // in order around the polygon
    double volume = 0.0, area = 0.0;
    detail::measure(points, faces, &volume, &area);
    unscale(exponent, 0.0, area, hull);  // flat: no volume, the area of one side
    const glm::dvec3 origin = detail::vec3(points[a]);
    const glm::dvec3 normal = glm::cross(detail::vec3(points[b]) - origin, detail::vec3(points[c]) - origin);
    const glm::dvec3 unit = glm::normalize(normal);
    std::copy(&unit.x, &unit.x + 3, hull.normal);
    return hull;
}

}  // namespace

Hull hull(PointSpan input, const HullOptions& options) {
    int exponent = 0;
    if (Hull invalid = check_input(input, &exponent); !invalid.ok()) return invalid;
    const bool seed = options.side_test == SideTest::Seed;
    if (seed && options.algorithm != Algorithm::Giftwrap)
        return detail::failure("the seed's epsilon side tests exist for gift wrapping only");

    std::vector<double> scaled;
    PointSpan points = input;
    if (exponent != 0) {  // multiplying by a power of two is exact
        scaled.resize(3 * input.count);
        for (std::size_t i = 0; i < scaled.size(); ++i) scaled[i] = std::ldexp(input.xyz[i], exponent);
        points = PointSpan(scaled.data(), input.count);
    }

    Polygons faces;
    double volume = 0.0, area = 0.0;
    std::string error;
    if (seed) {
        // The seed's own behaviour, for comparison: its epsilon also judges degeneracy.
        if (points.count < 4) return detail::failure("a 3D hull needs at least 4 points, got " + std::to_string(points.count));
        if (!detail::giftwrap_faces(points, options.giftwrap_scan, true, faces, error)) return detail::failure(error);
        detail::measure(points, faces, &volume, &area);
    } else {
        const Simplex simplex = detail::find_simplex(points);
        if (simplex.dimension < 3) {
            Hull result = lower_dimensional(points, simplex, exponent);
            if (options.merge_coplanar && result.dimension == 2) {
                result.face_offsets = {0, static_cast<std::uint32_t>(result.vertices.size())};
                result.face_vertices = result.vertices;
            }
            return result;
        }
        if (options.algorithm == Algorithm::Giftwrap) {
            if (!detail::giftwrap_faces(points, options.giftwrap_scan, false, faces, error)) return detail::failure(error);
            detail::measure(points, faces, &volume, &area);
        } else if (!detail::quickhull_faces(points, simplex, faces, &volume, &area, error)) {
            return detail::failure(error);
        }
    }

    Hull result;
    result.dimension = 3;
    rotate_to_lowest(faces);
    fill_from_polygons(points.count, faces, result);
    unscale(exponent, volume, area, result);
    if (options.merge_coplanar) {
        result.face_offsets = std::move(faces.offsets);
        result.face_vertices = std::move(faces.vertices);
    }
    return result;
}

Hull giftwrap(PointSpan points, GiftwrapScan scan) {
    HullOptions options;
    options.algorithm = Algorithm::Giftwrap;
    options.giftwrap_scan = scan;
    return hull(points, options);
}

const char* algorithm_name(Algorithm algorithm) {
    switch (algorithm) {
        case Algorithm::Quickhull:
            return "quickhull";
        case Algorithm::Giftwrap:
            return "giftwrap";
    }
    return "unknown";
}

bool parse_algorithm(const std::string& name, Algorithm* out) {
    if (name == "quickhull") {
        *out = Algorithm::Quickhull;
        return true;
    }
    if (name == "giftwrap") {
        *out = Algorithm::Giftwrap;
        return true;
    }
    return false;
}

}  // namespace hullkit
