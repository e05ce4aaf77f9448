// libFuzzer target: the route scene reader (parse_scene, native/src/route/scene_io.cpp) on arbitrary
// bytes. The bytes up to the first NUL are the scene JSON; the bytes after it, if any, are what the
// mesh loader hands out for any "mesh" file the scene names (nothing touches the file system;
// without a NUL every mesh file is missing, which must be reported cleanly). Odd sizes read without
// requiring a route. Checked:
//  - the same scene, bit for bit, or the same message, with and without the fast path for inline
//    mesh arrays (native/src/route/scene_arrays.hpp);
//  - a scene: at least one part, every mesh with whole index triples in range, at least one
//    triangle and finite coordinates, a route of at least 2 finite waypoints (when required),
//    a finite margin >= 0, no rotations or a unit quaternion per waypoint, a finite pivot;
//    written back as JSON with inline meshes and read again, the same scene;
//  - an error: no scene, one line starting with the file name, no control characters and only
//    well-formed UTF-8 (no raw byte of the input reaches a terminal);
//  - no exception of any kind escapes.
// Built by scripts/fuzz.sh (clang++ -fsanitize=fuzzer,address,undefined).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "hullkit/mesh_io.hpp"
#include "hullkit/scene_io.hpp"
#include "route/scene_arrays.hpp"
#include "../route/scene_bits.hpp"

namespace {

/// True if `text` is well-formed UTF-8 without C0/C1 control characters or DEL.
bool terminal_safe(const std::string& text) {
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 || c == 0x7f) return false;
        if (c < 0x80) {
            ++i;
            continue;
        }
        std::size_t length = c >= 0xf0 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 ? 2 : 0;
        if (length == 0 || c > 0xf4 || i + length > text.size()) return false;
        std::uint32_t code = c & (0x7f >> length);
        for (std::size_t k = 1; k < length; ++k) {
            const unsigned char d = static_cast<unsigned char>(text[i + k]);
            if ((d & 0xc0) != 0x80) return false;
            code = code << 6 | (d & 0x3f);
        }
        if ((length == 3 && code < 0x800) || (length == 4 && (code < 0x10000 || code > 0x10ffff)) ||
            (code >= 0xd800 && code <= 0xdfff) || (code >= 0x80 && code < 0xa0)) {
            return false;
        }
        i += length;
    }
    return true;
}

void check_mesh(const hullkit::TriangleMesh& mesh) {
    if (mesh.xyz.size() % 3 != 0 || mesh.triangles.empty() || mesh.triangles.size() % 3 != 0) std::abort();
    for (double x : mesh.xyz) {
        if (!std::isfinite(x)) std::abort();
    }
    for (std::uint32_t v : mesh.triangles) {
        if (v >= mesh.xyz.size() / 3) std::abort();
    }
}

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (unsigned char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c < 0x20) {
            static const char* const kHex = "0123456789abcdef";
            out += "\\u00";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        } else {
            out += static_cast<char>(c);
        }
    }
    return out + "\"";
}

std::string json_parts(const std::vector<hullkit::TriangleMesh>& meshes) {
    std::string out = "[";
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const hullkit::TriangleMesh& mesh = meshes[m];
        out += std::string(m ? "," : "") + "{\"name\":" + json_string(mesh.name) + ",\"vertices\":[";
        for (std::size_t i = 0; i < mesh.xyz.size(); i += 3) {
            out += std::string(i ? "," : "") + "[" + hullkit::format_json_number(mesh.xyz[i]) + "," +
                   hullkit::format_json_number(mesh.xyz[i + 1]) + "," + hullkit::format_json_number(mesh.xyz[i + 2]) + "]";
        }
        out += "],\"triangles\":[";
        for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
            out += std::string(t ? "," : "") + "[" + std::to_string(mesh.triangles[t]) + "," +
                   std::to_string(mesh.triangles[t + 1]) + "," + std::to_string(mesh.triangles[t + 2]) + "]";
        }
        out += "]}";
    }
    return out + "]";
}

bool same_meshes(const std::vector<hullkit::TriangleMesh>& a, const std::vector<hullkit::TriangleMesh>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t m = 0; m < a.size(); ++m) {
        if (a[m].name != b[m].name || a[m].xyz != b[m].xyz || a[m].triangles != b[m].triangles) return false;
    }
    return true;
}

