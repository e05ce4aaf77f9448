// `hullkit verify POINTS HULL`: checks a hull file (any mesh format) against its point set (hullkit/verify.hpp).
#pragma once

#include <string>
#include <vector>

namespace hullkit_cli {

/// Runs `hullkit verify` with the arguments after the command name. Returns the exit status:
/// 0 the hull is correct (prints "ok: N points, F triangles, V vertices"), 1 it is not (prints each
/// problem on its own line), 2 a usage or input problem (one line "hullkit: ..." on stderr).
int run_verify(const std::vector<std::string>& args);

}  // namespace hullkit_cli
