// PLY meshes: ascii and binary (little or big endian) bodies behind one text header, read from
// memory or streamed (io::PlyReader).
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

/// The range of an integer type, for ascii values ("300" is not a uchar, "1e300" not a uint).
void integer_range(ScalarType type, double* low, double* high) {
    switch (type) {
        case ScalarType::Int8: *low = -128.0, *high = 127.0; return;
        case ScalarType::UInt8: *low = 0.0, *high = 255.0; return;
        case ScalarType::Int16: *low = -32768.0, *high = 32767.0; return;
        case ScalarType::UInt16: *low = 0.0, *high = 65535.0; return;
        case ScalarType::Int32: *low = -2147483648.0, *high = 2147483647.0; return;
        default: *low = 0.0, *high = 4294967295.0; return;  // UInt32
    }
}

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

/// The length of the longest prefix of `text` made of whole lines ("\n", "\r\n" or "\r" line ends,
/// as io::LineCursor reads them); all of it `at_end`. A "\r" at the very end is not yet a whole
/// line end: a "\n" may follow.
std::size_t whole_lines_length(std::string_view text, bool at_end) {
    if (at_end) return text.size();
    for (std::size_t n = text.size(); n > 0; --n) {
        // Scanning back, a "\r" before the last byte is followed by something other than "\n".
        if (text[n - 1] == '\n' || (text[n - 1] == '\r' && n < text.size())) return n;
    }
    return 0;
}

/// Reads the header from `text`, whole lines from the start of the file; `whole`: the file has
/// nothing more. NeedMore when the header runs past `text`; Failed with *error.
io::ReadStatus read_header(std::string_view text, bool whole, const std::string& source, Header* header,
                           std::string* error) {
    // The header is text; stop scanning at end_header so that a binary body is never split.
    if (text.empty() && !whole) return io::ReadStatus::NeedMore;
    io::LineCursor lines(text);
    std::string_view line;
    bool format_seen = false;
    auto fail = [&](const std::string& what) {
        *error = io::at_line(source, lines.line_number(), what);
        return io::ReadStatus::Failed;
    };
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
            return io::ReadStatus::Done;
        } else {
            return fail("unknown PLY header line " + io::quote(keyword));
        }
    }
    if (!whole) return io::ReadStatus::NeedMore;
    *error = source + ": the PLY header has no \"end_header\"";
    return io::ReadStatus::Failed;
}

/// An element's name for messages: as it is when it is short printable ASCII, otherwise quoted with
/// every other byte shown as '?' (a header may name an element anything; no byte of it is echoed).
std::string element_label(const std::string& name) {
    if (name.size() <= 40 && std::all_of(name.begin(), name.end(), [](char c) { return c > 0x20 && c < 0x7f; })) return name;
    return io::quote(name);
}

/// Hands out the values of the body one by one, as text fields or binary scalars, reading the
/// input as it goes (all of it may be in memory already).
class BodyReader {
public:
    BodyReader(io::ChunkedInput& input, const Header& header, const std::string& source)
        : input_(input), encoding_(header.encoding), source_(source), line_base_(header.body_line) {}

    /// Starts row `row` of element `element` (for messages; ascii: moves to the next non-blank line).
    bool begin_row(const Element& element, std::uint64_t row) {
        element_ = &element;
        row_ = row;
        if (encoding_ != Encoding::Ascii) {
            row_offset_ = input_.offset();
            return true;
        }
        std::string_view line;
        do {
            if (!next_line(&line)) return fail("the file ends before " + where() + " (ascii body)");
            words_ = io::split_words(line, 0);
        } while (words_.empty());
        next_word_ = 0;
        return true;
    }

    /// Ascii: no values may be left on the row's line.
    bool end_row() {
        if (encoding_ == Encoding::Ascii && next_word_ != words_.size()) {
            return fail(where() + " has " + std::to_string(words_.size() - next_word_) + " values too many");
        }
        return true;
    }

    bool read(ScalarType type, double* out) {
        if (encoding_ == Encoding::Ascii) {
            if (next_word_ >= words_.size()) return fail(where() + " has too few values");
            std::string_view word = words_[next_word_++];
            if (!io::parse_finite(word, out)) return fail(where() + ": value " + io::quote(word) + " is not a finite number");
            if (is_integer(type)) {
                if (*out != std::floor(*out)) return fail(where() + ": value " + io::quote(word) + " is not an integer");
                double low, high;
                integer_range(type, &low, &high);
                if (*out < low || *out > high) {
                    return fail(where() + ": value " + io::quote(word) + " is outside the declared type's range [" +
                                integer_text(low) + ", " + integer_text(high) + "]");
                }
            }
            return true;
        }
        const std::size_t size = size_of(type);
        if (input_.available().size() < size && !input_.fill(size)) {
            const std::uint64_t offset = input_.offset();
            return fail("binary PLY is truncated in " + where() + " (byte " + std::to_string(offset) + " of " +
                        std::to_string(offset + input_.available().size()) + ")");
        }
        unsigned char b[8];
        std::memcpy(b, input_.available().data(), size);
        input_.consume(size);
        if (encoding_ == Encoding::BigEndian) {
            for (std::size_t i = 0; i < size / 2; ++i) std::swap(b[i], b[size - 1 - i]);
        }
        *out = decode(type, b);  // the host is little endian (x86, arm64, wasm)
        if (!std::isfinite(*out)) return fail(where() + " (byte " + std::to_string(row_offset_) + "): a value is not a finite number");
        return true;
    }

