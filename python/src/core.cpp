// hullkit._core: the C++ core for Python (pybind11). Thin: numpy arrays in (float64, C order;
// the Python layer converts once and checks shapes), numpy arrays out that own the core's vectors
// (moved, not copied); the Python package (hullkit/__init__.py, spatial.py, dask.py) shapes the
// API. Long calls release the GIL. Errors from the core raise CoreError(message, point), which the
// Python layer turns into hullkit.HullkitError.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <limits>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <numeric>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "hullkit/constrained.hpp"
#include "hullkit/delaunay.hpp"
#include "hullkit/delaunay3.hpp"
#include "hullkit/hull.hpp"
#include "hullkit/hull_nd.hpp"
#include "hullkit/mesh_read.hpp"
#include "hullkit/point_reader.hpp"
#include "hullkit/predicates.hpp"
#include "hullkit/route.hpp"
#include "hullkit/scene_io.hpp"
#include "hullkit/verify.hpp"

namespace py = pybind11;

namespace {

using Points = py::array_t<double, py::array::c_style>;

/// A numpy array of `shape` that takes over `values` (no copy): the vector lives in a capsule
/// that the array keeps alive.
template <class T>
py::array_t<T> owned(std::vector<T>&& values, std::vector<py::ssize_t> shape = {}) {
    auto* heap = new std::vector<T>(std::move(values));
    py::capsule keeper(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    if (shape.empty()) shape = {static_cast<py::ssize_t>(heap->size())};
    return py::array_t<T>(shape, heap->data(), keeper);
}

/// (n, 3) float64 from a flat x y z vector.
py::array_t<double> owned_points(std::vector<double>&& xyz, py::ssize_t dims = 3) {
    const auto n = static_cast<py::ssize_t>(xyz.size()) / dims;
    return owned(std::move(xyz), {n, dims});
}

/// Threads that are joined however the scope is left (an exception such as bad_alloc included:
/// a std::thread destroyed unjoined ends the process).
struct JoinedThreads {
    std::vector<std::thread> threads;
    ~JoinedThreads() {
        for (std::thread& t : threads) {
            if (t.joinable()) t.join();
        }
    }
};

/// Linear interpolation from located queries: out[i, c] = sum over the simplex's corners k of
/// weights[i, k] * values[corner k, c], corner by corner in order (so a query at a corner, weights
/// exactly 1 and 0, gets that corner's value exactly); NaN outside (simplex -1). On a few threads
/// in blocks of rows (each row written once: any split gives the same bits). `corners` holds
/// `count` indices per simplex.
py::array_t<double> blend_values(const std::vector<std::int32_t>& simplex, const std::vector<double>& weights,
                                 const std::uint32_t* corners, std::size_t count, const Points& values) {
    const std::size_t m = simplex.size();
    const auto columns = static_cast<std::size_t>(values.shape(1));
    py::array_t<double> out({static_cast<py::ssize_t>(m), static_cast<py::ssize_t>(columns)});
    double* o = out.mutable_data();
    const double* v = values.data();
    auto fill = [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            double* row = o + i * columns;
            if (simplex[i] < 0) {
                std::fill(row, row + columns, std::numeric_limits<double>::quiet_NaN());
                continue;
            }
            const std::uint32_t* c = corners + count * static_cast<std::size_t>(simplex[i]);
            const double* w = &weights[count * i];
            for (std::size_t j = 0; j < columns; ++j) {
                double total = w[0] * v[c[0] * columns + j];
                for (std::size_t k = 1; k < count; ++k) total += w[k] * v[c[k] * columns + j];
                row[j] = total;
            }
        }
    };
    py::gil_scoped_release unlocked;
    const std::size_t parts = m < (std::size_t{1} << 16) ? 1 : std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 4);
    JoinedThreads workers;
    for (std::size_t k = 1; k < parts; ++k) workers.threads.emplace_back(fill, m * k / parts, m * (k + 1) / parts);
    fill(0, m / parts);
    return out;
}

struct CoreError : std::runtime_error {
    CoreError(const std::string& message, std::int64_t point_) : std::runtime_error(message), point(point_) {}
    std::int64_t point;
};

std::size_t rows(const Points& points, py::ssize_t dims, const char* what) {
    if (points.ndim() != 2 || points.shape(1) != dims)
        throw std::invalid_argument(std::string(what) + " must have shape (n, " + std::to_string(dims) + ")");
    return static_cast<std::size_t>(points.shape(0));
}

/// Fails unless `values` has one row per point (of `points`): (n, k).
void check_values(const Points& values, const Points& points) {
    if (values.ndim() != 2 || values.shape(0) != points.shape(0))
        throw std::invalid_argument("values must have shape (" + std::to_string(points.shape(0)) + ", k)");
}

/// A core point location (delaunay_locate or delaunay3_locate, given as `locate(data, count,
/// options)`) on (q, Dims) queries with the GIL released; its error raised as CoreError.
template <std::size_t Dims, class Options, class Locate>
auto run_locate(const Points& queries, bool barycentric, bool nearest, unsigned threads, Locate locate) {
    const std::size_t n = rows(queries, static_cast<py::ssize_t>(Dims), "queries");
    Options options;
    options.barycentric = barycentric;
    options.nearest = nearest;
    options.threads = threads;
    decltype(locate(queries.data(), n, options)) found;
    {
        py::gil_scoped_release unlocked;
        found = locate(queries.data(), n, options);
    }
    if (!found.ok()) throw CoreError(found.error, found.error_query);
    return found;
}

/// A locate's answers as Python's (simplex, barycentric (q, Corners) or None, nearest or None).
template <std::size_t Corners, class Queries>
py::tuple located_tuple(std::vector<std::int32_t>&& simplex, Queries& found, bool barycentric, bool nearest) {
    py::object weights = py::none(), near = py::none();
    if (barycentric) weights = owned_points(std::move(found.barycentric), Corners);
    if (nearest) near = owned(std::move(found.nearest));
    return py::make_tuple(owned(std::move(simplex)), weights, near);
}

py::dict hull_dict(hullkit::Hull&& result) {
    py::dict out;
    out["dimension"] = result.dimension;
    out["triangles"] = owned(std::move(result.triangles));
    out["vertices"] = owned(std::move(result.vertices));
    out["face_offsets"] = owned(std::move(result.face_offsets));
    out["face_vertices"] = owned(std::move(result.face_vertices));
    out["normal"] = py::make_tuple(result.normal[0], result.normal[1], result.normal[2]);
    out["volume"] = result.volume;
    out["area"] = result.area;
    return out;
}

hullkit::HullOptions hull_options(const std::string& algorithm, bool merge_coplanar, unsigned threads) {
    hullkit::HullOptions options;
    if (!hullkit::parse_algorithm(algorithm, &options.algorithm))
        throw std::invalid_argument("unknown algorithm \"" + algorithm + "\" (quickhull or giftwrap)");
    options.merge_coplanar = merge_coplanar;
    options.threads = threads;
    return options;
}

py::dict hull(const Points& points, const std::string& algorithm, bool merge_coplanar, unsigned threads) {
    const hullkit::PointSpan span(points.data(), rows(points, 3, "points"));
    const hullkit::HullOptions options = hull_options(algorithm, merge_coplanar, threads);
    hullkit::Hull result;
    {
        py::gil_scoped_release unlocked;  // the arrays are only read; other Python threads may run
        result = hullkit::hull(span, options);
    }
    if (!result.ok()) throw CoreError(result.error, result.error_point);
    return hull_dict(std::move(result));
}

py::dict report_dict(const hullkit::VerifyReport& report) {
    py::dict out;
    out["ok"] = report.ok;
    out["problems"] = report.lines();
    out["problem_count"] = report.problem_count;
    out["notes"] = report.notes;
    out["checked_points"] = report.checked_points;
    out["triangle_count"] = report.triangle_count;
    out["vertex_count"] = report.vertex_count;
    out["face_count"] = report.face_count;
    out["dimension"] = report.dimension;
    return out;
}

/// Checks triangles (m, 3) as the hull of points with volume.
py::dict verify_triangles(const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& triangles) {
    const hullkit::PointSpan span(points.data(), rows(points, 3, "points"));
    if (triangles.ndim() != 2 || triangles.shape(1) != 3) throw std::invalid_argument("triangles must have shape (m, 3)");
    hullkit::VerifyReport report;
    {
        py::gil_scoped_release unlocked;
        report = hullkit::verify(span, triangles.data(), static_cast<std::size_t>(triangles.shape(0)));
    }
    return report_dict(report);
}

/// Checks a hull result (the dict hull() returned) of any dimension.
py::dict verify_hull(const Points& points, const py::dict& result) {
    const hullkit::PointSpan span(points.data(), rows(points, 3, "points"));
    hullkit::Hull h;
    h.dimension = result["dimension"].cast<int>();
    h.triangles = result["triangles"].cast<std::vector<std::uint32_t>>();
    h.vertices = result["vertices"].cast<std::vector<std::uint32_t>>();
    h.face_offsets = result["face_offsets"].cast<std::vector<std::uint32_t>>();
    h.face_vertices = result["face_vertices"].cast<std::vector<std::uint32_t>>();
    const auto normal = result["normal"].cast<std::vector<double>>();
    for (std::size_t k = 0; k < 3 && k < normal.size(); ++k) h.normal[k] = normal[k];
    h.volume = result["volume"].cast<double>();
    h.area = result["area"].cast<double>();
    hullkit::VerifyReport report;
    {
        py::gil_scoped_release unlocked;
        report = hullkit::verify(span, h);
    }
    return report_dict(report);
}


