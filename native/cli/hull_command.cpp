// `hullkit hull INPUT...`: argument parsing and I/O around hullkit::hull (whole clouds) and
// hullkit::HullBuilder (clouds over the memory budget, streamed). No geometry here.
#include "hullkit/hull.hpp"
#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"
#include "hullkit/point_reader.hpp"
#include "cli_io.hpp"
#include "progress.hpp"
#include "hull_command.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <vector>

#include <unistd.h>

using hullkit_cli::CliError;
using hullkit_cli::kExitOk;
using hullkit_cli::kExitUsage;

namespace {

/// Every algorithm the CLI offers; extend together with hullkit::Algorithm.
constexpr hullkit::Algorithm kAlgorithms[] = {hullkit::Algorithm::Quickhull,
                                              hullkit::Algorithm::Giftwrap};

const char* const kHullUsage =
    R"(Usage: hullkit hull [INPUT...|-] [-o FILE] [--format FORMAT] [--normals]
                    [--vertices-only] [--algorithm NAME] [--merge-coplanar]
                    [--epsilon exact|seed] [--threads N] [--memory MB] [--stats]
                    [--quiet]

Computes the convex hull of the 3D points in INPUT (standard input if INPUT is
missing or '-') and writes its vertices and triangles (counter-clockwise seen
from outside). Several INPUTs are read in order as one cloud (indices run on
from one file to the next). Points that are all coplanar, collinear or identical
give a polygon, a segment or a point (OFF/OBJ: the polygon's triangles; JSON:
"dimension"); no points give the empty hull (dimension -1).

Input formats, detected automatically ('#' starts a comment in all of them):
  x y z           one point per line, separated by whitespace or a comma; a
                  byte-order mark and a header row of column names ("x,y,z")
                  are skipped
  qhull / rbox    the dimension (3), the point count, then one point per line
  OBJ             'v x y z' lines are the points; other records are ignored
                  (records that are not OBJ's are skipped with a warning)
  OFF             'OFF', 'vertices faces edges', vertex lines; faces ignored
  PLY, STL        the vertices (PLY point clouds without faces too), by name
                  or content
  glTF            .gltf (buffers embedded or in files next to it) or .glb: the
                  vertices of the default scene's triangle meshes, node
                  transforms applied
  TetGen .node    a file named .node: 'points 3 attributes markers', then
                  'index x y z [attributes] [marker]' lines

Options:
  -o, --output FILE   write the hull to FILE instead of standard output
  --format FORMAT     off (default), obj, json, xyz, glb or normals; without
                      --format, an output FILE ending in .off, .obj, .json,
                      .xyz, .glb or .normals selects it.
                      json: "points" (the hull's vertices), "triangles" (and
                        with --merge-coplanar "faces") indexing "points",
                        "vertices" (the input index of each point),
                        "equations" (each triangle's plane, as --normals),
                        "volume", "area", "dimension";
                      glb: binary glTF, the coordinates rounded to float32
  --normals           the same as --format normals: each face's plane as
                      qconvex's 'n' prints them: "4", the face count, then
                      "nx ny nz offset" a face (the outward unit normal;
                      inside, n.x + offset <= 0)
  --vertices-only     the same as --format xyz: the hull's vertices alone, one
                      'x y z # INDEX' line each (INDEX: the point's input
                      index), which hullkit hull reads back as points: hull
                      each part of a cloud, then the parts' outputs together
  --algorithm NAME    hull algorithm: {algorithms}
  --merge-coplanar    write each planar face as one convex polygon (a cube: 6
                      quads) instead of triangles; JSON gets a "faces" list
  --epsilon MODE      exact (default): every decision by exact predicates;
                      seed: the seed document's epsilon (giftwrap only), for
                      comparison, it may reject near-degenerate input
  --threads N         threads for parsing and quickhull, a whole number from 0
                      to 1024: 0 (default) every hardware thread, 1 the calling
                      thread only; the output is the same for every N
  --memory MB         memory for the points, a whole number from 1 to
                      1073741824 (default {memory}):
                      a cloud that fits is hulled whole; a larger one is
                      streamed in pieces, keeping only the hull's vertices
                      between them, with the same output
  --stats             print one JSON line of statistics to standard error:
                      points, vertices, faces, volume, area, algorithm,
                      seconds (the hull computation alone), streamed, threads
  --quiet             no progress line (it is drawn on standard error only
                      when that is a terminal and the run takes over a second)
                      and no warnings about skipped input records
  -h, --help          show this help

Exit status: 0 on success, 2 on a usage or input problem (one line on standard
error).
)";

// ---- arguments of `hullkit hull` ----

struct HullArgs {
    std::vector<std::string> inputs;  ///< empty: standard input
    std::string output;  ///< empty: standard output
    bool format_given = false;
    hullkit::OutputFormat format = hullkit::OutputFormat::Off;
    hullkit::Algorithm algorithm = hullkit::HullOptions{}.algorithm;
    hullkit::SideTest side_test = hullkit::HullOptions{}.side_test;
    bool merge_coplanar = false;
    unsigned threads = 0;
    std::uint64_t memory_mb = 0;  ///< 0: the default, default_memory_mb()
    bool stats = false;
    bool quiet = false;
    bool help = false;
};

/// The default --memory: a quarter of the machine's memory, at most 2 GiB, at least 64 MiB.
std::uint64_t default_memory_mb() {
    std::uint64_t mb = 2048;
    const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
    if (pages > 0 && page_size > 0) {
        mb = std::min<std::uint64_t>(mb, static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size) / 4 >> 20);
    }
    return std::max<std::uint64_t>(mb, 64);
}

/// "quickhull, giftwrap"; with `mark_default`, the library's default is marked "(default)".
std::string known_algorithms(bool mark_default) {
    std::string names;
    for (hullkit::Algorithm algorithm : kAlgorithms) {
        if (!names.empty()) names += ", ";
        names += hullkit::algorithm_name(algorithm);
        if (mark_default && algorithm == hullkit::HullOptions{}.algorithm) names += " (default)";
    }
    return names;
}

/// Walks argv, handing out option values given as "--name VALUE" or "--name=VALUE".
class ArgCursor {
public:
    explicit ArgCursor(std::vector<std::string> args) : args_(std::move(args)) {}

