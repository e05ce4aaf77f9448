#include "delaunay_command.hpp"

#include <cstdio>

namespace hullkit_cli {

int run_delaunay(const std::vector<std::string>&) {
    std::fputs("hullkit: delaunay: not built yet\n", stderr);
    return 2;
}

int run_verify_delaunay(const std::vector<std::string>&) {
    std::fputs("hullkit: verify-delaunay: not built yet\n", stderr);
    return 2;
}

}  // namespace hullkit_cli
