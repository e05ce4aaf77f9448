// Working arrays of the size of the input (a hull's faces, the candidates' copy, sort buffers, the
// 2D and 3D meshes and their outputs): mapped on their own, on transparent huge pages where fresh
// pages are costly, and given back to the system when freed (or, for std::vectors a caller gets
// back, advised onto huge pages where they are reserved: reserve_large).
//
// Why mapped: freed arrays below glibc's (rising) mmap threshold stayed in the heap, so that a
// process hulling 1e6 points on a sphere five times peaked 80 MB above one that did it once.
//
// Why huge pages, and where: a first call touches every page of these arrays for the first time,
// and what a fresh page costs depends on the machine far more than on the code. Four 2-core
// benchmark machines so far (Linux, THP in "madvise" mode, virtual):
// - the first: the first hull of 1e6 points on a sphere spent about half its time in page faults
//   (2.3 s; 1.2 s with MADV_HUGEPAGE);
// - the second (a host that took free 2 MiB blocks back): huge pages made every first call slower,
//   1e6 uniform points tetrahedralized on one thread 3.55-3.67 s against 3.11-3.18 s without, the
//   hull of 1e6 points on a sphere 0.68-0.72 s against 0.62-0.66 s;
// - the third (Dec 2026, about 10 us a fresh 4 KiB page: 256 MiB touched in 0.66-0.77 s, on huge
//   pages 0.02-0.44 s): 1e6 uniform points tetrahedralized on one thread 2.65-2.80 s against
//   3.53-3.64 s without (117 503 page faults down to 13 400, the same peak memory), on two threads
//   1.51-1.94 s against 2.19-2.67 s, 1e6 uniform points triangulated in 2D on one thread
//   0.74-0.77 s against 1.04-1.21 s, the hull of 1e6 points on a sphere 1.01-1.18 s against
//   1.69-1.77 s (peak memory 7-17 MB higher); warm calls faster too (fewer TLB misses);
// - the fourth (7 Dec 2026, about 1.6 us a fresh 4 KiB page: 256 MiB in 0.10 s, on huge pages
//   0.3-0.55 s; free 2 MiB blocks reported to the host, virtio-balloon): like the second, the 2D
//   Delaunay triangulation of 1e6 uniform points took 0.70-0.86 s on huge pages against
//   0.51-0.56 s without, the tetrahedralization on one thread 3.02-3.30 s against 2.71-2.93 s
//   (each right after a CGAL run, as the benchmarks run them; warm calls alike).
// So the process decides, at its first large array: it times the first touch of a few fresh
// 4 KiB pages (fresh_page_seconds) and uses huge pages where one costs kCostlyFreshPage or more.
// HULLKIT_HUGE_PAGES=0 or =1 in the environment decides instead (read once). On more than one
// thread the 3D mesh's rows are mapped in advance on the threads (Prefault). Only the memory's
// placement changes, never a value, so results stay bit-identical either way.
//
// How: arrays of at least kLargeArray bytes are mapped on their own (mmap), aligned to 2 MiB,
// rounded up to whole 2 MiB pages (marked MADV_HUGEPAGE unless turned off) and unmapped when freed;
// smaller ones come from operator new as usual; those from kPopulateArray bytes up that are about
// to be filled have their pages mapped in one call first (populate: on the machine of Dec 2026 a
// fresh page cost ~9.5 us mapped on first touch, ~4.5 us mapped in advance; with arrays from
// 32 KiB up, the grid of 2500 holes meshed went from 430 page faults to 59 in its first call).
// Elsewhere (WebAssembly, other systems, sanitizer builds) every array comes from operator new and
// nothing is mapped in advance.
//
// A LargeArray's resize(n) and LargeArray(n) leave the new elements unwritten (the allocator
// default-initializes them): each such array is written in full by its owner before any read,
// often on the threads, so a serial zero fill would only add a pass over fresh pages on one
// thread. Sizing with an explicit value (resize(n, v), LargeArray(n, v), assign) writes it.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <new>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

// Under AddressSanitizer or ThreadSanitizer large arrays come from operator new too, so that the
// sanitizers see them (they do not watch memory mapped by hand).
#include "sanitizer_build.hpp"

#if defined(__linux__) && !defined(__EMSCRIPTEN__) && !defined(HULLKIT_SANITIZED)
#include <sys/mman.h>
#define HULLKIT_HUGE_PAGES 1
#else
#define HULLKIT_HUGE_PAGES 0
#endif

