// `hullkit route SCENE.json`: reads the scene (and the mesh files it names), checks its route with
// hullkit::RouteChecker and writes the report as JSON. No geometry here.
#include "route_command.hpp"

#include "cli_io.hpp"
#include "progress.hpp"

#include "hullkit/mesh_io.hpp"
#include "hullkit/route.hpp"
#include "hullkit/scene_io.hpp"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace hullkit_cli {

namespace {

constexpr int kExitClear = 0;
constexpr int kExitNotClear = 1;  // bad input exits 2 through the shared error path (cli_io)

const char* const kRouteUsage =
    R"(Usage: hullkit route SCENE [-o FILE] [--samples N] [--no-clearance]
                     [--threads N] [--quiet]

Checks a traverse moved along a route of straight translations, or of legs that
turn while they move, against obstacles, one check per leg (swept convex hulls,
exact predicates): no contact is missed and none is invented. Writes the report
as JSON: per leg "clear" (with its clearance), "hit" (the first contact as a
fraction of the leg, the obstacle, triangle and part) or "start-overlap".

Scene (JSON; '-' reads it from standard input):
  {"traverse": {"parts": [...], "pivot": [x,y,z]}, "route": [WAYPOINT, ...],
   "obstacles": [...], "margin": m}
  a WAYPOINT is [x,y,z] or {"position": [x,y,z], "rotation": ROTATION}, a
  ROTATION {"quaternion": [w,x,y,z]}, {"axis": [x,y,z], "degrees": a} or
  {"yaw_pitch_roll_degrees": [yaw, pitch, roll]}; a part or obstacle is
  {"box": {"min", "max"}}, {"vertices", "triangles"} or {"mesh": FILE} (OBJ,
  OFF, PLY, STL, glTF; relative to the scene file). See docs/route-checking.md.

Options:
  -o, --output FILE   write the report to FILE instead of standard output
  --samples N         also report per leg what checking N+1 evenly spaced poses
                      would find ("sampled"), for comparison; a whole number
                      from 0 to 1000000 (default 0: none)
  --no-clearance      do not compute the clearance of clear legs (faster)
  --threads N         check legs on N threads, a whole number from 0 to 1024:
                      0 (default) every hardware thread, 1 this thread only;
                      the report is the same for every N
  --quiet             no progress line (otherwise shown on a terminal's
                      standard error when the check takes more than about a
                      second) and no warnings about skipped mesh records
  -h, --help          show this help

Exit status: 0 every leg clear, 1 some leg not clear, 2 a usage or input problem
(one line on standard error).
)";

}  // namespace

int run_route(const std::vector<std::string>& args) {
    std::vector<std::string> scenes;
    std::string output;
    unsigned samples = 0;
    unsigned threads = 0;
    bool no_clearance = false;
    bool quiet = false;
    bool help = false;
    try {
        CLI::App app("hullkit route", "hullkit route");
        app.set_help_flag();  // the help text above, in the layout of every command
        app.add_flag("-h,--help", help);
        app.add_option("SCENE", scenes);
        add_whole_number_option(app, "--samples", &samples, 0, 1000000);
        app.add_flag("--no-clearance", no_clearance);
        // Bounded: a mistyped huge N would start a thread per block.
        add_whole_number_option(app, "--threads", &threads, 0, 1024);
        app.add_flag("--quiet", quiet);
        app.add_option("-o,--output", output)->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
        parse_or_throw(app, args, "route");
        if (help) {
            std::fputs(kRouteUsage, stdout);
            return kExitClear;
        }
        if (scenes.size() != 1) {
            throw UsageError("route needs one SCENE file, got " + std::to_string(scenes.size()) + " (try 'hullkit route --help')");
        }
        if (app.count("--output") && output.empty()) throw UsageError("option --output needs a file name");
    } catch (const UsageError& error) {
        return print_usage_error(error.what());
    }
    const std::string& scene_path = scenes[0];

    hullkit::SceneResult scene = hullkit::read_scene_file(scene_path);
    if (!scene.ok()) return print_usage_error(scene.error);
    if (!quiet) print_warnings("", scene.warnings);

    hullkit::RouteOptions options;
    options.clearance = !no_clearance;
    options.samples = samples;
    options.threads = threads;
    hullkit::RouteChecker checker(std::move(scene.scene));
    if (!checker.error().empty()) return print_usage_error(scene_path + ": " + checker.error());
    hullkit::RouteReport report;
    {
        // Progress::update is thread-safe, as RouteOptions::progress requires; the line is
        // cleared when `progress` goes, before the report is written.
        const std::size_t waypoints = checker.scene().route.size() / 3;
        Progress progress("legs", waypoints > 0 ? waypoints - 1 : 0, quiet);
        options.progress = [&progress](std::size_t legs_done) { progress.update(legs_done); };
        report = checker.check(options);
        options.progress = nullptr;  // it refers to `progress`
    }
    if (!report.ok()) return print_usage_error(scene_path + ": " + report.error);

    try {
        write_output(output, hullkit::write_report_json(checker.scene(), report, options));
    } catch (const UsageError& error) {
        return print_usage_error(error.what());
    }
    return report.clear ? kExitClear : kExitNotClear;
}

}  // namespace hullkit_cli
