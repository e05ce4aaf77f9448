// Text readers and writers for point sets and hulls; see mesh_io.hpp for the formats.
#include "hullkit/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <system_error>
#include <unordered_map>

#include "point_key.hpp"

namespace hullkit {
namespace {

// ---------------------------------------------------------------------------------------------
// Lines and fields
// ---------------------------------------------------------------------------------------------

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/// Walks the text line by line, handing out only lines with content: the part before any '#'
/// that is not all whitespace. Line numbers count every line, so messages match an editor's.
class LineCursor {
public:
    explicit LineCursor(const std::string& text)
        : pos_(text.data()), end_(text.data() + text.size()) {}

    /// Advances to the next line with content; false at the end of the text.
    bool next(std::string_view* content) {
        while (pos_ < end_) {
            const char* begin = pos_;
            const char* newline = static_cast<const char*>(std::memchr(pos_, '\n', end_ - pos_));
            const char* stop = newline ? newline : end_;
            pos_ = newline ? newline + 1 : end_;
            ++line_number_;
            const char* hash = static_cast<const char*>(std::memchr(begin, '#', stop - begin));
            if (hash) stop = hash;
            while (begin < stop && is_space(*begin)) ++begin;
            while (stop > begin && is_space(stop[-1])) --stop;
            if (begin < stop) {
                *content = std::string_view(begin, stop - begin);
                return true;
            }
        }
        return false;
    }

    /// The number of the line last read (with or without content).
    std::size_t line_number() const { return line_number_; }

private:
    const char* pos_;
    const char* end_;
    std::size_t line_number_ = 0;
};

/// Splits trimmed line content into fields at whitespace and, if `allow_commas`, at a single
/// comma (with optional whitespace around it). Returns false with *what set for an empty
/// field ("1,,2", a leading or a trailing comma), which would otherwise vanish silently.
bool split_fields(std::string_view line, bool allow_commas, std::vector<std::string_view>* fields,
                  std::string* what) {
    fields->clear();
    std::size_t i = 0;
    const std::size_t n = line.size();
    bool after_comma = false;
    while (i < n) {
        char c = line[i];
        if (is_space(c)) {
            ++i;
            continue;
        }
        if (allow_commas && c == ',') {
            if (fields->empty() || after_comma) {
                *what = "empty field before a comma";
                return false;
            }
            after_comma = true;
            ++i;
            continue;
        }
        std::size_t start = i;
        while (i < n && !is_space(line[i]) && !(allow_commas && line[i] == ',')) ++i;
        fields->push_back(line.substr(start, i - start));
        after_comma = false;
    }
    if (after_comma) {
        *what = "empty field after the last comma";
        return false;
    }
    return true;
}

/// A field as it should appear inside a one-line message: printable ASCII, at most 40 chars.
std::string quoted(std::string_view field) {
    constexpr std::size_t kMax = 40;
    std::string out = "\"";
    for (std::size_t i = 0; i < field.size() && i < kMax; ++i) {
        unsigned char c = static_cast<unsigned char>(field[i]);
        out += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
    }
    if (field.size() > kMax) out += "...";
    out += '"';
    return out;
}

// ---------------------------------------------------------------------------------------------
// Numbers
// ---------------------------------------------------------------------------------------------

/// A number in strtod's decimal syntax ("-1.5e3", ".5", "+2", "inf", "nan"); the whole field
/// must be the number. Hexadecimal floats are not part of the syntax. Out-of-range values
/// become +-inf or +-0 as with strtod: not a syntax error, the hull reports non-finite points.
bool parse_double(std::string_view field, double* out) {
    const char* begin = field.data();
    const char* end = begin + field.size();
    if (begin < end && *begin == '+') {  // strtod allows a '+', from_chars does not
        ++begin;
        if (begin < end && (*begin == '+' || *begin == '-')) return false;
    }
    if (begin == end) return false;
    double value = 0.0;
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
    // from_chars is ~5x faster than strtod (1e6 points: most of the parse time) and ignores
    // the C locale's decimal separator.
    auto [stop, status] = std::from_chars(begin, end, value);
    if (stop != end) return false;
    if (status == std::errc::result_out_of_range) {
        value = std::strtod(begin, nullptr);  // rare: let strtod pick +-inf / +-0
    } else if (status != std::errc()) {
        return false;
    }
#else
    // The text is NUL-terminated and every field ends at whitespace, ',', '#', '\n' or the end,
    // none of which can continue a number, so strtod never reads past the field.
    if (std::memchr(begin, 'x', end - begin) || std::memchr(begin, 'X', end - begin)) return false;
    char* stop = nullptr;
    value = std::strtod(begin, &stop);
    if (stop != end) return false;
#endif
    *out = value;
    return true;
}

/// A non-negative decimal integer (digits only) that fits in `limit`.
bool parse_count(std::string_view field, std::uint64_t limit, std::uint64_t* out) {
    if (field.empty()) return false;
    std::uint64_t value = 0;
    for (char c : field) {
        if (c < '0' || c > '9') return false;
        std::uint64_t digit = static_cast<std::uint64_t>(c - '0');
        if (value > (limit - digit) / 10) return false;
        value = value * 10 + digit;
    }
    *out = value;
    return true;
}

/// Counts in headers index uint32 points; anything larger cannot be a valid hullkit input.
constexpr std::uint64_t kMaxCount = 0xffffffffu;

/// Reserving a header's count up front is only safe when the text could hold that many points
/// (every point needs at least "0 0 0\n"), so a lying header cannot exhaust memory.
std::size_t safe_reserve(std::uint64_t declared, std::size_t text_size) {
    std::uint64_t possible = text_size / 6 + 1;
    return static_cast<std::size_t>(std::min(declared, possible));
}

// ---------------------------------------------------------------------------------------------
// Reader: a cursor plus the error bookkeeping every format shares
// ---------------------------------------------------------------------------------------------

class Reader {
public:
    Reader(const std::string& text, const std::string& source)
        : cursor_(text), source_(source), text_size_(text.size()) {}

