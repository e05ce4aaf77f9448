// The route-checking scene and report as JSON, with nlohmann-json.
//
// No exceptions: the wasm build does not catch them, so the parser runs through a SAX handler
// with exceptions off, and every value's type is checked before it is read.
#include "hullkit/scene_io.hpp"

#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"

#include <nlohmann/json.hpp>

#include "scene_arrays.hpp"

#include "motion.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace hullkit {

namespace {

using nlohmann::json;

/// The DOM parser with exceptions off that remembers why parsing failed.
struct LocatingParser : nlohmann::detail::json_sax_dom_parser<json> {
    explicit LocatingParser(json& root) : json_sax_dom_parser(root, false) {}
    bool parse_error(std::size_t /*position*/, const std::string& /*last_token*/, const nlohmann::detail::exception& ex) {
        message = ex.what();
        return false;
    }
    std::string message;
};

/// nlohmann's "[json.exception.parse_error.101] parse error at line 3, column 5: ..." without the tag.
std::string readable_parse_error(std::string message) {
    std::size_t tag_end = message.find("] ");
    if (message.rfind("[json.exception.", 0) == 0 && tag_end != std::string::npos) message.erase(0, tag_end + 2);
    return message;
}

/// `text` safe to print on a terminal: well-formed UTF-8 (names may be in any language) is kept,
/// every control character (C0, DEL, C1) and every byte that is not part of well-formed UTF-8
/// becomes '?'. Messages quote keys, file names and nlohmann's "last read" bytes from the input.
std::string terminal_safe(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c < 0x80) {
            out += (c < 0x20 || c == 0x7f) ? '?' : static_cast<char>(c);
            ++i;
            continue;
        }
        const std::size_t length = c >= 0xf0 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 ? 2 : 0;
        bool ok = length != 0 && c <= 0xf4 && i + length <= text.size();
        std::uint32_t code = c & (0x7f >> length);
        for (std::size_t k = 1; ok && k < length; ++k) {
            const unsigned char d = static_cast<unsigned char>(text[i + k]);
            ok = (d & 0xc0) == 0x80;
            code = code << 6 | (d & 0x3f);
        }
        ok = ok && !(length == 3 && code < 0x800) && !(length == 4 && (code < 0x10000 || code > 0x10ffff)) &&
             !(code >= 0xd800 && code <= 0xdfff);
        if (!ok) {
            out += '?';  // one byte at a time: what follows may be well-formed again
            ++i;
        } else {
            const bool control = code >= 0x80 && code < 0xa0;  // C1, e.g. U+009B (CSI)
            if (control) {
                out += '?';
            } else {
                out.append(text, i, length);
            }
            i += length;
        }
    }
    return out;
}

/// Keys that would describe a rotation; outside a waypoint they get a message that says where
/// rotations go.
bool is_rotation_key(const std::string& key) {
    static const char* const kKeys[] = {"rotation", "rotations", "orientation", "orientations", "transform",
                                        "transforms", "quaternion", "matrix", "pose", "poses", "euler", "angle",
                                        "angles", "axis_angle", "rotate"};
    for (const char* name : kKeys) {
        if (key == name) return true;
    }
    return false;
}

const char* const kRotationPlace =
    "a rotation belongs to a waypoint: {\"position\": [x, y, z], \"rotation\": {\"quaternion\": [w, x, y, z]}} "
    "(or \"axis\" with \"degrees\", or \"yaw_pitch_roll_degrees\")";

const char* type_name(const json& value) {
    switch (value.type()) {
        case json::value_t::null: return "null";
        case json::value_t::boolean: return "a boolean";
        case json::value_t::string: return "a string";
        case json::value_t::array:
        case json::value_t::binary: return "an array";  // an inline mesh array read ahead (scene_arrays.hpp)
        case json::value_t::object: return "an object";
        case json::value_t::number_integer:
        case json::value_t::number_unsigned:
        case json::value_t::number_float: return "a number";
        default: return "an unknown value";
    }
}

/// Walks the JSON tree; the first problem found is kept and stops the walk.
class SceneParser {
public:
    SceneParser(const std::string& source, const MeshLoader& load_mesh, route_detail::PackedMeshArrays* packed = nullptr)
        : source_(source), load_mesh_(load_mesh), packed_(packed) {}