namespace hullkit::detail {

/// Arrays this large (bytes) or larger are mapped on their own (on huge pages: up to 2 MiB of the
/// last page may then be touched without being used, at most a third of such an array).
inline constexpr std::size_t kLargeArray = std::size_t{4} << 20;
inline constexpr std::size_t kHugePage = std::size_t{2} << 20;

/// A fresh 4 KiB page's first touch from this many seconds up makes huge pages worth their risk
/// (see the top of this file): the machines that gained from them took about 10 us a page, the
/// one where they cost 10-35 % about 1.6 us.
inline constexpr double kCostlyFreshPage = 4e-6;

/// What the first touch of a fresh 4 KiB page costs this process, in seconds: 32 pages mapped
/// and touched one at a time, the median of their times (so that a page slowed by something else
/// does not count). About 0.05-0.3 ms in all, spent once, at the first large array. 0 where large
/// arrays are not mapped by hand.
inline double fresh_page_seconds() {
#if HULLKIT_HUGE_PAGES
    constexpr std::size_t kPages = 32, kPage = 4096;
    void* mapped = mmap(nullptr, kPages * kPage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) return 0;
    madvise(mapped, kPages * kPage, MADV_NOHUGEPAGE);
    volatile char* bytes = static_cast<volatile char*>(mapped);
    double seconds[kPages];
    for (std::size_t k = 0; k < kPages; ++k) {
        const auto start = std::chrono::steady_clock::now();
        bytes[k * kPage] = 1;
        seconds[k] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    munmap(mapped, kPages * kPage);
    std::nth_element(seconds, seconds + kPages / 2, seconds + kPages);
    return seconds[kPages / 2];
#else
    return 0;
#endif
}

/// The rule huge_pages() applies: HULLKIT_HUGE_PAGES=0 turns them off and any other value on;
/// unset, they are on where a fresh 4 KiB page costs kCostlyFreshPage or more (the cost is only
/// measured then: `fresh_page` is called at most once).
template <class Measure>
bool huge_pages_rule(const char* environment, Measure&& fresh_page) {
    if (environment != nullptr) return std::string_view(environment) != "0";
    return fresh_page() >= kCostlyFreshPage;
}

/// Whether large arrays are advised onto transparent huge pages (see the top of this file), decided
/// once per process, at the first large array: huge_pages_rule on the environment's
/// HULLKIT_HUGE_PAGES and fresh_page_seconds().
inline bool huge_pages() {
    static const bool on = huge_pages_rule(std::getenv("HULLKIT_HUGE_PAGES"), fresh_page_seconds);
    return on;
}

/// The bytes a large array of `bytes` takes: whole 2 MiB pages.
inline std::size_t large_size(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

/// A large array's memory, mapped on its own (2 MiB aligned) and unmapped when released: the
/// system gets it back at once. From malloc, freed arrays below glibc's (rising) mmap threshold
/// stayed in the heap, so that a process hulling 1e6 points on a sphere five times peaked 80 MB
/// above one that did it once.
inline void* allocate_large(std::size_t bytes) {
#if HULLKIT_HUGE_PAGES
    const std::size_t size = large_size(bytes);
    void* mapped = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    // Keep the 2 MiB aligned part; give back what is before and after it.
    const auto start = reinterpret_cast<std::uintptr_t>(mapped);
    const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
    if (aligned > start) munmap(mapped, aligned - start);
    const std::uintptr_t tail = aligned + size, end = start + size + kHugePage;
    if (end > tail) munmap(reinterpret_cast<void*>(tail), end - tail);
    void* memory = reinterpret_cast<void*>(aligned);
    if (huge_pages()) madvise(memory, size, MADV_HUGEPAGE);  // a hint: without it the array works all the same
    return memory;
#else
    return ::operator new(bytes);
#endif
}

/// Releases what allocate_large(bytes) returned.
inline void release_large(void* memory, std::size_t bytes) noexcept {
#if HULLKIT_HUGE_PAGES
    munmap(memory, large_size(bytes));
#else
    (void)bytes;
    ::operator delete(memory);
#endif
}

/// A std::allocator for trivially copyable working arrays, with large ones on huge pages.
template <class T>
struct LargeArrayAllocator {
    using value_type = T;
    static_assert(alignof(T) <= alignof(std::max_align_t), "over-aligned types need their own allocator");

    LargeArrayAllocator() = default;
    template <class U>
    LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = n * sizeof(T);
        return static_cast<T*>(bytes >= kLargeArray ? allocate_large(bytes) : ::operator new(bytes));
    }
    void deallocate(T* memory, std::size_t n) noexcept {
        if (n * sizeof(T) >= kLargeArray) {
            release_large(memory, n * sizeof(T));
        } else {
            ::operator delete(memory);
        }
    }

    /// resize(n) and sized construction default-initialize (see the top of this file); an
    /// explicit value is written as usual.
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

    template <class U>
    bool operator==(const LargeArrayAllocator<U>&) const noexcept { return true; }
    template <class U>
    bool operator!=(const LargeArrayAllocator<U>&) const noexcept { return false; }
};

/// Unless huge pages are off, advises them for the whole 2 MiB pages of [memory, memory + bytes) when
/// that is large: for arrays that keep std::allocator (those a caller gets back), reserved and
/// then filled. Pages already touched stay as they are. With huge pages off, nothing.
inline void advise_huge_pages(const void* memory, std::size_t bytes) {
#if HULLKIT_HUGE_PAGES
    if (bytes < kLargeArray || !huge_pages()) return;
    const auto first = reinterpret_cast<std::uintptr_t>(memory);
    const std::uintptr_t begin = (first + kHugePage - 1) / kHugePage * kHugePage;
    const std::uintptr_t end = (first + bytes) / kHugePage * kHugePage;
    if (begin < end) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)memory;
    (void)bytes;
#endif
}

/// Maps the pages of [memory, memory + bytes) in advance, in `parts` pieces that the caller may
/// hand to its threads (prefault_part(k) for k < parts): the system zeroes a fresh page on its
/// first touch, and an array first written on one thread (a vector's resize) would have all of
/// that done there. Nothing is written (MADV_POPULATE_WRITE; where the system lacks it, nothing
/// happens and the pages are mapped on first touch as before).
struct Prefault {
    const void* memory = nullptr;
    std::size_t bytes = 0, parts = 0;
    void part(std::size_t k) const {
#if HULLKIT_HUGE_PAGES && defined(MADV_POPULATE_WRITE)
        const auto first = reinterpret_cast<std::uintptr_t>(memory);  // whole 2 MiB pages inside it
        const std::uintptr_t begin = (first + kHugePage - 1) / kHugePage * kHugePage;
        const std::uintptr_t end = (first + bytes) / kHugePage * kHugePage;
        if (end <= begin) return;
        const std::size_t pages = (end - begin) / kHugePage;
        const std::uintptr_t from = begin + pages * k / parts * kHugePage, to = begin + pages * (k + 1) / parts * kHugePage;
        if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
#else
        (void)k;
#endif
    }
};

/// Arrays from this many bytes (two pages) up, and below kLargeArray unless huge pages are off,
/// have their pages mapped in one call before they are filled: populate(). (From 32 KiB up instead, the process meshing the
/// grid of 256 holes once took 25 more page faults: 235 against 210.)
inline constexpr std::size_t kPopulateArray = std::size_t{8} << 10;

/// Maps the 4 KiB pages under [memory, memory + bytes) in one call, for an array about to be
/// written from its start: a fresh page mapped on its first touch costs a fault each (about 10 us
/// on the benchmark machines of Dec 2026), mapped in advance about half that (MADV_POPULATE_WRITE
/// writes nothing; pages already mapped stay as they are). Only for arrays of kPopulateArray bytes
/// and more, and below kLargeArray unless huge pages are off: smaller ones mostly reuse the heap's
/// pages, larger ones are on huge pages.
/// Where the system lacks it, nothing happens.
inline void populate(const void* memory, std::size_t bytes) {
#if HULLKIT_HUGE_PAGES && defined(MADV_POPULATE_WRITE)
    if (bytes < kPopulateArray || (bytes >= kLargeArray && huge_pages())) return;
    constexpr std::uintptr_t kPage = 4096;
    const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(memory) / kPage * kPage;
    const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(memory) + bytes + kPage - 1) / kPage * kPage;
    madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
    (void)memory;
    (void)bytes;
#endif
}

