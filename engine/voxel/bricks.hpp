#pragma once
// bricks pass (DESIGN §4 pass 5): a 3³ corner-centred brick per leaf node from its cells,
// complete across node borders (brick_layout.hpp), for the albedo pool and the opacity-by-axis
// pool.
#include "voxel/brick_pool.hpp"

namespace vct {

class Bricks {
public:
    Bricks();
    // Allocates the pools, fills the leaf level; returns the leaf partial bricks for bricks_mip.
    LeafPartials run(Octree& octree);

private:
    gl::Program albedoLeaf_, opacityLeaf_;
    BrickCompletion completion_;
};

}  // namespace vct
