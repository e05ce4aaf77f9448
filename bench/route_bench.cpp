// hullkit_route_bench: hullkit's route check against FCL 0.7 on the same scene and route.
//
//   hullkit_route_bench --scene SCENE.json --route ROUTE.json [--runs N] [--reference-poses P]
//                       [--ccd naive|ca]
//   hullkit_route_bench --scene SCENE.json --route ROUTE.json --first-call [--no-clearance]
//   hullkit_route_bench --scene SCENE.json --route A.json [--route B.json ...] --legs L --threads T
//                       [--no-clearance] [--runs N] [--dump FILE]
//
// SCENE is a `hullkit route` scene (its own route is ignored); ROUTE a JSON array of waypoints,
// [x, y, z] or {"position": [x, y, z], "rotation": {...}} (read by hullkit::parse_route: a route
// with rotations has legs that turn about the scene's pivot).
// With --threads (RouteOptions::threads) it times hullkit alone on L legs: the waypoints of the
// routes given, in turn and over again, as one route. It prints one JSON line: the first check
// in this process ("first_seconds": run it in a fresh process) and the median of N more
// ("warm_seconds"); --dump writes the report with every double as its bits, for `cmp` against
// another thread count's.
// With --first-call it builds the checker and times one check (clearance on, or off with
// --no-clearance) on one thread: the first check in a fresh process ("hullkit-first").
// Otherwise it prints one JSON line per method to stdout, every hullkit check on one thread
// (RouteOptions::threads = 1: FCL is single-threaded):
//   hullkit            RouteChecker: build (hulls + BVH), check with clearance off (verdict and
//                      first contact; the first of these is the process's first check) and on;
//                      then, untimed, sanity checks of the reports against hullkit's own exact
//                      static test (RouteChecker::static_contact) at the reported poses
//   fcl-100            fcl::collide (BVHModel<OBBRSS>) at 100 evenly spaced poses per leg, stopping
//                      at the first hit
//   fcl-ccd            fcl::continuousCollide once per leg: --ccd naive (the default on straight
//                      routes) with its default request (CCDC_NAIVE: collide at 10 poses, translation
//                      motion); --ccd ca (the default on turning routes) with interp motion
//                      (fcl::InterpMotion about the pivot, what CCDM_LINEAR builds) and the
//                      conservative-advancement solver (CCDC_CONSERVATIVE_ADVANCEMENT)
//   fcl-reference      fcl::collide at P (default 2000) poses per leg: the reference verdicts
// each with per-leg verdicts ("hits": 1 hit / 0 clear), first-contact fractions, medians over N
// runs of the timed part (FCL: at most 3) and the first run's time.
// Poses: on a turning route every pose FCL tests is hullkit::leg_pose's (the checker's own motion),
// as an FCL transform x = pivot + R (v - pivot) + offset (translation pivot + offset - R pivot).
// The traverse's parts are merged into one FCL model, as are the obstacles.
#include "hullkit/mesh_io.hpp"
#include "hullkit/route.hpp"
#include "hullkit/scene_io.hpp"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/continuous_collision.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/motion/interp_motion.h>

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

/// A route: waypoints (flat x y z) and, on a turning route, an orientation per waypoint.
struct Route {
    std::vector<double> xyz;
    std::vector<double> rotations;  ///< empty, or w x y z per waypoint
    std::size_t waypoints() const { return xyz.size() / 3; }
    std::size_t legs() const { return waypoints() - 1; }
    bool turned() const { return !rotations.empty(); }
    const double* rotations_or_null() const { return turned() ? rotations.data() : nullptr; }
};

/// The pose hullkit's checker gives the traverse at fraction f of leg k: offset and quaternion.
void leg_pose_at(const Route& route, std::size_t k, double f, double offset[3], double rotation[4]) {
    if (!route.turned()) {
        const double* a = &route.xyz[3 * k];
        const double* b = a + 3;
        for (int i = 0; i < 3; ++i) offset[i] = a[i] + f * (b[i] - a[i]);
        rotation[0] = 1, rotation[1] = rotation[2] = rotation[3] = 0;
        return;
    }
    hullkit::leg_pose(&route.xyz[3 * k], &route.rotations[4 * k], &route.xyz[3 * k + 3], &route.rotations[4 * k + 4], f,
                      offset, rotation);
}

