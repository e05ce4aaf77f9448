// Threads for the core, shared by every capability: how many to use, and a parallel loop over
// numbered tasks. Results must never depend on the thread count: callers give each task its own
// output slot and combine the slots in task order afterwards.
//
// The WebAssembly build has no threads: there everything runs on the calling thread.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace hullkit::detail {

/// Whether this build can start threads (not the single-threaded WebAssembly build).
constexpr bool kHaveThreads =
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    false;
#else
    true;
#endif

/// The number of threads to use: `requested`, or every hardware thread for 0; never more than
/// `work_items` (at least 1), and 1 where the build has no threads.
inline unsigned resolve_threads(unsigned requested, std::size_t work_items = ~std::size_t{0}) {
    if (!kHaveThreads) return 1;
    unsigned threads = requested;
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    if (work_items < threads) threads = static_cast<unsigned>(std::max<std::size_t>(1, work_items));
    return threads;
}

/// parallel_for's work on `threads` > 1 threads.
template <class Body>
void spread(unsigned threads, std::size_t tasks, Body& body) {
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr first_error;
    std::mutex error_mutex;
    auto work = [&] {
        for (;;) {
            if (failed.load(std::memory_order_relaxed)) return;
            const std::size_t task = next.fetch_add(1, std::memory_order_relaxed);
            if (task >= tasks) return;
            try {
                body(task);
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_mutex);
                if (!first_error) first_error = std::current_exception();
                failed.store(true, std::memory_order_relaxed);
            }
        }
    };
    std::vector<std::thread> helpers;
    helpers.reserve(threads - 1);
    for (unsigned t = 1; t < threads; ++t) {
        try {
            helpers.emplace_back(work);
        } catch (const std::system_error&) {  // no more threads to be had: the others share it
            break;
        }
    }
    work();
    for (std::thread& helper : helpers) helper.join();
    if (first_error) std::rethrow_exception(first_error);
}

/// Calls body(task) once for every task in [0, tasks), on up to `threads` threads (the calling
/// thread is one of them); tasks are handed out in increasing order as threads become free.
/// If a body throws, no new tasks start and the first exception is rethrown once every thread
/// has stopped. If no thread can be started, the calling thread does all the work.
template <class Body>
void parallel_for(unsigned threads, std::size_t tasks, Body&& body) {
    threads = resolve_threads(threads, tasks);
    if (!kHaveThreads || threads <= 1) {
        for (std::size_t task = 0; task < tasks; ++task) body(task);
        return;
    }
    if constexpr (kHaveThreads) {  // no std::thread in a build without threads
        spread(threads, tasks, body);
    }
}

}  // namespace hullkit::detail
