// hullkit_bench: times one convex hull implementation on one input, in its own process, so that the
// peak memory reported is that run's.
//
//   hullkit_bench --impl IMPL --input FILE.bin [--runs 5] [--budget 60] [--name NAME]
//                 [--qhull-options "qhull"]
//
// IMPL is one of
//   hullkit-ALGO  hullkit::hull() with the algorithm parse_algorithm("ALGO") knows, e.g.
//                 hullkit-quickhull, hullkit-giftwrap. A name this build of hullkit does not know
//                 gives a result line with "error": "unknown algorithm ..." (and exit status 0), so
//                 a table can show the row as missing instead of the whole run failing.
//   qhull         Qhull 2020 (libqhull_r, reentrant C API): qh_new_qhull() on the in-memory array,
//                 option string "qhull" by default, i.e. Qhull's 3-d defaults: pre-merged facets
//                 (C-0, so faces are Qhull's own merged facet list, not triangles), no 'Qt', no
//                 output (outfile NULL). Override with --qhull-options (must start with "qhull").
//   cgal          CGAL::convex_hull_3 (CGAL 5.x) over std::vector<Point_3> with the
//                 Exact_predicates_inexact_constructions_kernel, into a CGAL::Surface_mesh.
//   command-hullkit  the whole command a user runs, one fresh process per run:
//                 `hullkit hull FILE -o OUT.off` (text in, OFF out; hullkit next to this binary
//                 unless --hullkit PATH), FILE being a text point file (rbox format).
//   command-qconvex  the same for Qhull's command: `qconvex o < FILE > OUT.off`.
//                 For the two command rows the time is the child's wall time (fork to exit), and
//                 peak_rss_mb its own peak (wait4's ru_maxrss), minor_faults its minor page faults.
//
// Input file: raw little-endian IEEE-754 doubles, x0 y0 z0 x1 y1 z1 ..., no header; the point count
// is the file size / 24. bench/make_inputs.mjs writes them.
//
// Timing: only the hull computation, `runs` times, after the input is read and converted into what
// the implementation takes (hullkit: the flat array itself; Qhull: the flat array; CGAL: a vector
// of Point_3 built once before the first run). Everything is freed between runs, outside the timed
// part (Qhull: qh_freeqhull + qh_memfreeshort; hullkit and CGAL: the result's destructor). Once the
// runs so far add up to more than --budget seconds no further run is started (at least one runs).
//
// The first run of the in-process implementations is the first call in a fresh process (nothing
// warmed: allocator, page tables, caches), what a user of `hullkit hull` gets; it is reported as
// "first" (with its minor page faults, "first_minor_faults") beside "warm_median", the median of
// the later runs.
//
// Output: one JSON line on stdout:
//   {"impl", "input", "file", "n", "runs": [seconds...], "median", "vertices", "faces",
//    "peak_rss_mb", "input_rss_mb", ...}
// vertices = the hull vertex count as reported by that implementation (hullkit: Hull::vertices,
// Qhull: its vertex list, CGAL: the mesh's vertices), faces = its face count (hullkit and CGAL:
// triangles, Qhull: merged facets). peak_rss_mb = getrusage(RUSAGE_SELF).ru_maxrss at exit (the
// whole process: input included); first_peak_rss_mb = the same right after the first run (what a
// process computing one hull reaches: the headline); input_rss_mb = the same taken right before
// the first run.
// On failure the line has "error" instead of the results.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "hullkit/hull.hpp"

// Qhull last: its headers define macros (True, False, trace...) that other headers do not expect.
#include <libqhull_r/libqhull_r.h>
#include <libqhull_r/mem_r.h>

namespace {

struct Args {
    std::string impl;
    std::string input;
    std::string name;
    int runs = 5;
    double budget = 60.0;
    std::string qhull_options = "qhull";
    std::string hullkit_cli;  // command-hullkit: the CLI (default: "hullkit" next to this binary)
};

/// One timed run: returns seconds and fills in the counts of the result it produced.
struct RunResult {
    double seconds = 0.0;
    std::size_t vertices = 0;
    std::size_t faces = 0;
    double peak_rss_mb = 0.0;  // command rows: the child's peak
    long minor_faults = 0;     // command rows: the child's minor page faults
    std::string error;  // empty on success
};

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            default:
                if (c < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    out += buf;
                } else {
                    out += static_cast<char>(c);
                }
        }
    }
    return out + "\"";
}

