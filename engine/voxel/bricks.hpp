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

// Opacity bricks of one level by transmittance (shaders/bricks_opacity.comp): the leaf level
// from the cells, a level above from the complete samples of the level below.
void filterOpacity(const gl::Program& program, const Octree& octree, int level);

}  // namespace vct
