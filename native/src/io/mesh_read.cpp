// Mesh format detection and the shared helpers of the mesh readers.
#include "hullkit/mesh_read.hpp"

#include "mesh_read_internal.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace hullkit {
namespace io {

std::vector<std::string_view> split_words(std::string_view line, char comment) {
    if (comment != 0) {
        std::size_t cut = line.find(comment);
        if (cut != std::string_view::npos) line = line.substr(0, cut);
    }
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

bool parse_finite(std::string_view field, double* out) {
    if (field.empty() || field.size() > 400) return false;
    std::string copy(field);  // strtod needs a terminated string
    char* end = nullptr;
    errno = 0;
    double value = std::strtod(copy.c_str(), &end);
    // Overflow gives inf (rejected below); underflow to a subnormal or zero is a fine value.
    if (end != copy.c_str() + copy.size() || !std::isfinite(value)) return false;
    *out = value;
    return true;
}

bool parse_integer(std::string_view field, std::int64_t* out) {
    if (field.empty() || field.size() > 19) return false;
    std::size_t i = (field[0] == '-' || field[0] == '+') ? 1 : 0;
    if (i == field.size()) return false;
    std::int64_t value = 0;
    for (; i < field.size(); ++i) {
        if (field[i] < '0' || field[i] > '9') return false;
        const int digit = field[i] - '0';
        // 19 digits can exceed int64: refuse rather than overflow.
        if (value > (INT64_MAX - digit) / 10) return false;
        value = value * 10 + digit;
    }
    *out = field[0] == '-' ? -value : value;
    return true;
}

std::string printable(std::string_view text) {
    std::string out(text.substr(0, 40));
    // Printable ASCII only: no byte of a file (control codes, invalid UTF-8) reaches a terminal.
    for (char& c : out) {
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    }
    return text.size() > 40 ? out + "..." : out;
}

std::string quote(std::string_view field) { return "\"" + printable(field) + "\""; }

const char* non_finite_reason(std::string_view field) {
    std::size_t i = !field.empty() && (field[0] == '+' || field[0] == '-') ? 1 : 0;
    // "1e400", ".5e999": digits that strtod rounds to infinity; "nan", "inf", "infinity": words.
    const bool numeral = i < field.size() && ((field[i] >= '0' && field[i] <= '9') || field[i] == '.');
    return numeral ? "is out of the double range" : "is not a finite number";
}

std::size_t bom_length(std::string_view text) { return text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0; }

std::string extension_of(const std::string& source) {
    std::size_t dot = source.find_last_of("./\\");
    if (dot == std::string::npos || source[dot] != '.') return "";
    std::string extension = source.substr(dot + 1);
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

MeshResult mesh_error(std::string message) {
    MeshResult result;
    result.error = std::move(message);
    return result;
}

std::string at_line(const std::string& source, std::size_t line, const std::string& what) {
    return source + ":" + std::to_string(line) + ": " + what;
}

void SkippedRecords::add_kind(const std::string& word, std::uint64_t count, std::size_t first_line) {
    for (Kind& kind : kinds_) {
        if (kind.word == word) {
            kind.count += count;
            kind.first_line = std::min(kind.first_line, first_line);
            return;
        }
    }
    // Every kind after the first kMaxKinds - 1 named ones goes to "other" (the empty word).
    std::size_t named = 0;
    for (const Kind& kind : kinds_) named += kind.word.empty() ? 0 : 1;
    if (!word.empty() && named >= kMaxKinds - 1) return add_kind(std::string(), count, first_line);
    kinds_.push_back(Kind{word, count, first_line});
}

void SkippedRecords::add(std::string_view word, std::size_t line) {
    // Records longer than a message shows are told apart by what it shows.
    add_kind(std::string(word.substr(0, 41)), 1, line);
}

void SkippedRecords::merge(const SkippedRecords& later, std::size_t line_base) {
    for (const Kind& kind : later.kinds_) add_kind(kind.word, kind.count, line_base + kind.first_line);
}

std::vector<std::string> SkippedRecords::messages(const char* what) const {
    std::vector<std::string> out;
    std::vector<const Kind*> ordered;
    for (const Kind& kind : kinds_) ordered.push_back(&kind);
    // In the order of their first lines ("other" last): the same whatever the pieces were.
    std::sort(ordered.begin(), ordered.end(), [](const Kind* a, const Kind* b) {
        if (a->word.empty() != b->word.empty()) return b->word.empty();
        return a->first_line < b->first_line;
    });
    for (const Kind* kind : ordered) {
        std::string message = "skipped " + std::to_string(kind->count) + " " + (kind->word.empty() ? "other " : "") +
                              what + (kind->count == 1 ? "" : "s");
        if (!kind->word.empty()) message += " " + quote(kind->word);
        message += " (first at line " + std::to_string(kind->first_line) + ")";
        out.push_back(std::move(message));
    }
    return out;
}

bool is_known_obj_record(std::string_view word) {
    static const char* const kKnown[] = {
        "vt",       "vn",       "vp",         "o",         "g",     "s",     "mg",    "mtllib", "usemtl",
        "maplib",   "usemap",   "l",          "p",         "cstype", "deg",  "bmat",  "step",   "curv",
        "curv2",    "surf",     "parm",       "trim",      "hole",  "scrv",  "sp",    "end",    "con",
        "lod",      "bevel",    "c_interp",   "d_interp",  "shadow_obj", "trace_obj", "ctech", "stech"};
    for (const char* record : kKnown) {
        if (word == record) return true;
    }
    return false;
}

void append_fan(const std::vector<std::uint32_t>& corners, std::vector<std::uint32_t>* triangles) {
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        triangles->insert(triangles->end(), {corners[0], corners[k], corners[k + 1]});
    }
}

bool starts_with_word(std::string_view text, std::string_view word) {
    return text.size() >= word.size() && text.compare(0, word.size(), word) == 0 &&
           (text.size() == word.size() || std::isspace(static_cast<unsigned char>(text[word.size()])));
}

/// A binary STL's size is exactly 84 + 50 * the count stored at byte 80.
bool has_binary_stl_size(std::string_view head, std::uint64_t size) {
    if (head.size() < 84 || size < 84) return false;
    const auto* b = reinterpret_cast<const unsigned char*>(head.data()) + 80;
    std::uint64_t count = b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint64_t{b[3]} << 24);
    return size == 84 + 50 * count;
}

bool has_binary_stl_size(const std::string& bytes) { return has_binary_stl_size(bytes, bytes.size()); }

/// ASCII STL starts with "solid"; binary STL headers sometimes do too, so also look for "facet"
/// or "endsolid" and for the absence of NUL bytes near the start.
bool looks_like_ascii_stl(const std::string& bytes) {
    if (!starts_with_word(bytes, "solid")) return false;
    std::string_view head = std::string_view(bytes).substr(0, 1024);
    if (head.find('\0') != std::string_view::npos) return false;
    return head.find("facet") != std::string_view::npos || head.find("endsolid") != std::string_view::npos;
}

}  // namespace io

