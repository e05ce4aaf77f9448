// libFuzzer target: hullkit::hull on arbitrary bytes read as little-endian doubles (x y z per
// point; NaN, infinities, huge and tiny magnitudes, repeats and flat sets all come up). A hull
// that is returned must pass the exact verify(); an error must be one line. Quickhull always;
// gift wrapping too on small inputs, where it must give the same vertices.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "hullkit/hull.hpp"
#include "hullkit/verify.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::size_t count = size / 24;
    if (count > 400) return 0;  // keeps each input fast; structure matters, not size
    std::vector<double> xyz(3 * count);
    if (count) std::memcpy(xyz.data(), data, 24 * count);
    const hullkit::PointSpan points(xyz.data(), count);
    const hullkit::Hull quick = hullkit::hull(points, {});
    if (!quick.ok()) {
        if (quick.error.empty() || quick.error.find('\n') != std::string::npos) std::abort();
        return 0;
    }
    const hullkit::VerifyReport report = hullkit::verify(points, quick);
    if (!report.ok) std::abort();
    if (count <= 60) {
        hullkit::HullOptions options;
        options.algorithm = hullkit::Algorithm::Giftwrap;
        const hullkit::Hull wrap = hullkit::hull(points, options);
        if (!wrap.ok() || wrap.vertices != quick.vertices || wrap.dimension != quick.dimension) std::abort();
    }
    return 0;
}