/// The furthest-site Delaunay triangulation of 2D points, from their hull cycle `hull` (the
/// indices of the points on the hull's boundary, in order either way): the triangulation of the
/// hull's strictly convex corners whose triangles' circumcircles hold every corner (inside or on),
/// i.e. the upper hull of the points lifted to the paraboloid. Exact: the corners by orient2d,
/// the triangles by Lawson's flips from the fan of the lowest-indexed corner, flipping while an
/// edge's opposite corner lies strictly outside a circle (incircle); each flip raises the lifted
/// surface, so they end, at the unique answer up to cocircular ties (which keep the fan's edges).
/// Returns (triangles (m, 3) int32, counter-clockwise (y up), each from its lowest index and
/// sorted; neighbors (m, 3) int32, across from each corner, -1 on the hull; group (m,) int32:
/// triangles whose circumcircles coincide exactly, joined across their edges, share a number
/// (0, 1, ... by first triangle); centres (groups, 2): each group's circumcentre; corners (h,)
/// int32: the corners counter-clockwise from the lowest index).
/// Constrained Delaunay triangulation: with `ring_starts` given (a polygon's rings) the triangles
/// inside by `fill`; else the graph of `segments`, then without `convex` its exterior removed and
/// the regions around `holes` (Triangle's .poly meaning), `regions` (k, 3: x, y, max_area) giving
/// regional area bounds. `quality` is (min_angle, max_area, conforming, max_steiner_points,
/// keep_segments, unsuitable): Delaunay refinement (unsuitable: None or Triangle's -u test, called
/// as unsuitable((ax, ay), (bx, by), (cx, cy), area) -> bool). Returns (coords (m, 2), triangles (t, 3) clockwise, halfedges, constrained,
/// representative, crossing_count, steiner_count, unrefined_count, triangle_region (t,) int32: each
/// triangle's region row, -1 for none; empty without regions). With `mesh` ((t, 3) uint32 corner
/// triples, not None) the triangulation is refined instead (Triangle's -r: refine_mesh, `segments`
/// kept inside, ring_starts, holes and regions unused), `mesh_areas` None or (t,) float64 bounds per
/// triangle (then triangle_region is each output triangle's input triangle).
py::tuple constrained(const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& segments,
                      py::object ring_starts, const std::string& fill, bool convex, const Points& holes,
                      const Points& regions, double min_angle, double max_area, bool conforming,
                      std::size_t max_steiner_points, unsigned keep_segments, py::object unsuitable,
                      py::object mesh, py::object mesh_areas) {
    const std::size_t n = rows(points, 2, "points");
    const hullkit::PointSpan2 span(points.data(), n);
    hullkit::QualityOptions quality;
    quality.min_angle = min_angle;
    quality.max_area = max_area;
    quality.conforming = conforming;
    quality.max_steiner_points = max_steiner_points;
    quality.keep_segments = keep_segments;
    // Triangle's -u: the callable, called with the GIL for each triangle tested; the first
    // exception it raises stops further calls (they answer false) and is raised once the core returns.
    std::unique_ptr<py::error_already_set> raised;
    if (!unsuitable.is_none()) {
        quality.unsuitable = [&unsuitable, &raised](const double* a, const double* b, const double* c, double area) {
            if (raised) return false;
            py::gil_scoped_acquire gil;
            try {
                return py::cast<bool>(unsuitable(py::make_tuple(a[0], a[1]), py::make_tuple(b[0], b[1]), py::make_tuple(c[0], c[1]), area));
            } catch (py::error_already_set& error) {
                raised = std::make_unique<py::error_already_set>(std::move(error));
            } catch (const py::cast_error&) {
                PyErr_SetString(PyExc_TypeError, "unsuitable must return True or False");
                raised = std::make_unique<py::error_already_set>();
            }
            return false;
        };
    }
    hullkit::ConstrainedDelaunay d;
    if (!mesh.is_none()) {
        const auto corners = mesh.cast<py::array_t<std::uint32_t, py::array::c_style>>();
        hullkit::RefineMeshOptions options;
        options.quality = quality;
        if (!mesh_areas.is_none()) {
            const auto areas = mesh_areas.cast<py::array_t<double, py::array::c_style>>();
            options.triangle_max_area.assign(areas.data(), areas.data() + areas.size());
        }
        py::gil_scoped_release release;
        d = hullkit::refine_mesh(span, corners.data(), static_cast<std::size_t>(corners.size()) / 3, segments.data(),
                                 static_cast<std::size_t>(segments.size()) / 2, options);
    } else if (!ring_starts.is_none()) {
        const auto starts = ring_starts.cast<py::array_t<std::uint32_t, py::array::c_style>>();
        hullkit::PolygonOptions options;
        options.quality = quality;
        if (!hullkit::parse_fill_rule(fill, &options.fill)) throw std::invalid_argument("fill must be 'evenodd' or 'nonzero', got '" + fill + "'");
        py::gil_scoped_release release;
        d = hullkit::triangulate_polygon(span, starts.data(), static_cast<std::size_t>(starts.size()), options);
    } else {
        hullkit::ConstrainedOptions options;
        options.quality = quality;
        options.remove_exterior = !convex;
        const std::size_t h = rows(holes, 2, "holes");
        options.holes.assign(holes.data(), holes.data() + 2 * h);
        const std::size_t r = rows(regions, 3, "regions");
        for (std::size_t k = 0; k < r; ++k)
            options.regions.push_back({regions.data()[3 * k], regions.data()[3 * k + 1], regions.data()[3 * k + 2]});
        py::gil_scoped_release release;
        d = hullkit::constrained_delaunay(span, segments.data(), static_cast<std::size_t>(segments.size()) / 2, options);
    }
    if (raised) throw std::move(*raised);
    if (!d.ok()) throw CoreError(d.error, d.error_point >= 0 ? d.error_point : -1);
    const auto triangles = static_cast<py::ssize_t>(d.triangle_count());
    const std::size_t crossings = d.crossing_count, steiner = d.steiner_count, unrefined = d.unrefined_count;
    return py::make_tuple(owned_points(std::move(d.coords), 2), owned(std::move(d.triangles), {triangles, 3}),
                          owned(std::move(d.halfedges)), owned(std::move(d.constrained)), owned(std::move(d.representative)),
                          crossings, steiner, unrefined, owned(std::move(d.triangle_region)));
}

py::tuple furthest_delaunay(const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& hull) {
    const std::size_t n = rows(points, 2, "points");
    const std::size_t count = static_cast<std::size_t>(hull.size());
    const std::uint32_t* cycle = hull.data();
    for (std::size_t k = 0; k < count; ++k) {
        if (cycle[k] >= n) throw std::invalid_argument("hull index out of range");
    }
    // The corners' coordinates, scaled by one power of two into incircle's exact range.
    double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < count; ++k) {
        for (int axis = 0; axis < 2; ++axis) {
            const double magnitude = std::fabs(points.data()[2 * cycle[k] + axis]);
            if (!std::isfinite(magnitude)) throw std::invalid_argument("coordinates must be finite");
            largest = std::max(largest, magnitude);
            if (magnitude != 0.0) smallest = std::min(smallest, magnitude);
        }
    }
    int exponent = 0;
    if (!hullkit::incircle_range_ok(largest, smallest) && !hullkit::incircle_scale_exponent(largest, smallest, &exponent))
        throw std::invalid_argument("the nonzero |coordinates| span more than the exact in-circle test's range");
    auto at = [&](std::uint32_t i, int axis) { return std::ldexp(points.data()[2 * i + axis], exponent); };
    auto orient = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        return hullkit::orient2d(at(a, 0), at(a, 1), at(b, 0), at(b, 1), at(c, 0), at(c, 1));
    };
    auto incircle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        return hullkit::incircle(at(a, 0), at(a, 1), at(b, 0), at(b, 1), at(c, 0), at(c, 1), at(d, 0), at(d, 1));
    };
    // The strictly convex corners (a point inside a hull edge is no vertex: lifted, it lies below).
    std::vector<std::uint32_t> corners;
    int turn = 0;
    for (std::size_t k = 0; k < count && count >= 3; ++k) {
        const int o = orient(cycle[(k + count - 1) % count], cycle[k], cycle[(k + 1) % count]);
        if (o != 0) corners.push_back(cycle[k]), turn = o;
    }
    if (turn < 0) std::reverse(corners.begin(), corners.end());
    if (!corners.empty()) std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    const std::size_t h = corners.size();
    std::vector<std::uint32_t> tri;    // 3 corners per triangle, counter-clockwise
    std::vector<std::int32_t> twin;    // per half-edge (corner k to k + 1 of its triangle)
    for (std::size_t i = 1; i + 1 < h; ++i) {
        tri.insert(tri.end(), {corners[0], corners[i], corners[i + 1]});
        twin.insert(twin.end(), {-1, -1, -1});
        if (i > 1) {  // the fan: edge corners[i] -> corners[0] of triangle i - 1 meets 0 -> i of triangle i
            const std::int32_t previous = static_cast<std::int32_t>(3 * (i - 2) + 2), current = static_cast<std::int32_t>(3 * (i - 1));
            twin[previous] = current, twin[current] = previous;
        }
    }
    auto next = [](std::int32_t e) { return e % 3 == 2 ? e - 2 : e + 1; };
    auto prev = [](std::int32_t e) { return e % 3 == 0 ? e + 2 : e - 1; };
    auto link = [&](std::int32_t a, std::int32_t b) {
        twin[a] = b;
        if (b >= 0) twin[b] = a;
    };
    std::vector<std::int32_t> stack;
    for (std::int32_t e = 0; e < static_cast<std::int32_t>(twin.size()); ++e) {
        if (twin[e] > e) stack.push_back(e);
    }
    while (!stack.empty()) {
        const std::int32_t a = stack.back();
        stack.pop_back();
        const std::int32_t b = twin[a];
        if (b < 0) continue;
        // Triangle (pr, pl, p0) on half-edge a = pr -> pl, and (pl, pr, p1) across it.
        const std::int32_t al = next(a), ar = prev(a), bl = prev(b), br = next(b);
        const std::uint32_t pr = tri[a], pl = tri[al], p0 = tri[ar], p1 = tri[bl];
        if (incircle(pr, pl, p0, p1) >= 0) continue;  // p1 inside or on the circle: furthest-legal
        tri[a] = p1, tri[b] = p0;                      // now (p1, pl, p0) and (p0, pr, p1)
        const std::int32_t hbl = twin[bl], har = twin[ar];
        link(a, hbl), link(b, har), link(ar, bl);
        stack.insert(stack.end(), {a, al, b, br});
    }
    // Canonical: each triangle from its lowest corner, the triangles sorted.
    const std::size_t m = tri.size() / 3;
    std::vector<std::uint32_t> shift(m);
    for (std::size_t t = 0; t < m; ++t) {
        const std::uint32_t* c = &tri[3 * t];
        shift[t] = c[1] < c[0] && c[1] < c[2] ? 1 : c[2] < c[0] && c[2] < c[1] ? 2 : 0;
    }
    auto corner_of = [&](std::size_t t, std::size_t k) { return tri[3 * t + (shift[t] + k) % 3]; };
    std::vector<std::uint32_t> order(m);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t u, std::uint32_t v) {
        for (std::size_t k = 0; k < 3; ++k) {
            if (corner_of(u, k) != corner_of(v, k)) return corner_of(u, k) < corner_of(v, k);
        }
        return false;
    });
    std::vector<std::int32_t> slot(m);
    for (std::size_t q = 0; q < m; ++q) slot[order[q]] = static_cast<std::int32_t>(q);
    std::vector<std::int32_t> triangles(3 * m), neighbors(3 * m, -1);
    for (std::size_t q = 0; q < m; ++q) {
        const std::size_t t = order[q];
        for (std::size_t k = 0; k < 3; ++k) {
            triangles[3 * q + k] = static_cast<std::int32_t>(corner_of(t, k));
            // Across from corner k: the half-edge from corner k + 1 to k + 2.
            const std::int32_t e = twin[3 * t + (shift[t] + k + 1) % 3];
            neighbors[3 * q + k] = e < 0 ? -1 : slot[e / 3];
        }
    }
    // Groups: triangles joined across edges whose far corner is exactly on the circle.
    std::vector<std::int32_t> parent(m);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](std::int32_t t) {
        while (parent[t] != t) t = parent[t] = parent[parent[t]];
        return t;
    };
    for (std::size_t q = 0; q < m; ++q) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::int32_t other = neighbors[3 * q + k];
            if (other < static_cast<std::int32_t>(q)) continue;  // -1, or looked at from the other side
            const std::int32_t* c = &triangles[3 * q];
            const std::int32_t* d = &triangles[3 * other];
            const std::int64_t far = std::int64_t{d[0]} + d[1] + d[2] - c[(k + 1) % 3] - c[(k + 2) % 3];
            if (incircle(c[0], c[1], c[2], static_cast<std::uint32_t>(far)) == 0) {
                const std::int32_t r1 = find(static_cast<std::int32_t>(q)), r2 = find(other);
                parent[std::max(r1, r2)] = std::min(r1, r2);
            }
        }
    }
    std::vector<std::int32_t> group(m), number(m, -1);
    std::vector<double> centres;
    for (std::size_t q = 0; q < m; ++q) {
        const std::int32_t root = find(static_cast<std::int32_t>(q));
        if (number[root] < 0) {
            number[root] = static_cast<std::int32_t>(centres.size() / 2);
            centres.resize(centres.size() + 2);
            const double* xy = points.data();
            hullkit::circumcentre(xy + 2 * triangles[3 * q], xy + 2 * triangles[3 * q + 1], xy + 2 * triangles[3 * q + 2],
                          &centres[centres.size() - 2]);
        }
        group[q] = number[root];
    }
    std::vector<std::int32_t> corner_list(corners.begin(), corners.end());
    const auto rows_m = static_cast<py::ssize_t>(m);
    return py::make_tuple(owned(std::move(triangles), {rows_m, 3}), owned(std::move(neighbors), {rows_m, 3}),
                          owned(std::move(group)), owned_points(std::move(centres), 2), owned(std::move(corner_list)));
}

