// hullkit_delaunay3_bench: times one 3D Delaunay implementation on one input file in its own process
// (so that the first call is a user's first call and the peak memory is that run's), and reads
// other programs' tetrahedra back to count and compare them.
//
//   hullkit_delaunay3_bench --impl hullkit|cgal --input FILE.bin [--runs 5] [--budget 60]
//                           [--threads N] [--name NAME] [--no-examine]
//   hullkit_delaunay3_bench --count TETS --format ele|qhull|u32 --input FILE.bin [--impl LABEL] [--name NAME]
//
// --impl
//   hullkit  hullkit::delaunay3(PointSpan, Delaunay3Options{threads}) on the flat array itself;
//            --threads: 0 (default) every hardware thread, 1 the calling thread only.
//   cgal     CGAL::Delaunay_triangulation_3<Epick> (CGAL 5.x) constructed from the range of
//            Point_3 (a vector built once, untimed): its range insert sorts the points along a
//            Hilbert curve first. Single-threaded (the sequential tag).
// --count reads the tetrahedra another program wrote (TetGen's or hullkit's .ele, numbered from 1
// as the .node files here are; qhull's `i` output: a count line, then 4 indices from 0 a line;
// u32: raw little-endian uint32, 4 per tetrahedron, from 0, as bench/delaunay3_python.py and
// bench/delaunay3_wasm_bench.mjs write them) and reports them as below, without "first"/"runs".
//
// Input file: raw little-endian doubles x0 y0 z0 x1 ..., no header (point count = size / 24);
// bench/delaunay3_inputs.mjs writes them.
//
// Timing: the tetrahedralization alone, after the input is in memory in the form the implementation
// takes. The first run is reported on its own ("first": what a user meets: allocator and page
// tables cold) with its minor page faults, the median of the later runs as "warm". Each run's
// result is freed before the next one starts, outside the timed part; no run starts once the runs
// so far add up to more than --budget seconds (at least one runs).
//
// After the runs (untimed, and after peak_rss_mb is taken) the last result is examined (with
// --no-examine, for the memory test, only counted):
//   "tetrahedra"   the number of (finite) tetrahedra;
//   "flat"         how many have zero volume, exactly: with integer coordinates below 2^19 in
//                  magnitude the determinant in int64 (no rounding possible), otherwise CGAL's exact
//                  orientation predicate; "flat_method" says which;
//   "fingerprint"  a hash of the set of tetrahedra that ignores their order and their corners'
//                  order (each tetrahedron's sorted indices hashed with splitmix64, summed mod 2^64):
//                  two implementations with the same fingerprint built the same tetrahedra.
//
// Output: one JSON line on stdout:
//   {"impl", "input", "n", "threads", "first", "first_minor_faults", "runs", "warm", "tetrahedra",
//    "flat", "flat_method", "fingerprint", "peak_rss_mb", "peak_rss_all_runs_mb", "input_rss_mb"}
// peak_rss_mb = getrusage(RUSAGE_SELF).ru_maxrss right after the first run (the first call's peak:
// the whole process, input and CGAL's Point_3 copy included); peak_rss_all_runs_mb the same after
// the warm runs too (the allocator's heap may have grown between calls); input_rss_mb the same
// before the first run. On failure the line has "error" instead.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <sys/resource.h>

#include "hullkit/delaunay3.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangulation = CGAL::Delaunay_triangulation_3<Kernel>;
using Tet = std::array<std::uint32_t, 4>;

struct Args {
    std::string impl, input, name, count, format;
    int runs = 5;
    double budget = 60.0;
    unsigned threads = 0;
    bool examine = true;
};