std::string json_number(double x) {
    if (!std::isfinite(x)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", x);
    return buf;
}

double peak_rss_mb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

std::string basename_without_bin(const std::string& path) {
    std::string base = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
    if (base.size() > 4 && base.compare(base.size() - 4, 4, ".bin") == 0) base.resize(base.size() - 4);
    return base;
}

bool host_is_little_endian() {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

/// Reads the whole file as little-endian doubles; false (and `error`) on a bad file.
bool read_points(const std::string& path, std::vector<double>& xyz, std::string& error) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) {
        error = "cannot open " + path;
        return false;
    }
    const std::streamoff size = in.tellg();
    if (size < 0 || size % 24 != 0) {
        error = path + ": size " + std::to_string(size) + " is not a whole number of 3D points (24 bytes each)";
        return false;
    }
    xyz.resize(static_cast<std::size_t>(size) / 8);
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(xyz.data()), size)) {
        error = "cannot read " + path;
        return false;
    }
    if (!host_is_little_endian()) {
        for (double& x : xyz) {
            unsigned char b[8];
            std::memcpy(b, &x, 8);
            std::reverse(b, b + 8);
            std::memcpy(&x, b, 8);
        }
    }
    return true;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

long minor_faults_so_far() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

// ---- the implementations: each returns a function performing one timed run ----

using Runner = std::function<RunResult()>;

Runner hullkit_runner(const std::vector<double>& xyz, hullkit::Algorithm algorithm) {
    return [&xyz, algorithm]() {
        RunResult r;
        hullkit::HullOptions options;
        options.algorithm = algorithm;
        const hullkit::PointSpan points(xyz.data(), xyz.size() / 3);
        const auto start = std::chrono::steady_clock::now();
        hullkit::Hull hull = hullkit::hull(points, options);
        r.seconds = seconds_since(start);
        if (!hull.ok()) r.error = "hullkit: " + hull.error;
        r.vertices = hull.vertices.size();
        r.faces = hull.face_count();
        return r;  // the Hull is destroyed here, after the clock stopped
    };
}

Runner qhull_runner(std::vector<double>& xyz, const std::string& options) {
    return [&xyz, options]() {
        RunResult r;
        qhT qh_storage;
        qhT* qh = &qh_storage;
        qh_zero(qh, stderr);
        std::vector<char> flags(options.begin(), options.end());
        flags.push_back('\0');
        const auto start = std::chrono::steady_clock::now();
        // ismalloc = False: Qhull reads our array in place and does not free it.
        // outfile = NULL: no output is produced, only the hull structure.
        const int exitcode = qh_new_qhull(qh, 3, static_cast<int>(xyz.size() / 3), xyz.data(), False,
                                          flags.data(), nullptr, stderr);
        r.seconds = seconds_since(start);
        if (exitcode != 0) {
            r.error = "qhull: qh_new_qhull exit code " + std::to_string(exitcode);
        } else {
            vertexT* vertex;
            facetT* facet;
            FORALLvertices {
                if (!vertex->deleted) ++r.vertices;
            }
            FORALLfacets {
                if (!facet->visible) ++r.faces;
            }
        }
        qh_freeqhull(qh, !qh_ALL);
        int curlong = 0;
        int totlong = 0;
        qh_memfreeshort(qh, &curlong, &totlong);
        if (curlong || totlong) {
            std::fprintf(stderr, "hullkit_bench: qhull did not free %d bytes of long memory (%d pieces)\n",
                         totlong, curlong);
        }
        return r;
    };
}

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point3>;

Runner cgal_runner(const std::vector<Point3>& points) {
    return [&points]() {
        RunResult r;
        Mesh mesh;
        const auto start = std::chrono::steady_clock::now();
        CGAL::convex_hull_3(points.begin(), points.end(), mesh);
        r.seconds = seconds_since(start);
        r.vertices = mesh.number_of_vertices();
        r.faces = mesh.number_of_faces();
        if (r.vertices == 0) r.error = "cgal: empty hull (degenerate input?)";
        return r;  // the mesh is destroyed after the clock stopped
    };
}

/// "V F" from the counts line of an OFF file (hullkit: "OFF" then "V F 0"; qconvex o: "3" then
/// "V F R"): the first line with three numbers.
void read_off_counts(const std::string& path, RunResult& r) {
    std::ifstream in(path);
    std::string line;
    for (int k = 0; k < 3 && std::getline(in, line); ++k) {
        std::istringstream fields(line);
        std::size_t v = 0, f = 0, e = 0;
        if (fields >> v >> f >> e) {
            r.vertices = v;
            r.faces = f;
            return;
        }
    }
    r.error = path + ": no OFF counts line in the output";
}

