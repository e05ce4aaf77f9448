// 2D points from a fuzzer's bytes, for the 2D fuzz targets (fuzz_delaunay, fuzz_constrained).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace fuzz_input {

/// Points read from `size` bytes in one of four ways (`mode`): (0) little-endian doubles x y (NaN,
/// infinities, huge and tiny magnitudes); (1) int8 pairs (grids, collinear and cocircular sets,
/// repeats); (2) int8 pairs scaled by 2^-30 around (1e6, -1e6) (the same, exactly, far from the
/// origin); (3) int16 pairs.
inline std::vector<double> points2d(const std::uint8_t* data, std::size_t size, int mode) {
    std::vector<double> xy;
    if (mode == 0) {
        xy.resize(size / 16 * 2);
        if (!xy.empty()) std::memcpy(xy.data(), data, 8 * xy.size());
    } else if (mode == 1 || mode == 2) {
        for (std::size_t i = 0; i + 1 < size; i += 2) {
            const double x = static_cast<std::int8_t>(data[i]), y = static_cast<std::int8_t>(data[i + 1]);
            if (mode == 1) xy.insert(xy.end(), {x, y});
            else xy.insert(xy.end(), {1e6 + std::ldexp(x, -30), -1e6 + std::ldexp(y, -30)});
        }
    } else {
        for (std::size_t i = 0; i + 3 < size; i += 4) {
            xy.push_back(static_cast<std::int16_t>(data[i] | data[i + 1] << 8));
            xy.push_back(static_cast<std::int16_t>(data[i + 2] | data[i + 3] << 8));
        }
    }
    return xy;
}

}  // namespace fuzz_input
