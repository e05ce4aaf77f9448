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

const char* const kRouteDescription =
    "Checks a traverse moved along a route of straight translations, or of legs that turn while they\n"
    "move, against obstacles, one check per leg (swept convex hulls, exact predicates): no contact\n"
    "is missed and none is invented. Writes the report as JSON: per leg \"clear\" (with its\n"
    "clearance), \"hit\" (the first contact as a fraction of the leg, the obstacle, triangle and\n"
    "part) or \"start-overlap\".\n"
    "Scene: {\"traverse\": {\"parts\": [...], \"pivot\": [x,y,z]}, \"route\": [WAYPOINT, ...],\n"
    "\"obstacles\": [...], \"margin\": m}; a WAYPOINT is [x,y,z] or {\"position\": [x,y,z],\n"
    "\"rotation\": {\"quaternion\": [w,x,y,z]} or {\"axis\": [x,y,z], \"degrees\": a}}; a part or\n"
    "obstacle is {\"box\": {\"min\", \"max\"}}, {\"vertices\", \"triangles\"} or {\"mesh\": FILE}\n"
    "(OBJ, OFF, PLY, STL, glTF; relative to the scene file). See README.md.\n"
    "Exit status: 0 every leg clear, 1 some leg not clear, 2 a usage or input problem.";

}  // namespace

int run_route(const std::vector<std::string>& args) {
    CLI::App app(kRouteDescription, "hullkit route");
    std::string scene_path;
    std::string output;
    std::uint32_t samples = 0;
    unsigned threads = 0;
    bool no_clearance = false;
    bool quiet = false;
    app.add_option("SCENE", scene_path, "the scene (JSON); '-' reads standard input")->required()->type_name("");
    app.add_option("--samples", samples,
                   "also report per leg what checking N+1 evenly spaced poses would find (\"sampled\"), "
                   "for comparison")
        ->type_name("N")
        ->check(CLI::Range(0u, 1000000u));
    app.add_flag("--no-clearance", no_clearance, "do not compute the clearance of clear legs (faster)");
    app.add_option("--threads", threads,
                   "check legs on N threads: 0 (default) every hardware thread, 1 this thread only; "
                   "the report is the same for every N")
        ->type_name("N")
        ->check(CLI::Range(0u, 1024u));  // bounded: a mistyped huge N would start a thread per block
    app.add_flag("--quiet", quiet,
                 "no progress line (otherwise shown on a terminal's standard error when the check "
                 "takes more than about a second)");
    app.add_option("-o,--output", output, "write the report to FILE instead of standard output")->type_name("FILE");

    // CLI11 wants argv order reversed for its vector overload.
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    try {
        app.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        std::fputs(app.help().c_str(), stdout);
        return kExitClear;
    } catch (const CLI::ParseError& error) {
        return print_usage_error(std::string("route: ") + error.what() + " (try 'hullkit route --help')");
    }

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
