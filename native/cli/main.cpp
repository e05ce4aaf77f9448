// The `hullkit` command: the subcommands' dispatch, --help and --version, and the one place
// failures become a line on stderr and an exit status. The subcommands are in *_command.cpp.
//
// Exit codes: 0 success; 2 any usage or input problem; 1 an internal failure (a bug or out of
// memory). Every failure prints exactly one line "hullkit: ..." on stderr.
#include "cli_io.hpp"
#include "delaunay3_command.hpp"
#include "delaunay_command.hpp"
#include "triangulate_command.hpp"
#include "hull_command.hpp"
#include "route_command.hpp"
#include "verify_command.hpp"

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr const char* kVersion = "0.1.0";

using hullkit_cli::CliError;
using hullkit_cli::kExitInternal;
using hullkit_cli::kExitOk;

const char* const kMainUsage =
    R"(Usage: hullkit <command> [options]

Commands:
  hull             compute the convex hull of a 3D point set
  verify           check exactly that a mesh file is the convex hull of a point set
  delaunay         Delaunay triangulation of 2D points (by lifting to a paraboloid)
  verify-delaunay  check exactly that a mesh file is a Delaunay triangulation
  triangulate      constrained Delaunay triangulation of polygons with holes and planar graphs
  delaunay3        Delaunay tetrahedralization of 3D points (by lifting to 4D)
  verify-delaunay3 check exactly that tetrahedra are a Delaunay tetrahedralization
  route            check a traverse's route (straight or turning legs) against obstacles

Options:
  -h, --help  show this help
  --version   show the version

Run 'hullkit hull --help' for the options of a command.
)";

void print_error(const std::string& message) {
    // One line per error, even if a message from deeper down contained a line break.
    std::string line = message;
    for (char& c : line) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    std::fprintf(stderr, "hullkit: %s\n", line.c_str());
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
    if (command == "hull") return hullkit_cli::run_hull(std::move(rest));
    if (command == "verify") return hullkit_cli::run_verify(rest);
    if (command == "delaunay") return hullkit_cli::run_delaunay(rest);
    if (command == "verify-delaunay") return hullkit_cli::run_verify_delaunay(rest);
    if (command == "triangulate") return hullkit_cli::run_triangulate(rest);
    if (command == "delaunay3") return hullkit_cli::run_delaunay3(rest);
    if (command == "verify-delaunay3") return hullkit_cli::run_verify_delaunay3(rest);
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
