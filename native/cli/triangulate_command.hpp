// `hullkit triangulate`: constrained Delaunay triangulation of polygons with holes and of planar
// straight-line graphs (see triangulate_command.cpp for the options).
#pragma once

#include <string>
#include <vector>

namespace hullkit_cli {

/// Runs `hullkit triangulate` with the arguments after the command name; returns the exit status.
int run_triangulate(const std::vector<std::string>& args);

}  // namespace hullkit_cli
