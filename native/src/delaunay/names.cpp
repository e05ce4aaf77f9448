// Names of the Delaunay algorithms, for the CLI and the JS layer.
#include "hullkit/delaunay.hpp"

namespace hullkit {

const char* delaunay_algorithm_name(DelaunayAlgorithm algorithm) {
    switch (algorithm) {
        case DelaunayAlgorithm::Incremental: return "incremental";
        case DelaunayAlgorithm::Giftwrap: return "giftwrap";
    }
    return "unknown";
}

bool parse_delaunay_algorithm(const std::string& name, DelaunayAlgorithm* out) {
    for (DelaunayAlgorithm algorithm : {DelaunayAlgorithm::Incremental, DelaunayAlgorithm::Giftwrap}) {
        if (name == delaunay_algorithm_name(algorithm)) {
            *out = algorithm;
            return true;
        }
    }
    return false;
}

}  // namespace hullkit
