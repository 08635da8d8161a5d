#pragma once
// What a frame is asked to show and how: image size, shadow maps, octree resolution, GI and cone
// settings, the display transform and the debug views. Checked once, before any GPU work
// (validateRenderSettings), and against the context's limits when a Renderer takes them.
#include <string>

#include "core/image.hpp"

#include "render/composite.hpp"
#include "render/cone_trace.hpp"
#include "render/indirect_filter.hpp"

namespace vct {

enum class ViewMode { Lit, Voxels, Radiance, Cones };
ViewMode parseViewMode(const std::string& name);

struct RenderSettings {
    int width = 1280;
    int height = 720;
    int lightViewResolution = 0;     // texels per side of each light-view (photon) map; 0: photonMapResolution()
    // Texels per side of each shadow map (at least the photons'): the direct light's shadow edges.
    // 6144 is the smallest that brings 16 pixel samples of Sponza's direct light within 0.012 RMSE
    // of the path tracer; one sample stays filtered over its pixel (shadow.glsl), so a map finer
    // than the pixel does not alias (docs/benchmark.md). A point light's faces get half
    // (shadowMapSide in render/light_view.hpp).
    int shadowMapResolution = 6144;
    int pcfRadius = 1;               // shadow filter: (2r+1)² hardware-bilinear taps
    DisplaySettings display;
    ViewMode view = ViewMode::Lit;
    bool gi = true;          // indirect light by cone tracing
    bool photons = true;     // inject light (false: only emission and ambient occlusion)
    int bounces = 1;         // light bounces the indirect light holds (1..kMaxBounces)
    ConeSettings cones;
    GiResolution giResolution = GiResolution::Auto;  // cones at every pixel, or at one per 2×2 or 4×4 block
    float giFilter = kDefaultGiFilterVoxels;  // the cones' edge-aware filter, σ along surfaces in voxels; 0: off
    int voxelLevels = 8;     // octree resolution 2^voxelLevels
    int voxelViewLevel = 0;  // level shown by the voxel views; 0 = voxelLevels (the voxels)
    bool bricks = true;      // trilinear in the bricks (else nearest sample for cones, raw node values for voxel views)
    bool fullFrames = false;  // every pass every image (its sample 0), as if the geometry changed (benchmarks)

    bool operator==(const RenderSettings&) const = default;
};

// Throws a clear error for any setting out of its range. Needs no GL context.
void validateRenderSettings(const RenderSettings& settings);
// Throws when the settings exceed this context's limits (image or light-view map size).
void validateRenderSettingsForContext(const RenderSettings& settings);

// The photons' light-view map resolution: the one asked for, or by default (0) one that follows
// the voxels, four texels per voxel side (2^(levels + 2), within 256..4096): photons only need to
// cover every voxel face a few times (docs/benchmark.md "Photons sized to the voxels" measures
// what finer maps change), while shadow edges have their own map (shadowMapResolution).
int photonMapResolution(const RenderSettings& settings);

// What a frame with these settings needs (the pass table's skip reasons and the memory budget
// both ask here).
bool needsOctree(const RenderSettings& settings);    // GI or a voxel view
bool needsRadiance(const RenderSettings& settings);  // GI in the lit view, or the radiance or cone view

}  // namespace vct
