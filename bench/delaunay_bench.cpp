// hullkit_delaunay_bench: times one Delaunay implementation on one 2D input file, in its own
// process, so that the first call is a user's first call and the peak memory is that run's.
//
//   hullkit_delaunay_bench --impl IMPL --input FILE.bin [--runs 5] [--budget 60] [--name NAME] [--threads N]
//
// IMPL is one of
//   hullkit-ALGO  hullkit::delaunay() with the algorithm parse_delaunay_algorithm("ALGO") knows
//                 (hullkit-incremental, hullkit-giftwrap); an unknown name gives a result line with
//                 "error" (exit status 0), so a table can show the row as missing. --threads sets
//                 DelaunayOptions::threads (default 0: the library's default, two for large inputs).
//   cgal          CGAL::Delaunay_triangulation_2 (CGAL 5.x, Exact_predicates_inexact_constructions_
//                 kernel): the range insert, which sorts the points along a Hilbert curve first.
//
// Input file: raw little-endian doubles x0 y0 x1 y1 ..., no header (point count = size / 16);
// bench/delaunay_inputs.mjs writes them.
//
// Timing: the triangulation alone, after the input is read and converted into what the
// implementation takes (hullkit: the flat array itself; CGAL: a vector of Point_2 built once). The
// first run is reported on its own ("first": what a user meets, caches and allocator cold) and the
// median of the later runs as "warm". Results are freed between runs, outside the timed part. No run
// starts once the runs so far add up to more than --budget seconds (at least one runs).
//
// Output: one JSON line on stdout:
//   {"impl", "input", "n", "first", "runs": [seconds...], "warm" (median of runs after the first,
//    null with one run), "triangles", "peak_rss_mb", "input_rss_mb"}
// peak_rss_mb = getrusage(RUSAGE_SELF).ru_maxrss at exit (the whole process, input included);
// input_rss_mb the same right before the first run. On failure the line has "error" instead.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <iterator>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "hullkit/delaunay.hpp"

namespace {

struct Args {
    std::string impl, input, name;
    int runs = 5;
    double budget = 60.0;
    unsigned threads = 0;
};

/// Parses the command line with CLI11 (as the hullkit command does); exits 2 on a usage error.
Args parse_args(int argc, char** argv) {
    Args args;
    CLI::App app{"times one Delaunay implementation on one 2D input file", "hullkit_delaunay_bench"};
    app.add_option("--impl", args.impl, "hullkit-ALGO or cgal")->required();
    app.add_option("--input", args.input, "raw little-endian x y doubles")->required();
    app.add_option("--runs", args.runs, "timed runs, the first reported on its own")->check(CLI::PositiveNumber);
    app.add_option("--budget", args.budget, "no further run once the runs add up to this many seconds");
    app.add_option("--threads", args.threads, "hullkit: DelaunayOptions::threads (0: the library's default, 1: one thread)");
    app.add_option("--name", args.name, "the input's name in the output (default: the file name without .bin)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        std::exit(app.exit(error) == 0 ? 0 : 2);
    }
    if (args.name.empty()) {
        const std::size_t slash = args.input.find_last_of('/');
        args.name = args.input.substr(slash == std::string::npos ? 0 : slash + 1);
        if (args.name.size() > 4 && args.name.compare(args.name.size() - 4, 4, ".bin") == 0) args.name.resize(args.name.size() - 4);
    }
    return args;
}

double peak_rss_mb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

void print_error(const Args& args, const std::string& error) {
    std::printf("{\"impl\":%s,\"input\":%s,\"error\":%s}\n", json_string(args.impl).c_str(), json_string(args.name).c_str(),
                json_string(error).c_str());
}

/// One timed run: seconds, and the triangle count of what it built (to compare implementations).
struct Run {
    double seconds = 0;
    std::size_t triangles = 0;
};

using Runner = std::function<Run()>;

}  // namespace

int main(int argc, char** argv) {
    const Args args = parse_args(argc, argv);
    std::ifstream in(args.input, std::ios::binary);
    if (!in) {
        print_error(args, "cannot open " + args.input);
        return 0;
    }
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() % 16 != 0) {
        print_error(args, args.input + ": not a whole number of 2D points");
        return 0;
    }
    std::vector<double> xy(bytes.size() / 8);
    std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(xy.data()));  // little-endian host
    bytes = {};
    bytes.shrink_to_fit();
    const std::size_t n = xy.size() / 2;

    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<Kernel::Point_2> cgal_points;
    Runner run;
    if (args.impl.rfind("hullkit-", 0) == 0) {
        hullkit::DelaunayOptions options;
        options.threads = args.threads;
        const std::string algorithm = args.impl.substr(8);
        if (!hullkit::parse_delaunay_algorithm(algorithm, &options.algorithm)) {
            print_error(args, "unknown algorithm \"" + algorithm + "\"");
            return 0;
        }
        run = [&xy, options]() {
            const auto start = std::chrono::steady_clock::now();
            hullkit::Delaunay result = hullkit::delaunay(hullkit::PointSpan2(xy), options);
            const auto stop = std::chrono::steady_clock::now();
            if (!result.ok()) throw std::runtime_error(result.error);
            return Run{std::chrono::duration<double>(stop - start).count(), result.triangle_count()};
        };
    } else if (args.impl == "cgal") {
        cgal_points.reserve(n);
        for (std::size_t i = 0; i < n; ++i) cgal_points.emplace_back(xy[2 * i], xy[2 * i + 1]);
        run = [&cgal_points]() {
            const auto start = std::chrono::steady_clock::now();
            CGAL::Delaunay_triangulation_2<Kernel> triangulation;
            triangulation.insert(cgal_points.begin(), cgal_points.end());
            const auto stop = std::chrono::steady_clock::now();
            return Run{std::chrono::duration<double>(stop - start).count(), triangulation.number_of_faces()};
        };
    } else {
        print_error(args, "unknown implementation (known: hullkit-ALGO, cgal)");
        return 0;
    }

    const double input_rss = peak_rss_mb();
    std::vector<double> runs;
    std::size_t triangles = 0;
    double total = 0;
    try {
        for (int k = 0; k < args.runs && (k == 0 || total < args.budget); ++k) {
            const Run result = run();
            runs.push_back(result.seconds);
            triangles = result.triangles;
            total += result.seconds;
        }
    } catch (const std::exception& error) {
        print_error(args, error.what());
        return 0;
    }
    std::string warm = "null";
    if (runs.size() > 1) {
        std::vector<double> later(runs.begin() + 1, runs.end());
        std::sort(later.begin(), later.end());
        const std::size_t m = later.size();
        const double median = m % 2 ? later[m / 2] : (later[m / 2 - 1] + later[m / 2]) / 2;
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.6g", median);
        warm = buffer;
    }
    std::string list;
    for (double seconds : runs) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%s%.6g", list.empty() ? "" : ",", seconds);
        list += buffer;
    }
    std::printf("{\"impl\":%s,\"input\":%s,\"n\":%zu,\"first\":%.6g,\"runs\":[%s],\"warm\":%s,\"triangles\":%zu,"
                "\"peak_rss_mb\":%.1f,\"input_rss_mb\":%.1f}\n",
                json_string(args.impl).c_str(), json_string(args.name).c_str(), n, runs.front(), list.c_str(), warm.c_str(),
                triangles, peak_rss_mb(), input_rss);
    return 0;
}
