// hullkit_route_bench: hullkit's route check against FCL 0.7 on the same scene and route.
//
//   hullkit_route_bench --scene SCENE.json --route ROUTE.json [--runs N] [--reference-poses P]
//   hullkit_route_bench --scene SCENE.json --route A.json [--route B.json ...] --legs L --threads T
//                       [--no-clearance] [--runs N] [--dump FILE]
//
// SCENE is a `hullkit route` scene (its own route is ignored); ROUTE a JSON array of waypoints.
// With --threads (RouteOptions::threads) it times hullkit alone on L legs: the waypoints of the
// routes given, in turn and over again, as one route. It prints one JSON line: the first check
// in this process ("first_seconds": run it in a fresh process) and the median of N more
// ("warm_seconds"); --dump writes the report with every double as its bits, for `cmp` against
// another thread count's. Otherwise it prints one JSON line per method to stdout:
//   hullkit            RouteChecker: build (hulls + BVH), check with clearance off (verdict and
//                      first contact) and on
//   fcl-100            fcl::collide (BVHModel<OBBRSS>) at 100 evenly spaced poses per leg, stopping
//                      at the first hit
//   fcl-ccd            fcl::continuousCollide with its default request, once per leg
//   fcl-reference      fcl::collide at P (default 2000) poses per leg: the reference verdicts
// each with per-leg verdicts ("hits": 1 hit / 0 clear) and medians over N runs of the timed part.
// The traverse's parts are merged into one FCL model, as are the obstacles.
#include "hullkit/mesh_io.hpp"
#include "hullkit/route.hpp"
#include "hullkit/scene_io.hpp"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/continuous_collision.h>
#include <fcl/geometry/bvh/BVH_model.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
using Model = fcl::BVHModel<fcl::OBBRSSd>;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

[[noreturn]] void die(const std::string& message) {
    std::fprintf(stderr, "hullkit_route_bench: %s\n", message.c_str());
    std::exit(2);
}

/// All meshes' triangles in one FCL model.
std::shared_ptr<Model> fcl_model(const std::vector<hullkit::TriangleMesh>& meshes) {
    auto model = std::make_shared<Model>();
    std::vector<fcl::Vector3d> points;
    std::vector<fcl::Triangle> triangles;
    for (const hullkit::TriangleMesh& mesh : meshes) {
        const std::size_t base = points.size();
        for (std::size_t i = 0; i < mesh.xyz.size(); i += 3) points.emplace_back(mesh.xyz[i], mesh.xyz[i + 1], mesh.xyz[i + 2]);
        for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
            triangles.emplace_back(base + mesh.triangles[t], base + mesh.triangles[t + 1], base + mesh.triangles[t + 2]);
        }
    }
    model->beginModel(static_cast<int>(triangles.size()), static_cast<int>(points.size()));
    model->addSubModel(points, triangles);
    model->endModel();
    return model;
}

fcl::Transform3d at(const double* a, const double* b, double f) {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() = fcl::Vector3d(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]));
    return tf;
}

/// fcl::collide at `poses` evenly spaced poses of each leg (fractions 0 ... 1), first hit stops.
std::vector<int> fcl_poses(const Model& traverse, const Model& obstacles, const std::vector<double>& route, int poses) {
    std::vector<int> hits;
    const fcl::Transform3d identity = fcl::Transform3d::Identity();
    fcl::CollisionRequestd request;  // defaults: one contact is enough
    for (std::size_t k = 0; k + 1 < route.size() / 3; ++k) {
        int hit = 0;
        for (int i = 0; i < poses && !hit; ++i) {
            fcl::CollisionResultd result;
            fcl::collide(&traverse, at(&route[3 * k], &route[3 * k + 3], double(i) / (poses - 1)), &obstacles, identity, request, result);
            hit = result.isCollision();
        }
        hits.push_back(hit);
    }
    return hits;
}

/// fcl::continuousCollide with the default request, one call per leg.
std::vector<int> fcl_ccd(const Model& traverse, const Model& obstacles, const std::vector<double>& route) {
    std::vector<int> hits;
    const fcl::Transform3d identity = fcl::Transform3d::Identity();
    fcl::ContinuousCollisionRequestd request;  // defaults: CCDC_NAIVE, 10 iterations
    for (std::size_t k = 0; k + 1 < route.size() / 3; ++k) {
        fcl::ContinuousCollisionResultd result;
        fcl::continuousCollide(&traverse, at(&route[3 * k], &route[3 * k + 3], 0), at(&route[3 * k], &route[3 * k + 3], 1),
                               &obstacles, identity, identity, request, result);
        hits.push_back(result.is_collide ? 1 : 0);
    }
    return hits;
}

/// Runs `body` `runs` times; returns the median seconds and keeps the last result.
template <typename Result>
double timed(int runs, const std::function<Result()>& body, Result* last) {
    std::vector<double> times;
    for (int r = 0; r < runs; ++r) {
        const Clock::time_point start = Clock::now();
        *last = body();
        times.push_back(seconds_since(start));
    }
    return median(times);
}

