// `hullkit route` (native/cli/route_command.cpp) run as a process: scenes whose answers are
// worked out by hand, the exit status, the report on stdout or in a file, --samples and
// --no-clearance, --threads (the same report for every thread count) and --quiet, and every
// malformed scene of the issue giving exit 2 and its one-line message.
#include "cli/cli_support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

using hullkit_test::RunResult;
using hullkit_test::TempDir;
using nlohmann::json;

/// A unit cube [0,1]^3 named "cube" moved along `route`; a slab "wall" x in [3, 4]; and whatever
/// `extra` obstacles (JSON text, with a leading comma).
std::string cube_scene(const std::string& route, double margin = 0, const std::string& extra = "") {
    return R"({"traverse": {"parts": [{"name": "cube", "box": {"min": [0,0,0], "max": [1,1,1]}}]},
  "route": )" + route + R"(,
  "obstacles": [{"name": "wall", "box": {"min": [3,-10,-10], "max": [4,10,10]}})" + extra + R"(],
  "margin": )" + std::to_string(margin) + "}";
}

RunResult run_scene(const TempDir& dir, const std::string& scene, std::vector<std::string> options = {}) {
    hullkit_test::write_text(dir.file("scene.json"), scene);
    options.insert(options.begin(), {"route", dir.file("scene.json")});
    return hullkit_test::run_cli(dir, options);
}

json report_of(const RunResult& run) {
    INFO(run.err);
    REQUIRE(run.err.empty());
    return json::parse(run.out);
}

/// lo <= exact <= hi, hi - lo <= 1e-9 (the issue's bracket).
void require_bracket(const json& leg, double exact) {
    INFO(leg.dump());
    REQUIRE(leg["status"] == "hit");
    const double lo = leg["fraction"][0], hi = leg["fraction"][1];
    CHECK(lo <= exact);
    CHECK(exact <= hi);
    CHECK(hi - lo <= 1e-9);
}

/// The report text without its timings: everything before "build_seconds", which the last line
/// holds together with "seconds" and nothing else.
std::string without_timings(const RunResult& run) {
    INFO(run.err);
    REQUIRE(run.err.empty());
    const std::size_t at = run.out.rfind("\"build_seconds\": ");
    REQUIRE(at != std::string::npos);
    const std::string tail = run.out.substr(at);
    INFO(tail);
    REQUIRE(std::regex_match(tail, std::regex(R"("build_seconds": [-+.e0-9]+, "seconds": [-+.e0-9]+\}\n)")));
    return run.out.substr(0, at);
}

std::string one_error_line(const RunResult& run) {
    INFO(run.out);
    REQUIRE(run.exit_code == 2);
    REQUIRE(run.out.empty());
    const std::vector<std::string> lines = run.err_lines();
    REQUIRE(lines.size() == 1);
    return lines[0];
}

}  // namespace

TEST_CASE("cli route: a cube into a wall, first contact exact", "[cli_route]") {
    TempDir dir("hullkit-route");
    // The cube's face x = 1 meets the wall x = 3 after moving 2 of 5: fraction 0.4.
    RunResult run = run_scene(dir, cube_scene("[[0,0,0],[5,0,0]]"));
    CHECK(run.exit_code == 1);
    json report = report_of(run);
    CHECK(report["clear"] == false);
    REQUIRE(report["legs"].size() == 1);
    const json& leg = report["legs"][0];
    require_bracket(leg, 0.4);
    CHECK(leg["obstacle"] == "wall");
    CHECK(leg["part"] == "cube");
    CHECK(std::abs(leg["position"][0].get<double>() - 2.0) <= 1e-8);
    CHECK(leg["position"][1] == 0.0);
    CHECK(leg["triangle"].get<int>() >= 0);
    CHECK(leg["triangle"].get<int>() < 12);
    CHECK(report["build_seconds"].get<double>() >= 0);
    CHECK(report["seconds"].get<double>() >= 0);

    // With a margin of 0.5 the contact comes 0.5 earlier: at 1.5 of 5.
    require_bracket(report_of(run_scene(dir, cube_scene("[[0,0,0],[5,0,0]]", 0.5)))["legs"][0], 0.3);
}

