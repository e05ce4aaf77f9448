// The hull writers: OFF, OBJ, JSON, xyz and binary glTF (.glb), into a string or streamed to a
// file; the output format names; format_double and format_json_number; match_points. See
// mesh_io.hpp for the formats.
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
#include <unordered_map>

#include "hull/point_key.hpp"

namespace hullkit {

const char* output_format_name(OutputFormat format) {
    switch (format) {
        case OutputFormat::Off: return "off";
        case OutputFormat::Obj: return "obj";
        case OutputFormat::Json: return "json";
        case OutputFormat::Xyz: return "xyz";
        case OutputFormat::Glb: return "glb";
        case OutputFormat::Normals: return "normals";
    }
    return "?";
}

bool parse_output_format(const std::string& name, OutputFormat* out) {
    for (OutputFormat format : {OutputFormat::Off, OutputFormat::Obj, OutputFormat::Json, OutputFormat::Xyz, OutputFormat::Glb,
                                OutputFormat::Normals}) {
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

/// One JSON array of numbers: [a,b,c] (non-finite as null).
void put_json_numbers(TextOut& out, const double* values, int count) {
    out.put('[');
    for (int k = 0; k < count; ++k) {
        if (k) out.put(',');
        out.json_number(values[k]);
    }
    out.put(']');
}

/// Self-contained: "points" holds the hull's vertices, "triangles" and "faces" index "points",
/// "vertices" gives the input index of each point, "equations" the plane of each triangle.
void put_json(TextOut& out, PointSpan points, const Hull& hull, InputIndex id) {
    const VertexPositions position(points, hull);
    const std::vector<double> equations = plane_equations(points, hull);
    out.reserve(80 * hull.vertices.size() + 120 * hull.face_count() + 64);
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
        out.uint(position.of(hull.triangles[i]));
        out.put(',');
        out.uint(position.of(hull.triangles[i + 1]));
        out.put(',');
        out.uint(position.of(hull.triangles[i + 2]));
        out.put(']');
        out.record_done();
    }
    out.put("],\"points\":[");
    for (std::size_t i = 0; i < hull.vertices.size(); ++i) {
        if (i) out.put(',');
        put_json_numbers(out, points[hull.vertices[i]], 3);
        out.record_done();
    }
    out.put("],\"equations\":[");
    for (std::size_t t = 0; t < hull.face_count(); ++t) {
        if (t) out.put(',');
        put_json_numbers(out, &equations[4 * t], 4);
        out.record_done();
    }
    out.put(']');
    if (!hull.face_offsets.empty()) {  // merge_coplanar: the faces as polygons, indices into "points"
        out.put(",\"faces\":[");
        for (std::size_t f = 0; f + 1 < hull.face_offsets.size(); ++f) {
            if (f) out.put(',');
            out.put('[');
            for (std::uint32_t k = hull.face_offsets[f]; k < hull.face_offsets[f + 1]; ++k) {
                if (k > hull.face_offsets[f]) out.put(',');
                out.uint(position.of(hull.face_vertices[k]));
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

/// The plane of each face, qconvex's `n` layout: "4" (the dimension plus one), the face count, then
/// "nx ny nz offset" a line. Faces: the merged polygons (each from its first three corners, never
/// collinear in a convex polygon) when the hull has them, else the triangles.
void put_normals(TextOut& out, PointSpan points, const Hull& hull) {
    const VertexPositions validate(points, hull);
    std::vector<double> equations;
    if (hull.face_offsets.empty()) {
        equations = plane_equations(points, hull);
    } else {
        std::vector<std::uint32_t> firsts;
        for (std::size_t f = 0; f + 1 < hull.face_offsets.size(); ++f) {
            if (hull.face_offsets[f + 1] - hull.face_offsets[f] < 3) throw std::invalid_argument("a face has fewer than 3 corners");
            firsts.insert(firsts.end(), hull.face_vertices.begin() + hull.face_offsets[f],
                          hull.face_vertices.begin() + hull.face_offsets[f] + 3);
        }
        equations = plane_equations(points, firsts.data(), firsts.size() / 3);
    }
    out.reserve(80 * (equations.size() / 4) + 16);
    out.put("4\n");
    out.uint(equations.size() / 4);
    out.put('\n');
    for (std::size_t k = 0; k < equations.size(); k += 4) {
        out.number(equations[k]);
        for (int c = 1; c < 4; ++c) {
            out.put(' ');
            out.number(equations[k + c]);
        }
        out.put('\n');
        out.record_done();
    }
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
        case OutputFormat::Normals: return put_normals(out, points, hull);
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

std::string write_normals(PointSpan points, const Hull& hull) {
    return to_text([&](TextOut& out) { put_normals(out, points, hull); });
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
