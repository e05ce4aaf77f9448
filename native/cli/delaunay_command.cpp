// `hullkit delaunay` and `hullkit verify-delaunay`: argument parsing (CLI11) and I/O around
// hullkit::delaunay and hullkit::verify_delaunay. No geometry here.
#include "delaunay_command.hpp"
#include "progress.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "cli_io.hpp"
#include "svg.hpp"
#include "hullkit/delaunay.hpp"
#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"

namespace hullkit_cli {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitNotDelaunay = 1;

const char* const kDelaunayUsage =
    R"(Usage: hullkit delaunay [INPUT|-] [-o FILE] [--format FORMAT] [--algorithm NAME]
                        [--merge-cocircular] [--voronoi] [--stats]
                        [--threads N] [--quiet]

Computes the Delaunay triangulation of the 2D points in INPUT (standard input if
INPUT is missing or '-'): the lower convex hull of the points lifted to the
paraboloid z = x^2 + y^2, projected back to the plane. Every decision is exact.
Triangles are clockwise with the y axis pointing up (as delaunator's, which
calls them counter-clockwise on a y-down screen). Exact duplicates are merged
into their lowest index. Collinear points or fewer than 3 distinct points give
no triangles ("dimension" 1, 0), no points the empty triangulation (-1).

Input ('#' starts a comment):
  x y             one point per line, separated by whitespace or a comma (x y z
                  lines also work: z is ignored); a byte-order mark and a
                  header row of column names ("x,y") are skipped
  qhull / rbox    the dimension (2, or 3 with z ignored), the point count, then
                  one point per line ('rbox 100 D2 | hullkit delaunay')
  OBJ, OFF, PLY,  the x and y of the file's vertices (by name or content)
  STL, glTF

Options:
  -o, --output FILE   write to FILE instead of standard output
  --format FORMAT     off (default): every input point with z = 0, in input
                        order, and the triangles (indices = input indices);
                      json: {"dimension", "triangles": [[i,j,k],...],
                        "halfedges", "hull", "duplicates": [[i, first],...]}
                        with --merge-cocircular also "polygons", with
                        --voronoi also "voronoi";
                      svg: a picture of the triangulation, its hull and the
                        points (with --voronoi, the Voronoi cells too);
                      without --format, an output FILE ending in .off, .json
                      or .svg selects that format
  --algorithm NAME    {algorithms}
  --merge-cocircular  JSON: also the Delaunay polygons (the lifted hull's lower
                      faces before triangulation; a square grid gives squares)
  --voronoi           JSON: also the whole Voronoi diagram, "voronoi":
                        {"vertices": [[x,y],...] (cocircular triangles share
                        one), "triangle_vertex", "ridge_points": [[p,q],...],
                        "ridge_vertices": [[a,b],...] (a = -1: a ray),
                        "cells": [[v,...],...] (per point, counter-clockwise;
                        -1 last when unbounded; [] for a repeated point),
                        "area": [...] (null when unbounded)};
                      SVG: also draw the Voronoi cells, clipped to the picture
  --stats             print one JSON line to standard error: points,
                      triangles, hull, algorithm, seconds (the triangulation
                      alone)
  --threads N         a whole number from 0 to 1024: 1 everything on this
                      thread; 0 (default) or more: the insertion is serial,
                      and for 50 000 points or more the output stage takes a
                      second thread. The output is the same for every N
  --quiet             no progress line (otherwise drawn on standard error when
                      it is a terminal and the triangulation lasts over a
                      second: points inserted, rate, time left)
  -h, --help          show this help

Exit status: 0 on success, 2 on a usage or input problem (one line on standard
error).
)";

const char* const kVerifyDelaunayUsage =
    R"(Usage: hullkit verify-delaunay POINTS TRIANGLES

Checks, with exact arithmetic, that TRIANGLES is a Delaunay triangulation of
the 2D points in POINTS ('-' reads them from standard input; the input formats
of 'hullkit delaunay'): every triangle clockwise with y up and not degenerate,
each edge shared by at most two triangles, the boundary the convex hull, every
distinct point used, 2n - h - 2 triangles, and no point inside the circumcircle
across any interior edge.