    /// Advances to the next line with content; false at the end of the text.
    bool next_line() { return cursor_.next(&line_); }
    std::string_view line() const { return line_; }
    std::size_t line_number() const { return cursor_.line_number(); }
    std::size_t text_size() const { return text_size_; }

    /// Splits the current line; on an empty comma field records the error and returns false.
    bool split(bool allow_commas) {
        std::string what;
        if (split_fields(line_, allow_commas, &fields_, &what)) return true;
        return fail(what);
    }
    const std::vector<std::string_view>& fields() const { return fields_; }

    /// Records "source:LINE: what" for the current line; returns false for `return fail(..)`.
    bool fail(const std::string& what) { return fail_at(line_number(), what); }
    bool fail_at(std::size_t line, const std::string& what) {
        error_ = source_ + ":" + std::to_string(line) + ": " + what;
        return false;
    }
    /// For problems no single line is to blame for (an empty input).
    bool fail_whole(const std::string& what) {
        error_ = source_ + ": " + what;
        return false;
    }
    const std::string& error() const { return error_; }

    /// Parses fields[first..first+count) as numbers into *out (appended).
    bool append_numbers(std::size_t first, std::size_t count, const char* what,
                        std::vector<double>* out) {
        for (std::size_t i = first; i < first + count; ++i) {
            double value;
            if (!parse_double(fields_[i], &value)) {
                return fail(std::string(what) + " " + quoted(fields_[i]) + " is not a number");
            }
            out->push_back(value);
        }
        return true;
    }

