// `hullkit hull` on every core and with bounded memory: the output is the same bytes for every
// --threads, whole or streamed (--memory), through standard input, from several files, and for
// the map-reduce recipe (--vertices-only per part, then the parts' outputs hulled together).
#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <limits>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "hull/hull_checks.hpp"
#include "sanitized.hpp"

using hullkit_test::Cloud;
using hullkit_test::read_text;
using hullkit_test::run_cli;
using hullkit_test::RunResult;
using hullkit_test::TempDir;

namespace {

/// Points as "x y z" lines, shortest round-trip doubles, from point `first` to `last`.
std::string as_text(const std::vector<double>& xyz, std::size_t first = 0, std::size_t last = ~std::size_t{0}) {
    last = std::min(last, xyz.size() / 3);
    std::string text;
    char number[32];
    for (std::size_t i = first; i < last; ++i) {
        for (int k = 0; k < 3; ++k) {
            const auto end = std::to_chars(number, number + sizeof number, xyz[3 * i + k]).ptr;
            text.append(number, end);
            text += k == 2 ? '\n' : ' ';
        }
    }
    return text;
}

/// A binary little-endian PLY point cloud (float64 x y z), as scanners write them.
std::string as_ply(const std::vector<double>& xyz) {
    std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(xyz.size() / 3) +
                      "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
    ply.append(reinterpret_cast<const char*>(xyz.data()), xyz.size() * sizeof(double));
    return ply;
}

RunResult hull(const TempDir& dir, std::vector<std::string> args) {
    args.insert(args.begin(), "hull");
    return run_cli(dir, args);
}

/// Runs the CLI with `args` and returns its peak resident memory in KiB (and *exit_code).
long peak_kib(const std::vector<std::string>& args, int* exit_code) {
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        std::vector<char*> argv{const_cast<char*>(HULLKIT_CLI_PATH)};
        for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
        argv.push_back(nullptr);
        if (!std::freopen("/dev/null", "w", stdout)) _exit(127);
        execv(HULLKIT_CLI_PATH, argv.data());
        _exit(127);
    }
    int status = 0;
    struct rusage usage {};
    REQUIRE(wait4(child, &status, 0, &usage) == child);
    *exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
    return usage.ru_maxrss;
}

}  // namespace

TEST_CASE("cli stream: --threads 1, 2, 3, 8 write the same bytes", "[threads]") {
    TempDir dir("hullkit-stream");
    const std::vector<std::pair<std::string, std::vector<double>>> clouds = {
        {"ball.txt", hullkit_test::random_cloud(Cloud::Ball, 120000, 1)},
        {"sphere.txt", hullkit_test::random_cloud(Cloud::Sphere, 70000, 2)}};
    for (const auto& [name, xyz] : clouds) {
        INFO(name);
        hullkit_test::write_text(dir.file(name), as_text(xyz));
        for (const char* format : {"off", "json"}) {
            const RunResult one = hull(dir, {dir.file(name), "--threads", "1", "--format", format, "--merge-coplanar"});
            REQUIRE(one.exit_code == 0);
            for (const char* threads : {"2", "3", "8", "0"}) {
                INFO(threads << " threads, " << format);
                const RunResult more = hull(dir, {dir.file(name), "--threads", threads, "--format", format, "--merge-coplanar"});
                REQUIRE(more.exit_code == 0);
                CHECK(more.out == one.out);
            }
        }
    }
}

