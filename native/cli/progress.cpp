#include "progress.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace hullkit_cli {

namespace {

constexpr std::int64_t kFirstDrawNs = 1'000'000'000;  // nothing for short runs
constexpr std::int64_t kRedrawNs = 200'000'000;

/// 1234567 -> "1.23M"
std::string short_count(double value) {
    const char* suffix[] = {"", "k", "M", "G", "T"};
    int k = 0;
    while (value >= 1000.0 && k < 4) value /= 1000.0, ++k;
    char text[32];
    std::snprintf(text, sizeof text, k == 0 ? "%.0f%s" : "%.3g%s", value, suffix[k]);
    return text;
}

std::string duration(double seconds) {
    char text[32];
    const long s = static_cast<long>(seconds + 0.5);
    if (s >= 3600) {
        std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, s / 60 % 60);
    } else {
        std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
    }
    return text;
}

/// The wait before the first draw: a second, or HULLKIT_PROGRESS_AFTER_MS milliseconds (the
/// tests draw at once, to see the line on small inputs).
std::int64_t first_draw_ns() {
    const char* text = std::getenv("HULLKIT_PROGRESS_AFTER_MS");
    if (text == nullptr || *text == '\0') return kFirstDrawNs;
    char* end = nullptr;
    const long long ms = std::strtoll(text, &end, 10);
    if (*end != '\0' || ms < 0 || ms > 86'400'000) return kFirstDrawNs;
    return static_cast<std::int64_t>(ms) * 1'000'000;
}

}  // namespace

Progress::Progress(std::string unit, std::uint64_t total, bool quiet)
    : unit_(std::move(unit)),
      total_(total),
      enabled_(!quiet && isatty(fileno(stderr)) == 1),
      start_(std::chrono::steady_clock::now()),
      next_draw_ns_(first_draw_ns()) {}

Progress::~Progress() { finish(); }

void Progress::set_total(std::uint64_t total) { total_.store(total, std::memory_order_relaxed); }

void Progress::update(std::uint64_t done, double fraction) {
    if (!enabled_) return;
    const std::int64_t now = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                 std::chrono::steady_clock::now() - start_).count();
    if (now < next_draw_ns_.load(std::memory_order_relaxed)) return;
    std::unique_lock<std::mutex> lock(draw_mutex_, std::try_to_lock);
    if (!lock.owns_lock() || now < next_draw_ns_.load(std::memory_order_relaxed)) return;
    next_draw_ns_.store(now + kRedrawNs, std::memory_order_relaxed);
    draw(done, fraction);
}

void Progress::draw(std::uint64_t done, double fraction) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0.0;
    const std::uint64_t total = total_.load(std::memory_order_relaxed);
    if (fraction < 0 && total > 0) fraction = static_cast<double>(done) / static_cast<double>(total);
    std::string line = "hullkit: ";
    if (fraction >= 0) {
        constexpr int kWidth = 24;
        fraction = std::min(1.0, fraction);
        const int filled = static_cast<int>(fraction * kWidth);
        line += "[" + std::string(filled, '#') + std::string(kWidth - filled, '.') + "] ";
        char percent[16];
        std::snprintf(percent, sizeof percent, "%3.0f%% ", 100.0 * fraction);
        line += percent;
    }
    line += short_count(static_cast<double>(done));
    if (total > 0) line += "/" + short_count(static_cast<double>(total));
    line += " " + unit_ + ", " + short_count(rate) + " " + unit_ + "/s";
    if (fraction > 0 && fraction < 1) line += ", " + duration(elapsed * (1 - fraction) / fraction) + " left";
    // \r back to the start, the line, then clear whatever a longer earlier line left.
    std::fprintf(stderr, "\r%s\x1b[K", line.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void Progress::finish() {
    std::lock_guard<std::mutex> lock(draw_mutex_);
    next_draw_ns_.store(INT64_MAX, std::memory_order_relaxed);
    if (drawn_) {
        std::fputs("\r\x1b[K", stderr);
        std::fflush(stderr);
        drawn_ = false;
    }
}

}  // namespace hullkit_cli