TRIANGLES: a mesh file in any format the other commands read (OFF, OBJ, PLY,
STL, glTF), as 'hullkit delaunay' writes it (OFF). Its vertices are matched to
the input points with exactly the same x and y (and z = 0); duplicates stand for
the lowest index.

Prints 'ok: ...' or each problem on its own line.

Options:
  -h, --help          show this help

Exit status: 0 the triangulation is Delaunay, 1 it is not, 2 a usage or input
problem (one line on standard error).
)";

enum class Format { Off, Json, Svg };

struct DelaunayArgs {
    std::string input = "-";
    std::string output;  ///< empty: standard output
    Format format = Format::Off;
    hullkit::DelaunayOptions options;
    bool voronoi = false;
    bool stats = false;
    bool quiet = false;  ///< no progress line
};

bool parse_format(std::string name, Format* out) {
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (name == "off") *out = Format::Off;
    else if (name == "json") *out = Format::Json;
    else if (name == "svg") *out = Format::Svg;
    else return false;
    return true;
}

/// The format a file name's extension asks for; false for any other name.
bool format_from_path(const std::string& path, Format* out) {
    const std::size_t dot = path.find_last_of("./");
    return dot != std::string::npos && path[dot] == '.' && parse_format(path.substr(dot + 1), out);
}

constexpr hullkit::DelaunayAlgorithm kAlgorithms[] = {hullkit::DelaunayAlgorithm::Incremental,
                                                      hullkit::DelaunayAlgorithm::Giftwrap};

/// "incremental (default), giftwrap": the names parse_delaunay_algorithm knows.
std::string known_algorithms(bool mark_default) {
    std::string names;
    for (hullkit::DelaunayAlgorithm algorithm : kAlgorithms) {
        if (!names.empty()) names += ", ";
        names += hullkit::delaunay_algorithm_name(algorithm);
        if (mark_default && algorithm == hullkit::DelaunayOptions{}.algorithm) names += " (default)";
    }
    return names;
}

/// Returns false after printing the help for -h/--help.
bool parse_delaunay_args(const std::vector<std::string>& argv, DelaunayArgs* args) {
    CLI::App app{"hullkit delaunay", "hullkit delaunay"};
    app.set_help_flag();  // our own help text, in the style of the other commands
    bool help = false, merge = false;
    std::string format_name, algorithm_name;
    app.add_flag("-h,--help", help);
    // As with `hullkit hull`, an option given twice takes its last value.
    const auto last = CLI::MultiOptionPolicy::TakeLast;
    app.add_option("input", args->input);
    app.add_option("-o,--output", args->output)->multi_option_policy(last);
    app.add_option("--format", format_name)->multi_option_policy(last);
    app.add_option("--algorithm", algorithm_name)->multi_option_policy(last);
    app.add_flag("--merge-cocircular", merge);
    app.add_flag("--voronoi", args->voronoi);
    app.add_flag("--stats", args->stats);
    // Bounded as in `hullkit route`; the triangulation uses at most two threads anyway.
    add_whole_number_option(app, "--threads", &args->options.threads, 0, 1024);
    app.add_flag("--quiet", args->quiet);
    parse_or_throw(app, argv, "delaunay");
    if (help) {
        std::string usage = kDelaunayUsage;
        const std::string slot = "{algorithms}";
        usage.replace(usage.find(slot), slot.size(), "triangulation algorithm: " + known_algorithms(true));
        std::fputs(usage.c_str(), stdout);
        return false;
    }
    args->options.merge_cocircular = merge;
    if (app.count("--output") && args->output.empty()) throw UsageError("option --output needs a file name");
    if (app.count("--format")) {
        if (!parse_format(format_name, &args->format)) {
            throw UsageError("unknown format \"" + format_name + "\" (known: off, json, svg)");
        }
    } else if (!args->output.empty() && args->output != "-") {
        format_from_path(args->output, &args->format);  // the default stays OFF
    }
    if (app.count("--algorithm") && !hullkit::parse_delaunay_algorithm(algorithm_name, &args->options.algorithm)) {
        throw UsageError("unknown algorithm \"" + algorithm_name + "\" (known: " + known_algorithms(false) + ")");
    }
    if (args->voronoi && args->format == Format::Off) {
        throw UsageError("--voronoi adds the Voronoi diagram to JSON output or draws its cells in SVG, not in OFF "
                         "(add --format json or --format svg)");
    }
    if (args->input.empty()) throw UsageError("INPUT is an empty file name");
    return true;
}

