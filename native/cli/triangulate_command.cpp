// `hullkit triangulate`: reading polygons and planar graphs (x y rings, Triangle's .poly, GeoJSON),
// argument parsing (CLI11) and writing around hullkit::triangulate_polygon,
// hullkit::constrained_delaunay (its domain and quality options). No geometry here.
#include "triangulate_command.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cli_io.hpp"
#include "hullkit/constrained.hpp"
#include "hullkit/mesh_io.hpp"
#include "svg.hpp"

namespace hullkit_cli {
namespace {

const char* const kUsage =
    R"(Usage: hullkit triangulate [INPUT|-] [-o FILE] [--format FORMAT]
                           [--fill evenodd|nonzero] [--convex] [--stats]
                           [--min-angle DEG] [--max-area A] [--conforming]
                           [--max-steiner N] [--keep-segments boundary|all]
                           [--region-attributes] [--triangle-areas FILE]

Triangulates polygons with holes, or a planar straight-line graph, exactly: a
constrained Delaunay triangulation in which every ring edge or segment is an
edge (split where a point lies on it; where two cross, at their exactly computed
crossing rounded to the nearest double, which is added to the points) and every
other edge is as Delaunay as the segments allow. No triangle overlaps another or
has zero area, whatever the input.

Input (the format from the file name, else the content):
  x y rings       one vertex per line ("x y" or "x,y"), a blank line between
                  rings; the first ring is the outline, the others holes, in
                  any orientation and nesting ('#' starts a comment). Rings are
                  closed for you; repeating the first vertex is harmless
  GeoJSON         a Polygon, MultiPolygon, Feature or FeatureCollection of them
                  (.json, .geojson, or text starting with '{')
  Triangle .poly  vertices, segments and hole points, as Triangle reads them:
                  the exterior (reached from the hull without crossing a
                  segment) and the region around each hole point are removed;
                  with --convex the exterior is kept (Triangle's -c); its
                  regions' area bounds apply, and their attributes with
                  --region-attributes
  Triangle .node  vertices: their Delaunay triangulation (Triangle without -p)
  Triangle .ele   a mesh to refine (Triangle's -r), its vertices read from the
                  .node file beside it: the domain is its triangles, their
                  boundary is kept and the inside triangulated anew, then
                  refined by --min-angle, --max-area, --triangle-areas
Rings are filled by --fill: evenodd (default; holes whatever their orientation)
or nonzero (GeoJSON's and SVG's nonzero rule: holes wound the other way).

Options:
  -o, --output FILE   write to FILE instead of standard output
  --format FORMAT     off (default): the points (input vertices, then added
                        ones) with z = 0 and the triangles;
                      obj: the same as a Wavefront OBJ (1-based);
                      json: {"points": [[x,y],...], "triangles": [[i,j,k],...],
                        "halfedges", "constrained" (1 per half-edge on a
                        segment), "added", "duplicates": [[i, first],...]};
                      svg: a picture, segment edges drawn dark;
                      node: Triangle's .node and .ele files (-o BASE.node or
                        BASE.ele writes both)
                      without --format, an output FILE ending in .off, .obj,
                      .json, .svg, .node or .ele selects that format
  --fill RULE         evenodd (default) or nonzero, for rings and GeoJSON
  --convex            .poly input: keep the triangles outside the segments too
                      (the whole convex hull, hole regions still removed)
  --min-angle DEG     a quality mesh (Triangle's -q): add points until every
                      angle is at least DEG degrees, 0 to 34 (default 0: no
                      angle bound; up to 28.6 refinement always finishes);
                      angles between segments smaller than DEG stay (counted
                      as unrefined in --stats)
  --max-area A        no triangle larger than A (Triangle's -a; default 0:
                      no area bound)
  --conforming        every triangle Delaunay: segments split as needed
                      (Triangle's -D)
  --keep-segments WHICH
                      boundary: refinement adds no point on the boundary's
                      segments (rings, a .poly's outline and holes; Triangle's
                      -Y); all: on no segment (-YY); default: any segment
                      may be split. Where a circumcentre lies beyond a kept
                      one, a triangle above --max-area gets its centroid, one
                      with only a small angle is left (counted as unrefined)
  --region-attributes .poly input: give each triangle the attribute of the
                      region holding it, 0 outside every region (Triangle's
                      -A): an attribute column in the .ele file, "attributes"
                      (one per triangle) in JSON; the last of several region
                      points in one region wins
  --triangle-areas FILE
                      .ele input: each triangle's own area bound from
                      Triangle's .area file ("index area" lines; 0 or less:
                      none; Triangle's -ra); every edge of the mesh is then
                      kept (default: none)
  --max-steiner N     a whole number from 0 to 4000000000: fail once
                      refinement has added N points (Triangle's -S; default
                      0: no cap)
  --stats             print one JSON line to standard error: points, added,
                      segments, crossings, steiner (points added by
                      refinement), unrefined, triangles, seconds
  -h, --help          show this help

Exit status: 0 on success, 2 on a usage or input problem (one line on standard
error, naming the line of the file).
)";

enum class Format { Off, Obj, Json, Svg, Node };

bool parse_format(std::string name, Format* out) {
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (name == "off") *out = Format::Off;
    else if (name == "obj") *out = Format::Obj;
    else if (name == "json") *out = Format::Json;
    else if (name == "svg") *out = Format::Svg;
    else if (name == "node" || name == "ele") *out = Format::Node;
    else return false;
    return true;
}

std::string extension_of(const std::string& path) {
    const std::size_t dot = path.find_last_of("./");
    if (dot == std::string::npos || path[dot] != '.') return "";
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

/// What the input holds: points with, per point, the line it came from; and either ring starts
/// (rings) or segments and hole points (.poly).
struct Input {
    std::vector<double> xy;
    std::vector<std::size_t> line;  ///< per point, its 1-based line (0 for GeoJSON)
    bool poly = false;
    std::vector<std::uint32_t> ring_starts;
    std::vector<std::uint32_t> segments;
    std::vector<std::size_t> segment_line;
    std::vector<double> holes;
    std::vector<hullkit::RegionSeed> regions;  ///< a .poly's regional area bounds
    std::vector<double> region_attributes;     ///< and their attributes
    bool mesh = false;                          ///< a .ele (and .node) to refine
    std::vector<std::uint32_t> triangles;       ///< its triangles, 0-based
    std::vector<std::size_t> triangle_line;     ///< per triangle, its line of the .ele
    std::vector<std::uint64_t> triangle_number; ///< per triangle, its number in the .ele
    std::uint64_t node_first = 0;               ///< the .node's first vertex number
    std::string node_source;                    ///< the .node file beside it
    bool whole_hull = false;                    ///< a .node alone: no segments, the whole hull
};

/// The numbers on a line, before any '#'; commas count as spaces. False if a word is not a number.
bool numbers_of(const std::string& raw, std::vector<double>* out) {
    out->clear();
    std::string text = raw.substr(0, raw.find('#'));
    for (char& c : text)
        if (c == ',' || c == '\r' || c == '\t') c = ' ';
    std::istringstream words(text);
    std::string word;
    while (words >> word) {
        char* end = nullptr;
        const double v = std::strtod(word.c_str(), &end);
        if (end == word.c_str() || *end != '\0') return false;
        out->push_back(v);
    }
    return true;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t begin = 0;
    while (begin <= text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string::npos) end = text.size();
        lines.push_back(text.substr(begin, end - begin));
        begin = end + 1;
    }
    return lines;
}

void read_rings(const std::string& text, const std::string& source, Input* in) {
    const std::vector<std::string> lines = lines_of(text);
    std::vector<double> v;
    bool ring_open = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string where = source + " line " + std::to_string(i + 1);
        if (!numbers_of(lines[i], &v)) throw UsageError(where + ": expected \"x y\", got \"" + lines[i] + "\"");
        if (v.empty()) {
            // A blank line ends a ring (a comment line does not).
            if (lines[i].find('#') == std::string::npos) ring_open = false;
            continue;
        }
        if (v.size() != 2) throw UsageError(where + ": expected 2 numbers (x y), got " + std::to_string(v.size()));
        if (!ring_open && !in->xy.empty()) in->ring_starts.push_back(static_cast<std::uint32_t>(in->xy.size() / 2));
        ring_open = true;
        in->xy.push_back(v[0]), in->xy.push_back(v[1]);
        in->line.push_back(i + 1);
    }
}

/// Triangle's files (.poly, .node, .ele, .area): lines of numbers, '#' comments, read one after
/// another; errors name the file and line.
class TriangleFile {
public:
    TriangleFile(const std::string& text, std::string source) : lines_(lines_of(text)), source_(std::move(source)) {}
    /// The next line with numbers on it (they are in v), its 1-based number.
    std::size_t next(const char* what) {
        for (; i_ < lines_.size(); ++i_) {
            if (!numbers_of(lines_[i_], &v))
                throw UsageError(at(i_ + 1) + ": not numbers in the " + what + ": \"" + lines_[i_] + "\"");
            if (!v.empty()) return ++i_;
        }
        throw UsageError(source_ + ": the file ends before the " + std::string(what));
    }
    std::uint64_t whole(double value, std::size_t line, const char* what) const {
        if (!(value >= 0 && value < 4294967296.0 && value == static_cast<double>(static_cast<std::uint64_t>(value))))
            throw UsageError(at(line) + ": " + what + " must be a whole number, got " + hullkit::format_double(value));
        return static_cast<std::uint64_t>(value);
    }
    /// Whether a line from here on holds numbers (an optional section follows).
    bool more() {
        std::vector<double> w;
        for (std::size_t j = i_; j < lines_.size(); ++j)
            if (numbers_of(lines_[j], &w) && !w.empty()) return true;
        return false;
    }
    /// No numbers after the last section.
    void end(const char* after) {
        std::vector<double> w;
        for (std::size_t j = i_; j < lines_.size(); ++j) {
            if (numbers_of(lines_[j], &w) && !w.empty()) throw UsageError(at(j + 1) + ": unexpected numbers after the " + after);
        }
    }
    /// `count` lines "index x y ...", numbered one after another from the first's index (returned).
    std::uint64_t vertices(std::uint64_t count, Input* in) {
        std::int64_t first_index = -1;
        for (std::uint64_t k = 0; k < count; ++k) {
            const std::size_t line = next("vertices");
            if (v.size() < 3) throw UsageError(at(line) + ": expected \"index x y\"");
            const std::uint64_t index = whole(v[0], line, "a vertex index");
            if (first_index < 0) first_index = static_cast<std::int64_t>(index);
            if (index != static_cast<std::uint64_t>(first_index) + k)
                throw UsageError(at(line) + ": vertex index " + std::to_string(index) + ", expected " +
                                 std::to_string(first_index + static_cast<std::int64_t>(k)));
            in->xy.push_back(v[1]), in->xy.push_back(v[2]);
            in->line.push_back(line);
        }
        return first_index < 0 ? 0 : static_cast<std::uint64_t>(first_index);
    }
    /// `arity` vertex numbers from v[1] on (numbered from `first`, `count` of them), made 0-based.
    void corners(std::size_t line, int arity, std::uint64_t first, std::uint64_t count, const char* what,
                 std::vector<std::uint32_t>* out) const {
        if (v.size() < static_cast<std::size_t>(arity) + 1)
            throw UsageError(at(line) + ": expected an index and " + std::to_string(arity) + " vertex numbers");
        for (int k = 1; k <= arity; ++k) {
            const std::uint64_t vertex = whole(v[k], line, what);
            if (vertex < first || vertex - first >= count)
                throw UsageError(at(line) + ": " + what + " " + std::to_string(vertex) + " is not one of the " +
                                 std::to_string(count) + " vertices (numbered from " + std::to_string(first) + ")");
            out->push_back(static_cast<std::uint32_t>(vertex - first));
        }
    }
    std::string at(std::size_t line) const { return source_ + " line " + std::to_string(line); }
    std::vector<double> v;

private:
    std::vector<std::string> lines_;
    std::string source_;
    std::size_t i_ = 0;
};

void read_poly(const std::string& text, const std::string& source, Input* in) {
    in->poly = true;
    TriangleFile file(text, source);
    const std::vector<double>& v = file.v;
    std::size_t line = file.next("header (vertex count, dimension, attributes, markers)");
    const std::uint64_t count = file.whole(v[0], line, "the vertex count");
    if (count == 0) throw UsageError(file.at(line) + ": vertices in a separate .node file are not supported; list them in the .poly file");
    if (v.size() > 1 && v[1] != 2) throw UsageError(file.at(line) + ": the dimension must be 2");
    // Attribute and marker counts: checked to be whole numbers; the values after x y are not used.
    if (v.size() > 2) file.whole(v[2], line, "the attribute count");
    if (v.size() > 3) file.whole(v[3], line, "the marker count");
    const std::uint64_t first_index = file.vertices(count, in);
    line = file.next("segment header");
    const std::uint64_t segments = file.whole(v[0], line, "the segment count");
    for (std::uint64_t k = 0; k < segments; ++k) {
        line = file.next("segments");
        file.corners(line, 2, first_index, count, "segment vertex", &in->segments);
        in->segment_line.push_back(line);
    }
    if (!file.more()) return;  // no hole section: none
    line = file.next("hole header");
    const std::uint64_t holes = file.whole(v[0], line, "the hole count");
    for (std::uint64_t k = 0; k < holes; ++k) {
        line = file.next("holes");
        if (v.size() < 3) throw UsageError(file.at(line) + ": expected \"index x y\"");
        in->holes.push_back(v[1]), in->holes.push_back(v[2]);
    }
    if (!file.more()) return;
    // Regions: "index x y attribute max_area" (a max_area <= 0 is no bound, as Triangle reads it).
    line = file.next("region header");
    const std::uint64_t regions = file.whole(v[0], line, "the region count");
    for (std::uint64_t k = 0; k < regions; ++k) {
        line = file.next("regions");
        if (v.size() < 4) throw UsageError(file.at(line) + ": expected \"index x y attribute [max_area]\"");
        const double area = v.size() >= 5 && v[4] > 0 ? v[4] : 0.0;
        in->regions.push_back({v[1], v[2], area});
        in->region_attributes.push_back(v[3]);
    }
    file.end("regions");
}

/// Triangle's .node: "count 2 [attributes [markers]]", then "index x y ..." lines. Returns the
/// vertex count and sets *first to the first index.
std::uint64_t read_node_vertices(const std::string& text, const std::string& source, Input* in, std::uint64_t* first) {
    TriangleFile node(text, source);
    const std::size_t line = node.next("header (vertex count, dimension, attributes, markers)");
    const std::uint64_t count = node.whole(node.v[0], line, "the vertex count");
    if (node.v.size() > 1 && node.v[1] != 2) throw UsageError(node.at(line) + ": the dimension must be 2");
    *first = node.vertices(count, in);
    node.end("vertices");
    return count;
}

/// A .node alone: the Delaunay triangulation of its vertices (Triangle without -p).
void read_node(const std::string& text, const std::string& source, Input* in) {
    in->poly = true;
    in->whole_hull = true;
    std::uint64_t first = 0;
    read_node_vertices(text, source, in, &first);
}

/// A mesh to refine (Triangle's -r): BASE.ele's triangles over BASE.node's vertices.
void read_node_ele(const std::string& ele_text, const std::string& ele_source, const std::string& node_path, Input* in) {
    in->mesh = true;
    in->node_source = node_path;
    std::uint64_t first = 0;
    const std::uint64_t count = read_node_vertices(read_input(node_path), node_path, in, &first);
    in->node_first = first;
    TriangleFile ele(ele_text, ele_source);
    std::size_t line = 0;
    line = ele.next("header (triangle count, corners per triangle, attributes)");
    const std::uint64_t triangles = ele.whole(ele.v[0], line, "the triangle count");
    if (ele.v.size() > 1 && ele.v[1] != 3)
        throw UsageError(ele.at(line) + ": only 3-corner triangles can be refined, the header says " + hullkit::format_double(ele.v[1]));
    for (std::uint64_t k = 0; k < triangles; ++k) {
        line = ele.next("triangles");
        ele.corners(line, 3, first, count, "corner", &in->triangles);
        in->triangle_line.push_back(line);
        in->triangle_number.push_back(ele.whole(ele.v[0], line, "a triangle number"));
    }
    ele.end("triangles");
}

/// Triangle's .area file: per triangle of the mesh, its own area bound (<= 0: none).
std::vector<double> read_area(const std::string& path, std::size_t triangles) {
    TriangleFile file(read_input(path), path);
    std::size_t line = file.next("header (triangle count)");
    const std::uint64_t count = file.whole(file.v[0], line, "the triangle count");
    if (count != triangles)
        throw UsageError(file.at(line) + ": " + std::to_string(count) + " areas for a mesh of " + std::to_string(triangles) + " triangles");
    std::vector<double> areas;
    for (std::uint64_t k = 0; k < count; ++k) {
        line = file.next("areas");
        if (file.v.size() < 2) throw UsageError(file.at(line) + ": expected \"index area\"");
        if (!std::isfinite(file.v[1])) throw UsageError(file.at(line) + ": the area is not a finite number");
        areas.push_back(file.v[1]);
    }
    file.end("areas");
    return areas;
}

void add_geojson_polygon(const nlohmann::json& rings, const std::string& where, Input* in) {
    if (!rings.is_array()) throw UsageError(where + ": a Polygon's coordinates must be an array of rings");
    for (std::size_t r = 0; r < rings.size(); ++r) {
        if (!rings[r].is_array()) throw UsageError(where + " ring " + std::to_string(r) + ": not an array of positions");
        if (!in->xy.empty()) in->ring_starts.push_back(static_cast<std::uint32_t>(in->xy.size() / 2));
        for (std::size_t i = 0; i < rings[r].size(); ++i) {
            const nlohmann::json& p = rings[r][i];
            if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number())
                throw UsageError(where + " ring " + std::to_string(r) + " position " + std::to_string(i) + ": not [x, y]");
            in->xy.push_back(p[0].get<double>()), in->xy.push_back(p[1].get<double>());
            in->line.push_back(0);
        }
    }
}

void add_geojson(const nlohmann::json& value, const std::string& where, Input* in) {
    if (!value.is_object() || !value.contains("type")) throw UsageError(where + ": not a GeoJSON object");
    const std::string type = value["type"].is_string() ? value["type"].get<std::string>() : "";
    if (type == "FeatureCollection") {
        const nlohmann::json& features = value["features"];
        if (!features.is_array()) throw UsageError(where + ": a FeatureCollection needs a features array");
        for (std::size_t k = 0; k < features.size(); ++k) add_geojson(features[k], where + " feature " + std::to_string(k), in);
    } else if (type == "Feature") {
        add_geojson(value["geometry"], where, in);
    } else if (type == "Polygon") {
        add_geojson_polygon(value["coordinates"], where, in);
    } else if (type == "MultiPolygon") {
        const nlohmann::json& polygons = value["coordinates"];
        if (!polygons.is_array()) throw UsageError(where + ": a MultiPolygon's coordinates must be an array");
        for (std::size_t k = 0; k < polygons.size(); ++k) add_geojson_polygon(polygons[k], where + " polygon " + std::to_string(k), in);
    } else {
        throw UsageError(where + ": GeoJSON " + (type.empty() ? std::string("without a type") : type) + " is not a Polygon or MultiPolygon");
    }
}

Input read_input_file(const std::string& path) {
    const std::string text = read_input(path);
    const std::string source = path == "-" ? "<stdin>" : path;
    const std::string ext = extension_of(path);
    Input in;
    const std::size_t first = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    if (ext == "poly") {
        read_poly(text, source, &in);
    } else if (ext == "node") {
        read_node(text, source, &in);
    } else if (ext == "ele") {
        read_node_ele(text, source, path.substr(0, path.size() - 3) + "node", &in);
    } else if (ext == "json" || ext == "geojson" || (first != std::string::npos && text[first] == '{')) {
        nlohmann::json value;
        try {
            value = nlohmann::json::parse(text);
        } catch (const nlohmann::json::exception& error) {
            throw UsageError(source + ": not valid JSON (" + error.what() + ")");
        }
        add_geojson(value, source, &in);
    } else {
        read_rings(text, source, &in);
    }
    return in;
}

struct Args {
    std::string input = "-", output;
    Format format = Format::Off;
    hullkit::FillRule fill = hullkit::FillRule::EvenOdd;
    bool convex = false, stats = false, region_attributes = false;
    std::string triangle_areas;  ///< a .area file for a .ele input
    hullkit::QualityOptions quality;
};

bool parse_args(const std::vector<std::string>& argv, Args* args) {
    CLI::App app{"hullkit triangulate", "hullkit triangulate"};
    app.set_help_flag();
    bool help = false;
    std::string format_name, fill_name;
    const auto last = CLI::MultiOptionPolicy::TakeLast;
    app.add_flag("-h,--help", help);
    app.add_option("input", args->input);
    app.add_option("-o,--output", args->output)->multi_option_policy(last);
    app.add_option("--format", format_name)->multi_option_policy(last);
    app.add_option("--fill", fill_name)->multi_option_policy(last);
    app.add_flag("--convex", args->convex);
    app.add_flag("--stats", args->stats);
    app.add_option("--min-angle", args->quality.min_angle)->multi_option_policy(last);
    app.add_option("--max-area", args->quality.max_area)->multi_option_policy(last);
    app.add_flag("--conforming", args->quality.conforming);
    app.add_flag("--region-attributes", args->region_attributes);
    app.add_option("--triangle-areas", args->triangle_areas)->multi_option_policy(last);
    std::string keep_name;
    app.add_option("--keep-segments", keep_name)->multi_option_policy(last);
    unsigned max_steiner = 0;
    add_whole_number_option(app, "--max-steiner", &max_steiner, 0, 4000000000u);
    parse_or_throw(app, argv, "triangulate");
    args->quality.max_steiner_points = max_steiner;
    if (help) {
        std::fputs(kUsage, stdout);
        return false;
    }
    if (app.count("--output") && args->output.empty()) throw UsageError("option --output needs a file name");
    if (app.count("--format")) {
        if (!parse_format(format_name, &args->format)) throw UsageError("unknown format \"" + format_name + "\" (known: off, obj, json, svg, node)");
    } else if (!args->output.empty() && args->output != "-") {
        parse_format(extension_of(args->output), &args->format);
    }
    if (app.count("--keep-segments")) {
        if (keep_name == "boundary") args->quality.keep_segments = 1;
        else if (keep_name == "all") args->quality.keep_segments = 2;
        else throw UsageError("--keep-segments must be boundary or all, got \"" + keep_name + "\"");
    }
    if (app.count("--fill") && !hullkit::parse_fill_rule(fill_name, &args->fill))
        throw UsageError("unknown fill rule \"" + fill_name + "\" (known: evenodd, nonzero)");
    if (args->format == Format::Node && (args->output.empty() || args->output == "-"))
        throw UsageError("--format node writes two files (BASE.node and BASE.ele): give -o BASE.node");
    if (args->input.empty()) throw UsageError("INPUT is an empty file name");
    if (app.count("--triangle-areas") && args->triangle_areas.empty()) throw UsageError("option --triangle-areas needs a file name");
    if (!args->triangle_areas.empty() && extension_of(args->input) != "ele")
        throw UsageError("--triangle-areas bounds the triangles of a mesh to refine: the input must be a Triangle .ele file");
    if (args->convex && extension_of(args->input) == "ele")
        throw UsageError("--convex applies to .poly input; a .ele mesh's domain is its triangles");
    if (!(args->quality.min_angle >= 0 && args->quality.min_angle <= 34))
        throw UsageError("--min-angle must be from 0 to 34 degrees, got " + hullkit::format_double(args->quality.min_angle));
    if (!(args->quality.max_area >= 0 && std::isfinite(args->quality.max_area)))
        throw UsageError("--max-area must be a positive number, got " + hullkit::format_double(args->quality.max_area));
    return true;
}

// ---- writers ----

std::string write_off(const hullkit::ConstrainedDelaunay& d) {
    std::string out = "OFF\n";
    append_uint(out, d.coords.size() / 2);
    out += ' ';
    append_uint(out, d.triangle_count());
    out += " 0\n";
    for (std::size_t i = 0; i < d.coords.size(); i += 2)
        out += hullkit::format_double(d.coords[i]) + ' ' + hullkit::format_double(d.coords[i + 1]) + " 0\n";
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        out += '3';
        for (int k = 0; k < 3; ++k) out += ' ', append_uint(out, d.triangles[3 * t + k]);
        out += '\n';
    }
    return out;
}

std::string write_obj(const hullkit::ConstrainedDelaunay& d) {
    std::string out;
    for (std::size_t i = 0; i < d.coords.size(); i += 2)
        out += "v " + hullkit::format_double(d.coords[i]) + ' ' + hullkit::format_double(d.coords[i + 1]) + " 0\n";
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        out += 'f';
        for (int k = 0; k < 3; ++k) out += ' ', append_uint(out, d.triangles[3 * t + k] + std::uint64_t{1});
        out += '\n';
    }
    return out;
}

