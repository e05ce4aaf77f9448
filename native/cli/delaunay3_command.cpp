// `hullkit delaunay3` and `hullkit verify-delaunay3`: argument parsing (CLI11) and I/O around
// hullkit::delaunay3 and hullkit::verify_delaunay3. No geometry here.
#include "delaunay3_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "cli_io.hpp"
#include "hullkit/delaunay3.hpp"
#include "hullkit/mesh_io.hpp"
#include "hullkit/point_reader.hpp"
#include "progress.hpp"

namespace hullkit_cli {
namespace {

const char* const kDelaunay3Usage =
    R"(Usage: hullkit delaunay3 [INPUT|-] [-o FILE] [--format FORMAT]
                         [--voronoi FILE] [--furthest-site] [--threads N]
                         [--stats] [--quiet]

Computes the Delaunay tetrahedralization of the 3D points in INPUT (standard
input if INPUT is missing or '-'): the lower convex hull of the points lifted to
(x, y, z, x^2 + y^2 + z^2), projected back. Every decision is exact; cospherical
points (grids, lattices, spheres) are tetrahedralized by one rule that depends
only on the points, and no tetrahedron is flat. Tetrahedra are positively
oriented (a, b, c counter-clockwise seen from d). Exact duplicates are merged
into their lowest index. Coplanar points give the triangles of their plane,
collinear points the points in order along their line, no points dimension -1.

Input: every point format of 'hullkit hull' (x y z lines, qhull/rbox, OBJ, OFF,
PLY, STL, glTF vertices, TetGen .node).

Options:
  -o, --output FILE   write to FILE instead of standard output
  --format FORMAT     json (default): {"dimension", "tetrahedra": [[a,b,c,d],
                        ...], "neighbors": [[...],...] (the tetrahedron across
                        the face opposite each corner, -1 on the hull), "hull":
                        [[a,b,c],...] (outward), "duplicates": [[i, first],
                        ...]}; coplanar input: "triangles", "neighbors",
                        "normal"; collinear or one point: "vertices";
                      ele: TetGen's .ele, and FILE's .node beside it (every
                        input point, numbered from 1 in input order);
                      vtk: a legacy VTK unstructured grid of tetrahedra (opens
                        in ParaView);
                      without --format, an output FILE ending in .json, .ele
                      or .vtk selects that format
  --voronoi FILE      also write the Voronoi diagram to FILE (default: none;
                        '-': standard output, when -o names a file) as
                        JSON: {"vertices": [[x,y,z],...] (the circumcentres;
                        cospherical tetrahedra share one),
                        "tetrahedron_vertex": [...], "faces": [[p, q,
                        bounded, [v,...]],...] (between points p < q,
                        counter-clockwise seen from q), "cells":
                        [[face,...],...] (per point), "volume": [...] (null
                        when unbounded: a hull point, or for a duplicate
                        point)}; with --furthest-site the furthest-site
                        diagram (every cell unbounded; a point in no
                        tetrahedron has no faces and volume 0)
  --furthest-site     the furthest-site tetrahedralization instead (qdelaunay
                        Qu): the tetrahedra whose circumspheres hold every
                        point; only the hull's extreme points are corners;
                        coplanar points: the furthest-site triangles of the
                        polygon's corners; collinear: the two end points
  --threads N         a whole number from 0 to 1024: 0 (default) every
                      hardware thread, 1 this thread only; the output is the
                      same for every N
  --stats             print one JSON line to standard error: points,
                      tetrahedra, hull, dimension, threads, seconds (the
                      tetrahedralization alone)
  --quiet             no progress line (otherwise drawn on standard error when
                      it is a terminal and the run lasts over a second)
  -h, --help          show this help

Exit status: 0 on success, 2 on a usage or input problem (one line on standard
error).
)";

const char* const kVerifyDelaunay3Usage =
    R"(Usage: hullkit verify-delaunay3 POINTS TETRAHEDRA

Checks, with exact arithmetic, that TETRAHEDRA is the Delaunay tetrahedralization
of the 3D points in POINTS ('-' reads them from standard input; the input formats
of 'hullkit delaunay3'): every tetrahedron positively oriented and not flat,
each face shared by at most two tetrahedra on opposite sides, the boundary a
closed convex surface (the convex hull), every distinct point used, and no point
inside the circumsphere across any interior face (cospherical ties broken by the
rule of 'hullkit delaunay3').

TETRAHEDRA: the JSON of 'hullkit delaunay3' (0-based indices into POINTS), or a
TetGen .ele file (indices numbered as its .node file beside it says, from 1 if
there is none).

Prints 'ok: ...' or each problem on its own line.

Options:
  -h, --help          show this help

Exit status: 0 the tetrahedralization is Delaunay, 1 it is not, 2 a usage or
input problem (one line on standard error).
)";

