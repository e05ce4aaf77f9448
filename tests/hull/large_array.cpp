// The working arrays' memory helpers (native/src/hull/large_array.hpp): populate() maps exactly the
// pages under the range it is given, and the sizing helpers keep std::vector's meaning.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "hull/large_array.hpp"

#if HULLKIT_HUGE_PAGES && defined(MADV_POPULATE_WRITE)
#include <unistd.h>

namespace {

/// How many of the `pages` pages from `memory` are resident (mincore).
std::size_t resident(void* memory, std::size_t pages) {
    std::vector<unsigned char> in(pages);
    REQUIRE(mincore(memory, pages * 4096, in.data()) == 0);
    std::size_t count = 0;
    for (unsigned char c : in) count += c & 1;
    return count;
}

}  // namespace

TEST_CASE("populate maps the pages under its range and no others", "[large_array]") {
    REQUIRE(sysconf(_SC_PAGESIZE) == 4096);
    constexpr std::size_t kPages = 64;
    void* mapped = mmap(nullptr, kPages * 4096, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    REQUIRE(mapped != MAP_FAILED);
    auto* bytes = static_cast<unsigned char*>(mapped);
    if (madvise(bytes + 63 * 4096, 4096, MADV_POPULATE_WRITE) != 0) {
        munmap(mapped, kPages * 4096);
        WARN("this kernel has no MADV_POPULATE_WRITE (Linux 5.14 and later): populate() maps nothing here");
        return;
    }
    REQUIRE(resident(mapped, kPages) == 1);
    // From the middle of page 2 to the middle of page 20 (72 KiB): pages 2..20 mapped, the array's
    // partial first and last pages included.
    hullkit::detail::populate(bytes + 2 * 4096 + 100, 18 * 4096);
    CHECK(resident(bytes, 2) == 0);
    CHECK(resident(bytes + 2 * 4096, 19) == 19);
    CHECK(resident(bytes + 21 * 4096, 42) == 0);
    // Nothing is written: the pages read as zeros.
    for (std::size_t k = 2 * 4096; k < 21 * 4096; ++k) REQUIRE(bytes[k] == 0);
    // Below kPopulateArray nothing is done (small arrays mostly reuse the heap's pages).
    hullkit::detail::populate(bytes + 30 * 4096, hullkit::detail::kPopulateArray - 1);
    CHECK(resident(bytes + 30 * 4096, 8) == 0);
    munmap(mapped, kPages * 4096);
}
#endif

TEST_CASE("resize_large and reserve_populated size vectors as resize and reserve do", "[large_array]") {
    std::vector<std::uint32_t> v{7, 8, 9};
    hullkit::detail::resize_large(v, 100000);
    REQUIRE(v.size() == 100000);
    CHECK(v[0] == 7);
    CHECK(v[2] == 9);
    CHECK(v[3] == 0);
    CHECK(v.back() == 0);
    std::vector<double> w{1.5};
    hullkit::detail::reserve_populated(w, 50000, 20000);
    CHECK(w.size() == 1);
    CHECK(w[0] == 1.5);
    CHECK(w.capacity() >= 50000);
    // A used count above the capacity maps no more than the capacity.
    std::vector<std::uint8_t> u;
    hullkit::detail::reserve_populated(u, 40000, 1000000);
    CHECK(u.capacity() >= 40000);
    CHECK(u.empty());
}

TEST_CASE("huge pages: the environment decides when set, else the cost of a fresh page", "[large_array]") {
    using hullkit::detail::huge_pages_rule;
    using hullkit::detail::kCostlyFreshPage;
    int measured = 0;
    const auto costing = [&](double seconds) {
        return [&measured, seconds] {
            ++measured;
            return seconds;
        };
    };
    // Set: "0" is off, anything else on, and nothing is measured.
    CHECK_FALSE(huge_pages_rule("0", costing(1.0)));
    CHECK(huge_pages_rule("1", costing(0.0)));
    CHECK(huge_pages_rule("yes", costing(0.0)));
    CHECK(measured == 0);
    // Unset: on from kCostlyFreshPage a page up, measured once.
    CHECK(huge_pages_rule(nullptr, costing(10e-6)));
    CHECK(huge_pages_rule(nullptr, costing(kCostlyFreshPage)));
    CHECK_FALSE(huge_pages_rule(nullptr, costing(1.6e-6)));
    CHECK_FALSE(huge_pages_rule(nullptr, costing(0.0)));  // where nothing is mapped by hand
    CHECK(measured == 4);
}

TEST_CASE("huge pages: a fresh page's first touch is timed on Linux", "[large_array]") {
    const double seconds = hullkit::detail::fresh_page_seconds();
#if HULLKIT_HUGE_PAGES
    // A fault takes some time, and far less than a millisecond on any machine this runs on.
    CHECK(seconds > 0);
    CHECK(seconds < 1e-3);
#else
    CHECK(seconds == 0);
#endif
}