Args parse_args(int argc, char** argv) {
    Args args;
    CLI::App app{"times one 3D Delaunay implementation on one input file", "hullkit_delaunay3_bench"};
    app.add_option("--impl", args.impl, "hullkit or cgal (with --count: the label of the result line)");
    app.add_option("--input", args.input, "raw little-endian x y z doubles")->required();
    app.add_option("--runs", args.runs, "timed runs, the first reported on its own")->check(CLI::PositiveNumber);
    app.add_option("--budget", args.budget, "no further run once the runs add up to this many seconds");
    app.add_option("--threads", args.threads, "hullkit: Delaunay3Options::threads (0: every hardware thread)");
    app.add_option("--name", args.name, "the input's name in the output (default: the file name without .bin)");
    app.add_flag("!--no-examine", args.examine, "only count the tetrahedra (no flat count, no fingerprint): for the memory test");
    app.add_option("--count", args.count, "read these tetrahedra instead of computing any");
    app.add_option("--format", args.format, "of --count: ele (from 1), qhull (`i` output) or u32 (raw, from 0)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        std::exit(app.exit(error) == 0 ? 0 : 2);
    }
    if (args.count.empty() && args.impl.empty()) {
        std::fprintf(stderr, "hullkit_delaunay3_bench: --impl or --count is required\n");
        std::exit(2);
    }
    if (args.name.empty()) args.name = std::filesystem::path(args.input).stem().string();
    return args;
}

rusage usage_now() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage;
}
double peak_rss_mb() { return static_cast<double>(usage_now().ru_maxrss) / 1024.0; }  // Linux: kilobytes

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c >= 0 && c < 0x20 ? ' ' : c;
    }
    return out + "\"";
}

std::string number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

[[noreturn]] void fail(const Args& args, const std::string& error) {
    std::printf("{\"impl\":%s,\"input\":%s,\"error\":%s}\n", json_string(args.impl).c_str(), json_string(args.name).c_str(),
                json_string(error).c_str());
    std::exit(0);
}

std::vector<char> read_file(const Args& args, const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(args, "cannot open " + path);
    return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::vector<double> read_points(const Args& args) {
    std::vector<char> bytes = read_file(args, args.input);
    if (bytes.size() % 24 != 0) fail(args, args.input + ": not a whole number of 3D points");
    std::vector<double> xyz(bytes.size() / 8);
    std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(xyz.data()));  // little-endian host
    return xyz;
}

// ---- examining a result

std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

/// Counts, zero-volume tetrahedra and the order-free fingerprint of a list of tetrahedra.
class Examiner {
public:
    explicit Examiner(const std::vector<double>& xyz) : xyz_(xyz), points_(xyz.size() / 3) {
        integer_ = std::all_of(xyz.begin(), xyz.end(), [](double v) { return v == std::floor(v) && std::fabs(v) < 524288.0; });
    }

    /// Adds one tetrahedron; false if an index is out of range.
    bool add(Tet t) {
        for (std::uint32_t v : t)
            if (v >= points_) return false;
        ++count_;
        if (flat(t)) ++flat_;
        std::sort(t.begin(), t.end());
        std::uint64_t h = 0;
        for (std::uint32_t v : t) h = splitmix64(h ^ v);
        fingerprint_ += h;
        return true;
    }

    /// Counts without examining (--no-examine).
    void add_count(std::size_t count) { count_ += count; }

    /// The result's JSON fields (without braces); without examination the count alone.
    std::string fields(bool examined = true) const {
        if (!examined) return "\"tetrahedra\":" + std::to_string(count_);
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fingerprint_));
        return "\"tetrahedra\":" + std::to_string(count_) + ",\"flat\":" + std::to_string(flat_) + ",\"flat_method\":\"" +
               (integer_ ? "int64" : "cgal-orientation") + "\",\"fingerprint\":\"" + hex + "\"";
    }

private:
    bool flat(const Tet& t) const {
        const double* p[4];
        for (int k = 0; k < 4; ++k) p[k] = &xyz_[3 * std::size_t(t[k])];
        if (integer_) {
            std::int64_t d[3][3];
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) d[r][c] = static_cast<std::int64_t>(p[r + 1][c]) - static_cast<std::int64_t>(p[0][c]);
            const std::int64_t det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                                     d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
            return det == 0;
        }
        auto point = [](const double* q) { return Kernel::Point_3(q[0], q[1], q[2]); };
        return CGAL::orientation(point(p[0]), point(p[1]), point(p[2]), point(p[3])) == CGAL::COPLANAR;
    }

    const std::vector<double>& xyz_;
    std::size_t points_;
    bool integer_ = false;
    std::size_t count_ = 0, flat_ = 0;
    std::uint64_t fingerprint_ = 0;
};

