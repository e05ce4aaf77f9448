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
#include <memory>
#include <new>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <system_error>
#include <unordered_map>

// fast_float (Debian libfast-float-dev, header-only): the from_chars algorithm, inlined here;
// ~3x fewer instructions per number than libstdc++'s std::from_chars. Without it the reader
// falls back to std::from_chars / strtod with the same results.
#if __has_include(<fast_float/fast_float.h>)
#include <fast_float/fast_float.h>
#define HULLKIT_HAVE_FAST_FLOAT 1
#endif

#include "hullkit/point_reader.hpp"
#include "io/mesh_read_internal.hpp"
#include "point_key.hpp"

namespace hullkit {
namespace {

// ---------------------------------------------------------------------------------------------
// Lines and fields
// ---------------------------------------------------------------------------------------------

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/// Walks a text line by line, handing out only lines with content: the part before any '#'
/// that is not all whitespace. Line numbers count every line, so messages match an editor's.
/// The text is one piece of memory: a whole string, or a batch of whole lines that PointReader
/// read from a file.
class LineCursor {
public:
    explicit LineCursor(std::string_view text)
        : begin_(text.data()), pos_(text.data()), end_(text.data() + text.size()), line_begin_(pos_) {}

    /// Advances to the next line with content; false at the end of the text.
    bool next(std::string_view* content) {
        while (pos_ < end_) {
            const char* newline = static_cast<const char*>(std::memchr(pos_, '\n', end_ - pos_));
            const char* begin = pos_;
            const char* stop = newline ? newline : end_;
            line_begin_ = pos_;
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
    /// Offsets into the text: where the line last read starts, and where the next one starts.
    std::size_t line_start() const { return static_cast<std::size_t>(line_begin_ - begin_); }
    std::size_t offset() const { return static_cast<std::size_t>(pos_ - begin_); }

private:
    const char* begin_;
    const char* pos_;
    const char* end_;
    const char* line_begin_;
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
/// Parses the number at the start of [begin, end) in the syntax of parse_double below; returns
/// where it stops (the caller checks what follows), or nullptr if no number starts there.
const char* parse_double_prefix(const char* begin, const char* end, double* out) {
    if (begin < end && *begin == '+') {  // strtod allows a '+', from_chars does not
        ++begin;
        if (begin < end && (*begin == '+' || *begin == '-')) return nullptr;
    }
    if (begin == end) return nullptr;
    double value = 0.0;
#if defined(HULLKIT_HAVE_FAST_FLOAT)
    auto [stop, status] = fast_float::from_chars(begin, end, value);
#elif defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
    // from_chars is ~5x faster than strtod and ignores the C locale's decimal separator.
    auto [stop, status] = std::from_chars(begin, end, value);
#else
    // The text is NUL-terminated or the field ends at whitespace, ',', '#', '\n' (none of which
    // continues a number); strtod is given a copy to be safe with a chunk buffer.
    const std::string copy(begin, end);
    if (copy.find_first_of("xX") != std::string::npos) return nullptr;
    char* copy_stop = nullptr;
    value = std::strtod(copy.c_str(), &copy_stop);
    const char* stop = begin + (copy_stop - copy.c_str());
    const std::errc status = stop == begin ? std::errc::invalid_argument : std::errc();
#endif
    if (status == std::errc::result_out_of_range) {
        value = std::strtod(std::string(begin, stop).c_str(), nullptr);  // rare: strtod picks +-inf / +-0
    } else if (status != std::errc()) {
        return nullptr;
    }
    *out = value;
    return stop;
}

/// A number in strtod's decimal syntax ("-1.5e3", ".5", "+2", "inf", "nan"); the whole field
/// must be the number. Hexadecimal floats are not part of the syntax. Out-of-range values
/// become +-inf or +-0 as with strtod: not a syntax error, the hull reports non-finite points.
bool parse_double(std::string_view field, double* out) {
    const char* end = field.data() + field.size();
    return parse_double_prefix(field.data(), end, out) == end;
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
/// `text_size` is kUnknownSize for a stream (a pipe); then at most 2^16 points are reserved and
/// the array grows beyond that as needed.
constexpr std::size_t kUnknownSize = ~std::size_t{0};

std::size_t safe_reserve(std::uint64_t declared, std::size_t text_size) {
    std::uint64_t possible = text_size == kUnknownSize ? std::uint64_t{1} << 16 : text_size / 6 + 1;
    return static_cast<std::size_t>(std::min(declared, possible));
}

// ---------------------------------------------------------------------------------------------
// Reader: a cursor plus the error bookkeeping every format shares
// ---------------------------------------------------------------------------------------------

class Reader {
public:
    /// `whole`: the text is all of the input. Otherwise it is the start of a longer input, and
    /// running out of it (ran_out()) means that more must be read, not that the input ends.
    Reader(std::string_view text, const std::string& source, bool whole = true)
        : cursor_(text), source_(source), text_size_(text.size()), whole_(whole) {}

    /// Advances to the next line with content; false at the end of the text.
    bool next_line() {
        if (cursor_.next(&line_)) return true;
        if (!whole_) ran_out_ = true;
        return false;
    }
    bool ran_out() const { return ran_out_; }
    std::string_view line() const { return line_; }
    std::size_t line_number() const { return cursor_.line_number(); }
    std::size_t text_size() const { return text_size_; }
    const LineCursor& cursor() const { return cursor_; }

    /// Splits the current line; on an empty comma field records the error and returns false.
    bool split(bool allow_commas) {
        std::string what;
        if (split_fields(line_, allow_commas, &fields_, &what)) return true;
        return fail(what);
    }
    const std::vector<std::string_view>& fields() const { return fields_; }

    /// Records what is wrong with the current line; returns false for `return fail(..)`.
    bool fail(const std::string& what) { return fail_at(line_number(), what); }
    bool fail_at(std::size_t line, const std::string& what) {
        error_line_ = line;
        error_what_ = what;
        return false;
    }
    /// For problems no single line is to blame for (an empty input).
    bool fail_whole(const std::string& what) { return fail_at(0, what); }
    /// "source:LINE: what", or "source: what" for the whole input.
    std::string error() const {
        return error_line_ ? io::at_line(source_, error_line_, error_what_) : source_ + ": " + error_what_;
    }
    /// The failing line (0: the whole input) and what is wrong, for a caller that numbers the
    /// lines itself (a piece of a longer text).
    std::size_t error_line() const { return error_line_; }
    std::string& error_what() { return error_what_; }

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
        // Fast path for the common line, three numbers separated by whitespace, without
        // splitting into fields; anything else (commas, a wrong count, a bad number) takes the
        // general path below, which gives the error messages.
        double point[3];
        const char* p = line_.data();
        const char* const end = p + line_.size();
        int k = 0;
        for (; k < 3; ++k) {
            while (p < end && is_space(*p)) ++p;
            p = parse_double_prefix(p, end, &point[k]);
            if (!p || (p < end && !is_space(*p))) break;  // a bad number, or "1,2": the general path
        }
        if (k == 3 && p == end) {  // the line is trimmed: nothing may follow the third number
            // push_back inlines; a range insert of 3 doubles is a call and a memmove per point.
            xyz->push_back(point[0]);
            xyz->push_back(point[1]);
            xyz->push_back(point[2]);
            return true;
        }
        if (!split(allow_commas)) return false;
        if (fields_.size() != 3) {
            return fail("expected 3 coordinates, got " + std::to_string(fields_.size()));
        }
        return append_numbers(0, 3, "coordinate", xyz);
    }

private:
    LineCursor cursor_;
    const std::string& source_;
    std::size_t text_size_;
    bool whole_;
    bool ran_out_ = false;
    std::string_view line_;
    std::vector<std::string_view> fields_;
    std::size_t error_line_ = 0;
    std::string error_what_;
};

// ---------------------------------------------------------------------------------------------
// Format detection
// ---------------------------------------------------------------------------------------------

using io::PointTextFormat;

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

PointTextFormat detect_format(const std::vector<std::string_view>& first_fields) {
    if (is_off_keyword(first_fields[0])) return PointTextFormat::Off;
    if (is_obj_keyword(first_fields[0])) return PointTextFormat::Obj;
    if (is_rbox_header(first_fields)) return PointTextFormat::Rbox;
    return PointTextFormat::Xyz;
}

// ---------------------------------------------------------------------------------------------
// The point formats: a header read once (rbox, OFF), then point lines that may be parsed in
// pieces (parse_point_piece). Header readers start with the reader on the first content line,
// split without commas.
// ---------------------------------------------------------------------------------------------

/// "header declares N points but the file has M", for counts that fall short at the end.
std::string count_mismatch(std::uint64_t declared, const char* what, std::uint64_t found) {
    return "header declares " + std::to_string(declared) + " " + what + " but the file has " + std::to_string(found);
}

/// qhull/rbox: the dimension (must be 3) on the current line, the point count on the next.
bool read_rbox_header(Reader& reader, io::PointTextHeader* header) {
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
    header->counted = true;
    header->declared = count;
    header->count_line = reader.line_number();
    return true;
}

/// One OBJ record: "v x y z ..." appends a point; other OBJ records are skipped, and records that
/// are not OBJ's (FCL's "648 1292" count line, a misspelt keyword, a point missing its "v") are
/// skipped too but tallied in *skipped, for the result's warnings.
bool read_obj_line(Reader& reader, std::vector<double>* xyz, io::SkippedRecords* skipped) {
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
        return reader.append_numbers(4, n - 3, "vertex value", &extra);
    }
    // Faces and every other OBJ record carry no points.
    if (keyword != "f" && !io::is_known_obj_record(keyword)) skipped->add(keyword, reader.line_number());
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
            return reader.fail_at(header.counts_line, count_mismatch(header.vertex_count, "vertices", i));
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
            return reader.fail_at(header.counts_line, count_mismatch(header.face_count, "faces", i));
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

/// Where writers put their text: a string, or a file written in ~1 MiB pieces through one
/// reused buffer (the text of a 1e6-point hull is ~100 MB: never held whole). Numbers are
/// formatted with std::to_chars: the shortest text that reads back to the same double.
class TextOut {
public:
    TextOut() = default;
    explicit TextOut(std::FILE* file) : file_(file) { buffer_.reserve(kFlushAt + 4096); }

    void put(char c) { buffer_ += c; }
    void put(std::string_view text) { buffer_.append(text.data(), text.size()); }
    void uint(std::uint64_t value) {
        char digits[24];
        const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
        buffer_.append(digits, static_cast<std::size_t>(end - digits));
    }
    /// Shortest round-trip text ("0.1", "1", "1e+22", "-0", "inf", "nan").
    void number(double value) {
        char digits[32];
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
        const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
        buffer_.append(digits, static_cast<std::size_t>(end - digits));
#else
        // A C++ library without floating-point to_chars (Emscripten 3.1's libc++): the fewest of
        // 15, 16, 17 significant digits that read back to the same double.
        int n = 0;
        for (int precision = 15; precision <= 17; ++precision) {
            n = std::snprintf(digits, sizeof digits, "%.*g", precision, value);
            if (precision == 17 || std::strtod(digits, nullptr) == value || value != value) break;
        }
        buffer_.append(digits, static_cast<std::size_t>(n));
#endif
    }
    /// JSON has no NaN or infinity: those are written as null.
    void json_number(double value) {
        if (std::isfinite(value)) {
            number(value);
        } else {
            put("null");
        }
    }
    void xyz(const double* p) {
        number(p[0]);
        put(' ');
        number(p[1]);
        put(' ');
        number(p[2]);
    }
    /// Called after each record: hands a full buffer to the file.
    void record_done() {
        if (file_ && buffer_.size() >= kFlushAt) flush();
    }
    /// Writes out what is buffered (file mode); false once a write failed (errno kept).
    bool flush() {
        if (file_ && !buffer_.empty()) {
            if (!failed_ && std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
                failed_ = true;
                errno_ = errno;
            }
            buffer_.clear();
        }
        return !failed_;
    }
    int error_number() const { return errno_; }
    std::string& text() { return buffer_; }
    void reserve(std::size_t bytes) {
        if (!file_) buffer_.reserve(bytes);
    }

private:
    static constexpr std::size_t kFlushAt = std::size_t{1} << 20;
    std::FILE* file_ = nullptr;
    std::string buffer_;
    bool failed_ = false;
    int errno_ = 0;
};

/// The faces to write: the merged polygons when the hull has them (merge_coplanar), else its
/// triangles as polygons of three corners (without building an offset table for them).
struct FaceList {
    const std::vector<std::uint32_t>& corners;
    const std::vector<std::uint32_t>* offsets;  // null: triangles

    explicit FaceList(const Hull& hull)
        : corners(hull.face_offsets.empty() ? hull.triangles : hull.face_vertices),
          offsets(hull.face_offsets.empty() ? nullptr : &hull.face_offsets) {}
    std::size_t size() const { return offsets ? offsets->size() - 1 : corners.size() / 3; }
    std::size_t begin(std::size_t f) const { return offsets ? (*offsets)[f] : 3 * f; }
    std::size_t end(std::size_t f) const { return offsets ? (*offsets)[f + 1] : 3 * f + 3; }
};

/// For each input point, its position in hull.vertices: OFF and OBJ list only the hull's
/// vertices, so faces must be re-indexed. hull.vertices is ascending for a polytope but in
/// polygon order for a planar hull, so the lookup does not rely on any order.
class VertexPositions {
public:
    /// Throws std::invalid_argument if a vertex is out of range or listed twice.
    VertexPositions(PointSpan points, const Hull& hull)
        : count_(points.count),
          // calloc: the zeroed pages of a large table are mapped lazily, so only the pages that
          // hold a hull vertex's entry are ever touched (a cube's few hundred vertices among
          // 1e6 points touch a few pages, not 4 MB).
          position_(static_cast<std::uint32_t*>(std::calloc(points.count ? points.count : 1, sizeof(std::uint32_t)))) {
        if (!position_) throw std::bad_alloc();
        for (std::size_t i = 0; i < hull.vertices.size(); ++i) {
            const std::uint32_t v = hull.vertices[i];
            if (v >= points.count) {
                throw std::invalid_argument("hull vertex " + std::to_string(v) + " is out of range for " +
                                            std::to_string(points.count) + " points");
            }
            if (position_.get()[v] != 0) {
                throw std::invalid_argument("hull vertex " + std::to_string(v) + " is listed twice");
            }
            position_.get()[v] = static_cast<std::uint32_t>(i) + 1;  // 0: not a vertex
        }
        if (hull.triangles.size() % 3 != 0) {
            throw std::invalid_argument("hull triangle index count is not a multiple of 3");
        }
    }

    /// The position of input point `corner` in hull.vertices; throws if it is not listed there.
    std::uint32_t of(std::uint32_t corner) const {
        const std::uint32_t stored = corner < count_ ? position_.get()[corner] : 0;
        if (stored == 0) {
            throw std::invalid_argument("triangle corner " + std::to_string(corner) + " is not a hull vertex");
        }
        return stored - 1;
    }

private:
    struct Free {
        void operator()(std::uint32_t* p) const { std::free(p); }
    };
    std::size_t count_;
    std::unique_ptr<std::uint32_t, Free> position_;
};

// ---------------------------------------------------------------------------------------------
// Inputs that are not text
// ---------------------------------------------------------------------------------------------

/// Every point of `reader` in one array, as parse_points returns it.
PointsResult read_all_points(PointReader& reader) {
    PointsResult result;
    // Reserve for as many points as the header declares or, without a count, as the text could
    // hold, so the array never grows and copies itself; never more than the text could hold, so
    // a lying header cannot exhaust memory. Only address space: the pages are touched as points
    // arrive.
    const std::uint64_t declared = reader.declared_points();
    const std::size_t size = reader.size() ? static_cast<std::size_t>(reader.size()) : kUnknownSize;
    result.xyz.reserve(3 * safe_reserve(declared ? declared : kMaxCount, size));
    while (reader.append_next(&result.xyz)) {
    }
    if (!reader.error().empty()) {
        result.xyz = {};
        result.error = reader.error();
    } else {
        result.warnings = reader.warnings();
    }
    // No shrink_to_fit: it would copy the whole array; the spare capacity is address space that
    // was never touched.
    return result;
}

/// The options of the readers that take only point text, as parse_points does.
PointReaderOptions text_only(unsigned threads) {
    PointReaderOptions options;
    options.threads = threads;
    options.text_only = true;
    return options;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// For PointReader (io/point_reader.cpp): the point-text header and pieces of point lines
// ---------------------------------------------------------------------------------------------

namespace io {

std::string binary_input_message(std::string_view head, std::uint64_t size, bool size_known, const char* expected) {
    auto starts_with = [&](std::string_view word) {
        return head.size() >= word.size() && head.substr(0, word.size()) == word &&
               (head.size() == word.size() || std::isspace(static_cast<unsigned char>(head[word.size()])));
    };
    const std::string what = std::string("not ") + expected + ": ";
    if (starts_with("ply")) return what + "PLY is not supported by the point reader (read: xyz, rbox, OBJ, OFF)";
    if (starts_with("solid") && head.find("facet") != std::string_view::npos) {
        return what + "ASCII STL is not supported by the point reader (read: xyz, rbox, OBJ, OFF)";
    }
    for (std::size_t i = 0; i < head.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(head[i]);
        const bool text = c >= 0x20 ? c != 0x7f : (c == '\n' || c == '\t' || c == '\r' || c == '\v' || c == '\f');
        if (text) continue;
        // Binary STL: an 80-byte header, a little-endian uint32 triangle count, 50 bytes each.
        if (size_known && has_binary_stl_size(head, size)) {
            return what + "binary STL is not supported by the point reader (read: xyz, rbox, OBJ, OFF)";
        }
        char detail[64];
        std::snprintf(detail, sizeof detail, "binary data (byte 0x%02x at offset %zu)", c, i);
        return what + detail;
    }
    return {};
}

ReadStatus read_point_text_header(std::string_view text, bool whole, const std::string& source,
                                  PointTextHeader* header, std::string* error) {
    Reader reader(text, source, whole);
    bool ok = false;
    if (!reader.next_line()) {
        ok = reader.fail_whole("no points found (the input is empty)");
    } else if (reader.split(false)) {  // cannot fail without commas
        header->format = detect_format(reader.fields());
        // A file named .obj is OBJ whatever its first line (FCL's meshes start with "648 1292").
        if (header->format != PointTextFormat::Off && io::extension_of(source) == "obj") {
            header->format = PointTextFormat::Obj;
        }
        switch (header->format) {
            case PointTextFormat::Xyz:
            case PointTextFormat::Obj:  // no header: the first content line is the first point line
                header->body_offset = reader.cursor().line_start();
                header->body_line = reader.line_number() - 1;
                ok = true;
                break;
            case PointTextFormat::Rbox:
                ok = read_rbox_header(reader, header);
                break;
            case PointTextFormat::Off: {
                OffHeader off;
                if ((ok = read_off_header(reader, &off))) {
                    header->counted = true;
                    header->declared = off.vertex_count;
                    header->count_line = off.counts_line;
                }
                break;
            }
        }
        if (ok && header->counted) {
            header->body_offset = reader.cursor().offset();
            header->body_line = reader.line_number();
        }
    }
    if (ok) return ReadStatus::Done;
    if (reader.ran_out()) return ReadStatus::NeedMore;  // every failure after that is for want of text
    *error = reader.error();
    return ReadStatus::Failed;
}

void parse_point_piece(std::string_view text, const PointTextHeader& header, std::uint64_t limit,
                       std::vector<double>* xyz, PointPiece* piece) {
    const std::string no_source;  // the caller numbers the lines and writes the message
    Reader reader(text, no_source);
    const std::size_t start = xyz->size();
    const PointTextFormat format = header.format;
    if (!header.counted) limit = ~std::uint64_t{0};
    std::uint64_t found = 0;
    bool ok = true;
    for (;;) {
        if (found == limit && format == PointTextFormat::Off) {
            piece->at_limit = true;  // every vertex read; what follows are faces, which points ignore
            break;
        }
        if (!reader.next_line()) break;
        if (format == PointTextFormat::Obj) {
            if (!(ok = read_obj_line(reader, xyz, &piece->skipped))) break;
            continue;
        }
        if (found == limit) {  // rbox: a point line after the last one declared
            ok = reader.fail("more points than the " + std::to_string(header.declared) + " declared on line " +
                             std::to_string(header.count_line));
            break;
        }
        if (!(ok = reader.append_point_line(/*allow_commas=*/format == PointTextFormat::Xyz, xyz))) break;
        ++found;
    }
    piece->points = (xyz->size() - start) / 3;
    piece->lines = reader.line_number();
    if (!ok) {
        piece->error_line = reader.error_line();
        piece->error_what = std::move(reader.error_what());
    }
}

std::string missing_points_message(const PointTextHeader& header, std::uint64_t found) {
    return count_mismatch(header.declared, header.format == PointTextFormat::Off ? "vertices" : "points", found);
}

}  // namespace io

// ---------------------------------------------------------------------------------------------
// Public API
// ---------------------------------------------------------------------------------------------

PointsResult parse_points(const std::string& text, const std::string& source, unsigned threads) {
    PointReader reader(std::string_view(text), source, text_only(threads));
    return read_all_points(reader);
}

PointsResult read_points_file(std::FILE* file, const std::string& source, unsigned threads) {
    PointReader reader(file, source, text_only(threads));
    return read_all_points(reader);
}

PointsResult read_points_file(const std::string& path, unsigned threads) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) {
        PointsResult result;
        result.error = path + ": cannot open: " + std::strerror(errno);
        return result;
    }
    PointsResult result = read_points_file(file, path, threads);
    std::fclose(file);
    return result;
}

MeshResult read_off_mesh(const std::string& text, const std::string& source) {
    MeshResult result;
    Reader reader(text, source);
    OffHeader header;
    std::string binary = io::binary_input_message(std::string_view(text).substr(0, io::kSniffBytes), text.size(),
                                                  /*size_known=*/true, "an OFF file");
    bool ok = !binary.empty() ? reader.fail_whole(binary)
              : reader.next_line() ? read_off_header(reader, &header) &&
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
        case OutputFormat::Xyz: return "xyz";
        case OutputFormat::Glb: return "glb";
    }
    return "?";
}

bool parse_output_format(const std::string& name, OutputFormat* out) {
    for (OutputFormat format : {OutputFormat::Off, OutputFormat::Obj, OutputFormat::Json, OutputFormat::Xyz, OutputFormat::Glb}) {
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

namespace {

/// Appends each face, one a line: "n i j k ..." (OFF, with_count) or "f i j k ..." (OBJ), the
/// corners as positions in hull.vertices plus `base`.
void put_faces(TextOut& out, const FaceList& faces, const VertexPositions& position, unsigned base,
               bool with_count) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const std::size_t begin = faces.begin(f), end = faces.end(f);
        if (with_count) {
            out.uint(end - begin);
        } else {
            out.put('f');
        }
        for (std::size_t k = begin; k < end; ++k) {
            out.put(' ');
            out.uint(std::uint64_t{position.of(faces.corners[k])} + base);
        }
        out.put('\n');
        out.record_done();
    }
}

void put_off(TextOut& out, PointSpan points, const Hull& hull) {
    const FaceList faces(hull);
    const VertexPositions position(points, hull);
    out.reserve(64 * hull.vertices.size() + 24 * faces.size() + 32);
    out.put("OFF\n");
    out.uint(hull.vertices.size());
    out.put(' ');
    out.uint(faces.size());
    out.put(" 0\n");
    for (std::uint32_t v : hull.vertices) {
        out.xyz(points[v]);
        out.put('\n');
        out.record_done();
    }
    put_faces(out, faces, position, 0, true);
}

void put_obj(TextOut& out, PointSpan points, const Hull& hull) {
    const FaceList faces(hull);
    const VertexPositions position(points, hull);
    out.reserve(64 * hull.vertices.size() + 24 * faces.size());
    for (std::uint32_t v : hull.vertices) {
        out.put("v ");
        out.xyz(points[v]);
        out.put('\n');
        out.record_done();
    }
    put_faces(out, faces, position, 1, false);  // OBJ indices are 1-based
}

/// The input index of point v: index[v] when the hull's points are a subset of the input's.
struct InputIndex {
    const std::uint64_t* index;
    std::uint64_t operator()(std::uint32_t v) const { return index ? index[v] : v; }
};

void put_json(TextOut& out, PointSpan points, const Hull& hull, InputIndex id) {
    {  // only to validate: JSON keeps input indices
        const VertexPositions position(points, hull);
        for (std::uint32_t corner : hull.triangles) position.of(corner);
    }
    out.reserve(80 * hull.vertices.size() + 32 * hull.face_count() + 64);
    out.put("{\"vertices\":[");
    for (std::size_t i = 0; i < hull.vertices.size(); ++i) {
        if (i) out.put(',');
        out.uint(id(hull.vertices[i]));
        out.record_done();
    }
    out.put("],\"triangles\":[");
    for (std::size_t i = 0; i < hull.triangles.size(); i += 3) {
        if (i) out.put(',');
        out.put('[');
        out.uint(id(hull.triangles[i]));
        out.put(',');
        out.uint(id(hull.triangles[i + 1]));
        out.put(',');
        out.uint(id(hull.triangles[i + 2]));
        out.put(']');
        out.record_done();
    }
    out.put("],\"points\":[");
    for (std::size_t i = 0; i < hull.vertices.size(); ++i) {
        if (i) out.put(',');
        const double* p = points[hull.vertices[i]];
        out.put('[');
        out.json_number(p[0]);
        out.put(',');
        out.json_number(p[1]);
        out.put(',');
        out.json_number(p[2]);
        out.put(']');
        out.record_done();
    }
    out.put(']');
    if (!hull.face_offsets.empty()) {  // merge_coplanar: the faces as polygons of input indices
        out.put(",\"faces\":[");
        for (std::size_t f = 0; f + 1 < hull.face_offsets.size(); ++f) {
            if (f) out.put(',');
            out.put('[');
            for (std::uint32_t k = hull.face_offsets[f]; k < hull.face_offsets[f + 1]; ++k) {
                if (k > hull.face_offsets[f]) out.put(',');
                out.uint(id(hull.face_vertices[k]));
            }
            out.put(']');
            out.record_done();
        }
        out.put(']');
    }
    out.put(",\"volume\":");
    out.json_number(hull.volume);
    out.put(",\"area\":");
    out.json_number(hull.area);
    out.put(",\"dimension\":");
    out.put(std::to_string(hull.dimension));
    out.put("}\n");
}

/// The hull's vertices alone, "x y z # INDEX" a line, which the point readers read back.
void put_xyz(TextOut& out, PointSpan points, const Hull& hull, InputIndex id) {
    const VertexPositions validate(points, hull);
    out.reserve(80 * hull.vertices.size() + 64);
    out.put("# hull vertices: x y z # index of the point in the input\n");
    for (std::uint32_t v : hull.vertices) {
        out.xyz(points[v]);
        out.put(" # ");
        out.uint(id(v));
        out.put('\n');
        out.record_done();
    }
}

/// Appends `value` as 4 little-endian bytes.
void put_u32(std::string& bytes, std::uint32_t value) {
    const char b[4] = {static_cast<char>(value & 0xff), static_cast<char>((value >> 8) & 0xff),
                       static_cast<char>((value >> 16) & 0xff), static_cast<char>(value >> 24)};
    bytes.append(b, 4);
}

/// Binary glTF 2.0: one mesh of one primitive, the hull's vertices as float32 POSITION (in the
/// order of Hull::vertices) and its triangles as uint32 indices (a hull without triangles, a
/// segment or a point: a POINTS primitive). Throws std::domain_error for a coordinate that does
/// not fit a float.
void put_glb(TextOut& out, PointSpan points, const Hull& hull) {
    const VertexPositions position(points, hull);
    const std::size_t nv = hull.vertices.size();
    const std::size_t ni = hull.triangles.size();
    if (nv > 0xffffffffu / 12 || ni > (0xffffffffu - 12 * nv) / 4) throw std::domain_error("the hull is too large for a glTF buffer");
    std::string bin;
    bin.reserve(12 * nv + 4 * ni);
    float low[3] = {0, 0, 0}, high[3] = {0, 0, 0};
    for (std::size_t i = 0; i < nv; ++i) {
        const double* p = points[hull.vertices[i]];
        for (int k = 0; k < 3; ++k) {
            const float f = static_cast<float>(p[k]);  // rounded to the nearest float
            if (!std::isfinite(f)) {
                throw std::domain_error("coordinate " + format_double(p[k]) + " of hull vertex " +
                                        std::to_string(hull.vertices[i]) + " does not fit a glTF float32 position");
            }
            low[k] = i == 0 ? f : std::min(low[k], f);
            high[k] = i == 0 ? f : std::max(high[k], f);
            std::uint32_t word;
            std::memcpy(&word, &f, 4);
            put_u32(bin, word);
        }
    }
    for (std::uint32_t corner : hull.triangles) put_u32(bin, position.of(corner));

    TextOut json;
    auto vec3 = [&json](const float* v) {
        json.put('[');
        for (int k = 0; k < 3; ++k) {
            if (k) json.put(',');
            json.number(static_cast<double>(v[k]));
        }
        json.put(']');
    };
    json.put(R"({"asset":{"version":"2.0","generator":"hullkit"},"scene":0,"scenes":[{"nodes":[)");
    if (nv > 0) {
        json.put(R"(0]}],"nodes":[{"mesh":0,"name":"convex hull"}],"meshes":[{"name":"convex hull","primitives":[{"attributes":{"POSITION":0})");
        json.put(ni > 0 ? R"(,"indices":1,"mode":4}]}],)" : R"(,"mode":0}]}],)");
        json.put(R"("accessors":[{"bufferView":0,"componentType":5126,"count":)");
        json.uint(nv);
        json.put(R"(,"type":"VEC3","min":)");
        vec3(low);
        json.put(R"(,"max":)");
        vec3(high);
        json.put('}');
        if (ni > 0) {
            json.put(R"(,{"bufferView":1,"componentType":5125,"count":)");
            json.uint(ni);
            json.put(R"(,"type":"SCALAR"})");
        }
        json.put(R"(],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)");
        json.uint(12 * nv);
        json.put(R"(,"target":34962})");
        if (ni > 0) {
            json.put(R"(,{"buffer":0,"byteOffset":)");
            json.uint(12 * nv);
            json.put(R"(,"byteLength":)");
            json.uint(4 * ni);
            json.put(R"(,"target":34963})");
        }
        json.put(R"(],"buffers":[{"byteLength":)");
        json.uint(bin.size());
        json.put("}]}");
    } else {
        json.put("]}]}");
    }
    std::string& text = json.text();
    while (text.size() % 4 != 0) text += ' ';  // the JSON chunk is padded with spaces
    const std::size_t total = 12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size());
    std::string head;
    put_u32(head, 0x46546C67u);  // "glTF"
    put_u32(head, 2);
    put_u32(head, static_cast<std::uint32_t>(total));
    put_u32(head, static_cast<std::uint32_t>(text.size()));
    put_u32(head, 0x4E4F534Au);  // "JSON"
    out.reserve(total);
    out.put(head);
    out.put(text);
    if (!bin.empty()) {  // 12 bytes a vertex, 4 an index: already a multiple of 4
        std::string chunk;
        put_u32(chunk, static_cast<std::uint32_t>(bin.size()));
        put_u32(chunk, 0x004E4942u);  // "BIN\0"
        out.put(chunk);
        out.put(bin);
    }
    out.record_done();
}

void put_hull(TextOut& out, OutputFormat format, PointSpan points, const Hull& hull, InputIndex id) {
    switch (format) {
        case OutputFormat::Off: return put_off(out, points, hull);
        case OutputFormat::Obj: return put_obj(out, points, hull);
        case OutputFormat::Json: return put_json(out, points, hull, id);
        case OutputFormat::Xyz: return put_xyz(out, points, hull, id);
        case OutputFormat::Glb: return put_glb(out, points, hull);
    }
    throw std::invalid_argument("unknown output format");
}

/// The text a writer produces, as one string.
template <class Put>
std::string to_text(Put put) {
    TextOut out;
    put(out);
    return std::move(out.text());
}

}  // namespace

std::string write_off(PointSpan points, const Hull& hull) {
    return to_text([&](TextOut& out) { put_off(out, points, hull); });
}

std::string write_obj(PointSpan points, const Hull& hull) {
    return to_text([&](TextOut& out) { put_obj(out, points, hull); });
}

std::string write_json(PointSpan points, const Hull& hull, const std::uint64_t* index) {
    return to_text([&](TextOut& out) { put_json(out, points, hull, InputIndex{index}); });
}

std::string write_glb(PointSpan points, const Hull& hull) {
    return to_text([&](TextOut& out) { put_glb(out, points, hull); });
}

std::string write_xyz(PointSpan points, const Hull& hull, const std::uint64_t* index) {
    return to_text([&](TextOut& out) { put_xyz(out, points, hull, InputIndex{index}); });
}

std::string write_hull(OutputFormat format, PointSpan points, const Hull& hull, const std::uint64_t* index) {
    return to_text([&](TextOut& out) { put_hull(out, format, points, hull, InputIndex{index}); });
}

bool write_hull_file(OutputFormat format, PointSpan points, const Hull& hull, std::FILE* file, int* error_number,
                     const std::uint64_t* index) {
    TextOut out(file);
    put_hull(out, format, points, hull, InputIndex{index});
    if (out.flush()) return true;
    *error_number = out.error_number();
    return false;
}

std::string format_double(double value) {
    TextOut out;
    out.number(value);
    return std::move(out.text());
}

std::string format_json_number(double value) {
    TextOut out;
    out.json_number(value);
    return std::move(out.text());
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