nlohmann::json line(const char* impl, const std::string& route_name, std::size_t legs) {
    return {{"impl", impl}, {"route", route_name}, {"legs", legs}};
}

/// The route's waypoints (flat x y z) from its JSON file.
std::vector<double> read_route(const std::string& path) {
    std::string text, error;
    if (!hullkit::read_file(path, &text, &error)) die(error);
    std::vector<double> route;
    for (const auto& point : nlohmann::json::parse(text)) {
        for (int axis = 0; axis < 3; ++axis) route.push_back(point.at(axis).get<double>());
    }
    return route;
}

/// "route-hit" for ".../route-hit.json".
std::string route_name_of(const std::string& path) {
    std::string name = path.substr(path.find_last_of('/') + 1);
    return name.substr(0, name.rfind('.'));
}

/// The report with every double as its bits (hex), one leg per line: equal files are equal
/// reports, field by field and bit by bit (the timings left out).
std::string canonical_report(const hullkit::RouteReport& report) {
    auto bits = [](double x) {
        std::uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        char text[20];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(b));
        return std::string(text);
    };
    std::string out = "clear " + std::to_string(report.clear) + " min_clearance " + bits(report.min_clearance) + "\n";
    for (const hullkit::LegReport& leg : report.legs) {
        out += std::string(hullkit::leg_status_name(leg.status)) + " " + std::to_string(leg.obstacle) + " " +
               std::to_string(leg.triangle) + " " + std::to_string(leg.part) + " " + std::to_string(leg.sampled_hit);
        for (double x : {leg.fraction_lo, leg.fraction_hi, leg.position[0], leg.position[1], leg.position[2],
                         leg.clearance, leg.sampled_fraction}) {
            out += " " + bits(x);
        }
        out += "\n";
    }
    return out;
}

