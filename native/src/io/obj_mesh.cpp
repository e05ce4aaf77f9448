// OBJ meshes: vertices and faces, other records skipped (unknown ones with a warning).
#include "hullkit/mesh_read.hpp"

#include "mesh_read_internal.hpp"

namespace hullkit {

MeshResult read_obj_mesh(const std::string& text, const std::string& source) {
    MeshResult result;
    io::LineCursor lines(text);
    std::string_view line;
    std::vector<std::uint32_t> corners;
    // A positive index may name a vertex defined further down, so those are checked at the end,
    // against the line they came from.
    struct Pending {
        std::size_t line;
        std::int64_t index;
    };
    std::vector<Pending> forward;
    io::SkippedRecords skipped;
    auto fail = [&](const std::string& what) { return io::mesh_error(io::at_line(source, lines.line_number(), what)); };

    while (lines.next(&line)) {
        std::vector<std::string_view> words = io::split_words(line, '#');
        if (words.empty()) continue;
        const std::string_view record = words[0];
        if (record == "v") {
            // "v x y z", "v x y z w" or the common colour extension "v x y z r g b".
            if (words.size() != 4 && words.size() != 5 && words.size() != 7) {
                return fail("a vertex needs 3 coordinates (\"v x y z\"), got " + std::to_string(words.size() - 1) +
                            " values");
            }
            for (int axis = 1; axis <= 3; ++axis) {
                double value;
                if (!io::parse_finite(words[axis], &value)) {
                    return fail("coordinate " + io::quote(words[axis]) + " is not a finite number");
                }
                result.xyz.push_back(value);
            }
        } else if (record == "f") {
            if (words.size() < 4) {
                return fail("a face needs at least 3 vertices, got " + std::to_string(words.size() - 1));
            }
            corners.clear();
            const std::int64_t defined = static_cast<std::int64_t>(result.point_count());
            for (std::size_t k = 1; k < words.size(); ++k) {
                // "i", "i/t", "i//n", "i/t/n": the vertex index is the part before the first slash.
                std::string_view corner = words[k].substr(0, words[k].find('/'));
                std::int64_t index;
                if (!io::parse_integer(corner, &index) || index == 0) {
                    return fail("face corner " + io::quote(words[k]) + " is not a vertex index (1-based, or negative)");
                }
                if (index < 0) {
                    if (-index > defined) {
                        return fail("face index " + std::to_string(index) + " out of range (" + std::to_string(defined) +
                                    " vertices so far)");
                    }
                    index = defined + index;  // -1 is the last vertex read
                } else {
                    index -= 1;
                    if (index >= defined) forward.push_back({lines.line_number(), index});
                }
                if (index > 0xfffffffeLL) return fail("face index " + io::quote(corner) + " is too large");
                corners.push_back(static_cast<std::uint32_t>(index));
            }
            io::append_fan(corners, &result.triangles);
        } else if (!io::is_known_obj_record(record)) {
            // As three.js's OBJLoader and tinyobjloader do: skip it (FCL's meshes start with a
            // "V F" count line such as "648 1292"), and say so in the result's warnings.
            skipped.add(record, lines.line_number());
        }
    }
    const std::int64_t count = static_cast<std::int64_t>(result.point_count());
    for (const Pending& pending : forward) {
        if (pending.index >= count) {
            return io::mesh_error(io::at_line(source, pending.line,
                                              "face index " + std::to_string(pending.index + 1) + " out of range (" +
                                                  std::to_string(count) + " vertices)"));
        }
    }
    if (result.xyz.empty()) return io::mesh_error(source + ": no vertices (\"v x y z\" lines), expected an OBJ mesh");
    result.warnings = skipped.messages("unknown OBJ record");
    return result;
}

}  // namespace hullkit