/// Reads tetrahedra written by another program (--count) into the examiner.
void count_file(const Args& args, Examiner& examiner) {
    const std::vector<char> bytes = read_file(args, args.count);
    auto bad = [&](const std::string& why) { fail(args, args.count + ": " + why); };
    if (args.format == "u32") {
        if (bytes.size() % 16 != 0) bad("not a whole number of uint32 quadruples");
        for (std::size_t at = 0; at < bytes.size(); at += 16) {
            Tet t;
            std::copy(bytes.begin() + at, bytes.begin() + at + 16, reinterpret_cast<char*>(t.data()));
            if (!examiner.add(t)) bad("index out of range");
        }
        return;
    }
    const bool ele = args.format == "ele";
    if (!ele && args.format != "qhull") bad("unknown --format \"" + args.format + "\" (known: ele, qhull, u32)");
    const char* at = bytes.data();
    const char* end = at + bytes.size();
    // The next unsigned number on the current line (skipping blanks), or nothing at the line's end.
    auto next = [&](std::uint64_t* out) {
        while (at < end && (*at == ' ' || *at == '\t' || *at == '\r')) ++at;
        const auto [stop, error] = std::from_chars(at, end, *out);
        if (error != std::errc()) return false;
        at = stop;
        return true;
    };
    auto next_line = [&]() {
        while (at < end && *at != '\n') ++at;
        if (at < end) ++at;
    };
    std::uint64_t declared = 0, value = 0;
    if (!next(&declared)) bad("no count on the first line");
    next_line();
    std::size_t seen = 0;
    while (at < end) {
        while (at < end && (*at == ' ' || *at == '\t' || *at == '\r')) ++at;
        if (at == end || *at == '\n' || *at == '#') {
            next_line();
            continue;
        }
        if (ele && !next(&value)) bad("a line without its tetrahedron number");
        Tet t;
        for (std::uint32_t& v : t) {
            if (!next(&value) || (ele && value == 0)) bad("a line without four indices (line " + std::to_string(seen + 2) + ")");
            v = static_cast<std::uint32_t>(ele ? value - 1 : value);
        }
        if (!examiner.add(t)) bad("index out of range");
        ++seen;
        next_line();
    }
    if (seen != declared) bad("declares " + std::to_string(declared) + " tetrahedra, holds " + std::to_string(seen));
}

// ---- the timed implementations

/// One timed run; the result stays alive (in the runner) until the next run or the examination.
using Runner = std::function<double()>;
using Examine = std::function<void(Examiner&, bool full)>;

struct Implementation {
    Runner run;
    std::function<void()> release;  // frees the last result, untimed
    Examine examine;
};

double since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Implementation make_hullkit(const Args& args, const std::vector<double>& xyz, std::shared_ptr<hullkit::Delaunay3> last) {
    hullkit::Delaunay3Options options;
    options.threads = args.threads;
    Implementation impl;
    impl.run = [&xyz, options, last]() {
        const auto start = std::chrono::steady_clock::now();
        *last = hullkit::delaunay3(hullkit::PointSpan(xyz), options);
        const double seconds = since(start);
        if (!last->ok()) throw std::runtime_error(last->error);
        if (last->dimension != 3) throw std::runtime_error("dimension " + std::to_string(last->dimension));
        return seconds;
    };
    impl.release = [last]() { *last = hullkit::Delaunay3{}; };
    impl.examine = [last](Examiner& examiner, bool full) {
        const auto& t = last->tetrahedra;
        if (!full) return examiner.add_count(t.size() / 4);
        for (std::size_t i = 0; i + 3 < t.size(); i += 4) examiner.add({t[i], t[i + 1], t[i + 2], t[i + 3]});
    };
    return impl;
}