    /// The body must end with the last element.
    bool finish() {
        if (encoding_ != Encoding::Ascii) {
            const std::uint64_t end = input_.offset();
            std::uint64_t extra = 0;
            while (input_.fill(1)) {  // a stream: count what is left
                extra += input_.available().size();
                input_.consume(input_.available().size());
            }
            if (extra != 0) {
                return fail("binary PLY has " + std::to_string(extra) + " bytes after the last element (byte " +
                            std::to_string(end) + ")");
            }
            return true;
        }
        std::string_view line;
        while (next_line(&line)) {
            if (!io::split_words(line, 0).empty()) return fail("content after the last element");
        }
        return true;
    }

    bool fail(const std::string& what) {
        if (error_.empty()) {
            error_ = encoding_ == Encoding::Ascii ? io::at_line(source_, line_base_ + lines_, what) : source_ + ": " + what;
        }
        return false;
    }
    const std::string& error() const { return error_; }

private:
    /// The row being read, for messages ("vertex 12"), put together only when one is written.
    std::string where() const { return element_label(element_->name) + " " + std::to_string(row_); }

    /// The next line of an ascii body, without its line end (as io::LineCursor reads lines);
    /// false at the end of the input. The line stays valid until the next call.
    bool next_line(std::string_view* line) {
        std::size_t scanned = 0;
        for (;;) {
            const std::string_view text = input_.available();
            std::size_t end = scanned;
            while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
            // A "\r" at the end of what was read may be the start of "\r\n": read on first.
            if (end < text.size() && (text[end] == '\n' || end + 1 < text.size() || input_.at_end())) {
                std::size_t next = end + 1;
                if (text[end] == '\r' && next < text.size() && text[next] == '\n') ++next;
                *line = text.substr(0, end);
                input_.consume(next);
                ++lines_;
                return true;
            }
            if (input_.at_end()) {
                if (text.empty()) return false;
                *line = text;  // the last line, without a line end
                input_.consume(text.size());
                ++lines_;
                return true;
            }
            scanned = end;
            input_.fill(text.size() + 1);
        }
    }

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

    io::ChunkedInput& input_;
    Encoding encoding_;
    const std::string& source_;
    std::uint64_t row_offset_ = 0;  ///< binary: where the current row starts
    std::size_t line_base_;         ///< ascii: the lines before the body
    std::size_t lines_ = 0;         ///< ascii: the body's lines read so far
    std::vector<std::string_view> words_;
    std::size_t next_word_ = 0;
    const Element* element_ = nullptr;
    std::uint64_t row_ = 0;
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

struct io::PlyReader::State {
    State(io::ChunkedInput& in, const std::string& name, bool faces) : input(in), source(name), faces_required(faces) {}

    io::ChunkedInput& input;
    const std::string source;
    const bool faces_required;
    Header header;
    // The vertex element's x y z (scalars) and the face element's index list.
    const Element* vertex = nullptr;
    const Element* face = nullptr;
    int axis_property[3] = {-1, -1, -1};
    int index_property = -1;
    std::unique_ptr<BodyReader> body;
    std::size_t element = 0;  ///< where reading goes on: row `row` of element `element`
    std::uint64_t row = 0;
    bool done = false;
    std::string error;
    std::vector<std::uint32_t> corners;

    bool fail(std::string message) {
        error = std::move(message);
        return false;
    }

    /// Finds the vertex and face elements and checks that they have what a mesh needs.
    bool find_elements() {
        for (const Element& element : header.elements) {
            if (element.name == "vertex") {
                vertex = &element;
                const char* axes[3] = {"x", "y", "z"};
                for (int axis = 0; axis < 3; ++axis) {
                    axis_property[axis] = find_property(element, {axes[axis]});
                    if (axis_property[axis] < 0 || element.properties[axis_property[axis]].is_list) {
                        return fail(source + ": the PLY vertex element has no scalar property \"" + axes[axis] + "\"");
                    }
                }
            } else if (element.name == "face") {
                face = &element;
                index_property = find_property(element, {"vertex_indices", "vertex_index"});
                if (index_property < 0 || !element.properties[index_property].is_list ||
                    !is_integer(element.properties[index_property].type)) {
                    return fail(source + ": the PLY face element has no integer list property \"vertex_indices\"");
                }
            }
        }
        if (!vertex) return fail(source + ": the PLY header declares no \"vertex\" element");
        if (!face && faces_required) return fail(source + ": the PLY header declares no \"face\" element");
        if (vertex->count > 0xffffffffULL) return fail(source + ": too many vertices for 32-bit indices");
        return true;
    }

