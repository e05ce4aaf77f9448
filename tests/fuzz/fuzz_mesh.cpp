// libFuzzer target: every mesh reader (native/src/io: OBJ, OFF, PLY ascii and binary, STL ascii and
// binary; glTF when the content says so, fuzz_gltf covers it) and the point readers built on them (read_ply_points, read_points, read_points_2d) on
// arbitrary bytes. Each reader runs directly, and read_mesh (format detection) runs under
// a file name whose extension the input's size picks. Checked for every result:
//  - a mesh: whole xyz triples, whole index triples, every index in range, finite coordinates
//    (read_off_mesh may keep non-finite ones; read_mesh refuses them), STL corners merged exactly
//    (no two vertices with the same coordinates), and the mesh read back from OFF text written
//    with the shortest round-trip numbers is the same mesh;
//  - read_mesh gives exactly the result of the reader for the format it detected (plus its own
//    checks: finite coordinates, at least one triangle);
//  - an error: no mesh, one line that starts with the file name, printable ASCII only (no byte of
//    the input reaches a terminal).
// Built by scripts/fuzz.sh (clang++ -fsanitize=fuzzer,address,undefined).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <tuple>

#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"

namespace {

bool same_number(double a, double b) { return a == b || (a != a && b != b); }

bool same_mesh(const hullkit::MeshResult& a, const hullkit::MeshResult& b) {
    if (a.error != b.error || a.triangles != b.triangles || a.xyz.size() != b.xyz.size()) return false;
    for (std::size_t i = 0; i < a.xyz.size(); ++i) {
        if (!same_number(a.xyz[i], b.xyz[i])) return false;
    }
    return true;
}

void check_error(const hullkit::MeshResult& mesh, const std::string& source) {
    if (!mesh.xyz.empty() || !mesh.triangles.empty()) std::abort();
    if (mesh.error.rfind(source + ":", 0) != 0) std::abort();
    for (unsigned char c : mesh.error) {
        if (c < 0x20 || c >= 0x7f) std::abort();
    }
}

/// Checks a reader's result; `finite`: the reader refuses non-finite coordinates.
void check(const hullkit::MeshResult& mesh, const std::string& source, bool finite, bool merged) {
    if (!mesh.ok()) return check_error(mesh, source);
    if (mesh.xyz.size() % 3 != 0 || mesh.triangles.size() % 3 != 0) std::abort();
    for (std::uint32_t v : mesh.triangles) {
        if (v >= mesh.point_count()) std::abort();
    }
    for (double x : mesh.xyz) {
        if (finite && !std::isfinite(x)) std::abort();
    }
    if (merged) {
        std::set<std::tuple<double, double, double>> seen;
        for (std::size_t i = 0; i < mesh.xyz.size(); i += 3) {
            if (!seen.insert({mesh.xyz[i], mesh.xyz[i + 1], mesh.xyz[i + 2]}).second) std::abort();
        }
    }
    // Written as OFF and read back: the same mesh (numbers round trip exactly).
    if (mesh.point_count() > 2000 || !finite) return;
    std::string off = "OFF\n" + std::to_string(mesh.point_count()) + " " + std::to_string(mesh.triangle_count()) + " 0\n";
    for (std::size_t i = 0; i < mesh.xyz.size(); i += 3) {
        off += hullkit::format_double(mesh.xyz[i]) + " " + hullkit::format_double(mesh.xyz[i + 1]) + " " +
               hullkit::format_double(mesh.xyz[i + 2]) + "\n";
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
        off += "3 " + std::to_string(mesh.triangles[t]) + " " + std::to_string(mesh.triangles[t + 1]) + " " +
               std::to_string(mesh.triangles[t + 2]) + "\n";
    }
    const hullkit::MeshResult back = hullkit::read_off_mesh(off, "back.off");
    if (!same_mesh(back, mesh)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    check(hullkit::read_obj_mesh(bytes, "fuzz.obj"), "fuzz.obj", true, false);
    check(hullkit::read_off_mesh(bytes, "fuzz.off"), "fuzz.off", false, false);
    const hullkit::MeshResult ply = hullkit::read_ply_mesh(bytes, "fuzz.ply");
    check(ply, "fuzz.ply", true, false);
    // The point readers on the same bytes: a PLY point cloud reads as the mesh's vertices whenever
    // the mesh reads; every result is whole triples (pairs) or a one-line error naming the file.
    const hullkit::PointsResult ply_points = hullkit::read_ply_points(bytes, "fuzz.ply");
    if (ply.ok() && (!ply_points.ok() || ply_points.xyz != ply.xyz)) std::abort();
    for (const char* name : {"fuzz.ply", "fuzz.stl", "fuzz"}) {
        const hullkit::PointsResult points = hullkit::read_points(bytes, name);
        const hullkit::Points2Result points2 = hullkit::read_points_2d(bytes, name);
        if (points.ok() ? points.xyz.size() % 3 != 0 : points.error.rfind(std::string(name) + ":", 0) != 0) std::abort();
        if (points2.ok() ? points2.xy.size() % 2 != 0 : points2.error.rfind(std::string(name) + ":", 0) != 0) std::abort();
    }
    check(hullkit::read_stl_mesh(bytes, "fuzz.stl"), "fuzz.stl", true, true);

    // Detection, under a name whose extension decides when the content does not.
    static const char* const kNames[] = {"fuzz", "fuzz.obj", "fuzz.OFF", "fuzz.ply", "fuzz.stl"};
    const std::string source = kNames[size % 5];
    const hullkit::MeshFormat format = hullkit::detect_mesh_format(bytes, source);
    const hullkit::MeshResult mesh = hullkit::read_mesh(bytes, source);
    check(mesh, source, true, format == hullkit::MeshFormat::StlAscii || format == hullkit::MeshFormat::StlBinary);
    hullkit::MeshResult direct;
    switch (format) {
        case hullkit::MeshFormat::Obj: direct = hullkit::read_obj_mesh(bytes, source); break;
        case hullkit::MeshFormat::Off: direct = hullkit::read_off_mesh(bytes, source); break;
        case hullkit::MeshFormat::Ply: direct = hullkit::read_ply_mesh(bytes, source); break;
        case hullkit::MeshFormat::StlAscii:
        case hullkit::MeshFormat::StlBinary: direct = hullkit::read_stl_mesh(bytes, source); break;
        case hullkit::MeshFormat::Gltf:
        case hullkit::MeshFormat::Glb: direct = hullkit::read_gltf_mesh(bytes, source, hullkit::files_next_to(source)); break;
        case hullkit::MeshFormat::Unknown:
            if (mesh.ok()) std::abort();
            return 0;
    }
    // read_mesh adds checks of its own (finite coordinates, some triangle); otherwise the same.
    if (mesh.ok()) {
        if (!same_mesh(mesh, direct)) std::abort();
    } else if (!direct.ok()) {
        if (mesh.error != direct.error) std::abort();
    } else {
        bool finite = true;
        for (double x : direct.xyz) finite = finite && std::isfinite(x);
        if (finite && !direct.triangles.empty()) std::abort();
    }
    return 0;
}