enum class Format { Json, Ele, Vtk };

bool parse_format(std::string name, Format* out) {
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (name == "json") *out = Format::Json;
    else if (name == "ele") *out = Format::Ele;
    else if (name == "vtk") *out = Format::Vtk;
    else return false;
    return true;
}

bool format_from_path(const std::string& path, Format* out) {
    const std::size_t dot = path.find_last_of("./");
    return dot != std::string::npos && path[dot] == '.' && parse_format(path.substr(dot + 1), out);
}

struct Delaunay3Args {
    std::string input = "-";
    std::string output;
    Format format = Format::Json;
    std::string voronoi;  ///< --voronoi FILE: the Voronoi cells as JSON there
    unsigned threads = 0;
    bool furthest_site = false;
    bool stats = false;
    bool quiet = false;
};

bool parse_args(const std::vector<std::string>& argv, Delaunay3Args* args) {
    CLI::App app{"hullkit delaunay3", "hullkit delaunay3"};
    app.set_help_flag();
    bool help = false;
    std::string format_name;
    const auto last = CLI::MultiOptionPolicy::TakeLast;
    app.add_flag("-h,--help", help);
    app.add_option("input", args->input);
    app.add_option("-o,--output", args->output)->multi_option_policy(last);
    app.add_option("--format", format_name)->multi_option_policy(last);
    app.add_option("--voronoi", args->voronoi)->multi_option_policy(last);
    add_whole_number_option(app, "--threads", &args->threads, 0, 1024);
    app.add_flag("--furthest-site", args->furthest_site);
    app.add_flag("--stats", args->stats);
    app.add_flag("--quiet", args->quiet);
    parse_or_throw(app, argv, "delaunay3");
    if (help) {
        std::fputs(kDelaunay3Usage, stdout);
        return false;
    }
    if (app.count("--output") && args->output.empty()) throw UsageError("option --output needs a file name");
    if (app.count("--format")) {
        if (!parse_format(format_name, &args->format)) {
            throw UsageError("unknown format \"" + format_name + "\" (known: json, ele, vtk)");
        }
    } else if (!args->output.empty() && args->output != "-") {
        format_from_path(args->output, &args->format);  // the default stays JSON
    }
    if (args->format == Format::Ele && (args->output.empty() || args->output == "-")) {
        throw UsageError("--format ele writes FILE.ele and FILE.node: give -o FILE.ele");
    }
    if (args->input.empty()) throw UsageError("INPUT is an empty file name");
    if (app.count("--voronoi") && args->voronoi.empty()) throw UsageError("option --voronoi needs a file name");
    const bool output_to_stdout = args->output.empty() || args->output == "-";
    if (args->voronoi == "-" && output_to_stdout) {
        throw UsageError("--voronoi - and the tetrahedra would both go to standard output: give -o FILE or --voronoi FILE");
    }
    return true;
}

std::string source_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

/// Every point of `path` (any format hullkit reads), or a UsageError naming the file.
std::vector<double> read_cloud(const std::string& path, unsigned threads, bool quiet) {
    std::FILE* file = path == "-" ? stdin : std::fopen(path.c_str(), "rb");
    if (!file) throw UsageError(path + ": cannot open: " + std::strerror(errno));
    struct Closer {
        std::FILE* file;
        ~Closer() {
            if (file != stdin) std::fclose(file);
        }
    } closer{file};
    hullkit::PointReaderOptions options;
    options.threads = threads;
    hullkit::PointReader reader(file, source_name(path), options);
    // Address space for every point the header declares or the file could hold (no point line is
    // shorter than 6 bytes), so that the array never grows by a copy (which would hold it twice);
    // pages are touched only as points arrive.
    std::vector<double> xyz;
    const std::uint64_t expected = reader.declared_points() ? reader.declared_points() : reader.size() / 6 + 1;
    xyz.reserve(3 * static_cast<std::size_t>(std::min<std::uint64_t>(expected, std::uint64_t{1} << 31)));
    while (reader.append_next(&xyz)) {
    }
    if (!reader.error().empty()) throw UsageError(reader.error());
    if (!quiet) print_warnings(source_name(path), reader.warnings());
    return xyz;
}

