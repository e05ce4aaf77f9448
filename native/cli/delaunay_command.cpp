// `hullkit delaunay` and `hullkit verify-delaunay`: placeholder until the Delaunay core links
// (helper dfaces keeps the real command ready and puts it back as soon as hullkit::delaunay exists).
#include "delaunay_command.hpp"

#include "cli_io.hpp"

namespace hullkit_cli {

int run_delaunay(const std::vector<std::string>&) { return print_usage_error("delaunay: not built yet"); }

int run_verify_delaunay(const std::vector<std::string>&) {
    return print_usage_error("verify-delaunay: not built yet");
}

}  // namespace hullkit_cli
