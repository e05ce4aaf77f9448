// PLY meshes: ascii and binary (little or big endian) bodies behind one text header.
#include "hullkit/mesh_read.hpp"

#include "mesh_read_internal.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace hullkit {

namespace {

enum class Encoding { Ascii, LittleEndian, BigEndian };

enum class ScalarType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool parse_scalar_type(std::string_view name, ScalarType* out) {
    struct Entry {
        const char* name;
        ScalarType type;
    };
    static const Entry kTypes[] = {
        {"char", ScalarType::Int8},     {"int8", ScalarType::Int8},       {"uchar", ScalarType::UInt8},
        {"uint8", ScalarType::UInt8},   {"short", ScalarType::Int16},     {"int16", ScalarType::Int16},
        {"ushort", ScalarType::UInt16}, {"uint16", ScalarType::UInt16},   {"int", ScalarType::Int32},
        {"int32", ScalarType::Int32},   {"uint", ScalarType::UInt32},     {"uint32", ScalarType::UInt32},
        {"float", ScalarType::Float32}, {"float32", ScalarType::Float32}, {"double", ScalarType::Float64},
        {"float64", ScalarType::Float64}};
    for (const Entry& entry : kTypes) {
        if (name == entry.name) {
            *out = entry.type;
            return true;
        }
    }
    return false;
}

std::size_t size_of(ScalarType type) {
    switch (type) {
        case ScalarType::Int8:
        case ScalarType::UInt8: return 1;
        case ScalarType::Int16:
        case ScalarType::UInt16: return 2;
        case ScalarType::Int32:
        case ScalarType::UInt32:
        case ScalarType::Float32: return 4;
        case ScalarType::Float64: return 8;
    }
    return 0;
}

bool is_integer(ScalarType type) { return type != ScalarType::Float32 && type != ScalarType::Float64; }

/// An integral value read from the file, for messages. An ascii body may hold any magnitude
/// ("1e300"), which a cast to an integer type cannot hold.
std::string integer_text(double value) {
    if (std::fabs(value) >= 1e15) return format_double(value);  // "1e+300"
    char text[32];
    std::snprintf(text, sizeof text, "%.0f", value);
    return text;
}

struct Property {
    std::string name;
    ScalarType type = ScalarType::Float32;  ///< the items' type for a list
    bool is_list = false;
    ScalarType count_type = ScalarType::UInt8;
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;
};

struct Header {
    Encoding encoding = Encoding::Ascii;
    std::vector<Element> elements;
    std::size_t body_offset = 0;  ///< first byte after "end_header\n"
    std::size_t body_line = 0;    ///< number of the line "end_header"
};

/// Reads the header; returns an error message ("" on success).
std::string read_header(const std::string& bytes, const std::string& source, Header* header) {
    // The header is text; stop scanning at end_header so that a binary body is never split.
    io::LineCursor lines(bytes);
    std::string_view line;
    bool format_seen = false;
    auto fail = [&](const std::string& what) { return io::at_line(source, lines.line_number(), what); };
    if (!lines.next(&line) || io::split_words(line, 0) != std::vector<std::string_view>{"ply"}) {
        return fail("expected \"ply\" on the first line");
    }
    while (lines.next(&line)) {
        std::vector<std::string_view> words = io::split_words(line, 0);
        if (words.empty()) continue;
        const std::string_view keyword = words[0];
        if (keyword == "comment" || keyword == "obj_info") continue;
        if (keyword == "format") {
            if (words.size() != 3 || words[2] != "1.0") return fail("expected \"format ascii|binary_little_endian|binary_big_endian 1.0\"");
            if (words[1] == "ascii") {
                header->encoding = Encoding::Ascii;
            } else if (words[1] == "binary_little_endian") {
                header->encoding = Encoding::LittleEndian;
            } else if (words[1] == "binary_big_endian") {
                header->encoding = Encoding::BigEndian;
            } else {
                return fail("unknown PLY format " + io::quote(words[1]));
            }
            format_seen = true;
        } else if (keyword == "element") {
            std::int64_t count;
            if (words.size() != 3 || !io::parse_integer(words[2], &count) || count < 0) {
                return fail("expected \"element NAME COUNT\"");
            }
            header->elements.push_back({std::string(words[1]), static_cast<std::uint64_t>(count), {}});
        } else if (keyword == "property") {
            if (header->elements.empty()) return fail("a property before any element");
            Property property;
            if (words.size() == 5 && words[1] == "list") {
                property.is_list = true;
                if (!parse_scalar_type(words[2], &property.count_type) || !is_integer(property.count_type)) {
                    return fail("list count type " + io::quote(words[2]) + " is not an integer type");
                }
                if (!parse_scalar_type(words[3], &property.type)) return fail("unknown property type " + io::quote(words[3]));
                property.name = std::string(words[4]);
            } else if (words.size() == 3) {
                if (!parse_scalar_type(words[1], &property.type)) return fail("unknown property type " + io::quote(words[1]));
                property.name = std::string(words[2]);
            } else {
                return fail("expected \"property TYPE NAME\" or \"property list COUNT_TYPE TYPE NAME\"");
            }
            header->elements.back().properties.push_back(property);
        } else if (keyword == "end_header") {
            if (!format_seen) return fail("no \"format\" line before end_header");
            header->body_offset = lines.offset();
            header->body_line = lines.line_number();
            return "";
        } else {
            return fail("unknown PLY header line " + io::quote(keyword));
        }
    }
    return source + ": the PLY header has no \"end_header\"";
}

/// An element's name for messages: as it is when it is short printable ASCII, otherwise quoted with
/// every other byte shown as '?' (a header may name an element anything; no byte of it is echoed).
std::string element_label(const std::string& name) {
    if (name.size() <= 40 && std::all_of(name.begin(), name.end(), [](char c) { return c > 0x20 && c < 0x7f; })) return name;
    return io::quote(name);
}

/// Hands out the values of the body one by one, as text fields or binary scalars.
class BodyReader {
public:
    BodyReader(const std::string& bytes, const Header& header, const std::string& source)
        : bytes_(bytes), encoding_(header.encoding), source_(source), offset_(header.body_offset),
          lines_(std::string_view(bytes), header.body_offset) {
        line_base_ = header.body_line;
    }