/// FCL's transform for a pose: x = pivot + R (v - pivot) + offset.
fcl::Transform3d transform_of(const double offset[3], const double q[4], const double pivot[3]) {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    const fcl::Matrix3d r = fcl::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
    const fcl::Vector3d c(pivot[0], pivot[1], pivot[2]);
    tf.linear() = r;
    tf.translation() = c + fcl::Vector3d(offset[0], offset[1], offset[2]) - r * c;
    return tf;
}

/// FCL's transform at fraction f of leg k (a straight route: the translation, as before).
fcl::Transform3d at(const Route& route, const double pivot[3], std::size_t k, double f) {
    if (!route.turned()) {
        const double* a = &route.xyz[3 * k];
        const double* b = a + 3;
        fcl::Transform3d tf = fcl::Transform3d::Identity();
        tf.translation() = fcl::Vector3d(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]));
        return tf;
    }
    double offset[3], rotation[4];
    leg_pose_at(route, k, f, offset, rotation);
    return transform_of(offset, rotation, pivot);
}

/// Per-leg verdicts (1 hit / 0 clear) and the fraction of the first contact found (-1 when clear).
struct Verdicts {
    std::vector<int> hits;
    std::vector<double> first;
};

/// fcl::collide at `poses` evenly spaced poses of each leg (fractions 0 ... 1), first hit stops.
Verdicts fcl_poses(const Model& traverse, const Model& obstacles, const Route& route, const double pivot[3], int poses) {
    Verdicts out;
    const fcl::Transform3d identity = fcl::Transform3d::Identity();
    fcl::CollisionRequestd request;  // defaults: one contact is enough
    for (std::size_t k = 0; k < route.legs(); ++k) {
        int hit = 0;
        double first = -1.0;
        for (int i = 0; i < poses && !hit; ++i) {
            fcl::CollisionResultd result;
            const double f = double(i) / (poses - 1);
            fcl::collide(&traverse, at(route, pivot, k, f), &obstacles, identity, request, result);
            hit = result.isCollision();
            if (hit) first = f;
        }
        out.hits.push_back(hit);
        out.first.push_back(first);
    }
    return out;
}

/// fcl::InterpMotion with a reference point, its velocities computed: FCL 0.7's constructor
/// taking the reference point leaves them unset, and the one without leaves the point itself
/// uninitialised. The reference point (the pivot) then moves linearly while the traverse turns
/// at constant angular speed about it along the shorter arc (the angle-axis of R1 R0^T, angle in
/// [0, pi]): the motion hullkit's checker gives the traverse.
class PivotInterpMotion : public fcl::InterpMotion<double> {
public:
    PivotInterpMotion(const fcl::Transform3d& begin, const fcl::Transform3d& end, const fcl::Vector3d& pivot)
        : fcl::InterpMotion<double>(begin, end, pivot) {
        computeVelocity();
    }
};

