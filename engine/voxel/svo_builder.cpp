#include "voxel/svo_builder.hpp"

#include <algorithm>
#include <cstdio>

#include "core/error.hpp"

namespace vct {

void SvoBuilder::build(const GpuScene& gpuScene, const Scene& scene, int levels, gl::GpuTimer& timer) {
    const VoxelGrid grid = makeVoxelGrid(scene, levels);
    float maxEmission = 0.0f;
    for (const Material& m : scene.materials)
        maxEmission = std::max({maxEmission, m.emissive.x, m.emissive.y, m.emissive.z});
    {
        gl::GpuTimer::Scope pass(timer, "voxelize");
        voxelizer_.run(gpuScene, scene, grid, fragments_);
    }
    {
        gl::GpuTimer::Scope pass(timer, "svo_build");
        build_.run(fragments_, grid, octree_);
    }
    {
        gl::GpuTimer::Scope pass(timer, "svo_leaves");
        leafStatistics_ = leaves_.run(fragments_, build_.fragmentNodeTexture(), maxEmission, octree_);
    }
    {
        gl::GpuTimer::Scope pass(timer, "svo_neighbours");
        neighbours_.run(octree_);
    }
    PartialBricks leafPartial;
    {
        gl::GpuTimer::Scope pass(timer, "bricks");
        leafPartial = bricks_.run(octree_);
    }
    {
        gl::GpuTimer::Scope pass(timer, "bricks_mip");
        bricksMip_.run(octree_, std::move(leafPartial));
    }
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
