#pragma once
// The sparse voxel octree of a scene and the objects of the six passes that build it (the pass
// table, engine/pipeline/frame_passes.cpp, runs them one by one and may re-run only some).
#include <string>
#include <vector>

#include "render/gpu_scene.hpp"
#include "voxel/bricks.hpp"
#include "voxel/bricks_mip.hpp"
#include "voxel/svo_build.hpp"
#include "voxel/svo_leaves.hpp"
#include "voxel/svo_neighbours.hpp"
#include "voxel/voxelize.hpp"

namespace vct {

struct VoxelMemoryReport {
    std::size_t fragmentList = 0, nodePool = 0, neighbourLinks = 0, cells = 0, brickPools = 0, denseTexture = 0;
    std::uint32_t fragments = 0;
    std::vector<std::uint32_t> nodesPerLevel;  // levels 0..L (L = occupied cells)
    std::uint32_t maxFragmentsInCell = 0;
    int fragmentListRegrowths = 0;
    std::size_t total() const { return fragmentList + nodePool + neighbourLinks + cells + brickPools; }
};

class SvoBuilder {
public:
    SvoBuilder() = default;

    void voxelize(const GpuScene& gpuScene, const Scene& scene, int levels);
    void buildStructure();
    void leaves(const GpuScene& gpuScene);
    void neighbours();
    void bricks();
    void bricksMip();

    const Octree& octree() const { return octree_; }
    const FragmentList& fragments() const { return fragments_; }
    GLuint fragmentNodeTexture() const { return build_.fragmentNodeTexture(); }
    VoxelMemoryReport memory() const;

private:
    Voxelizer voxelizer_;
    SvoBuild build_;
    SvoLeaves leaves_;
    SvoNeighbours neighbours_;
    Bricks bricks_;
    BricksMip bricksMip_;
    FragmentList fragments_;
    Octree octree_;
    LeafStatistics leafStatistics_;
    VoxelGrid grid_;
    PartialBricks leafAlbedo_;  // between the bricks and bricks_mip passes
    std::uint64_t geometryBricksBuilds_ = 0;  // Octree::geometryBricksBuild of the last one
};

std::string formatVoxelMemory(const VoxelMemoryReport& report);

}  // namespace vct
