// libFuzzer target: the point readers (xyz, rbox, OBJ, OFF) through parse_points on arbitrary
// bytes, and the chunked file reader on the same bytes (as a stream of unknown size), which must
// give the very same result.
// Built by scripts/fuzz.sh (clang++ -fsanitize=fuzzer,address,undefined).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "hullkit/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const hullkit::PointsResult parsed = hullkit::parse_points(text, "fuzz.txt");
    // Every result is either points (a whole number of xyz triples) or one line of error.
    if (parsed.ok() ? parsed.xyz.empty() || parsed.xyz.size() % 3 != 0
                    : !parsed.xyz.empty() || parsed.error.find('\n') != std::string::npos) {
        std::abort();
    }
    // No byte of the input may reach the message unescaped (no raw control bytes on a terminal).
    for (unsigned char c : parsed.error) {
        if (c < 0x20 || c >= 0x7f) std::abort();
    }
    if (size == 0) return 0;  // fmemopen needs at least one byte
    std::FILE* file = fmemopen(const_cast<std::uint8_t*>(data), size, "rb");
    if (!file) return 0;
    const hullkit::PointsResult streamed = hullkit::read_points_file(file, "fuzz.txt");
    std::fclose(file);
    // A stream has no known size, so a binary STL (recognised by its size) is plain binary data.
    const bool stl = parsed.error.find("binary STL is not supported") != std::string::npos;
    if (stl ? streamed.error.rfind("fuzz.txt: not a point file: binary data", 0) != 0 : streamed.error != parsed.error) {
        std::abort();
    }
    if (streamed.xyz.size() != parsed.xyz.size()) std::abort();
    for (std::size_t i = 0; i < parsed.xyz.size(); ++i) {
        const double a = parsed.xyz[i], b = streamed.xyz[i];
        if (!(a == b || (a != a && b != b))) std::abort();  // equal, or both NaN
    }
    return 0;
}
