#include "gl/gpu_timer.hpp"

#include "core/error.hpp"

namespace vct::gl {

Query GpuTimer::takeQuery() {
    if (freeQueries_.empty()) return createQuery(GL_TIMESTAMP);
    Query query = std::move(freeQueries_.back());
    freeQueries_.pop_back();
    return query;
}

void GpuTimer::beginFrame() {
    if (current_) fail("GpuTimer::beginFrame called twice without endFrame (engine bug)");
    current_ = PendingFrame{frameCounter_++, {}};
}

void GpuTimer::beginPass(const std::string& name) {
    if (!current_) fail("GpuTimer::beginPass outside a frame (engine bug)");
    PendingPass pass{name, takeQuery(), takeQuery(), std::chrono::steady_clock::now(), 0.0};
    glQueryCounter(pass.start.id(), GL_TIMESTAMP);
    current_->passes.push_back(std::move(pass));
}

void GpuTimer::endPass() {
    PendingPass& pass = current_->passes.back();
    glQueryCounter(pass.end.id(), GL_TIMESTAMP);
    if (finishEachPass_) glFinish();
    pass.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - pass.cpuStart).count();
}

void GpuTimer::endFrame() {
    if (!current_) return;
    pending_.push_back(std::move(*current_));
    current_.reset();
    while (pending_.size() > kMaxPendingFrames) {
        for (auto& pass : pending_.front().passes) {
            freeQueries_.push_back(std::move(pass.start));
            freeQueries_.push_back(std::move(pass.end));
        }
        pending_.pop_front();
    }
}

bool GpuTimer::ready(const PendingFrame& frame) const {
    if (frame.passes.empty()) return true;
    GLint available = 0;
    glGetQueryObjectiv(frame.passes.back().end.id(), GL_QUERY_RESULT_AVAILABLE, &available);
    return available != 0;
}

FrameTimings GpuTimer::resolve(PendingFrame& frame) {
    FrameTimings timings;
    timings.frame = frame.frame;
    GLuint64 first = 0, last = 0;
    for (auto& pass : frame.passes) {
        GLuint64 start = 0, end = 0;
        glGetQueryObjectui64v(pass.start.id(), GL_QUERY_RESULT, &start);
        glGetQueryObjectui64v(pass.end.id(), GL_QUERY_RESULT, &end);
        if (timings.passes.empty()) first = start;
        last = end;
        timings.passes.push_back({pass.name, double(end - start) * 1e-6, pass.cpuMs});
        timings.totalCpuMs += pass.cpuMs;
        freeQueries_.push_back(std::move(pass.start));
        freeQueries_.push_back(std::move(pass.end));
    }
    timings.totalGpuMs = frame.passes.empty() ? 0.0 : double(last - first) * 1e-6;
    return timings;
}

std::optional<FrameTimings> GpuTimer::poll() {
    if (pending_.empty() || !ready(pending_.front())) return std::nullopt;
    FrameTimings timings = resolve(pending_.front());
    pending_.pop_front();
    return timings;
}

std::optional<FrameTimings> GpuTimer::waitForLatest() {
    if (pending_.empty()) return std::nullopt;
    FrameTimings timings = resolve(pending_.back());  // GL_QUERY_RESULT blocks until available
    pending_.pop_back();
    while (!pending_.empty()) {
        resolve(pending_.front());
        pending_.pop_front();
    }
    return timings;
}

}  // namespace vct::gl