/// Appends a number's shortest text (integers exactly; doubles that read back to the same bits).
template <class Number>
void append(std::string& text, Number value) {
    char digits[32];
    text.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
}

/// One row of at most eight numbers, formatted on the stack and appended to the text in one piece:
/// a million points' tetrahedra are seven million rows, and growing the string number by number
/// cost more than the digits.
class Line {
public:
    template <class Number>
    Line& operator<<(Number value) {
        end_ = std::to_chars(end_, data_ + sizeof data_, value).ptr;
        return *this;
    }
    Line& operator<<(char c) {
        *end_++ = c;
        return *this;
    }
    void append_to(std::string& text) const { text.append(data_, static_cast<std::size_t>(end_ - data_)); }

private:
    char data_[8 * 32];  // eight numbers (a double's shortest text is at most 24 characters) and separators
    char* end_ = data_;
};

/// Text written straight to a file (or standard output for "" and "-") through a buffer of about
/// a megabyte: a million points' tetrahedra are hundreds of megabytes of text, never held whole.
/// Numbers by std::to_chars (doubles: the shortest text that reads back the same).
class TextOut {
public:
    explicit TextOut(const std::string& path) : path_(path.empty() || path == "-" ? "<stdout>" : path) {
        file_ = path.empty() || path == "-" ? stdout : std::fopen(path.c_str(), "wb");
        if (!file_) throw UsageError(path + ": cannot open for writing: " + std::strerror(errno));
        buffer_.reserve(kFlushAt + 256);
    }
    ~TextOut() {
        if (file_ && file_ != stdout) std::fclose(file_);
    }
    TextOut(const TextOut&) = delete;
    TextOut& operator=(const TextOut&) = delete;

    void put(const char* text) {
        buffer_ += text;
        maybe_flush();
    }
    void put(char c) { buffer_ += c; }
    /// Text formatted elsewhere, written after what is buffered.
    void put_block(const std::string& text) {
        flush();
        if (!text.empty() && std::fwrite(text.data(), 1, text.size(), file_) != text.size()) {
            throw UsageError(path_ + ": cannot write: " + std::strerror(errno));
        }
    }
    void number(std::int64_t value) {
        append(buffer_, value);
        maybe_flush();
    }
    void real(double value) {
        append(buffer_, value);
        maybe_flush();
    }
    /// Writes what is left and closes the file; a full disk or a closed pipe is an error naming it.
    void finish() {
        flush();
        const bool ok = file_ == stdout ? std::fflush(stdout) == 0 : std::fclose(file_) == 0;
        if (file_ != stdout) file_ = nullptr;
        if (!ok) throw UsageError(path_ + ": cannot write: " + std::strerror(errno));
    }

private:
    static constexpr std::size_t kFlushAt = std::size_t{1} << 20;
    void maybe_flush() {
        if (buffer_.size() >= kFlushAt) flush();
    }
    void flush() {
        if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
            throw UsageError(path_ + ": cannot write: " + std::strerror(errno));
        }
        buffer_.clear();
    }
    std::string path_;
    std::FILE* file_ = nullptr;
    std::string buffer_;
};

/// Rows 0 .. count-1, each appended to a string by row(i, text), formatted on `threads` threads
/// (0: every hardware thread) in batches of consecutive rows and written in order: the same bytes
/// for every thread count. The tetrahedra's text is several times their binary size, and one
/// thread formatting it took about as long as the tetrahedralization on two.
template <class Row>
void put_rows(TextOut& out, std::size_t count, unsigned threads, const Row& row) {
    constexpr std::size_t kRows = std::size_t{1} << 15;  // a batch: about 1 MB of text
    const unsigned workers = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::string> pieces(count > kRows ? workers : 1);
    const std::size_t stride = kRows * pieces.size();
    for (std::size_t start = 0; start < count; start += stride) {
        auto format = [&](std::size_t k) {
            std::string& text = pieces[k];
            text.clear();
            const std::size_t end = std::min(count, start + (k + 1) * kRows);
            for (std::size_t i = start + k * kRows; i < end; ++i) row(i, text);
        };
        std::vector<std::thread> helpers;
        for (std::size_t k = 1; k < pieces.size() && start + k * kRows < count; ++k) helpers.emplace_back(format, k);
        format(0);
        for (std::thread& helper : helpers) helper.join();
        for (std::size_t k = 0; k <= helpers.size(); ++k) out.put_block(pieces[k]);
    }
}

