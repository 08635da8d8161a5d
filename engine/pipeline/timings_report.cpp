#include "pipeline/timings_report.hpp"

#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/image.hpp"

namespace vct {

std::string formatTimingsTable(const TimingsReport& report) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "%-18s %10s %10s\n", "pass", "gpu ms", "cpu ms");
    out += line;
    for (const auto& pass : report.timings.passes) {
        std::snprintf(line, sizeof line, "%-18s %10.3f %10.3f\n", pass.name.c_str(), pass.gpuMs, pass.cpuMs);
        out += line;
    }
    for (const PassRun& run : report.graph)
        if (!run.ran) {
            std::snprintf(line, sizeof line, "%-18s %21s   (%s)\n", run.name.c_str(), "skipped", run.reason.c_str());
            out += line;
        }
    std::snprintf(line, sizeof line, "%-18s %10.3f %10.3f   (%s, %dx%d)\n", "total", report.timings.totalGpuMs,
                  report.timings.totalCpuMs, report.context.renderer.c_str(), report.width, report.height);
    out += line;
    const SampleTimings& samples = report.samples;
    if (samples.count > 1) {  // the table above is the last sample's frame
        std::snprintf(line, sizeof line, "%-18s %10.3f %10.3f   (%d samples per pixel)\n", "all samples",
                      samples.totalGpuMs, samples.totalCpuMs, samples.count);
        out += line;
        std::snprintf(line, sizeof line, "%-18s %10.3f %10.3f\n", "each extra sample", samples.perSampleGpuMs(),
                      samples.perSampleCpuMs());
        out += line;
    }
    return out;
}

void writeTimingsJson(const std::filesystem::path& path, const TimingsReport& report) {
    ensureWritable(path);
    nlohmann::json json;
    json["backend"] = report.context.backend;
    json["renderer"] = report.context.renderer;
    json["gl_version"] = report.context.version;
    json["width"] = report.width;
    json["height"] = report.height;
    json["frame"] = report.timings.frame;
    json["passes"] = nlohmann::json::array();
    for (const auto& pass : report.timings.passes)
        json["passes"].push_back({{"name", pass.name}, {"gpu_ms", pass.gpuMs}, {"cpu_ms", pass.cpuMs}});
    json["total_gpu_ms"] = report.timings.totalGpuMs;
    json["total_cpu_ms"] = report.timings.totalCpuMs;
    std::size_t total = 0;
    json["memory"] = nlohmann::json::array();
    for (const auto& pool : report.memory) {
        json["memory"].push_back({{"name", pool.name}, {"bytes", pool.bytes}});
        total += pool.bytes;
    }
    json["memory_total_bytes"] = total;
    json["graph"] = nlohmann::json::array();
    for (const PassRun& run : report.graph)
        json["graph"].push_back({{"name", run.name},
                                 {"stage", stageName(declaration(run.pass).stage)},
                                 {"ran", run.ran},
                                 {"reason", run.reason}});
    const SampleTimings& samples = report.samples;
    json["samples"] = {{"count", samples.count},
                       {"first_gpu_ms", samples.firstGpuMs},
                       {"first_cpu_ms", samples.firstCpuMs},
                       {"per_sample_gpu_ms", samples.perSampleGpuMs()},
                       {"per_sample_cpu_ms", samples.perSampleCpuMs()},
                       {"total_gpu_ms", samples.totalGpuMs},
                       {"total_cpu_ms", samples.totalCpuMs}};
    const FrameStatistics& s = report.statistics;
    json["statistics"] = {{"light_views_rendered", s.lightViewsRendered},
                          {"light_views", s.lightViewsTotal},
                          {"touched_nodes_per_level", s.touchedNodesPerLevel},
                          {"nodes_per_level", s.nodesPerLevel},
                          {"photons_missed", s.photonsMissed},
                          {"bounces_gathered", s.bouncesGathered},
                          {"bounce_own_gathers", s.bounceOwnGathers},
                          {"cone_samples", s.cones.samples},
                          {"cone_samples_saved_by_empty_space_skipping", s.cones.samplesSaved},
                          {"sky_pixels_without_gi_work", s.cones.skyPixels},
                          {"cone_traced_pixels", s.cones.tracedPixels},
                          {"pixels_with_carried_indirect_light", s.cones.carriedPixels}};
    if (report.voxels) {
        const VoxelMemoryReport& v = *report.voxels;
        json["voxels"] = {{"levels", int(v.nodesPerLevel.size()) - 1},
                          {"fragments", v.fragments},
                          {"fragment_list_regrowths", v.fragmentListRegrowths},
                          {"max_fragments_in_voxel", v.maxFragmentsInCell},
                          {"nodes_per_level", v.nodesPerLevel},
                          {"bytes",
                           {{"fragment_list", v.fragmentList},
                            {"node_pool", v.nodePool},
                            {"neighbour_links", v.neighbourLinks},
                            {"voxel_values", v.cells},
                            {"brick_pool", v.brickPools},
                            {"dense_texture_equivalent", v.denseTexture}}}};
    }
    std::ofstream file(path);
    file << json.dump(2) << "\n";
    if (!file) fail("cannot write timings to '", path.string(), "'");
}

}  // namespace vct