Implementation make_cgal(const std::vector<double>& xyz, std::shared_ptr<std::vector<Kernel::Point_3>> points,
                         std::shared_ptr<std::unique_ptr<Triangulation>> last) {
    const std::size_t n = xyz.size() / 3;
    points->reserve(n);
    for (std::size_t i = 0; i < n; ++i) points->emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    Implementation impl;
    impl.run = [points, last]() {
        const auto start = std::chrono::steady_clock::now();
        *last = std::make_unique<Triangulation>(points->begin(), points->end());
        return since(start);
    };
    impl.release = [last]() { last->reset(); };
    impl.examine = [&xyz, last](Examiner& examiner, bool full) {
        if (!full) return examiner.add_count((*last)->number_of_finite_cells());
        // Vertex -> input index: the indices sorted by coordinates, each vertex's point looked up.
        const std::size_t n = xyz.size() / 3;
        std::vector<std::uint32_t> order(n);
        std::iota(order.begin(), order.end(), 0u);
        auto key = [&xyz](std::uint32_t i) { return std::array<double, 3>{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}; };
        std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
        std::unordered_map<Triangulation::Vertex_handle, std::uint32_t> index;
        index.reserve((*last)->number_of_vertices());
        for (auto v = (*last)->finite_vertices_begin(); v != (*last)->finite_vertices_end(); ++v) {
            const std::array<double, 3> p{v->point().x(), v->point().y(), v->point().z()};
            index[v] = *std::lower_bound(order.begin(), order.end(), p, [&](std::uint32_t i, const std::array<double, 3>& q) { return key(i) < q; });
        }
        for (auto c = (*last)->finite_cells_begin(); c != (*last)->finite_cells_end(); ++c)
            examiner.add({index[c->vertex(0)], index[c->vertex(1)], index[c->vertex(2)], index[c->vertex(3)]});
    };
    return impl;
}

}  // namespace

int main(int argc, char** argv) {
    const Args args = parse_args(argc, argv);
    const std::vector<double> xyz = read_points(args);
    const std::size_t n = xyz.size() / 3;
    Examiner examiner(xyz);

    if (!args.count.empty()) {
        count_file(args, examiner);
        std::printf("{\"impl\":%s,\"input\":%s,\"n\":%zu,%s}\n", json_string(args.impl.empty() ? args.count : args.impl).c_str(),
                    json_string(args.name).c_str(), n, examiner.fields().c_str());
        return 0;
    }

    Implementation impl;
    auto hullkit_result = std::make_shared<hullkit::Delaunay3>();
    auto cgal_points = std::make_shared<std::vector<Kernel::Point_3>>();
    auto cgal_result = std::make_shared<std::unique_ptr<Triangulation>>();
    if (args.impl == "hullkit") impl = make_hullkit(args, xyz, hullkit_result);
    else if (args.impl == "cgal") impl = make_cgal(xyz, cgal_points, cgal_result);
    else fail(args, "unknown implementation (known: hullkit, cgal)");

    const double input_rss = peak_rss_mb();
    std::vector<double> runs;
    long first_faults = 0;
    double first_peak = 0;
    double total = 0;
    try {
        for (int k = 0; k < args.runs && (k == 0 || total < args.budget); ++k) {
            if (k > 0) impl.release();
            const long faults = usage_now().ru_minflt;
            runs.push_back(impl.run());
            if (k == 0) {
                first_faults = usage_now().ru_minflt - faults;
                first_peak = peak_rss_mb();
            }
            total += runs.back();
        }
    } catch (const std::exception& error) {
        fail(args, error.what());
    }
    const double peak = peak_rss_mb();
    impl.examine(examiner, args.examine);

    std::string warm = "null";
    if (runs.size() > 1) {
        std::vector<double> later(runs.begin() + 1, runs.end());
        std::sort(later.begin(), later.end());
        const std::size_t m = later.size();
        warm = number(m % 2 ? later[m / 2] : (later[m / 2 - 1] + later[m / 2]) / 2);
    }
    std::string list;
    for (double seconds : runs) list += (list.empty() ? "" : ",") + number(seconds);
    std::printf("{\"impl\":%s,\"input\":%s,\"n\":%zu,\"threads\":%u,\"first\":%s,\"first_minor_faults\":%ld,\"runs\":[%s],"
                "\"warm\":%s,%s,\"peak_rss_mb\":%.1f,\"peak_rss_all_runs_mb\":%.1f,\"input_rss_mb\":%.1f}\n",
                json_string(args.impl).c_str(), json_string(args.name).c_str(), n, args.impl == "cgal" ? 1u : args.threads, number(runs.front()).c_str(),
                first_faults, list.c_str(), warm.c_str(), examiner.fields(args.examine).c_str(), first_peak, peak, input_rss);
    return 0;
}
