// `hullkit verify POINTS HULL`: reads a point set and a hull file (any mesh format), matches the
// hull's vertices to input points by exact coordinates, and runs hullkit::verify.
#include "verify_command.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_io.hpp"
#include "hullkit/hull.hpp"
#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"
#include "hullkit/verify.hpp"

namespace hullkit_cli {
namespace {

constexpr int kExitNotAHull = 1;

const char* const kVerifyUsage =
    R"(Usage: hullkit verify [options] POINTS HULL

Checks, with exact arithmetic, that HULL is the convex hull of the 3D points in
POINTS: its triangles close up into a convex surface facing outwards, every
point lies inside or on it, only extreme points are its vertices (the lowest
index of identical points), and no triangle has zero area.

POINTS: any input of 'hullkit hull' ('-': standard input). HULL: a mesh file in
any format the other commands read (OFF, OBJ, PLY, STL, glTF; the format from
the content, then the name), as 'hullkit hull' writes it. Its vertices are
matched to the input points with exactly the same coordinates, so the float32
positions of STL and GLB match only points whose coordinates are floats. A hull
of lower dimension is recognised by its shape: no vertex (no points), 1 vertex
(a point), 2 vertices (a segment), or a polygon fanned from its first vertex.

Prints 'ok: N points, F triangles, V vertices', or each problem on its own line.

Options:
  -h, --help          show this help

Exit status: 0 the hull is correct, 1 it is not, 2 a usage or input problem
(one line on standard error).
)";

std::string coordinates(const double* p) {
    return hullkit::format_double(p[0]) + " " + hullkit::format_double(p[1]) + " " + hullkit::format_double(p[2]);
}

/// True if the triangles (OFF indices) are the fan 0 k k+1 of an m-gon, as written for a polygon.
bool is_polygon_fan(const std::vector<std::uint32_t>& triangles, std::size_t m) {
    if (m < 3 || triangles.size() != 3 * (m - 2)) return false;
    for (std::size_t k = 1; k + 1 < m; ++k) {
        const std::uint32_t* t = &triangles[3 * (k - 1)];
        if (t[0] != 0 || t[1] != k || t[2] != k + 1) return false;
    }
    return true;
}

int verify_files(const std::string& points_path, const std::string& hull_path) {
    const std::string points_name = points_path == "-" ? "<stdin>" : points_path;
    hullkit::PointsResult points = hullkit::read_points(read_input(points_path), points_name);
    if (!points.ok()) throw UsageError(points.error);
    const hullkit::MeshResult mesh = read_mesh_file(hull_path);

    // Each hull vertex is the input point with the same coordinates (the lowest index of equals).
    const std::size_t m = mesh.point_count();
    const std::vector<std::int64_t> found =
        hullkit::match_points(hullkit::PointSpan(points.xyz), hullkit::PointSpan(mesh.xyz.data(), m));
    std::vector<std::uint32_t> input_index(m);
    std::vector<std::string> unmatched;
    for (std::size_t k = 0; k < m; ++k) {
        input_index[k] = static_cast<std::uint32_t>(found[k]);
        if (found[k] < 0) {
            unmatched.push_back(hull_path + ": vertex " + std::to_string(k) + " (" + coordinates(&mesh.xyz[3 * k]) +
                                ") is not one of the input points");
        }
    }
    if (!unmatched.empty()) {
        const std::size_t shown = std::min(unmatched.size(), hullkit::kVerifyMaxProblems);
        for (std::size_t k = 0; k < shown; ++k) std::printf("%s\n", unmatched[k].c_str());
        if (shown < unmatched.size()) {
            std::printf("... and %zu more unmatched vertices\n", unmatched.size() - shown);
        }
        return kExitNotAHull;
    }

    const hullkit::PointSpan span(points.xyz);
    std::vector<std::uint32_t> triangles(mesh.triangles.size());
    for (std::size_t k = 0; k < triangles.size(); ++k) triangles[k] = input_index[mesh.triangles[k]];

    hullkit::VerifyReport report;
    std::vector<std::string> extra;
    if (m >= 3 && !is_polygon_fan(mesh.triangles, m)) {
        // A solid: the triangles say everything; a hull vertex no triangle uses is a problem.
        report = hullkit::verify(span, triangles.data(), triangles.size() / 3);
        std::vector<char> used(m, 0);
        for (std::uint32_t k : mesh.triangles) used[k] = 1;
        for (std::size_t k = 0; k < m; ++k) {
            if (!used[k]) extra.push_back("vertex " + std::to_string(k) + " (point " + std::to_string(input_index[k]) +
                                          ") is not a corner of any triangle");
        }
    } else {
        hullkit::Hull hull;
        hull.dimension = static_cast<int>(std::min<std::size_t>(m, 3)) - 1;
        hull.vertices = input_index;
        hull.triangles = triangles;
        report = hullkit::verify(span, hull);
    }

    if (report.ok && extra.empty()) {
        std::printf("ok: %zu points, %zu triangles, %zu vertices\n", points.count(), report.triangle_count, m);
        return kExitOk;
    }
    for (const std::string& line : report.lines()) std::printf("%s\n", line.c_str());
    for (const std::string& line : extra) std::printf("%s\n", line.c_str());
    for (const std::string& note : report.notes) std::printf("note: %s\n", note.c_str());
    std::printf("not the convex hull: %zu problem%s\n", report.problem_count + extra.size(),
                report.problem_count + extra.size() == 1 ? "" : "s");
    return kExitNotAHull;
}

}  // namespace

int run_verify(const std::vector<std::string>& args) {
    try {
        std::vector<std::string> files;
        bool options_ended = false;
        for (const std::string& arg : args) {
            if (!options_ended && arg.size() > 1 && arg[0] == '-') {
                if (arg == "--") {
                    options_ended = true;
                } else if (arg == "-h" || arg == "--help") {
                    std::fputs(kVerifyUsage, stdout);
                    return kExitOk;
                } else {
                    throw UsageError("unknown option \"" + arg + "\" (try 'hullkit verify --help')");
                }
            } else {
                files.push_back(arg);
            }
        }
        if (files.size() != 2) {
            throw UsageError("verify needs two files, POINTS and HULL, got " + std::to_string(files.size()) +
                             " (try 'hullkit verify --help')");
        }
        if (files[1] == "-") throw UsageError("HULL must be a file ('-' is allowed for POINTS only)");
        const int status = verify_files(files[0], files[1]);
        if (std::fflush(stdout) != 0) throw UsageError(std::string("<stdout>: cannot write: ") + std::strerror(errno));
        return status;
    } catch (const UsageError& error) {
        return print_usage_error(error.what());
    }
}

}  // namespace hullkit_cli