/// Per triangle, the attribute of its region (0 outside every region): --region-attributes.
std::vector<double> attributes_of(const Input& in, const hullkit::ConstrainedDelaunay& d) {
    std::vector<double> out(d.triangle_count(), 0.0);
    for (std::size_t t = 0; t < d.triangle_region.size() && t < out.size(); ++t) {
        if (d.triangle_region[t] >= 0) out[t] = in.region_attributes[static_cast<std::size_t>(d.triangle_region[t])];
    }
    return out;
}

std::string write_json(const hullkit::ConstrainedDelaunay& d, const std::vector<double>* attributes) {
    std::string out = "{\"dimension\":" + std::to_string(d.dimension) + ",\"points\":[";
    for (std::size_t i = 0; i < d.coords.size(); i += 2) {
        if (i) out += ',';
        out += '[' + hullkit::format_json_number(d.coords[i]) + ',' + hullkit::format_json_number(d.coords[i + 1]) + ']';
    }
    out += "],\"triangles\":[";
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        if (t) out += ',';
        out += '[' + std::to_string(d.triangles[3 * t]) + ',' + std::to_string(d.triangles[3 * t + 1]) + ',' +
               std::to_string(d.triangles[3 * t + 2]) + ']';
    }
    out += "],\"halfedges\":[";
    for (std::size_t e = 0; e < d.halfedges.size(); ++e) out += (e ? "," : "") + std::to_string(d.halfedges[e]);
    out += "],\"constrained\":[";
    for (std::size_t e = 0; e < d.constrained.size(); ++e) out += (e ? "," : "") + std::to_string(d.constrained[e]);
    if (attributes) {
        out += "],\"attributes\":[";
        for (std::size_t t = 0; t < attributes->size(); ++t) out += (t ? "," : "") + hullkit::format_json_number((*attributes)[t]);
    }
    out += "],\"added\":" + std::to_string(d.added_count()) + ",\"duplicates\":[";
    bool first = true;
    for (std::size_t i = 0; i < d.representative.size(); ++i) {
        if (d.representative[i] == i) continue;
        out += (first ? "[" : ",[") + std::to_string(i) + ',' + std::to_string(d.representative[i]) + ']';
        first = false;
    }
    out += "]}\n";
    return out;
}