namespace {

using io::starts_with_word;

/// The first field of the first line that is neither blank nor a '#' comment.
std::string_view first_word(const std::string& bytes) {
    io::LineCursor lines(std::string_view(bytes).substr(0, std::min<std::size_t>(bytes.size(), 1 << 16)));
    std::string_view line;
    while (lines.next(&line)) {
        std::vector<std::string_view> words = io::split_words(line, '#');
        if (!words.empty()) return words[0];
    }
    return {};
}

/// A JSON object with an "asset" key in its first kilobytes: a glTF.
bool looks_like_gltf_json(const std::string& bytes) {
    const std::size_t start = bytes.find_first_not_of(" \t\r\n");
    if (start == std::string::npos || bytes[start] != '{') return false;
    return std::string_view(bytes).substr(start, 4096).find("\"asset\"") != std::string_view::npos;
}

bool is_obj_record(std::string_view word) {
    static const char* const kRecords[] = {"v",  "vt", "vn",     "vp",     "f", "l",      "p",
                                           "o",  "g",  "s",      "mtllib", "usemtl", "cstype"};
    for (const char* record : kRecords) {
        if (word == record) return true;
    }
    return false;
}

}  // namespace

const char* mesh_format_name(MeshFormat format) {
    switch (format) {
        case MeshFormat::Unknown: return "unknown";
        case MeshFormat::Obj: return "OBJ";
        case MeshFormat::Off: return "OFF";
        case MeshFormat::Ply: return "PLY";
        case MeshFormat::StlAscii: return "ASCII STL";
        case MeshFormat::StlBinary: return "binary STL";
        case MeshFormat::Gltf: return "glTF";
        case MeshFormat::Glb: return "binary glTF";
    }
    return "unknown";
}

