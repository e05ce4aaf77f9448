// libFuzzer target: the 2D point reader (parse_points_2d, native/src/io/points2d.cpp) on arbitrary
// bytes. Checked: points are whole finite x y pairs, each with the number of a line of the input
// whose first two fields (split at whitespace and commas, after a byte-order mark on line 1) are
// exactly those coordinates (strtod); warnings are printable ASCII; an error is one line of printable
// ASCII (no byte of the input reaches a terminal) starting with the file name, with no points;
// input with a NUL byte in its first 4 KiB is refused as not a point file, not with a complaint
// about coordinates.
// Built by scripts/fuzz.sh (clang++ -fsanitize=fuzzer,address,undefined).
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "hullkit/mesh_io.hpp"

namespace {

/// Line `number` (1-based; "\n", "\r\n" or "\r" ends a line) of `text`.
std::string line_of(const std::string& text, std::size_t number) {
    std::size_t start = 0;
    for (std::size_t line = 1; line < number; ++line) {
        std::size_t end = text.find_first_of("\r\n", start);
        if (end == std::string::npos) std::abort();  // the line does not exist
        start = end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
    }
    std::size_t end = text.find_first_of("\r\n", start);
    return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

/// The first `count` fields of `line` (separated by whitespace and commas), as strtod reads them.
std::vector<double> leading_numbers(const std::string& line, std::size_t count) {
    std::vector<double> out;
    std::size_t i = 0;
    auto separator = [](char c) { return c == ',' || std::isspace(static_cast<unsigned char>(c)); };
    while (out.size() < count) {
        while (i < line.size() && separator(line[i])) ++i;
        std::size_t start = i;
        while (i < line.size() && !separator(line[i])) ++i;
        if (i == start) std::abort();
        out.push_back(std::strtod(line.substr(start, i - start).c_str(), nullptr));
    }
    return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::vector<std::size_t> lines{42};  // must be cleared
    const hullkit::Points2Result result = hullkit::parse_points_2d(text, "fuzz.txt", &lines);
    if (!result.ok()) {
        if (!result.xy.empty() || !lines.empty()) std::abort();
        if (result.error.rfind("fuzz.txt:", 0) != 0) std::abort();
        for (unsigned char c : result.error) {
            if (c < 0x20 || c >= 0x7f) std::abort();
        }
        if (text.substr(0, 4096).find('\0') != std::string::npos &&
            result.error.find(": not a point file: ") == std::string::npos) {
            std::abort();
        }
        return 0;
    }
    if (result.xy.size() % 2 != 0 || lines.size() != result.count()) std::abort();
    if (text.substr(0, 4096).find('\0') != std::string::npos) std::abort();
    for (const std::string& warning : result.warnings) {
        for (unsigned char c : warning) {
            if (c < 0x20 || c >= 0x7f) std::abort();
        }
    }
    for (std::size_t i = 0; i < result.count(); ++i) {
        if (!std::isfinite(result.xy[2 * i]) || !std::isfinite(result.xy[2 * i + 1])) std::abort();
        if (i > 0 && lines[i] <= lines[i - 1]) std::abort();
        std::string line = line_of(text, lines[i]);
        if (lines[i] == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a byte-order mark
        const std::vector<double> numbers = leading_numbers(line, 2);
        if (numbers[0] != result.xy[2 * i] || numbers[1] != result.xy[2 * i + 1]) std::abort();
    }
    // Without asking for the lines: the same points.
    const hullkit::Points2Result again = hullkit::parse_points_2d(text, "fuzz.txt");
    if (again.xy != result.xy || !again.ok()) std::abort();
    return 0;
}