TEST_CASE("cli stream: huge pages on or off (HULLKIT_HUGE_PAGES=1, =0, unset) write the same bytes", "[threads]") {
    // Working arrays of these sizes (a sphere's hull faces, the 3D mesh of 10^5 points: over 4 MiB)
    // are mapped on transparent huge pages where the environment asks for them (or, unset, where
    // the machine's fresh pages are costly); only where the memory sits changes, so the outputs
    // must be byte for byte the same, on one thread and two.
    TempDir dir("hullkit-huge");
    hullkit_test::write_text(dir.file("sphere.txt"), as_text(hullkit_test::random_cloud(Cloud::Sphere, 150000, 3)));
    hullkit_test::write_text(dir.file("ball.txt"), as_text(hullkit_test::random_cloud(Cloud::Ball, 100000, 4)));
    const std::vector<std::vector<std::string>> commands = {
        {"hull", dir.file("sphere.txt"), "--format", "off"},
        {"delaunay3", dir.file("ball.txt"), "--format", "json"}};
    for (const auto& command : commands) {
        for (const char* threads : {"1", "2"}) {
            INFO(command[0] << ", " << threads << " threads");
            std::string line;
            for (const std::string& word : command) line += " " + hullkit_test::sh_quote(word);
            line += " --threads " + std::string(threads) + " </dev/null";
            const std::string cli = hullkit_test::sh_quote(HULLKIT_CLI_PATH);
            const RunResult on = hullkit_test::run_shell(dir, "HULLKIT_HUGE_PAGES=1 " + cli + line);
            const RunResult off = hullkit_test::run_shell(dir, "HULLKIT_HUGE_PAGES=0 " + cli + line);
            const RunResult chosen = hullkit_test::run_shell(dir, "unset HULLKIT_HUGE_PAGES; " + cli + line);
            REQUIRE(on.exit_code == 0);
            REQUIRE(off.exit_code == 0);
            REQUIRE(chosen.exit_code == 0);
            CHECK(on.out.size() > 100000);
            CHECK(on.out == off.out);
            CHECK(chosen.out == on.out);
        }
    }
}

TEST_CASE("cli stream: over --memory the cloud streams, from a file, a PLY or standard input, with the same output") {
    TempDir dir("hullkit-stream");
    const auto xyz = hullkit_test::random_cloud(Cloud::Ball, 150000, 3);
    hullkit_test::write_text(dir.file("ball.txt"), as_text(xyz));
    hullkit_test::write_text(dir.file("ball.ply"), as_ply(xyz));
    const RunResult whole = hull(dir, {dir.file("ball.txt"), "--stats"});
    REQUIRE(whole.exit_code == 0);
    CHECK_THAT(whole.err, Catch::Contains("\"streamed\":false"));
    for (const std::string& input : {dir.file("ball.txt"), dir.file("ball.ply")}) {
        INFO(input);
        const RunResult streamed = hull(dir, {input, "--memory", "1", "--stats"});
        REQUIRE(streamed.exit_code == 0);
        CHECK_THAT(streamed.err, Catch::Contains("\"streamed\":true") && Catch::Contains("\"points\":150000"));
        CHECK(streamed.out == whole.out);
        const RunResult json_whole = hull(dir, {input, "--format", "json"});
        const RunResult json_streamed = hull(dir, {input, "--format", "json", "--memory", "1"});
        CHECK(json_streamed.out == json_whole.out);  // input indices too
    }
    const RunResult piped = run_cli(dir, {"hull", "-", "--memory", "1", "--stats"}, dir.file("ball.txt"));
    REQUIRE(piped.exit_code == 0);
    CHECK_THAT(piped.err, Catch::Contains("\"streamed\":true"));
    CHECK(piped.out == whole.out);
}

TEST_CASE("cli stream: a file over the memory limit is hulled with bounded peak memory and the same output") {
    TempDir dir("hullkit-stream");
    {  // freed before the runs: a child's peak memory counts what it was forked from
        const auto xyz = hullkit_test::random_cloud(Cloud::Ball, 2000000, 4);  // 48 MB of coordinates
        hullkit_test::write_text(dir.file("ball.ply"), as_ply(xyz));
    }
    int code = 0;
    const long whole_kib = peak_kib({"hull", dir.file("ball.ply"), "-o", dir.file("whole.off"), "--memory", "4096"}, &code);
    REQUIRE(code == 0);
    const long streamed_kib = peak_kib({"hull", dir.file("ball.ply"), "-o", dir.file("streamed.off"), "--memory", "8"}, &code);
    REQUIRE(code == 0);
    CHECK(read_text(dir.file("streamed.off")) == read_text(dir.file("whole.off")));
    INFO("peak memory: whole " << whole_kib / 1024 << " MB, streamed under --memory 8: " << streamed_kib / 1024 << " MB");
    if (!hullkit_test::kSanitized) {  // the sanitizers' shadow memory says nothing about ours
        CHECK(whole_kib > 48 * 1024);
        CHECK(streamed_kib < 32 * 1024);
    }
}