    bool fail(const std::string& path, const std::string& what) {
        if (error_.empty()) error_ = source_ + ": " + (path.empty() ? "" : path + ": ") + what;
        return false;
    }
    const std::string& error() const { return error_; }
    std::vector<std::string>& warnings() { return warnings_; }

    /// An object whose keys are all in `known` (a rotation key gets its own message).
    bool check_object(const json& value, const std::string& path, std::initializer_list<const char*> known) {
        if (!value.is_object()) return fail(path, std::string("expected an object, got ") + type_name(value));
        for (auto it = value.begin(); it != value.end(); ++it) {
            const std::string& key = it.key();
            bool ok = false;
            for (const char* name : known) ok = ok || key == name;
            if (ok) continue;
            const std::string where = path.empty() ? key : path + "." + key;
            if (is_rotation_key(key)) return fail(where, kRotationPlace);
            std::string list;
            for (const char* name : known) list += std::string(list.empty() ? "" : ", ") + name;
            return fail(where, "unknown key (known here: " + list + ")");
        }
        return true;
    }

    bool finite_number(const json& value, const std::string& path, double* out) {
        if (!value.is_number()) return fail(path, std::string("expected a number, got ") + type_name(value));
        *out = value.get<double>();
        if (!std::isfinite(*out)) return fail(path, "expected a finite number");
        return true;
    }

    /// [x, y, z], appended to *out; path() names the value in a message, and is called only
    /// for one (a mesh's 1e5 vertices would otherwise build 4e5 strings).
    template <class Path>
    bool vec3_at(const json& value, const Path& path, std::vector<double>* out, const char* hint = "") {
        if (!value.is_array() || value.size() != 3) {
            return fail(path(), std::string("expected 3 numbers [x, y, z]") + hint + ", got " +
                                    (value.is_array() ? std::to_string(value.size()) + " values" : type_name(value)));
        }
        for (std::size_t axis = 0; axis < 3; ++axis) {
            if (!value[axis].is_number()) {
                return fail(path(), std::string("expected 3 numbers [x, y, z]") + hint + ", entry " + std::to_string(axis) +
                                        " is " + type_name(value[axis]));
            }
            const double x = value[axis].get<double>();
            if (!std::isfinite(x)) return fail(path() + "[" + std::to_string(axis) + "]", "expected a finite number");
            out->push_back(x);
        }
        return true;
    }
    bool vec3(const json& value, const std::string& path, std::vector<double>* out, const char* hint = "") {
        return vec3_at(value, [&] { return path; }, out, hint);
    }

    /// n finite numbers, into out[0 .. n).
    bool numbers(const json& value, const std::string& path, std::size_t n, const char* shape, double* out) {
        if (!value.is_array() || value.size() != n) {
            return fail(path, std::string("expected ") + shape + ", got " +
                                  (value.is_array() ? std::to_string(value.size()) + " values" : type_name(value)));
        }
        for (std::size_t k = 0; k < n; ++k) {
            if (!finite_number(value[k], path + "[" + std::to_string(k) + "]", &out[k])) return false;
        }
        return true;
    }

