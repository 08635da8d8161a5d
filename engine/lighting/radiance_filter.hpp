#pragma once
// radiance_mip and radiance_border passes (DESIGN §4 passes 9–10) over the touched nodes only.
//   mip:    touched voxels → touched leaves → … → root (parents of touched nodes), and for each
//           touched node its partial radiance brick (bricks_leaf / bricks_mip, RADIANCE variant).
//   border: the nodes sharing a brick sample with a touched node (3³ neighbourhood, via the
//           neighbour links and the octree) get their complete samples, so borders agree.
// Both filter two channels through the same nodes: the radiance and the direction its reflected
// part leaves in (radiance_volume.hpp).
// DESIGN lists border before mip because the classic scheme completes leaf borders first; here
// parents filter the children's *partial* bricks (brick_layout.hpp), which needs no completed
// borders, so all levels are completed last in one pass each.
#include <array>
#include <vector>

#include "lighting/list_dispatch.hpp"
#include "lighting/radiance_volume.hpp"

namespace vct {

class RadianceFilter {
public:
    RadianceFilter();
    void mip(const Octree& octree, RadianceVolume& volume);
    void border(const Octree& octree, RadianceVolume& volume);

private:
    // One filtered quantity: per-cell values (read by the leaf pass at binding 18), per-node raw
    // means, partial bricks per level and the pool of complete samples.
    struct Channel {
        GLuint cells;
        GLuint raw;
        const std::vector<PartialBricks>& partial;
        GLuint pool;
        BrickCompletion& completion;
    };
    std::array<Channel, 2> channelsOf(const RadianceVolume& volume);

    gl::Program touchParents_, leaf_, parent_, touchBorder_;
    BrickCompletion completion_, directionCompletion_;
    ListDispatch listDispatch_;
};

}  // namespace vct
