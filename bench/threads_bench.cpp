// hullkit_threads_bench: the library half of the threads-and-streaming benchmark (issue 14) and the
// writer of its large input files. bench/threads_run.sh drives it, one process per run, so that the
// first call it times is what a fresh `hullkit hull` process gets.
//
//   hullkit_threads_bench --cloud ball|sphere|cube --n N --threads T [--runs R] [--seed S]
//       Generates the cloud in this process (not timed), then times hullkit::hull() with
//       HullOptions::threads = T: the first call, then R-1 more ("warm": allocator free lists, page
//       tables and caches primed by the first). Prints one JSON line:
//         {"cloud", "n", "seed", "threads", "hardware_threads", "runs", "first_seconds",
//          "warm_median_seconds" (null when R = 1), "vertices", "triangles", "volume",
//          "volume_bits", "area_bits", "triangles_fnv1a", "runs_identical",
//          "generate_seconds", "peak_rss_mb"}
//       volume_bits and area_bits are the doubles' IEEE-754 bits in hex; triangles_fnv1a is the
//       64-bit FNV-1a hash of the triangle index array (each index as 4 little-endian bytes). Equal
//       strings in two processes mean bit-identical results, which the script checks across thread
//       counts; runs_identical says whether every run of this process gave the first run's bits.
//   hullkit_threads_bench --write-ply FILE --cloud C --n N [--seed S]
//       Writes the same cloud as a binary little-endian PLY point cloud (property double x y z,
//       no faces), generated and written block by block, so memory stays small whatever N is.
//   hullkit_threads_bench --write-text FILE --cloud C --n N [--seed S]
//       Writes it as qhull/rbox text: "3", N, then "x y z" per line, each coordinate the shortest
//       decimal that reads back as the same double (std::to_chars). The generator is one stream
//       per seed, so the text file with --n 1e7 holds exactly the first 1e7 points of the PLY file
//       written with --n 1e8: qconvex and hullkit then read the same doubles.
//
// N may be written as 1e7. The clouds (default seed 14):
//   cube    uniform in [-1,1]^3
//   ball    uniform in the unit ball: cube points with x^2+y^2+z^2 > 1 are rejected
//   sphere  uniform on the unit sphere: three standard normals (Marsaglia's polar method) divided
//           by their length
// Random bits come from xoshiro256** seeded through splitmix64, turned into doubles here rather than
// by std:: distributions, whose output the standard leaves to each library: the clouds are the same
// wherever the bench is built (the sphere's normals use std::log, i.e. the platform's libm).
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h>

#include "hullkit/hull.hpp"

namespace {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// ---- the clouds ----

class Random {
public:
    explicit Random(std::uint64_t seed) {
        // splitmix64 spreads any seed (0 included) over the 256-bit state, which must not be all zero.
        for (std::uint64_t& word : state_) {
            seed += 0x9e3779b97f4a7c15ULL;
            std::uint64_t z = seed;
            z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
            z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
            word = z ^ (z >> 31);
        }
    }

    std::uint64_t next() {  // xoshiro256**
        const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
        const std::uint64_t t = state_[1] << 17;
        state_[2] ^= state_[0];
        state_[3] ^= state_[1];
        state_[1] ^= state_[2];
        state_[0] ^= state_[3];
        state_[2] ^= t;
        state_[3] = rotl(state_[3], 45);
        return result;
    }

    /// Uniform in [-1, 1): the top 53 bits as a multiple of 2^-52, shifted. Exact, no rounding.
    double symmetric() { return static_cast<double>(next() >> 11) * 0x1p-52 - 1.0; }

private:
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    std::uint64_t state_[4];
};

enum class CloudKind { Cube, Ball, Sphere };

CloudKind parse_cloud(const std::string& name) {
    if (name == "cube") return CloudKind::Cube;
    if (name == "ball") return CloudKind::Ball;
    if (name == "sphere") return CloudKind::Sphere;
    throw UsageError("unknown cloud \"" + name + "\" (cube, ball or sphere)");
}

/// One endless stream of points per (kind, seed): the first n of a longer stream are the n-point cloud.
class Cloud {
public:
    Cloud(CloudKind kind, std::uint64_t seed) : kind_(kind), random_(seed) {}

    void next(double* p) {
        switch (kind_) {
            case CloudKind::Cube:
                for (int k = 0; k < 3; ++k) p[k] = random_.symmetric();
                return;
            case CloudKind::Ball:
                do {
                    for (int k = 0; k < 3; ++k) p[k] = random_.symmetric();
                } while (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > 1.0);
                return;
            case CloudKind::Sphere: {
                double length = 0.0;
                do {
                    for (int k = 0; k < 3; ++k) p[k] = normal();
                    length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                } while (!(length > 0.0));
                for (int k = 0; k < 3; ++k) p[k] /= length;
                return;
            }
        }
    }

private:
    /// A standard normal; the polar method makes two at a time, the second is kept for the next call.
    double normal() {
        if (has_spare_) {
            has_spare_ = false;
            return spare_;
        }
        double u, v, s;
        do {
            u = random_.symmetric();
            v = random_.symmetric();
            s = u * u + v * v;
        } while (s >= 1.0 || s == 0.0);
        const double factor = std::sqrt(-2.0 * std::log(s) / s);
        spare_ = v * factor;
        has_spare_ = true;
        return u * factor;
    }

