// embind registrations for route checking: the friendly API lives in route.js.
//
// The scene crosses the boundary as JSON text (the same format as `hullkit route`), mesh files as
// bytes registered by name beforehand, routes as a malloc'ed block of doubles, and the report
// comes back as the same JSON text the CLI writes.
#include <emscripten/bind.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "hullkit/route.hpp"
#include "hullkit/scene_io.hpp"

namespace {

/// A RouteChecker plus what loading its scene needs; one per JS RouteChecker.
class RouteCheckerHandle {
public:
    /// Registers mesh bytes under `name` (a scene's "mesh" value); a JS Uint8Array arrives as bytes.
    void add_file(const std::string& name, const std::string& bytes) { files_[name] = bytes; }

    /// Parses the scene and builds the checker (hulls, BVH); returns "" or the error.
    std::string load(const std::string& json, const std::string& source, bool require_route) {
        const std::map<std::string, std::string>& files = files_;
        hullkit::MeshLoader loader = [&files](const std::string& path, std::string* bytes, std::string* error) {
            auto it = files.find(path);
            if (it == files.end()) {
                *error = "\"" + path + "\" is not in options.files";
                return false;
            }
            *bytes = it->second;
            return true;
        };
        hullkit::SceneReadOptions options;
        options.require_route = require_route;
        hullkit::SceneResult scene = hullkit::parse_scene(json, source, loader, options);
        files_.clear();  // the bytes are not needed any more
        if (!scene.ok()) return scene.error;
        checker_ = std::make_unique<hullkit::RouteChecker>(std::move(scene.scene));
        if (!checker_->error().empty()) {
            std::string error = source + ": " + checker_->error();
            checker_.reset();
            return error;
        }
        return "";
    }

    /// Checks `count` waypoints at `xyz` (a malloc'ed block of 3 * count doubles), or the scene's
    /// own route when count is 0. Returns the report JSON, or "" with error() set.
    std::string check(std::uintptr_t xyz, std::uint32_t count, bool clearance, std::uint32_t samples) {
        error_.clear();
        if (!checker_) {
            error_ = "no scene loaded";
            return "";
        }
        const hullkit::RouteOptions options = options_of(clearance, samples);
        return report_json(count == 0 ? checker_->check(options)
                                      : checker_->check(reinterpret_cast<const double*>(xyz), count, options),
                           clearance, samples);
    }

    /// Checks a route given as the JSON array of a scene's "route" (waypoints with rotations);
    /// `source` starts its error messages. Returns the report JSON, or "" with error() set.
    std::string check_json(const std::string& route_json, const std::string& source, bool clearance,
                           std::uint32_t samples) {
        error_.clear();
        if (!checker_) {
            error_ = "no scene loaded";
            return "";
        }
        const hullkit::RouteResult route = hullkit::parse_route(route_json, source);
        if (!route.ok()) {
            error_ = route.error;
            return "";
        }
        return report_json(checker_->check(route.route.data(), route.rotations.empty() ? nullptr : route.rotations.data(),
                                           route.route.size() / 3, options_of(clearance, samples)),
                           clearance, samples);
    }

    std::string error() const { return error_; }
    double build_seconds() const { return checker_ ? checker_->build_seconds() : 0.0; }
    /// Waypoints of the scene's own route (0 when it has none).
    std::uint32_t route_waypoints() const {
        return checker_ ? static_cast<std::uint32_t>(checker_->scene().route.size() / 3) : 0;
    }

private:
    static hullkit::RouteOptions options_of(bool clearance, std::uint32_t samples) {
        hullkit::RouteOptions options;
        options.clearance = clearance;
        options.samples = samples;
        return options;
    }

    std::string report_json(const hullkit::RouteReport& report, bool clearance, std::uint32_t samples) {
        if (!report.ok()) {
            error_ = report.error;
            return "";
        }
        return hullkit::write_report_json(checker_->scene(), report, options_of(clearance, samples));
    }

    std::map<std::string, std::string> files_;
    std::unique_ptr<hullkit::RouteChecker> checker_;
    std::string error_;
};

}  // namespace

EMSCRIPTEN_BINDINGS(hullkit_route) {
    emscripten::class_<RouteCheckerHandle>("RouteCheckerHandle")
        .constructor<>()
        .function("addFile", &RouteCheckerHandle::add_file)
        .function("load", &RouteCheckerHandle::load)
        .function("check", &RouteCheckerHandle::check)
        .function("checkJson", &RouteCheckerHandle::check_json)
        .function("error", &RouteCheckerHandle::error)
        .function("buildSeconds", &RouteCheckerHandle::build_seconds)
        .function("routeWaypoints", &RouteCheckerHandle::route_waypoints);
}
