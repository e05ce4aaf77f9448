// glTF 2.0 meshes (.gltf with its buffers, .glb), parsed by tinygltf (gltf_config.hpp): the
// triangle primitives of every mesh the scene's nodes reach, with the node transforms applied.
// Also the .glb writer of a hull (mesh_io.hpp's write_glb).
#include "hullkit/mesh_read.hpp"

#include "gltf_config.hpp"

#include <nlohmann/json.hpp>
#include "mesh_read_internal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <utility>

#if !defined(__EMSCRIPTEN__)
#include <sys/stat.h>
#endif

namespace hullkit {

namespace {

/// A 4x4 matrix in glTF's column-major order: m[4 * column + row].
using Matrix = std::array<double, 16>;

constexpr Matrix kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix out{};
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            double sum = 0;
            for (int k = 0; k < 4; ++k) sum += a[4 * k + row] * b[4 * column + k];
            out[4 * column + row] = sum;
        }
    }
    return out;
}

/// A node's own transform: its matrix, or translation * rotation * scale.
Matrix local_transform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        Matrix m{};
        std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
        return m;
    }
    const double t[3] = {node.translation.size() == 3 ? node.translation[0] : 0.0,
                         node.translation.size() == 3 ? node.translation[1] : 0.0,
                         node.translation.size() == 3 ? node.translation[2] : 0.0};
    const double s[3] = {node.scale.size() == 3 ? node.scale[0] : 1.0, node.scale.size() == 3 ? node.scale[1] : 1.0,
                         node.scale.size() == 3 ? node.scale[2] : 1.0};
    double x = 0, y = 0, z = 0, w = 1;  // a unit quaternion, as glTF requires
    if (node.rotation.size() == 4) {
        x = node.rotation[0];
        y = node.rotation[1];
        z = node.rotation[2];
        w = node.rotation[3];
    }
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    Matrix m{};
    for (int column = 0; column < 3; ++column) {
        for (int row = 0; row < 3; ++row) m[4 * column + row] = r[row][column] * s[column];
    }
    m[12] = t[0];
    m[13] = t[1];
    m[14] = t[2];
    m[15] = 1;
    return m;
}

const char* mode_name(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS: return "POINTS";
        case TINYGLTF_MODE_LINE: return "LINES";
        case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
        default: return "unknown";
    }
}

const char* component_name(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "DOUBLE";
        default: return "unknown";
    }
}

std::size_t component_size(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

/// One line of printable ASCII from tinygltf's messages (several lines, file bytes in them).
std::string one_line(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\n' || c == '\r') {
            if (!out.empty() && out.back() != ' ') out += out.back() == ';' ? " " : "; ";
            continue;
        }
        const unsigned char u = static_cast<unsigned char>(c);
        out += (u >= 0x20 && u < 0x7f) ? c : '?';
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
    if (out.size() > 300) out = out.substr(0, 297) + "...";
    return out;
}

/// What the file-system callbacks share: the caller's loader and what it said.
struct FileContext {
    const ExternalFileLoader* load = nullptr;
    std::string uri;    ///< the first external file that could not be read
    std::string error;  ///< why
};

bool file_exists(const std::string&, void*) { return true; }  // reading it will tell
std::string expand_path(const std::string& path, void*) { return path; }
bool write_file(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
    if (error) *error = "hullkit's glTF reader writes no files";
    return false;
}
bool read_file_callback(std::vector<unsigned char>* out, std::string* error, const std::string& uri, void* user) {
    FileContext& context = *static_cast<FileContext*>(user);
    std::string bytes, why;
    bool ok = false;
    if (context.load && *context.load) {
        ok = (*context.load)(uri, &bytes, &why);
    } else {
        why = "no external files are read here";
    }
    if (!ok) {
        if (context.uri.empty()) {
            context.uri = uri;
            context.error = why;
        }
        if (error) *error = why;
        return false;
    }
    out->assign(bytes.begin(), bytes.end());
    return true;
}

/// Images are never decoded: hullkit wants geometry only.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

/// Skipped primitives, by kind, for the warnings.
struct SkippedPrimitives {
    struct Kind {
        std::uint64_t count = 0;
        std::size_t mesh = 0, primitive = 0;
        std::size_t order = 0;
    };
    std::map<std::string, Kind> kinds;