    CloudKind kind_;
    Random random_;
    bool has_spare_ = false;
    double spare_ = 0.0;
};

// ---- small helpers ----

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double peak_rss_mb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
}

std::string hex64(std::uint64_t x) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(x));
    return buf;
}

std::string double_bits(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return hex64(bits);
}

std::string json_number(double x) {
    if (!std::isfinite(x)) return "null";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

/// FNV-1a over the indices as little-endian bytes, so the hash does not depend on the host's byte order.
std::uint64_t fnv1a(const std::vector<std::uint32_t>& values) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (std::uint32_t v : values) {
        for (int b = 0; b < 4; ++b) {
            h ^= (v >> (8 * b)) & 0xffu;
            h *= 0x100000001b3ULL;
        }
    }
    return h;
}

bool host_is_little_endian() {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2.0;
}

std::uint64_t parse_count(const std::string& text, const char* option, double largest) {
    // std::stod takes "1e7" as well as "10000000"; the value must still be a whole number.
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || !(value >= 0.0) || value > largest || value != std::floor(value)) {
        throw UsageError(std::string(option) + " needs a whole number, not \"" + text + "\"");
    }
    return static_cast<std::uint64_t>(value);
}

// ---- the three modes ----

struct Args {
    std::string cloud = "ball";
    std::uint64_t n = 0;
    std::uint64_t seed = 14;
    unsigned threads = 1;
    int runs = 3;
    std::string write_ply;
    std::string write_text;
};

class OutputFile {
public:
    explicit OutputFile(const std::string& path) : path_(path), file_(std::fopen(path.c_str(), "wb")) {
        if (!file_) throw std::runtime_error("cannot create " + path + ": " + std::strerror(errno));
    }
    ~OutputFile() {
        if (file_) std::fclose(file_);
    }
    void write(const void* data, std::size_t bytes) {
        if (std::fwrite(data, 1, bytes, file_) != bytes) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
    }
    void close() {
        std::FILE* f = file_;
        file_ = nullptr;
        if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
    }

private:
    std::string path_;
    std::FILE* file_;
};

// Blocks of 64 Ki points (1.5 MiB of doubles): large enough that fwrite's per-call cost vanishes,
// small enough that the 2.4 GB file costs no memory to speak of.
constexpr std::size_t kBlockPoints = std::size_t{1} << 16;

void write_ply(const Args& args) {
    if (!host_is_little_endian()) throw std::runtime_error("--write-ply writes the doubles as they are in memory: needs a little-endian host");
    OutputFile out(args.write_ply);
    const std::string header = "ply\nformat binary_little_endian 1.0\ncomment hullkit_threads_bench --cloud " + args.cloud +
                               " --seed " + std::to_string(args.seed) + "\nelement vertex " + std::to_string(args.n) +
                               "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
    out.write(header.data(), header.size());
    Cloud cloud(parse_cloud(args.cloud), args.seed);
    std::vector<double> block(3 * kBlockPoints);
    for (std::uint64_t done = 0; done < args.n;) {
        const std::size_t count = static_cast<std::size_t>(std::min<std::uint64_t>(kBlockPoints, args.n - done));
        for (std::size_t i = 0; i < count; ++i) cloud.next(&block[3 * i]);
        out.write(block.data(), count * 3 * sizeof(double));
        done += count;
    }
    out.close();
}

void write_text(const Args& args) {
    OutputFile out(args.write_text);
    Cloud cloud(parse_cloud(args.cloud), args.seed);
    std::vector<char> buffer(std::size_t{1} << 20);
    std::size_t used = 0;
    const std::string header = "3\n" + std::to_string(args.n) + "\n";
    std::memcpy(buffer.data(), header.data(), header.size());
    used = header.size();
    double p[3];
    for (std::uint64_t i = 0; i < args.n; ++i) {
        // A line is at most 3 * 24 characters plus separators; flush well before that could overflow.
        if (buffer.size() - used < 128) {
            out.write(buffer.data(), used);
            used = 0;
        }
        cloud.next(p);
        for (int k = 0; k < 3; ++k) {
            const std::to_chars_result r = std::to_chars(buffer.data() + used, buffer.data() + buffer.size(), p[k]);
            if (r.ec != std::errc()) throw std::runtime_error("std::to_chars failed");
            used = static_cast<std::size_t>(r.ptr - buffer.data());
            buffer[used++] = k < 2 ? ' ' : '\n';
        }
    }
    out.write(buffer.data(), used);
    out.close();
}