/// One run of a command in a fresh process: stdin from `in` (unless empty), stdout to `out`.
Runner command_runner(std::vector<std::string> argv, std::string in, std::string out, std::string off) {
    return [argv, in, out, off]() {
        RunResult r;
        std::vector<char*> args;
        for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        const auto start = std::chrono::steady_clock::now();
        const pid_t pid = fork();
        if (pid == 0) {
            if (!in.empty()) {
                const int fd = open(in.c_str(), O_RDONLY);
                if (fd < 0 || dup2(fd, 0) < 0) _exit(126);
                close(fd);
            }
            const int fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (fd < 0 || dup2(fd, 1) < 0) _exit(126);
            close(fd);
            execvp(args[0], args.data());
            _exit(127);
        }
        if (pid < 0) {
            r.error = std::string("fork failed: ") + std::strerror(errno);
            return r;
        }
        int status = 0;
        rusage usage{};
        wait4(pid, &status, 0, &usage);
        r.seconds = seconds_since(start);
        r.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
        r.minor_faults = usage.ru_minflt;
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            r.error = argv[0] + " failed (status " + std::to_string(status) + ")";
            return r;
        }
        read_off_counts(off, r);
        unlink(off.c_str());
        return r;
    };
}

void usage_and_exit(const char* message) {
    if (message) std::fprintf(stderr, "hullkit_bench: %s\n", message);
    std::fprintf(stderr,
                 "usage: hullkit_bench --impl hullkit-ALGO|qhull|cgal --input FILE.bin [--runs 5]\n"
                 "                     [--budget SECONDS] [--name NAME] [--qhull-options \"qhull ...\"]\n");
    std::exit(2);
}

Args parse_args(int argc, char** argv) {
    Args args;
    for (int i = 1; i < argc; ++i) {
        const std::string key = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage_and_exit((key + " needs a value").c_str());
            return argv[++i];
        };
        if (key == "--impl") args.impl = value();
        else if (key == "--input") args.input = value();
        else if (key == "--name") args.name = value();
        else if (key == "--runs") args.runs = std::atoi(value().c_str());
        else if (key == "--budget") args.budget = std::atof(value().c_str());
        else if (key == "--qhull-options") args.qhull_options = value();
        else if (key == "--hullkit") args.hullkit_cli = value();
        else if (key == "--help" || key == "-h") usage_and_exit(nullptr);
        else usage_and_exit(("unknown argument " + key).c_str());
    }
    if (args.impl.empty() || args.input.empty()) usage_and_exit("--impl and --input are required");
    if (args.runs < 1) usage_and_exit("--runs must be at least 1");
    if (args.qhull_options.rfind("qhull", 0) != 0) usage_and_exit("--qhull-options must start with \"qhull\"");
    if (args.name.empty()) args.name = basename_without_bin(args.input);
    if (args.hullkit_cli.empty()) {
        const std::string self = argv[0];
        const std::size_t slash = self.find_last_of('/');
        args.hullkit_cli = (slash == std::string::npos ? std::string(".") : self.substr(0, slash)) + "/hullkit";
    }
    return args;
}

}  // namespace

