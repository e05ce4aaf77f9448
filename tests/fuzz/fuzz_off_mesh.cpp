// libFuzzer target: read_off_mesh (the OFF reader of `hullkit verify`) on arbitrary bytes.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "hullkit/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const hullkit::MeshResult mesh = hullkit::read_off_mesh(text, "fuzz.off");
    if (mesh.ok()) {
        if (mesh.xyz.size() % 3 != 0 || mesh.triangles.size() % 3 != 0) std::abort();
        for (std::uint32_t v : mesh.triangles) {
            if (v >= mesh.point_count()) std::abort();  // every index checked against the vertices
        }
    } else {
        if (!mesh.xyz.empty() || !mesh.triangles.empty()) std::abort();
        for (unsigned char c : mesh.error) {
            if (c < 0x20 || c >= 0x7f) std::abort();
        }
    }
    return 0;
}
