// Points as hash keys: exact coordinate equality, with -0.0 and +0.0 the same point.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace hullkit::detail {

struct PointKey {
    double xyz[3];
    bool operator==(const PointKey& other) const {
        return xyz[0] == other.xyz[0] && xyz[1] == other.xyz[1] && xyz[2] == other.xyz[2];
    }
};

inline PointKey key_of(const double* p) {
    // + 0.0 turns -0.0 into +0.0: they are the same point and must hash alike.
    return PointKey{{p[0] + 0.0, p[1] + 0.0, p[2] + 0.0}};
}

struct PointKeyHash {
    std::size_t operator()(const PointKey& key) const {
        std::uint64_t h = 0x9e3779b97f4a7c15ull;
        for (double c : key.xyz) {
            std::uint64_t bits;
            std::memcpy(&bits, &c, sizeof bits);
            h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
            h *= 0xff51afd7ed558ccdull;
            h ^= h >> 33;
        }
        return static_cast<std::size_t>(h);
    }
};

}  // namespace hullkit::detail
