// Helpers for the tests that run the built `hullkit` command (HULLKIT_CLI_PATH): a scratch
// directory, whole-file reads and writes, and running a shell command with its output captured.
#pragma once

#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace hullkit_test {

/// A file in tests/data (HULLKIT_TEST_DATA).
inline std::string data_path(const std::string& name) { return std::string(HULLKIT_TEST_DATA) + "/" + name; }

/// A fresh directory under the system's temporary directory, named `prefix` plus a random
/// suffix, removed with everything in it when the test ends.
class TempDir {
public:
    explicit TempDir(const std::string& prefix) {
        std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

/// The whole file as bytes (empty if it cannot be read).
inline std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void write_text(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    REQUIRE(out.good());
}

/// Single-quotes a word for /bin/sh.
inline std::string sh_quote(const std::string& word) {
    std::string quoted = "'";
    for (char c : word) quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

struct RunResult {
    int exit_code = -1;
    std::string out;
    std::string err;

    std::vector<std::string> err_lines() const {
        std::vector<std::string> lines;
        std::istringstream in(err);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        return lines;
    }
};

/// Runs a shell command line with stdout and stderr captured in files of `dir`.
inline RunResult run_shell(const TempDir& dir, const std::string& command) {
    const std::string out = dir.file("run.out"), err = dir.file("run.err");
    // The parentheses keep redirections inside `command` apart from the captured ones.
    const std::string full = "(" + command + ") >" + sh_quote(out) + " 2>" + sh_quote(err);
    int status = std::system(full.c_str());
    RunResult result;
    REQUIRE(status != -1);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.out = read_text(out);
    result.err = read_text(err);
    return result;
}

/// Runs `hullkit ARGS` (each argument quoted), optionally with stdin from a file (else /dev/null).
inline RunResult run_cli(const TempDir& dir, const std::vector<std::string>& args,
                         const std::string& stdin_path = "") {
    std::string command = sh_quote(HULLKIT_CLI_PATH);
    for (const std::string& arg : args) command += " " + sh_quote(arg);
    command += " <" + sh_quote(stdin_path.empty() ? "/dev/null" : stdin_path);
    return run_shell(dir, command);
}

}  // namespace hullkit_test
