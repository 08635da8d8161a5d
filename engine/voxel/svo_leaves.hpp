#pragma once
// svo_leaves pass (DESIGN §4 pass 3): fragment values → per-cell integer sums (atomicAdd,
// order-independent) → normalized cell values: albedo, opacity, normal, area, emission.
#include "render/gpu_scene.hpp"
#include "voxel/octree.hpp"

namespace vct {

struct LeafStatistics {
    std::uint32_t maxFragmentsInCell = 0;
};

class SvoLeaves {
public:
    SvoLeaves();
    // Material colours and emission come from gpuScene's material buffer, by the fragment's index.
    LeafStatistics run(const FragmentList& fragments, GLuint fragmentNodeTexture, const GpuScene& gpuScene,
                       Octree& octree);

private:
    gl::Program accumulate_, normalize_;
    // The integer sums and the overflow status, kept from build to build (gl::fitBuffer).
    gl::Buffer accumulators_, projected_, status_;
};

}  // namespace vct