    /// The current line must be exactly "x y z"; appends the point to *xyz.
    bool append_point_line(bool allow_commas, std::vector<double>* xyz) {
        if (!split(allow_commas)) return false;
        if (fields_.size() != 3) {
            return fail("expected 3 coordinates, got " + std::to_string(fields_.size()));
        }
        return append_numbers(0, 3, "coordinate", xyz);
    }

private:
    LineCursor cursor_;
    std::string source_;
    std::size_t text_size_;
    std::string_view line_;
    std::vector<std::string_view> fields_;
    std::string error_;
};

// ---------------------------------------------------------------------------------------------
// Format detection
// ---------------------------------------------------------------------------------------------

enum class PointFormat { Xyz, Rbox, Obj, Off };

/// "OFF" and its variants (COFF, NOFF, 4OFF, STOFF, ...), so that a variant is reported as
/// unsupported instead of being misread as plain points.
bool is_off_keyword(std::string_view field) {
    return field.size() >= 3 && field.substr(field.size() - 3) == "OFF";
}

bool is_obj_keyword(std::string_view field) {
    static const char* const kKeywords[] = {
        "v",    "vn",     "vt",   "vp",  "f",    "l",    "p",     "o",     "g",
        "s",    "mg",     "usemtl", "mtllib", "cstype", "deg", "bmat", "step", "curv",
        "curv2", "surf",  "parm", "trim", "hole", "scrv", "sp",    "end",   "con",
        "bevel", "c_interp", "d_interp", "lod", "usemap", "maplib", "shadow_obj",
        "trace_obj", "ctech", "stech"};
    for (const char* keyword : kKeywords) {
        if (field == keyword) return true;
    }
    return false;
}

/// qhull's header line: the dimension alone, or followed by a comment such as "rbox 1000 s D3".
/// A line of numbers ("1 2 3") is a point, not a header.
bool is_rbox_header(const std::vector<std::string_view>& fields) {
    std::uint64_t dimension;
    if (fields.empty() || !parse_count(fields[0], kMaxCount, &dimension)) return false;
    double ignored;
    return fields.size() == 1 || !parse_double(fields[1], &ignored);
}

PointFormat detect_format(const std::vector<std::string_view>& first_fields) {
    if (is_off_keyword(first_fields[0])) return PointFormat::Off;
    if (is_obj_keyword(first_fields[0])) return PointFormat::Obj;
    if (is_rbox_header(first_fields)) return PointFormat::Rbox;
    return PointFormat::Xyz;
}

// ---------------------------------------------------------------------------------------------
// The point formats. Each starts with the reader on the first content line, split without
// commas.
// ---------------------------------------------------------------------------------------------

bool read_xyz(Reader& reader, std::vector<double>* xyz) {
    // No header count to go by: a typical "x y z" line takes ~20 bytes per coordinate.
    xyz->reserve(reader.text_size() / 20);
    do {
        if (!reader.append_point_line(/*allow_commas=*/true, xyz)) return false;
    } while (reader.next_line());
    return true;
}

bool read_rbox(Reader& reader, std::vector<double>* xyz) {
    std::uint64_t dimension = 0;
    parse_count(reader.fields()[0], kMaxCount, &dimension);  // checked by is_rbox_header
    if (dimension != 3) {
        return reader.fail("dimension is " + std::to_string(dimension) +
                           ", expected 3 (hullkit reads 3D points)");
    }
    if (!reader.next_line()) {
        return reader.fail("file ends after the dimension line; expected the point count");
    }
    if (!reader.split(false)) return false;
    std::uint64_t count = 0;
    if (reader.fields().size() != 1 || !parse_count(reader.fields()[0], kMaxCount, &count)) {
        return reader.fail("expected the point count (one non-negative integer), got " +
                           quoted(reader.line()));
    }
    const std::size_t count_line = reader.line_number();
    xyz->reserve(safe_reserve(count, reader.text_size()) * 3);
    std::uint64_t found = 0;
    while (reader.next_line()) {
        if (found == count) {
            return reader.fail("more points than the " + std::to_string(count) +
                               " declared on line " + std::to_string(count_line));
        }
        if (!reader.append_point_line(false, xyz)) return false;
        ++found;
    }
    if (found != count) {
        return reader.fail_at(count_line, "header declares " + std::to_string(count) +
                                              " points but the file has " +
                                              std::to_string(found));
    }
    return true;
}

bool read_obj(Reader& reader, std::vector<double>* xyz) {
    do {
        if (!reader.split(false)) return false;
        const auto& fields = reader.fields();
        std::string_view keyword = fields[0];
        if (keyword == "v") {
            // x y z, x y z w (rational weight), or x y z r g b (a widespread colour extension);
            // only x y z is the point, the rest is still checked to be numeric.
            std::size_t n = fields.size() - 1;
            if (n != 3 && n != 4 && n != 6) {
                return reader.fail("expected \"v x y z [w]\", got " + std::to_string(n) +
                                   (n == 1 ? " number" : " numbers"));
            }
            if (!reader.append_numbers(1, 3, "coordinate", xyz)) return false;
            std::vector<double> extra;
            if (!reader.append_numbers(4, n - 3, "vertex value", &extra)) return false;
        } else if (!std::isalpha(static_cast<unsigned char>(keyword[0]))) {
            // A bare "1 2 3" in an OBJ file is most likely a point missing its "v": say so
            // rather than drop it.
            return reader.fail("line does not start with an OBJ keyword (found " +
                               quoted(keyword) + ")");
        }
        // Every other record (faces, normals, groups, materials, ...) carries no points.
    } while (reader.next_line());
    return true;
}

struct OffHeader {
    std::uint64_t vertex_count = 0;
    std::uint64_t face_count = 0;
    std::size_t counts_line = 0;
};

/// Reads "OFF" and "nv nf ne" (on the same line or the next one); leaves the reader on the
/// counts line.
bool read_off_header(Reader& reader, OffHeader* header) {
    if (!reader.split(false)) return false;
    std::string_view keyword = reader.fields()[0];
    if (keyword != "OFF") {
        if (is_off_keyword(keyword)) {
            return reader.fail("unsupported OFF variant " + quoted(keyword) +
                               " (only plain OFF is read)");
        }
        return reader.fail("not an OFF file: expected \"OFF\", got " + quoted(keyword));
    }
    std::vector<std::string_view> counts(reader.fields().begin() + 1, reader.fields().end());
    if (counts.empty()) {
        if (!reader.next_line()) {
            return reader.fail("file ends after \"OFF\"; expected \"vertices faces edges\"");
        }
        if (!reader.split(false)) return false;
        counts = reader.fields();
    }
    if (counts.size() != 3) {
        return reader.fail("expected the counts \"vertices faces edges\", got " +
                           std::to_string(counts.size()) + " values");
    }
    const char* names[] = {"vertex", "face", "edge"};
    std::uint64_t values[3];
    for (int i = 0; i < 3; ++i) {
        if (!parse_count(counts[i], kMaxCount, &values[i])) {
            return reader.fail(std::string(names[i]) + " count " + quoted(counts[i]) +
                               " is not a non-negative integer");
        }
    }
    header->vertex_count = values[0];
    header->face_count = values[1];
    header->counts_line = reader.line_number();
    return true;
}

/// Reads the header's vertex lines into *xyz.
bool read_off_vertices(Reader& reader, const OffHeader& header, std::vector<double>* xyz) {
    xyz->reserve(safe_reserve(header.vertex_count, reader.text_size()) * 3);
    for (std::uint64_t i = 0; i < header.vertex_count; ++i) {
        if (!reader.next_line()) {
            return reader.fail_at(header.counts_line,
                                  "header declares " + std::to_string(header.vertex_count) +
                                      " vertices but the file has " + std::to_string(i));
        }
        if (!reader.append_point_line(false, xyz)) return false;
    }
    return true;
}

/// The current line is a face "n i0 ... i(n-1) [colour...]"; appends its fan triangulation.
bool append_off_face(Reader& reader, std::uint64_t vertex_count,
                     std::vector<std::uint32_t>* triangles) {
    if (!reader.split(false)) return false;
    const auto& fields = reader.fields();
    std::uint64_t n = 0;
    if (!parse_count(fields[0], kMaxCount, &n)) {
        return reader.fail("face vertex count " + quoted(fields[0]) +
                           " is not a non-negative integer");
    }
    if (n < 3) return reader.fail("face has " + std::to_string(n) + " vertices, need at least 3");
    if (fields.size() - 1 < n) {
        return reader.fail("face declares " + std::to_string(n) + " vertices but lists " +
                           std::to_string(fields.size() - 1));
    }
    std::vector<std::uint32_t> corners;
    corners.reserve(static_cast<std::size_t>(n));
    for (std::size_t i = 1; i <= n; ++i) {
        std::uint64_t index = 0;
        if (!parse_count(fields[i], kMaxCount, &index)) {
            return reader.fail("vertex index " + quoted(fields[i]) +
                               " is not a non-negative integer");
        }
        if (index >= vertex_count) {
            return reader.fail("vertex index " + std::to_string(index) +
                               " is out of range (the file has " + std::to_string(vertex_count) +
                               " vertices)");
        }
        corners.push_back(static_cast<std::uint32_t>(index));
    }
    std::vector<double> colour;  // optional per-face colour: checked, then ignored
    if (!reader.append_numbers(static_cast<std::size_t>(n) + 1,
                               fields.size() - 1 - static_cast<std::size_t>(n), "face colour value",
                               &colour)) {
        return false;
    }
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
        triangles->insert(triangles->end(), {corners[0], corners[i], corners[i + 1]});
    }
    return true;
}

bool read_off_faces(Reader& reader, const OffHeader& header,
                    std::vector<std::uint32_t>* triangles) {
    for (std::uint64_t i = 0; i < header.face_count; ++i) {
        if (!reader.next_line()) {
            return reader.fail_at(header.counts_line,
                                  "header declares " + std::to_string(header.face_count) +
                                      " faces but the file has " + std::to_string(i));
        }
        if (!append_off_face(reader, header.vertex_count, triangles)) return false;
    }
    if (reader.next_line()) {
        return reader.fail("unexpected content after the last of the " +
                           std::to_string(header.face_count) + " faces");
    }
    return true;
}

// ---------------------------------------------------------------------------------------------
// Writers
// ---------------------------------------------------------------------------------------------

void append_uint(std::string& out, std::uint64_t value) {
    char buffer[24];
    int n = std::snprintf(buffer, sizeof buffer, "%llu", static_cast<unsigned long long>(value));
    out.append(buffer, static_cast<std::size_t>(n));
}

void append_double(std::string& out, double value) {
    char buffer[40];
    int n = std::snprintf(buffer, sizeof buffer, "%.17g", value);
    out.append(buffer, static_cast<std::size_t>(n));
}

void append_json_number(std::string& out, double value) {
    if (std::isfinite(value)) {
        append_double(out, value);
    } else {
        out += "null";
    }
}

void append_xyz(std::string& out, const double* p, const char* separator) {
    append_double(out, p[0]);
    out += separator;
    append_double(out, p[1]);
    out += separator;
    append_double(out, p[2]);
}

/// For each triangle corner, its position in hull.vertices: OFF and OBJ list only the hull's
/// vertices, so faces must be re-indexed. hull.vertices is ascending for a polytope but in
/// polygon order for a planar hull, so the lookup does not rely on any order.
/// Throws if the hull does not fit the points.
/// The faces to write: the merged polygons when the hull has them (merge_coplanar), else its
/// triangles as polygons of three corners.
struct FaceList {
    const std::vector<std::uint32_t>& corners;
    std::vector<std::uint32_t> offsets;

