// constrained_bench.cpp: times one constrained Delaunay implementation on one input of
// bench/constrained_inputs.mjs in its own process (issue 31), so that the first call is a user's
// first call and the peak memory is that run's. Built twice (bench/CMakeLists.txt):
//   hullkit_constrained_cgal_bench  CGAL only (always: the peers' rows do not wait for hullkit's core)
//   hullkit_constrained_bench       CGAL and hullkit (HULLKIT_CONSTRAINED_BENCH_HULLKIT=1; built when
//                                   native/include/hullkit/constrained.hpp exists, links hullkit_delaunay)
//
//   BINARY --impl IMPL --input bench/out/constrained/NAME.json [--runs 5] [--budget 60] [--threads N] [--dump PREFIX]
//
// IMPL is one of
//   hullkit     a polygon: hullkit::triangulate_polygon(PointSpan2, holeIndices, count, PolygonOptions)
//               (even-odd fill, the default); a graph: hullkit::constrained_delaunay(PointSpan2,
//               segments, count, ConstrainedOptions). --threads sets the options' threads (default 0:
//               the library's default). Only in hullkit_constrained_bench.
//   cgal-cdt    CGAL::Constrained_Delaunay_triangulation_2 (CGAL 5.5, Exact_predicates_inexact_
//               constructions_kernel, Exact_predicates_tag: crossing constraints allowed, as hullkit
//               allows them). The points are inserted first in CGAL's spatial sort order with a hint
//               (what CDT::insert_constraints(points, index pairs) does; here by hand to keep each
//               vertex's input index), then every segment or ring edge by insert_constraint(va, vb).
//               A polygon then gets the standard "mark domains" pass: a breadth-first walk from the
//               infinite face giving every face its nesting level (the number of constraints crossed
//               from outside); the inside is the odd levels, whose faces are counted. All timed.
//   cgal-mesh   a polygon only: the same CDT and marks (the mesh face base's in_domain flags), then
//               CGAL::Delaunay_mesher_2 with Delaunay_mesh_size_criteria_2(0.125, 0) — the default
//               shape bound B = 0.125 (smallest angle about 20.7 degrees), no size bound — init(true)
//               (the marks as the domain) and refine_mesh(). Timed whole; the line reports the mesh's
//               triangles inside, vertices and smallest angle (the quality-mesh comparison).
//   cgal-refine a polygon only: Triangle's -r, refining a mesh that exists: the CDT and marks of
//               cgal-mesh built before the clock starts, then the same Delaunay_mesher_2 timed.
//   hullkit-refine a polygon only: the same for hullkit: hullkit::triangulate_polygon untimed, then
//               hullkit::refine_mesh on its coordinates and triangles with hullkit-mesh's angle bound
//               timed (the refined mesh is dumped and checked as hullkit-mesh's). Only in
//               hullkit_constrained_bench.
//   hullkit-mesh a polygon only: hullkit::triangulate_polygon with PolygonOptions.quality.min_angle =
//               asin(sqrt(0.125)) in degrees (CGAL's bound above; no area bound). Timed whole; the line
//               adds the smallest angle, the bound ("min_angle_bound_deg": what the check of the dump
//               holds the mesh to) and the library's count of triangles left below it ("unrefined").
//               Only in hullkit_constrained_bench.
//
// Input: the JSON of bench/constrained_inputs.mjs: a polygon ({"kind": "polygon", "coords",
// "holeIndices"}) or a graph ({"kind": "graph", "pointsFile", "segmentsFile"}: raw float64 x y, uint32
// index pairs, next to it). The input is read and converted into what each implementation takes
// (hullkit: the flat arrays; CGAL: a vector of Point_2 and the index pairs) before the clock starts.
// The first run is reported on its own ("first": caches and allocator cold) and the median of the later
// runs as "warm"; results are freed between runs, outside the timed part; no run starts once the runs
// add up to more than --budget seconds.
//
// --dump PREFIX writes the first run's triangles (the inside ones for a polygon) to PREFIX.tri (uint32
// index triples) and the coordinates they index to PREFIX.xy (float64 x y: the input's, then any
// points the implementation added), for bench/constrained_check.mjs (hullkit-mesh's with --mesh). Not for
// cgal-mesh.
//
// Output: one JSON line on stdout: {"impl", "input", "kind", "n", "first", "runs", "warm",
// "triangles", "vertices", "added_points", "peak_rss_mb", "input_rss_mb", "detail"} (+ "min_angle_deg"
// for the meshes, "min_angle_bound_deg" and "unrefined" for hullkit-mesh); "error" instead on failure
// (exit status 0: the table shows the row as failed).
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/resource.h>