    void add(const std::string& what, std::size_t mesh, std::size_t primitive) {
        auto [it, inserted] = kinds.try_emplace(what);
        if (inserted) {
            it->second.mesh = mesh;
            it->second.primitive = primitive;
            it->second.order = kinds.size();
        }
        ++it->second.count;
    }
    std::vector<std::string> messages() const {
        std::vector<std::pair<std::size_t, std::string>> ordered;
        for (const auto& [what, kind] : kinds) {
            ordered.emplace_back(kind.order, "skipped " + std::to_string(kind.count) + " " +
                                                 (kind.count == 1 ? "primitive " : "primitives ") + what +
                                                 " (first: mesh " + std::to_string(kind.mesh) + ", primitive " +
                                                 std::to_string(kind.primitive) + ")");
        }
        std::sort(ordered.begin(), ordered.end());
        std::vector<std::string> out;
        for (auto& entry : ordered) out.push_back(std::move(entry.second));
        return out;
    }
};

/// The most node visits (a node reached along several paths counts each time): a hierarchy that
/// shares subtrees can name exponentially many instances in a few bytes.
constexpr std::uint64_t kMaxNodeVisits = std::uint64_t{1} << 20;
/// Vertex indices are uint32; the last value is kept free.
constexpr std::uint64_t kMaxVertices = 0xfffffffeu;

class GltfReader {
public:
    GltfReader(const tinygltf::Model& model, const std::string& source) : model_(model), source_(source) {}

    bool read(MeshResult* out) {
        out_ = out;
        std::vector<int> roots;
        if (model_.defaultScene >= 0) {
            if (static_cast<std::size_t>(model_.defaultScene) >= model_.scenes.size()) {
                return fail("the default scene " + std::to_string(model_.defaultScene) + " does not exist (" +
                            std::to_string(model_.scenes.size()) + " scenes)");
            }
            roots = model_.scenes[static_cast<std::size_t>(model_.defaultScene)].nodes;
        } else if (!model_.scenes.empty()) {
            for (const tinygltf::Scene& scene : model_.scenes) roots.insert(roots.end(), scene.nodes.begin(), scene.nodes.end());
        } else {
            // No scene: every mesh, as it is.
            for (std::size_t m = 0; m < model_.meshes.size(); ++m) {
                if (!add_mesh(static_cast<int>(m), kIdentity)) return false;
            }
            out->warnings = skipped_.messages();
            return true;
        }
        if (!walk(roots)) return false;
        out->warnings = skipped_.messages();
        return true;
    }

    const std::string& error() const { return error_; }

private:
    bool fail(const std::string& what) {
        error_ = source_ + ": " + what;
        return false;
    }