    /// A waypoint's "rotation", as a unit quaternion w x y z.
    bool rotation(const json& value, const std::string& path, double q[4]) {
        if (!value.is_object()) {
            return fail(path, std::string("expected {\"quaternion\": [w, x, y, z]}, {\"axis\": [x, y, z], \"degrees\": a} "
                                          "or {\"yaw_pitch_roll_degrees\": [yaw, pitch, roll]}, got ") + type_name(value));
        }
        if (!check_object(value, path, {"quaternion", "axis", "degrees", "yaw_pitch_roll_degrees"})) return false;
        const int kinds = int(value.contains("quaternion")) + int(value.contains("axis") || value.contains("degrees")) +
                          int(value.contains("yaw_pitch_roll_degrees"));
        if (kinds != 1) {
            return fail(path, std::string(kinds == 0 ? "needs" : "give only") +
                                  " one of \"quaternion\": [w, x, y, z], \"axis\": [x, y, z] with \"degrees\": a, "
                                  "and \"yaw_pitch_roll_degrees\": [yaw, pitch, roll]");
        }
        if (value.contains("quaternion")) {
            const std::string where = path + ".quaternion";
            if (!numbers(value["quaternion"], where, 4, "4 numbers [w, x, y, z]", q)) return false;
            const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            if (!(std::fabs(length - 1.0) <= 1e-9)) {
                return fail(where, "not a unit quaternion (its length is " + format_json_number(length) +
                                       "; allowed: 1 within 1e-9)");
            }
            for (int k = 0; k < 4; ++k) q[k] /= length;
            return true;
        }
        if (value.contains("axis")) {
            if (!value.contains("degrees")) return fail(path, "\"axis\" without \"degrees\"");
            double axis[3], degrees;
            if (!numbers(value["axis"], path + ".axis", 3, "3 numbers [x, y, z]", axis)) return false;
            if (!finite_number(value["degrees"], path + ".degrees", &degrees)) return false;
            const double length = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
            if (!(length > 0.0)) return fail(path + ".axis", "a zero axis has no direction");
            if (!std::isfinite(length)) return fail(path + ".axis", "too long (its length overflows)");
            double sine, cosine;
            route_detail::sin_cos_degrees(0.5 * degrees, &sine, &cosine);
            q[0] = cosine;
            for (int k = 0; k < 3; ++k) q[k + 1] = sine / length * axis[k];
            return true;
        }
        if (value.contains("degrees")) return fail(path, "\"degrees\" without \"axis\"");
        // Yaw about z, then pitch about the turned y, then roll about the turned x (intrinsic
        // z-y'-x''): q = q_z(yaw) q_y(pitch) q_x(roll).
        double angles[3];
        if (!numbers(value["yaw_pitch_roll_degrees"], path + ".yaw_pitch_roll_degrees", 3, "3 numbers [yaw, pitch, roll]",
                     angles)) {
            return false;
        }
        double sy, cy, sp, cp, sr, cr;
        route_detail::sin_cos_degrees(0.5 * angles[0], &sy, &cy);
        route_detail::sin_cos_degrees(0.5 * angles[1], &sp, &cp);
        route_detail::sin_cos_degrees(0.5 * angles[2], &sr, &cr);
        q[0] = cy * cp * cr + sy * sp * sr;
        q[1] = cy * cp * sr - sy * sp * cr;
        q[2] = cy * sp * cr + sy * cp * sr;
        q[3] = sy * cp * cr - cy * sp * sr;
        return true;
    }

    /// A waypoint: [x, y, z] or {"position": [x, y, z], "rotation": R}; *turned tells whether it
    /// had a rotation (else q is the identity).
    bool waypoint(const json& value, const std::string& path, std::vector<double>* xyz, double q[4], bool* turned) {
        q[0] = 1.0, q[1] = q[2] = q[3] = 0.0;
        *turned = false;
        if (!value.is_object()) return vec3(value, path, xyz, " or {\"position\": [x, y, z], \"rotation\": ...}");
        if (!check_object(value, path, {"position", "rotation"})) return false;
        if (!value.contains("position")) return fail(path, "missing \"position\"");
        if (!vec3(value["position"], path + ".position", xyz)) return false;
        if (!value.contains("rotation")) return true;
        *turned = true;
        return rotation(value["rotation"], path + ".rotation", q);
    }

    /// "route": at least 2 waypoints; *rotations stays empty when none has a rotation.
    bool waypoints(const json& route, std::vector<double>* xyz, std::vector<double>* rotations) {
        if (!route.is_array()) return fail("route", std::string("expected an array of waypoints [x, y, z], got ") + type_name(route));
        bool any_turned = false;
        std::vector<double> turns;
        for (std::size_t k = 0; k < route.size(); ++k) {
            double q[4];
            bool turned;
            if (!waypoint(route[k], "route[" + std::to_string(k) + "]", xyz, q, &turned)) return false;
            any_turned = any_turned || turned;
            turns.insert(turns.end(), q, q + 4);
        }
        if (any_turned) *rotations = std::move(turns);
        if (route.size() < 2) return fail("route", "needs at least 2 waypoints, got " + std::to_string(route.size()));
        return true;
    }