int main(int argc, char** argv) {
    const Args args = parse_args(argc, argv);

    std::ostringstream head;
    head << "{\"impl\":" << json_string(args.impl) << ",\"input\":" << json_string(args.name)
         << ",\"file\":" << json_string(args.input);
    auto fail = [&](const std::string& error, std::size_t n) {
        std::cout << head.str() << ",\"n\":" << n << ",\"error\":" << json_string(error) << "}" << std::endl;
    };

    const bool command = args.impl.rfind("command-", 0) == 0;
    std::vector<double> xyz;
    std::string error;
    if (command) {
        // The input is a text file; the point count is its second line (rbox format).
        std::ifstream in(args.input);
        std::string header, count;
        if (!in || !std::getline(in, header) || !std::getline(in, count)) {
            fail("cannot read the rbox header of " + args.input, 0);
            return 1;
        }
        xyz.resize(3 * std::strtoull(count.c_str(), nullptr, 10));
    } else if (!read_points(args.input, xyz, error)) {
        fail(error, 0);
        return 1;
    }
    const std::size_t n = xyz.size() / 3;

    std::vector<Point3> cgal_points;  // only filled for CGAL
    Runner run;
    std::string detail;  // what exactly ran, for the JSON line
    if (args.impl.rfind("hullkit-", 0) == 0) {
        const std::string name = args.impl.substr(8);
        hullkit::Algorithm algorithm{};
        if (!hullkit::parse_algorithm(name, &algorithm)) {
            fail("unknown algorithm \"" + name + "\": hullkit::parse_algorithm does not know it in this build", n);
            return 0;
        }
        detail = std::string("hullkit::hull, algorithm ") + hullkit::algorithm_name(algorithm);
        run = hullkit_runner(xyz, algorithm);
    } else if (args.impl == "qhull") {
        if (n > static_cast<std::size_t>(INT32_MAX)) {
            fail("too many points for Qhull's int count", n);
            return 1;
        }
        detail = "qh_new_qhull \"" + args.qhull_options + "\" (Qhull " + qh_version + ")";
        run = qhull_runner(xyz, args.qhull_options);
    } else if (command) {
        const std::string off = "/tmp/hullkit_bench_" + std::to_string(getpid()) + ".off";
        if (args.impl == "command-hullkit") {
            detail = "hullkit hull FILE -o OUT.off (" + args.hullkit_cli + ")";
            run = command_runner({args.hullkit_cli, "hull", args.input, "-o", off}, "", "/dev/null", off);
        } else if (args.impl == "command-qconvex") {
            detail = "qconvex o < FILE > OUT.off";
            run = command_runner({"qconvex", "o"}, args.input, off, off);
        } else {
            fail("unknown command implementation \"" + args.impl + "\" (known: command-hullkit, command-qconvex)", n);
            return 2;
        }
    } else if (args.impl == "cgal") {
        cgal_points.reserve(n);
        for (std::size_t i = 0; i < n; ++i) cgal_points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        detail = "CGAL::convex_hull_3 (CGAL " CGAL_STR(CGAL_VERSION) ", Epick) into Surface_mesh";
        run = cgal_runner(cgal_points);
    } else {
        fail("unknown implementation \"" + args.impl + "\" (known: hullkit-ALGO, qhull, cgal)", n);
        return 2;
    }

    const double input_rss = peak_rss_mb();
    std::vector<double> times;
    RunResult last;
    double total = 0.0;
    double command_peak = 0.0;
    long first_faults = 0;
    double first_peak = 0.0;
    for (int k = 0; k < args.runs; ++k) {
        if (k > 0 && total > args.budget) break;
        const long faults_before = minor_faults_so_far();
        last = run();
        if (k == 0) {
            first_faults = command ? last.minor_faults : minor_faults_so_far() - faults_before;
            first_peak = command ? last.peak_rss_mb : peak_rss_mb();
        }
        command_peak = std::max(command_peak, last.peak_rss_mb);
        if (!last.error.empty()) {
            fail(last.error, n);
            return 1;
        }
        times.push_back(last.seconds);
        total += last.seconds;
    }

    auto median_of = [](std::vector<double> v) {
        if (v.empty()) return std::nan("");
        std::sort(v.begin(), v.end());
        const std::size_t m = v.size();
        return m % 2 ? v[m / 2] : 0.5 * (v[m / 2 - 1] + v[m / 2]);
    };
    std::vector<double> sorted = times;
    std::sort(sorted.begin(), sorted.end());
    const double median = median_of(times);
    const double warm_median = median_of(std::vector<double>(times.begin() + 1, times.end()));

    std::cout << head.str() << ",\"n\":" << n << ",\"detail\":" << json_string(detail) << ",\"runs\":[";
    for (std::size_t k = 0; k < times.size(); ++k) std::cout << (k ? "," : "") << json_number(times[k]);
    std::cout << "],\"runs_requested\":" << args.runs << ",\"median\":" << json_number(median)
              << ",\"min\":" << json_number(sorted.front()) << ",\"first\":" << json_number(times.front())
              << ",\"warm_median\":" << json_number(warm_median) << ",\"first_minor_faults\":" << first_faults
              << ",\"vertices\":" << last.vertices << ",\"faces\":" << last.faces
              << ",\"peak_rss_mb\":" << json_number(command ? command_peak : peak_rss_mb())
              << ",\"first_peak_rss_mb\":" << json_number(first_peak)
              << ",\"input_rss_mb\":" << json_number(command ? 0.0 : input_rss) << "}" << std::endl;
    return 0;
}
