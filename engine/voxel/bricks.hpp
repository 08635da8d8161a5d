#pragma once
// bricks pass (DESIGN §4 pass 5): a 3³ corner-centred brick per leaf node from its cells,
// complete across node borders (brick_layout.hpp).
#include "voxel/brick_pool.hpp"

namespace vct {

class Bricks {
public:
    Bricks();
    // Allocates the pool, fills the leaf level; returns the leaf partial bricks for bricks_mip.
    PartialBricks run(Octree& octree);

private:
    gl::Program leaf_;
    BrickCompletion completion_;
};

}  // namespace vct
