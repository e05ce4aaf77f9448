// libFuzzer target: the glTF 2.0 reader (read_gltf_mesh, through tinygltf) on arbitrary bytes, as
// a .glb and as a .gltf whose external buffer files are served from memory (every URI gets the
// input itself, so a .gltf can name its own bytes as a buffer). Checked for every result:
//  - a mesh: whole xyz triples, whole index triples, every index in range, finite coordinates;
//    warnings and errors one line of printable ASCII (an error starting with the file name);
//  - written as .glb (write_glb, float32 positions) and read back: the same triangles and the
//    positions rounded to float (when they fit a float);
//  - read_mesh on the same bytes gives the same mesh or the same error.
// Built by scripts/fuzz.sh (clang++ -fsanitize=fuzzer,address,undefined).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "hullkit/hull.hpp"
#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"

namespace {

void check_line(const std::string& text) {
    for (unsigned char c : text) {
        if (c < 0x20 || c >= 0x7f) std::abort();
    }
}

void check(const hullkit::MeshResult& mesh, const std::string& source) {
    for (const std::string& warning : mesh.warnings) check_line(warning);
    if (!mesh.ok()) {
        if (!mesh.xyz.empty() || !mesh.triangles.empty()) std::abort();
        if (mesh.error.rfind(source + ":", 0) != 0) std::abort();
        check_line(mesh.error);
        return;
    }
    if (mesh.xyz.size() % 3 != 0 || mesh.triangles.size() % 3 != 0) std::abort();
    for (std::uint32_t v : mesh.triangles) {
        if (v >= mesh.point_count()) std::abort();
    }
    for (double x : mesh.xyz) {
        if (!std::isfinite(x)) std::abort();
    }
    if (mesh.point_count() > 5000 || mesh.triangles.empty()) return;
    // Every vertex as a "hull" vertex, the triangles as they are: the .glb writer's input.
    hullkit::Hull hull;
    hull.dimension = 3;
    hull.triangles = mesh.triangles;
    for (std::uint32_t v = 0; v < mesh.point_count(); ++v) hull.vertices.push_back(v);
    std::string glb;
    try {
        glb = hullkit::write_glb(hullkit::PointSpan(mesh.xyz), hull);
    } catch (const std::domain_error&) {
        return;  // a coordinate beyond float's range
    }
    const hullkit::MeshResult back = hullkit::read_gltf_mesh(glb, "back.glb", {});
    if (!back.ok() || back.triangles != mesh.triangles || back.xyz.size() != mesh.xyz.size()) std::abort();
    for (std::size_t i = 0; i < mesh.xyz.size(); ++i) {
        if (back.xyz[i] != static_cast<double>(static_cast<float>(mesh.xyz[i]))) std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const hullkit::ExternalFileLoader from_memory = [&bytes](const std::string&, std::string* out, std::string*) {
        *out = bytes;
        return true;
    };
    for (const char* name : {"fuzz.glb", "fuzz.gltf"}) {
        const hullkit::MeshResult mesh = hullkit::read_gltf_mesh(bytes, name, from_memory);
        check(mesh, name);
        // read_mesh detects the format (by content, else by the name) and checks for triangles.
        const hullkit::MeshResult detected = hullkit::read_mesh(bytes, name, from_memory);
        check(detected, name);
        const hullkit::MeshFormat format = hullkit::detect_mesh_format(bytes, name);
        if (format == hullkit::MeshFormat::Gltf || format == hullkit::MeshFormat::Glb) {
            if (detected.ok() && (!mesh.ok() || detected.xyz != mesh.xyz || detected.triangles != mesh.triangles)) std::abort();
            if (!mesh.ok() && detected.error != mesh.error) std::abort();
        }
    }
    return 0;
}
