// Scene JSON (native/src/route/scene_io.cpp): the issue's example scene, every malformed scene
// with its message, mesh loading through a callback, and the report writer read back by an
// independent JSON parser.
#include "hullkit/scene_io.hpp"

#include "cli/cli_support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace {

using hullkit::Scene;
using hullkit::SceneResult;

/// A loader over an in-memory set of files (what the JS layer does with options.files).
hullkit::MeshLoader map_loader(std::map<std::string, std::string> files) {
    return [files](const std::string& path, std::string* bytes, std::string* error) {
        auto it = files.find(path);
        if (it == files.end()) {
            *error = path + ": no such mesh given";
            return false;
        }
        *bytes = it->second;
        return true;
    };
}

const char* const kCube = R"("vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "triangles": [[0,2,1],[0,1,3],[0,3,2],[1,2,3]])";

/// A valid scene with one field replaced: `part`, `route` and `rest` are spliced in as JSON text.
std::string scene_with(const std::string& part, const std::string& route = "[[0,0,0],[1,0,0]]",
                       const std::string& rest = R"("obstacles": [{"box": {"min": [4,-1,-1], "max": [5,1,1]}}])") {
    return R"({"traverse": {"parts": [)" + part + R"(]}, "route": )" + route + ", " + rest + "}";
}

std::string error_of(const std::string& json, const hullkit::MeshLoader& loader = {}) {
    SceneResult result = hullkit::parse_scene(json, "s.json", loader);
    REQUIRE_FALSE(result.ok());
    REQUIRE(result.scene.parts.empty());
    REQUIRE(result.scene.obstacles.empty());
    REQUIRE(result.error.find('\n') == std::string::npos);
    return result.error;
}

/// Six times the signed volume of a closed mesh (positive when outward oriented).
double six_volume(const hullkit::TriangleMesh& mesh) {
    double sum = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
        const double* a = &mesh.xyz[3 * mesh.triangles[t]];
        const double* b = &mesh.xyz[3 * mesh.triangles[t + 1]];
        const double* c = &mesh.xyz[3 * mesh.triangles[t + 2]];
        sum += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return sum;
}

}  // namespace

TEST_CASE("scene_io: the issue's crane scene", "[scene_io]") {
    SceneResult result = hullkit::read_scene_file(hullkit_test::data_path("route/crane.json"));
    INFO(result.error);
    REQUIRE(result.ok());
    const Scene& scene = result.scene;
    REQUIRE(scene.parts.size() == 3);
    CHECK(scene.parts[0].name == "load");
    CHECK(scene.parts[0].xyz.size() == 3 * 8);        // the STL's 36 corners merged into 8
    CHECK(scene.parts[0].triangles.size() == 3 * 12);
    CHECK(six_volume(scene.parts[0]) == Approx(6.0));  // a unit box, outward
    CHECK(scene.parts[1].name == "hook");
    CHECK(scene.parts[1].triangles == std::vector<std::uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3});
    CHECK(scene.parts[2].name == "spreader");
    CHECK(six_volume(scene.parts[2]) == Approx(6 * 2 * 2 * 0.2));
    CHECK(scene.route == std::vector<double>{0, 0, 0, 10, 0, 0, 10, 5, 0, 10, 5, -3});
    REQUIRE(scene.obstacles.size() == 4);
    CHECK(scene.obstacles[0].name == "wall");
    CHECK(scene.obstacles[1].name == "plate");
    CHECK(scene.obstacles[2].name == "vessel");
    CHECK(scene.obstacles[2].triangles.size() == 3 * 10);  // 5 quads
    CHECK(scene.obstacles[3].name == "obstacle 3");        // unnamed: named by its index
    CHECK(scene.obstacles[3].triangles.size() == 3 * 12);  // the OFF post's 6 quads
    CHECK(scene.margin == 0.05);
}

TEST_CASE("scene_io: boxes are closed and outward for every axis", "[scene_io]") {
    SceneResult result = hullkit::parse_scene(
        scene_with(R"({"box": {"min": [-1,-2,-3], "max": [4,5,6]}})", "[[0,0,0],[1,1,1]]", R"("obstacles": [])"), "s.json", {});
    INFO(result.error);
    REQUIRE(result.ok());
    const hullkit::TriangleMesh& box = result.scene.parts[0];
    CHECK(box.name == "part 0");
    CHECK(six_volume(box) == Approx(6.0 * 5 * 7 * 9));
    // Closed: every directed edge appears once and its reverse once.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t t = 0; t < box.triangles.size(); t += 3) {
        for (int k = 0; k < 3; ++k) edges[{box.triangles[t + k], box.triangles[t + (k + 1) % 3]}]++;
    }
    CHECK(edges.size() == 36);
    for (const auto& [edge, count] : edges) {
        CHECK(count == 1);
        CHECK(edges.count({edge.second, edge.first}) == 1);
    }
    CHECK(result.scene.margin == 0.0);
    CHECK(result.scene.obstacles.empty());
}

