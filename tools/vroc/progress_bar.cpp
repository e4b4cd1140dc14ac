// SPDX-License-Identifier: MIT
#include "progress_bar.h"

#include <cstdio>

namespace vroc::cli {

ProgressBar::ProgressBar(bool enabled, std::string label) : enabled_(enabled), label_(std::move(label)) {}

ProgressBar::~ProgressBar() { clear(); }

void ProgressBar::update(std::int64_t done, std::int64_t total) {
    if (!enabled_ || total <= 0) return;
    const double fraction = static_cast<double>(done) / static_cast<double>(total);
    draw(fraction, std::to_string(done) + "/" + std::to_string(total) + " frames", done >= total);
}

void ProgressBar::updateRuns(int done, int failed, int total, double seconds_left) {
    if (!enabled_ || total <= 0) return;
    std::string tail = std::to_string(done) + "/" + std::to_string(total) + " runs";
    if (failed > 0) tail += ", " + std::to_string(failed) + " failed";
    if (seconds_left >= 0 && done + failed < total) {
        char eta[48];
        if (seconds_left < 90) std::snprintf(eta, sizeof eta, ", ~%.0f s left", seconds_left);
        else std::snprintf(eta, sizeof eta, ", ~%.0f min left", seconds_left / 60);
        tail += eta;
    }
    draw(static_cast<double>(done + failed) / total, tail, done + failed >= total);
}

void ProgressBar::draw(double fraction, const std::string& tail, bool final) {
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && !final && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(kWidth, ' ');
    std::fprintf(stderr, "\r\033[K%s [%s] %3d%% %s", label_.c_str(), bar.c_str(), static_cast<int>(fraction * 100), tail.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressBar::clear() {
    if (!drawn_) return;
    std::fputs("\r\033[K", stderr);   // carriage return + erase line
    std::fflush(stderr);
    drawn_ = false;
}

}  // namespace vroc::cli
