// `hullkit delaunay` and `hullkit verify-delaunay`: argument parsing and I/O around
// hullkit::delaunay and hullkit::verify_delaunay. No geometry here.
#pragma once

#include <string>
#include <vector>

namespace hullkit_cli {

/// Runs `hullkit delaunay` with the arguments after the command name; returns the exit status
/// (0 success, 2 a usage or input problem with one line "hullkit: ..." on stderr).
int run_delaunay(const std::vector<std::string>& args);

/// Runs `hullkit verify-delaunay POINTS TRIANGLES`: 0 the triangulation is Delaunay, 1 it is
/// not (each problem on its own line), 2 a usage or input problem.
int run_verify_delaunay(const std::vector<std::string>& args);

}  // namespace hullkit_cli