    /// Every node under `roots`, depth first, each with its world transform.
    bool walk(const std::vector<int>& roots) {
        struct Visit {
            int node;
            Matrix parent;
            std::size_t depth;
        };
        std::vector<Visit> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, kIdentity, 0});
        std::uint64_t visits = 0;
        while (!stack.empty()) {
            const Visit visit = stack.back();
            stack.pop_back();
            if (visit.node < 0 || static_cast<std::size_t>(visit.node) >= model_.nodes.size()) {
                return fail("node " + std::to_string(visit.node) + " does not exist (" + std::to_string(model_.nodes.size()) +
                            " nodes)");
            }
            // A path longer than there are nodes repeats one: the hierarchy has a cycle.
            if (visit.depth > model_.nodes.size()) return fail("the node hierarchy has a cycle (through node " + std::to_string(visit.node) + ")");
            if (++visits > kMaxNodeVisits) {
                return fail("the node hierarchy names more than " + std::to_string(kMaxNodeVisits) + " node instances");
            }
            const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(visit.node)];
            const Matrix world = multiply(visit.parent, local_transform(node));
            if (node.mesh >= 0 && !add_mesh(node.mesh, world)) return false;
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
                stack.push_back({*it, world, visit.depth + 1});
            }
        }
        return true;
    }

    bool add_mesh(int mesh_index, const Matrix& transform) {
        if (static_cast<std::size_t>(mesh_index) >= model_.meshes.size()) {
            return fail("mesh " + std::to_string(mesh_index) + " does not exist (" + std::to_string(model_.meshes.size()) +
                        " meshes)");
        }
        const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(mesh_index)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            const std::size_t m = static_cast<std::size_t>(mesh_index);
            if (primitive.mode != -1 && primitive.mode != TINYGLTF_MODE_TRIANGLES) {
                skipped_.add(std::string("of mode ") + mode_name(primitive.mode) + " (" + std::to_string(primitive.mode) +
                                 "), only TRIANGLES are read",
                             m, p);
                continue;
            }
            const auto position = primitive.attributes.find("POSITION");
            if (position == primitive.attributes.end()) {
                skipped_.add("without POSITION", m, p);
                continue;
            }
            where_ = "mesh " + std::to_string(mesh_index) + ", primitive " + std::to_string(p) + ": ";
            const std::size_t first = out_->xyz.size() / 3;
            if (!add_positions(position->second, transform)) return false;
            const std::size_t count = out_->xyz.size() / 3 - first;
            if (!add_triangles(primitive.indices, first, count)) return false;
        }
        return true;
    }

    /// The accessor `index` and its bytes: *data points at its first element, *stride between
    /// elements of `element` bytes.
    bool locate(int index, const char* role, std::size_t element, const tinygltf::Accessor** accessor,
                const unsigned char** data, std::size_t* stride) {
        const std::string name = std::string(role) + " accessor " + std::to_string(index);
        if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) {
            return fail(where_ + name + " does not exist (" + std::to_string(model_.accessors.size()) + " accessors)");
        }
        const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
        *accessor = &a;
        if (a.sparse.isSparse) return fail(where_ + name + " is sparse, which hullkit does not read");
        *data = nullptr;
        *stride = element;
        // Without a buffer view an accessor is all zeros, which only a sparse one would change.
        if (a.bufferView < 0) return fail(where_ + name + " has no buffer view");
        if (static_cast<std::size_t>(a.bufferView) >= model_.bufferViews.size()) {
            return fail(where_ + name + ": buffer view " + std::to_string(a.bufferView) + " does not exist");
        }
        const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size()) {
            return fail(where_ + name + ": buffer " + std::to_string(view.buffer) + " does not exist");
        }
        const std::vector<unsigned char>& buffer = model_.buffers[static_cast<std::size_t>(view.buffer)].data;
        if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
            return fail(where_ + name + ": buffer view " + std::to_string(a.bufferView) + " (bytes " +
                        std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) + ") runs past the end of buffer " +
                        std::to_string(view.buffer) + " (" + std::to_string(buffer.size()) + " bytes)");
        }
        if (view.byteStride != 0) {
            if (view.byteStride < element) {
                return fail(where_ + name + ": byte stride " + std::to_string(view.byteStride) + " is less than an element (" +
                            std::to_string(element) + " bytes)");
            }
            *stride = view.byteStride;
        }
        if (a.count > 0) {
            const std::size_t length = view.byteLength;
            if (a.byteOffset > length || length - a.byteOffset < element ||
                (a.count - 1) > (length - a.byteOffset - element) / *stride) {
                return fail(where_ + name + ": " + std::to_string(a.count) + " elements run past the end of buffer view " +
                            std::to_string(a.bufferView) + " (" + std::to_string(length) + " bytes)");
            }
        }
        *data = buffer.data() + view.byteOffset + a.byteOffset;
        return true;
    }

    bool add_positions(int index, const Matrix& m) {
        const tinygltf::Accessor* a = nullptr;
        const std::string name = "POSITION accessor " + std::to_string(index);
        if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) {
            return fail(where_ + name + " does not exist (" + std::to_string(model_.accessors.size()) + " accessors)");
        }
        const tinygltf::Accessor& probe = model_.accessors[static_cast<std::size_t>(index)];
        if (probe.type != TINYGLTF_TYPE_VEC3) return fail(where_ + name + " is not of type VEC3");
        const int type = probe.componentType;
        const std::size_t size = component_size(type);
        if (size == 0 || type == TINYGLTF_COMPONENT_TYPE_INT || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
            return fail(where_ + name + " has components of type " + component_name(type) + " (" + std::to_string(type) +
                        "); positions are FLOAT, or BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT (normalized or not)");
        }
        const unsigned char* data = nullptr;
        std::size_t stride = 0;
        if (!locate(index, "POSITION", 3 * size, &a, &data, &stride)) return false;
        const std::uint64_t before = out_->xyz.size() / 3;
        if (a->count > kMaxVertices - before) {
            return fail(where_ + "more than " + std::to_string(kMaxVertices) + " vertices in all");
        }
        out_->xyz.reserve(out_->xyz.size() + 3 * a->count);
        for (std::size_t i = 0; i < a->count; ++i) {
            double p[3] = {0, 0, 0};
            if (data) {
                const unsigned char* element = data + i * stride;
                for (int k = 0; k < 3; ++k) p[k] = component(element + k * size, type, a->normalized);
            }
            for (int k = 0; k < 3; ++k) {
                if (!std::isfinite(p[k])) {
                    return fail(where_ + name + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
                }
            }
            for (int row = 0; row < 3; ++row) {
                out_->xyz.push_back(m[row] * p[0] + m[4 + row] * p[1] + m[8 + row] * p[2] + m[12 + row]);
            }
        }
        return true;
    }

    /// One component as a double: a float as it is, an integer as it is or, normalized, as glTF
    /// maps it to [0, 1] or [-1, 1].
    static double component(const unsigned char* at, int type, bool normalized) {
        switch (type) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                float value;
                std::memcpy(&value, at, 4);
                return value;
            }
            case TINYGLTF_COMPONENT_TYPE_BYTE: {
                const double value = static_cast<std::int8_t>(at[0]);
                return normalized ? std::max(value / 127.0, -1.0) : value;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? at[0] / 255.0 : at[0];
            case TINYGLTF_COMPONENT_TYPE_SHORT: {
                std::int16_t value;
                std::memcpy(&value, at, 2);
                return normalized ? std::max(value / 32767.0, -1.0) : value;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                std::uint16_t value;
                std::memcpy(&value, at, 2);
                return normalized ? value / 65535.0 : value;
            }
            default: return 0;
        }
    }

    bool add_triangles(int index, std::size_t first, std::size_t count) {
        if (index < 0) {  // not indexed: every three vertices are a triangle
            if (count % 3 != 0) {
                return fail(where_ + std::to_string(count) + " vertices without indices are not whole triangles (a multiple of 3)");
            }
            for (std::size_t i = 0; i < count; ++i) out_->triangles.push_back(static_cast<std::uint32_t>(first + i));
            return true;
        }
        const std::string name = "indices accessor " + std::to_string(index);
        if (static_cast<std::size_t>(index) >= model_.accessors.size()) {
            return fail(where_ + name + " does not exist (" + std::to_string(model_.accessors.size()) + " accessors)");
        }
        const tinygltf::Accessor& probe = model_.accessors[static_cast<std::size_t>(index)];
        const int type = probe.componentType;
        if (probe.type != TINYGLTF_TYPE_SCALAR) return fail(where_ + name + " is not of type SCALAR");
        if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
            return fail(where_ + name + " has components of type " + component_name(type) + " (" + std::to_string(type) +
                        "); indices are UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
        }
        const std::size_t size = component_size(type);
        const tinygltf::Accessor* a = nullptr;
        const unsigned char* data = nullptr;
        std::size_t stride = 0;
        if (!locate(index, "indices", size, &a, &data, &stride)) return false;
        if (a->count % 3 != 0) return fail(where_ + name + ": " + std::to_string(a->count) + " indices are not whole triangles (a multiple of 3)");
        out_->triangles.reserve(out_->triangles.size() + a->count);
        for (std::size_t i = 0; i < a->count; ++i) {
            std::uint32_t value = 0;
            if (data) {
                const unsigned char* at = data + i * stride;
                if (size == 1) {
                    value = at[0];
                } else if (size == 2) {
                    std::uint16_t v;
                    std::memcpy(&v, at, 2);
                    value = v;
                } else {
                    std::memcpy(&value, at, 4);
                }
            }
            if (value >= count) {
                return fail(where_ + name + ": index " + std::to_string(value) + " (element " + std::to_string(i) +
                            ") out of range (" + std::to_string(count) + " vertices)");
            }
            out_->triangles.push_back(static_cast<std::uint32_t>(first + value));
        }
        return true;
    }

    const tinygltf::Model& model_;
    const std::string& source_;
    MeshResult* out_ = nullptr;
    std::string where_;
    std::string error_;
    SkippedPrimitives skipped_;
};