/// fcl::continuousCollide, one call per leg: `ca` false, the default request (CCDC_NAIVE, 10
/// iterations, translation motion); true, interp motion about the pivot and conservative advancement.
Verdicts fcl_ccd(const Model& traverse, const Model& obstacles, const Route& route, const double pivot[3], bool ca) {
    Verdicts out;
    const fcl::Transform3d identity = fcl::Transform3d::Identity();
    fcl::ContinuousCollisionRequestd request;  // defaults: CCDC_NAIVE, 10 iterations, CCDM_TRANS
    if (ca) {
        request.ccd_motion_type = fcl::CCDM_LINEAR;  // what it selects: fcl::InterpMotion (built here about the pivot)
        request.ccd_solver_type = fcl::CCDC_CONSERVATIVE_ADVANCEMENT;
    }
    const fcl::Vector3d c(pivot[0], pivot[1], pivot[2]);
    for (std::size_t k = 0; k < route.legs(); ++k) {
        fcl::ContinuousCollisionResultd result;
        if (ca) {
            const PivotInterpMotion moving(at(route, pivot, k, 0), at(route, pivot, k, 1), c);
            const PivotInterpMotion still(identity, identity, fcl::Vector3d::Zero());
            fcl::continuousCollide(&traverse, &moving, &obstacles, &still, request, result);
        } else {
            fcl::continuousCollide(&traverse, at(route, pivot, k, 0), at(route, pivot, k, 1), &obstacles, identity, identity,
                                   request, result);
        }
        out.hits.push_back(result.is_collide ? 1 : 0);
        out.first.push_back(result.is_collide ? result.time_of_contact : -1.0);
    }
    return out;
}

/// Median and first of `runs` timed runs.
struct Timing {
    double median = 0.0;
    double first = 0.0;
    std::vector<double> all;  ///< every run's seconds, in order
};

/// Runs `body` `runs` times; returns the median and the first run's seconds and keeps the last result.
template <typename Result>
Timing timed(int runs, const std::function<Result()>& body, Result* last) {
    std::vector<double> times;
    for (int r = 0; r < runs; ++r) {
        const Clock::time_point start = Clock::now();
        *last = body();
        times.push_back(seconds_since(start));
    }
    const double first = times.front();
    return {median(times), first, times};
}

nlohmann::json line(const char* impl, const std::string& route_name, std::size_t legs) {
    return {{"impl", impl}, {"route", route_name}, {"legs", legs}};
}

/// The route's waypoints and orientations from its JSON file (hullkit's own route reader).
Route read_route(const std::string& path) {
    std::string text, error;
    if (!hullkit::read_file(path, &text, &error)) die(error);
    hullkit::RouteResult parsed = hullkit::parse_route(text, path);
    if (!parsed.ok()) die(parsed.error);
    if (parsed.route.size() < 6) die(path + ": fewer than 2 waypoints");
    return {std::move(parsed.route), std::move(parsed.rotations)};
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
               std::to_string(leg.triangle) + " " + std::to_string(leg.part) + " " + std::to_string(leg.sampled_hit) + " " +
               std::to_string(leg.grazing);
        for (double x : {leg.fraction_lo, leg.fraction_hi, leg.position[0], leg.position[1], leg.position[2],
                         leg.rotation[0], leg.rotation[1], leg.rotation[2], leg.rotation[3], leg.clearance, leg.sampled_fraction}) {
            out += " " + bits(x);
        }
        out += "\n";
    }
    return out;
}