    bool done() const { return index_ >= args_.size(); }
    const std::string& next() { return args_[index_++]; }

    /// The value of option `name` whose argument `arg` was just taken by next().
    std::string value_of(const std::string& arg, const std::string& name) {
        if (arg.size() > name.size() && arg.compare(0, name.size() + 1, name + "=") == 0) {
            return arg.substr(name.size() + 1);
        }
        if (done()) throw CliError("option " + name + " needs a value");
        return next();
    }

private:
    std::vector<std::string> args_;
    std::size_t index_ = 0;
};

/// True if `arg` is option `name`, alone or as "name=value".
bool is_option(const std::string& arg, const std::string& name) {
    return arg == name || arg.compare(0, name.size() + 1, name + "=") == 0;
}

HullArgs parse_hull_args(std::vector<std::string> argv) {
    HullArgs args;
    bool options_ended = false;
    ArgCursor cursor(std::move(argv));
    while (!cursor.done()) {
        const std::string arg = cursor.next();
        const bool is_flag = !options_ended && arg.size() > 1 && arg[0] == '-';
        if (!is_flag) {
            args.inputs.push_back(arg);
        } else if (arg == "--") {
            options_ended = true;
        } else if (arg == "-h" || arg == "--help") {
            args.help = true;
        } else if (arg == "-o" || is_option(arg, "--output")) {
            args.output = cursor.value_of(arg, arg == "-o" ? "-o" : "--output");
            if (args.output.empty()) throw CliError("option " + arg + " needs a file name");
        } else if (is_option(arg, "--format")) {
            std::string name = cursor.value_of(arg, "--format");
            if (!hullkit::parse_output_format(name, &args.format)) {
                throw CliError("unknown format \"" + name + "\" (known: off, obj, json, xyz, glb, normals)");
            }
            args.format_given = true;
        } else if (arg == "--vertices-only") {
            args.format = hullkit::OutputFormat::Xyz;
            args.format_given = true;
        } else if (arg == "--normals") {
            args.format = hullkit::OutputFormat::Normals;
            args.format_given = true;
        } else if (is_option(arg, "--threads")) {
            args.threads = static_cast<unsigned>(hullkit_cli::parse_whole_number(cursor.value_of(arg, "--threads"), "--threads", 0, 1024));
        } else if (is_option(arg, "--memory")) {
            args.memory_mb = hullkit_cli::parse_whole_number(cursor.value_of(arg, "--memory"), "--memory", 1, std::uint64_t{1} << 30);
        } else if (arg == "--quiet") {
            args.quiet = true;
        } else if (is_option(arg, "--algorithm")) {
            std::string name = cursor.value_of(arg, "--algorithm");
            if (!hullkit::parse_algorithm(name, &args.algorithm)) {
                throw CliError("unknown algorithm \"" + name + "\" (known: " + known_algorithms(false) +
                               ")");
            }
        } else if (is_option(arg, "--epsilon")) {
            std::string mode = cursor.value_of(arg, "--epsilon");
            if (mode == "exact") {
                args.side_test = hullkit::SideTest::Exact;
            } else if (mode == "seed") {
                args.side_test = hullkit::SideTest::Seed;
            } else {
                throw CliError("unknown epsilon \"" + mode + "\" (known: exact, seed)");
            }
        } else if (arg == "--merge-coplanar") {
            args.merge_coplanar = true;
        } else if (arg == "--stats") {
            args.stats = true;
        } else {
            throw CliError("unknown option \"" + arg + "\" (try 'hullkit hull --help')");
        }
    }
    // Without --format the output file's extension decides; the default stays OFF.
    if (!args.format_given && !args.output.empty() && args.output != "-") {
        hullkit::output_format_from_path(args.output, &args.format);
    }
    return args;
}

// ---- I/O ----

bool is_stdio(const std::string& path) { return path.empty() || path == "-"; }

/// Writes the hull to `path` (or stdout) in pieces, never holding the whole text. `index` maps the
/// hull's point indices to the input's (null: the same).
void write_hull_output(const std::string& path, hullkit::OutputFormat format, hullkit::PointSpan points,
                       const hullkit::Hull& hull, const std::uint64_t* index) {
    int error_number = 0;
    if (format == hullkit::OutputFormat::Glb) {
        // Binary, and refused as a whole for a coordinate beyond float32: built first, then written.
        std::string bytes;
        try {
            bytes = hullkit::write_glb(points, hull);
        } catch (const std::domain_error& error) {
            throw CliError((is_stdio(path) ? std::string("<stdout>") : path) + ": " + error.what());
        }
        try {
            hullkit_cli::write_output(path, bytes);
        } catch (const hullkit_cli::UsageError& error) {
            throw CliError(error.what());
        }
        return;
    }
    if (is_stdio(path)) {
        if (!hullkit::write_hull_file(format, points, hull, stdout, &error_number, index) || std::fflush(stdout) != 0) {
            throw CliError(std::string("<stdout>: cannot write: ") + std::strerror(error_number ? error_number : errno));
        }
        return;
    }
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw CliError(path + ": cannot open for writing: " + std::strerror(errno));
    bool written = false;
    try {
        written = hullkit::write_hull_file(format, points, hull, file, &error_number, index);
    } catch (...) {
        std::fclose(file);
        throw;
    }
    // fclose flushes, so a full disk may only show up here.
    if (std::fclose(file) != 0 && written) {
        written = false;
        error_number = errno;
    }
    if (!written) throw CliError(path + ": cannot write: " + std::strerror(error_number));
}

void print_stats(std::uint64_t points, const hullkit::Hull& hull, hullkit::Algorithm algorithm, double seconds,
                 bool streamed, unsigned threads) {
    std::fprintf(stderr,
                 "{\"points\":%llu,\"vertices\":%zu,\"faces\":%zu,\"volume\":%s,\"area\":%s,"
                 "\"algorithm\":\"%s\",\"seconds\":%.9g,\"streamed\":%s,\"threads\":%u}\n",
                 static_cast<unsigned long long>(points), hull.vertices.size(),
                 hull.face_offsets.empty() ? hull.face_count() : hull.face_offsets.size() - 1,
                 hullkit::format_json_number(hull.volume).c_str(),
                 hullkit::format_json_number(hull.area).c_str(),
                 hullkit::algorithm_name(algorithm), seconds, streamed ? "true" : "false", threads);
}

// ---- commands ----

/// Bytes of memory a point costs while it is hulled whole: its coordinates (24) and quickhull's
/// working arrays for it (candidate lists, the spatially ordered copy, sort keys, outside-list
/// links), measured on balls, cubes and spheres.
constexpr std::uint64_t kBytesPerPointWhole = 96;

/// Reads the points of every input in turn (one cloud, indices running on) and hulls them: whole
/// while they fit in the memory budget, else streamed through a HullBuilder that keeps only the
/// hull's vertices between pieces (same output).
}  // namespace

