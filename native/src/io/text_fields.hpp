// The point readers' text helpers (point_text.cpp): lines with content (blank lines and '#'
// comments skipped), fields split at whitespace or a comma, strict number parsing, and the
// Reader that walks a text and keeps the one-line error message of whatever is wrong. Inline:
// the number parser is on the hot path of reading 1e7-point files.
// (mesh_read_internal.hpp has similar line and number helpers for the mesh readers; these are
// the point readers'.)
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

// fast_float (Debian libfast-float-dev, header-only): the from_chars algorithm, inlined here;
// ~3x fewer instructions per number than libstdc++'s std::from_chars. Without it the reader
// falls back to std::from_chars / strtod with the same results.
#if __has_include(<fast_float/fast_float.h>)
#include <fast_float/fast_float.h>
#define HULLKIT_HAVE_FAST_FLOAT 1
#endif

#include "mesh_read_internal.hpp"

namespace hullkit::io::text {

// ---------------------------------------------------------------------------------------------
// Lines and fields
// ---------------------------------------------------------------------------------------------

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

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
inline bool split_fields(std::string_view line, bool allow_commas, std::vector<std::string_view>* fields,
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
inline std::string quoted(std::string_view field) {
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
inline const char* parse_double_prefix(const char* begin, const char* end, double* out) {
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
inline bool parse_double(std::string_view field, double* out) {
    const char* end = field.data() + field.size();
    return parse_double_prefix(field.data(), end, out) == end;
}

/// Whether `fields`, the first content line of a point file, are a header row of column names
/// ("x,y,z" as CSV files start): `width` fields (2 or 3 with `width` 0), none of them a number.
inline bool is_column_names(const std::vector<std::string_view>& fields, std::size_t width) {
    if (width ? fields.size() != width : fields.size() != 2 && fields.size() != 3) return false;
    double ignored;
    for (std::string_view field : fields) {
        if (parse_double(field, &ignored)) return false;
    }
    return true;
}

/// A non-negative decimal integer (digits only) that fits in `limit`.
inline bool parse_count(std::string_view field, std::uint64_t limit, std::uint64_t* out) {
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
inline constexpr std::uint64_t kMaxCount = 0xffffffffu;

/// Reserving a header's count up front is only safe when the text could hold that many points
/// (every point needs at least "0 0 0\n"), so a lying header cannot exhaust memory.
/// `text_size` is kUnknownSize for a stream (a pipe); then at most 2^16 points are reserved and
/// the array grows beyond that as needed.
inline constexpr std::size_t kUnknownSize = ~std::size_t{0};

inline std::size_t safe_reserve(std::uint64_t declared, std::size_t text_size) {
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
        error_point_ = kNoPoint;
        error_tail_.clear();
        return false;
    }
    /// Records that coordinate `field` of the point being appended to `out` is not finite; the
    /// message names the point (see set_points_start) and says whether the number overflowed.
    bool fail_coordinate(std::string_view field, const std::vector<double>& out) {
        fail("coordinate " + quoted(field));
        error_point_ = (out.size() - points_start_) / 3;
        error_tail_ = io::non_finite_reason(field);
        return false;
    }
    /// Where the points read from this text start in the array they are appended to: messages
    /// about a coordinate count the points from there (a piece of a longer text: from the
    /// piece's first point, which the caller numbers).
    void set_points_start(std::size_t size) { points_start_ = size; }
    /// For problems no single line is to blame for (an empty input).
    bool fail_whole(const std::string& what) { return fail_at(0, what); }
    /// "source:LINE: what", or "source: what" for the whole input.
    std::string error() const {
        const std::string what = io::describe_problem(error_what_, error_point_, error_tail_);
        return error_line_ ? io::at_line(source_, error_line_, what) : source_ + ": " + what;
    }
    /// The failing line (0: the whole input) and what is wrong (see io::describe_problem), for a
    /// caller that numbers the lines and points itself (a piece of a longer text).
    std::size_t error_line() const { return error_line_; }
    std::string& error_what() { return error_what_; }
    std::size_t error_point() const { return error_point_; }
    std::string& error_tail() { return error_tail_; }

    /// Parses fields[first..first+count) as numbers into *out (appended); with `coordinates`, each
    /// must be finite (fail_coordinate).
    bool append_numbers(std::size_t first, std::size_t count, const char* what,
                        std::vector<double>* out, bool coordinates = false) {
        for (std::size_t i = first; i < first + count; ++i) {
            double value;
            if (!parse_double(fields_[i], &value)) {
                return fail(std::string(what) + " " + quoted(fields_[i]) + " is not a number");
            }
            if (coordinates && !std::isfinite(value)) return fail_coordinate(fields_[i], *out);
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
        // The line is trimmed: nothing may follow the third number. (A non-finite coordinate takes
        // the general path too, for its message.)
        if (k == 3 && p == end && std::isfinite(point[0]) && std::isfinite(point[1]) && std::isfinite(point[2])) {
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
        return append_numbers(0, 3, "coordinate", xyz, /*coordinates=*/true);
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
    std::size_t error_point_ = kNoPoint;
    std::string error_tail_;
    std::size_t points_start_ = 0;
};

}  // namespace hullkit::io::text