std::string write_svg(const hullkit::ConstrainedDelaunay& d) {
    const hullkit::PointSpan2 points(d.coords);
    const SvgFrame frame = frame_of(points);
    std::string title = "Constrained Delaunay triangulation: ";
    append_uint(title, d.triangle_count());
    title += " triangles";
    std::string out = svg_header(frame, title);
    std::string fill, free_edges, segments;
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        fill += 'M';
        for (int k = 0; k < 3; ++k) {
            if (k) fill += 'L';
            const double* p = points[d.triangles[3 * t + k]];
            append_svg_point(fill, frame, p[0], p[1]);
        }
        fill += 'Z';
    }
    for (std::size_t e = 0; e < d.triangles.size(); ++e) {
        if (d.halfedges[e] >= 0 && static_cast<std::size_t>(d.halfedges[e]) > e) continue;  // each edge once
        const double* a = points[d.triangles[e]];
        const double* b = points[d.triangles[e % 3 == 2 ? e - 2 : e + 1]];
        std::string& path = d.constrained[e] ? segments : free_edges;
        path += 'M';
        append_svg_point(path, frame, a[0], a[1]);
        path += 'L';
        append_svg_point(path, frame, b[0], b[1]);
    }
    out += "<path id=\"inside\" fill=\"#dbeafe\" stroke=\"none\" d=\"" + fill + "\"/>\n";
    out += "<path id=\"edges\" fill=\"none\" stroke=\"#2563eb\" stroke-width=\"0.8\" d=\"" + free_edges + "\"/>\n";
    out += "<path id=\"segments\" fill=\"none\" stroke=\"#111827\" stroke-width=\"2\" stroke-linecap=\"round\" d=\"" + segments + "\"/>\n";
    out += "</svg>\n";
    return out;
}