TEST_CASE("scene_io: meshes through a loader, as the JS layer passes bytes", "[scene_io]") {
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::string json = scene_with(R"({"mesh": "traverse.parts[0].mesh"})", "[[0,0,0],[1,0,0]]",
                                        R"("obstacles": [{"mesh": "vessel.obj"}])");
    SceneResult ok = hullkit::parse_scene(json, "scene", map_loader({{"traverse.parts[0].mesh", obj}, {"vessel.obj", obj}}));
    INFO(ok.error);
    REQUIRE(ok.ok());
    CHECK(ok.scene.parts[0].triangles.size() == 3);
    // A broken mesh handed in as bytes is named once, by its field.
    CHECK(error_of(json, map_loader({{"traverse.parts[0].mesh", "v 0 0 0\nf 1 2 3\n"}, {"vessel.obj", obj}})) ==
          "s.json: traverse.parts[0].mesh:2: face index 2 out of range (1 vertices)");
    // A named file: the field, then the file and line.
    CHECK(error_of(json, map_loader({{"traverse.parts[0].mesh", obj}, {"vessel.obj", obj + "f 1 2 9\n"}})) ==
          "s.json: obstacles[0].mesh: vessel.obj:5: face index 9 out of range (3 vertices)");
    CHECK(error_of(json, map_loader({{"traverse.parts[0].mesh", obj}})) ==
          "s.json: obstacles[0].mesh: vessel.obj: no such mesh given");
    CHECK(error_of(json) == "s.json: traverse.parts[0].mesh: mesh files cannot be read here");
}