/// Checks JSON syntax without exceptions (the WebAssembly build cannot catch them); keeps
/// nlohmann's message for the first error.
struct JsonCheck : nlohmann::json_sax<nlohmann::json> {
    std::string message;
    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return true; }
    bool key(string_t&) override { return true; }
    bool end_object() override { return true; }
    bool start_array(std::size_t) override { return true; }
    bool end_array() override { return true; }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) override {
        message = error.what();
        // "[json.exception.parse_error.101] parse error at line 1, ...": without the tag.
        const std::size_t tag = message.find("] ");
        if (message.rfind("[json.exception.", 0) == 0 && tag != std::string::npos) message = message.substr(tag + 2);
        return false;
    }
};

/// Empty if `text` is JSON; else why not.
std::string json_problem(const char* begin, const char* end) {
    JsonCheck check;
    if (nlohmann::json::sax_parse(begin, end, &check, nlohmann::json::input_format_t::json, true) && check.message.empty()) {
        return {};
    }
    return check.message.empty() ? "not JSON" : check.message;
}

std::uint32_t read_u32(const std::string& bytes, std::size_t at) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data()) + at;
    return b[0] | (b[1] << 8) | (b[2] << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
}

bool starts_like_glb(const std::string& bytes) { return bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0; }

}  // namespace