TEST_CASE("cli route: clear legs report their clearance, exit 0", "[cli_route]") {
    TempDir dir("hullkit-route");
    // Moving along y, 2 away from the wall all the time; then along z, still 2 away.
    RunResult run = run_scene(dir, cube_scene("[[0,0,0],[0,5,0],[0,5,3]]", 0.25));
    CHECK(run.exit_code == 0);
    json report = report_of(run);
    CHECK(report["clear"] == true);
    CHECK(std::abs(report["min_clearance"].get<double>() - 2.0) <= 2e-9);
    REQUIRE(report["legs"].size() == 2);
    for (const json& leg : report["legs"]) {
        INFO(leg.dump());
        CHECK(leg["status"] == "clear");
        CHECK(std::abs(leg["clearance"].get<double>() - 2.0) <= 2e-9);
        CHECK(leg["obstacle"] == "wall");
        CHECK(leg["fraction"].get<double>() >= 0);
        CHECK(leg["fraction"].get<double>() <= 1);
        CHECK_FALSE(leg.contains("sampled"));
    }
    // --no-clearance: the verdict alone.
    json fast = report_of(run_scene(dir, cube_scene("[[0,0,0],[0,5,0],[0,5,3]]", 0.25), {"--no-clearance"}));
    CHECK(fast["clear"] == true);
    for (const json& leg : fast["legs"]) {
        CHECK(leg["status"] == "clear");
        CHECK(leg["clearance"].is_null());
    }
}

TEST_CASE("cli route: starting in contact", "[cli_route]") {
    TempDir dir("hullkit-route");
    // The cube starts at x in [2.5, 3.5], inside the wall's slab; leg 1 moves it away but starts there too.
    RunResult run = run_scene(dir, cube_scene("[[2.5,0,0],[2.5,0,5],[-5,0,5]]"));
    CHECK(run.exit_code == 1);
    json report = report_of(run);
    REQUIRE(report["legs"].size() == 2);
    for (const json& leg : report["legs"]) {
        INFO(leg.dump());
        CHECK(leg["status"] == "start-overlap");
        CHECK(leg["obstacle"] == "wall");
        CHECK(leg["part"] == "cube");
        CHECK(leg.contains("triangle"));
    }
}

TEST_CASE("cli route: a thin plate that sampling misses", "[cli_route]") {
    TempDir dir("hullkit-route");
    // A zero-thickness plate at x = 2.2 (before the wall). The cube moves 10 along x; 4-step
    // sampling looks at offsets 0, 2.5, 5, 7.5, 10: the cube spans [0,1], [2.5,3.5] ... and the
    // wall at 3..4 is seen at 2.5, but the plate at 2.2 never is. The exact answer: the plate at
    // offset 1.2, fraction 0.12.
    const std::string plate = R"(, {"name": "plate", "vertices": [[2.2,-5,-5],[2.2,5,-5],[2.2,0,5]], "triangles": [[0,1,2]]})";
    json report = report_of(run_scene(dir, cube_scene("[[0,0,0],[10,0,0]]", 0, plate), {"--samples", "4"}));
    const json& leg = report["legs"][0];
    require_bracket(leg, 0.12);
    CHECK(leg["obstacle"] == "plate");
    CHECK(leg["triangle"] == 0);
    CHECK(leg["sampled"]["hit"] == true);
    CHECK(leg["sampled"]["fraction"] == 0.25);  // sampling only finds the wall, at 2.5 of 10

    // Moving along y past the plate's edge: sampling at 4 steps finds nothing, and neither does
    // the exact check, whose clearance is 1.2 (to the plate).
    json along = report_of(run_scene(dir, cube_scene("[[0,0,0],[0,3,0]]", 0, plate), {"--samples=4"}));
    const json& clear = along["legs"][0];
    CHECK(clear["status"] == "clear");
    CHECK(std::abs(clear["clearance"].get<double>() - 1.2) <= 1.2e-9);
    CHECK(clear["obstacle"] == "plate");
    CHECK(clear["sampled"] == json({{"hit", false}, {"fraction", nullptr}}));
}