TEST_CASE("scene_io: mesh files relative to the scene file", "[scene_io]") {
    hullkit_test::TempDir dir("hullkit-scene");
    hullkit_test::write_text(dir.file("bad.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
    const std::string base = scene_with(std::string("{") + kCube + "}", "[[0,0,0],[1,0,0]]", R"("obstacles": [{"mesh": "MESH"}])");
    auto with_mesh = [&](const std::string& name) {
        std::string text = base;
        text.replace(text.find("MESH"), 4, name);
        hullkit_test::write_text(dir.file("s.json"), text);
        return hullkit::read_scene_file(dir.file("s.json"));
    };
    CHECK(with_mesh("bad.obj").error == dir.file("s.json") + ": obstacles[0].mesh: bad.obj:3: face index 9 out of range (2 vertices)");
    CHECK(with_mesh("missing.stl").error ==
          dir.file("s.json") + ": obstacles[0].mesh: " + dir.file("missing.stl") + ": cannot open: No such file or directory");
    hullkit_test::write_text(dir.file("short.stl"), std::string(90, '\0'));
    CHECK(with_mesh("short.stl").error ==
          dir.file("s.json") + ": obstacles[0].mesh: short.stl: binary STL is too long: 84 + 50*N bytes expected (N = 0 "
                               "triangles: 84 bytes), got 90");
    CHECK(hullkit::read_scene_file(dir.file("nope.json")).error == dir.file("nope.json") + ": cannot open: No such file or directory");
}

TEST_CASE("scene_io: every malformed scene gives one message naming the field", "[scene_io]") {
    const std::string part = std::string("{") + kCube + "}";
    struct Case {
        std::string json;
        std::string message;
    };
    const Case cases[] = {
        {" \n", "s.json: empty file, expected a JSON scene"},
        {"{\"route\": [[0,0,NaN]]}", "s.json: invalid JSON: parse error at line 1, column 17: syntax error while parsing value - "
                                     "invalid literal; last read: '0,N'"},
        {"{\"margin\": 1e999}", "s.json: invalid JSON: number overflow parsing '1e999'"},
        {"[1, 2]", "s.json: expected an object, got an array"},
        {R"({"route": [[0,0,0],[1,0,0]], "obstacles": []})", "s.json: missing \"traverse\""},
        {R"({"traverse": {}, "route": [[0,0,0],[1,0,0]], "obstacles": []})", "s.json: traverse: missing \"parts\""},
        {R"({"traverse": {"parts": []}, "route": [[0,0,0],[1,0,0]], "obstacles": []})",
         "s.json: traverse.parts: no parts (the traverse needs at least one)"},
        {R"({"traverse": {"parts": [)" + part + R"(]}, "obstacles": []})", "s.json: missing \"route\""},
        {R"({"traverse": {"parts": [)" + part + R"(]}, "route": [[0,0,0],[1,0,0]]})", "s.json: missing \"obstacles\""},
        {scene_with(part, "[[0,0,0]]"), "s.json: route: needs at least 2 waypoints, got 1"},
        {scene_with(part, "[]"), "s.json: route: needs at least 2 waypoints, got 0"},
        {scene_with(part, "{\"from\": 1}"), "s.json: route: expected an array of waypoints [x, y, z], got an object"},
        {scene_with(part, "[[0,0,0],[1,0]]"),
         "s.json: route[1]: expected 3 numbers [x, y, z] or {\"position\": [x, y, z], \"rotation\": ...}, got 2 values"},
        {scene_with(part, "[[0,0,0],[1,0,0,0,0,0,1]]"),
         "s.json: route[1]: expected 3 numbers [x, y, z] or {\"position\": [x, y, z], \"rotation\": ...}, got 7 values"},
        {scene_with(part, "[[0,0,0],[1,\"2\",0]]"),
         "s.json: route[1]: expected 3 numbers [x, y, z] or {\"position\": [x, y, z], \"rotation\": ...}, entry 1 is a string"},
        {scene_with(part, "[[0,0,0],{\"position\": [1,0,0], \"rotation\": [0,0,0,1]}]"),
         "s.json: route[1].rotation: expected {\"quaternion\": [w, x, y, z]}, {\"axis\": [x, y, z], \"degrees\": a} or {\"yaw_pitch_roll_degrees\": [yaw, pitch, roll]}, got an array"},
        {scene_with(R"({"box": {"min": [0,0,0], "max": [1,1,1]}, "orientation": [0,0,1]})"),
         "s.json: traverse.parts[0].orientation: a rotation belongs to a waypoint: {\"position\": [x, y, z], \"rotation\": {\"quaternion\": [w, x, y, z]}} (or \"axis\" with \"degrees\", or \"yaw_pitch_roll_degrees\")"},
        {R"({"transform": [1,0,0], "traverse": {"parts": [)" + part + R"(]}, "route": [[0,0,0],[1,0,0]], "obstacles": []})",
         "s.json: transform: a rotation belongs to a waypoint: {\"position\": [x, y, z], \"rotation\": {\"quaternion\": [w, x, y, z]}} (or \"axis\" with \"degrees\", or \"yaw_pitch_roll_degrees\")"},
        {scene_with(part, "[[0,0,0],[1,0,0]]", R"("obstacles": [], "margn": 0.1)"),
         "s.json: margn: unknown key (known here: traverse, route, obstacles, margin)"},
        {scene_with(R"({"name": "a", "verts": [[0,0,0]]})"),
         "s.json: traverse.parts[0].verts: unknown key (known here: name, box, vertices, triangles, mesh)"},
        {scene_with(part, "[[0,0,0],[1,0,0]]",
                    R"("obstacles": [{"box": {"min": [0,0,0], "max": [1,1,1]}}, )" + part +
                        R"(, {"box": {"min": [0,0], "max": [1,1,1]}}])"),
         "s.json: obstacles[2].box.min: expected 3 numbers [x, y, z], got 2 values"},
        {scene_with(part, "[[0,0,0],[1,0,0]]", R"("obstacles": [{"box": {"min": [0,0,0]}}])"), "s.json: obstacles[0].box: missing \"max\""},
        {scene_with(part, "[[0,0,0],[1,0,0]]", R"("obstacles": [{"box": {"min": [0,2,0], "max": [1,1,1]}}])"),
         "s.json: obstacles[0].box: min[1] is greater than max[1]"},
        {scene_with(part, "[[0,0,0],[1,0,0]]", R"("obstacles": [{"box": [0,0,0,1,1,1]}])"),
         "s.json: obstacles[0].box: expected an object, got an array"},
        {scene_with(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2],[0,1,3]]})"),
         "s.json: traverse.parts[0].triangles[1][2]: index 3 out of range (3 vertices)"},
        {scene_with(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,-1]]})"),
         "s.json: traverse.parts[0].triangles[0][2]: index -1 out of range (3 vertices)"},
        {scene_with(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,1.5]]})"),
         "s.json: traverse.parts[0].triangles[0][2]: expected a vertex index (an integer >= 0), got a number"},
        {scene_with(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1]]})"),
         "s.json: traverse.parts[0].triangles[0]: expected 3 vertex indices [i, j, k]"},
        {scene_with(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": []})"), "s.json: traverse.parts[0].triangles: no triangles"},
        {scene_with(R"({"vertices": [[0,0,0],[1,0,null],[0,1,0]], "triangles": [[0,1,2]]})"),
         "s.json: traverse.parts[0].vertices[1]: expected 3 numbers [x, y, z], entry 2 is null"},
        {scene_with(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]]})"), "s.json: traverse.parts[0]: \"vertices\" without \"triangles\""},
        {scene_with(R"({"triangles": [[0,1,2]]})"), "s.json: traverse.parts[0]: \"triangles\" without \"vertices\""},
        {scene_with(R"({"name": "x"})"), "s.json: traverse.parts[0]: needs one of \"box\", \"vertices\" + \"triangles\" or \"mesh\""},
        {scene_with(R"({"box": {"min": [0,0,0], "max": [1,1,1]}, "mesh": "a.stl"})"),
         "s.json: traverse.parts[0]: give only one of \"box\", \"vertices\" + \"triangles\" and \"mesh\""},
        {scene_with(R"({"name": 7, "box": {"min": [0,0,0], "max": [1,1,1]}})"), "s.json: traverse.parts[0].name: expected a string, got a number"},
        {scene_with(R"({"mesh": 7})"), "s.json: traverse.parts[0].mesh: expected a file name, got a number"},
        {scene_with(part, "[[0,0,0],[1,0,0]]", R"("obstacles": {"box": 1})"), "s.json: obstacles: expected an array, got an object"},
        {scene_with(part, "[[0,0,0],[1,0,0]]", R"("obstacles": [], "margin": -0.5)"), "s.json: margin: must be >= 0"},
        {scene_with(part, "[[0,0,0],[1,0,0]]", R"("obstacles": [], "margin": "0.5")"), "s.json: margin: expected a number, got a string"},
    };
    for (const Case& c : cases) {
        INFO(c.json);
        CHECK(error_of(c.json) == c.message);
    }
}