/// JSON lists of index tuples: [[a,b,c],[...]].
template <class Int>
void json_tuples(TextOut& out, const std::vector<Int>& values, std::size_t arity, unsigned threads) {
    out.put('[');
    put_rows(out, values.size() / arity, threads, [&](std::size_t i, std::string& text) {
        Line line;
        if (i) line << ',';
        line << '[';
        for (std::size_t k = 0; k < arity; ++k) {
            if (k) line << ',';
            line << static_cast<std::int64_t>(values[arity * i + k]);
        }
        (line << ']').append_to(text);
    });
    out.put(']');
}

void write_json(TextOut& out, const hullkit::Delaunay3& d, unsigned threads) {
    out.put("{\"dimension\":");
    out.number(d.dimension);
    if (d.dimension == 3) {
        out.put(",\"tetrahedra\":");
        json_tuples(out, d.tetrahedra, 4, threads);
        out.put(",\"neighbors\":");
        json_tuples(out, d.neighbors, 4, threads);
        out.put(",\"hull\":");
        json_tuples(out, d.hull, 3, threads);
    } else if (d.dimension == 2) {
        out.put(",\"triangles\":");
        json_tuples(out, d.triangles, 3, threads);
        out.put(",\"neighbors\":");
        json_tuples(out, d.neighbors, 3, threads);
        out.put(",\"normal\":[");
        for (int k = 0; k < 3; ++k) {
            if (k) out.put(',');
            out.real(d.normal[k]);
        }
        out.put(']');
    } else {
        out.put(",\"vertices\":");
        json_tuples(out, d.vertices, 1, threads);
    }
    out.put(",\"duplicates\":[");
    bool first = true;
    for (std::size_t i = 0; i < d.representative.size(); ++i) {
        if (d.representative[i] == i) continue;
        if (!first) out.put(',');
        first = false;
        out.put('[');
        out.number(static_cast<std::int64_t>(i));
        out.put(',');
        out.number(d.representative[i]);
        out.put(']');
    }
    out.put("]}\n");
}

/// One point's coordinates, space-separated, and a newline.
void put_point(Line& line, const double* p) { line << p[0] << ' ' << p[1] << ' ' << p[2] << '\n'; }

/// TetGen's .node: "N 3 0 0" then "i x y z", numbered from 1.
void write_node(TextOut& out, const std::vector<double>& xyz, unsigned threads) {
    const std::size_t n = xyz.size() / 3;
    out.number(static_cast<std::int64_t>(n));
    out.put(" 3 0 0\n");
    put_rows(out, n, threads, [&](std::size_t i, std::string& text) {
        Line line;
        line << static_cast<std::int64_t>(i + 1) << ' ';
        put_point(line, &xyz[3 * i]);
        line.append_to(text);
    });
}

/// TetGen's .ele: "T 4 0" then "t a b c d", numbered from 1 (tetrahedra and nodes alike).
void write_ele(TextOut& out, const hullkit::Delaunay3& d, unsigned threads) {
    out.number(static_cast<std::int64_t>(d.tetrahedron_count()));
    out.put(" 4 0\n");
    put_rows(out, d.tetrahedron_count(), threads, [&](std::size_t t, std::string& text) {
        const std::uint32_t* corners = &d.tetrahedra[4 * t];
        Line line;
        line << static_cast<std::int64_t>(t + 1);
        for (int k = 0; k < 4; ++k) line << ' ' << std::int64_t{corners[k]} + 1;
        (line << '\n').append_to(text);
    });
}