/// The --threads mode: hullkit alone on `legs` legs cycling through `waypoints`, on `threads`
/// threads.
int run_threads(const hullkit::Scene& scene, const Route& waypoints, const std::string& route_name,
                std::size_t legs, unsigned threads, bool clearance, int runs, const std::string& dump_path) {
    const std::size_t count = waypoints.waypoints();
    if (count < 2) die("the routes have fewer than 2 waypoints");
    Route route;
    for (std::size_t k = 0; k <= legs; ++k) {
        const std::size_t i = k % count;
        route.xyz.insert(route.xyz.end(), &waypoints.xyz[3 * i], &waypoints.xyz[3 * i + 3]);
        if (waypoints.turned()) route.rotations.insert(route.rotations.end(), &waypoints.rotations[4 * i], &waypoints.rotations[4 * i + 4]);
    }
    const hullkit::RouteChecker checker(scene);
    if (!checker.error().empty()) die(checker.error());
    hullkit::RouteOptions options;
    options.clearance = clearance;
    options.threads = threads;
    auto check = [&] { return checker.check(route.xyz.data(), route.rotations_or_null(), legs + 1, options); };
    // The first check in this process: nothing of the check path is warm yet.
    Clock::time_point start = Clock::now();
    hullkit::RouteReport report = check();
    const double first = seconds_since(start);
    if (!report.ok()) die(report.error);
    const std::string canonical = canonical_report(report);
    hullkit::RouteReport warm_report;
    const double warm = timed<hullkit::RouteReport>(runs, check, &warm_report).median;
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

/// The --first-call mode: one check, the first in this process, on one thread.
int run_first_call(hullkit::Scene scene, const Route& route, const std::string& route_name, bool clearance) {
    const Clock::time_point build_start = Clock::now();
    const hullkit::RouteChecker checker(std::move(scene));
    const double build = seconds_since(build_start);
    if (!checker.error().empty()) die(checker.error());
    hullkit::RouteOptions options;
    options.clearance = clearance;
    options.threads = 1;
    const Clock::time_point start = Clock::now();
    const hullkit::RouteReport report = checker.check(route.xyz.data(), route.rotations_or_null(), route.waypoints(), options);
    const double first = seconds_since(start);
    if (!report.ok()) die(report.error);
    std::size_t hit = 0;
    for (const hullkit::LegReport& leg : report.legs) hit += leg.status != hullkit::LegStatus::Clear;
    nlohmann::json out = line("hullkit-first", route_name, route.legs());
    out["clearance"] = clearance;
    out["turned"] = route.turned();
    out["legs_not_clear"] = hit;
    out["build_seconds"] = build;
    out["first_seconds"] = first;
    out["first_ms_per_leg"] = 1e3 * first / route.legs();
    std::printf("%s\n", out.dump().c_str());
    return 0;
}

/// hullkit's exact static test at the pose of fraction f of leg k.
hullkit::StaticContact static_at(const hullkit::RouteChecker& checker, const Route& route, std::size_t k, double f,
                                 bool want_distance) {
    double offset[3], rotation[4];
    leg_pose_at(route, k, f, offset, rotation);
    return route.turned() ? checker.static_contact(offset, rotation, want_distance) : checker.static_contact(offset, want_distance);
}

/// The first of `poses` evenly spaced poses of leg k at which hullkit's static test finds contact, or -1.
double static_first(const hullkit::RouteChecker& checker, const Route& route, std::size_t k, int poses) {
    for (int i = 0; i < poses; ++i) {
        const double f = double(i) / (poses - 1);
        if (static_at(checker, route, k, f, false).contact) return f;
    }
    return -1.0;
}

nlohmann::json fraction_or_null(double f) { return f < 0 ? nlohmann::json(nullptr) : nlohmann::json(f); }

}  // namespace