#ifndef HULLKIT_CONSTRAINED_BENCH_HULLKIT
#define HULLKIT_CONSTRAINED_BENCH_HULLKIT 0
#endif
#if HULLKIT_CONSTRAINED_BENCH_HULLKIT
#include "hullkit/constrained.hpp"
#endif

namespace {

struct Args {
    std::string impl, input, dump;
    int runs = 5;
    double budget = 60.0;
    unsigned threads = 0;
};

Args parse_args(int argc, char** argv) {
    Args args;
    CLI::App app{"times one constrained Delaunay implementation on one input", "hullkit_constrained_bench"};
    app.add_option("--impl", args.impl, "hullkit, hullkit-mesh, hullkit-refine, cgal-cdt, cgal-mesh or cgal-refine")->required();
    app.add_option("--input", args.input, "an input JSON of bench/constrained_inputs.mjs")->required();
    app.add_option("--runs", args.runs, "timed runs, the first reported on its own")->check(CLI::PositiveNumber);
    app.add_option("--budget", args.budget, "no further run once the runs add up to this many seconds");
    app.add_option("--threads", args.threads, "hullkit: the options' threads (0: the library's default)");
    app.add_option("--dump", args.dump, "write the first run's triangles to PREFIX.tri and coordinates to PREFIX.xy");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        std::exit(app.exit(error) == 0 ? 0 : 2);
    }
    return args;
}

double peak_rss_mb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;
        out += c;
    }
    return out + "\"";
}

/// The input: flat coordinates, and either ring starts (a polygon) or segments (a graph).
struct Input {
    std::string name, kind;
    std::vector<double> xy;
    std::vector<std::uint32_t> hole_indices;  // polygon
    std::vector<std::uint32_t> segments;      // graph: index pairs
    bool polygon() const { return kind == "polygon"; }
    std::size_t count() const { return xy.size() / 2; }
};

std::vector<char> read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

Input read_input(const std::string& path) {
    const std::vector<char> text = read_bytes(path);
    const nlohmann::json json = nlohmann::json::parse(text.begin(), text.end());
    Input input;
    input.kind = json.at("kind").get<std::string>();
    input.name = json.at("name").get<std::string>();
    if (input.polygon()) {
        input.xy = json.at("coords").get<std::vector<double>>();
        input.hole_indices = json.at("holeIndices").get<std::vector<std::uint32_t>>();
    } else {
        const std::size_t slash = path.find_last_of('/');
        const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
        const std::vector<char> xy = read_bytes(dir + json.at("pointsFile").get<std::string>());
        const std::vector<char> seg = read_bytes(dir + json.at("segmentsFile").get<std::string>());
        if (xy.size() % 16 != 0 || seg.size() % 8 != 0) throw std::runtime_error(path + ": binary files of the wrong size");
        input.xy.resize(xy.size() / 8);
        std::copy(xy.begin(), xy.end(), reinterpret_cast<char*>(input.xy.data()));  // little-endian host
        input.segments.resize(seg.size() / 4);
        std::copy(seg.begin(), seg.end(), reinterpret_cast<char*>(input.segments.data()));
    }
    return input;
}