// ---- writers ----

/// Appends `values` as a JSON array of numbers.
template <typename Int>
void append_json_array(std::string& out, const std::vector<Int>& values) {
    out += '[';
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i) out += ',';
        out += std::to_string(values[i]);
    }
    out += ']';
}

/// OFF: every input point (z = 0) in input order, so OFF indices are input indices, then the
/// triangles. Duplicates are written too (no triangle uses them).
std::string write_delaunay_off(hullkit::PointSpan2 points, const hullkit::Delaunay& result) {
    std::string out = "OFF\n";
    append_uint(out, points.count);
    out += ' ';
    append_uint(out, result.triangle_count());
    out += " 0\n";
    for (std::size_t i = 0; i < points.count; ++i) {
        out += hullkit::format_double(points[i][0]);
        out += ' ';
        out += hullkit::format_double(points[i][1]);
        out += " 0\n";
    }
    for (std::size_t t = 0; t < result.triangle_count(); ++t) {
        out += "3";
        for (int k = 0; k < 3; ++k) {
            out += ' ';
            append_uint(out, result.triangles[3 * t + k]);
        }
        out += '\n';
    }
    return out;
}

/// JSON pairs [[a,b],...] from a flat array.
template <typename Number>
void append_json_pairs(std::string& out, const std::vector<Number>& values) {
    out += '[';
    for (std::size_t i = 0; i + 1 < values.size(); i += 2) {
        if (i) out += ',';
        out += '[';
        if constexpr (std::is_floating_point_v<Number>) {
            out += hullkit::format_double(values[i]);
            out += ',';
            out += hullkit::format_double(values[i + 1]);
        } else {
            out += std::to_string(values[i]);
            out += ',';
            out += std::to_string(values[i + 1]);
        }
        out += ']';
    }
    out += ']';
}

/// The whole Voronoi diagram as a JSON object, per input point like `hullkit delaunay3 --voronoi`:
/// "cells" lists each point's vertices counter-clockwise (an unbounded cell ends with -1, the vertex
/// at infinity), "area" is null for those; a repeated point has no cell of its own ([] and null).
void append_voronoi_json(std::string& out, const hullkit::VoronoiDiagram& v, const hullkit::Delaunay& result) {
    out += "{\"vertices\":";
    append_json_pairs(out, v.vertices);
    out += ",\"triangle_vertex\":";
    append_json_array(out, v.triangle_vertex);
    out += ",\"ridge_points\":";
    append_json_pairs(out, v.ridge_points);
    out += ",\"ridge_vertices\":";
    append_json_pairs(out, v.ridge_vertices);
    out += ",\"cells\":[";
    std::string areas;
    for (std::size_t i = 0; i < v.point_cell.size(); ++i) {
        if (i) {
            out += ',';
            areas += ',';
        }
        const std::int32_t c = v.point_cell[i];
        if (c < 0 || (!result.representative.empty() && result.representative[i] != i)) {
            out += "[]";
            areas += "null";
            continue;
        }
        out += '[';
        for (std::int64_t k = v.cell_offsets[c]; k < v.cell_offsets[c + 1]; ++k) {
            if (k != v.cell_offsets[c]) out += ',';
            out += std::to_string(v.cells[k]);
        }
        out += ']';
        areas += std::isfinite(v.areas[c]) ? hullkit::format_double(v.areas[c]) : std::string("null");
    }
    out += "],\"area\":[";
    out += areas;
    out += "]}";
}

