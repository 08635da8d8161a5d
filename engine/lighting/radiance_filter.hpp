#pragma once
// radiance_leaves and radiance_mip passes: the radiance bricks (brick_layout.hpp), only through the
// nodes beside light.
//   leaves: the touched nodes of every level (parents of touched nodes, up to the root), the
//           border nodes of every level (the 3³ neighbourhood of touched ones: every node whose
//           samples can be other than zero), then the bricks the last filtering lit that are not
//           on the border now (every other brick, the first time over new geometry bricks) as no
//           light over the geometry's density (shaders/border_age.comp, radiance_clear.comp),
//           and the leaf bricks of the border leaves from their voxels
//           (shaders/radiance_leaves.comp).
//   mip:    the directional bricks of every level above the leaves, bottom-up, over the border
//           nodes (shaders/radiance_mip.comp): each node computes the samples it owns, then
//           the others are copied from their owners (shaders/radiance_share.comp).
#include "lighting/list_dispatch.hpp"
#include "lighting/radiance_volume.hpp"

namespace vct {

class RadianceFilter {
public:
    RadianceFilter();
    void leaves(const Octree& octree, RadianceVolume& volume);
    void mip(const Octree& octree, RadianceVolume& volume);

private:
    // The samples the level's border nodes share with an owner that computed them
    // (shaders/shared_samples.glsl), copied from it (shaders/radiance_share.comp).
    void shareSamples(const Octree& octree, RadianceVolume& volume, int level);

    gl::Program ageBorder_, clear_, clearBorder_, touchParents_, touchBorder_, leaves_, mip_, share_;
    ListDispatch listDispatch_;
};

}  // namespace vct
