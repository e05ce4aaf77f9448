// `hullkit delaunay3` and `hullkit verify-delaunay3`: argument parsing and I/O around
// hullkit::delaunay3 and hullkit::verify_delaunay3. No geometry here.
#pragma once

#include <string>
#include <vector>

namespace hullkit_cli {

/// Runs `hullkit delaunay3` with the arguments after the command name; returns the exit status
/// (0 success, 2 a usage or input problem with one line "hullkit: ..." on stderr).
int run_delaunay3(const std::vector<std::string>& args);

/// Runs `hullkit verify-delaunay3 POINTS TETRAHEDRA`: 0 the tetrahedralization is Delaunay, 1 it is
/// not (each problem on its own line), 2 a usage or input problem.
int run_verify_delaunay3(const std::vector<std::string>& args);

}  // namespace hullkit_cli