    explicit FaceList(const Hull& hull)
        : corners(hull.face_offsets.empty() ? hull.triangles : hull.face_vertices), offsets(hull.face_offsets) {
        if (offsets.empty()) {
            for (std::size_t i = 0; i <= hull.triangles.size(); i += 3) offsets.push_back(static_cast<std::uint32_t>(i));
        }
    }
    std::size_t size() const { return offsets.size() - 1; }
};

std::vector<std::uint32_t> local_corner_indices(PointSpan points, const Hull& hull,
                                                const std::vector<std::uint32_t>& corners) {
    // (input index, position in hull.vertices), sorted by input index for binary search.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> position;
    position.reserve(hull.vertices.size());
    for (std::size_t i = 0; i < hull.vertices.size(); ++i) {
        if (hull.vertices[i] >= points.count) {
            throw std::invalid_argument("hull vertex " + std::to_string(hull.vertices[i]) +
                                        " is out of range for " + std::to_string(points.count) +
                                        " points");
        }
        position.emplace_back(hull.vertices[i], static_cast<std::uint32_t>(i));
    }
    std::sort(position.begin(), position.end());
    for (std::size_t i = 1; i < position.size(); ++i) {
        if (position[i].first == position[i - 1].first) {
            throw std::invalid_argument("hull vertex " + std::to_string(position[i].first) +
                                        " is listed twice");
        }
    }
    if (hull.triangles.size() % 3 != 0) {
        throw std::invalid_argument("hull triangle index count is not a multiple of 3");
    }
    std::vector<std::uint32_t> local;
    local.reserve(corners.size());
    for (std::uint32_t corner : corners) {
        auto it = std::lower_bound(position.begin(), position.end(),
                                   std::make_pair(corner, std::uint32_t{0}));
        if (it == position.end() || it->first != corner) {
            throw std::invalid_argument("triangle corner " + std::to_string(corner) +
                                        " is not a hull vertex");
        }
        local.push_back(it->second);
    }
    return local;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Public API
// ---------------------------------------------------------------------------------------------

PointsResult parse_points(const std::string& text, const std::string& source) {
    PointsResult result;
    Reader reader(text, source);
    bool ok;
    if (!reader.next_line()) {
        ok = reader.fail_whole("no points found (the input is empty)");
    } else if (!reader.split(false)) {
        ok = false;
    } else {
        switch (detect_format(reader.fields())) {
            case PointFormat::Off: {
                OffHeader header;
                ok = read_off_header(reader, &header) &&
                     read_off_vertices(reader, header, &result.xyz);
                break;
            }
            case PointFormat::Obj: ok = read_obj(reader, &result.xyz); break;
            case PointFormat::Rbox: ok = read_rbox(reader, &result.xyz); break;
            case PointFormat::Xyz: ok = read_xyz(reader, &result.xyz); break;
        }
        if (ok && result.xyz.empty()) ok = reader.fail_whole("no points found");
    }
    if (!ok) {
        result.xyz = {};
        result.error = reader.error();
    } else {
        result.xyz.shrink_to_fit();
    }
    return result;
}

MeshResult read_off_mesh(const std::string& text, const std::string& source) {
    MeshResult result;
    Reader reader(text, source);
    OffHeader header;
    bool ok = reader.next_line() ? read_off_header(reader, &header) &&
                                       read_off_vertices(reader, header, &result.xyz) &&
                                       read_off_faces(reader, header, &result.triangles)
                                 : reader.fail_whole("empty input, expected an OFF file");
    if (!ok) {
        result = MeshResult{};
        result.error = reader.error();
    }
    return result;
}

bool read_file(const std::string& path, std::string* out, std::string* error) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) {
        *error = path + ": cannot open: " + std::strerror(errno);
        return false;
    }
    out->clear();
    char buffer[1 << 16];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) out->append(buffer, n);
    bool failed = std::ferror(file) != 0;
    int saved_errno = errno;
    std::fclose(file);
    if (failed) {
        *error = path + ": cannot read: " + std::strerror(saved_errno);
        out->clear();
        return false;
    }
    return true;
}

