// Names of the leg statuses, as the JSON report and the JS layer spell them.
#include "hullkit/route.hpp"

namespace hullkit {

const char* leg_status_name(LegStatus status) {
    switch (status) {
        case LegStatus::Clear: return "clear";
        case LegStatus::Hit: return "hit";
        case LegStatus::StartOverlap: return "start-overlap";
    }
    return "unknown";
}

}  // namespace hullkit