/// The constraint index pairs: a graph's segments, or a polygon's ring edges (closing edge included).
std::vector<std::pair<std::uint32_t, std::uint32_t>> constraint_pairs(const Input& input) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    if (!input.polygon()) {
        for (std::size_t s = 0; s + 1 < input.segments.size(); s += 2) pairs.emplace_back(input.segments[s], input.segments[s + 1]);
        return pairs;
    }
    std::vector<std::uint32_t> starts{0};
    starts.insert(starts.end(), input.hole_indices.begin(), input.hole_indices.end());
    const auto n = static_cast<std::uint32_t>(input.count());
    for (std::size_t r = 0; r < starts.size(); ++r) {
        const std::uint32_t s = starts[r], e = r + 1 < starts.size() ? starts[r + 1] : n;
        for (std::uint32_t i = s; i < e; ++i) pairs.emplace_back(i, i + 1 < e ? i + 1 : s);
    }
    return pairs;
}

// ---- CGAL
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
struct VertexInfo {
    std::uint32_t index = std::numeric_limits<std::uint32_t>::max();  // input index; max: added by CGAL
};
struct FaceInfo {
    int nesting_level = -1;
    bool in_domain() const { return nesting_level % 2 == 1; }
};
using Itag = CGAL::Exact_predicates_tag;
// The CDT of cgal-cdt.
using CdtVb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
using CdtFbInfo = CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>;
using CdtFb = CGAL::Constrained_triangulation_face_base_2<Kernel, CdtFbInfo>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<CdtVb, CdtFb>, Itag>;
// The CDT of cgal-mesh: the mesher's vertex and face bases on top.
using MeshVb = CGAL::Delaunay_mesh_vertex_base_2<Kernel, CdtVb>;
using MeshFb = CGAL::Delaunay_mesh_face_base_2<Kernel, CdtFb>;
using MeshCdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<MeshVb, MeshFb>, Itag>;
using MeshCriteria = CGAL::Delaunay_mesh_size_criteria_2<MeshCdt>;

/// Inserts the points in spatial sort order (each with its input index), then the constraints.
template <class Tr>
void cgal_insert(Tr& cdt, const std::vector<Point>& points, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) {
    using Vertex_handle = typename Tr::Vertex_handle;
    using Face_handle = typename Tr::Face_handle;
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    using Map = CGAL::Pointer_property_map<Point>::const_type;
    CGAL::Spatial_sort_traits_adapter_2<Kernel, Map> traits(CGAL::make_property_map(points));
    CGAL::spatial_sort(order.begin(), order.end(), traits);
    std::vector<Vertex_handle> vertices(points.size());
    Face_handle hint;
    for (std::size_t i : order) {
        Vertex_handle v = cdt.insert(points[i], hint);
        if (v->info().index == std::numeric_limits<std::uint32_t>::max()) v->info().index = static_cast<std::uint32_t>(i);
        vertices[i] = v;
        hint = v->face();
    }
    for (const auto& [a, b] : pairs) {
        if (vertices[a] != vertices[b]) cdt.insert_constraint(vertices[a], vertices[b]);
    }
}

/// The standard nesting-level marking: from the infinite face, flood through unconstrained edges;
/// crossing a constrained edge goes one level deeper.
template <class Tr>
void mark_domains(Tr& cdt) {
    using Face_handle = typename Tr::Face_handle;
    for (Face_handle f : cdt.all_face_handles()) f->info().nesting_level = -1;
    std::deque<Face_handle> border{cdt.infinite_face()};
    std::deque<Face_handle> queue;
    int level = 0;
    while (!border.empty()) {
        std::deque<Face_handle> next_border;
        for (Face_handle start : border) {
            if (start->info().nesting_level != -1) continue;
            start->info().nesting_level = level;
            queue.push_back(start);
            while (!queue.empty()) {
                Face_handle f = queue.front();
                queue.pop_front();
                for (int i = 0; i < 3; ++i) {
                    Face_handle g = f->neighbor(i);
                    if (g->info().nesting_level != -1) continue;
                    if (cdt.is_constrained(typename Tr::Edge(f, i))) {
                        next_border.push_back(g);
                    } else {
                        g->info().nesting_level = level;
                        queue.push_back(g);
                    }
                }
            }
        }
        border.swap(next_border);
        ++level;
    }
}

