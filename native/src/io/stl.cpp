// STL meshes, ASCII and binary; repeated corners are merged into shared vertices.
#include "hullkit/mesh_read.hpp"

#include "mesh_read_internal.hpp"

#include <cmath>
#include <cstring>
#include <unordered_map>

namespace hullkit {

namespace {

/// Merges corners with exactly the same coordinates into one vertex.
class VertexMerger {
public:
    explicit VertexMerger(MeshResult* mesh) : mesh_(mesh) {}

    std::uint32_t add(double x, double y, double z) {
        // +0.0 (adding 0.0 turns -0 into +0) so that -0 and +0 share a key.
        Key key{bits(x + 0.0), bits(y + 0.0), bits(z + 0.0)};
        auto [it, inserted] = index_.emplace(key, static_cast<std::uint32_t>(mesh_->point_count()));
        if (inserted) mesh_->xyz.insert(mesh_->xyz.end(), {x, y, z});
        return it->second;
    }

private:
    struct Key {
        std::uint64_t x, y, z;
        bool operator==(const Key& other) const { return x == other.x && y == other.y && z == other.z; }
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            std::uint64_t h = k.x * 0x9E3779B97F4A7C15ULL;
            h ^= (k.y + 0x632BE59BD9B4E019ULL + (h << 6) + (h >> 2));
            h ^= (k.z + 0x85157AF5ULL + (h << 6) + (h >> 2));
            return static_cast<std::size_t>(h ^ (h >> 29));
        }
    };
    static std::uint64_t bits(double value) {
        std::uint64_t out;
        std::memcpy(&out, &value, sizeof out);
        return out;
    }

    MeshResult* mesh_;
    std::unordered_map<Key, std::uint32_t, KeyHash> index_;
};

float little_endian_float(const unsigned char* b) {
    std::uint32_t word = b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t{b[3]} << 24);
    float value;
    std::memcpy(&value, &word, sizeof value);
    return value;
}

MeshResult read_binary_stl(const std::string& bytes, const std::string& source) {
    if (bytes.size() < 84) {
        return io::mesh_error(source + ": binary STL is truncated: at least 84 bytes expected (header and triangle count), got " +
                              std::to_string(bytes.size()));
    }
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const std::uint64_t count = data[80] | (data[81] << 8) | (data[82] << 16) | (std::uint64_t{data[83]} << 24);
    const std::uint64_t expected = 84 + 50 * count;
    if (bytes.size() != expected) {
        return io::mesh_error(source + ": binary STL is " + (bytes.size() < expected ? "truncated" : "too long") +
                              ": 84 + 50*N bytes expected (N = " + std::to_string(count) + " triangles: " +
                              std::to_string(expected) + " bytes), got " + std::to_string(bytes.size()));
    }
    MeshResult mesh;
    mesh.triangles.reserve(3 * count);
    VertexMerger merger(&mesh);
    for (std::uint64_t t = 0; t < count; ++t) {
        const unsigned char* record = data + 84 + 50 * t + 12;  // skip the normal
        std::uint32_t corner[3];
        for (int c = 0; c < 3; ++c) {
            double p[3];
            for (int axis = 0; axis < 3; ++axis) {
                p[axis] = little_endian_float(record + 12 * c + 4 * axis);
                if (!std::isfinite(p[axis])) {
                    return io::mesh_error(source + ": triangle " + std::to_string(t) + " (byte " +
                                          std::to_string(84 + 50 * t + 12 + 12 * c + 4 * axis) +
                                          "): coordinate is not a finite number");
                }
            }
            corner[c] = merger.add(p[0], p[1], p[2]);
        }
        mesh.triangles.insert(mesh.triangles.end(), corner, corner + 3);
    }
    return mesh;
}

MeshResult read_ascii_stl(const std::string& text, const std::string& source) {
    MeshResult mesh;
    VertexMerger merger(&mesh);
    io::LineCursor lines(text);
    std::string_view line;
    // Where we are in "solid / facet / outer loop / vertex x3 / endloop / endfacet / endsolid".
    enum class State { BeforeSolid, InSolid, InFacet, InLoop, AfterLoop, AfterSolid } state = State::BeforeSolid;
    std::vector<std::uint32_t> loop;
    auto fail = [&](const std::string& what) { return io::mesh_error(io::at_line(source, lines.line_number(), what)); };
    auto expect = [&](std::string_view got, const char* wanted) {
        return fail("expected \"" + std::string(wanted) + "\", got " + io::quote(got));
    };

    while (lines.next(&line)) {
        std::vector<std::string_view> words = io::split_words(line, 0);
        if (words.empty()) continue;
        const std::string_view word = words[0];
        switch (state) {
            case State::BeforeSolid:
            case State::AfterSolid:
                if (word != "solid") return expect(word, "solid");
                state = State::InSolid;
                break;
            case State::InSolid:
                if (word == "endsolid") {
                    state = State::AfterSolid;
                } else if (word == "facet") {
                    state = State::InFacet;
                } else {
                    return expect(word, "facet");
                }
                break;
            case State::InFacet:
                if (word != "outer" || words.size() != 2 || words[1] != "loop") return expect(line, "outer loop");
                loop.clear();
                state = State::InLoop;
                break;
            case State::InLoop:
                if (word == "endloop") {
                    if (loop.size() < 3) return fail("a facet needs 3 vertices, got " + std::to_string(loop.size()));
                    io::append_fan(loop, &mesh.triangles);
                    state = State::AfterLoop;
                } else if (word == "vertex") {
                    if (words.size() != 4) return fail("expected \"vertex x y z\"");
                    double p[3];
                    for (int axis = 0; axis < 3; ++axis) {
                        if (!io::parse_finite(words[axis + 1], &p[axis])) {
                            return fail("coordinate " + io::quote(words[axis + 1]) + " is not a finite number");
                        }
                    }
                    loop.push_back(merger.add(p[0], p[1], p[2]));
                } else {
                    return expect(word, "vertex");
                }
                break;
            case State::AfterLoop:
                if (word != "endfacet") return expect(word, "endfacet");
                state = State::InSolid;
                break;
        }
    }
    if (state != State::AfterSolid) {
        return io::mesh_error(source + ": ASCII STL ends early (line " + std::to_string(lines.line_number()) +
                              "): no \"endsolid\"");
    }
    return mesh;
}

}  // namespace

MeshResult read_stl_mesh(const std::string& bytes, const std::string& source) {
    const bool ascii = io::looks_like_ascii_stl(bytes) ||
                       (!io::has_binary_stl_size(bytes) && io::starts_with_word(bytes, "solid") &&
                        bytes.find('\0') == std::string::npos);
    return ascii ? read_ascii_stl(bytes, source) : read_binary_stl(bytes, source);
}

}  // namespace hullkit