    /// Starts row `row` of element `element` (for messages; ascii: moves to the next non-blank line).
    bool begin_row(const Element& element, std::uint64_t row) {
        where_ = element_label(element.name) + " " + std::to_string(row);
        if (encoding_ != Encoding::Ascii) {
            row_offset_ = offset_;
            return true;
        }
        std::string_view line;
        do {
            if (!lines_.next(&line)) return fail("the file ends before " + where_ + " (ascii body)");
            words_ = io::split_words(line, 0);
        } while (words_.empty());
        next_word_ = 0;
        return true;
    }

    /// Ascii: no values may be left on the row's line.
    bool end_row() {
        if (encoding_ == Encoding::Ascii && next_word_ != words_.size()) {
            return fail(where_ + " has " + std::to_string(words_.size() - next_word_) + " values too many");
        }
        return true;
    }

    bool read(ScalarType type, double* out) {
        if (encoding_ == Encoding::Ascii) {
            if (next_word_ >= words_.size()) return fail(where_ + " has too few values");
            std::string_view word = words_[next_word_++];
            if (!io::parse_finite(word, out)) return fail(where_ + ": value " + io::quote(word) + " is not a finite number");
            if (is_integer(type) && *out != std::floor(*out)) {
                return fail(where_ + ": value " + io::quote(word) + " is not an integer");
            }
            return true;
        }
        const std::size_t size = size_of(type);
        if (bytes_.size() - offset_ < size) {
            return fail("binary PLY is truncated in " + where_ + " (byte " + std::to_string(offset_) + " of " +
                        std::to_string(bytes_.size()) + ")");
        }
        unsigned char b[8];
        std::memcpy(b, bytes_.data() + offset_, size);
        offset_ += size;
        if (encoding_ == Encoding::BigEndian) {
            for (std::size_t i = 0; i < size / 2; ++i) std::swap(b[i], b[size - 1 - i]);
        }
        *out = decode(type, b);  // the host is little endian (x86, arm64, wasm)
        if (!std::isfinite(*out)) return fail(where_ + " (byte " + std::to_string(row_offset_) + "): a value is not a finite number");
        return true;
    }