/// What one run produced: the triangle count and, when dumping, the triangles and coordinates.
struct Run {
    double seconds = 0;
    std::size_t triangles = 0;
    std::size_t vertices = 0;
    std::size_t added = 0;
    double min_angle_deg = -1;
    double min_angle_bound_deg = -1;  // hullkit-mesh: the bound asked for
    long long unrefined = -1;         // hullkit-mesh: triangles the library left below it
};

struct Dump {
    std::vector<std::uint32_t> triangles;
    std::vector<double> xy;
};

/// The triangles (inside ones for a polygon) of a CGAL CDT as input indices, vertices CGAL added
/// appended to the coordinates.
template <class Tr>
void cgal_dump(Tr& cdt, const Input& input, bool inside_only, Dump* dump) {
    dump->xy = input.xy;
    dump->triangles.clear();
    std::uint32_t next = static_cast<std::uint32_t>(input.count());
    for (auto v : cdt.finite_vertex_handles()) {
        if (v->info().index == std::numeric_limits<std::uint32_t>::max()) {
            v->info().index = next++;
            dump->xy.push_back(v->point().x());
            dump->xy.push_back(v->point().y());
        }
    }
    for (auto f : cdt.finite_face_handles()) {
        if (inside_only && !f->info().in_domain()) continue;
        for (int i = 0; i < 3; ++i) dump->triangles.push_back(f->vertex(i)->info().index);
    }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The angle at corner a of triangle a b c, in degrees.
double corner_angle(double ax, double ay, double bx, double by, double cx, double cy) {
    const double ux = bx - ax, uy = by - ay, vx = cx - ax, vy = cy - ay;
    return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / M_PI;
}

/// The smallest angle (degrees) of triangles given as index triples into flat x y coordinates.
[[maybe_unused]] double smallest_angle(const std::vector<std::uint32_t>& triangles, const std::vector<double>& xy) {
    double smallest = 180;
    for (std::size_t t = 0; t < triangles.size(); t += 3) {
        for (int i = 0; i < 3; ++i) {
            const double* a = &xy[2 * triangles[t + i]];
            const double* b = &xy[2 * triangles[t + (i + 1) % 3]];
            const double* c = &xy[2 * triangles[t + (i + 2) % 3]];
            smallest = std::min(smallest, corner_angle(a[0], a[1], b[0], b[1], c[0], c[1]));
        }
    }
    return smallest;
}

/// The smallest angle (degrees) of the in-domain faces of a mesh.
double smallest_angle(const MeshCdt& cdt) {
    double smallest = 180;
    for (auto f : cdt.finite_face_handles()) {
        if (!f->is_in_domain()) continue;
        for (int i = 0; i < 3; ++i) {
            const Point& a = f->vertex(i)->point();
            const Point& b = f->vertex((i + 1) % 3)->point();
            const Point& c = f->vertex((i + 2) % 3)->point();
            smallest = std::min(smallest, corner_angle(a.x(), a.y(), b.x(), b.y(), c.x(), c.y()));
        }
    }
    return smallest;
}

#if HULLKIT_CONSTRAINED_BENCH_HULLKIT
/// hullkit::triangulate_polygon timed on the input; with quality options (hullkit-mesh) the line
/// also gets the mesh's smallest angle, the bound and hullkit's count of triangles left below it.
/// CGAL's default shape bound B = 0.125 is sin^2 of the smallest angle: asin(sqrt(0.125)) degrees.
double cgal_default_angle_deg() { return std::asin(std::sqrt(0.125)) * 180 / M_PI; }

/// A hullkit result's line (and dump); with quality options, the mesh's fields too.
Run hullkit_run(double seconds, const hullkit::ConstrainedDelaunay& result, std::size_t input_count,
                const hullkit::QualityOptions& quality, Dump* dump) {
    if (!result.ok()) throw std::runtime_error(result.error);
    if (dump) *dump = Dump{result.triangles, result.coords};
    // Added points: every point past the input's (refine_mesh's input holds the crossings too).
    Run out{seconds, result.triangle_count(), result.coords.size() / 2, result.coords.size() / 2 - input_count};
    if (quality.active()) {
        out.min_angle_deg = smallest_angle(result.triangles, result.coords);
        out.min_angle_bound_deg = quality.min_angle;
        out.unrefined = static_cast<long long>(result.unrefined_count);
    }
    return out;
}

std::function<Run(Dump*)> hullkit_polygon_run(const Input& input, const hullkit::PolygonOptions& options) {
    return [&input, options](Dump* dump) {
        const auto start = std::chrono::steady_clock::now();
        hullkit::ConstrainedDelaunay result = hullkit::triangulate_polygon(
            hullkit::PointSpan2(input.xy), input.hole_indices.data(), input.hole_indices.size(), options);
        return hullkit_run(seconds_since(start), result, input.count(), options.quality, dump);
    };
}
#endif

}  // namespace