void time_hull(const Args& args) {
    if (args.n > 0xffffffffULL) throw UsageError("--n: hullkit::hull takes at most 2^32-1 points");
    if (args.runs < 1) throw UsageError("--runs needs at least 1");
    auto start = std::chrono::steady_clock::now();
    std::vector<double> xyz(3 * args.n);
    Cloud cloud(parse_cloud(args.cloud), args.seed);
    for (std::uint64_t i = 0; i < args.n; ++i) cloud.next(&xyz[3 * i]);
    const double generate_seconds = seconds_since(start);

    hullkit::HullOptions options;
    options.threads = args.threads;
    const hullkit::PointSpan points(xyz.data(), static_cast<std::size_t>(args.n));
    double first_seconds = 0.0;
    std::vector<double> warm;
    std::size_t vertices = 0, triangles = 0;
    double volume = 0.0;
    std::string volume_bits, area_bits, hash;
    bool runs_identical = true;
    for (int run = 0; run < args.runs; ++run) {
        start = std::chrono::steady_clock::now();
        hullkit::Hull hull = hullkit::hull(points, options);
        const double seconds = seconds_since(start);  // the Hull is freed after the clock stopped
        if (!hull.ok()) throw std::runtime_error("hullkit::hull failed: " + hull.error);
        const std::string run_hash = hex64(fnv1a(hull.triangles));
        const std::string run_volume = double_bits(hull.volume), run_area = double_bits(hull.area);
        if (run == 0) {
            first_seconds = seconds;
            vertices = hull.vertices.size();
            triangles = hull.face_count();
            volume = hull.volume;
            volume_bits = run_volume;
            area_bits = run_area;
            hash = run_hash;
        } else {
            warm.push_back(seconds);
            runs_identical = runs_identical && run_hash == hash && run_volume == volume_bits && run_area == area_bits;
        }
    }
    std::printf(
        "{\"cloud\":\"%s\",\"n\":%llu,\"seed\":%llu,\"threads\":%u,\"hardware_threads\":%u,\"runs\":%d,"
        "\"first_seconds\":%s,\"warm_median_seconds\":%s,\"vertices\":%zu,\"triangles\":%zu,\"volume\":%s,"
        "\"volume_bits\":\"%s\",\"area_bits\":\"%s\",\"triangles_fnv1a\":\"%s\",\"runs_identical\":%s,"
        "\"generate_seconds\":%s,\"peak_rss_mb\":%s}\n",
        args.cloud.c_str(), static_cast<unsigned long long>(args.n), static_cast<unsigned long long>(args.seed),
        args.threads, std::thread::hardware_concurrency(), args.runs, json_number(first_seconds).c_str(),
        warm.empty() ? "null" : json_number(median(warm)).c_str(), vertices, triangles, json_number(volume).c_str(),
        volume_bits.c_str(), area_bits.c_str(), hash.c_str(), runs_identical ? "true" : "false",
        json_number(generate_seconds).c_str(), json_number(peak_rss_mb()).c_str());
}

Args parse_args(int argc, char** argv) {
    Args args;
    bool have_n = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw UsageError("option " + arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--cloud") {
            args.cloud = value();
            parse_cloud(args.cloud);
        } else if (arg == "--n") {
            args.n = parse_count(value(), "--n", 1e12);
            have_n = true;
        } else if (arg == "--seed") {
            args.seed = parse_count(value(), "--seed", 9e15);
        } else if (arg == "--threads") {
            args.threads = static_cast<unsigned>(parse_count(value(), "--threads", 1024));
        } else if (arg == "--runs") {
            args.runs = static_cast<int>(parse_count(value(), "--runs", 1000));
        } else if (arg == "--write-ply") {
            args.write_ply = value();
        } else if (arg == "--write-text") {
            args.write_text = value();
        } else {
            throw UsageError("unknown option " + arg);
        }
    }
    if (!have_n) throw UsageError("--n N is required");
    if (!args.write_ply.empty() && !args.write_text.empty()) throw UsageError("--write-ply and --write-text: one at a time");
    return args;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Args args = parse_args(argc, argv);
        if (!args.write_ply.empty()) {
            write_ply(args);
        } else if (!args.write_text.empty()) {
            write_text(args);
        } else {
            time_hull(args);
        }
        return 0;
    } catch (const UsageError& error) {
        std::fprintf(stderr,
                     "hullkit_threads_bench: %s\nusage: hullkit_threads_bench --cloud ball|sphere|cube --n N --threads T [--runs R] [--seed S]\n"
                     "       hullkit_threads_bench --write-ply FILE | --write-text FILE  --cloud C --n N [--seed S]\n",
                     error.what());
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "hullkit_threads_bench: %s\n", error.what());
        return 1;
    }
}
