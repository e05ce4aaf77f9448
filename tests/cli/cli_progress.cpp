// The progress line of `hullkit hull`, `delaunay` and `route`: drawn on standard error only when it
// is a terminal (here a pseudo-terminal), cleared at the end, never with --quiet, and never
// changing the output. HULLKIT_PROGRESS_AFTER_MS=0 draws at once, so small inputs show it.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "cli_support.hpp"

using hullkit_test::data_path;
using hullkit_test::read_text;
using hullkit_test::TempDir;
using hullkit_test::write_text;

namespace {

struct TerminalRun {
    int exit_code = -1;
    std::string terminal;  // what the command wrote to standard error, a pseudo-terminal
};

/// Runs `hullkit ARGS` with standard error on a new pseudo-terminal (standard output to
/// `out_path`, standard input from /dev/null) and HULLKIT_PROGRESS_AFTER_MS=0.
TerminalRun run_on_terminal(const std::vector<std::string>& args, const std::string& out_path) {
    int master = -1, slave = -1;
    REQUIRE(openpty(&master, &slave, nullptr, nullptr, nullptr) == 0);
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        const int in = open("/dev/null", O_RDONLY);
        const int out = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (in < 0 || out < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(slave, 2) < 0) _exit(126);
        close(master);
        setenv("HULLKIT_PROGRESS_AFTER_MS", "0", 1);
        std::vector<char*> argv;
        std::string program = HULLKIT_CLI_PATH;
        argv.push_back(program.data());
        std::vector<std::string> copies(args);
        for (std::string& arg : copies) argv.push_back(arg.data());
        argv.push_back(nullptr);
        execv(program.c_str(), argv.data());
        _exit(127);
    }
    close(slave);
    TerminalRun run;
    char buffer[4096];
    for (;;) {
        const ssize_t got = read(master, buffer, sizeof buffer);
        if (got > 0) {
            run.terminal.append(buffer, static_cast<std::size_t>(got));
        } else if (got < 0 && errno == EINTR) {
            continue;
        } else {
            break;  // EIO once the child's side is closed
        }
    }
    close(master);
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return run;
}

std::string random_cloud_text(std::size_t n, int dimensions, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::string text;
    char line[96];
    for (std::size_t i = 0; i < n; ++i) {
        if (dimensions == 3) {
            std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", u(rng), u(rng), u(rng));
        } else {
            std::snprintf(line, sizeof line, "%.17g %.17g\n", u(rng), u(rng));
        }
        text += line;
    }
    return text;
}

/// The output with a route report's timings ("build_seconds", "seconds") blanked: they differ
/// from run to run.
std::string without_timings(std::string text) {
    static const std::regex timing("\"(build_)?seconds\": ?[-+0-9.eE]+");
    return std::regex_replace(text, timing, "\"$1seconds\":0");
}

/// A drawn progress line: "\rhullkit: ... UNIT ..." then, at the end, the clearing "\r\x1b[K".
void require_drawn_and_cleared(const std::string& terminal, const std::string& unit) {
    INFO(terminal);
    const std::size_t drawn = terminal.find("\rhullkit: ");
    REQUIRE(drawn != std::string::npos);
    REQUIRE(terminal.find(" " + unit, drawn) != std::string::npos);
    REQUIRE(terminal.size() >= 4);
    REQUIRE(terminal.compare(terminal.size() - 4, 4, "\r\x1b[K") == 0);
}

}  // namespace

TEST_CASE("cli progress: hull, delaunay and route draw a progress line on a terminal and clear it, --quiet and files get none",
          "[cli]") {
    TempDir dir("hullkit-progress");
    const std::string cloud = dir.file("cloud.txt"), plane = dir.file("plane.txt");
    write_text(cloud, random_cloud_text(200000, 3, 1));
    write_text(plane, random_cloud_text(140000, 2, 2));  // over 65 536: delaunay reports as it inserts
    struct Case {
        std::string name, unit;
        std::vector<std::string> args;
    };
    const std::vector<Case> cases = {
        {"hull", "points", {"hull", cloud}},
        {"delaunay", "points", {"delaunay", plane}},
        {"route", "legs", {"route", data_path("route/crane.json")}},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        // The reference: standard error to a file, where no line may be drawn.
        std::vector<std::string> to_file = c.args;
        to_file.insert(to_file.end(), {"-o", dir.file(c.name + ".file")});
        const hullkit_test::RunResult plain = hullkit_test::run_cli(dir, to_file);
        REQUIRE((plain.exit_code == 0 || (c.name == "route" && plain.exit_code == 1)));  // route: 1 when a leg hits
        REQUIRE(plain.err.find('\r') == std::string::npos);

        const TerminalRun shown = run_on_terminal(c.args, dir.file(c.name + ".terminal"));
        REQUIRE(shown.exit_code == plain.exit_code);
        require_drawn_and_cleared(shown.terminal, c.unit);
        const std::string reference = without_timings(read_text(dir.file(c.name + ".file")));
        REQUIRE(without_timings(read_text(dir.file(c.name + ".terminal"))) == reference);

        std::vector<std::string> quiet = c.args;
        quiet.push_back("--quiet");
        const TerminalRun hidden = run_on_terminal(quiet, dir.file(c.name + ".quiet"));
        REQUIRE(hidden.exit_code == plain.exit_code);
        REQUIRE(hidden.terminal.find('\r') == std::string::npos);
        REQUIRE(without_timings(read_text(dir.file(c.name + ".quiet"))) == reference);
    }
}