/// Points and facets for the exact side tests below: the coordinates of `points` (n, 2 or 3) and
/// of `queries` (k, same) in one array, scaled by one power of two when they leave the
/// predicates' exact range (scaling by 2^k changes no sign); `facets` (m, dims) checked.
struct FacetTests {
    std::size_t dims = 0, n = 0, m = 0, k = 0;
    const std::uint32_t* facets = nullptr;
    std::vector<double> xyz;

    FacetTests(const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& facet_array, const Points& queries) {
        if (points.ndim() != 2 || (points.shape(1) != 2 && points.shape(1) != 3))
            throw std::invalid_argument("points must have shape (n, 2) or (n, 3)");
        dims = static_cast<std::size_t>(points.shape(1));
        n = static_cast<std::size_t>(points.shape(0));
        if (facet_array.ndim() != 2 || static_cast<std::size_t>(facet_array.shape(1)) != dims)
            throw std::invalid_argument("facets must have shape (m, " + std::to_string(dims) + ")");
        if (queries.ndim() != 2 || static_cast<std::size_t>(queries.shape(1)) != dims)
            throw std::invalid_argument("queries must have shape (k, " + std::to_string(dims) + ")");
        m = static_cast<std::size_t>(facet_array.shape(0));
        k = static_cast<std::size_t>(queries.shape(0));
        facets = facet_array.data();
        for (std::size_t j = 0; j < dims * m; ++j) {
            if (facets[j] >= n) throw std::invalid_argument("facet corner out of range");
        }
        xyz.assign(points.data(), points.data() + dims * n);
        xyz.insert(xyz.end(), queries.data(), queries.data() + dims * k);
        double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
        for (double value : xyz) {
            if (!std::isfinite(value)) throw std::invalid_argument("coordinates must be finite");
            const double magnitude = std::fabs(value);
            largest = std::max(largest, magnitude);
            if (magnitude != 0.0) smallest = std::min(smallest, magnitude);
        }
        int exponent = 0;
        if (!hullkit::predicates_range_ok(largest, smallest) && !hullkit::predicates_scale_exponent(largest, smallest, &exponent))
            throw std::invalid_argument("the nonzero |coordinates| span more than the exact predicates' range");
        if (exponent != 0) {
            for (double& value : xyz) value = std::ldexp(value, exponent);
        }
    }

    /// +1 when query q is strictly outside facet f (right of a 2D edge a -> b; on the side a 3D
    /// triangle's normal points to), 0 on its line or plane, -1 inside.
    int side(std::size_t f, std::size_t q) const {
        const std::uint32_t* c = facets + dims * f;
        const double* p = xyz.data() + dims * (n + q);
        if (dims == 2) {
            const double* a = xyz.data() + 2 * c[0];
            const double* b = xyz.data() + 2 * c[1];
            return -hullkit::orient2d(a[0], a[1], b[0], b[1], p[0], p[1]);
        }
        return hullkit::orient3d(xyz.data() + 3 * c[0], xyz.data() + 3 * c[1], xyz.data() + 3 * c[2], p);
    }
};

/// The side of each hull facet each query lies on, exactly: (k, m) int8, +1 strictly outside,
/// 0 on the facet's line or plane, -1 inside (FacetTests::side). `points` (n, 2) with `facets`
/// (m, 2) a counter-clockwise polygon's edges, or (n, 3) with (m, 3) triangles counter-clockwise
/// seen from outside; `queries` (k, 2 or 3).
py::array_t<std::int8_t> facet_sides(const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& facets,
                                     const Points& queries) {
    const FacetTests tests(points, facets, queries);
    std::vector<std::int8_t> sides(tests.k * tests.m);
    {
        py::gil_scoped_release unlocked;
        for (std::size_t q = 0; q < tests.k; ++q) {
            for (std::size_t f = 0; f < tests.m; ++f) sides[q * tests.m + f] = static_cast<std::int8_t>(tests.side(f, q));
        }
    }
    return owned(std::move(sides), {static_cast<py::ssize_t>(tests.k), static_cast<py::ssize_t>(tests.m)});
}

/// For each query, the first facet whose line or plane holds it exactly (side 0), -1 for none:
/// (k,) int32. On a convex hull's facets (the queries inside the hull) that is the query lying on
/// the hull's boundary. O(k m) exact tests (a float filter decides nearly all of them).
py::array_t<std::int32_t> facet_holding(const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& facets,
                                        const Points& queries) {
    const FacetTests tests(points, facets, queries);
    std::vector<std::int32_t> holding(tests.k, -1);
    {
        py::gil_scoped_release unlocked;
        for (std::size_t q = 0; q < tests.k; ++q) {
            for (std::size_t f = 0; f < tests.m; ++f) {
                if (tests.side(f, q) == 0) {
                    holding[q] = static_cast<std::int32_t>(f);
                    break;
                }
            }
        }
    }
    return owned(std::move(holding));
}

/// Python lists of ints: for each r of `rows` (all groups when empty), [flat[offsets[r]], ...,
/// flat[offsets[r + 1] - 1]], after one empty list when `leading_empty` (scipy's Voronoi regions
/// and ridge vertices, Delaunay faces' corners). Each distinct value's int object is made once and
/// shared; ten times faster than numpy's tolist and slicing for millions of short lists.
py::list nested_lists(const py::array_t<std::int64_t, py::array::c_style>& flat,
                      const py::array_t<std::int64_t, py::array::c_style>& offsets,
                      const py::array_t<std::int64_t, py::array::c_style>& rows, bool leading_empty) {
    if (flat.ndim() != 1 || offsets.ndim() != 1 || rows.ndim() != 1 || offsets.shape(0) < 1)
        throw std::invalid_argument("nested_lists needs 1-D flat, offsets (at least one entry) and rows");
    const std::int64_t* f = flat.data();
    const std::int64_t* o = offsets.data();
    const auto groups = static_cast<std::size_t>(offsets.shape(0) - 1), size = static_cast<std::size_t>(flat.shape(0));
    const bool all = rows.shape(0) == 0;
    const std::size_t count = all ? groups : static_cast<std::size_t>(rows.shape(0));
    std::int64_t low = 0, high = -1;
    for (std::size_t k = 0; k < size; ++k) low = std::min(low, f[k]), high = std::max(high, f[k]);
    for (std::size_t g = 0; g < groups; ++g) {
        if (o[g] < 0 || o[g] > o[g + 1] || static_cast<std::size_t>(o[g + 1]) > size)
            throw std::invalid_argument("nested_lists: offsets must ascend within the flat array");
    }
    // Shared int objects when the values are few for their count (else one object per entry).
    const bool shared = high - low <= static_cast<std::int64_t>(4 * size + 1024);
    std::vector<py::object> number(shared ? static_cast<std::size_t>(high - low + 1) : 0);
    auto item = [&](std::int64_t v) {
        if (!shared) return PyLong_FromLongLong(v);
        py::object& slot = number[static_cast<std::size_t>(v - low)];
        if (!slot) slot = py::int_(v);
        return slot.inc_ref().ptr();
    };
    const std::size_t lead = leading_empty ? 1 : 0;
    py::list out(count + lead);
    if (lead) PyList_SET_ITEM(out.ptr(), 0, PyList_New(0));
    for (std::size_t k = 0; k < count; ++k) {
        const std::int64_t g = all ? static_cast<std::int64_t>(k) : rows.data()[k];
        if (g < 0 || static_cast<std::size_t>(g) >= groups) throw std::invalid_argument("nested_lists: row out of range");
        const std::int64_t begin = o[g], end = o[g + 1];
        PyObject* list = PyList_New(static_cast<py::ssize_t>(end - begin));
        if (!list) throw py::error_already_set();
        for (std::int64_t j = begin; j < end; ++j) PyList_SET_ITEM(list, static_cast<py::ssize_t>(j - begin), item(f[j]));
        PyList_SET_ITEM(out.ptr(), static_cast<py::ssize_t>(k + lead), list);
    }
    return out;
}