void run(const std::string& text, const std::string* mesh_bytes, bool require_route) {
    std::size_t loads = 0;
    const hullkit::MeshLoader loader = [&](const std::string& path, std::string* bytes, std::string* error) {
        ++loads;
        if (path.empty()) std::abort();  // the reader refuses an empty name itself
        if (!mesh_bytes) {
            *error = path + ": cannot open: No such file or directory";
            return false;
        }
        *bytes = *mesh_bytes;
        return true;
    };
    hullkit::SceneReadOptions options;
    options.require_route = require_route;
    const hullkit::SceneResult result = hullkit::parse_scene(text, "fuzz.json", loader, options);
    const hullkit::SceneResult tree = hullkit::route_detail::parse_scene_tree_only(text, "fuzz.json", loader, options);
    if (tree.error != result.error || tree.warnings != result.warnings || !hullkit_test::same_scene_bits(tree.scene, result.scene)) {
        std::abort();
    }
    if (!result.ok()) {
        const hullkit::Scene& s = result.scene;
        if (!s.parts.empty() || !s.obstacles.empty() || !s.route.empty() || s.margin != 0) std::abort();
        if (result.error.rfind("fuzz.json: ", 0) != 0 || !terminal_safe(result.error)) std::abort();
        return;
    }
    const hullkit::Scene& scene = result.scene;
    if (scene.parts.empty()) std::abort();
    for (const hullkit::TriangleMesh& mesh : scene.parts) check_mesh(mesh);
    for (const hullkit::TriangleMesh& mesh : scene.obstacles) check_mesh(mesh);
    if (scene.route.size() % 3 != 0 || (require_route && scene.route.size() < 6)) std::abort();
    for (double x : scene.route) {
        if (!std::isfinite(x)) std::abort();
    }
    if (!std::isfinite(scene.margin) || scene.margin < 0) std::abort();
    // Rotations: none, or one unit quaternion per waypoint; a finite pivot.
    if (!scene.rotations.empty() && scene.rotations.size() != scene.route.size() / 3 * 4) std::abort();
    for (std::size_t i = 0; i < scene.rotations.size(); i += 4) {
        const double* q = &scene.rotations[i];
        const double length2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        if (!(std::fabs(length2 - 1.0) <= 1e-12)) std::abort();
    }
    for (double c : scene.pivot) {
        if (!std::isfinite(c)) std::abort();
    }

    // Written back with inline meshes and read again: the same scene, and no file asked for.
    if (scene.parts.size() + scene.obstacles.size() > 50) return;
    std::string json = "{\"traverse\":{\"parts\":" + json_parts(scene.parts) + ",\"pivot\":[" +
                       hullkit::format_json_number(scene.pivot[0]) + "," + hullkit::format_json_number(scene.pivot[1]) +
                       "," + hullkit::format_json_number(scene.pivot[2]) + "]},\"obstacles\":" +
                       json_parts(scene.obstacles) + ",\"margin\":" + hullkit::format_json_number(scene.margin);
    if (!scene.route.empty()) {
        json += ",\"route\":[";
        for (std::size_t i = 0; i < scene.route.size(); i += 3) {
            const std::string position = "[" + hullkit::format_json_number(scene.route[i]) + "," +
                                         hullkit::format_json_number(scene.route[i + 1]) + "," +
                                         hullkit::format_json_number(scene.route[i + 2]) + "]";
            std::string waypoint = position;
            if (!scene.rotations.empty()) {
                const double* q = &scene.rotations[i / 3 * 4];
                waypoint = "{\"position\":" + position + ",\"rotation\":{\"quaternion\":[" +
                           hullkit::format_json_number(q[0]) + "," + hullkit::format_json_number(q[1]) + "," +
                           hullkit::format_json_number(q[2]) + "," + hullkit::format_json_number(q[3]) + "]}}";
            }
            json += std::string(i ? "," : "") + waypoint;
        }
        json += "]";
    }
    json += "}";
    const std::size_t before = loads;
    const hullkit::SceneResult back = hullkit::parse_scene(json, "back.json", loader, options);
    if (!back.ok() || loads != before || !same_meshes(back.scene.parts, scene.parts) ||
        !same_meshes(back.scene.obstacles, scene.obstacles) || back.scene.route != scene.route ||
        back.scene.margin != scene.margin || back.scene.rotations.size() != scene.rotations.size() ||
        !std::equal(scene.pivot, scene.pivot + 3, back.scene.pivot)) {
        std::abort();
    }
    // Normalizing a unit quaternion again may move its last bits.
    for (std::size_t i = 0; i < scene.rotations.size(); ++i) {
        if (!(std::fabs(back.scene.rotations[i] - scene.rotations[i]) <= 1e-15)) std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = bytes.find('\0');
    const std::string text = bytes.substr(0, nul);
    const std::string mesh = nul == std::string::npos ? std::string() : bytes.substr(nul + 1);
    // Any exception (nlohmann's included) is a bug: the wasm build cannot catch them.
    try {
        run(text, nul == std::string::npos ? nullptr : &mesh, size % 2 == 0);
    } catch (...) {
        std::abort();
    }
    return 0;
}
