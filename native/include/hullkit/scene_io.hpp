// hullkit: the route-checking scene and report as JSON (the format `hullkit route` and the JS
// layer read and write).
//
// Scene:
//   {"traverse": {"parts": [PART, ...], "pivot": [x,y,z]}, "route": [WAYPOINT, ...],
//    "obstacles": [PART, ...], "margin": m}
// where PART is {"name": "...", and exactly one of
//   "box": {"min": [x,y,z], "max": [x,y,z]}                       an axis-aligned box, 12 triangles
//   "vertices": [[x,y,z], ...], "triangles": [[i,j,k], ...]      an inline triangle mesh
//   "mesh": "file.stl"                                            OBJ, OFF, PLY, STL or glTF, see mesh_read.hpp
// }. "margin" is optional (default 0), "pivot" too (default [0, 0, 0], the traverse's own origin).
// Parts without a name are called "part K", obstacles "obstacle K" (K their index).
// WAYPOINT is [x, y, z] (a translation of the traverse) or {"position": [x, y, z], "rotation": R}
// with "rotation" optional (the identity) and R exactly one of
//   {"quaternion": [w, x, y, z]}          a unit quaternion (length 1 within 1e-9; normalized)
//   {"axis": [x, y, z], "degrees": a}      a turn by a degrees about the axis (right-handed)
//   {"yaw_pitch_roll_degrees": [y, p, r]}  yaw about z, then pitch about the turned y, then roll
//                                          about the turned x (intrinsic z-y'-x''): Rz Ry Rx
// The traverse turns about its pivot: a vertex v goes to pivot + R (v - pivot) + position; see
// route.hpp for the motion between waypoints. A rotation key anywhere else ("rotation",
// "orientation", "transform", ...) is rejected with a message saying where rotations go.
// Every problem gives one line naming the JSON path: "scene.json: obstacles[2].box.min: expected
// 3 numbers"; unknown keys are errors too (a misspelt "margn" must not silently mean margin 0).
#pragma once

#include "hullkit/route.hpp"

#include <functional>
#include <string>
#include <vector>

namespace hullkit {

/// Fetches the bytes of the mesh file a scene names (`path` exactly as written in the scene).
/// Returns false and sets *error to a one-line reason (e.g. "vessel.obj: cannot open: No such file").
using MeshLoader = std::function<bool(const std::string& path, std::string* bytes, std::string* error)>;

/// A loader reading `path` relative to `directory` ("" or "." for the current directory; absolute
/// paths are used as they are).
MeshLoader file_mesh_loader(const std::string& directory);

struct SceneReadOptions {
    /// A scene without "route" is an error; off for a RouteChecker whose routes come later.
    bool require_route = true;
};

struct SceneResult {
    Scene scene;
    std::string error;  ///< empty on success: "SOURCE: JSON.PATH: what is wrong"
    /// What the mesh readers skipped: "SOURCE: JSON.PATH: FILE: skipped 1 unknown OBJ record ...".
    std::vector<std::string> warnings;

    bool ok() const { return error.empty(); }
};

/// Parses a scene from JSON text. `source` starts every error message (the scene's file name);
/// `load_mesh` fetches "mesh" files (without one, a "mesh" entry is an error).
SceneResult parse_scene(const std::string& json_text, const std::string& source, const MeshLoader& load_mesh,
                        const SceneReadOptions& options = {});

/// A route on its own: the JSON array of a scene's "route" (same rules and messages).
struct RouteResult {
    std::vector<double> route;      ///< flat x y z
    std::vector<double> rotations;  ///< empty, or w x y z per waypoint
    std::string error;

    bool ok() const { return error.empty(); }
};
RouteResult parse_route(const std::string& json_text, const std::string& source);

/// Reads a scene file; mesh paths are relative to the scene file's directory. "-" reads standard
/// input (mesh paths then relative to the current directory).
SceneResult read_scene_file(const std::string& path, const SceneReadOptions& options = {});

/// The report as JSON text (one leg per line):
///   {"clear": bool, "min_clearance": d|null, "legs": [LEG, ...], "build_seconds": b, "seconds": s}
/// with LEG one of
///   {"status":"hit","obstacle":NAME,"triangle":i,"part":NAME,"fraction":[lo,hi],"position":[x,y,z]}
///   (plus "rotation":[w,x,y,z], the orientation at lo, when the route checked has rotations, and
///   "grazing":true when the hit is a graze the bounds could not resolve; see LegReport)
///   {"status":"clear","clearance":d|null,"obstacle":NAME|null,"fraction":f|null}
///   {"status":"start-overlap","obstacle":NAME,"part":NAME,"triangle":i}
/// plus "sampled": {"hit": bool, "fraction": f|null} on every leg when options.samples > 0.
/// Names come from `scene`. JSON has no infinity: a clearance that was not computed, or is
/// infinite (no obstacles), is null. Numbers are written so that they read back exactly.
std::string write_report_json(const Scene& scene, const RouteReport& report, const RouteOptions& options);

}  // namespace hullkit