/// Triangle's .node (vertices numbered from 1) and .ele (triangles counter-clockwise, as Triangle
/// writes them: y up).
void write_node_ele(const std::string& output, const hullkit::ConstrainedDelaunay& d, const std::vector<double>* attributes) {
    const std::string ext = extension_of(output);
    const std::string base = ext == "node" || ext == "ele" ? output.substr(0, output.size() - ext.size() - 1) : output;
    std::string node = std::to_string(d.coords.size() / 2) + " 2 0 0\n";
    for (std::size_t i = 0; i < d.coords.size(); i += 2)
        node += std::to_string(i / 2 + 1) + ' ' + hullkit::format_double(d.coords[i]) + ' ' + hullkit::format_double(d.coords[i + 1]) + '\n';
    std::string ele = std::to_string(d.triangle_count()) + (attributes ? " 3 1\n" : " 3 0\n");
    for (std::size_t t = 0; t < d.triangle_count(); ++t) {
        ele += std::to_string(t + 1) + ' ' + std::to_string(d.triangles[3 * t] + 1) + ' ' + std::to_string(d.triangles[3 * t + 2] + 1) + ' ' +
               std::to_string(d.triangles[3 * t + 1] + 1);
        if (attributes) ele += ' ' + hullkit::format_double((*attributes)[t]);
        ele += '\n';
    }
    write_output(base + ".node", node);
    write_output(base + ".ele", ele);
}