int hullkit_cli::run_hull(std::vector<std::string> argv) {
    HullArgs args = parse_hull_args(std::move(argv));
    if (args.help) {
        // The algorithm list is filled in from kAlgorithms so the help cannot go stale.
        std::string usage = kHullUsage;
        const std::string slot = "{algorithms}";
        usage.replace(usage.find(slot), slot.size(), known_algorithms(true));
        const std::string memory = "{memory}";
        usage.replace(usage.find(memory), memory.size(), std::to_string(default_memory_mb()) + " MB on this machine");
        std::fputs(usage.c_str(), stdout);
        return kExitOk;
    }
    if (args.inputs.empty()) args.inputs.push_back("-");
    const std::uint64_t budget = (args.memory_mb ? args.memory_mb : default_memory_mb()) << 20;
    hullkit::HullOptions options;
    options.algorithm = args.algorithm;
    options.side_test = args.side_test;
    options.merge_coplanar = args.merge_coplanar;
    options.threads = args.threads;
    // Only quickhull with exact sides streams; the others take the points whole, as before.
    const bool may_stream = args.algorithm == hullkit::Algorithm::Quickhull && args.side_test == hullkit::SideTest::Exact;
    const std::uint64_t whole_limit = std::max<std::uint64_t>(budget / kBytesPerPointWhole, 1024);

    hullkit::PointReaderOptions reading;
    reading.threads = args.threads;
    // Text is read and parsed a few MB at a time (on threads): enough for the threads to share,
    // small beside the points themselves.
    reading.batch_bytes = static_cast<std::size_t>(std::clamp<std::uint64_t>(budget / 256, 1 << 20, 4 << 20));

    hullkit_cli::Progress progress("points", 0, args.quiet);
    // The points read and not yet handed to the builder: the whole cloud while it fits the
    // budget; once it does not, pieces of that size, each added to the builder and cleared.
    std::vector<double> points;
    hullkit::HullBuilder builder(options);
    bool streaming = false;
    double hull_seconds = 0.0;
    std::uint64_t added = 0;  // points handed to the builder
    // What a message about a point names: the input, or all of them (indices run across them).
    std::string cloud_name;
    for (const std::string& input : args.inputs) cloud_name += (cloud_name.empty() ? "" : " + ") + (is_stdio(input) ? std::string("<stdin>") : input);
    auto timed = [&](auto&& work) {
        const auto start = std::chrono::steady_clock::now();
        work();
        hull_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    auto add_piece = [&] {
        bool ok = false;
        timed([&] { ok = builder.add(hullkit::PointSpan(points), added); });
        if (!ok) throw CliError(cloud_name + ": " + builder.error());
        added += points.size() / 3;
        points.clear();  // the capacity stays for the next piece
        streaming = true;
#if defined(__GLIBC__)  // nested: elsewhere the function-like __GLIBC_PREREQ does not exist
#if __GLIBC_PREREQ(2, 33)
        // Freed memory goes back to the system once it is a quarter of the budget. glibc keeps
        // freed blocks below its (adaptive) mmap threshold for reuse, and across pieces they
        // fragment: on one thread, 16 files of 6e6 points peaked at 466 MB under --memory 300
        // (140 MB live), and 182 MB with this.
        if (mallinfo2().fordblks > budget / 4) malloc_trim(0);
#endif
#endif
    };
    std::vector<std::pair<std::string, std::vector<std::string>>> warnings;  // per input, printed at the end
    for (const std::string& input : args.inputs) {
        const std::string name = is_stdio(input) ? "<stdin>" : input;
        std::FILE* file = is_stdio(input) ? stdin : std::fopen(input.c_str(), "rb");
        if (!file) throw CliError(input + ": cannot open: " + std::strerror(errno));
        struct Closer {
            std::FILE* file;
            ~Closer() { if (file != stdin) std::fclose(file); }
        } closer{file};
        hullkit::PointReader reader(file, name, reading);
        const std::uint64_t size = reader.size();
        // Address space for the points the header declares or the file could hold, up to a
        // piece and the batch that completes it (no point line is shorter than 6 bytes), so that
        // the array never grows by a copy, which would hold the old array and one of twice its
        // size at once (with several inputs, each used to add a piece's worth). Pages are
        // touched as points arrive.
        const std::uint64_t expected = reader.declared_points() ? reader.declared_points() : size ? size / 6 + 1 : 0;
        const std::uint64_t batch_points = reading.batch_bytes / 6 + 1;
        points.reserve(3 * static_cast<std::size_t>(std::min(points.size() / 3 + expected, whole_limit + batch_points)));
        while (reader.append_next(&points)) {
            if (may_stream && points.size() / 3 > whole_limit) add_piece();
            progress.update(added + points.size() / 3, args.inputs.size() == 1 && size > 0
                                                           ? static_cast<double>(reader.bytes_read()) / static_cast<double>(size)
                                                           : -1.0);
        }
        if (!reader.error().empty()) throw CliError(reader.error());
        warnings.emplace_back(name, reader.warnings());
    }
    progress.finish();  // before the warnings, which would otherwise share the progress line
    if (!args.quiet) {
        for (const auto& [name, lines] : warnings) hullkit_cli::print_warnings(name, lines);
    }
    const unsigned threads_used = args.threads ? args.threads : std::max(1u, std::thread::hardware_concurrency());

    if (!streaming) {
        hullkit::Hull hull;
        timed([&] { hull = hullkit::hull(hullkit::PointSpan(points), options); });
        if (!hull.ok()) throw CliError(cloud_name + ": " + hull.error);
        write_hull_output(args.output, args.format, hullkit::PointSpan(points), hull, nullptr);
        if (args.stats) print_stats(points.size() / 3, hull, args.algorithm, hull_seconds, false, threads_used);
        return kExitOk;
    }
    if (!points.empty()) add_piece();
    hullkit::StreamedHull result;
    timed([&] { result = builder.finish(); });
    if (!result.ok()) throw CliError(cloud_name + ": " + result.hull.error);
    write_hull_output(args.output, args.format, hullkit::PointSpan(result.points), result.hull, result.index.data());
    if (args.stats) print_stats(result.point_count, result.hull, args.algorithm, hull_seconds, true, threads_used);
    return kExitOk;
}