/// Pairs the half-edges that join the same two points: for half-edges h = 0 .. count - 1 with ends
/// lower(h) < n and higher(h) (the smaller and larger point index), calls pair(h, g) once for each
/// two with equal ends (a surface's twins; a half-edge without a partner, on the rim of an open
/// surface, is left alone). A counting sort by the lower end (in ascending half-edge order), then
/// each end's few by the higher (stable): partners are then neighbours, as in a sort by (lower,
/// higher, half-edge). A radix sort of 64-bit keys took 1.1 s for 2e6 triangles, mostly in its five
/// passes over 6e6 keys; this takes two.
template <class Lower, class Higher, class Pair>
void pair_half_edges(std::size_t n, std::size_t count, Lower lower, Higher higher, Pair pair) {
    std::vector<std::uint32_t> start(n + 1, 0);
    for (std::size_t h = 0; h < count; ++h) ++start[lower(h) + 1];
    for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    std::unique_ptr<std::uint32_t[]> order(new std::uint32_t[count]);  // every slot is written below
    {
        std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
        for (std::size_t h = 0; h < count; ++h) order[next[lower(h)]++] = static_cast<std::uint32_t>(h);
    }
    for (std::size_t i = 0; i < n; ++i) {
        std::uint32_t* first = order.get() + start[i];
        std::uint32_t* last = order.get() + start[i + 1];
        if (last - first > 32) {  // a point of high degree (a cone's apex, a fan's centre)
            std::stable_sort(first, last, [&](std::uint32_t a, std::uint32_t b) { return higher(a) < higher(b); });
        } else {
            for (std::uint32_t* a = first + 1; a < last; ++a) {  // insertion sort: a handful each
                const std::uint32_t h = *a;
                const auto key = higher(h);
                std::uint32_t* b = a;
                for (; b > first && higher(b[-1]) > key; --b) *b = b[-1];
                *b = h;
            }
        }
        for (std::uint32_t* a = first; a + 1 < last;) {
            if (higher(a[0]) != higher(a[1])) {
                ++a;
                continue;
            }
            pair(a[0], a[1]);
            a += 2;
        }
    }
}

/// scipy's ConvexHull extras for triangles (m, 3) of a closed (or open: -1 across the rim)
/// oriented surface: neighbors[t][j], the triangle across the edge opposite corner j, found by
/// matching each directed edge with its reverse through per-vertex lists (linear time); and
/// equations[t], the outward unit normal and offset of t's plane (hullkit::plane_equations, as
/// `hullkit hull --normals` and the JS result's `equations` give them).
py::tuple surface_extras(const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& triangles) {
    const std::size_t n = rows(points, 3, "points");
    if (triangles.ndim() != 2 || triangles.shape(1) != 3) throw std::invalid_argument("triangles must have shape (m, 3)");
    const std::size_t m = static_cast<std::size_t>(triangles.shape(0));
    const std::uint32_t* v = triangles.data();
    for (std::size_t k = 0; k < 3 * m; ++k) {
        if (v[k] >= n) throw std::invalid_argument("triangle corner out of range");
    }
    std::vector<std::int32_t> neighbors(3 * m, -1);
    std::vector<double> equations;
    const double* xyz = points.data();
    {
        py::gil_scoped_release unlocked;
        // The planes on a second thread, the neighbours on this one (the two write apart; each
        // value is computed the same way whichever thread computes it).
        JoinedThreads planes;
        // (The corners were checked above: plane_equations cannot throw here.)
        planes.threads.emplace_back([&] { equations = hullkit::plane_equations(hullkit::PointSpan(xyz, n), v, m); });
        auto lower = [v](std::size_t h) { return std::min(v[h], v[h - h % 3 + (h % 3 + 1) % 3]); };
        auto higher = [v](std::size_t h) { return std::max(v[h], v[h - h % 3 + (h % 3 + 1) % 3]); };
        pair_half_edges(n, 3 * m, lower, higher, [&](std::uint32_t h, std::uint32_t g) {
            // Across edge h (corners k, k + 1 of its triangle) lies g's triangle: opposite corner k + 2.
            neighbors[h - h % 3 + (h % 3 + 2) % 3] = static_cast<std::int32_t>(g / 3);
            neighbors[g - g % 3 + (g % 3 + 2) % 3] = static_cast<std::int32_t>(h / 3);
        });
    }
    const auto count = static_cast<py::ssize_t>(m);
    return py::make_tuple(owned(std::move(neighbors), {count, 3}), owned(std::move(equations), {count, 4}));
}

/// A streaming hull (hullkit::HullBuilder): pieces with 64-bit indices in, the hull of all out.
class Builder {
public:
    Builder(const std::string& algorithm, unsigned threads) : builder_(hull_options(algorithm, false, threads)) {}

    void add(const Points& points, std::uint64_t first_index) {
        const hullkit::PointSpan span(points.data(), rows(points, 3, "points"));
        bool ok = false;
        {
            py::gil_scoped_release unlocked;
            ok = builder_.add(span, first_index);
        }
        if (!ok) throw CoreError(builder_.error(), -1);
    }

    void add_indexed(const Points& points, const py::array_t<std::uint64_t, py::array::c_style>& indices) {
        const hullkit::PointSpan span(points.data(), rows(points, 3, "points"));
        if (indices.ndim() != 1 || static_cast<std::size_t>(indices.shape(0)) != span.count)
            throw std::invalid_argument("indices must have one entry per point");
        bool ok = false;
        {
            py::gil_scoped_release unlocked;
            ok = builder_.add_indexed(span, indices.data());
        }
        if (!ok) throw CoreError(builder_.error(), -1);
    }

    /// {"hull": hull dict over `points`, "points": (k, 3), "index": (k,) uint64, "point_count"}.
    py::dict finish() {
        hullkit::StreamedHull streamed;
        {
            py::gil_scoped_release unlocked;
            streamed = builder_.finish();
        }
        if (!streamed.ok()) throw CoreError(streamed.hull.error, -1);
        py::dict out;
        out["point_count"] = streamed.point_count;
        out["hull"] = hull_dict(std::move(streamed.hull));
        out["points"] = owned_points(std::move(streamed.points));
        out["index"] = owned(std::move(streamed.index));
        return out;
    }

    std::uint64_t points_added() const { return builder_.points_added(); }

private:
    hullkit::HullBuilder builder_;
};

/// A Delaunay triangulation with the points it was made from (kept alive, not copied).
class Triangulation {
public:
    Triangulation(Points points, const std::string& algorithm, bool merge_cocircular, unsigned threads)
        : points_(std::move(points)) {
        const hullkit::PointSpan2 span = this->span();
        hullkit::DelaunayOptions options;
        if (!hullkit::parse_delaunay_algorithm(algorithm, &options.algorithm))
            throw std::invalid_argument("unknown algorithm \"" + algorithm + "\" (incremental or giftwrap)");
        options.merge_cocircular = merge_cocircular;
        options.threads = threads;
        {
            py::gil_scoped_release unlocked;
            result_ = hullkit::delaunay(span, options);
        }
        if (!result_.ok()) throw CoreError(result_.error, result_.error_point);
    }

    hullkit::PointSpan2 span() const { return hullkit::PointSpan2(points_.data(), rows(points_, 2, "points")); }
    const hullkit::Delaunay& result() const { return result_; }
    const Points& points() const { return points_; }

    /// The nearest input point to each query (exact; ties to the lowest index), -1 without points.
    py::array_t<std::int64_t> find(const Points& queries, std::int64_t start) {
        const std::size_t n = rows(queries, 2, "queries");
        std::vector<std::int64_t> found(n, -1);
        if (result_.dimension >= 0) {
            py::gil_scoped_release unlocked;
            if (!locator_) locator_ = std::make_unique<hullkit::DelaunayLocator>(span(), result_);
            for (std::size_t i = 0; i < n; ++i) {
                found[i] = locator_->find(queries.data()[2 * i], queries.data()[2 * i + 1], i == 0 ? start : -1);
            }
        }
        return owned(std::move(found));
    }

