#pragma once
// bricks_mip pass (DESIGN §4 pass 6): bricks of every coarser level, bottom-up, by the ¼ ½ ¼
// tent over the children's partial bricks, then completed across node borders.
#include "voxel/brick_pool.hpp"

namespace vct {

class BricksMip {
public:
    BricksMip();
    void run(const Octree& octree, LeafPartials leafPartials);

private:
    gl::Program program_;
    BrickCompletion completion_;
};

}  // namespace vct