    bool box(const json& value, const std::string& path, TriangleMesh* mesh) {
        if (!check_object(value, path, {"min", "max"})) return false;
        if (!value.contains("min")) return fail(path, "missing \"min\"");
        if (!value.contains("max")) return fail(path, "missing \"max\"");
        std::vector<double> lo, hi;
        if (!vec3(value["min"], path + ".min", &lo) || !vec3(value["max"], path + ".max", &hi)) return false;
        for (int axis = 0; axis < 3; ++axis) {
            if (lo[axis] > hi[axis]) {
                return fail(path, "min[" + std::to_string(axis) + "] is greater than max[" + std::to_string(axis) + "]");
            }
        }
        // Corner c has x from bit 0, y from bit 1, z from bit 2 (0: min, 1: max).
        for (int c = 0; c < 8; ++c) {
            for (int axis = 0; axis < 3; ++axis) mesh->xyz.push_back((c >> axis) & 1 ? hi[axis] : lo[axis]);
        }
        // Two triangles per face, counter-clockwise seen from outside.
        static const std::uint32_t kTriangles[36] = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                                                     2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
        mesh->triangles.assign(kTriangles, kTriangles + 36);
        return true;
    }

    /// The array read ahead for a "vertices" or "triangles" value (a binary node in the tree
    /// stands for it: JSON text cannot make one), or null for a value in the tree.
    template <class T>
    static std::vector<T>* packed(const json& value, std::vector<std::vector<T>>& arrays) {
        if (!value.is_binary()) return nullptr;
        const std::uint64_t slot = value.get_binary().subtype();
        return slot < arrays.size() ? &arrays[slot] : nullptr;
    }

    bool inline_mesh(const json& value, const std::string& path, TriangleMesh* mesh) {
        if (!value.contains("triangles")) return fail(path, "\"vertices\" without \"triangles\"");
        const json& vertices = value["vertices"];
        const json& triangles = value["triangles"];
        std::vector<double>* packed_xyz = packed_ ? packed(vertices, packed_->vertices) : nullptr;
        std::vector<std::uint32_t>* packed_indices = packed_ ? packed(triangles, packed_->triangles) : nullptr;
        if (!vertices.is_array() && !packed_xyz) return fail(path + ".vertices", std::string("expected an array of [x, y, z], got ") + type_name(vertices));
        if (!triangles.is_array() && !packed_indices) return fail(path + ".triangles", std::string("expected an array of [i, j, k], got ") + type_name(triangles));
        const std::uint64_t count = packed_xyz ? packed_xyz->size() / 3 : vertices.size();
        if (count > 0xffffffffULL) return fail(path + ".vertices", "too many vertices");
        if (packed_xyz) {
            mesh->xyz = std::move(*packed_xyz);  // every [x, y, z] finite, checked as it was read
        } else {
            mesh->xyz.reserve(3 * vertices.size());
            for (std::size_t i = 0; i < vertices.size(); ++i) {
                if (!vec3_at(vertices[i], [&] { return path + ".vertices[" + std::to_string(i) + "]"; }, &mesh->xyz)) return false;
            }
        }
        if (packed_indices) {  // non-empty, every index an integer below 2^32
            for (std::size_t i = 0; i < packed_indices->size(); ++i) {
                if ((*packed_indices)[i] >= count) {
                    return fail(path + ".triangles[" + std::to_string(i / 3) + "][" + std::to_string(i % 3) + "]",
                                "index " + std::to_string((*packed_indices)[i]) + " out of range (" + std::to_string(count) +
                                    " vertices)");
                }
            }
            mesh->triangles = std::move(*packed_indices);
            return true;
        }
        if (triangles.empty()) return fail(path + ".triangles", "no triangles");
        mesh->triangles.reserve(3 * triangles.size());
        for (std::size_t t = 0; t < triangles.size(); ++t) {
            // The names in messages are built only for one.
            const auto where = [&] { return path + ".triangles[" + std::to_string(t) + "]"; };
            const json& corners = triangles[t];
            if (!corners.is_array() || corners.size() != 3) return fail(where(), "expected 3 vertex indices [i, j, k]");
            for (std::size_t k = 0; k < 3; ++k) {
                const json& index = corners[k];
                const auto at = [&] { return where() + "[" + std::to_string(k) + "]"; };
                if (!index.is_number_integer() && !(index.is_number_float() && std::floor(index.get<double>()) == index.get<double>())) {
                    return fail(at(), std::string("expected a vertex index (an integer >= 0), got ") + type_name(index));
                }
                const double i = index.get<double>();
                if (i < 0 || i >= static_cast<double>(count)) {
                    return fail(at(), "index " + index.dump() +
                                          " out of range (" + std::to_string(count) + " vertices)");
                }
                mesh->triangles.push_back(static_cast<std::uint32_t>(i));
            }
        }
        return true;
    }

