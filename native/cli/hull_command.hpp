// `hullkit hull INPUT...`: the convex hull of a point cloud, whole or streamed.
#pragma once

#include <string>
#include <vector>

namespace hullkit_cli {

/// Runs `hullkit hull` with the arguments after the command name; returns the exit status (0, or
/// throws CliError for a usage or input problem).
int run_hull(std::vector<std::string> argv);

}  // namespace hullkit_cli
