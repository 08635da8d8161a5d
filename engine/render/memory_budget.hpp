#pragma once
// GPU memory budget (docs/robustness.md, resource limits). vct can estimate, before allocating
// anything, what a frame of a scene at given settings will hold on the GPU; with a budget set
// (`--memory-budget MiB` or $VCT_MEMORY_BUDGET_MIB) a request over it fails early, naming what it
// needs and the largest setting that fits. Without a budget only the GL limits apply (checked
// where each pool is allocated) and GL_OUT_OF_MEMORY is reported by gl::checkErrors.
//
// The estimate is deliberately conservative (an upper bound in practice, tested against the pools
// the renderer reports): exact for the image targets and light-view maps; for the octree it uses
// the voxelizer's own first fragment-list size (estimateFragments) and, for occupied voxels,
// 1.3 × the surface area in voxel faces times |n|₁ (the layers a surface crosses), with interior
// nodes at 1/3 of the voxels (a surface fills about 4 of a leaf's 8 voxels).
#include <cstddef>
#include <optional>
#include <string>

#include "render/cone_trace.hpp"
#include "scene/scene.hpp"

namespace vct {

struct MemoryRequest {
    int width = 0, height = 0;
    int lightViewResolution = 0;
    int voxelLevels = 0;
    bool octree = true;    // GI or a voxel view
    bool radiance = true;  // GI or the radiance view
    bool bounces = false;  // further bounces (`--bounces` > 1): a copy of every voxel's first bounce
    int shadowMapResolution = 0;  // a depth map of its own per light-view map when above lightViewResolution
    GiResolution giResolution = GiResolution::Auto;  // which pixels trace cones (giBlockSize)
    int coneRays = kDefaultNarrowCones;  // narrow cones per traced pixel (0: the cone set), kept to share them
};

struct MemoryEstimate {
    std::size_t imageTargets = 0;  // G-buffer, direct, indirect, composite, voxel view
    std::size_t lightViewMaps = 0;
    std::size_t sceneData = 0;     // vertices, indices, textures with mipmaps
    std::size_t voxels = 0;        // fragment list, octree, bricks, radiance volume
    std::size_t total() const { return imageTargets + lightViewMaps + sceneData + voxels; }
};

MemoryEstimate estimateGpuMemory(const Scene& scene, const MemoryRequest& request);

// The budget in bytes: set by setMemoryBudgetMiB (the command line), else $VCT_MEMORY_BUDGET_MIB,
// else none. A value that is not a positive number is an error naming it.
std::optional<std::size_t> memoryBudget();
void setMemoryBudgetMiB(double mib);

// Throws vct::Error when a budget is set and the request's estimate exceeds it: the message gives
// the estimate by part, the budget, and the largest settings that fit, found by shrinking the
// largest part first (voxel levels by one, light-view maps by half, the image by 10 %).
void checkMemoryBudget(const Scene& scene, const MemoryRequest& request);

}  // namespace vct
