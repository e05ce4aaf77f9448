// Reading 2D point sets (the input of Delaunay triangulation); see parse_points_2d in mesh_io.hpp.
// Lines and numbers come from the readers' shared helpers (mesh_read_internal.hpp), fields (split at
// whitespace or a comma) and header rows from the 3D point reader's (text_fields.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "hullkit/mesh_io.hpp"
#include "mesh_read_internal.hpp"
#include "text_fields.hpp"

namespace hullkit {
namespace {

/// Header counts index uint32 points.
constexpr std::int64_t kMaxCount = 0xffffffffLL;

/// Hands out the fields of each line that has any ('#' starts a comment; fields are separated by
/// whitespace or one comma, as in the 3D reader) and keeps the first problem as
/// "source:LINE: what". A UTF-8 byte-order mark at the start is skipped.
class Reader2 {
public:
    Reader2(const std::string& text, const std::string& source, std::vector<std::size_t>* point_lines)
        : lines_(text, io::bom_length(text)), source_(source), text_size_(text.size()), point_lines_(point_lines) {}

    /// Advances to the next line with fields; false at the end of the text, or after an empty
    /// field between commas (then the error is recorded: see failed()).
    bool next() {
        std::string_view line;
        while (lines_.next(&line)) {
            line = line.substr(0, line.find('#'));
            while (!line.empty() && io::text::is_space(line.front())) line.remove_prefix(1);
            while (!line.empty() && io::text::is_space(line.back())) line.remove_suffix(1);
            line_ = line;
            std::string what;
            if (!io::text::split_fields(line, /*allow_commas=*/true, &fields_, &what)) return fail(what);
            if (!fields_.empty()) return true;
        }
        return false;
    }
    bool failed() const { return !error_.empty(); }
    /// The current line, without its comment.
    std::string_view line() const { return line_; }
    const std::vector<std::string_view>& fields() const { return fields_; }
    std::size_t line_number() const { return lines_.line_number(); }
    std::size_t text_size() const { return text_size_; }

    /// Records a problem; the first one recorded is the one reported.
    bool fail(const std::string& what) { return fail_at(line_number(), what); }
    bool fail_at(std::size_t line, const std::string& what) {
        if (error_.empty()) error_ = io::at_line(source_, line, what);
        return false;
    }
    bool fail_whole(const std::string& what) {
        if (error_.empty()) error_ = source_ + ": " + what;
        return false;
    }
    const std::string& error() const { return error_; }

