#pragma once
// Running the benchmark: the engine at every sweep point and the path tracer at every spp of its
// curve, each measured for time and for error against the cached reference (reference_cache.hpp).
//
// Engine timing protocol, per point, on one Renderer (so shaders, scene upload and context are
// warm): starting from the default point,
//   1. setSettings(point) and render: the "update" frame, only the passes that depend on the
//      change (engine/pipeline/pass_graph.hpp); its image is the one measured;
//   2. the Direct AOV of the same state (composite only), for the indirect part = final − direct;
//   3. `repeats` warm full frames (RenderSettings::fullFrames: every pass, octree included), the
//      fastest counts (the machine is shared): frame_ms. Their image must equal step 1's;
//   4. `repeats` static-geometry frames: lights and camera nudged (by 10⁻⁴) every frame, so every
//      pass but the octree's runs (light_view … composite), the fastest counts: frame_static_ms,
//      what a frame costs when lights and camera move over static geometry;
//   5. back to the default point.
// A frame's cost is max(GPU span, Σ pass CPU ms): on llvmpipe compute dispatches run on the CPU
// at submission, so the GPU timestamps miss them (benchmarks/incremental.sh does the same). A
// pass's cost (the per-pass columns) is max(its GPU ms, its CPU ms); passes overlap a little, so
// these may sum to slightly more than the frame.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench/reference_cache.hpp"
#include "bench/sweep.hpp"
#include "metrics/image_metrics.hpp"
#include "metrics/region_ratio.hpp"
#include "pipeline/renderer.hpp"

namespace vct::bench {

struct ErrorMetrics {
    double rmse = 0.0, relMse = 0.0, psnr = 0.0, ssim = 0.0;  // full image
    double directRmse = 0.0;                                  // direct part against the direct reference
    double indirectRmse = 0.0, indirectRelMse = 0.0;          // indirect part alone
    double indirectRatio = 0.0;  // mean luminance of the indirect part / the reference's
};

// The default point's indirect part is also compared per region, on a grid of this many cells per
// side (metrics/region_ratio.hpp): where the engine's indirect light is too dark or too bright.
inline constexpr int kIndirectRegionGrid = 3;

struct PassCost {
    std::string name;
    double gpuMs = 0.0, cpuMs = 0.0;
    double ms() const { return gpuMs > cpuMs ? gpuMs : cpuMs; }
};

struct BenchRow {
    std::string kind;  // "engine" or "pathtracer"
    std::string label, parameter, value;
    bool isDefault = false;
    PointSettings settings;    // engine rows
    int spp = 0;               // path-tracer rows
    double frameMs = 0.0;      // engine: fastest warm full frame; path tracer: fastest render (BVH excluded)
    double frameStaticMs = 0.0;  // engine: fastest static-geometry frame; path tracer: = frameMs
    std::vector<double> frameSamplesMs;  // every timed repeat
    double updateMs = 0.0;     // engine: the frame after setSettings from the default point
    std::string updatePasses;  // the passes it ran, ';'-separated
    double setupMs = 0.0;      // path tracer: textures and BVH
    std::vector<PassCost> passes;  // engine: of the fastest full frame
    std::size_t memoryBytes = 0;   // engine: GPU pools the point uses
    std::uint64_t coneSamples = 0;
    ErrorMetrics error;
    // Engine default point only: mean luminance of the indirect part per region / the reference's.
    std::optional<metrics::RegionRatios> indirectRegions;
    bool pareto = false;
    bool incrementalIdentical = true;  // engine: step 1's image equals the full frame's
};

// Errors of an image split into direct and indirect parts against the reference.
ErrorMetrics measureErrors(const ImageF& final, const ImageF& direct, const ImageF& indirect,
                           const ReferenceImages& reference, const metrics::DisplaySettings& display);

using Progress = std::function<void(const BenchRow&, std::size_t index, std::size_t count)>;

// The path tracer at each spp of the sweep's curve (seed: the curve's), `threads` as `vct
// reference --threads`; each rendered `sweep.repeats` times, the fastest counts (as the engine's).
std::vector<BenchRow> runPathTracerCurve(const Scene& scene, const Camera& camera, const SweepDefinition& sweep,
                                         const ReferenceImages& reference, const metrics::DisplaySettings& display,
                                         int threads, const Progress& progress = {});

// The reference a point's images are measured against: the path-traced image with as many bounces
// as the point renders (a `bounces` sweep compares each count with its own ground truth).
using ReferenceForBounces = std::function<const ReferenceImages&(int bounces)>;

// Every point (their settings complete: size and display included) on a GL context current on
// this thread.
std::vector<BenchRow> runEnginePoints(const Scene& scene, const Camera& camera, const std::vector<SweepPoint>& points,
                                      int repeats, const ReferenceForBounces& reference,
                                      const metrics::DisplaySettings& display, const Progress& progress = {});

}  // namespace vct::bench