    bool mesh_file(const json& value, const std::string& path, TriangleMesh* mesh) {
        if (!value.is_string()) return fail(path, std::string("expected a file name, got ") + type_name(value));
        const std::string file = value.get<std::string>();
        if (file.empty()) return fail(path, "empty file name");
        if (!load_mesh_) return fail(path, "mesh files cannot be read here");
        std::string bytes, why;
        if (!load_mesh_(file, &bytes, &why)) return fail(path, why);
        // A glTF's buffer files are named relative to it, and fetched as the scene's meshes are.
        const std::size_t slash = file.find_last_of('/');
        const std::string directory = slash == std::string::npos ? "" : file.substr(0, slash + 1);
        const MeshLoader& load = load_mesh_;
        MeshResult result = read_mesh(bytes, file, [&load, directory](const std::string& uri, std::string* out, std::string* why) {
            return load(!uri.empty() && uri[0] == '/' ? uri : directory + uri, out, why);
        });
        if (!result.ok()) {
            // Bytes handed in by the JS layer are named after their field: no need to say it twice.
            return file == path ? fail("", result.error) : fail(path, result.error);
        }
        for (const std::string& warning : result.warnings) {
            warnings_.push_back(terminal_safe(source_ + ": " + (file == path ? "" : path + ": ") + file + ": " + warning));
        }
        mesh->xyz = std::move(result.xyz);
        mesh->triangles = std::move(result.triangles);
        return true;
    }

    /// A part or an obstacle.
    bool shape(const json& value, const std::string& path, const std::string& default_name, TriangleMesh* mesh) {
        if (!check_object(value, path, {"name", "box", "vertices", "triangles", "mesh"})) return false;
        mesh->name = default_name;
        if (value.contains("name")) {
            if (!value["name"].is_string()) return fail(path + ".name", std::string("expected a string, got ") + type_name(value["name"]));
            mesh->name = value["name"].get<std::string>();
        }
        const int kinds = int(value.contains("box")) + int(value.contains("vertices") || value.contains("triangles")) +
                          int(value.contains("mesh"));
        if (kinds == 0) return fail(path, "needs one of \"box\", \"vertices\" + \"triangles\" or \"mesh\"");
        if (kinds > 1) return fail(path, "give only one of \"box\", \"vertices\" + \"triangles\" and \"mesh\"");
        if (value.contains("box")) return box(value["box"], path + ".box", mesh);
        if (value.contains("mesh")) return mesh_file(value["mesh"], path + ".mesh", mesh);
        if (!value.contains("vertices")) return fail(path, "\"triangles\" without \"vertices\"");
        return inline_mesh(value, path, mesh);
    }

    bool shapes(const json& value, const std::string& path, const char* noun, std::vector<TriangleMesh>* out) {
        if (!value.is_array()) return fail(path, std::string("expected an array, got ") + type_name(value));
        out->resize(value.size());
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (!shape(value[i], path + "[" + std::to_string(i) + "]", std::string(noun) + " " + std::to_string(i),
                       &(*out)[i])) {
                return false;
            }
        }
        return true;
    }

    bool scene(const json& root, const SceneReadOptions& options, Scene* out) {
        if (!check_object(root, "", {"traverse", "route", "obstacles", "margin"})) return false;
        if (!root.contains("traverse")) return fail("", "missing \"traverse\"");
        const json& traverse = root["traverse"];
        if (!check_object(traverse, "traverse", {"parts", "pivot"})) return false;
        if (!traverse.contains("parts")) return fail("traverse", "missing \"parts\"");
        if (!shapes(traverse["parts"], "traverse.parts", "part", &out->parts)) return false;
        if (out->parts.empty()) return fail("traverse.parts", "no parts (the traverse needs at least one)");
        if (traverse.contains("pivot") && !numbers(traverse["pivot"], "traverse.pivot", 3, "3 numbers [x, y, z]", out->pivot)) {
            return false;
        }

        if (root.contains("route")) {
            const json& route = root["route"];
            if (!waypoints(route, &out->route, &out->rotations)) return false;
        } else if (options.require_route) {
            return fail("", "missing \"route\"");
        }

        if (!root.contains("obstacles")) return fail("", "missing \"obstacles\"");
        if (!shapes(root["obstacles"], "obstacles", "obstacle", &out->obstacles)) return false;

        if (root.contains("margin")) {
            if (!finite_number(root["margin"], "margin", &out->margin)) return false;
            if (out->margin < 0) return fail("margin", "must be >= 0");
        }
        return true;
    }