const char* output_format_name(OutputFormat format) {
    switch (format) {
        case OutputFormat::Off: return "off";
        case OutputFormat::Obj: return "obj";
        case OutputFormat::Json: return "json";
    }
    return "?";
}

bool parse_output_format(const std::string& name, OutputFormat* out) {
    for (OutputFormat format : {OutputFormat::Off, OutputFormat::Obj, OutputFormat::Json}) {
        if (name == output_format_name(format)) {
            *out = format;
            return true;
        }
    }
    return false;
}

bool output_format_from_path(const std::string& path, OutputFormat* out) {
    std::size_t dot = path.find_last_of("./");
    if (dot == std::string::npos || path[dot] != '.') return false;
    std::string extension = path.substr(dot + 1);
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return parse_output_format(extension, out);
}

/// Appends each face as `prefix` then its corners (as local indices + `base`), one face a line.
void append_faces(std::string& out, const FaceList& faces, const std::vector<std::uint32_t>& local,
                  unsigned long long base, bool with_count) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const std::uint32_t begin = faces.offsets[f], end = faces.offsets[f + 1];
        if (with_count) {
            append_uint(out, end - begin);
        } else {
            out += 'f';
        }
        for (std::uint32_t k = begin; k < end; ++k) {
            out += ' ';
            append_uint(out, local[k] + base);
        }
        out += '\n';
    }
}

