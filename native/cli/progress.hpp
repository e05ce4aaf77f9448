// A one-line progress bar for long runs of the `hullkit` subcommands.
//
// Shown only when standard error is a terminal (never into a pipe or a file), not with --quiet,
// and only once a run has lasted about a second (HULLKIT_PROGRESS_AFTER_MS overrides the wait);
// redrawn a few times a second with the count done, the rate and, when the total is known, the
// time left; cleared when the run ends.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace hullkit_cli {

class Progress {
public:
    /// `unit` names what is counted ("points", "legs", "bytes"); `total` is the count expected
    /// (0 when unknown: then only update()'s fraction, if given, draws the bar and the time left). `quiet` silences it.
    Progress(std::string unit, std::uint64_t total, bool quiet);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// Records that `done` units are finished. `fraction` (0 to 1) is how far the whole run is,
    /// when the caller knows it better than done / total (e.g. bytes of a file read); negative:
    /// done / total, or unknown without a total. Safe from any thread; cheap when nothing is drawn.
    void update(std::uint64_t done, double fraction = -1.0);
    /// Changes the expected total (e.g. once a header says how many points follow).
    void set_total(std::uint64_t total);
    /// Clears the line, if one was drawn. Called by the destructor too.
    void finish();

private:
    void draw(std::uint64_t done, double fraction);

    std::string unit_;
    std::atomic<std::uint64_t> total_;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
    std::atomic<std::int64_t> next_draw_ns_;
    std::mutex draw_mutex_;
};

}  // namespace hullkit_cli
