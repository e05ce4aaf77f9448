// libFuzzer target: the point readers (xyz, rbox, OBJ, OFF) through parse_points on arbitrary
// bytes; the chunked file reader on the same bytes (as a stream of unknown size), which must give
// the very same result; and hullkit::PointReader in batches of any size on 1 or 3 threads, whose
// batches joined must be parse_points' result (text only) or read_points' (every format: PLY is
// streamed, STL read whole), with the same message.
// Built by scripts/fuzz.sh (clang++ -fsanitize=fuzzer,address,undefined).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"
#include "hullkit/point_reader.hpp"

namespace {

/// Equal, or both NaN, element by element.
bool same_points(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!(a[i] == b[i] || (a[i] != a[i] && b[i] != b[i]))) return false;
    }
    return true;
}

/// Whether `part` is the start of `whole` (same_points on that start).
bool is_prefix(const std::vector<double>& part, const std::vector<double>& whole) {
    return part.size() <= whole.size() && same_points(part, std::vector<double>(whole.begin(), whole.begin() + part.size()));
}

/// Every batch of a PointReader joined; `error` its message. Aborts if a batch breaks the contract.
std::vector<double> read_batches(hullkit::PointReader& reader, std::string* error) {
    std::vector<double> all, batch;
    while (reader.next(&batch)) {
        if (batch.empty() || batch.size() % 3 != 0) std::abort();
        all.insert(all.end(), batch.begin(), batch.end());
        if (reader.points_read() != all.size() / 3) std::abort();
    }
    if (!batch.empty()) std::abort();
    *error = reader.error();
    return all;
}

/// PointReader on `text` must give `expected` (the points, or the message) with every batch size
/// and thread count tried; before an error, the points handed out must agree with each other.
void check_reader(const std::string& text, const std::string& source, bool text_only, const hullkit::PointsResult& expected,
                  const std::uint8_t* data, std::size_t size) {
    std::vector<double> longest;
    const std::size_t batches[] = {7, 64, 1000};
    for (std::size_t batch : batches) {
        for (unsigned threads : {1u, 3u}) {
            hullkit::PointReaderOptions options;
            options.batch_bytes = batch;
            options.threads = threads;
            options.text_only = text_only;
            std::string error;
            std::vector<double> got;
            if (batch == 64 && size > 0) {  // a stream of unknown size
                std::FILE* file = fmemopen(const_cast<std::uint8_t*>(data), size, "rb");
                if (!file) continue;
                hullkit::PointReader reader(file, source, options);
                got = read_batches(reader, &error);
                std::fclose(file);
                // Binary STL is known by its size; a stream has none (read_points mode reads it whole).
                const bool stl = expected.error.find("binary STL is not supported") != std::string::npos;
                if (stl && text_only) {
                    if (error.rfind(source + ": not a point file: binary data", 0) != 0) std::abort();
                    continue;
                }
            } else {
                hullkit::PointReader reader(std::string_view(text), source, options);
                got = read_batches(reader, &error);
            }
            if (error != expected.error) std::abort();
            if (expected.ok() ? !same_points(got, expected.xyz) : !(is_prefix(got, longest) || is_prefix(longest, got))) {
                std::abort();
            }
            if (got.size() > longest.size()) longest = got;
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const hullkit::PointsResult parsed = hullkit::parse_points(text, "fuzz.txt");
    // Every result is either points (a whole number of xyz triples, all finite; none for an input
    // without any) or one line of error.
    if (parsed.ok() ? parsed.xyz.size() % 3 != 0
                    : !parsed.xyz.empty() || parsed.error.find('\n') != std::string::npos) {
        std::abort();
    }
    for (double v : parsed.xyz) {
        if (!std::isfinite(v)) std::abort();
    }
    // No byte of the input may reach the message or a warning unescaped (no raw control bytes on
    // a terminal).
    for (unsigned char c : parsed.error) {
        if (c < 0x20 || c >= 0x7f) std::abort();
    }
    for (const std::string& warning : parsed.warnings) {
        for (unsigned char c : warning) {
            if (c < 0x20 || c >= 0x7f) std::abort();
        }
    }
    check_reader(text, "fuzz.txt", /*text_only=*/true, parsed, data, size);
    check_reader(text, "fuzz.txt", false, hullkit::read_points(text, "fuzz.txt"), data, size);
    check_reader(text, "fuzz.ply", false, hullkit::read_points(text, "fuzz.ply"), data, size);
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
    if (!same_points(streamed.xyz, parsed.xyz)) std::abort();
    return 0;
}
