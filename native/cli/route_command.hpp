// `hullkit route SCENE.json`: argument parsing and I/O around hullkit::RouteChecker.
#pragma once

#include <string>
#include <vector>

namespace hullkit_cli {

/// Runs `hullkit route` with the arguments after the command name; returns the exit status:
/// 0 every leg is clear, 1 any leg is not, 2 a usage or input problem (one line on stderr).
int run_route(const std::vector<std::string>& args);

}  // namespace hullkit_cli