TEST_CASE("cli route: the issue's crane scene (meshes from STL, OBJ, OFF)", "[cli_route]") {
    TempDir dir("hullkit-route");
    RunResult run = hullkit_test::run_cli(dir, {"route", hullkit_test::data_path("route/crane.json")});
    CHECK(run.exit_code == 1);
    json report = report_of(run);
    REQUIRE(report["legs"].size() == 3);
    // Leg 0: the hook and the spreader reach x = 1; with the margin 0.05 the wall (x = 4) is met
    // after 2.95 of 10.
    require_bracket(report["legs"][0], 0.295);
    CHECK(report["legs"][0]["obstacle"] == "wall");
    // Leg 1: the load's underside (z = -1.5) passes 0.3 above the vessel's rim (z = -1.8).
    CHECK(report["legs"][1]["status"] == "clear");
    CHECK(std::abs(report["legs"][1]["clearance"].get<double>() - 0.3) <= 1e-9);
    CHECK(report["legs"][1]["obstacle"] == "vessel");
    // Leg 2: lowered into the open vessel; the hook ends 0.5 from its walls.
    CHECK(report["legs"][2]["status"] == "clear");
    CHECK(std::abs(report["legs"][2]["clearance"].get<double>() - 0.5) <= 1e-9);
    CHECK(report["legs"][2]["obstacle"] == "vessel");
}