/// The --threads mode: hullkit alone on `legs` legs cycling through `waypoints`, on `threads`
/// threads.
int run_threads(const hullkit::Scene& scene, const std::vector<double>& waypoints, const std::string& route_name,
                std::size_t legs, unsigned threads, bool clearance, int runs, const std::string& dump_path) {
    const std::size_t count = waypoints.size() / 3;
    if (count < 2) die("the routes have fewer than 2 waypoints");
    std::vector<double> route;
    for (std::size_t k = 0; k <= legs; ++k) route.insert(route.end(), &waypoints[3 * (k % count)], &waypoints[3 * (k % count) + 3]);
    const hullkit::RouteChecker checker(scene);
    if (!checker.error().empty()) die(checker.error());
    hullkit::RouteOptions options;
    options.clearance = clearance;
    options.threads = threads;
    // The first check in this process: nothing of the check path is warm yet.
    Clock::time_point start = Clock::now();
    hullkit::RouteReport report = checker.check(route.data(), legs + 1, options);
    const double first = seconds_since(start);
    if (!report.ok()) die(report.error);
    const std::string canonical = canonical_report(report);
    hullkit::RouteReport warm_report;
    const double warm = timed<hullkit::RouteReport>(runs, [&] { return checker.check(route.data(), legs + 1, options); }, &warm_report);
    if (canonical_report(warm_report) != canonical) die("two checks in one process gave different reports");
    if (!dump_path.empty()) {
        std::FILE* file = std::fopen(dump_path.c_str(), "wb");
        if (!file || std::fwrite(canonical.data(), 1, canonical.size(), file) != canonical.size() || std::fclose(file) != 0) {
            die(dump_path + ": cannot write");
        }
    }
    std::size_t hit = 0;
    for (const hullkit::LegReport& leg : report.legs) hit += leg.status != hullkit::LegStatus::Clear;
    nlohmann::json out = line("hullkit-threads", route_name, legs);
    out["threads"] = threads;
    out["hardware_threads"] = std::thread::hardware_concurrency();
    out["clearance"] = clearance;
    out["legs_not_clear"] = hit;
    out["build_seconds"] = checker.build_seconds();
    out["first_seconds"] = first;
    out["warm_seconds"] = warm;
    out["runs"] = runs;
    std::printf("%s\n", out.dump().c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::string scene_path, dump_path;
    std::vector<std::string> route_paths;
    int runs = 5, reference_poses = 2000, threads = -1;
    long threads_legs = 10000;
    bool clearance = true;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--no-clearance") {
            clearance = false;
            continue;
        }
        if (i + 1 >= argc) die("option " + arg + " needs a value");
        if (arg == "--scene") scene_path = argv[++i];
        else if (arg == "--route") route_paths.push_back(argv[++i]);
        else if (arg == "--runs") runs = std::max(1, std::atoi(argv[++i]));
        else if (arg == "--reference-poses") reference_poses = std::max(2, std::atoi(argv[++i]));
        else if (arg == "--threads") threads = std::max(0, std::atoi(argv[++i]));
        else if (arg == "--legs") threads_legs = std::max(1L, std::atol(argv[++i]));
        else if (arg == "--dump") dump_path = argv[++i];
        else die("unknown option " + arg);
    }
    if (scene_path.empty() || route_paths.empty()) die("usage: hullkit_route_bench --scene SCENE.json --route ROUTE.json [--runs N]");

    hullkit::SceneResult scene = hullkit::read_scene_file(scene_path);
    if (!scene.ok()) die(scene.error);
    if (threads >= 0) {
        std::vector<double> waypoints;
        std::string names;
        for (const std::string& path : route_paths) {
            const std::vector<double> more = read_route(path);
            waypoints.insert(waypoints.end(), more.begin(), more.end());
            names += (names.empty() ? "" : "+") + route_name_of(path);
        }
        return run_threads(scene.scene, waypoints, names, static_cast<std::size_t>(threads_legs),
                           static_cast<unsigned>(threads), clearance, runs, dump_path);
    }
    if (route_paths.size() != 1 || !clearance || !dump_path.empty()) {
        die("one --route; --no-clearance, --dump and more routes go with --threads");
    }
    const std::vector<double> route = read_route(route_paths[0]);
    const std::size_t legs = route.size() / 3 - 1;
    const std::string route_name = route_name_of(route_paths[0]);
    std::size_t obstacle_triangles = 0, traverse_vertices = 0;
    for (const auto& mesh : scene.scene.obstacles) obstacle_triangles += mesh.triangles.size() / 3;
    for (const auto& mesh : scene.scene.parts) traverse_vertices += mesh.xyz.size() / 3;

    // ---- hullkit: build, then verdicts with and without clearance.
    {
        std::unique_ptr<hullkit::RouteChecker> checker;
        std::vector<double> builds;
        for (int r = 0; r < runs; ++r) {
            hullkit::Scene copy = scene.scene;  // the copy is not timed
            const Clock::time_point start = Clock::now();
            checker = std::make_unique<hullkit::RouteChecker>(std::move(copy));
            builds.push_back(seconds_since(start));
        }
        if (!checker->error().empty()) die(checker->error());
        hullkit::RouteOptions verdict_only;
        verdict_only.clearance = false;
        hullkit::RouteReport fast, full;
        const double fast_s = timed<hullkit::RouteReport>(runs, [&] { return checker->check(route.data(), legs + 1, verdict_only); }, &fast);
        const double full_s = timed<hullkit::RouteReport>(runs, [&] { return checker->check(route.data(), legs + 1, {}); }, &full);
        if (!fast.ok()) die(fast.error);
        nlohmann::json out = line("hullkit", route_name, legs);
        std::vector<int> hits, hits_full;
        std::vector<double> first;
        for (const auto& leg : fast.legs) {
            hits.push_back(leg.status != hullkit::LegStatus::Clear);
            first.push_back(leg.status == hullkit::LegStatus::Clear ? -1.0 : leg.fraction_lo);
        }
        for (const auto& leg : full.legs) hits_full.push_back(leg.status != hullkit::LegStatus::Clear);
        out["obstacle_triangles"] = obstacle_triangles;
        out["traverse_vertices"] = traverse_vertices;
        out["build_seconds"] = median(builds);
        out["ms_per_leg"] = 1e3 * fast_s / legs;
        out["ms_per_leg_clearance"] = 1e3 * full_s / legs;
        out["hits"] = hits;
        out["hits_with_clearance"] = hits_full;
        out["first_fraction"] = first;
        out["min_clearance"] = std::isfinite(full.min_clearance) ? nlohmann::json(full.min_clearance) : nlohmann::json(nullptr);
        std::printf("%s\n", out.dump().c_str());
        std::fflush(stdout);
    }

    // ---- FCL: build the two models, then the three methods.
    std::shared_ptr<Model> traverse, obstacles;
    std::vector<double> builds;
    for (int r = 0; r < std::min(runs, 3); ++r) {
        const Clock::time_point start = Clock::now();
        obstacles = fcl_model(scene.scene.obstacles);
        traverse = fcl_model(scene.scene.parts);
        builds.push_back(seconds_since(start));
    }
    const double fcl_build = median(builds);

    std::vector<int> hits;
    double s = timed<std::vector<int>>(std::min(runs, 3), [&] { return fcl_poses(*traverse, *obstacles, route, 100); }, &hits);
    nlohmann::json out = line("fcl-100", route_name, legs);
    out["build_seconds"] = fcl_build;
    out["ms_per_leg"] = 1e3 * s / legs;
    out["hits"] = hits;
    std::printf("%s\n", out.dump().c_str());
    std::fflush(stdout);

    s = timed<std::vector<int>>(std::min(runs, 3), [&] { return fcl_ccd(*traverse, *obstacles, route); }, &hits);
    out = line("fcl-ccd", route_name, legs);
    out["ms_per_leg"] = 1e3 * s / legs;
    out["hits"] = hits;
    std::printf("%s\n", out.dump().c_str());
    std::fflush(stdout);

    s = timed<std::vector<int>>(1, [&] { return fcl_poses(*traverse, *obstacles, route, reference_poses); }, &hits);
    out = line("fcl-reference", route_name, legs);
    out["poses"] = reference_poses;
    out["ms_per_leg"] = 1e3 * s / legs;
    out["hits"] = hits;
    std::printf("%s\n", out.dump().c_str());
    return 0;
}
