#include "reference/progress.hpp"

#include <cmath>
#include <cstdio>

#include <unistd.h>

namespace vct::reference {

std::string formatDuration(double seconds) {
    char buffer[64];
    if (!std::isfinite(seconds) || seconds < 0) return "?";
    if (seconds < 60) std::snprintf(buffer, sizeof buffer, "%.1f s", seconds);
    else if (seconds < 3600) std::snprintf(buffer, sizeof buffer, "%d min %02d s", int(seconds / 60), int(seconds) % 60);
    else std::snprintf(buffer, sizeof buffer, "%d h %02d min", int(seconds / 3600), int(seconds / 60) % 60);
    return buffer;
}

Progress::Progress(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled), tty_(isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {}

double Progress::elapsedSeconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(double fraction, const std::string& detail) {
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    fraction = std::fmin(std::fmax(fraction, 0.0), 1.0);
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = elapsedSeconds();
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : NAN;
    if (tty_) {
        if (drawn_ && now - lastDraw_ < std::chrono::milliseconds(200) && fraction < 1.0) return;
        lastDraw_ = now;
        drawn_ = true;
        constexpr int kWidth = 30;
        const int filled = int(fraction * kWidth);
        std::string bar(std::size_t(filled), '#');
        bar.append(std::size_t(kWidth - filled), '.');
        std::fprintf(stderr, "\r\033[Kvct: %s [%s] %3d%% %s, %s elapsed, ETA %s", label_.c_str(), bar.c_str(),
                     int(fraction * 100), detail.c_str(), formatDuration(elapsed).c_str(), formatDuration(eta).c_str());
        std::fflush(stderr);
        return;
    }
    const int decile = int(fraction * 10.0 + 1e-9);
    if (decile <= lastDecile_ || decile >= 10) return;  // the caller reports the end
    lastDecile_ = decile;
    std::fprintf(stderr, "vct: %s %3d%% %s, %s elapsed, ETA %s\n", label_.c_str(), decile * 10, detail.c_str(),
                 formatDuration(elapsed).c_str(), formatDuration(eta).c_str());
}

void Progress::finish() {
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    if (tty_ && drawn_) std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
}

}  // namespace vct::reference