MeshFormat detect_mesh_format(const std::string& bytes, const std::string& source) {
    if (starts_with_word(bytes, "ply")) return MeshFormat::Ply;
    if (bytes.compare(0, 4, "glTF") == 0) return MeshFormat::Glb;
    if (io::looks_like_ascii_stl(bytes)) return MeshFormat::StlAscii;
    if (io::has_binary_stl_size(bytes)) return MeshFormat::StlBinary;
    const std::string extension = io::extension_of(source);
    if (bytes.find('\0') == std::string::npos) {
        std::string_view word = first_word(bytes);
        if (word == "OFF") return MeshFormat::Off;
        if (word == "solid") return MeshFormat::StlAscii;
        if (is_obj_record(word)) return MeshFormat::Obj;
        if (looks_like_gltf_json(bytes)) return MeshFormat::Gltf;
    }
    if (extension == "gltf") return MeshFormat::Gltf;
    if (extension == "glb") return MeshFormat::Glb;
    if (extension == "obj") return MeshFormat::Obj;
    if (extension == "off") return MeshFormat::Off;
    if (extension == "ply") return MeshFormat::Ply;
    if (extension == "stl") return starts_with_word(bytes, "solid") ? MeshFormat::StlAscii : MeshFormat::StlBinary;
    return MeshFormat::Unknown;
}

MeshResult read_mesh(const std::string& bytes, const std::string& source) {
    return read_mesh(bytes, source, files_next_to(source));
}

MeshResult read_mesh(const std::string& bytes, const std::string& source, const ExternalFileLoader& load) {
    MeshResult result;
    switch (detect_mesh_format(bytes, source)) {
        case MeshFormat::Gltf:
        case MeshFormat::Glb: result = read_gltf_mesh(bytes, source, load); break;
        case MeshFormat::Obj: result = read_obj_mesh(bytes, source); break;
        case MeshFormat::Off: result = read_off_mesh(bytes, source); break;
        case MeshFormat::Ply: result = read_ply_mesh(bytes, source); break;
        case MeshFormat::StlAscii:
        case MeshFormat::StlBinary: result = read_stl_mesh(bytes, source); break;
        case MeshFormat::Unknown:
            return io::mesh_error(source + (bytes.empty() ? ": empty file, expected a mesh (OBJ, OFF, PLY, STL or glTF)"
                                                           : ": not a mesh file this reader knows (OBJ, OFF, PLY, STL or glTF)"));
    }
    if (!result.ok()) return result;  // (every reader refuses non-finite coordinates, naming where)
    if (result.triangles.empty()) return io::mesh_error(source + ": the mesh has no triangles");
    return result;
}

bool starts_like_mesh_file(const std::string& head, std::uint64_t size, const std::string& source) {
    const std::string extension = io::extension_of(source);
    if (extension == "ply" || extension == "stl" || extension == "gltf" || extension == "glb") return true;
    if (extension == "obj" || extension == "off") return false;
    return starts_with_word(head, "ply") || starts_with_word(head, "solid") || head.compare(0, 4, "glTF") == 0 ||
           io::has_binary_stl_size(head, size);
}

PointsResult read_points(const std::string& bytes, const std::string& source) {
    const std::string extension = io::extension_of(source);
    MeshFormat format = MeshFormat::Unknown;
    if (extension == "ply") {
        format = MeshFormat::Ply;
    } else if (extension == "stl") {
        format = MeshFormat::StlBinary;
    } else if (extension == "gltf" || extension == "glb") {
        format = MeshFormat::Gltf;
    } else if (extension != "obj" && extension != "off") {
        format = detect_mesh_format(bytes, "");
    }
    PointsResult points;
    if (format == MeshFormat::Ply) return read_ply_points(bytes, source);
    if (format != MeshFormat::StlAscii && format != MeshFormat::StlBinary && format != MeshFormat::Gltf &&
        format != MeshFormat::Glb) {
        return parse_points(bytes, source);
    }
    MeshResult mesh = read_mesh(bytes, source);  // STL (ASCII or binary) or glTF (.gltf or .glb), by content
    points.error = std::move(mesh.error);
    points.xyz = std::move(mesh.xyz);
    points.warnings = std::move(mesh.warnings);
    return points;
}

Points2Result read_points_2d(const std::string& bytes, const std::string& source) {
    const std::string extension = io::extension_of(source);
    // (The content is judged after a UTF-8 byte-order mark, which the text readers skip.)
    const std::size_t bom = io::bom_length(bytes);
    const bool mesh_file = extension == "obj" || extension == "off" || extension == "ply" || extension == "stl" ||
                           extension == "gltf" || extension == "glb" ||
                           detect_mesh_format(bom ? bytes.substr(bom) : bytes, "") != MeshFormat::Unknown;
    if (!mesh_file) return parse_points_2d(bytes, source);
    const PointsResult points = read_points(bytes, source);
    Points2Result out;
    out.error = points.error;
    out.warnings = points.warnings;
    out.xy.reserve(2 * points.count());
    for (std::size_t i = 0; i < points.count(); ++i) {
        out.xy.push_back(points.xyz[3 * i]);
        out.xy.push_back(points.xyz[3 * i + 1]);
    }
    return out;
}

}  // namespace hullkit
