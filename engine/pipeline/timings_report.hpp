#pragma once
// The timing report of a rendered frame: a table for people (stdout) and JSON for tools.
// JSON schema (documented in README "Timings"):
//   { "backend": str, "renderer": str, "gl_version": str, "width": int, "height": int,
//     "frame": int,              index of the reported frame (earlier frames warm caches)
//     "passes": [ { "name": str, "gpu_ms": num, "cpu_ms": num } ],   in execution order
//     "total_gpu_ms": num,       GPU time from the first pass's start to the last pass's end
//     "total_cpu_ms": num,       sum of the passes' CPU submission times
//     "memory": [ { "name": str, "bytes": int } ], "memory_total_bytes": int,
//     "graph": [ { "name": str, "ran": bool, "reason": str } ],   every pass, ran or skipped, and why
//     "statistics": { "light_views_rendered": int, "light_views": int,
//                     "touched_nodes_per_level": [int], "nodes_per_level": [int], "photons_missed": int,
//                     "cone_samples": int, "cone_samples_saved_by_empty_space_skipping": int,
//                     "sky_pixels_without_gi_work": int },   (of the last frame that ran each pass)
//     "voxels": {              only when the frame built the octree
//        "levels": int, "fragments": int, "fragment_list_regrowths": int, "max_fragments_in_voxel": int,
//        "nodes_per_level": [int],  levels 0..L, the last = occupied voxels
//        "bytes": { "fragment_list", "node_pool", "neighbour_links", "voxel_values", "brick_pool",
//                   "dense_texture_equivalent" } } }
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
