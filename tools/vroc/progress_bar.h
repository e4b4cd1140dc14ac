// SPDX-License-Identifier: MIT
// A one-line progress bar on stderr, redrawn at most 10 times a second. Disabled (draws nothing)
// when stderr is not a terminal or the user asked for --quiet, so logs hold only errors.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace vroc::cli {

class ProgressBar {
public:
    ProgressBar(bool enabled, std::string label);
    ~ProgressBar();   ///< clears the line if anything was drawn

    void update(std::int64_t done, std::int64_t total);
    /// "12/64 runs, 1 failed, ~3 min left" (seconds_left < 0: unknown).
    void updateRuns(int done, int failed, int total, double seconds_left);

    /// Clears the line (before printing results); later updates draw again.
    void finish() { clear(); }

private:
    void clear();
    void draw(double fraction, const std::string& tail, bool final);

    bool enabled_;
    bool drawn_ = false;
    std::string label_;
    std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace vroc::cli