    /// Binary: the body must end with the last element.
    bool finish() {
        if (encoding_ != Encoding::Ascii && offset_ != bytes_.size()) {
            return fail("binary PLY has " + std::to_string(bytes_.size() - offset_) + " bytes after the last element (byte " +
                        std::to_string(offset_) + ")");
        }
        if (encoding_ == Encoding::Ascii) {
            std::string_view line;
            while (lines_.next(&line)) {
                if (!io::split_words(line, 0).empty()) return fail("content after the last element");
            }
        }
        return true;
    }

    bool fail(const std::string& what) {
        if (error_.empty()) {
            error_ = encoding_ == Encoding::Ascii ? io::at_line(source_, line_base_ + lines_.line_number(), what)
                                                  : source_ + ": " + what;
        }
        return false;
    }
    const std::string& error() const { return error_; }

private:
    static double decode(ScalarType type, const unsigned char* b) {
        switch (type) {
            case ScalarType::Int8: return static_cast<std::int8_t>(b[0]);
            case ScalarType::UInt8: return b[0];
            case ScalarType::Int16: return static_cast<std::int16_t>(b[0] | (b[1] << 8));
            case ScalarType::UInt16: return static_cast<std::uint16_t>(b[0] | (b[1] << 8));
            case ScalarType::Int32:
            case ScalarType::UInt32: {
                std::uint32_t word = b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t{b[3]} << 24);
                return type == ScalarType::Int32 ? static_cast<double>(static_cast<std::int32_t>(word)) : word;
            }
            case ScalarType::Float32: {
                float value;
                std::memcpy(&value, b, 4);
                return value;
            }
            case ScalarType::Float64: {
                double value;
                std::memcpy(&value, b, 8);
                return value;
            }
        }
        return 0;
    }

    const std::string& bytes_;
    Encoding encoding_;
    const std::string& source_;
    std::size_t offset_ = 0;
    std::size_t row_offset_ = 0;
    io::LineCursor lines_;  ///< ascii: counts lines from the body's start
    std::size_t line_base_ = 0;
    std::vector<std::string_view> words_;
    std::size_t next_word_ = 0;
    std::string where_;
    std::string error_;
};

int find_property(const Element& element, std::initializer_list<const char*> names) {
    for (std::size_t i = 0; i < element.properties.size(); ++i) {
        for (const char* name : names) {
            if (element.properties[i].name == name) return static_cast<int>(i);
        }
    }
    return -1;
}

}  // namespace

