#pragma once
// Per-pass GPU timing with GL_TIMESTAMP queries (DESIGN 5.6). Each pass is bracketed by two
// timestamps; results are read back only once the GPU has produced them (a frame or more later),
// so timing never stalls the pipeline. CPU time (submission on this thread) is recorded beside.
#include <chrono>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "gl/objects.hpp"

namespace vct::gl {

struct PassTiming {
    std::string name;
    double gpuMs = 0.0;
    double cpuMs = 0.0;
};

struct FrameTimings {
    std::uint64_t frame = 0;
    std::vector<PassTiming> passes;
    double totalGpuMs = 0.0;  // first pass start to last pass end on the GPU
    double totalCpuMs = 0.0;  // sum of the passes' CPU times
};

class GpuTimer {
public:
    void beginFrame();
    void beginPass(const std::string& name);
    void endPass();
    void endFrame();

    // The oldest finished frame whose results the GPU has delivered, without waiting.
    std::optional<FrameTimings> poll();
    // Waits for every submitted frame and returns the newest (for headless runs at exit).
    std::optional<FrameTimings> waitForLatest();

    // With `finish`, every pass ends with glFinish, so a pass's CPU time is its whole cost even
    // where the driver defers work past the pass's end (llvmpipe rasterizes at the next flush and
    // runs compute at submission, so without it one pass's work can land in the next one's time).
    // Frames get slower (no overlap between passes): for measuring passes, not for rendering.
    void setFinishEachPass(bool finish) { finishEachPass_ = finish; }

    // Brackets a pass for the lifetime of the object.
    class Scope {
    public:
        Scope(GpuTimer& timer, const std::string& name) : timer_(timer) { timer_.beginPass(name); }
        ~Scope() { timer_.endPass(); }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        GpuTimer& timer_;
    };

private:
    struct PendingPass {
        std::string name;
        Query start, end;
        std::chrono::steady_clock::time_point cpuStart;
        double cpuMs = 0.0;
    };
    struct PendingFrame {
        std::uint64_t frame = 0;
        std::vector<PendingPass> passes;
    };

    Query takeQuery();
    bool ready(const PendingFrame& frame) const;
    FrameTimings resolve(PendingFrame& frame);

    std::deque<PendingFrame> pending_;
    std::optional<PendingFrame> current_;
    std::vector<Query> freeQueries_;
    std::uint64_t frameCounter_ = 0;
    bool finishEachPass_ = false;
    static constexpr std::size_t kMaxPendingFrames = 8;  // older results are dropped, not waited on
};

}  // namespace vct::gl
