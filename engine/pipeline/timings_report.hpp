#pragma once
// The timing report of a rendered frame: a table for people (stdout) and JSON for tools.
// The JSON schema, every key with its type and meaning, is docs/timings.md; a test
// (Docs.TimingsSchemaMatchesWhatRenderWrites) checks it against what writeTimingsJson writes.
#include <filesystem>
#include <string>
#include <vector>

#include "gl/context.hpp"
#include "gl/gpu_timer.hpp"
#include <optional>

#include "pipeline/renderer.hpp"

namespace vct {

// The samples of an accumulated frame (`vct render --samples N`): the first is a whole frame,
// each further one re-runs only the passes that depend on the camera.
struct SampleTimings {
    int count = 0;
    double firstGpuMs = 0.0, firstCpuMs = 0.0;  // the first sample's frame
    double totalGpuMs = 0.0, totalCpuMs = 0.0;  // every sample's frame
    void add(const std::optional<gl::FrameTimings>& frame) {
        const double gpu = frame ? frame->totalGpuMs : 0.0, cpu = frame ? frame->totalCpuMs : 0.0;
        if (count == 0) firstGpuMs = gpu, firstCpuMs = cpu;
        totalGpuMs += gpu;
        totalCpuMs += cpu;
        ++count;
    }
    // Mean cost of one sample after the first (0 with a single sample).
    double perSampleGpuMs() const { return count > 1 ? (totalGpuMs - firstGpuMs) / (count - 1) : 0.0; }
    double perSampleCpuMs() const { return count > 1 ? (totalCpuMs - firstCpuMs) / (count - 1) : 0.0; }
};

struct TimingsReport {
    gl::ContextInfo context;
    int width = 0;
    int height = 0;
    gl::FrameTimings timings;
    std::vector<MemoryPool> memory;
    std::optional<VoxelMemoryReport> voxels;
    std::vector<PassRun> graph;
    FrameStatistics statistics;
    SampleTimings samples;
};

std::string formatTimingsTable(const TimingsReport& report);
void writeTimingsJson(const std::filesystem::path& path, const TimingsReport& report);

}  // namespace vct
