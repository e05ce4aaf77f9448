// The point readers: point text (xyz, rbox, OBJ, OFF; TetGen .node by name) told apart by its first line, its header
// read once and its point lines parsed in pieces for PointReader (io::read_point_text_header,
// io::parse_point_piece), parse_points and read_points_file on top of PointReader, the OFF mesh
// reader (read_off_mesh) and read_file; see mesh_io.hpp for the formats. Lines, fields and
// numbers come from text_fields.hpp.
#include "hullkit/mesh_io.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hullkit/point_reader.hpp"
#include "mesh_read_internal.hpp"
#include "text_fields.hpp"

namespace hullkit {
namespace {

using io::text::kMaxCount;
using io::text::kUnknownSize;
using io::text::parse_count;
using io::text::parse_double;
using io::text::quoted;
using io::text::Reader;
using io::text::safe_reserve;

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

/// TetGen's .node header: "points dimension attributes markers" (the last two optional, 0 if
/// absent); only 3D nodes are points here.
bool read_node_header(Reader& reader, io::PointTextHeader* header) {
    if (!reader.split(false)) return false;
    const auto& fields = reader.fields();
    std::uint64_t values[4] = {0, 3, 0, 0};
    if (fields.size() > 4) return reader.fail("expected the .node header \"points 3 attributes markers\", got " + quoted(reader.line()));
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (!parse_count(fields[i], kMaxCount, &values[i])) {
            return reader.fail("expected the .node header \"points 3 attributes markers\", got " + quoted(reader.line()));
        }
    }
    if (values[1] != 3) return reader.fail(".node file of dimension " + std::to_string(values[1]) + " (only 3D nodes are read)");
    if (values[3] > 1) return reader.fail(".node header: markers must be 0 or 1, got " + std::to_string(values[3]));
    if (values[2] > 1000) return reader.fail(".node header: " + std::to_string(values[2]) + " attributes per node is too many");
    header->counted = true;
    header->declared = values[0];
    header->count_line = reader.line_number();
    header->node_fields = static_cast<std::size_t>(4 + values[2] + values[3]);
    return true;
}

/// One .node point line: "index x y z [attributes...] [marker]"; the index is any number (TetGen
/// numbers from 0 or 1), the point is x y z, the rest is checked to be numeric.
bool read_node_line(Reader& reader, const io::PointTextHeader& header, std::vector<double>* xyz) {
    if (!reader.split(false)) return false;
    const std::size_t n = reader.fields().size();
    if (n != header.node_fields) {
        return reader.fail("expected " + std::to_string(header.node_fields) + " numbers (index, x, y, z" +
                           (header.node_fields > 4 ? ", attributes, marker" : "") + ") as the header says, got " +
                           std::to_string(n));
    }
    std::vector<double> extra;
    if (!reader.append_numbers(0, 1, "node index", &extra)) return false;
    if (!reader.append_numbers(1, 3, "coordinate", xyz, /*coordinates=*/true)) return false;
    return reader.append_numbers(4, n - 4, "node value", &extra);
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
        if (!reader.append_numbers(1, 3, "coordinate", xyz, /*coordinates=*/true)) return false;
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
        // No content at all (an empty file, only comments): no points, which is no error.
        if (reader.ran_out()) return ReadStatus::NeedMore;
        header->format = PointTextFormat::Xyz;
        header->body_offset = text.size();
        header->body_line = reader.line_number();
        return ReadStatus::Done;
    }
    if (reader.split(false)) {  // cannot fail without commas
        header->format = detect_format(reader.fields());
        // A file named .obj is OBJ whatever its first line (FCL's meshes start with "648 1292");
        // one named .node is TetGen's (its lines "index x y z" would read as four coordinates).
        if (header->format != PointTextFormat::Off && io::extension_of(source) == "obj") {
            header->format = PointTextFormat::Obj;
        }
        if (io::extension_of(source) == "node") header->format = PointTextFormat::Node;
        switch (header->format) {
            case PointTextFormat::Xyz: {
                // A header row of column names, as CSV files start ("x,y,z"), is skipped (and
                // said so in the warnings); the points start on the next line.
                std::vector<std::string_view> fields;
                std::string ignored;
                if (io::text::split_fields(reader.line(), true, &fields, &ignored) &&
                    io::text::is_column_names(fields, 3)) {
                    header->column_names_line = reader.line_number();
                    header->column_names = io::printable(reader.line());
                    header->body_offset = reader.cursor().offset();
                    header->body_line = reader.line_number();
                    ok = true;
                    break;
                }
            }
                [[fallthrough]];
            case PointTextFormat::Obj:  // no header: the first content line is the first point line
                header->body_offset = reader.cursor().line_start();
                header->body_line = reader.line_number() - 1;
                ok = true;
                break;
            case PointTextFormat::Rbox:
                ok = read_rbox_header(reader, header);
                break;
            case PointTextFormat::Node:
                ok = read_node_header(reader, header);
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
    reader.set_points_start(start);
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
        if (found == limit) {  // rbox, .node: a point line after the last one declared
            ok = reader.fail("more points than the " + std::to_string(header.declared) + " declared on line " +
                             std::to_string(header.count_line));
            break;
        }
        if (format == PointTextFormat::Node) {
            if (!(ok = read_node_line(reader, header, xyz))) break;
        } else if (!(ok = reader.append_point_line(/*allow_commas=*/format == PointTextFormat::Xyz, xyz))) {
            break;
        }
        ++found;
    }
    piece->points = (xyz->size() - start) / 3;
    piece->lines = reader.line_number();
    if (!ok) {
        piece->error_line = reader.error_line();
        piece->error_what = std::move(reader.error_what());
        piece->error_point = reader.error_point();
        piece->error_tail = std::move(reader.error_tail());
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

}  // namespace hullkit