    /// The current line must hold exactly `width` (2 or 3) finite numbers; appends x and y.
    bool append_point(std::size_t width, std::vector<double>* xy) {
        if (fields_.size() != width) {
            return fail("expected " + std::to_string(width) + " coordinates, got " + std::to_string(fields_.size()));
        }
        double value[3];
        for (std::size_t i = 0; i < width; ++i) {
            if (!io::parse_finite(fields_[i], &value[i])) {
                // Name the point too: the triangulation and its messages count points from 0. A
                // number too large for a double ("1e400") is said to be one.
                double number = 0.0;
                const bool numeric = io::text::parse_double(fields_[i], &number);
                return fail("coordinate " + io::quote(fields_[i]) + " of point " + std::to_string(xy->size() / 2) + " " +
                            (numeric ? io::non_finite_reason(fields_[i]) : "is not a finite number"));
            }
        }
        // A third coordinate is checked but not kept: the points are projected onto the x-y plane.
        xy->push_back(value[0]);
        xy->push_back(value[1]);
        if (point_lines_) point_lines_->push_back(line_number());
        return true;
    }

private:
    io::LineCursor lines_;
    std::string source_;
    std::size_t text_size_;
    std::vector<std::size_t>* point_lines_;
    std::vector<std::string_view> fields_;
    std::string_view line_;
    std::string error_;
};

/// qhull's header line: the dimension alone, or followed by a comment such as "rbox 1000 D2".
/// A line of numbers ("1 2") is a point, not a header.
bool is_rbox_header(const std::vector<std::string_view>& fields) {
    std::int64_t dimension;
    double ignored;
    return io::parse_integer(fields[0], &dimension) && dimension >= 0 &&
           (fields.size() == 1 || !io::parse_finite(fields[1], &ignored));
}

bool read_rbox(Reader2& reader, std::vector<double>* xy) {
    std::int64_t dimension = 0;
    io::parse_integer(reader.fields()[0], &dimension);  // checked by is_rbox_header
    if (dimension != 2 && dimension != 3) {
        if (reader.fields().size() > 1) {  // "1 x": more likely a point with a typo than a header
            return reader.fail("coordinate " + io::quote(reader.fields()[1]) + " is not a number (or, read as a " +
                               "qhull header, dimension " + std::to_string(dimension) + " is not 2 or 3)");
        }
        return reader.fail("dimension is " + std::to_string(dimension) + ", expected 2 (or 3, whose z is ignored)");
    }
    if (!reader.next()) return reader.fail("file ends after the dimension line; expected the point count");
    std::int64_t count = 0;
    if (reader.fields().size() != 1 || !io::parse_integer(reader.fields()[0], &count) || count < 0 ||
        count > kMaxCount) {
        return reader.fail("expected the point count (one non-negative integer), got " +
                           io::quote(reader.fields()[0]));
    }
    const std::size_t count_line = reader.line_number();
    // Reserve no more than the text could hold ("0 0\n" per point), so a lying header is harmless.
    xy->reserve(2 * std::min<std::size_t>(static_cast<std::size_t>(count), reader.text_size() / 4 + 1));
    std::int64_t found = 0;
    while (reader.next()) {
        if (found == count) {
            return reader.fail("more points than the " + std::to_string(count) + " declared on line " +
                               std::to_string(count_line));
        }
        if (!reader.append_point(static_cast<std::size_t>(dimension), xy)) return false;
        ++found;
    }
    if (reader.failed()) return false;
    if (found != count) {
        return reader.fail_at(count_line, "header declares " + std::to_string(count) + " points but the file has " +
                                              std::to_string(found));
    }
    return true;
}

/// Empty if `text` starts like text; else why it is not a 2D point file, naming the format where
/// it is recognisable (PLY, ASCII or binary STL), never echoing a byte of it. Bytes >= 0x80 may be
/// UTF-8 text (in a comment); other control bytes than whitespace are binary.
std::string binary_input_message(const std::string& text) {
    const std::string_view head = std::string_view(text).substr(0, 4096);
    const std::string unsupported = " is not supported by the 2D point reader (read: x y, x y z, rbox)";
    if (io::starts_with_word(head, "ply")) return "PLY" + unsupported;
    if (io::starts_with_word(head, "solid") && head.find("facet") != std::string_view::npos) return "ASCII STL" + unsupported;
    for (std::size_t i = 0; i < head.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(head[i]);
        if (c >= 0x20 ? c != 0x7f : (c == '\n' || c == '\t' || c == '\r' || c == '\v' || c == '\f')) continue;
        if (io::has_binary_stl_size(text)) return "binary STL" + unsupported;
        char detail[64];
        std::snprintf(detail, sizeof detail, "binary data (byte 0x%02x at offset %zu)", c, i);
        return detail;
    }
    return {};
}

/// 3D formats that hold more than points: named rather than read as a bad first point.
const char* other_format(std::string_view first_field) {
    if (first_field == "OFF") return "OFF";
    static const char* const kObjRecords[] = {"v", "vt", "vn", "f", "o", "g", "mtllib", "usemtl"};
    for (const char* record : kObjRecords) {
        if (first_field == record) return "OBJ";
    }
    return nullptr;
}

bool read_lines(Reader2& reader, std::vector<double>* xy) {
    // Every line has as many coordinates as the first: a stray 3-number line in a 2D file (or the
    // reverse) is more likely a mistake than a point.
    const std::size_t width = reader.fields().size();
    if (width != 2 && width != 3) {
        return reader.fail("expected 2 coordinates (x y) or 3 (x y z, z ignored), got " + std::to_string(width));
    }
    xy->reserve(reader.text_size() / 16);
    do {
        if (!reader.append_point(width, xy)) return false;
    } while (reader.next());
    return !reader.failed();
}

}  // namespace

Points2Result parse_points_2d(const std::string& text, const std::string& source,
                              std::vector<std::size_t>* point_lines) {
    Points2Result result;
    if (point_lines) point_lines->clear();
    Reader2 reader(text, source, point_lines);
    bool ok;
    const std::string binary = binary_input_message(text);
    const char* format = nullptr;
    if (!binary.empty()) {
        ok = reader.fail_whole("not a point file: " + binary);
    } else if (!reader.next()) {
        ok = !reader.failed();  // no content (an empty file, only comments): no points, no error
    } else if ((format = other_format(reader.fields()[0])) != nullptr) {
        ok = reader.fail_whole(std::string("not a point file: ") + format +
                               " is not supported by the 2D point reader (read: x y, x y z, rbox)");
    } else if (is_rbox_header(reader.fields())) {
        ok = read_rbox(reader, &result.xy);
    } else if (io::text::is_column_names(reader.fields(), 0)) {
        // A header row of column names, as CSV files start ("x,y"): skipped, and said so.
        result.warnings.push_back(io::column_names_warning(reader.line_number(), io::printable(reader.line())));
        ok = reader.next() ? read_lines(reader, &result.xy) : !reader.failed();
    } else {
        ok = read_lines(reader, &result.xy);
    }
    if (!ok) {
        result.xy = {};
        result.warnings.clear();
        result.error = reader.error();
        if (point_lines) point_lines->clear();
    } else {
        result.xy.shrink_to_fit();
    }
    return result;
}

}  // namespace hullkit
