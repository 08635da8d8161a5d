#include "viewer/frame_stats.hpp"

#include <algorithm>
#include <numeric>

namespace vct::viewer {

void FrameStats::push(std::deque<float>& history, float value) {
    history.push_back(value);
    while (history.size() > kHistory) history.pop_front();
}

void FrameStats::addFrameTime(double ms) { push(frameMs_, float(ms)); }

void FrameStats::addTimings(const gl::FrameTimings& timings) {
    latest_ = timings;
    push(gpuMs_, float(timings.totalGpuMs));
    std::map<std::string, double> frame;  // a pass may appear more than once (one per light…)
    std::map<std::string, Measurement> measured;
    for (const auto& pass : timings.passes) {
        frame[pass.name] += pass.gpuMs;
        Measurement& m = measured[pass.name];
        m.gpuMs += pass.gpuMs;
        m.cpuMs += pass.cpuMs;
        m.frame = timings.frame;
        if (std::find(passOrder_.begin(), passOrder_.end(), pass.name) == passOrder_.end())
            passOrder_.push_back(pass.name);
    }
    for (const auto& [name, m] : measured) lastRun_[name] = m;
    for (const auto& name : passOrder_) {
        auto& history = passMs_[name];
        // A pass first seen now gets zeros for the frames before, so every history lines up.
        while (history.size() + 1 < gpuMs_.size()) history.push_back(0.0f);
        const auto it = frame.find(name);
        push(history, it == frame.end() ? 0.0f : float(it->second));
    }
}

double FrameStats::meanFrameMs() const {
    if (frameMs_.empty()) return 0.0;
    return std::accumulate(frameMs_.begin(), frameMs_.end(), 0.0) / double(frameMs_.size());
}

const std::deque<float>& FrameStats::passHistory(const std::string& pass) const {
    static const std::deque<float> none;
    const auto it = passMs_.find(pass);
    return it == passMs_.end() ? none : it->second;
}

std::vector<std::string> FrameStats::passNames() const { return passOrder_; }

std::optional<FrameStats::Measurement> FrameStats::lastRun(const std::string& pass) const {
    const auto it = lastRun_.find(pass);
    if (it == lastRun_.end()) return std::nullopt;
    return it->second;
}

}  // namespace vct::viewer
