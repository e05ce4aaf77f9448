// The `hullkit` command: argument parsing and I/O around hullkit::hull. No geometry here.
//
// Exit codes: 0 success; 2 any usage or input problem; 1 an internal failure (a bug or out of
// memory). Every failure prints exactly one line "hullkit: ..." on stderr.
#include "hullkit/hull.hpp"
#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"
#include "delaunay_command.hpp"
#include "route_command.hpp"
#include "verify_command.hpp"

#include <cerrno>
#include <cstdint>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr const char* kVersion = "0.1.0";
constexpr int kExitOk = 0;
constexpr int kExitInternal = 1;
constexpr int kExitUsage = 2;

/// Every algorithm the CLI offers; extend together with hullkit::Algorithm.
constexpr hullkit::Algorithm kAlgorithms[] = {hullkit::Algorithm::Quickhull,
                                              hullkit::Algorithm::Giftwrap};

const char* const kMainUsage =
    R"(Usage: hullkit <command> [options]

Commands:
  hull             compute the convex hull of a 3D point set
  verify           check exactly that an OFF file is the convex hull of a point set
  delaunay         Delaunay triangulation of 2D points (by lifting to a paraboloid)
  verify-delaunay  check exactly that an OFF file is a Delaunay triangulation
  route            check a traverse's route of straight legs against obstacles

Options:
  -h, --help  show this help
  --version   show the version

Run 'hullkit hull --help' for the options of a command.
)";

const char* const kHullUsage =
    R"(Usage: hullkit hull [INPUT|-] [-o FILE] [--format off|obj|json] [--algorithm NAME]
                    [--merge-coplanar] [--epsilon exact|seed] [--stats]

Computes the convex hull of the 3D points in INPUT (standard input if INPUT is
missing or '-') and writes its vertices and triangles (counter-clockwise seen
from outside).

Input formats, detected automatically ('#' starts a comment in all of them):
  x y z           one point per line, separated by whitespace or a comma
  qhull / rbox    the dimension (3), the point count, then one point per line
  OBJ             'v x y z' lines are the points; other records are ignored
  OFF             'OFF', 'vertices faces edges', vertex lines; faces ignored
  PLY, STL        a file's vertices (PLY point clouds without faces too), by
                  name or content; from a file, not standard input

Options:
  -o, --output FILE   write the hull to FILE instead of standard output
  --format FORMAT     off (default), obj or json; without --format, an output
                      FILE ending in .obj or .json selects that format
  --algorithm NAME    hull algorithm: {algorithms}
  --merge-coplanar    write each planar face as one convex polygon (a cube: 6
                      quads) instead of triangles; JSON gets a "faces" list
  --epsilon MODE      exact (default): every decision by exact predicates;
                      seed: the seed document's epsilon (giftwrap only), for
                      comparison, it may reject near-degenerate input
  --stats             print one JSON line of statistics to standard error:
                      points, vertices, faces, volume, area, algorithm,
                      seconds (the hull computation alone)
Points that are all coplanar, collinear or identical give a polygon, a segment
or a point (OFF/OBJ: the polygon's triangles; JSON: "dimension").
  -h, --help          show this help

Exit status: 0 on success, 2 on a usage or input problem (one line on stderr).
)";

/// A failure to report as "hullkit: <message>" with the given exit code.
struct CliError : std::runtime_error {
    int exit_code;
    CliError(const std::string& message, int code = kExitUsage)
        : std::runtime_error(message), exit_code(code) {}
};

void print_error(const std::string& message) {
    // One line per error, even if a message from deeper down contained a line break.
    std::string line = message;
    for (char& c : line) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    std::fprintf(stderr, "hullkit: %s\n", line.c_str());
}

// ---- arguments of `hullkit hull` ----

