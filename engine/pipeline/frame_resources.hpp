#pragma once
// Everything the passes of a frame read and write (the GPU objects behind the pass table's
// Resource values), owned by the Renderer and handed to each pass's `run` (frame_passes.cpp).
// Objects that a frame may not need are created by the first pass that writes them.
#include <memory>
#include <vector>

#include "lighting/bounce_gather.hpp"
#include "lighting/inject.hpp"
#include "lighting/radiance_filter.hpp"
#include "pipeline/frame_passes.hpp"
#include "pipeline/render_settings.hpp"
#include "render/composite.hpp"
#include "render/cone_trace.hpp"
#include "render/direct_lighting.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"
#include "render/light_view_cache.hpp"
#include "render/view.hpp"
#include "render/cone_view.hpp"
#include "render/voxel_view.hpp"
#include "scene/scene.hpp"
#include "voxel/svo_builder.hpp"

namespace vct {

// Work each pass did or saved in the last frame that ran it.
struct FrameStatistics {
    std::uint32_t lightViewsRendered = 0, lightViewsTotal = 0;  // only changed lights re-render
    std::vector<std::uint32_t> touchedNodesPerLevel;           // radiance filtered through these
    std::vector<std::uint32_t> nodesPerLevel;
    std::uint32_t photonsMissed = 0;
    std::uint32_t bouncesGathered = 0;                         // further bounces the bounce pass added
    std::uint32_t bounceOwnGathers = 0;  // voxels of the last bounce that could not share a sibling's gather
    ConeStatistics cones;
};

struct FrameResources {
    const Scene* scene = nullptr;
    RenderSettings settings;
    std::vector<Light> lights;
    InputVersions versions{};

    std::unique_ptr<GpuScene> gpuScene;                  // the scene's triangles, textures, materials
    std::unique_ptr<SvoBuilder> svo;                     // Fragments … GeometryBricks
    LightViewCache lightViews;                           // LightViewMaps
    std::unique_ptr<RadianceVolume> radiance;            // CellRadiance, RadiancePartials, RadianceBricks
    std::unique_ptr<PhotonInjection> injection;
    std::unique_ptr<RadianceFilter> radianceFilter;
    std::unique_ptr<BounceGather> bounces;               // BouncedRadiance
    std::unique_ptr<GBuffer> gbuffer;                    // GBuffer
    std::unique_ptr<DirectLighting> direct;              // DirectRadiance
    std::unique_ptr<ConeTrace> coneTrace;                // IndirectIrradiance
    std::unique_ptr<VoxelView> voxelView;                // DebugImage
    std::unique_ptr<ConeView> coneView;                  // DebugImage (--view cones)
    std::unique_ptr<Composite> composite;                // Output
    // Mutable: the cone counters are read back only when someone asks (Renderer::statistics), so
    // that a frame never waits for the cone pass to finish just to count its samples.
    mutable FrameStatistics statistics;
    mutable bool coneStatisticsPending = false;

    std::uint64_t version(Input input) const { return versions[std::size_t(input)]; }
};

// The camera of the frame being rendered; absent when only view-independent passes run.
struct FrameView {
    const Camera* camera = nullptr;
    ViewTransform transform;  // jittered inside the pixel for samples after the first
    int sample = 0;           // the pixel sample (render/pixel_samples.hpp)
    int samplesInAverage = 1; // the output averages this many samples, this frame's included
};

}  // namespace vct