std::string write_off(PointSpan points, const Hull& hull) {
    const FaceList faces(hull);
    std::vector<std::uint32_t> local = local_corner_indices(points, hull, faces.corners);
    std::string out = "OFF\n";
    out.reserve(64 * hull.vertices.size() + 24 * faces.size() + 32);
    append_uint(out, hull.vertices.size());
    out += ' ';
    append_uint(out, faces.size());
    out += " 0\n";
    for (std::uint32_t v : hull.vertices) {
        append_xyz(out, points[v], " ");
        out += '\n';
    }
    append_faces(out, faces, local, 0, true);
    return out;
}

std::string write_obj(PointSpan points, const Hull& hull) {
    const FaceList faces(hull);
    std::vector<std::uint32_t> local = local_corner_indices(points, hull, faces.corners);
    std::string out;
    out.reserve(64 * hull.vertices.size() + 24 * faces.size());
    for (std::uint32_t v : hull.vertices) {
        out += "v ";
        append_xyz(out, points[v], " ");
        out += '\n';
    }
    append_faces(out, faces, local, 1, false);  // OBJ indices are 1-based
    return out;
}

std::string write_json(PointSpan points, const Hull& hull) {
    local_corner_indices(points, hull, hull.triangles);  // only to validate: JSON keeps input indices
    std::string out;
    out.reserve(80 * hull.vertices.size() + 32 * hull.face_count() + 64);
    out += "{\"vertices\":[";
    for (std::size_t i = 0; i < hull.vertices.size(); ++i) {
        if (i) out += ',';
        append_uint(out, hull.vertices[i]);
    }
    out += "],\"triangles\":[";
    for (std::size_t i = 0; i < hull.triangles.size(); i += 3) {
        if (i) out += ',';
        out += '[';
        append_uint(out, hull.triangles[i]);
        out += ',';
        append_uint(out, hull.triangles[i + 1]);
        out += ',';
        append_uint(out, hull.triangles[i + 2]);
        out += ']';
    }
    out += "],\"points\":[";
    for (std::size_t i = 0; i < hull.vertices.size(); ++i) {
        if (i) out += ',';
        const double* p = points[hull.vertices[i]];
        out += '[';
        append_json_number(out, p[0]);
        out += ',';
        append_json_number(out, p[1]);
        out += ',';
        append_json_number(out, p[2]);
        out += ']';
    }
    out += ']';
    if (!hull.face_offsets.empty()) {  // merge_coplanar: the faces as polygons of input indices
        out += ",\"faces\":[";
        for (std::size_t f = 0; f + 1 < hull.face_offsets.size(); ++f) {
            if (f) out += ',';
            out += '[';
            for (std::uint32_t k = hull.face_offsets[f]; k < hull.face_offsets[f + 1]; ++k) {
                if (k > hull.face_offsets[f]) out += ',';
                append_uint(out, hull.face_vertices[k]);
            }
            out += ']';
        }
        out += ']';
    }
    out += ",\"volume\":";
    append_json_number(out, hull.volume);
    out += ",\"area\":";
    append_json_number(out, hull.area);
    out += ",\"dimension\":";
    out += std::to_string(hull.dimension);
    out += "}\n";
    return out;
}