/// Legacy VTK, an unstructured grid: every input point, then the tetrahedra (cell type 10), or the
/// triangles of coplanar input (type 5).
void write_vtk(TextOut& out, const std::vector<double>& xyz, const hullkit::Delaunay3& d, unsigned threads) {
    const std::size_t n = xyz.size() / 3;
    out.put("# vtk DataFile Version 3.0\nhullkit delaunay3\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS ");
    out.number(static_cast<std::int64_t>(n));
    out.put(" double\n");
    put_rows(out, n, threads, [&](std::size_t i, std::string& text) {
        Line line;
        put_point(line, &xyz[3 * i]);
        line.append_to(text);
    });
    const bool solid = d.dimension == 3;
    const std::vector<std::uint32_t>& cells = solid ? d.tetrahedra : d.triangles;
    const std::size_t arity = solid ? 4 : 3;
    const std::size_t count = cells.size() / arity;
    out.put("CELLS ");
    out.number(static_cast<std::int64_t>(count));
    out.put(' ');
    out.number(static_cast<std::int64_t>(count * (arity + 1)));
    out.put('\n');
    put_rows(out, count, threads, [&](std::size_t c, std::string& text) {
        Line line;
        line << static_cast<std::int64_t>(arity);
        for (std::size_t k = 0; k < arity; ++k) line << ' ' << static_cast<std::int64_t>(cells[arity * c + k]);
        (line << '\n').append_to(text);
    });
    out.put("CELL_TYPES ");
    out.number(static_cast<std::int64_t>(count));
    out.put('\n');
    for (std::size_t c = 0; c < count; ++c) out.put(solid ? "10\n" : "5\n");
}

/// The Voronoi diagram as JSON: {"vertices": [[x,y,z],...], "tetrahedron_vertex": [...],
/// "faces": [[p, q, bounded, [v, ...]], ...], "cells": [[f, ...], ...], "volume": [...]}; a volume
/// is null for an unbounded cell (a hull point) and for a duplicate point (its representative's
/// cell is the one).
void write_voronoi(TextOut& out, const hullkit::Voronoi3& v, unsigned threads) {
    out.put("{\"vertices\":[");
    put_rows(out, v.vertices.size() / 3, threads, [&](std::size_t i, std::string& text) {
        text += i ? ",[" : "[";
        for (int k = 0; k < 3; ++k) {
            if (k) text += ',';
            append(text, v.vertices[3 * i + k]);
        }
        text += ']';
    });
    out.put("],\"tetrahedron_vertex\":[");
    put_rows(out, v.tetrahedron_vertex.size(), threads, [&](std::size_t t, std::string& text) {
        if (t) text += ',';
        append(text, static_cast<std::int64_t>(v.tetrahedron_vertex[t]));
    });
    out.put("],\"faces\":[");
    put_rows(out, v.face_count(), threads, [&](std::size_t f, std::string& text) {
        text += f ? ",[" : "[";
        append(text, static_cast<std::int64_t>(v.face_points[2 * f]));
        text += ',';
        append(text, static_cast<std::int64_t>(v.face_points[2 * f + 1]));
        text += v.face_bounded[f] ? ",true,[" : ",false,[";
        for (std::uint32_t k = v.face_offsets[f]; k < v.face_offsets[f + 1]; ++k) {
            if (k > v.face_offsets[f]) text += ',';
            append(text, static_cast<std::int64_t>(v.face_vertices[k]));
        }
        text += "]]";
    });
    out.put("],\"cells\":[");
    const std::size_t points = v.volume.size();
    put_rows(out, points, threads, [&](std::size_t i, std::string& text) {
        text += i ? ",[" : "[";
        for (std::uint32_t k = v.cell_offsets[i]; k < v.cell_offsets[i + 1]; ++k) {
            if (k > v.cell_offsets[i]) text += ',';
            append(text, static_cast<std::int64_t>(v.cell_faces[k]));
        }
        text += ']';
    });
    out.put("],\"volume\":[");
    put_rows(out, points, threads, [&](std::size_t i, std::string& text) {
        if (i) text += ',';
        if (std::isfinite(v.volume[i])) append(text, v.volume[i]);
        else text += "null";
    });
    out.put("]}\n");
}

/// "FILE.ele" -> "FILE.node" (any other name gets ".node" appended).
std::string node_path_of(const std::string& ele) {
    const std::size_t dot = ele.find_last_of("./");
    if (dot != std::string::npos && ele[dot] == '.') return ele.substr(0, dot) + ".node";
    return ele + ".node";
}