private:
    std::string source_;
    const MeshLoader& load_mesh_;
    route_detail::PackedMeshArrays* packed_;  ///< inline mesh arrays read ahead, or null
    std::string error_;
    std::vector<std::string> warnings_;
};

std::string directory_of(const std::string& path) {
    std::size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return "";
    return slash == 0 ? "/" : path.substr(0, slash);
}

}  // namespace

MeshLoader file_mesh_loader(const std::string& directory) {
    return [directory](const std::string& path, std::string* bytes, std::string* error) {
        std::string full = path;
        if (!path.empty() && path[0] != '/' && !directory.empty() && directory != ".") {
            full = directory + (directory.back() == '/' ? "" : "/") + path;
        }
        return read_file(full, bytes, error);
    };
}

namespace {

/// Parses JSON text into *root, or sets *error ("SOURCE: invalid JSON: ...").
bool parse_json(const std::string& json_text, const std::string& source, const char* expected, json* root,
                std::string* error) {
    if (json_text.find_first_not_of(" \t\r\n") == std::string::npos) {
        *error = source + ": empty file, expected " + expected;
        return false;
    }
    LocatingParser handler(*root);
    if (!json::sax_parse(json_text, &handler, json::input_format_t::json, true, false) || !handler.message.empty()) {
        *error = terminal_safe(source + ": invalid JSON: " +
                               (handler.message.empty() ? std::string("cannot parse") : readable_parse_error(handler.message)));
        return false;
    }
    return true;
}

}  // namespace

RouteResult parse_route(const std::string& json_text, const std::string& source) {
    RouteResult result;
    json root;
    if (!parse_json(json_text, source, "a JSON route", &root, &result.error)) return result;
    const MeshLoader no_meshes;
    SceneParser parser(source, no_meshes);
    if (!parser.waypoints(root, &result.route, &result.rotations)) {
        result = RouteResult{};
        result.error = terminal_safe(parser.error());
    }
    return result;
}

namespace {

SceneResult scene_from_tree(const json& root, const std::string& source, const MeshLoader& load_mesh,
                            const SceneReadOptions& options, route_detail::PackedMeshArrays* packed) {
    SceneResult result;
    SceneParser parser(source, load_mesh, packed);
    if (!parser.scene(root, options, &result.scene)) {
        result.scene = Scene{};
        result.error = terminal_safe(parser.error());
    } else {
        result.warnings = std::move(parser.warnings());
    }
    return result;
}

/// The tree of a text whose inline mesh arrays were taken out (pack_mesh_arrays): each "[]" left
/// for one becomes a binary node naming its array. False if the text does not parse (the whole
/// scene is then read the ordinary way, for the ordinary message) or its keys are not the ones
/// counted.
bool packed_tree(const std::string& packed_text, const route_detail::PackedMeshArrays& arrays, json* root) {
    std::size_t vertices_keys = 0, triangles_keys = 0;
    std::int64_t pending = -1, open = -1;  // the array taken out for the key just read, for its "[]"
    const auto mark = [&](int /*depth*/, json::parse_event_t event, json& parsed) {
        switch (event) {
            case json::parse_event_t::key: {
                const std::string& key = parsed.get_ref<const std::string&>();
                pending = -1;
                if (key == "vertices" && vertices_keys < arrays.vertices_keys.size()) {
                    pending = arrays.vertices_keys[vertices_keys];
                } else if (key == "triangles" && triangles_keys < arrays.triangles_keys.size()) {
                    pending = arrays.triangles_keys[triangles_keys];
                }
                vertices_keys += key == "vertices";
                triangles_keys += key == "triangles";
                break;
            }
            case json::parse_event_t::array_start:
                open = pending;
                pending = -1;
                break;
            case json::parse_event_t::array_end:
                if (open >= 0 && parsed.empty()) parsed = json::binary({}, static_cast<std::uint64_t>(open));
                open = -1;
                break;
            default:
                pending = open = -1;
        }
        return true;
    };
    *root = json::parse(packed_text, mark, /*allow_exceptions=*/false);
    return !root->is_discarded() && vertices_keys == arrays.vertices_keys.size() &&
           triangles_keys == arrays.triangles_keys.size();
}

}  // namespace