int main(int argc, char** argv) {
    const Args args = parse_args(argc, argv);
    std::string name = args.input;
    auto fail = [&](const std::string& error) {
        std::printf("{\"impl\":%s,\"input\":%s,\"error\":%s}\n", json_string(args.impl).c_str(), json_string(name).c_str(),
                    json_string(error).c_str());
        return 0;
    };
    Input input;
    try {
        input = read_input(args.input);
    } catch (const std::exception& error) {
        return fail(error.what());
    }
    name = input.name;
    const std::size_t n = input.count();
    const auto pairs = constraint_pairs(input);
    for (const auto& [a, b] : pairs) {
        if (a >= n || b >= n) return fail("a segment names a point past the input");
    }

    std::vector<Point> points;
    std::function<Run(Dump*)> run;
    std::string detail;
    if (args.impl == "cgal-cdt" || args.impl == "cgal-mesh" || args.impl == "cgal-refine") {
        points.reserve(n);
        for (std::size_t i = 0; i < n; ++i) points.emplace_back(input.xy[2 * i], input.xy[2 * i + 1]);
    }
    if (args.impl == "cgal-cdt") {
        detail = input.polygon() ? "CGAL 5.5 Constrained_Delaunay_triangulation_2 (Epick, Exact_predicates_tag): spatially sorted points, "
                                   "ring edges by insert_constraint, nesting levels (mark domains), inside faces counted"
                                 : "CGAL 5.5 Constrained_Delaunay_triangulation_2 (Epick, Exact_predicates_tag): spatially sorted points, "
                                   "segments by insert_constraint";
        run = [&](Dump* dump) {
            const auto start = std::chrono::steady_clock::now();
            Cdt cdt;
            cgal_insert(cdt, points, pairs);
            std::size_t triangles = 0;
            if (input.polygon()) {
                mark_domains(cdt);
                for (auto f : cdt.finite_face_handles()) triangles += f->info().in_domain();
            } else {
                triangles = cdt.number_of_faces();
            }
            Run result{seconds_since(start), triangles, cdt.number_of_vertices(), 0};
            std::size_t added = 0;
            for (auto v : cdt.finite_vertex_handles()) added += v->info().index == std::numeric_limits<std::uint32_t>::max();
            result.added = added;
            if (dump) cgal_dump(cdt, input, input.polygon(), dump);
            return result;  // the CDT is destroyed here, untimed
        };
    } else if (args.impl == "cgal-mesh" || args.impl == "cgal-refine") {
        const bool refine = args.impl == "cgal-refine";
        if (!input.polygon()) return fail(args.impl + " meshes polygons only");
        if (!args.dump.empty()) return fail("--dump is not for " + args.impl + " (its points are not the input's)");
        detail = refine ? "CGAL 5.5 CDT + mark domains untimed, then Delaunay_mesher_2 with Delaunay_mesh_size_criteria_2(0.125, 0) "
                          "timed (refining an existing mesh)"
                        : "CGAL 5.5 CDT + mark domains, then Delaunay_mesher_2 with Delaunay_mesh_size_criteria_2(0.125, 0): "
                          "shape bound B = 0.125 (about 20.7 degrees), no size bound";
        run = [&, refine](Dump*) {
            auto start = std::chrono::steady_clock::now();
            MeshCdt cdt;
            cgal_insert(cdt, points, pairs);
            mark_domains(cdt);
            for (auto f : cdt.all_face_handles()) f->set_in_domain(f->info().in_domain());
            if (refine) start = std::chrono::steady_clock::now();
            CGAL::Delaunay_mesher_2<MeshCdt, MeshCriteria> mesher(cdt, MeshCriteria(0.125, 0));
            mesher.init(true);
            mesher.refine_mesh();
            const double seconds = seconds_since(start);
            std::size_t triangles = 0;
            for (auto f : cdt.finite_face_handles()) triangles += f->is_in_domain();
            Run result{seconds, triangles, cdt.number_of_vertices(), cdt.number_of_vertices() - n};
            result.min_angle_deg = smallest_angle(cdt);
            return result;
        };
    } else if (args.impl == "hullkit") {
#if HULLKIT_CONSTRAINED_BENCH_HULLKIT
        if (input.polygon()) {
            hullkit::PolygonOptions options;
            options.threads = args.threads;
            detail = "hullkit::triangulate_polygon(PointSpan2, holeIndices, count, PolygonOptions{evenodd, threads " +
                     std::to_string(args.threads) + "})";
            run = hullkit_polygon_run(input, options);
        } else {
            hullkit::ConstrainedOptions options;
            options.threads = args.threads;
            detail = "hullkit::constrained_delaunay(PointSpan2, segments, count, ConstrainedOptions{threads " + std::to_string(args.threads) + "})";
            run = [&input, options](Dump* dump) {
                const auto start = std::chrono::steady_clock::now();
                hullkit::ConstrainedDelaunay result = hullkit::constrained_delaunay(
                    hullkit::PointSpan2(input.xy), input.segments.data(), input.segments.size() / 2, options);
                return hullkit_run(seconds_since(start), result, input.count(), options.quality, dump);
            };
        }
#else
        return fail("not available: this binary is the CGAL-only build (hullkit_constrained_cgal_bench)");
#endif
    } else if (args.impl == "hullkit-mesh") {
#if HULLKIT_CONSTRAINED_BENCH_HULLKIT
        if (!input.polygon()) return fail("hullkit-mesh meshes polygons only (as cgal-mesh)");
        hullkit::PolygonOptions options;
        options.threads = args.threads;
        options.quality.min_angle = cgal_default_angle_deg();
        detail = "hullkit::triangulate_polygon(..., PolygonOptions{evenodd, quality.min_angle " +
                 std::to_string(options.quality.min_angle) + " (CGAL's B = 0.125)})";
        run = hullkit_polygon_run(input, options);
#else
        return fail("not available: this binary is the CGAL-only build (hullkit_constrained_cgal_bench)");
#endif
    } else if (args.impl == "hullkit-refine") {
#if HULLKIT_CONSTRAINED_BENCH_HULLKIT
        if (!input.polygon()) return fail("hullkit-refine refines polygons' meshes only (as cgal-refine)");
        hullkit::RefineMeshOptions options;
        options.threads = args.threads;
        options.quality.min_angle = cgal_default_angle_deg();
        detail = "hullkit::triangulate_polygon untimed, then hullkit::refine_mesh(coords, triangles, ..., quality.min_angle " +
                 std::to_string(options.quality.min_angle) + " (CGAL's B = 0.125)) timed";
        run = [&input, options](Dump* dump) {
            hullkit::PolygonOptions polygon;
            polygon.threads = options.threads;
            const hullkit::ConstrainedDelaunay mesh = hullkit::triangulate_polygon(
                hullkit::PointSpan2(input.xy), input.hole_indices.data(), input.hole_indices.size(), polygon);
            if (!mesh.ok()) throw std::runtime_error(mesh.error);
            const auto start = std::chrono::steady_clock::now();
            hullkit::ConstrainedDelaunay result =
                hullkit::refine_mesh(hullkit::PointSpan2(mesh.coords), mesh.triangles.data(), mesh.triangle_count(), nullptr, 0, options);
            return hullkit_run(seconds_since(start), result, input.count(), options.quality, dump);
        };
#else
        return fail("not available: this binary is the CGAL-only build (hullkit_constrained_cgal_bench)");
#endif
    } else {
        return fail("unknown implementation (known: hullkit, hullkit-mesh, hullkit-refine, cgal-cdt, cgal-mesh, cgal-refine)");
    }

    const double input_rss = peak_rss_mb();
    std::vector<double> runs;
    Run last;
    double total = 0;
    try {
        for (int k = 0; k < args.runs && (k == 0 || total < args.budget); ++k) {
            Dump dump;
            const bool dumping = k == 0 && !args.dump.empty();
            const Run result = run(dumping ? &dump : nullptr);
            runs.push_back(result.seconds);
            if (k == 0) last = result;
            total += result.seconds;
            if (dumping) {
                std::ofstream tri(args.dump + ".tri", std::ios::binary);
                tri.write(reinterpret_cast<const char*>(dump.triangles.data()),
                          static_cast<std::streamsize>(dump.triangles.size() * sizeof(std::uint32_t)));
                std::ofstream xy(args.dump + ".xy", std::ios::binary);
                xy.write(reinterpret_cast<const char*>(dump.xy.data()), static_cast<std::streamsize>(dump.xy.size() * sizeof(double)));
                if (!tri || !xy) throw std::runtime_error("cannot write " + args.dump + ".tri/.xy");
            }
        }
    } catch (const std::exception& error) {
        return fail(error.what());
    }
    std::string warm = "null";
    if (runs.size() > 1) {
        std::vector<double> later(runs.begin() + 1, runs.end());
        std::sort(later.begin(), later.end());
        const std::size_t m = later.size();
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.6g", m % 2 ? later[m / 2] : (later[m / 2 - 1] + later[m / 2]) / 2);
        warm = buffer;
    }
    std::string list;
    for (double seconds : runs) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%s%.6g", list.empty() ? "" : ",", seconds);
        list += buffer;
    }
    std::string extra;
    if (last.min_angle_deg >= 0) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, ",\"min_angle_deg\":%.4f", last.min_angle_deg);
        extra = buffer;
    }
    if (last.min_angle_bound_deg >= 0) {
        char buffer[96];
        std::snprintf(buffer, sizeof buffer, ",\"min_angle_bound_deg\":%.17g,\"unrefined\":%lld", last.min_angle_bound_deg, last.unrefined);
        extra += buffer;
    }
    std::printf("{\"impl\":%s,\"input\":%s,\"kind\":%s,\"n\":%zu,\"first\":%.6g,\"runs\":[%s],\"warm\":%s,\"triangles\":%zu,"
                "\"vertices\":%zu,\"added_points\":%zu,\"peak_rss_mb\":%.1f,\"input_rss_mb\":%.1f%s,\"detail\":%s}\n",
                json_string(args.impl).c_str(), json_string(input.name).c_str(), json_string(input.kind).c_str(), n, runs.front(),
                list.c_str(), warm.c_str(), last.triangles, last.vertices, last.added, peak_rss_mb(), input_rss, extra.c_str(),
                json_string(detail).c_str());
    return 0;
}
