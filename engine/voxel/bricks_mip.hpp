#pragma once
// bricks_mip pass (DESIGN §4 pass 6): the bricks of every coarser level, bottom-up: albedo by the
// ¼ ½ ¼ tent over the children's partial bricks, then completed across node borders; opacity by
// transmittance over the level below (brick_layout.hpp), each shared sample computed once and
// copied into the other bricks that hold it (shaders/shared_samples.glsl).
#include "voxel/brick_pool.hpp"

namespace vct {

class BricksMip {
public:
    BricksMip();
    void run(const Octree& octree, PartialBricks leafAlbedo);

private:
    gl::Program albedo_, opacity_, share_;
    BrickCompletion completion_;
};

}  // namespace vct
