#pragma once
// bricks pass (DESIGN §4 pass 5): the leaf level's bricks from their cells, complete across node
// borders (brick_layout.hpp): albedo by the linear box filter (partial bricks, then completed),
// opacity by transmittance (shaders/bricks_opacity.comp, LEAF).
#include "voxel/brick_pool.hpp"

namespace vct {

class Bricks {
public:
    Bricks();
    // Allocates the pools, fills the leaf level; returns the leaf level's partial albedo bricks,
    // which bricks_mip filters up.
    PartialBricks run(Octree& octree);

private:
    gl::Program albedoLeaf_, opacityLeaf_;
    BrickCompletion completion_;
};

// Runs an opacity pass over every node of one level, with the cells and both opacity pools bound:
// bricks_opacity.comp (opacity by transmittance: the leaf level from the cells, a level above
// from the complete samples of the level below) or bricks_share.comp (the samples a node shares,
// copied from the node that computed them).
void runOpacityPass(const gl::Program& program, const Octree& octree, int level);

}  // namespace vct