ExternalFileLoader files_next_to(const std::string& source) {
#if defined(__EMSCRIPTEN__)
    (void)source;
    return {};  // no file system in the browser: a .glb, or a .gltf with data: URIs
#else
    const std::size_t slash = source.find_last_of('/');
    const std::string directory = slash == std::string::npos ? "" : source.substr(0, slash + 1);
    return [directory](const std::string& uri, std::string* bytes, std::string* error) {
        const std::string path = !uri.empty() && uri[0] == '/' ? uri : directory + uri;
        // Regular files only: a buffer named /dev/zero or a FIFO would never end.
        struct stat info {};
        if (stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
            *error = path + ": not a regular file";
            return false;
        }
        return read_file(path, bytes, error);
    };
#endif
}

MeshResult read_gltf_mesh(const std::string& bytes, const std::string& source, const ExternalFileLoader& load) {
    const bool binary = starts_like_glb(bytes);
    if (binary) {
        // tinygltf checks these too; its messages do not say how much is missing.
        if (bytes.size() < 20) {
            return io::mesh_error(source + ": binary glTF is truncated: " + std::to_string(bytes.size()) +
                                  " bytes, a header and a chunk take at least 20");
        }
        const std::uint32_t version = read_u32(bytes, 4), length = read_u32(bytes, 8);
        if (version != 2) return io::mesh_error(source + ": binary glTF version " + std::to_string(version) + ", only 2 is read");
        if (length > bytes.size()) {
            return io::mesh_error(source + ": binary glTF is truncated: its header says " + std::to_string(length) +
                                  " bytes, the file has " + std::to_string(bytes.size()));
        }
    }
    if (bytes.size() > 0xffffffffu) return io::mesh_error(source + ": glTF file larger than 4 GiB");
    if (bytes.empty()) return io::mesh_error(source + ": empty file, expected glTF");
    // The JSON (of a .glb: its first chunk, when it is whole and is JSON) checked before tinygltf.
    const char* json_begin = bytes.data();
    const char* json_end = bytes.data() + bytes.size();
    bool check_json = !binary;
    if (binary) {
        const std::uint32_t chunk = read_u32(bytes, 12);
        check_json = read_u32(bytes, 16) == 0x4E4F534Au && chunk <= bytes.size() - 20;
        json_begin = bytes.data() + 20;
        json_end = json_begin + (check_json ? chunk : 0);
    }
    if (check_json) {
        const std::string problem = json_problem(json_begin, json_end);
        if (!problem.empty()) return io::mesh_error(source + ": not a valid glTF 2.0 file: invalid JSON: " + one_line(problem));
    }

    tinygltf::TinyGLTF loader;
    FileContext context;
    context.load = &load;
    loader.SetFsCallbacks(tinygltf::FsCallbacks{&file_exists, &expand_path, &read_file_callback, &write_file, &context});
    loader.SetImageLoader(&skip_image, nullptr);
    tinygltf::Model model;
    std::string error, warning;
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                  static_cast<unsigned int>(bytes.size()), "")
                    : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), static_cast<unsigned int>(bytes.size()), "");
    } catch (const std::exception& e) {
        ok = false;
        error = e.what();
    }
    if (!ok) {
        if (!context.uri.empty()) {
            if (!load) {
                return io::mesh_error(source + ": its buffer refers to the external file " + io::quote(context.uri) +
                                      ", which cannot be read here: use a .glb, or a .gltf with its buffers embedded as data: URIs");
            }
            return io::mesh_error(source + ": cannot read its buffer file " + io::quote(context.uri) + ": " + one_line(context.error));
        }
        const std::string why = one_line(error.empty() ? warning : error);
        return io::mesh_error(source + ": not a valid glTF 2.0 file: " + (why.empty() ? "tinygltf refused it" : why));
    }
    MeshResult result;
    GltfReader reader(model, source);
    if (!reader.read(&result)) return io::mesh_error(reader.error());
    return result;
}

}  // namespace hullkit