    /// Reads row `row` of `element`: a vertex's x y z onto *xyz, a face's fan onto *triangles (if
    /// not null); every value is checked.
    bool read_row(const Element& element, std::vector<double>* xyz, std::vector<std::uint32_t>* triangles) {
        if (!body->begin_row(element, row)) return false;
        double point[3] = {0, 0, 0};
        for (std::size_t p = 0; p < element.properties.size(); ++p) {
            const Property& property = element.properties[p];
            if (!property.is_list) {
                double value;
                if (!body->read(property.type, &value)) return false;
                for (int axis = 0; axis < 3; ++axis) {
                    if (&element == vertex && static_cast<int>(p) == axis_property[axis]) point[axis] = value;
                }
                continue;
            }
            double count;
            if (!body->read(property.count_type, &count)) return false;
            const bool is_face_list = &element == face && static_cast<int>(p) == index_property;
            if (count < 0 || (is_face_list && count < 3)) {
                return body->fail(element_label(element.name) + " " + std::to_string(row) + ": " +
                                  (count < 0 ? "a list count is negative: " : "a face needs at least 3 vertices, got ") +
                                  integer_text(count));
            }
            corners.clear();
            for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(count); ++k) {
                double value;
                if (!body->read(property.type, &value)) return false;
                if (!is_face_list) continue;
                if (value < 0 || value >= static_cast<double>(vertex->count)) {
                    return body->fail("face " + std::to_string(row) + ": index " + integer_text(value) +
                                      " out of range (" + std::to_string(vertex->count) + " vertices)");
                }
                corners.push_back(static_cast<std::uint32_t>(value));
            }
            if (is_face_list && triangles) io::append_fan(corners, triangles);
        }
        if (!body->end_row()) return false;
        if (&element == vertex) {  // push_back inlines; a range insert is a call and a memmove
            xyz->push_back(point[0]);
            xyz->push_back(point[1]);
            xyz->push_back(point[2]);
        }
        return true;
    }
};

io::PlyReader::PlyReader(ChunkedInput& input, const std::string& source, bool faces_required)
    : state_(std::make_unique<State>(input, source, faces_required)) {}

io::PlyReader::~PlyReader() = default;

bool io::PlyReader::start() {
    State& s = *state_;
    for (;;) {  // the header, from as many whole lines as it takes
        const std::string_view text = s.input.available();
        const std::size_t length = whole_lines_length(text, s.input.at_end());
        const ReadStatus status =
            read_header(text.substr(0, length), s.input.at_end() && length == text.size(), s.source, &s.header, &s.error);
        if (status == ReadStatus::Failed) return false;
        if (status == ReadStatus::Done) break;
        s.input.fill(2 * text.size() + 1);
    }
    if (!s.find_elements()) return false;
    s.input.consume(s.header.body_offset);
    s.body = std::make_unique<BodyReader>(s.input, s.header, s.source);
    return true;
}

bool io::PlyReader::read(std::uint64_t max_bytes, std::vector<double>* xyz, std::vector<std::uint32_t>* triangles) {
    State& s = *state_;
    const std::uint64_t start = s.input.offset();
    const std::size_t xyz_start = xyz->size();
    for (; s.element < s.header.elements.size(); ++s.element, s.row = 0) {
        const Element& element = s.header.elements[s.element];
        // A binary row without properties holds no bytes: reading 10^18 of them would only spin
        // in a loop. An ascii row is still a line that must be there.
        if (element.properties.empty() && s.header.encoding != Encoding::Ascii) continue;
        while (s.row < element.count) {
            if (!s.read_row(element, xyz, triangles)) return s.fail(s.body->error());
            ++s.row;
            if (xyz->size() != xyz_start && s.input.offset() - start >= max_bytes) return true;
        }
    }
    if (!s.body->finish()) return s.fail(s.body->error());
    s.done = true;
    return true;
}

bool io::PlyReader::done() const { return state_->done; }
std::uint64_t io::PlyReader::vertex_count() const { return state_->vertex ? state_->vertex->count : 0; }
const std::string& io::PlyReader::error() const { return state_->error; }

namespace {

/// The PLY reader on bytes in memory; without `faces_required` a file with no "face" element is
/// a point cloud.
MeshResult read_ply(const std::string& bytes, const std::string& source, bool faces_required) {
    io::ChunkedInput input(bytes);
    io::PlyReader reader(input, source, faces_required);
    if (!reader.start()) return io::mesh_error(reader.error());
    MeshResult mesh;
    // Reserve only what the file could hold, so a lying header cannot allocate gigabytes.
    mesh.xyz.reserve(3 * std::min<std::uint64_t>(reader.vertex_count(), bytes.size() / 3));
    if (!reader.read(~std::uint64_t{0}, &mesh.xyz, &mesh.triangles)) return io::mesh_error(reader.error());
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