/// A core message about a mesh read from .node/.ele with its triangle and point numbers (0-based
/// positions) as the files number them: a number after "triangle(s)" (and after "and" or a comma
/// that follows one) becomes that triangle's number in the .ele, one after "point(s)" or
/// "corner(s)" that vertex's number in the .node.
std::string numbered_as_in_files(const std::string& message, const Input& in) {
    enum class Kind { None, Triangle, Point } kind = Kind::None;
    std::string out;
    std::size_t at = 0;
    while (at < message.size()) {
        const std::size_t end = std::min(message.find(' ', at), message.size());
        const std::string token = message.substr(at, end - at);
        // The word without the punctuation around it.
        const std::size_t first = token.find_first_not_of("(");
        const std::size_t last = token.find_last_not_of(",):;");
        const std::string word = first == std::string::npos || last < first ? "" : token.substr(first, last - first + 1);
        std::string replaced = token;
        if (word == "triangle" || word == "triangles") {
            kind = Kind::Triangle;
        } else if (word == "point" || word == "points" || word == "corner" || word == "corners") {
            kind = Kind::Point;
        } else if (!word.empty() && word.find_first_not_of("0123456789") == std::string::npos && kind != Kind::None) {
            const std::uint64_t k = std::stoull(word);
            std::uint64_t number = k;
            if (kind == Kind::Triangle && k < in.triangle_number.size()) number = in.triangle_number[k];
            else if (kind == Kind::Point && k < in.xy.size() / 2) number = k + in.node_first;
            replaced = token.substr(0, first) + std::to_string(number) + token.substr(last + 1);
            if (token.find(')') != std::string::npos) kind = Kind::None;  // a list "(points a, b, c)" ends
        } else if (word != "and") {
            kind = Kind::None;
        }
        out += replaced;
        if (end < message.size()) out += ' ';
        at = end + 1;
    }
    return out;
}