std::string write_delaunay_json(const hullkit::Delaunay& result, const hullkit::VoronoiDiagram* voronoi) {
    std::string out = "{\"dimension\":" + std::to_string(result.dimension) + ",\"triangles\":[";
    for (std::size_t t = 0; t < result.triangle_count(); ++t) {
        if (t) out += ',';
        out += '[';
        for (int k = 0; k < 3; ++k) {
            if (k) out += ',';
            append_uint(out, result.triangles[3 * t + k]);
        }
        out += ']';
    }
    out += "],\"halfedges\":";
    append_json_array(out, result.halfedges);
    out += ",\"hull\":";
    append_json_array(out, result.hull);
    out += ",\"duplicates\":[";
    bool first = true;
    for (std::size_t i = 0; i < result.representative.size(); ++i) {
        if (result.representative[i] == i) continue;
        if (!first) out += ',';
        first = false;
        out += '[';
        append_uint(out, i);
        out += ',';
        append_uint(out, result.representative[i]);
        out += ']';
    }
    out += ']';
    if (!result.polygon_offsets.empty()) {
        out += ",\"polygons\":[";
        for (std::size_t p = 0; p + 1 < result.polygon_offsets.size(); ++p) {
            if (p) out += ',';
            out += '[';
            for (std::uint32_t k = result.polygon_offsets[p]; k < result.polygon_offsets[p + 1]; ++k) {
                if (k != result.polygon_offsets[p]) out += ',';
                append_uint(out, result.polygon_vertices[k]);
            }
            out += ']';
        }
        out += ']';
    }
    if (voronoi) {
        out += ",\"voronoi\":";
        append_voronoi_json(out, *voronoi, result);
    }
    out += "}\n";
    return out;
}

/// The triangulation's edges (each once), the hull, the points and optionally the Voronoi cells.
std::string write_delaunay_svg(hullkit::PointSpan2 points, const hullkit::Delaunay& result, bool voronoi) {
    const SvgFrame frame = frame_of(points);
    std::string title = "Delaunay triangulation: ";
    append_uint(title, points.count);
    title += " points, ";
    append_uint(title, result.triangle_count());
    title += " triangles";
    std::string out = svg_header(frame, title);

    if (voronoi) {
        const hullkit::VoronoiCells cells =
            hullkit::delaunay_voronoi(points, result, frame.xmin, frame.ymin, frame.xmax, frame.ymax);
        out += "<g id=\"voronoi\" fill=\"#fde68a\" fill-opacity=\"0.45\" stroke=\"#d97706\" stroke-width=\"0.8\">\n";
        for (std::size_t i = 0; i + 1 < cells.cell_offsets.size(); ++i) {
            if (cells.cell_offsets[i + 1] - cells.cell_offsets[i] < 3) continue;
            out += "<polygon points=\"";
            for (std::uint32_t k = cells.cell_offsets[i]; k < cells.cell_offsets[i + 1]; ++k) {
                if (k != cells.cell_offsets[i]) out += ' ';
                append_svg_point(out, frame, cells.cell_xy[2 * k], cells.cell_xy[2 * k + 1]);
            }
            out += "\"/>\n";
        }
        out += "</g>\n";
    }

    // Every undirected edge once: a hull half-edge, or the half of an interior pair with the
    // larger index.
    out += "<path id=\"triangles\" fill=\"none\" stroke=\"#2563eb\" stroke-width=\"0.8\" stroke-linecap=\"round\" d=\"";
    for (std::size_t e = 0; e < result.triangles.size(); ++e) {
        if (result.halfedges[e] >= 0 && static_cast<std::size_t>(result.halfedges[e]) > e) continue;
        const std::size_t next = e % 3 == 2 ? e - 2 : e + 1;
        const double* a = points[result.triangles[e]];
        const double* b = points[result.triangles[next]];
        out += 'M';
        append_svg_point(out, frame, a[0], a[1]);
        out += 'L';
        append_svg_point(out, frame, b[0], b[1]);
    }
    out += "\"/>\n";

    if (!result.hull.empty()) {
        // Collinear points (dimension 1) give the line through them, not a closed polygon.
        out += result.dimension == 2 ? "<polygon" : "<polyline";
        out += " id=\"hull\" fill=\"none\" stroke=\"#111827\" stroke-width=\"2\" stroke-linejoin=\"round\" points=\"";
        for (std::size_t k = 0; k < result.hull.size(); ++k) {
            if (k) out += ' ';
            const double* p = points[result.hull[k]];
            append_svg_point(out, frame, p[0], p[1]);
        }
        out += "\"/>\n";
    }

    // Dots only while they stay visible as dots; a million would just fill the picture.
    if (points.count <= 20000) {
        out += "<g id=\"points\" fill=\"#dc2626\">\n";
        for (std::size_t i = 0; i < points.count; ++i) {
            if (!result.representative.empty() && result.representative[i] != i) continue;
            out += "<circle cx=\"";
            append_pixel(out, frame.x(points[i][0]));
            out += "\" cy=\"";
            append_pixel(out, frame.y(points[i][1]));
            out += "\" r=\"2\"/>\n";
        }
        out += "</g>\n";
    }
    out += "</svg>\n";
    return out;
}

