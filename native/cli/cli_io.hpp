// Input, output and error lines shared by the `hullkit` subcommands: reading a file or standard
// input, writing a file or standard output, and the one-line "hullkit: ..." message.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "hullkit/mesh_io.hpp"

namespace CLI {
class App;
}

namespace hullkit_cli {

constexpr int kExitOk = 0;
constexpr int kExitInternal = 1;  ///< a bug or out of memory
constexpr int kExitUsage = 2;     ///< a usage or input problem

/// A failure to report as "hullkit: <message>" with the given exit code (main() prints it).
struct CliError : std::runtime_error {
    int exit_code;
    CliError(const std::string& message, int code = kExitUsage) : std::runtime_error(message), exit_code(code) {}
};

/// A usage or input problem: reported as one line "hullkit: <what>" and exit status 2 (a CliError,
/// so that main() reports one that no command caught).
struct UsageError : CliError {
    explicit UsageError(const std::string& message) : CliError(message, kExitUsage) {}
};

/// The whole of `path`, or of standard input for "-". Throws UsageError naming the file.
std::string read_input(const std::string& path);

/// The vertices and triangles of a hull or triangulation file (for `hullkit verify` and
/// `verify-delaunay`): any mesh format the other commands read (OBJ, OFF, PLY, STL, glTF; the
/// format from the content, then the name), and what a hull of lower dimension or none is written
/// as: OFF or OBJ vertices without faces, OFF "0 0 0", an OBJ without records. Throws UsageError
/// with the reader's message.
hullkit::MeshResult read_mesh_file(const std::string& path);

/// Writes `text` to `path`, or to standard output for "" and "-". Throws UsageError naming the
/// file when it cannot be opened or written (a full disk included).
void write_output(const std::string& path, const std::string& text);

/// Prints "hullkit: <message>" as one line on standard error (line breaks in `message` become
/// spaces) and returns 2, the exit status of a usage or input problem.
int print_usage_error(const std::string& message);

/// Parses `args` with `app` (CLI11); on a CLI11 error throws UsageError with a one-line message in
/// the words of the other commands (unknown option, unexpected argument, missing value), ending
/// with a hint at 'hullkit COMMAND --help'.
void parse_or_throw(CLI::App& app, const std::vector<std::string>& args, const std::string& command);

/// A whole-number option value from `min` to `max`, or a UsageError in the words every command
/// uses, in its messages and in its --help: `option --threads needs a whole number from 0 to 1024,
/// got "x"`.
std::uint64_t parse_whole_number(const std::string& value, const std::string& option, std::uint64_t min, std::uint64_t max);

/// Adds option `name` ("--threads") to `app`: a whole number from `min` to `max` into *value, read by
/// parse_whole_number (so a bad value is that UsageError, out of parse_or_throw); given twice, the
/// last one counts.
void add_whole_number_option(CLI::App& app, const std::string& name, unsigned* value, unsigned min, unsigned max);

/// Prints each of a reader's warnings as one line "hullkit: warning: <source>: <warning>" on
/// standard error (`source` empty: "hullkit: warning: <warning>").
void print_warnings(const std::string& source, const std::vector<std::string>& warnings);

}  // namespace hullkit_cli
