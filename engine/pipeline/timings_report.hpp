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

struct TimingsReport {
    gl::ContextInfo context;
    int width = 0;
    int height = 0;
    gl::FrameTimings timings;
    std::vector<MemoryPool> memory;
    std::optional<VoxelMemoryReport> voxels;
    std::vector<PassRun> graph;
    FrameStatistics statistics;
};

std::string formatTimingsTable(const TimingsReport& report);
void writeTimingsJson(const std::filesystem::path& path, const TimingsReport& report);

}  // namespace vct