namespace {

/// The PLY reader; without `faces_required` a file with no "face" element is a point cloud.
MeshResult read_ply(const std::string& bytes, const std::string& source, bool faces_required) {
    Header header;
    std::string error = read_header(bytes, source, &header);
    if (!error.empty()) return io::mesh_error(error);

    // The vertex element's x y z (scalars) and the face element's index list.
    const Element* vertex = nullptr;
    const Element* face = nullptr;
    int axis_property[3] = {-1, -1, -1};
    int index_property = -1;
    for (const Element& element : header.elements) {
        if (element.name == "vertex") {
            vertex = &element;
            const char* axes[3] = {"x", "y", "z"};
            for (int axis = 0; axis < 3; ++axis) {
                axis_property[axis] = find_property(element, {axes[axis]});
                if (axis_property[axis] < 0 || element.properties[axis_property[axis]].is_list) {
                    return io::mesh_error(source + ": the PLY vertex element has no scalar property \"" + axes[axis] + "\"");
                }
            }
        } else if (element.name == "face") {
            face = &element;
            index_property = find_property(element, {"vertex_indices", "vertex_index"});
            if (index_property < 0 || !element.properties[index_property].is_list ||
                !is_integer(element.properties[index_property].type)) {
                return io::mesh_error(source + ": the PLY face element has no integer list property \"vertex_indices\"");
            }
        }
    }
    if (!vertex) return io::mesh_error(source + ": the PLY header declares no \"vertex\" element");
    if (!face && faces_required) return io::mesh_error(source + ": the PLY header declares no \"face\" element");
    if (vertex->count > 0xffffffffULL) return io::mesh_error(source + ": too many vertices for 32-bit indices");

    MeshResult mesh;
    BodyReader body(bytes, header, source);
    // Reserve only what the file could hold, so a lying header cannot allocate gigabytes.
    mesh.xyz.reserve(3 * std::min<std::uint64_t>(vertex->count, bytes.size() / 3));
    std::vector<std::uint32_t> corners;
    for (const Element& element : header.elements) {
        // A binary row without properties holds no bytes: reading 10^18 of them would only spin
        // in a loop. An ascii row is still a line that must be there.
        if (element.properties.empty() && header.encoding != Encoding::Ascii) continue;
        for (std::uint64_t row = 0; row < element.count; ++row) {
            if (!body.begin_row(element, row)) return io::mesh_error(body.error());
            double xyz[3] = {0, 0, 0};
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                const Property& property = element.properties[p];
                if (!property.is_list) {
                    double value;
                    if (!body.read(property.type, &value)) return io::mesh_error(body.error());
                    for (int axis = 0; axis < 3; ++axis) {
                        if (&element == vertex && static_cast<int>(p) == axis_property[axis]) xyz[axis] = value;
                    }
                    continue;
                }
                double count;
                if (!body.read(property.count_type, &count)) return io::mesh_error(body.error());
                const bool is_face_list = &element == face && static_cast<int>(p) == index_property;
                if (count < 0 || (is_face_list && count < 3)) {
                    body.fail(element_label(element.name) + " " + std::to_string(row) + ": " +
                              (count < 0 ? "a list count is negative: " : "a face needs at least 3 vertices, got ") +
                              integer_text(count));
                    return io::mesh_error(body.error());
                }
                corners.clear();
                for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(count); ++k) {
                    double value;
                    if (!body.read(property.type, &value)) return io::mesh_error(body.error());
                    if (!is_face_list) continue;
                    if (value < 0 || value >= static_cast<double>(vertex->count)) {
                        body.fail("face " + std::to_string(row) + ": index " + integer_text(value) +
                                  " out of range (" + std::to_string(vertex->count) + " vertices)");
                        return io::mesh_error(body.error());
                    }
                    corners.push_back(static_cast<std::uint32_t>(value));
                }
                if (is_face_list) io::append_fan(corners, &mesh.triangles);
            }
            if (!body.end_row()) return io::mesh_error(body.error());
            if (&element == vertex) mesh.xyz.insert(mesh.xyz.end(), xyz, xyz + 3);
        }
    }
    if (!body.finish()) return io::mesh_error(body.error());
    return mesh;
}

}  // namespace

MeshResult read_ply_mesh(const std::string& bytes, const std::string& source) {
    return read_ply(bytes, source, true);
}

PointsResult read_ply_points(const std::string& bytes, const std::string& source) {
    MeshResult mesh = read_ply(bytes, source, false);
    PointsResult points;
    points.error = std::move(mesh.error);
    points.xyz = std::move(mesh.xyz);
    return points;
}

}  // namespace hullkit
