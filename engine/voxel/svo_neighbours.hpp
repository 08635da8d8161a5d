#pragma once
// svo_neighbours pass (DESIGN §4 pass 4): six face-neighbour links per node, level by level.
#include "voxel/octree.hpp"

namespace vct {

class SvoNeighbours {
public:
    SvoNeighbours();
    void run(Octree& octree);

private:
    gl::Program program_;
};

}  // namespace vct
