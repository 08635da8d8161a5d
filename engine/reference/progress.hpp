#pragma once
// Progress of a long CPU render on stderr: on a terminal a bar redrawn in place with the elapsed
// time and an ETA (at most 5 times a second); in a log (stderr not a TTY) one line every ~10 %,
// so CI logs stay short. Thread-safe: workers report finished work from any thread.
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace vct::reference {

class Progress {
public:
    // `label` starts every line; `enabled` false makes every call a no-op.
    Progress(std::string label, bool enabled);

    // `fraction` in [0, 1] of the whole job; `detail` e.g. "12/64 spp".
    void update(double fraction, const std::string& detail);
    void finish();  // clears the bar (the caller prints its own summary)

    double elapsedSeconds() const;

private:
    std::string label_;
    bool enabled_;
    bool tty_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point lastDraw_{};
    int lastDecile_ = 0;
    bool drawn_ = false;
    std::mutex mutex_;
};

std::string formatDuration(double seconds);  // "4.2 s", "3 min 12 s", "1 h 05 min"

}  // namespace vct::reference