TEST_CASE("cli route: a mesh file with unknown OBJ records gives a warning line, and the report", "[cli_route]") {
    TempDir dir("hullkit-route");
    // A tetrahedron obstacle far from the route, its OBJ starting with FCL's "V F" count line.
    hullkit_test::write_text(dir.file("tetra.obj"), "4 4\nv 10 10 10\nv 11 10 10\nv 10 11 10\nv 10 10 11\n"
                                                    "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    const std::string scene = cube_scene("[[0,0,0],[1,0,0]]", 0, R"(, {"name": "tetra", "mesh": "tetra.obj"})");
    RunResult run = run_scene(dir, scene);
    CHECK(run.exit_code == 0);
    CHECK(run.err == "hullkit: warning: " + dir.file("scene.json") +
                         ": obstacles[1].mesh: tetra.obj: skipped 1 unknown OBJ record \"4\" (first at line 1)\n");
    CHECK(json::parse(run.out)["legs"].size() == 1);
    RunResult quiet = run_scene(dir, scene, {"--quiet"});
    CHECK(quiet.exit_code == 0);
    CHECK(quiet.err.empty());
}

TEST_CASE("cli route: --threads 1 and --threads 3 print the same report, --quiet", "[cli_route][threads]") {
    TempDir dir("hullkit-route");
    // 300 legs zigzagging through the wall and beside it (hits, clear legs, start overlaps), so
    // that three threads share the legs; and the crane scene.
    std::string route = "[[0,0,0]";
    for (int k = 1; k <= 300; ++k) {
        route += ",[" + std::to_string(k % 7 - 1) + "," + std::to_string((13 * k) % 11 - 5) + "," +
                 std::to_string(k % 3) + "]";
    }
    route += "]";
    hullkit_test::write_text(dir.file("zigzag.json"), cube_scene(route, 0.25));
    for (const std::string& scene : {dir.file("zigzag.json"), hullkit_test::data_path("route/crane.json")}) {
        for (const std::vector<std::string>& extra : {std::vector<std::string>{}, {"--samples", "4", "--no-clearance"}}) {
            std::vector<std::string> args = {"route", scene};
            args.insert(args.end(), extra.begin(), extra.end());
            auto with = [&](std::vector<std::string> more) {
                std::vector<std::string> all = args;
                all.insert(all.end(), more.begin(), more.end());
                return hullkit_test::run_cli(dir, all);
            };
            CAPTURE(scene, extra);
            const RunResult one = with({"--threads", "1"});
            CHECK(one.exit_code == 1);
            const std::string expected = without_timings(one);
            const RunResult three = with({"--threads", "3"});
            CHECK(three.exit_code == one.exit_code);
            CHECK(without_timings(three) == expected);
            const RunResult all = with({"--threads=0"});
            CHECK(without_timings(all) == expected);
            // --quiet: accepted, the same report (the progress line only ever goes to a terminal).
            const RunResult quiet = with({"--quiet", "--threads", "2"});
            CHECK(quiet.exit_code == one.exit_code);
            CHECK(without_timings(quiet) == expected);
        }
    }
    // The zigzag has every kind of leg.
    const json report = report_of(hullkit_test::run_cli(dir, {"route", dir.file("zigzag.json"), "--quiet"}));
    std::set<std::string> statuses;
    for (const json& leg : report["legs"]) statuses.insert(leg["status"].get<std::string>());
    CHECK(statuses == std::set<std::string>{"clear", "hit", "start-overlap"});
}

TEST_CASE("cli route: output file, standard input, help", "[cli_route]") {
    TempDir dir("hullkit-route");
    const std::string scene = cube_scene("[[0,0,0],[0,5,0]]");
    hullkit_test::write_text(dir.file("scene.json"), scene);
    RunResult to_file = hullkit_test::run_cli(dir, {"route", dir.file("scene.json"), "-o", dir.file("report.json")});
    CHECK(to_file.exit_code == 0);
    CHECK(to_file.out.empty());
    CHECK(to_file.err.empty());
    const json from_file = json::parse(hullkit_test::read_text(dir.file("report.json")));
    CHECK(from_file["legs"][0]["status"] == "clear");

    RunResult from_stdin = hullkit_test::run_cli(dir, {"route", "-"}, dir.file("scene.json"));
    CHECK(from_stdin.exit_code == 0);
    CHECK(report_of(from_stdin)["legs"] == from_file["legs"]);

    RunResult help = hullkit_test::run_cli(dir, {"route", "--help"});
    CHECK(help.exit_code == 0);
    CHECK(help.out.find("--samples N") != std::string::npos);
    CHECK(help.out.find("--threads N") != std::string::npos);
    CHECK(help.out.find("--quiet") != std::string::npos);
    CHECK(help.out.find("Exit status: 0 every leg clear, 1 some leg not clear, 2") != std::string::npos);
}

TEST_CASE("cli route: usage problems give exit 2 and one line", "[cli_route]") {
    TempDir dir("hullkit-route");
    CHECK(one_error_line(hullkit_test::run_cli(dir, {"route"})) == "hullkit: route needs one SCENE file, got 0 (try 'hullkit route --help')");
    CHECK(one_error_line(hullkit_test::run_cli(dir, {"route", "a.json", "--bogus"})) ==
          "hullkit: unknown option \"--bogus\" (try 'hullkit route --help')");
    CHECK(one_error_line(hullkit_test::run_cli(dir, {"route", "a.json", "--samples", "-3"})) ==
          "hullkit: option --samples needs a whole number from 0 to 1000000, got \"-3\"");
    CHECK(one_error_line(hullkit_test::run_cli(dir, {"route", "a.json", "--threads", "-1"})) ==
          "hullkit: option --threads needs a whole number from 0 to 1024, got \"-1\"");
    CHECK(one_error_line(hullkit_test::run_cli(dir, {"route", "a.json", "--threads", "x"})) ==
          "hullkit: option --threads needs a whole number from 0 to 1024, got \"x\"");
    CHECK(one_error_line(hullkit_test::run_cli(dir, {"route", dir.file("none.json")})) ==
          "hullkit: " + dir.file("none.json") + ": cannot open: No such file or directory");
    hullkit_test::write_text(dir.file("scene.json"), cube_scene("[[0,0,0],[0,5,0]]"));
    CHECK(one_error_line(hullkit_test::run_cli(dir, {"route", dir.file("scene.json"), "-o", dir.file("no/such/dir.json")})) ==
          "hullkit: " + dir.file("no/such/dir.json") + ": cannot open for writing: No such file or directory");
}

TEST_CASE("cli route: every malformed scene of the issue gives exit 2 and its message", "[cli_route]") {
    TempDir dir("hullkit-route");
    const std::string scene_path = dir.file("scene.json");
    hullkit_test::write_text(dir.file("bad-index.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
    hullkit_test::write_text(dir.file("bad-number.stl"),
                             "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 zero 0\nvertex 0 1 0\n");
    hullkit_test::write_text(dir.file("truncated.stl"), std::string(80, ' ') + std::string("\x02\0\0\0", 4) + std::string(60, '\0'));
    const std::string part = R"({"name": "cube", "box": {"min": [0,0,0], "max": [1,1,1]}})";
    auto scene = [&](const std::string& route, const std::string& obstacles, const std::string& more = "") {
        return R"({"traverse": {"parts": [)" + part + R"(]}, "route": )" + route + R"(, "obstacles": )" + obstacles + more + "}";
    };
    const std::string ok_route = "[[0,0,0],[1,0,0]]";
    struct Case {
        std::string json;
        std::string message;  // after "hullkit: SCENE: "
    };
    const Case cases[] = {
        {R"({"traverse": {"parts": [)" + part + R"(]}, "obstacles": []})", "missing \"route\""},
        {R"({"route": [[0,0,0],[1,0,0]], "obstacles": []})", "missing \"traverse\""},
        {scene("[[0,0,0]]", "[]"), "route: needs at least 2 waypoints, got 1"},
        {scene("[[0,0,0],[1,NaN,0]]", "[]"),
         "invalid JSON: parse error at line 1, column 107: syntax error while parsing value - invalid literal; last read: '1,N'"},
        {scene("[[0,0,0],[1,\"NaN\",0]]", "[]"),
         "route[1]: expected 3 numbers [x, y, z] or {\"position\": [x, y, z], \"rotation\": ...}, entry 1 is a string"},
        {scene("[[0,0,0],[1,0,0]]", "[]", R"(, "margin": 1e400)"), "invalid JSON: number overflow parsing '1e400'"},
        {scene(ok_route, R"([{"mesh": "missing.stl"}])"),
         "obstacles[0].mesh: " + dir.file("missing.stl") + ": cannot open: No such file or directory"},
        {scene(ok_route, R"([{"mesh": "bad-index.obj"}])"), "obstacles[0].mesh: bad-index.obj:5: face index 4 out of range (3 vertices)"},
        {scene(ok_route, R"([{"mesh": "bad-number.stl"}])"), "obstacles[0].mesh: bad-number.stl:5: coordinate \"zero\" is not a finite number"},
        {scene(ok_route, R"([{"mesh": "truncated.stl"}])"),
         "obstacles[0].mesh: truncated.stl: binary STL is truncated: 84 + 50*N bytes expected (N = 2 triangles: 184 bytes), got 144"},
        {scene(ok_route, R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,3]]}])"),
         "obstacles[0].triangles[0][2]: index 3 out of range (3 vertices)"},
        {scene(ok_route, R"([{"box": {"min": [0,0], "max": [1,1,1]}}])"), "obstacles[0].box.min: expected 3 numbers [x, y, z], got 2 values"},
        {scene("[[0,0,0],{\"translation\": [1,0,0], \"rotation\": [0,0,90]}]", "[]"),
         "route[1].translation: unknown key (known here: position, rotation)"},
        {scene("[[0,0,0],{\"position\": [1,0,0], \"rotation\": [0,0,90]}]", "[]"),
         "route[1].rotation: expected {\"quaternion\": [w, x, y, z]}, {\"axis\": [x, y, z], \"degrees\": a} or {\"yaw_pitch_roll_degrees\": [yaw, pitch, roll]}, got an array"},
        {scene("[[0,0,0,0,0,0],[1,0,0,0,0,90]]", "[]"),
         "route[0]: expected 3 numbers [x, y, z] or {\"position\": [x, y, z], \"rotation\": ...}, got 6 values"},
        {scene(ok_route, "[]", R"(, "margin": -1)"), "margin: must be >= 0"},
        {scene(ok_route, "[]", R"(, "clearance": 1)"), "clearance: unknown key (known here: traverse, route, obstacles, margin)"},
    };
    for (const Case& c : cases) {
        INFO(c.json);
        hullkit_test::write_text(scene_path, c.json);
        CHECK(one_error_line(hullkit_test::run_cli(dir, {"route", scene_path})) == "hullkit: " + scene_path + ": " + c.message);
    }
}