    /// scipy.spatial.Delaunay's `simplices` and `neighbors` (int32, (m, 3)) in one pass: simplex i
    /// is triangle i with its corners in scipy's counter-clockwise order (hullkit's corners 0, 2,
    /// 1), and neighbors[i, j] is the simplex across the edge opposite corner j (hullkit's
    /// half-edge 3i + (1, 0, 2)[j]), -1 on the hull.
    py::tuple scipy_arrays() const {
        const std::vector<std::uint32_t>& tri = result_.triangles;
        const std::vector<std::int32_t>& twin = result_.halfedges;
        const std::size_t m = tri.size() / 3;
        const auto rows = static_cast<py::ssize_t>(m);
        py::array_t<std::int32_t> simplices({rows, py::ssize_t{3}}), neighbors({rows, py::ssize_t{3}});
        std::int32_t* corners = simplices.mutable_data();
        std::int32_t* across = neighbors.mutable_data();
        auto fill = [&](std::size_t begin, std::size_t end) {
            static constexpr int kCorner[3] = {0, 2, 1}, kEdge[3] = {1, 0, 2};
            for (std::size_t i = begin; i < end; ++i) {
                for (int j = 0; j < 3; ++j) {
                    corners[3 * i + j] = static_cast<std::int32_t>(tri[3 * i + kCorner[j]]);
                    const std::int32_t h = twin[3 * i + kEdge[j]];
                    across[3 * i + j] = h >= 0 ? h / 3 : -1;
                }
            }
        };
        {
            // Fresh memory costs a page fault per 4 KiB here: large arrays are filled by a few
            // threads in blocks of rows (each row is written once, so any split gives the same).
            py::gil_scoped_release unlocked;
            const std::size_t parts = m < (std::size_t{1} << 16) ? 1 : std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 4);
            JoinedThreads workers;
            for (std::size_t k = 1; k < parts; ++k) workers.threads.emplace_back(fill, m * k / parts, m * (k + 1) / parts);
            fill(0, m / parts);
        }
        return py::make_tuple(simplices, neighbors);
    }

    /// hullkit::delaunay_locate on (q, 2) queries: (triangle int32 (q,), barycentric (q, 3) or None,
    /// nearest int32 (q,) or None). The GIL is released while the core works.
    py::tuple locate(const Points& queries, bool barycentric, bool nearest, unsigned threads) const {
        hullkit::DelaunayQueries found = locate_queries(queries, barycentric, nearest, threads);
        return located_tuple<3>(std::move(found.triangle), found, barycentric, nearest);
    }

    /// Linear interpolation of (n, k) values at (q, 2) queries: (simplex int32 (q,), values (q, k),
    /// NaN outside the hull).
    py::tuple interpolate(const Points& queries, const Points& values, unsigned threads) const {
        check_values(values, points_);
        hullkit::DelaunayQueries found = locate_queries(queries, true, false, threads);
        py::array_t<double> out = blend_values(found.triangle, found.barycentric, result_.triangles.data(), 3, values);
        return py::make_tuple(owned(std::move(found.triangle)), out);
    }

    /// Clough-Tocher interpolation of (n, k) values with gradients (n, k, 2) at (q, 2) queries:
    /// (triangle int32 (q,), values (q, k), NaN outside the hull). Each triangle is split at its
    /// centroid C into three cubic Bezier patches: ordinates at the corners the values, next to
    /// them along the edges and toward C from the gradients, off each edge the one that makes the
    /// derivative across it linear along the edge (across, inside the hull: toward the neighbour's
    /// centroid; on the hull: from the edge's midpoint toward C), around C their averages.
    py::tuple clough_tocher(const Points& queries, const Points& values, const Points& gradients, unsigned threads) const {
        check_values(values, points_);
        const std::size_t points = static_cast<std::size_t>(points_.shape(0));
        const auto columns = static_cast<std::size_t>(values.shape(1));
        if (gradients.ndim() != 3 || static_cast<std::size_t>(gradients.shape(0)) != points ||
            static_cast<std::size_t>(gradients.shape(1)) != columns || gradients.shape(2) != 2)
            throw std::invalid_argument("gradients must have shape (" + std::to_string(points) + ", " + std::to_string(columns) + ", 2)");
        hullkit::DelaunayQueries found = locate_queries(queries, true, false, threads);
        const std::size_t n = found.triangle.size();
        py::array_t<double> out({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(columns)});
        double* o = out.mutable_data();
        const double* xy = points_.data();
        const double* f = values.data();
        const double* g = gradients.data();
        const std::vector<std::uint32_t>& tri = result_.triangles;
        const std::vector<std::int32_t>& twin = result_.halfedges;
        auto patch = [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                double* row = o + i * columns;
                const std::int32_t t = found.triangle[i];
                if (t < 0) {
                    std::fill(row, row + columns, std::numeric_limits<double>::quiet_NaN());
                    continue;
                }
                std::uint32_t v[3];
                double P[3][2], C[2] = {0, 0};
                for (int k = 0; k < 3; ++k) {
                    v[k] = tri[3 * static_cast<std::size_t>(t) + k];
                    P[k][0] = xy[2 * v[k]], P[k][1] = xy[2 * v[k] + 1];
                }
                C[0] = (P[0][0] + P[1][0] + P[2][0]) / 3, C[1] = (P[0][1] + P[1][1] + P[2][1]) / 3;
                // Per edge m (opposite corner m, from i = m + 1 to j = m + 2): alpha, beta, gamma of
                // the direction across it, as alpha (P_i - C) + beta (P_j - C).
                double alpha[3], beta[3];
                for (int m = 0; m < 3; ++m) {
                    const int a = (m + 1) % 3, b = (m + 2) % 3;
                    double d[2];
                    const std::int32_t across = twin[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(a)];
                    if (across >= 0) {
                        const std::size_t u = static_cast<std::size_t>(across) / 3;
                        for (int c = 0; c < 2; ++c)
                            d[c] = (xy[2 * tri[3 * u] + c] + xy[2 * tri[3 * u + 1] + c] + xy[2 * tri[3 * u + 2] + c]) / 3 - C[c];
                    } else {
                        for (int c = 0; c < 2; ++c) d[c] = C[c] - (P[a][c] + P[b][c]) / 2;
                    }
                    const double ax = P[a][0] - C[0], ay = P[a][1] - C[1], bx = P[b][0] - C[0], by = P[b][1] - C[1];
                    const double det = ax * by - ay * bx;
                    alpha[m] = (d[0] * by - d[1] * bx) / det;
                    beta[m] = (ax * d[1] - ay * d[0]) / det;
                }
                // The sub-triangle (P_i, P_j, C) opposite the corner m of least weight (the first).
                const double* w = &found.barycentric[3 * i];
                const int m = w[1] < w[0] ? (w[2] < w[1] ? 2 : 1) : (w[2] < w[0] ? 2 : 0);
                const int a = (m + 1) % 3, b = (m + 2) % 3;
                const double s = w[a] - w[m], r = w[b] - w[m], q = 3 * w[m];
                for (std::size_t c = 0; c < columns; ++c) {
                    double F[3], centre[3], along_i[3], along_j[3], T[3];
                    const auto grad = [&](int k, const double* e) {
                        const double* gk = g + (static_cast<std::size_t>(v[k]) * columns + c) * 2;
                        return gk[0] * e[0] + gk[1] * e[1];
                    };
                    for (int k = 0; k < 3; ++k) {
                        F[k] = f[static_cast<std::size_t>(v[k]) * columns + c];
                        const double e[2] = {C[0] - P[k][0], C[1] - P[k][1]};
                        centre[k] = F[k] + grad(k, e) / 3;
                    }
                    for (int e = 0; e < 3; ++e) {
                        const int ei = (e + 1) % 3, ej = (e + 2) % 3;
                        const double edge[2] = {P[ej][0] - P[ei][0], P[ej][1] - P[ei][1]};
                        along_i[e] = F[ei] + grad(ei, edge) / 3;
                        along_j[e] = F[ej] - grad(ej, edge) / 3;
                        const double gamma = -alpha[e] - beta[e];
                        const double k0 = alpha[e] * F[ei] + beta[e] * along_i[e] + gamma * centre[ei];
                        const double k2 = alpha[e] * along_j[e] + beta[e] * F[ej] + gamma * centre[ej];
                        T[e] = ((k0 + k2) / 2 - alpha[e] * along_i[e] - beta[e] * along_j[e]) / gamma;
                    }
                    double D[3];
                    for (int k = 0; k < 3; ++k) D[k] = (centre[k] + T[(k + 1) % 3] + T[(k + 2) % 3]) / 3;
                    const double S = (D[0] + D[1] + D[2]) / 3;
                    row[c] = s * s * s * F[a] + r * r * r * F[b] + q * q * q * S + 3 * s * s * r * along_i[m] +
                             3 * s * r * r * along_j[m] + 3 * s * s * q * centre[a] + 3 * r * r * q * centre[b] +
                             3 * s * q * q * D[a] + 3 * r * q * q * D[b] + 6 * s * r * q * T[m];
                }
            }
        };
        {
            py::gil_scoped_release unlocked;
            const std::size_t parts = n < (std::size_t{1} << 14) ? 1 : std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 4);
            JoinedThreads workers;
            for (std::size_t k = 1; k < parts; ++k) workers.threads.emplace_back(patch, n * k / parts, n * (k + 1) / parts);
            patch(0, n / parts);
        }
        return py::make_tuple(owned(std::move(found.triangle)), out);
    }

    /// hullkit::delaunay_gradients on (n, k) values: (gradients (n, k, 2), sweeps, converged).
    py::tuple gradients(const Points& values, double tolerance, unsigned max_iterations) const {
        check_values(values, points_);
        const auto columns = static_cast<std::size_t>(values.shape(1));
        hullkit::GradientOptions options;
        options.tolerance = tolerance;
        options.max_iterations = max_iterations;
        hullkit::DelaunayGradients found;
        {
            py::gil_scoped_release unlocked;
            found = hullkit::delaunay_gradients(span(), result_, values.data(), columns, options);
        }
        if (!found.ok()) throw CoreError(found.error, -1);
        const py::ssize_t n = points_.shape(0), k = static_cast<py::ssize_t>(columns);
        return py::make_tuple(owned(std::move(found.gradients), {n, k, 2}), found.iterations, found.converged);
    }

    /// scipy.spatial.Voronoi's arrays (hullkit::delaunay_voronoi_diagram, dimension 2): (vertices
    /// (V, 2); ridge_points (R, 2) int32, p < q; ridge_vertices (R, 2) int32: [the vertex across,
    /// the vertex], or [-1, vertex] for a ray; the regions as one flat int32 array and int64
    /// offsets (one region per distinct point, in the core's cell order): each counter-clockwise, a
    /// bounded one from its lowest vertex, an unbounded one with -1 last; point_region (n,) intp:
    /// each point's region, counting an empty one first when `infinity_region` (a repeated point
    /// its representative's); volumes (n,): each point's cell area, inf when unbounded).
    py::tuple scipy_voronoi(bool infinity_region) const {
        if (result_.dimension != 2) throw std::invalid_argument("scipy_voronoi needs a 2D triangulation");
        const std::size_t n = static_cast<std::size_t>(points_.shape(0));
        hullkit::VoronoiDiagram found;
        std::vector<py::ssize_t> point_region(n);
        std::vector<double> volumes(n);
        {
            py::gil_scoped_release unlocked;
            found = hullkit::delaunay_voronoi_diagram(span(), result_, 0);
            const py::ssize_t first = infinity_region ? 1 : 0;
            if (found.ok()) {
                for (std::size_t s = 0; s < n; ++s) {
                    const auto cell = static_cast<std::size_t>(found.point_cell[s]);
                    point_region[s] = static_cast<py::ssize_t>(cell) + first;
                    volumes[s] = found.areas[cell];
                }
            }
        }
        if (!found.ok()) throw CoreError(found.error, -1);
        const auto ridges = static_cast<py::ssize_t>(found.ridge_points.size() / 2);
        return py::make_tuple(owned_points(std::move(found.vertices), 2), owned(std::move(found.ridge_points), {ridges, 2}),
                              owned(std::move(found.ridge_vertices), {ridges, 2}), owned(std::move(found.cells)),
                              owned(std::move(found.cell_offsets)), owned(std::move(point_region)), owned(std::move(volumes)));
    }

    py::tuple voronoi(double xmin, double ymin, double xmax, double ymax) const {
        if (!(xmin < xmax) || !(ymin < ymax)) throw std::invalid_argument("voronoi bounds need xmin < xmax and ymin < ymax");
        hullkit::VoronoiCells cells = hullkit::delaunay_voronoi(span(), result_, xmin, ymin, xmax, ymax);
        return py::make_tuple(owned(std::move(cells.cell_offsets)), owned_points(std::move(cells.cell_xy), 2));
    }

private:
    /// hullkit::delaunay_locate on (q, 2) queries, the GIL released.
    hullkit::DelaunayQueries locate_queries(const Points& queries, bool barycentric, bool nearest, unsigned threads) const {
        return run_locate<2, hullkit::DelaunayQueryOptions>(queries, barycentric, nearest, threads,
                                                           [&](const double* xy, std::size_t n, const hullkit::DelaunayQueryOptions& o) {
                                                               return hullkit::delaunay_locate(span(), result_, hullkit::PointSpan2(xy, n), o);
                                                           });
    }

    Points points_;
    hullkit::Delaunay result_;
    std::unique_ptr<hullkit::DelaunayLocator> locator_;
};

