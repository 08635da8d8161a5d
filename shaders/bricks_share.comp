#version 450
layout(local_size_x = 64) in;
// bricks_mip, last step of a level's opacity: the brick samples a node shares with another that owns
// them (shared_samples.glsl) are copied from the owner's bricks, both opacity pools;
// bricks_opacity.comp wrote only the samples each node owns.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "brick_gather.glsl"
#include "shared_samples.glsl"

layout(rgba16f, binding = IMAGE_OPACITY_PLUS) uniform coherent image3D uOpacityPlus;
layout(rgba16f, binding = IMAGE_OPACITY_MINUS) uniform coherent image3D uOpacityMinus;

void main() {
    uint i = linearInvocation();
    if (i >= uLevelCount[uLevel]) return;
    uint node = uLevelStart[uLevel] + i;
    uint around[27];
    nodesAround(node, around);
    uint present = nodesPresent(around);
    ivec3 origin = brickOrigin(node);
    for (int s = 0; s < 27; ++s) {
        ivec3 q = blockCoord3(s);
        uint owner;
        ivec3 ownerSample;
        if (!sampleFromOwner(around, present, q, owner, ownerSample)) continue;
        ivec3 source = brickOrigin(owner) + ownerSample;
        imageStore(uOpacityPlus, origin + q, imageLoad(uOpacityPlus, source));
        imageStore(uOpacityMinus, origin + q, imageLoad(uOpacityMinus, source));
    }
}