/// Reserves room for `capacity` elements and maps the pages of the first `used` at once
/// (populate): for an array that will be filled to about `used` and may grow to `capacity`.
template <class T, class A>
void reserve_populated(std::vector<T, A>& v, std::size_t capacity, std::size_t used) {
    v.reserve(capacity);
    populate(v.data(), std::min(used, v.capacity()) * sizeof(T));
}

/// Gives the whole pages inside [begin, end) back to the system (their contents are lost: they
/// read as zeros when touched again), where the system allows it (Linux); elsewhere nothing. For
/// an array rewritten in place from its front while its back is read and no longer needed.
/// Returns the end of what was given back (`begin` when nothing was), to start the next call.
inline void* release_pages(void* begin, void* end) {
#if HULLKIT_HUGE_PAGES
    // Whole huge pages when arrays are on them: giving back part of one would split it, and the
    // part written again would come back as 4 KiB pages, each faulted in on its own.
    const std::uintptr_t kPage = huge_pages() ? kHugePage : 4096;
    const std::uintptr_t from = (reinterpret_cast<std::uintptr_t>(begin) + kPage - 1) / kPage * kPage;
    const std::uintptr_t to = reinterpret_cast<std::uintptr_t>(end) / kPage * kPage;
    if (from >= to) return begin;
    madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
    return reinterpret_cast<void*>(to);
#else
    (void)end;
    return begin;
#endif
}

/// Reserves room for n elements in a std::vector, advised onto huge pages when large.
template <class T>
void reserve_large(std::vector<T>& v, std::size_t n) {
    v.reserve(n);
    advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

/// Sizes a std::vector to n elements (value-initialized), advised onto huge pages when large and
/// its pages mapped at once when of middle size (populate).
template <class T>
void resize_large(std::vector<T>& v, std::size_t n) {
    reserve_large(v, n);
    populate(v.data(), n * sizeof(T));
    v.resize(n);
}

/// A vector for working arrays that may grow to the size of the input.
template <class T>
using LargeArray = std::vector<T, LargeArrayAllocator<T>>;

}  // namespace hullkit::detail