/// An array viewing a vector inside a Triangulation or Tetrahedralization, which it keeps alive:
/// flat, or with `columns` (size / columns, columns).
template <class T>
py::array_t<T> view(const std::vector<T>& values, py::handle owner, py::ssize_t columns = 0) {
    const auto size = static_cast<py::ssize_t>(values.size());
    const auto item = static_cast<py::ssize_t>(sizeof(T));
    if (columns == 0) return py::array_t<T>({size}, {item}, values.data(), owner);
    return py::array_t<T>({size / columns, columns}, {columns * item, item}, values.data(), owner);
}

/// A read-only property of `Owner` (a Triangulation or Tetrahedralization): a view of the vector
/// `field` of its core result.
template <class Owner, class Result, class T>
auto result_view(std::vector<T> Result::*field, py::ssize_t columns = 0) {
    return [field, columns](py::object self) { return view(self.cast<const Owner&>().result().*field, self, columns); };
}

/// The fields the 2D and 3D Delaunay verifiers' reports share.
template <class Report>
py::dict delaunay_report_dict(const Report& report) {
    py::dict out;
    out["ok"] = report.ok;
    out["problems"] = report.problems;
    out["problem_count"] = report.problem_count;
    out["distinct_points"] = report.distinct_points;
    return out;
}

py::dict verify_delaunay(const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& triangles) {
    const hullkit::PointSpan2 span(points.data(), rows(points, 2, "points"));
    if (triangles.ndim() != 1 || triangles.shape(0) % 3 != 0)
        throw std::invalid_argument("triangles must be flat, 3 indices per triangle");
    hullkit::DelaunayVerifyReport report;
    {
        py::gil_scoped_release unlocked;
        report = hullkit::verify_delaunay(span, triangles.data(), static_cast<std::size_t>(triangles.shape(0) / 3));
    }
    py::dict out = delaunay_report_dict(report);
    out["hull_points"] = report.hull_points;
    return out;
}

/// A Delaunay tetrahedralization with the points it was made from (kept alive, not copied); its
/// arrays are views into the core's result, which they keep alive.
class Tetrahedralization {
public:
    Tetrahedralization(Points points, unsigned threads, bool furthest_site) : points_(std::move(points)) {
        const hullkit::PointSpan span(points_.data(), rows(points_, 3, "points"));
        hullkit::Delaunay3Options options;
        options.threads = threads;
        options.furthest_site = furthest_site;
        {
            py::gil_scoped_release unlocked;
            result_ = hullkit::delaunay3(span, options);
        }
        if (!result_.ok()) throw CoreError(result_.error, result_.error_point);
    }

    const hullkit::Delaunay3& result() const { return result_; }

    /// hullkit::delaunay3_locate on (q, 3) queries: (tetrahedron int32 (q,), barycentric (q, 4) or
    /// None, nearest int32 (q,) or None). The GIL is released while the core works.
    py::tuple locate(const Points& queries, bool barycentric, bool nearest, unsigned threads) const {
        hullkit::Delaunay3Queries found = locate_queries(queries, barycentric, nearest, threads);
        return located_tuple<4>(std::move(found.tetrahedron), found, barycentric, nearest);
    }

    /// Each point's Voronoi cell cut to the box [low, high] (3 each; every point in it, sides
    /// included): its volume, (n,) float64 (a repeated point's is its representative's). The cell
    /// is the box's six halfspaces and the halfspaces on the point's side of the bisector planes
    /// with its Delaunay neighbours; their polar dual about a point strictly inside the cell and the
    /// box (the point itself unless it is on the box) is hulled exactly (hullkit::hull on
    /// the rounded dual points, as hullkit.spatial.HalfspaceIntersection does), each dual face is a
    /// corner, and the volume is that of the exact hull of the corners. On `threads` threads, each
    /// cell's volume computed alone (the same bits for any count).
    py::array_t<double> clipped_volumes(const Points& low, const Points& high, unsigned threads) const {
        if (low.ndim() != 1 || low.shape(0) != 3 || high.ndim() != 1 || high.shape(0) != 3)
            throw std::invalid_argument("the box needs lower and upper corners of 3 coordinates");
        const double* lo = low.data();
        const double* hi = high.data();
        const std::size_t n = static_cast<std::size_t>(points_.shape(0));
        const double* xyz = points_.data();
        for (int a = 0; a < 3; ++a) {
            if (!(std::isfinite(lo[a]) && std::isfinite(hi[a]) && lo[a] < hi[a]))
                throw std::invalid_argument("the box needs finite lower < upper on every axis");
        }
        for (std::size_t i = 0; i < n; ++i) {
            for (int a = 0; a < 3; ++a) {
                if (!(xyz[3 * i + a] >= lo[a] && xyz[3 * i + a] <= hi[a]))
                    throw CoreError("point " + std::to_string(i) + " is outside the box", static_cast<std::int64_t>(i));
            }
        }
        std::vector<char> failed(n, 0);  // per point, so that the error names the lowest, whatever the threads
        std::vector<double> volume(n, 0.0);
        const hullkit::Delaunay3& r = result_;
        if (r.dimension != 3) throw std::invalid_argument("clipped volumes need points that span space");
        // Each point's Delaunay neighbours: both ends of every tetrahedron edge, sorted and unique.
        std::vector<std::vector<std::uint32_t>> neighbours(n);
        const std::size_t tets = r.tetrahedra.size() / 4;
        for (std::size_t t = 0; t < tets; ++t) {
            const std::uint32_t* c = &r.tetrahedra[4 * t];
            for (int i = 0; i < 4; ++i) {
                for (int j = 0; j < 4; ++j) {
                    if (i != j) neighbours[c[i]].push_back(c[j]);
                }
            }
        }
        {
            py::gil_scoped_release unlocked;
            auto cells = [&](std::size_t begin, std::size_t end) {
                std::vector<double> dual, corners;
                hullkit::HullOptions options;
                options.threads = 1;
                for (std::size_t i = begin; i < end; ++i) {
                    if (r.representative[i] != i) continue;
                    std::vector<std::uint32_t>& near = neighbours[i];
                    std::sort(near.begin(), near.end());
                    near.erase(std::unique(near.begin(), near.end()), near.end());
                    const double* site = xyz + 3 * i;
                    // The dual's centre p: the point itself, or, for a point on the box's boundary, a
                    // point a quarter of the way to its nearest neighbour's bisector, towards the
                    // box's centre (strictly inside both the cell and the box).
                    double p[3] = {site[0], site[1], site[2]};
                    bool on_box = false;
                    for (int a = 0; a < 3; ++a) on_box = on_box || site[a] == lo[a] || site[a] == hi[a];
                    if (on_box) {
                        double nearest = std::numeric_limits<double>::infinity();
                        for (std::uint32_t q : near) {
                            const double* o = xyz + 3 * q;
                            nearest = std::min(nearest, std::hypot(o[0] - site[0], o[1] - site[1], o[2] - site[2]));
                        }
                        double toward[3], length = 0;
                        for (int a = 0; a < 3; ++a) toward[a] = (lo[a] / 2 + hi[a] / 2) - site[a], length += toward[a] * toward[a];
                        length = std::sqrt(length);
                        const double step = std::min(nearest / 8, length / 2) / length;
                        for (int a = 0; a < 3; ++a) p[a] = site[a] + toward[a] * step;
                    }
                    // Halfspaces a . x <= b, shifted to p: a . y <= b - a . p = c, which must be > 0;
                    // their dual points a / c.
                    dual.clear();
                    bool inside = true;
                    auto add = [&](double ax, double ay, double az, double c) {
                        inside = inside && c > 0 && std::isfinite(1 / c);
                        dual.insert(dual.end(), {ax / c, ay / c, az / c});
                    };
                    for (std::uint32_t q : near) {
                        const double* o = xyz + 3 * q;
                        // (o - s) . x <= (|o|^2 - |s|^2) / 2, at p: (o - s) . (m - p) with m the midpoint.
                        const double d[3] = {o[0] - site[0], o[1] - site[1], o[2] - site[2]};
                        const double m[3] = {site[0] + d[0] / 2 - p[0], site[1] + d[1] / 2 - p[1], site[2] + d[2] / 2 - p[2]};
                        add(d[0], d[1], d[2], d[0] * m[0] + d[1] * m[1] + d[2] * m[2]);  // the bisector
                    }
                    for (int a = 0; a < 3; ++a) {
                        double e[3] = {0, 0, 0};
                        e[a] = 1;
                        add(e[0], e[1], e[2], hi[a] - p[a]);
                        e[a] = -1;
                        add(e[0], e[1], e[2], p[a] - lo[a]);
                    }
                    if (!inside) {  // the box too thin around the point for floating point
                        failed[i] = 1;
                        continue;
                    }
                    const hullkit::Hull h = hullkit::hull(hullkit::PointSpan(dual.data(), dual.size() / 3), options);
                    if (h.dimension != 3) continue;  // (cannot happen: the box alone bounds the cell)
                    corners.clear();
                    for (std::size_t f = 0; f < h.triangles.size() / 3; ++f) {
                        const double* a = &dual[3 * h.triangles[3 * f]];
                        const double* b = &dual[3 * h.triangles[3 * f + 1]];
                        const double* c = &dual[3 * h.triangles[3 * f + 2]];
                        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
                        const double nx = u[1] * v[2] - u[2] * v[1], ny = u[2] * v[0] - u[0] * v[2], nz = u[0] * v[1] - u[1] * v[0];
                        const double offset = nx * a[0] + ny * a[1] + nz * a[2];  // > 0: the origin is inside
                        corners.insert(corners.end(), {p[0] + nx / offset, p[1] + ny / offset, p[2] + nz / offset});
                    }
                    volume[i] = hullkit::hull(hullkit::PointSpan(corners.data(), corners.size() / 3), options).volume;
                }
            };
            const std::size_t parts = n < 256 ? 1 : std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, threads ? threads : 64);
            JoinedThreads workers;
            for (std::size_t k = 1; k < parts; ++k) workers.threads.emplace_back(cells, n * k / parts, n * (k + 1) / parts);
            cells(0, n / parts);
        }
        const auto bad = static_cast<std::int64_t>(std::find(failed.begin(), failed.end(), 1) - failed.begin());
        if (bad < static_cast<std::int64_t>(n))
            throw CoreError("point " + std::to_string(bad) + " is too close to the box's side for its cell to be cut", bad);
        for (std::size_t i = 0; i < n; ++i) volume[i] = volume[r.representative[i]];
        return owned(std::move(volume));
    }

    /// Linear interpolation of (n, k) values at (q, 3) queries: (simplex int32 (q,), values (q, k),
    /// NaN outside the hull).
    py::tuple interpolate(const Points& queries, const Points& values, unsigned threads) const {
        check_values(values, points_);
        hullkit::Delaunay3Queries found = locate_queries(queries, true, false, threads);
        py::array_t<double> out = blend_values(found.tetrahedron, found.barycentric, result_.tetrahedra.data(), 4, values);
        return py::make_tuple(owned(std::move(found.tetrahedron)), out);
    }

    /// hullkit::delaunay3_voronoi's arrays, in its field order: vertices (v, 3), tetrahedron_vertex,
    /// face_points (f, 2), face_offsets, face_vertices, face_bounded, cell_offsets, cell_faces, volume.
    py::tuple voronoi() const {
        hullkit::Voronoi3 v;
        {
            py::gil_scoped_release unlocked;
            v = hullkit::delaunay3_voronoi(span(), result_);
        }
        const auto faces = static_cast<py::ssize_t>(v.face_count());
        return py::make_tuple(owned_points(std::move(v.vertices)), owned(std::move(v.tetrahedron_vertex)),
                              owned(std::move(v.face_points), {faces, 2}), owned(std::move(v.face_offsets)),
                              owned(std::move(v.face_vertices)), owned(std::move(v.face_bounded)),
                              owned(std::move(v.cell_offsets)), owned(std::move(v.cell_faces)), owned(std::move(v.volume)));
    }