struct HullArgs {
    std::string input = "-";
    std::string output;  ///< empty: standard output
    bool format_given = false;
    hullkit::OutputFormat format = hullkit::OutputFormat::Off;
    hullkit::Algorithm algorithm = hullkit::HullOptions{}.algorithm;
    hullkit::SideTest side_test = hullkit::HullOptions{}.side_test;
    bool merge_coplanar = false;
    bool stats = false;
    bool help = false;
};

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
    bool input_given = false;
    bool options_ended = false;
    ArgCursor cursor(std::move(argv));
    while (!cursor.done()) {
        const std::string arg = cursor.next();
        const bool is_flag = !options_ended && arg.size() > 1 && arg[0] == '-';
        if (!is_flag) {
            if (input_given) {
                throw CliError("unexpected argument \"" + arg + "\" (only one INPUT is allowed)");
            }
            args.input = arg;
            input_given = true;
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
                throw CliError("unknown format \"" + name + "\" (known: off, obj, json)");
            }
            args.format_given = true;
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

/// Writes the hull to `path` (or stdout) in pieces, never holding the whole text.
void write_output(const std::string& path, hullkit::OutputFormat format, hullkit::PointSpan points,
                  const hullkit::Hull& hull) {
    int error_number = 0;
    if (is_stdio(path)) {
        if (!hullkit::write_hull_file(format, points, hull, stdout, &error_number) || std::fflush(stdout) != 0) {
            throw CliError(std::string("<stdout>: cannot write: ") + std::strerror(error_number ? error_number : errno));
        }
        return;
    }
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw CliError(path + ": cannot open for writing: " + std::strerror(errno));
    bool written = false;
    try {
        written = hullkit::write_hull_file(format, points, hull, file, &error_number);
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

void print_stats(std::size_t points, const hullkit::Hull& hull, hullkit::Algorithm algorithm,
                 double seconds) {
    std::fprintf(stderr,
                 "{\"points\":%zu,\"vertices\":%zu,\"faces\":%zu,\"volume\":%s,\"area\":%s,"
                 "\"algorithm\":\"%s\",\"seconds\":%.9g}\n",
                 points, hull.vertices.size(),
                 hull.face_offsets.empty() ? hull.face_count() : hull.face_offsets.size() - 1,
                 hullkit::format_json_number(hull.volume).c_str(),
                 hullkit::format_json_number(hull.area).c_str(),
                 hullkit::algorithm_name(algorithm), seconds);
}

// ---- commands ----

/// Whether the file at `path` goes to the mesh readers (hullkit::starts_like_mesh_file on its first
/// 84 bytes and its size). Such files are read whole by hullkit::read_points; text point files
/// are streamed.
bool is_mesh_file(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return false;  // read_points_file reports it
    char head[84];
    const std::size_t got = std::fread(head, 1, sizeof head, file);
    long size = -1;
    if (std::fseek(file, 0, SEEK_END) == 0) size = std::ftell(file);
    std::fclose(file);
    return hullkit::starts_like_mesh_file(std::string(head, got), size < 0 ? 0 : static_cast<std::uint64_t>(size), path);
}

/// Reads the points of `input` (a path, or stdin for "-"): text in chunks, without a copy of the
/// text; a PLY or STL file whole, its vertices as the points.
hullkit::PointsResult load_points(const std::string& input, const std::string& name) {
    hullkit::PointsResult points;
    if (is_stdio(input)) {
        points = hullkit::read_points_file(stdin, name);
    } else if (is_mesh_file(input)) {
        std::string bytes, error;
        if (!hullkit::read_file(input, &bytes, &error)) throw CliError(error);
        points = hullkit::read_points(bytes, name);
    } else {
        points = hullkit::read_points_file(input);
    }
    if (!points.ok()) throw CliError(points.error);
    return points;
}

int run_hull(std::vector<std::string> argv) {
    HullArgs args = parse_hull_args(std::move(argv));
    if (args.help) {
        // The algorithm list is filled in from kAlgorithms so the help cannot go stale.
        std::string usage = kHullUsage;
        const std::string slot = "{algorithms}";
        usage.replace(usage.find(slot), slot.size(), known_algorithms(true));
        std::fputs(usage.c_str(), stdout);
        return kExitOk;
    }
    const std::string name = is_stdio(args.input) ? "<stdin>" : args.input;
    hullkit::PointsResult points = load_points(args.input, name);

    hullkit::HullOptions options;
    options.algorithm = args.algorithm;
    options.side_test = args.side_test;
    options.merge_coplanar = args.merge_coplanar;
    const auto start = std::chrono::steady_clock::now();
    hullkit::Hull hull = hullkit::hull(hullkit::PointSpan(points.xyz), options);
    const auto stop = std::chrono::steady_clock::now();
    if (!hull.ok()) throw CliError(name + ": " + hull.error);

    write_output(args.output, args.format, hullkit::PointSpan(points.xyz), hull);
    if (args.stats) {
        print_stats(points.count(), hull, args.algorithm,
                    std::chrono::duration<double>(stop - start).count());
    }
    return kExitOk;
}

int run(int argc, char** argv) {
    if (argc < 2) throw CliError("missing command (try 'hullkit --help')");
    const std::string command = argv[1];
    std::vector<std::string> rest(argv + 2, argv + argc);
    if (command == "-h" || command == "--help") {
        std::fputs(kMainUsage, stdout);
        return kExitOk;
    }
    if (command == "--version") {
        std::printf("hullkit %s\n", kVersion);
        return kExitOk;
    }
    if (command == "hull") return run_hull(std::move(rest));
    if (command == "verify") return hullkit_cli::run_verify(rest);
    if (command == "delaunay") return hullkit_cli::run_delaunay(rest);
    if (command == "verify-delaunay") return hullkit_cli::run_verify_delaunay(rest);
    if (command == "route") return hullkit_cli::run_route(rest);
    if (!command.empty() && command[0] == '-') {
        throw CliError("unknown option \"" + command + "\" (try 'hullkit --help')");
    }
    throw CliError("unknown command \"" + command + "\" (try 'hullkit --help')");
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const CliError& error) {
        print_error(error.what());
        return error.exit_code;
    } catch (const std::bad_alloc&) {
        print_error("out of memory");
        return kExitInternal;
    } catch (const std::exception& error) {
        print_error(std::string("internal error: ") + error.what());
        return kExitInternal;
    }
}