/// The core's error with the input's line (and ring) for the point or segment it names.
std::string located(const std::string& source, const Input& in, const hullkit::ConstrainedDelaunay& d) {
    std::string where = source;
    if (d.error_triangle >= 0 && static_cast<std::size_t>(d.error_triangle) < in.triangle_line.size()) {
        where += " line " + std::to_string(in.triangle_line[static_cast<std::size_t>(d.error_triangle)]);
    } else if (d.error_point >= 0 && static_cast<std::size_t>(d.error_point) < in.line.size()) {
        const std::size_t p = static_cast<std::size_t>(d.error_point);
        if (in.mesh) where = in.node_source;
        if (in.line[p] > 0) where += " line " + std::to_string(in.line[p]);
        if (!in.poly && !in.mesh) {
            std::size_t ring = 0;
            while (ring < in.ring_starts.size() && in.ring_starts[ring] <= p) ++ring;
            const std::size_t start = ring == 0 ? 0 : in.ring_starts[ring - 1];
            where += " (ring " + std::to_string(ring) + ", vertex " + std::to_string(p - start) + ")";
        }
    } else if (d.error_segment >= 0 && in.poly && static_cast<std::size_t>(d.error_segment) < in.segment_line.size()) {
        where += " line " + std::to_string(in.segment_line[static_cast<std::size_t>(d.error_segment)]);
    }
    return where + ": " + (in.mesh ? numbered_as_in_files(d.error, in) : d.error);
}

}  // namespace