private:
    hullkit::PointSpan span() const { return hullkit::PointSpan(points_.data(), static_cast<std::size_t>(points_.shape(0))); }

    /// hullkit::delaunay3_locate on (q, 3) queries, the GIL released.
    hullkit::Delaunay3Queries locate_queries(const Points& queries, bool barycentric, bool nearest, unsigned threads) const {
        return run_locate<3, hullkit::Delaunay3QueryOptions>(queries, barycentric, nearest, threads,
                                                            [&](const double* xyz, std::size_t n, const hullkit::Delaunay3QueryOptions& o) {
                                                                return hullkit::delaunay3_locate(span(), result_, hullkit::PointSpan(xyz, n), o);
                                                            });
    }

    Points points_;
    hullkit::Delaunay3 result_;
};

py::dict verify_delaunay3(const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& tetrahedra,
                          bool perturbed) {
    const hullkit::PointSpan span(points.data(), rows(points, 3, "points"));
    if (tetrahedra.ndim() != 2 || tetrahedra.shape(1) != 4) throw std::invalid_argument("tetrahedra must have shape (m, 4)");
    hullkit::Delaunay3VerifyReport report;
    {
        py::gil_scoped_release unlocked;
        report = hullkit::verify_delaunay3(span, tetrahedra.data(), static_cast<std::size_t>(tetrahedra.shape(0)), perturbed);
    }
    py::dict out = delaunay_report_dict(report);
    out["hull_triangles"] = report.hull_triangles;
    return out;
}

/// Every point of a point file (any format hullkit reads), on `threads` threads for text.
py::array_t<double> read_points(const std::string& path, unsigned threads) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) throw CoreError(path + ": cannot open: " + std::strerror(errno), -1);
    std::vector<double> xyz;
    std::string error;
    {
        py::gil_scoped_release unlocked;
        hullkit::PointReaderOptions options;
        options.threads = threads;
        hullkit::PointReader reader(file, path, options);
        while (reader.append_next(&xyz)) {
        }
        error = reader.error();
    }
    std::fclose(file);
    if (!error.empty()) throw CoreError(error, -1);
    return owned_points(std::move(xyz));
}

/// The hull of a point file read in batches into a HullBuilder (memory: one batch and the running
/// hull), indices counted from 0 within the file: the map step of a hull across machines.
py::dict hull_file(const std::string& path, unsigned threads) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) throw CoreError(path + ": cannot open: " + std::strerror(errno), -1);
    hullkit::StreamedHull streamed;
    std::string error;
    {
        py::gil_scoped_release unlocked;
        hullkit::PointReaderOptions reading;
        reading.threads = threads;
        hullkit::PointReader reader(file, path, reading);
        hullkit::HullBuilder builder(hull_options("quickhull", false, threads));
        std::vector<double> xyz;
        std::uint64_t first = 0;
        while (error.empty() && reader.next(&xyz)) {
            if (!builder.add(hullkit::PointSpan(xyz), first)) error = path + ": " + builder.error();
            first += xyz.size() / 3;
        }
        if (error.empty()) error = reader.error();
        if (error.empty()) {
            streamed = builder.finish();
            if (!streamed.ok()) error = path + ": " + streamed.hull.error;
        }
    }
    std::fclose(file);
    if (!error.empty()) throw CoreError(error, -1);
    py::dict out;
    out["point_count"] = streamed.point_count;
    out["points"] = owned_points(std::move(streamed.points));
    out["index"] = owned(std::move(streamed.index));
    return out;
}

py::tuple read_mesh(const py::bytes& bytes, const std::string& source) {
    const std::string data = bytes;
    hullkit::MeshResult mesh = hullkit::read_mesh(data, source);
    if (!mesh.ok()) throw CoreError(mesh.error, -1);
    const auto triangles = static_cast<py::ssize_t>(mesh.triangles.size() / 3);
    return py::make_tuple(owned_points(std::move(mesh.xyz)), owned(std::move(mesh.triangles), {triangles, 3}));
}

/// A RouteChecker built from a scene's JSON text, its mesh files relative to `directory`.
class Checker {
public:
    /// Mesh files come from `files` (name as written in the scene -> bytes) when it is not empty,
    /// else from `directory`.
    Checker(const std::string& json, const std::string& source, const std::string& directory,
            const std::map<std::string, std::string>& files) {
        hullkit::SceneReadOptions options;
        options.require_route = false;
        hullkit::MeshLoader loader = hullkit::file_mesh_loader(directory);
        if (!files.empty()) {
            loader = [&files](const std::string& path, std::string* bytes, std::string* error) {
                const auto it = files.find(path);
                if (it == files.end()) {
                    *error = path + ": not among the scene's files";
                    return false;
                }
                *bytes = it->second;
                return true;
            };
        }
        hullkit::SceneResult scene = hullkit::parse_scene(json, source, loader, options);
        if (!scene.ok()) throw CoreError(scene.error, -1);
        checker_ = std::make_unique<hullkit::RouteChecker>(std::move(scene.scene));
        if (!checker_->error().empty()) throw CoreError(source + ": " + checker_->error(), -1);
    }

    /// The report as JSON (hullkit route's format); `route` (k, 3), or the scene's own when empty;
    /// `rotations` (k, 4) quaternions w x y z, or (0, 4) for none.
    std::string check(const Points& route, const Points& rotations, bool clearance, std::uint32_t samples,
                      unsigned threads) const {
        hullkit::RouteOptions options;
        options.clearance = clearance;
        options.samples = samples;
        options.threads = threads;
        const std::size_t waypoints = rows(route, 3, "route");
        const std::size_t turns = rows(rotations, 4, "rotations");
        if (turns != 0 && turns != waypoints) {
            throw std::invalid_argument("rotations must have one row per waypoint: " + std::to_string(turns) + " for " +
                                        std::to_string(waypoints) + " waypoints");
        }
        hullkit::RouteReport report;
        {
            py::gil_scoped_release unlocked;
            report = waypoints == 0 ? checker_->check(options)
                                    : checker_->check(route.data(), turns ? rotations.data() : nullptr, waypoints, options);
        }
        if (!report.ok()) throw CoreError(report.error, -1);
        return hullkit::write_report_json(checker_->scene(), report, options);
    }

    std::size_t scene_waypoints() const { return checker_->scene().route.size() / 3; }
    double build_seconds() const { return checker_->build_seconds(); }

private:
    std::unique_ptr<hullkit::RouteChecker> checker_;
};

/// `value` (finite) as Python's repr writes a float: the shortest digits that read back to it,
/// in positional notation when the decimal point falls within 16 places ("0.0001", "100.0",
/// "-0.0"), else with an exponent of at least two digits ("1e-05", "1.5e+16", "5e-324").
void append_python_float(double value, std::string* out) {
    char text[40];
    const char* end = std::to_chars(text, text + sizeof text, value, std::chars_format::scientific).ptr;
    const char* p = text;
    if (*p == '-') out->push_back(*p++);
    char digits[24];  // at most 17 significant digits
    int count = 0;
    for (; p < end && *p != 'e'; ++p) {
        if (*p != '.') digits[count++] = *p;
    }
    int exponent = 0;  // "e+20" -> 20 (the text is not NUL-terminated)
    const bool negative_exponent = p + 1 < end && p[1] == '-';
    std::from_chars(p + 2, end, exponent);
    if (negative_exponent) exponent = -exponent;
    const int point = exponent + 1;           // digits d1 d2 ... are 0.d1d2... x 10^point
    const auto n = [](int k) { return static_cast<std::size_t>(k); };
    if (point > -4 && point <= 16) {
        if (point <= 0) {
            out->append("0.").append(n(-point), '0').append(digits, n(count));
        } else if (point >= count) {
            out->append(digits, n(count)).append(n(point - count), '0').append(".0");
        } else {
            out->append(digits, n(point)).append(".").append(digits + point, n(count - point));
        }
        return;
    }
    out->push_back(digits[0]);
    if (count > 1) out->append(".").append(digits + 1, n(count - 1));
    const int shown = point - 1;
    out->append(shown < 0 ? "e-" : "e+");
    const std::string magnitude = std::to_string(shown < 0 ? -shown : shown);
    if (magnitude.size() < 2) out->push_back('0');
    out->append(magnitude);
}

/// A 2-D array as the JSON text json.dumps writes for its list of lists, byte for byte
/// ("[[0.5, -0.0, 1e-05], [...]]"): a scene's numpy meshes written ~5x faster than through
/// tolist(). Floats must be finite (json.dumps writes NaN, which the caller leaves to it).
template <class T>
std::string json_rows(const py::array_t<T, py::array::c_style>& array) {
    if (array.ndim() != 2) throw std::invalid_argument("json_rows: a 2-D array is needed");
    const std::size_t rows = static_cast<std::size_t>(array.shape(0)), columns = static_cast<std::size_t>(array.shape(1));
    const T* data = array.data();
    std::string out;
    {
        py::gil_scoped_release unlocked;
        out.reserve(rows * columns * 20 + rows * 4 + 2);
        char buffer[32];
        out += '[';
        for (std::size_t r = 0; r < rows; ++r) {
            out += r ? ", [" : "[";
            for (std::size_t c = 0; c < columns; ++c) {
                if (c) out += ", ";
                const T value = data[r * columns + c];
                if constexpr (std::is_floating_point_v<T>) {
                    append_python_float(value, &out);
                } else {
                    out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
                }
            }
            out += ']';
        }
        out += ']';
    }
    return out;
}

