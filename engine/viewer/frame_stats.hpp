#pragma once
// Rolling history of what the viewer measured: wall time per frame and the GPU timer's per-pass
// results (which arrive a frame or more late, without stalling). The panel plots these.
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gl/gpu_timer.hpp"

namespace vct::viewer {

class FrameStats {
public:
    static constexpr std::size_t kHistory = 120;

    void addFrameTime(double ms);
    void addTimings(const gl::FrameTimings& timings);

    const std::optional<gl::FrameTimings>& latest() const { return latest_; }
    double lastFrameMs() const { return frameMs_.empty() ? 0.0 : frameMs_.back(); }
    double meanFrameMs() const;  // over the history

    // Oldest first, at most kHistory values.
    const std::deque<float>& frameHistory() const { return frameMs_; }
    const std::deque<float>& gpuHistory() const { return gpuMs_; }
    // GPU ms of one pass in each of the frames of gpuHistory() (0 where it did not run).
    const std::deque<float>& passHistory(const std::string& pass) const;
    std::vector<std::string> passNames() const;  // every pass seen in the history, first-seen order

    // The pass's times in the newest measured frame that ran it (passes skipped since keep the
    // values of their last run); nullopt if it never ran.
    struct Measurement {
        double gpuMs = 0.0, cpuMs = 0.0;
        std::uint64_t frame = 0;  // GpuTimer frame number
    };
    std::optional<Measurement> lastRun(const std::string& pass) const;

private:
    static void push(std::deque<float>& history, float value);

    std::optional<gl::FrameTimings> latest_;
    std::deque<float> frameMs_, gpuMs_;
    std::map<std::string, std::deque<float>> passMs_;
    std::vector<std::string> passOrder_;
    std::map<std::string, Measurement> lastRun_;
};

}  // namespace vct::viewer