int main(int argc, char** argv) {
    std::string scene_path, dump_path, ccd_mode, only = "hullkit,fcl-100,fcl-ccd,fcl-reference,checks";
    std::vector<std::string> route_paths;
    int runs = 5, reference_poses = 2000, threads = -1;
    long threads_legs = 10000;
    bool clearance = true, first_call = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--no-clearance") {
            clearance = false;
            continue;
        }
        if (arg == "--first-call") {
            first_call = true;
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
        else if (arg == "--ccd") ccd_mode = argv[++i];
        else if (arg == "--only") only = argv[++i];
        else die("unknown option " + arg);
    }
    if (scene_path.empty() || route_paths.empty()) die("usage: hullkit_route_bench --scene SCENE.json --route ROUTE.json [--runs N]");
    if (!ccd_mode.empty() && ccd_mode != "naive" && ccd_mode != "ca") die("--ccd takes naive or ca");

    hullkit::SceneResult scene = hullkit::read_scene_file(scene_path);
    if (!scene.ok()) die(scene.error);
    if (threads >= 0) {
        Route waypoints;
        std::string names;
        for (const std::string& path : route_paths) {
            const Route more = read_route(path);
            if (!names.empty() && more.turned() != waypoints.turned()) die("--threads: mix of routes with and without rotations");
            waypoints.xyz.insert(waypoints.xyz.end(), more.xyz.begin(), more.xyz.end());
            waypoints.rotations.insert(waypoints.rotations.end(), more.rotations.begin(), more.rotations.end());
            names += (names.empty() ? "" : "+") + route_name_of(path);
        }
        return run_threads(scene.scene, waypoints, names, static_cast<std::size_t>(threads_legs),
                           static_cast<unsigned>(threads), clearance, runs, dump_path);
    }
    if (route_paths.size() != 1 || !dump_path.empty()) die("one --route; --dump and more routes go with --threads");
    const Route route = read_route(route_paths[0]);
    const std::size_t legs = route.legs();
    const std::string route_name = route_name_of(route_paths[0]);
    if (first_call) return run_first_call(scene.scene, route, route_name, clearance);
    if (!clearance) die("--no-clearance goes with --threads or --first-call");
    const bool use_ca = ccd_mode.empty() ? route.turned() : ccd_mode == "ca";
    if (route.turned() && !use_ca) die("--ccd naive moves by translation only: not for a route that turns");
    const double* pivot = scene.scene.pivot;
    auto wanted = [&](const std::string& method) { return ("," + only + ",").find("," + method + ",") != std::string::npos; };
    std::size_t obstacle_triangles = 0, traverse_vertices = 0;
    for (const auto& mesh : scene.scene.obstacles) obstacle_triangles += mesh.triangles.size() / 3;
    for (const auto& mesh : scene.scene.parts) traverse_vertices += mesh.xyz.size() / 3;

    // ---- hullkit: build, then verdicts with and without clearance, on one thread.
    std::unique_ptr<hullkit::RouteChecker> checker;
    hullkit::RouteReport fast, full;
    {
        std::vector<double> builds;
        for (int r = 0; r < runs; ++r) {
            hullkit::Scene copy = scene.scene;  // the copy is not timed
            const Clock::time_point start = Clock::now();
            checker = std::make_unique<hullkit::RouteChecker>(std::move(copy));
            builds.push_back(seconds_since(start));
        }
        if (!checker->error().empty()) die(checker->error());
        hullkit::RouteOptions verdict_only, with_clearance;
        verdict_only.clearance = false;
        verdict_only.threads = 1;
        with_clearance.threads = 1;
        const Timing fast_s = timed<hullkit::RouteReport>(
            runs, [&] { return checker->check(route.xyz.data(), route.rotations_or_null(), legs + 1, verdict_only); }, &fast);
        const Timing full_s = timed<hullkit::RouteReport>(
            runs, [&] { return checker->check(route.xyz.data(), route.rotations_or_null(), legs + 1, with_clearance); }, &full);
        if (!fast.ok()) die(fast.error);
        if (!full.ok()) die(full.error);
        nlohmann::json out = line("hullkit", route_name, legs);
        std::vector<int> hits, hits_full, grazing;
        std::vector<double> first, first_hi;
        for (std::size_t k = 0; k < legs; ++k) {
            const hullkit::LegReport& leg = fast.legs[k];
            hits.push_back(leg.status != hullkit::LegStatus::Clear);
            first.push_back(leg.status == hullkit::LegStatus::Clear ? -1.0 : leg.fraction_lo);
            first_hi.push_back(leg.status == hullkit::LegStatus::Clear ? -1.0 : leg.fraction_hi);
            if (leg.grazing) grazing.push_back(static_cast<int>(k));
        }
        std::vector<double> clearances;
        for (const auto& leg : full.legs) {
            hits_full.push_back(leg.status != hullkit::LegStatus::Clear);
            clearances.push_back(leg.status == hullkit::LegStatus::Clear && std::isfinite(leg.clearance) ? leg.clearance : -1.0);
        }
        out["turned"] = route.turned();
        out["threads"] = 1;
        out["obstacle_triangles"] = obstacle_triangles;
        out["traverse_vertices"] = traverse_vertices;
        out["build_seconds"] = median(builds);
        out["ms_per_leg"] = 1e3 * fast_s.median / legs;
        out["first_ms_per_leg"] = 1e3 * fast_s.first / legs;  // the first check in this process
        out["ms_per_leg_clearance"] = 1e3 * full_s.median / legs;
        out["first_ms_per_leg_clearance"] = 1e3 * full_s.first / legs;  // the first with clearance, after those
        std::vector<double> runs_ms, runs_ms_clearance;
        for (double x : fast_s.all) runs_ms.push_back(1e3 * x);
        for (double x : full_s.all) runs_ms_clearance.push_back(1e3 * x);
        out["runs_ms"] = runs_ms;  // every run, in order (the whole route)
        out["runs_ms_clearance"] = runs_ms_clearance;
        out["hits"] = hits;
        out["hits_with_clearance"] = hits_full;
        out["first_fraction"] = first;
        out["first_fraction_hi"] = first_hi;
        out["grazing_legs"] = grazing;
        out["clearances"] = clearances;
        out["min_clearance"] = std::isfinite(full.min_clearance) ? nlohmann::json(full.min_clearance) : nlohmann::json(nullptr);
        std::printf("%s\n", out.dump().c_str());
        std::fflush(stdout);
    }

    // ---- FCL: build the two models, then the three methods.
    if (!wanted("fcl-100") && !wanted("fcl-ccd") && !wanted("fcl-reference")) return 0;
    std::shared_ptr<Model> traverse, obstacles;
    std::vector<double> builds;
    for (int r = 0; r < std::min(runs, 3); ++r) {
        const Clock::time_point start = Clock::now();
        obstacles = fcl_model(scene.scene.obstacles);
        traverse = fcl_model(scene.scene.parts);
        builds.push_back(seconds_since(start));
    }
    const double fcl_build = median(builds);

    auto print = [&](const char* impl, const Timing& t, const Verdicts& v, nlohmann::json out) {
        out.update(line(impl, route_name, legs));
        out["ms_per_leg"] = 1e3 * t.median / legs;
        out["first_ms_per_leg"] = 1e3 * t.first / legs;
        std::vector<double> runs_ms;
        for (double x : t.all) runs_ms.push_back(1e3 * x);
        out["runs_ms"] = runs_ms;
        out["hits"] = v.hits;
        out["first_fraction"] = v.first;
        std::printf("%s\n", out.dump().c_str());
        std::fflush(stdout);
    };
    Verdicts v;
    Timing t;
    if (wanted("fcl-100")) {
        t = timed<Verdicts>(std::min(runs, 3), [&] { return fcl_poses(*traverse, *obstacles, route, pivot, 100); }, &v);
        print("fcl-100", t, v, {{"build_seconds", fcl_build}, {"poses", 100}, {"runs", std::min(runs, 3)}});
    }
    if (wanted("fcl-ccd")) {
        // Conservative advancement takes seconds per leg here: one run (its first is its median).
        const int ccd_runs = use_ca ? 1 : std::min(runs, 3);
        t = timed<Verdicts>(ccd_runs, [&] { return fcl_ccd(*traverse, *obstacles, route, pivot, use_ca); }, &v);
        print("fcl-ccd", t, v,
              {{"ccd", use_ca ? "interp motion, conservative advancement" : "default request: CCDC_NAIVE, 10 poses, translation"},
               {"runs", ccd_runs}});
    }
    if (!wanted("fcl-reference")) return 0;
    Verdicts reference;
    t = timed<Verdicts>(1, [&] { return fcl_poses(*traverse, *obstacles, route, pivot, reference_poses); }, &reference);
    print("fcl-reference", t, reference, {{"poses", reference_poses}});
    if (!wanted("checks")) return 0;

    // ---- Sanity checks of hullkit's reports (untimed), with its own exact static test.
    //   hi_not_in_contact   hit legs (not grazing) whose pose at fraction_hi is not in contact
    //   lo_after_reference  legs both hit where hullkit's lo is after the reference's first contact pose
    //   earlier_than_reference  legs both hit where lo precedes the reference's last clear pose (a
    //                       contact between its poses, or before a gap in the reference's contacts)
    //   clearance_mismatch  clear legs whose static distance at the reported fraction is not the
    //                       reported clearance (relative 1e-6 turning, 1e-9 straight)
    //   closer_than_clearance  clear legs where one of 21 evenly spaced poses is closer than the clearance
    //   disagreements       legs where hullkit and the reference differ, with hullkit's static test
    //                       at the reference's poses (its first contact fraction, or null)
    {
        const double tolerance = route.turned() ? 1e-6 : 1e-9;
        nlohmann::json hi_bad = nlohmann::json::array(), lo_bad = nlohmann::json::array(), earlier = nlohmann::json::array(),
                       mismatch = nlohmann::json::array(), closer = nlohmann::json::array(), disagree = nlohmann::json::array();
        double worst_clearance = 0.0;
        const Clock::time_point start = Clock::now();
        for (std::size_t k = 0; k < legs; ++k) {
            const hullkit::LegReport& leg = fast.legs[k];
            const bool hk_hit = leg.status != hullkit::LegStatus::Clear;
            if (leg.status == hullkit::LegStatus::Hit && !leg.grazing && !static_at(*checker, route, k, leg.fraction_hi, false).contact) {
                hi_bad.push_back({{"leg", k}, {"lo", leg.fraction_lo}, {"hi", leg.fraction_hi}});
            }
            if (hk_hit && reference.hits[k]) {
                if (leg.fraction_lo > reference.first[k]) {
                    lo_bad.push_back({{"leg", k}, {"lo", leg.fraction_lo}, {"reference", reference.first[k]}});
                }
                const double last_clear = reference.first[k] - 1.0 / (reference_poses - 1);
                if (leg.fraction_hi < last_clear) earlier.push_back({{"leg", k}, {"lo", leg.fraction_lo}, {"reference", reference.first[k]}});
            }
            if (hk_hit != (reference.hits[k] != 0)) {
                disagree.push_back({{"leg", k}, {"hullkit", hk_hit}, {"hullkit_lo", hk_hit ? nlohmann::json(leg.fraction_lo) : nlohmann::json(nullptr)},
                                    {"reference", reference.hits[k]}, {"reference_first", fraction_or_null(reference.first[k])},
                                    {"hullkit_static_first", fraction_or_null(static_first(*checker, route, k, reference_poses))}});
            }
            const hullkit::LegReport& clear_leg = full.legs[k];
            if (clear_leg.status == hullkit::LegStatus::Clear && std::isfinite(clear_leg.clearance)) {
                const double d = static_at(*checker, route, k, clear_leg.fraction_lo, true).distance;
                const double rel = std::abs(d - clear_leg.clearance) / std::max(clear_leg.clearance, 1e-300);
                worst_clearance = std::max(worst_clearance, rel);
                if (!(rel <= tolerance)) mismatch.push_back({{"leg", k}, {"clearance", clear_leg.clearance}, {"static_distance", d}});
                for (int i = 0; i <= 20; ++i) {
                    const double di = static_at(*checker, route, k, i / 20.0, true).distance;
                    if (di < clear_leg.clearance * (1 - tolerance)) {
                        closer.push_back({{"leg", k}, {"fraction", i / 20.0}, {"distance", di}, {"clearance", clear_leg.clearance}});
                        break;
                    }
                }
            }
        }
        nlohmann::json out = line("hullkit-checks", route_name, legs);
        out["hi_not_in_contact"] = hi_bad;
        out["lo_after_reference"] = lo_bad;
        out["earlier_than_reference"] = earlier;
        out["clearance_mismatch"] = mismatch;
        out["worst_clearance_relative"] = worst_clearance;
        out["closer_than_clearance"] = closer;
        out["disagreements"] = disagree;
        out["seconds"] = seconds_since(start);
        std::printf("%s\n", out.dump().c_str());
    }
    return 0;
}
