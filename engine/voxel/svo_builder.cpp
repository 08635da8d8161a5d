#include "voxel/svo_builder.hpp"

#include <algorithm>
#include <cstdio>

#include "core/error.hpp"

namespace vct {

void SvoBuilder::voxelize(const GpuScene& gpuScene, const Scene& scene, int levels) {
    grid_ = makeVoxelGrid(scene, levels);
    voxelizer_.run(gpuScene, scene, grid_, fragments_);
}

void SvoBuilder::buildStructure() { build_.run(fragments_, grid_, octree_); }

void SvoBuilder::leaves(const GpuScene& gpuScene) {
    leafStatistics_ = leaves_.run(fragments_, build_.fragmentNodeTexture(), gpuScene, octree_);
}

void SvoBuilder::neighbours() { neighbours_.run(octree_); }

void SvoBuilder::bricks() { leafAlbedo_ = bricks_.run(octree_); }

void SvoBuilder::bricksMip() {
    bricksMip_.run(octree_, std::move(leafAlbedo_));
    octree_.geometryBricksBuild = ++geometryBricksBuilds_;
}

VoxelMemoryReport SvoBuilder::memory() const {
    VoxelMemoryReport r;
    r.fragmentList = fragments_.bytes();
    r.fragments = fragments_.count;
    r.nodePool = octree_.nodePoolBytes();
    r.neighbourLinks = octree_.neighbourBytes();
    r.cells = octree_.cellBytes();
    r.brickPools = octree_.brickPoolBytes();
    r.denseTexture = octree_.denseTextureBytes();
    for (int l = 0; l <= octree_.levels; ++l) r.nodesPerLevel.push_back(octree_.levelCount[l]);
    r.maxFragmentsInCell = leafStatistics_.maxFragmentsInCell;
    r.fragmentListRegrowths = fragments_.regrowths;
    return r;
}

std::string formatVoxelMemory(const VoxelMemoryReport& r) {
    auto mib = [](std::size_t bytes) { return double(bytes) / 1048576.0; };
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "voxel fragments   %u (list %.2f MiB, grown %d times, max %u in one voxel)\n",
                  r.fragments, mib(r.fragmentList), r.fragmentListRegrowths, r.maxFragmentsInCell);
    out += line;
    out += "nodes per level  ";
    for (std::size_t l = 0; l < r.nodesPerLevel.size(); ++l) {
        std::snprintf(line, sizeof line, " %u", r.nodesPerLevel[l]);
        out += line;
    }
    out += "  (last: occupied voxels)\n";
    std::snprintf(line, sizeof line,
                  "octree memory     node pool %.2f MiB, neighbour links %.2f MiB, voxel values %.2f MiB, "
                  "brick pool %.2f MiB: total %.2f MiB (+ fragment list %.2f MiB while building)\n",
                  mib(r.nodePool), mib(r.neighbourLinks), mib(r.cells), mib(r.brickPools),
                  mib(r.nodePool + r.neighbourLinks + r.cells + r.brickPools), mib(r.fragmentList));
    out += line;
    std::snprintf(line, sizeof line, "dense equivalent  %.2f MiB (RGBA16F 3D texture with mips at the same resolution)\n",
                  mib(r.denseTexture));
    out += line;
    return out;
}

}  // namespace vct