int delaunay3_main(const std::vector<std::string>& argv) {
    Delaunay3Args args;
    if (!parse_args(argv, &args)) return kExitOk;
    const std::vector<double> xyz = read_cloud(args.input, args.threads, args.quiet);
    hullkit::Delaunay3Options options;
    options.threads = args.threads;
    options.furthest_site = args.furthest_site;
    hullkit::Delaunay3 result;
    const auto start = std::chrono::steady_clock::now();
    {
        Progress progress("points", 0, args.quiet);
        options.progress = [&progress](std::size_t done, std::size_t total) {
            progress.set_total(total);
            progress.update(done);
        };
        result = hullkit::delaunay3(hullkit::PointSpan(xyz.data(), xyz.size() / 3), options);
    }
    const auto stop = std::chrono::steady_clock::now();
    if (!result.ok()) throw UsageError(source_name(args.input) + ": " + result.error);
    if (args.format == Format::Ele && result.dimension != 3) {
        throw UsageError(source_name(args.input) + ": the points are " +
                         (result.dimension == 2 ? "coplanar" : "not spread in 3D") +
                         ": there are no tetrahedra for a .ele file (use --format json or vtk)");
    }
    if (args.format == Format::Ele) {
        TextOut node(node_path_of(args.output));
        write_node(node, xyz, args.threads);
        node.finish();
    }
    TextOut out(args.output);
    switch (args.format) {
        case Format::Json: write_json(out, result, args.threads); break;
        case Format::Vtk: write_vtk(out, xyz, result, args.threads); break;
        case Format::Ele: write_ele(out, result, args.threads); break;
    }
    out.finish();
    if (!args.voronoi.empty()) {
        const hullkit::Voronoi3 cells = hullkit::delaunay3_voronoi(hullkit::PointSpan(xyz.data(), xyz.size() / 3), result);
        TextOut file(args.voronoi);
        write_voronoi(file, cells, args.threads);
        file.finish();
    }
    if (args.stats) {
        const unsigned threads = args.threads ? args.threads : std::max(1u, std::thread::hardware_concurrency());
        std::fprintf(stderr,
                     "{\"points\":%zu,\"tetrahedra\":%zu,\"hull\":%zu,\"dimension\":%d,\"threads\":%u,\"seconds\":%.9g}\n",
                     xyz.size() / 3, result.tetrahedron_count(), result.hull.size() / 3, result.dimension, threads,
                     std::chrono::duration<double>(stop - start).count());
    }
    return kExitOk;
}

// ---- verify-delaunay3 ----

/// The tetrahedra of a `hullkit delaunay3` JSON file (0-based).
std::vector<std::uint32_t> read_json_tetrahedra(const std::string& text, const std::string& source) {
    const std::size_t key = text.find("\"tetrahedra\"");
    if (key == std::string::npos) throw UsageError(source + ": no \"tetrahedra\" list (the JSON of 'hullkit delaunay3')");
    std::size_t at = text.find('[', key);
    if (at == std::string::npos) throw UsageError(source + ": \"tetrahedra\" is not a list");
    std::vector<std::uint32_t> out;
    int depth = 0;
    for (; at < text.size(); ++at) {
        const char c = text[at];
        if (c == '[') {
            ++depth;
        } else if (c == ']') {
            if (--depth == 0) break;
        } else if (c >= '0' && c <= '9') {
            std::uint64_t value = 0;
            const auto [end, ec] = std::from_chars(text.data() + at, text.data() + text.size(), value);
            if (ec != std::errc() || value > 0xffffffffu) throw UsageError(source + ": an index in \"tetrahedra\" is too large");
            out.push_back(static_cast<std::uint32_t>(value));
            at = static_cast<std::size_t>(end - text.data()) - 1;
        } else if (c != ',' && c != ' ' && c != '\n' && c != '\r' && c != '\t') {
            throw UsageError(source + ": unexpected \"" + std::string(1, c) + "\" in \"tetrahedra\"");
        }
    }
    if (depth != 0) throw UsageError(source + ": the \"tetrahedra\" list is not closed");
    if (out.size() % 4) throw UsageError(source + ": \"tetrahedra\" holds " + std::to_string(out.size()) + " indices, not quadruples");
    return out;
}