SceneResult parse_scene(const std::string& json_text, const std::string& source, const MeshLoader& load_mesh,
                        const SceneReadOptions& options) {
    route_detail::PackedMeshArrays arrays;
    std::string packed_text;
    if (route_detail::pack_mesh_arrays(json_text, &packed_text, &arrays)) {
        json root;
        if (packed_tree(packed_text, arrays, &root)) return scene_from_tree(root, source, load_mesh, options, &arrays);
    }
    return route_detail::parse_scene_tree_only(json_text, source, load_mesh, options);
}

SceneResult route_detail::parse_scene_tree_only(const std::string& json_text, const std::string& source,
                                                const MeshLoader& load_mesh, const SceneReadOptions& options) {
    SceneResult result;
    json root;
    if (!parse_json(json_text, source, "a JSON scene", &root, &result.error)) return result;
    return scene_from_tree(root, source, load_mesh, options, nullptr);
}

SceneResult read_scene_file(const std::string& path, const SceneReadOptions& options) {
    SceneResult result;
    std::string text;
    if (path == "-") {
        char buffer[1 << 16];
        std::size_t n;
        while ((n = std::fread(buffer, 1, sizeof buffer, stdin)) > 0) text.append(buffer, n);
        return parse_scene(text, "<stdin>", file_mesh_loader(""), options);
    }
    if (!read_file(path, &text, &result.error)) return result;
    return parse_scene(text, path, file_mesh_loader(directory_of(path)), options);
}

std::string write_report_json(const Scene& scene, const RouteReport& report, const RouteOptions& options) {
    using ordered = nlohmann::ordered_json;
    // JSON has no NaN or infinity: those become null.
    auto number = [](double value) { return std::isfinite(value) ? ordered(value) : ordered(nullptr); };
    auto name_of = [](const std::vector<TriangleMesh>& meshes, std::int64_t index) {
        return index >= 0 && static_cast<std::size_t>(index) < meshes.size() ? ordered(meshes[index].name) : ordered(nullptr);
    };
    auto dump = [](const ordered& value) { return value.dump(-1, ' ', false, ordered::error_handler_t::replace); };

    std::string out = "{\"clear\": " + std::string(report.clear ? "true" : "false") +
                      ", \"min_clearance\": " + dump(number(report.min_clearance)) + ",\n \"legs\": [";
    for (std::size_t k = 0; k < report.legs.size(); ++k) {
        const LegReport& leg = report.legs[k];
        ordered entry;
        entry["status"] = leg_status_name(leg.status);
        switch (leg.status) {
            case LegStatus::Hit:
                entry["obstacle"] = name_of(scene.obstacles, leg.obstacle);
                entry["triangle"] = leg.triangle;
                entry["part"] = name_of(scene.parts, leg.part);
                entry["fraction"] = ordered::array({number(leg.fraction_lo), number(leg.fraction_hi)});
                entry["position"] = ordered::array({number(leg.position[0]), number(leg.position[1]), number(leg.position[2])});
                if (report.turned) {
                    entry["rotation"] = ordered::array({number(leg.rotation[0]), number(leg.rotation[1]),
                                                        number(leg.rotation[2]), number(leg.rotation[3])});
                }
                if (leg.grazing) entry["grazing"] = true;
                break;
            case LegStatus::Clear:
                entry["clearance"] = number(leg.clearance);
                entry["obstacle"] = name_of(scene.obstacles, leg.obstacle);
                entry["fraction"] = leg.obstacle >= 0 ? number(leg.fraction_lo) : ordered(nullptr);
                break;
            case LegStatus::StartOverlap:
                entry["obstacle"] = name_of(scene.obstacles, leg.obstacle);
                entry["part"] = name_of(scene.parts, leg.part);
                entry["triangle"] = leg.triangle;
                break;
        }
        if (options.samples > 0) {
            entry["sampled"] = {{"hit", leg.sampled_hit}, {"fraction", number(leg.sampled_fraction)}};
        }
        out += (k == 0 ? "\n  " : ",\n  ") + dump(entry);
    }
    out += std::string(report.legs.empty() ? "]" : "\n ]") + ",\n \"build_seconds\": " + dump(number(report.build_seconds)) +
           ", \"seconds\": " + dump(number(report.seconds)) + "}\n";
    return out;
}

}  // namespace hullkit