std::string write_hull(OutputFormat format, PointSpan points, const Hull& hull) {
    switch (format) {
        case OutputFormat::Off: return write_off(points, hull);
        case OutputFormat::Obj: return write_obj(points, hull);
        case OutputFormat::Json: return write_json(points, hull);
    }
    throw std::invalid_argument("unknown output format");
}

std::string format_double(double value) {
    std::string out;
    append_double(out, value);
    return out;
}

std::string format_json_number(double value) {
    std::string out;
    append_json_number(out, value);
    return out;
}

std::vector<std::int64_t> match_points(PointSpan points, PointSpan wanted) {
    std::unordered_map<detail::PointKey, std::int64_t, detail::PointKeyHash> index;  // coordinates -> input index
    index.reserve(2 * wanted.count + 1);
    for (std::size_t k = 0; k < wanted.count; ++k) index.emplace(detail::key_of(wanted[k]), -1);
    for (std::size_t i = 0; i < points.count; ++i) {
        auto it = index.find(detail::key_of(points[i]));
        if (it != index.end() && it->second < 0) it->second = static_cast<std::int64_t>(i);
    }
    std::vector<std::int64_t> found(wanted.count);
    for (std::size_t k = 0; k < wanted.count; ++k) found[k] = index.at(detail::key_of(wanted[k]));
    return found;
}

}  // namespace hullkit