/// The first node number of a TetGen .node file (0 or 1), or 1 when there is none.
std::uint64_t node_base(const std::string& node_path) {
    std::string text, error;
    if (!hullkit::read_file(node_path, &text, &error)) return 1;
    std::size_t line_start = 0;
    int content_lines = 0;
    while (line_start < text.size()) {
        std::size_t end = text.find('\n', line_start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(line_start, end - line_start);
        line_start = end + 1;
        const std::size_t hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        if (++content_lines == 2) return std::stoull(line.substr(line.find_first_not_of(" \t")));
    }
    return 1;
}

/// The tetrahedra of a TetGen .ele file, made 0-based.
std::vector<std::uint32_t> read_ele(const std::string& text, const std::string& source, std::uint64_t base) {
    std::vector<std::uint32_t> out;
    std::size_t line_start = 0, line_number = 0;
    bool header = true;
    std::uint64_t declared = 0, per = 4;
    while (line_start < text.size()) {
        std::size_t end = text.find('\n', line_start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(line_start, end - line_start);
        line_start = end + 1;
        ++line_number;
        const std::size_t hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        std::vector<std::uint64_t> fields;
        const char* p = line.data();
        const char* stop = p + line.size();
        while (p < stop) {
            while (p < stop && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
            if (p == stop) break;
            std::uint64_t value = 0;
            const auto [next, ec] = std::from_chars(p, stop, value);
            if (ec != std::errc()) throw UsageError(source + ":" + std::to_string(line_number) + ": not a whole number");
            fields.push_back(value);
            p = next;
        }
        if (fields.empty()) continue;
        if (header) {
            declared = fields[0];
            per = fields.size() > 1 ? fields[1] : 4;
            if (per != 4) throw UsageError(source + ": " + std::to_string(per) + " nodes per tetrahedron (only 4 are read)");
            header = false;
            continue;
        }
        if (fields.size() < 5) throw UsageError(source + ":" + std::to_string(line_number) + ": fewer than 4 nodes");
        for (int k = 1; k <= 4; ++k) {
            if (fields[k] < base || fields[k] - base > 0xffffffffu) {
                throw UsageError(source + ":" + std::to_string(line_number) + ": node " + std::to_string(fields[k]) +
                                 " is below the first node number " + std::to_string(base));
            }
            out.push_back(static_cast<std::uint32_t>(fields[k] - base));
        }
    }
    if (out.size() / 4 != declared) {
        throw UsageError(source + ": the header declares " + std::to_string(declared) + " tetrahedra, the file holds " +
                         std::to_string(out.size() / 4));
    }
    return out;
}

int verify_main(const std::vector<std::string>& argv) {
    CLI::App app{"hullkit verify-delaunay3", "hullkit verify-delaunay3"};
    app.set_help_flag();
    bool help = false;
    std::vector<std::string> files;
    app.add_flag("-h,--help", help);
    app.add_option("files", files);
    parse_or_throw(app, argv, "verify-delaunay3");
    if (help) {
        std::fputs(kVerifyDelaunay3Usage, stdout);
        return kExitOk;
    }
    if (files.size() != 2) {
        throw UsageError("verify-delaunay3 needs two files, POINTS and TETRAHEDRA, got " + std::to_string(files.size()) +
                         " (try 'hullkit verify-delaunay3 --help')");
    }
    if (files[1] == "-") throw UsageError("TETRAHEDRA must be a file ('-' is allowed for POINTS only)");
    const std::vector<double> xyz = read_cloud(files[0], 0, false);
    const std::string text = read_input(files[1]);
    Format format = Format::Json;
    format_from_path(files[1], &format);
    const std::vector<std::uint32_t> tets =
        format == Format::Ele ? read_ele(text, files[1], node_base(node_path_of(files[1]))) : read_json_tetrahedra(text, files[1]);
    const hullkit::Delaunay3VerifyReport report =
        hullkit::verify_delaunay3(hullkit::PointSpan(xyz.data(), xyz.size() / 3), tets.data(), tets.size() / 4);
    if (report.ok) {
        std::printf("ok: %zu points (%zu distinct), %zu tetrahedra, %zu hull triangles\n", xyz.size() / 3,
                    report.distinct_points, tets.size() / 4, report.hull_triangles);
        return kExitOk;
    }
    for (const std::string& line : report.problems) std::printf("%s\n", line.c_str());
    std::printf("not a Delaunay tetrahedralization: %zu problem%s\n", report.problem_count,
                report.problem_count == 1 ? "" : "s");
    return 1;
}

}  // namespace

int run_delaunay3(const std::vector<std::string>& args) {
    try {
        return delaunay3_main(args);
    } catch (const UsageError& error) {
        return print_usage_error(error.what());
    }
}

int run_verify_delaunay3(const std::vector<std::string>& args) {
    try {
        const int status = verify_main(args);
        if (std::fflush(stdout) != 0) throw UsageError(std::string("<stdout>: cannot write: ") + std::strerror(errno));
        return status;
    } catch (const UsageError& error) {
        return print_usage_error(error.what());
    }
}

}  // namespace hullkit_cli