int run_triangulate(const std::vector<std::string>& argv) {
    Args args;
    if (!parse_args(argv, &args)) return kExitOk;
    const Input in = read_input_file(args.input);
    const std::string source = args.input == "-" ? "<stdin>" : args.input;
    if (args.region_attributes && !in.poly)
        throw UsageError("--region-attributes needs a Triangle .poly input (its regions carry the attributes); " + source + " is not one");
    if (args.region_attributes && args.format != Format::Json && args.format != Format::Node)
        throw UsageError("--region-attributes writes the attributes into .ele (--format node) or JSON output; OFF, OBJ and SVG have no place for them");
    const auto started = std::chrono::steady_clock::now();
    const hullkit::PointSpan2 points(in.xy);
    hullkit::ConstrainedDelaunay d;
    if (in.mesh) {
        hullkit::RefineMeshOptions options;
        options.quality = args.quality;
        if (!args.triangle_areas.empty()) options.triangle_max_area = read_area(args.triangle_areas, in.triangles.size() / 3);
        d = hullkit::refine_mesh(points, in.triangles.data(), in.triangles.size() / 3, nullptr, 0, options);
    } else if (in.poly) {
        hullkit::ConstrainedOptions options;
        options.remove_exterior = !args.convex && !in.whole_hull;
        options.holes = in.holes;
        options.regions = in.regions;
        options.quality = args.quality;
        d = hullkit::constrained_delaunay(points, in.segments.data(), in.segments.size() / 2, options);
    } else {
        hullkit::PolygonOptions options;
        options.fill = args.fill;
        options.quality = args.quality;
        d = hullkit::triangulate_polygon(points, in.ring_starts.data(), in.ring_starts.size(), options);
    }
    if (!d.ok()) throw UsageError(located(source, in, d));
    const std::vector<double> attributes = args.region_attributes ? attributes_of(in, d) : std::vector<double>();
    const std::vector<double>* with = args.region_attributes ? &attributes : nullptr;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    switch (args.format) {
        case Format::Off: write_output(args.output, write_off(d)); break;
        case Format::Obj: write_output(args.output, write_obj(d)); break;
        case Format::Json: write_output(args.output, write_json(d, with)); break;
        case Format::Svg: write_output(args.output, write_svg(d)); break;
        case Format::Node: write_node_ele(args.output, d, with); break;
    }
    if (args.stats) {
        const std::size_t segments = in.poly ? in.segments.size() / 2 : in.mesh ? 0 : in.xy.size() / 2;
        std::fprintf(stderr,
                     "{\"points\":%zu,\"added\":%zu,\"segments\":%zu,\"crossings\":%zu,\"steiner\":%zu,\"unrefined\":%zu,"
                     "\"triangles\":%zu,\"seconds\":%.6f}\n",
                     in.xy.size() / 2, d.added_count(), segments, d.crossing_count, d.steiner_count, d.unrefined_count,
                     d.triangle_count(), seconds);
    }
    return kExitOk;
}

}  // namespace hullkit_cli