TEST_CASE("cli stream: map-reduce, --vertices-only per part and the parts' outputs hulled together, is the whole hull") {
    TempDir dir("hullkit-stream");
    const auto xyz = hullkit_test::random_cloud(Cloud::Ball, 30000, 5);
    hullkit_test::write_text(dir.file("all.txt"), as_text(xyz));
    const RunResult whole = hull(dir, {dir.file("all.txt")});
    REQUIRE(whole.exit_code == 0);
    std::vector<std::string> reduce = {"hull"};
    for (int part = 0; part < 3; ++part) {
        const std::string name = dir.file("part-" + std::to_string(part) + ".txt");
        hullkit_test::write_text(name, as_text(xyz, 10000 * part, 10000 * (part + 1)));
        const RunResult mapped = hull(dir, {name, "--vertices-only", "-o", name + ".xyz"});
        REQUIRE(mapped.exit_code == 0);
        const std::string vertices = read_text(name + ".xyz");
        CHECK_THAT(vertices, Catch::Contains(" # "));  // each vertex names its input index
        reduce.push_back(name + ".xyz");
    }
    const RunResult reduced = run_cli(dir, reduce);
    REQUIRE(reduced.exit_code == 0);
    CHECK(reduced.out == whole.out);
    // The parts themselves, given as several inputs, are the whole cloud too.
    const RunResult parts = run_cli(dir, {"hull", dir.file("part-0.txt"), dir.file("part-1.txt"), dir.file("part-2.txt")});
    REQUIRE(parts.exit_code == 0);
    CHECK(parts.out == whole.out);
    // --format xyz and an .xyz output name mean the same; the output reads back as points.
    const RunResult xyz_format = hull(dir, {dir.file("all.txt"), "--format", "xyz"});
    const RunResult xyz_name = hull(dir, {dir.file("all.txt"), "-o", dir.file("all.xyz")});
    REQUIRE(xyz_name.exit_code == 0);
    CHECK(read_text(dir.file("all.xyz")) == xyz_format.out);
    CHECK(hull(dir, {dir.file("all.xyz")}).out == whole.out);
}

TEST_CASE("cli stream: bad --threads and --memory, and a bad point deep in a streamed file, exit 2 with one line") {
    TempDir dir("hullkit-stream");
    auto xyz = hullkit_test::random_cloud(Cloud::Ball, 50000, 6);
    std::string text = as_text(xyz);
    hullkit_test::write_text(dir.file("ball.txt"), text);
    for (const auto& args : std::vector<std::vector<std::string>>{{"--threads", "x"}, {"--threads", "-1"},
                                                                   {"--memory", "0"}, {"--memory", "lots"},
                                                                   {"--threads"}}) {
        std::vector<std::string> all = {dir.file("ball.txt")};
        all.insert(all.end(), args.begin(), args.end());
        const RunResult bad = hull(dir, all);
        INFO(args[0]);
        CHECK(bad.exit_code == 2);
        REQUIRE(bad.err_lines().size() == 1);
        CHECK_THAT(bad.err, Catch::StartsWith("hullkit: option " + args[0]));
    }
    // A non-finite coordinate at point 40000: the same message whole and streamed.
    xyz[3 * 40000 + 1] = std::numeric_limits<double>::infinity();
    hullkit_test::write_text(dir.file("inf.txt"), as_text(xyz));
    const RunResult whole = hull(dir, {dir.file("inf.txt")});
    const RunResult streamed = hull(dir, {dir.file("inf.txt"), "--memory", "1"});
    CHECK(whole.exit_code == 2);
    CHECK(streamed.exit_code == 2);
    CHECK(whole.err == "hullkit: " + dir.file("inf.txt") + ":40001: coordinate \"inf\" of point 40000 is not a finite number\n");
    CHECK(streamed.err == whole.err);
    // A malformed line deep in the second of two inputs names that file and line.
    const std::size_t cut = text.find('\n', text.size() / 2) + 1;  // at a line's start
    hullkit_test::write_text(dir.file("bad.txt"), text.substr(0, cut) + "1 2 zwei\n" + text.substr(cut));
    const std::size_t bad_line = static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(cut), '\n')) + 1;
    for (const char* memory : {"4096", "1"}) {
        const RunResult bad = hull(dir, {dir.file("ball.txt"), dir.file("bad.txt"), "--memory", memory});
        CHECK(bad.exit_code == 2);
        CHECK_THAT(bad.err, Catch::StartsWith("hullkit: " + dir.file("bad.txt") + ":" + std::to_string(bad_line) + ": "));
    }
    // --quiet is accepted; no progress line goes into a file or a pipe.
    const RunResult quiet = hull(dir, {dir.file("ball.txt"), "--quiet"});
    CHECK(quiet.exit_code == 0);
    CHECK(hull(dir, {dir.file("ball.txt")}).err.empty());
}