TEST_CASE("scene_io: a checker's scene may leave the route out", "[scene_io]") {
    const std::string json = R"({"traverse": {"parts": [{"box": {"min": [0,0,0], "max": [1,1,1]}}]}, "obstacles": []})";
    hullkit::SceneReadOptions options;
    options.require_route = false;
    SceneResult result = hullkit::parse_scene(json, "s.json", {}, options);
    INFO(result.error);
    REQUIRE(result.ok());
    CHECK(result.scene.route.empty());
    CHECK(error_of(json) == "s.json: missing \"route\"");
}

TEST_CASE("scene_io: the report JSON, read back by nlohmann", "[scene_io]") {
    Scene scene;
    scene.parts.resize(2);
    scene.parts[0].name = "load";
    scene.parts[1].name = "hook \"7\"";  // quotes must be escaped
    scene.obstacles.resize(3);
    scene.obstacles[0].name = "wall";
    scene.obstacles[2].name = "plate";
    hullkit::RouteReport report;
    report.clear = false;
    report.min_clearance = 0.1 + 0.2;  // needs 17 digits to read back exactly
    report.build_seconds = 0.25;
    report.seconds = 1.5e-3;
    hullkit::LegReport hit;
    hit.status = hullkit::LegStatus::Hit;
    hit.obstacle = 2;
    hit.triangle = 1;
    hit.part = 1;
    hit.fraction_lo = 0.4 - 1e-12;
    hit.fraction_hi = 0.4;
    hit.position[0] = 4.0;
    hit.position[1] = -0.0;
    hit.position[2] = 1e300;
    hit.sampled_hit = false;
    hullkit::LegReport clear;
    clear.status = hullkit::LegStatus::Clear;
    clear.clearance = 0.3;
    clear.obstacle = 0;
    clear.fraction_lo = clear.fraction_hi = 0.75;
    clear.sampled_hit = false;
    hullkit::LegReport unmeasured;  // clearance off: NaN clearance, no obstacle
    unmeasured.status = hullkit::LegStatus::Clear;
    hullkit::LegReport overlap;
    overlap.status = hullkit::LegStatus::StartOverlap;
    overlap.obstacle = 0;
    overlap.part = 0;
    overlap.triangle = 11;
    overlap.sampled_hit = true;
    overlap.sampled_fraction = 0;
    report.legs = {hit, clear, unmeasured, overlap};

    hullkit::RouteOptions with_samples;
    with_samples.samples = 20;
    const std::string text = hullkit::write_report_json(scene, report, with_samples);
    const nlohmann::json out = nlohmann::json::parse(text);
    CHECK(out["clear"] == false);
    CHECK(out["min_clearance"].get<double>() == 0.1 + 0.2);
    CHECK(out["build_seconds"].get<double>() == 0.25);
    CHECK(out["seconds"].get<double>() == 1.5e-3);
    REQUIRE(out["legs"].size() == 4);
    const nlohmann::json expected_hit = {
        {"status", "hit"},      {"obstacle", "plate"},
        {"triangle", 1},        {"part", "hook \"7\""},
        {"fraction", {0.4 - 1e-12, 0.4}}, {"position", {4.0, -0.0, 1e300}},
        {"sampled", {{"hit", false}, {"fraction", nullptr}}}};
    CHECK(out["legs"][0] == expected_hit);
    CHECK(out["legs"][1] == nlohmann::json({{"status", "clear"}, {"clearance", 0.3}, {"obstacle", "wall"}, {"fraction", 0.75},
                                            {"sampled", {{"hit", false}, {"fraction", nullptr}}}}));
    CHECK(out["legs"][2] == nlohmann::json({{"status", "clear"}, {"clearance", nullptr}, {"obstacle", nullptr}, {"fraction", nullptr},
                                            {"sampled", {{"hit", false}, {"fraction", nullptr}}}}));
    CHECK(out["legs"][3] == nlohmann::json({{"status", "start-overlap"}, {"obstacle", "wall"}, {"part", "load"}, {"triangle", 11},
                                            {"sampled", {{"hit", true}, {"fraction", 0}}}}));
    // Key order as documented (the ordered writer keeps it), one leg per line.
    CHECK(text.find("{\"status\":\"hit\",\"obstacle\":\"plate\",\"triangle\":1,\"part\":") != std::string::npos);
    CHECK(std::count(text.begin(), text.end(), '\n') == 4 + 4);  // 4 legs, 4 lines around them

    // Without samples there is no "sampled"; an infinite clearance (no obstacles) is null.
    report.min_clearance = std::numeric_limits<double>::infinity();
    const nlohmann::json plain = nlohmann::json::parse(hullkit::write_report_json(scene, report, {}));
    CHECK(plain["min_clearance"].is_null());
    for (const auto& leg : plain["legs"]) CHECK_FALSE(leg.contains("sampled"));
    report.legs.clear();
    CHECK(nlohmann::json::parse(hullkit::write_report_json(scene, report, {}))["legs"] == nlohmann::json::array());
}

