#pragma once
// Voxelize pass (DESIGN §4 pass 1): conservative geometry-shader voxelization of every triangle
// into the voxel-fragment list. The list never truncates silently: when more fragments arrive
// than fit, it grows to the exact count and the pass runs again (FragmentList::regrowths).
#include "render/gpu_scene.hpp"
#include "voxel/octree.hpp"

namespace vct {

class Voxelizer {
public:
    Voxelizer();
    // `expectedFragments` sizes the first attempt (see estimateFragments).
    void run(const GpuScene& gpuScene, const Scene& scene, const VoxelGrid& grid, FragmentList& list);

private:
    void allocate(FragmentList& list, std::uint32_t capacity) const;
    gl::Program program_;
    gl::Framebuffer framebuffer_;  // no attachments: the pass writes only to the fragment list
};

// A generous estimate of the fragment count: surface area in voxel-face units plus per-triangle
// overhead. Only sizes the first attempt.
std::uint64_t estimateFragments(const Scene& scene, const VoxelGrid& grid);

}  // namespace vct