/// (n, D) float64 points' dimension D (any D), or ValueError.
int columns_of(const Points& points, const char* what) {
    if (points.ndim() != 2) throw std::invalid_argument(std::string(what) + " must be a 2-D array");
    return static_cast<int>(points.shape(1));
}

/// hullkit.hull_nd: (facets (m, D) int32, neighbors (m, D) int32, vertices int32, group int32: each
/// facet's flat piece of the boundary, by its lowest facet).
py::tuple hull_nd(const Points& points) {
    const int dims = columns_of(points, "points");
    const std::size_t n = static_cast<std::size_t>(points.shape(0));
    hullkit::HullNd h;
    {
        py::gil_scoped_release unlocked;
        h = hullkit::hull_nd(points.data(), n, dims);
    }
    if (!h.ok()) throw CoreError(h.error, h.error_point);
    const auto m = static_cast<py::ssize_t>(h.facet_count());
    std::vector<std::int32_t> facets(h.facets.begin(), h.facets.end()), vertices(h.vertices.begin(), h.vertices.end());
    return py::make_tuple(owned(std::move(facets), {m, dims}), owned(std::move(h.neighbors), {m, dims}),
                          owned(std::move(vertices)), owned(std::move(h.group)));
}

/// The Delaunay triangulation in d dimensions, kept for point location and the Voronoi volumes.
class TriangulationNd {
public:
    TriangulationNd(const Points& points, bool furthest_site)
        : points_(points.data(), points.data() + points.size()) {
        const int dims = columns_of(points, "points");
        const std::size_t n = static_cast<std::size_t>(points.shape(0));
        {
            py::gil_scoped_release unlocked;
            d_ = hullkit::delaunay_nd(points_.data(), n, dims, furthest_site);
        }
        if (!d_.ok()) throw CoreError(d_.error, d_.error_point);
    }
    py::array_t<std::int32_t> simplices() const {
        std::vector<std::int32_t> out(d_.simplices.begin(), d_.simplices.end());
        return owned(std::move(out), {static_cast<py::ssize_t>(d_.simplex_count()), d_.dimension + 1});
    }
    py::array_t<std::int32_t> neighbors() const {
        std::vector<std::int32_t> out(d_.neighbors);
        return owned(std::move(out), {static_cast<py::ssize_t>(d_.simplex_count()), d_.dimension + 1});
    }
    py::array_t<std::int32_t> group() const { return owned(std::vector<std::int32_t>(d_.group)); }
    py::array_t<std::uint32_t> representative() const { return owned(std::vector<std::uint32_t>(d_.representative)); }
    std::size_t duplicate_count() const { return d_.duplicate_count; }
    /// Each point's Voronoi cell volume (hullkit::voronoi_nd_volumes): inf when unbounded, NaN
    /// for a repeated point (its representative has the cell).
    py::array_t<double> cell_volumes() const {
        std::vector<double> volume;
        {
            py::gil_scoped_release unlocked;
            volume = hullkit::voronoi_nd_volumes(points_.data(), d_.representative.size(), d_.dimension, d_.simplices.data(),
                                                 d_.simplex_count());
        }
        return owned(std::move(volume));
    }
    py::array_t<std::int32_t> locate(const Points& queries) const {
        if (columns_of(queries, "xi") != d_.dimension) throw std::invalid_argument("xi has the wrong dimension");
        const std::size_t q = static_cast<std::size_t>(queries.shape(0));
        std::vector<std::int32_t> found;
        {
            py::gil_scoped_release unlocked;
            found = hullkit::locate_nd(points_.data(), d_, queries.data(), q);
        }
        return owned(std::move(found));
    }

private:
    std::vector<double> points_;
    hullkit::DelaunayNd d_;
};

}  // namespace

PYBIND11_MODULE(_core, m) {
    m.doc() = "hullkit's C++ core (use the hullkit package, not this module)";
    static py::exception<CoreError> core_error(m, "CoreError", PyExc_ValueError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const CoreError& e) {
            // A tuple becomes the exception's args: (message, point index or -1).
            PyErr_SetObject(core_error.ptr(), py::make_tuple(e.what(), e.point).ptr());
        }
    });
    m.def("hull", &hull, py::arg("points"), py::arg("algorithm") = "quickhull", py::arg("merge_coplanar") = false,
          py::arg("threads") = 0u);
    m.def("verify_triangles", &verify_triangles);
    m.def("hull_nd", &hull_nd);
    m.def("orient_nd", [](const Points& rows) {
        const int dims = columns_of(rows, "rows");
        if (rows.shape(0) != dims + 1) throw std::invalid_argument("orient_nd needs D + 1 rows of D coordinates");
        return hullkit::orient_nd(rows.data(), dims);
    });
    py::class_<TriangulationNd>(m, "TriangulationNd")
        .def(py::init<const Points&, bool>(), py::arg("points"), py::arg("furthest_site") = false)
        .def_property_readonly("simplices", &TriangulationNd::simplices)
        .def_property_readonly("neighbors", &TriangulationNd::neighbors)
        .def_property_readonly("group", &TriangulationNd::group)
        .def_property_readonly("representative", &TriangulationNd::representative)
        .def_property_readonly("duplicate_count", &TriangulationNd::duplicate_count)
        .def("locate", &TriangulationNd::locate)
        .def("cell_volumes", &TriangulationNd::cell_volumes);
    m.def("surface_extras", &surface_extras);
    m.def("facet_sides", &facet_sides);
    m.def("facet_holding", &facet_holding);
    m.def("nested_lists", &nested_lists);
    m.def("furthest_delaunay", &furthest_delaunay);
    m.def("constrained", &constrained);
    m.def("verify_hull", &verify_hull);
    m.def("verify_delaunay", &verify_delaunay);
    m.def("verify_delaunay3", &verify_delaunay3, py::arg("points"), py::arg("tetrahedra"), py::arg("perturbed") = true);
    m.def("read_points", &read_points, py::arg("path"), py::arg("threads") = 0u);
    m.def("read_mesh", &read_mesh);
    m.def("json_rows_float64", &json_rows<double>);
    m.def("json_rows_int64", &json_rows<std::int64_t>);
    m.def("hull_file", &hull_file, py::arg("path"), py::arg("threads") = 0u);

    py::class_<Builder>(m, "HullBuilder")
        .def(py::init<const std::string&, unsigned>(), py::arg("algorithm") = "quickhull", py::arg("threads") = 0u)
        .def("add", &Builder::add)
        .def("add_indexed", &Builder::add_indexed)
        .def("finish", &Builder::finish)
        .def_property_readonly("points_added", &Builder::points_added);

    using hullkit::Delaunay;
    py::class_<Triangulation>(m, "Triangulation")
        .def(py::init<Points, const std::string&, bool, unsigned>())
        .def_property_readonly("dimension", [](const Triangulation& t) { return t.result().dimension; })
        .def_property_readonly("triangles", result_view<Triangulation>(&Delaunay::triangles))
        .def_property_readonly("halfedges", result_view<Triangulation>(&Delaunay::halfedges))
        .def_property_readonly("hull", result_view<Triangulation>(&Delaunay::hull))
        .def_property_readonly("representative", result_view<Triangulation>(&Delaunay::representative))
        .def_property_readonly("polygon_offsets", result_view<Triangulation>(&Delaunay::polygon_offsets))
        .def_property_readonly("polygon_vertices", result_view<Triangulation>(&Delaunay::polygon_vertices))
        .def_property_readonly("duplicate_count", [](const Triangulation& t) { return t.result().duplicate_count; })
        .def("find", &Triangulation::find)
        .def("locate", &Triangulation::locate, py::arg("queries"), py::arg("barycentric") = false,
             py::arg("nearest") = false, py::arg("threads") = 0u)
        .def("scipy_arrays", &Triangulation::scipy_arrays)
        .def("gradients", &Triangulation::gradients)
        .def("interpolate", &Triangulation::interpolate)
        .def("clough_tocher", &Triangulation::clough_tocher)
        .def("voronoi", &Triangulation::voronoi)
        .def("scipy_voronoi", &Triangulation::scipy_voronoi);

    using hullkit::Delaunay3;
    py::class_<Tetrahedralization>(m, "Tetrahedralization")
        .def(py::init<Points, unsigned, bool>(), py::arg("points"), py::arg("threads") = 0u, py::arg("furthest_site") = false)
        .def_property_readonly("dimension", [](const Tetrahedralization& t) { return t.result().dimension; })
        .def_property_readonly("tetrahedra", result_view<Tetrahedralization>(&Delaunay3::tetrahedra, 4))
        .def_property_readonly("neighbors",  // per tetrahedron, or per triangle for coplanar points
                               [](py::object self) {
                                   const Delaunay3& d = self.cast<const Tetrahedralization&>().result();
                                   return view(d.neighbors, self, d.dimension == 2 ? 3 : 4);
                               })
        .def_property_readonly("hull", result_view<Tetrahedralization>(&Delaunay3::hull, 3))
        .def_property_readonly("triangles", result_view<Tetrahedralization>(&Delaunay3::triangles, 3))
        .def_property_readonly("vertices", result_view<Tetrahedralization>(&Delaunay3::vertices))
        .def_property_readonly("representative", result_view<Tetrahedralization>(&Delaunay3::representative))
        .def_property_readonly("normal",
                               [](const Tetrahedralization& t) {
                                   const double* n = t.result().normal;
                                   return py::make_tuple(n[0], n[1], n[2]);
                               })
        .def_property_readonly("duplicate_count", [](const Tetrahedralization& t) { return t.result().duplicate_count; })
        .def("locate", &Tetrahedralization::locate, py::arg("queries"), py::arg("barycentric") = false,
             py::arg("nearest") = false, py::arg("threads") = 0u)
        .def("voronoi", &Tetrahedralization::voronoi)
        .def("clipped_volumes", &Tetrahedralization::clipped_volumes)
        .def("interpolate", &Tetrahedralization::interpolate);

    py::class_<Checker>(m, "RouteChecker")
        .def(py::init<const std::string&, const std::string&, const std::string&, const std::map<std::string, std::string>&>(),
             py::arg("json"), py::arg("source"), py::arg("directory"), py::arg("files") = std::map<std::string, std::string>{})
        .def("check", &Checker::check)
        .def_property_readonly("scene_waypoints", &Checker::scene_waypoints)
        .def_property_readonly("build_seconds", &Checker::build_seconds);
}