TEST_CASE("scene_io: messages show no control character or malformed UTF-8 from the scene (tests/data/fuzz)", "[scene_io]") {
    auto read = [](const std::string& name) {
        const std::string text = hullkit_test::read_text(hullkit_test::data_path("fuzz/" + name));
        REQUIRE_FALSE(text.empty());
        return error_of(text, map_loader({}));
    };
    // A newline and an escape sequence in a mesh file name (JSON escapes) used to reach the
    // terminal, and the newline split the one-line message.
    CHECK(read("scene-control-characters-in-mesh-name.json") ==
          "s.json: traverse.parts[0].mesh: a?b?[2J.stl: no such mesh given");
    // A key with ESC and the C1 control U+009B (CSI): replaced; the UTF-8 bullet before them is kept.
    CHECK(read("scene-escape-and-c1-in-key.json") ==
          "s.json: \xe2\x80\xa2?[2J?: unknown key (known here: traverse, route, obstacles, margin)");
    // Malformed UTF-8: nlohmann's message quotes the bytes it read; they come out as '?'.
    const std::string invalid = read("scene-invalid-utf8-string.json");
    CHECK(invalid.rfind("s.json: invalid JSON: ", 0) == 0);
    for (unsigned char c : invalid) CHECK((c >= 0x20 && c < 0x7f));
}