std::string source_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

hullkit::Points2Result load_points_2d(const std::string& path, std::string* text) {
    *text = read_input(path);
    hullkit::Points2Result points = hullkit::read_points_2d(*text, source_name(path));
    if (!points.ok()) throw UsageError(points.error);
    return points;
}

int delaunay_main(const std::vector<std::string>& argv) {
    DelaunayArgs args;  // not const: the progress callback goes into its options
    if (!parse_delaunay_args(argv, &args)) return kExitOk;
    std::string text;
    const hullkit::Points2Result points = load_points_2d(args.input, &text);
    if (!args.quiet) print_warnings(source_name(args.input), points.warnings);
    const hullkit::PointSpan2 span(points.xy);

    const auto start = std::chrono::steady_clock::now();
    hullkit::Delaunay result;
    {
        // Cleared when `progress` goes, before anything else is written.
        hullkit_cli::Progress progress("points", 0, args.quiet);
        args.options.progress = [&progress](std::size_t done, std::size_t total) {
            progress.set_total(total);
            progress.update(done);
        };
        result = hullkit::delaunay(span, args.options);
        args.options.progress = nullptr;  // it refers to `progress`
    }
    const auto stop = std::chrono::steady_clock::now();
    if (!result.ok()) {
        std::string where = source_name(args.input);
        if (result.error_point >= 0) {
            // Name the line too: read the text again, this time keeping each point's line.
            std::vector<std::size_t> lines;
            hullkit::parse_points_2d(text, where, &lines);
            if (static_cast<std::size_t>(result.error_point) < lines.size()) {
                where += ":" + std::to_string(lines[static_cast<std::size_t>(result.error_point)]);
            }
        }
        throw UsageError(where + ": " + result.error);
    }

    std::string out;
    switch (args.format) {
        case Format::Off: out = write_delaunay_off(span, result); break;
        case Format::Json:
            if (args.voronoi) {
                const hullkit::VoronoiDiagram diagram = hullkit::delaunay_voronoi_diagram(span, result, args.options.threads);
                if (!diagram.ok()) throw UsageError(source_name(args.input) + ": " + diagram.error);
                out = write_delaunay_json(result, &diagram);
            } else {
                out = write_delaunay_json(result, nullptr);
            }
            break;
        case Format::Svg: out = write_delaunay_svg(span, result, args.voronoi); break;
    }
    write_output(args.output, out);
    if (args.stats) {
        std::fprintf(stderr, "{\"points\":%zu,\"triangles\":%zu,\"hull\":%zu,\"algorithm\":\"%s\",\"seconds\":%.9g}\n",
                     points.count(), result.triangle_count(), result.hull.size(),
                     hullkit::delaunay_algorithm_name(args.options.algorithm),
                     std::chrono::duration<double>(stop - start).count());
    }
    return kExitOk;
}

