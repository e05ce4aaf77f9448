#include "route_command.hpp"

#include <cstdio>

namespace hullkit_cli {

int run_route(const std::vector<std::string>&) {
    std::fputs("hullkit: route: not built yet\n", stderr);
    return 2;
}

}  // namespace hullkit_cli