int verify_delaunay_main(const std::vector<std::string>& argv) {
    CLI::App app{"hullkit verify-delaunay", "hullkit verify-delaunay"};
    app.set_help_flag();
    bool help = false;
    std::vector<std::string> files;
    app.add_flag("-h,--help", help);
    app.add_option("files", files);
    parse_or_throw(app, argv, "verify-delaunay");
    if (help) {
        std::fputs(kVerifyDelaunayUsage, stdout);
        return kExitOk;
    }
    if (files.size() != 2) {
        throw UsageError("verify-delaunay needs two files, POINTS and TRIANGLES, got " +
                         std::to_string(files.size()) + " (try 'hullkit verify-delaunay --help')");
    }
    if (files[1] == "-") throw UsageError("TRIANGLES must be a file ('-' is allowed for POINTS only)");
    std::string text;
    const hullkit::Points2Result points = load_points_2d(files[0], &text);
    const hullkit::MeshResult mesh = read_mesh_file(files[1]);

    // Tie each mesh vertex to the input point with the same coordinates (in the plane z = 0).
    std::vector<double> xyz(3 * points.count());
    for (std::size_t i = 0; i < points.count(); ++i) {
        xyz[3 * i] = points.xy[2 * i];
        xyz[3 * i + 1] = points.xy[2 * i + 1];
    }
    const std::vector<std::int64_t> found = hullkit::match_points(
        hullkit::PointSpan(xyz), hullkit::PointSpan(mesh.xyz.data(), mesh.point_count()));
    std::vector<std::string> unmatched;
    for (std::size_t k = 0; k < found.size(); ++k) {
        if (found[k] >= 0) continue;
        const double* v = &mesh.xyz[3 * k];
        unmatched.push_back(files[1] + ": vertex " + std::to_string(k) + " (" + hullkit::format_double(v[0]) + " " +
                            hullkit::format_double(v[1]) + " " + hullkit::format_double(v[2]) +
                            ") is not one of the input points (with z = 0)");
    }
    hullkit::DelaunayVerifyReport report;
    if (unmatched.empty()) {
        std::vector<std::uint32_t> triangles(mesh.triangles.size());
        for (std::size_t k = 0; k < triangles.size(); ++k) {
            triangles[k] = static_cast<std::uint32_t>(found[mesh.triangles[k]]);
        }
        report = hullkit::verify_delaunay(hullkit::PointSpan2(points.xy), triangles.data(), mesh.triangle_count());
    }
    if (unmatched.empty() && report.ok) {
        std::printf("ok: %zu points (%zu distinct, %zu on the hull), %zu triangles\n", points.count(),
                    report.distinct_points, report.hull_points, mesh.triangle_count());
        return kExitOk;
    }
    const std::size_t shown = std::min<std::size_t>(unmatched.size(), 20);
    for (std::size_t k = 0; k < shown; ++k) std::printf("%s\n", unmatched[k].c_str());
    if (shown < unmatched.size()) std::printf("... and %zu more unmatched vertices\n", unmatched.size() - shown);
    for (const std::string& line : report.problems) std::printf("%s\n", line.c_str());
    const std::size_t count = unmatched.empty() ? report.problem_count : unmatched.size();
    std::printf("not a Delaunay triangulation: %zu problem%s\n", count, count == 1 ? "" : "s");
    return kExitNotDelaunay;
}

}  // namespace

int run_delaunay(const std::vector<std::string>& args) {
    try {
        return delaunay_main(args);
    } catch (const UsageError& error) {
        return print_usage_error(error.what());
    }
}

int run_verify_delaunay(const std::vector<std::string>& args) {
    try {
        const int status = verify_delaunay_main(args);
        if (std::fflush(stdout) != 0) throw UsageError(std::string("<stdout>: cannot write: ") + std::strerror(errno));
        return status;
    } catch (const UsageError& error) {
        return print_usage_error(error.what());
    }
}

}  // namespace hullkit_cli
