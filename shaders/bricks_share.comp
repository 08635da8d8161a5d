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
        ivec3 q = ivec3(s % 3, (s / 3) % 3, s / 9);
        ivec3 owner = sampleOwner(q, present);
        if (owner == ivec3(0)) continue;
        ivec3 source = brickOrigin(around[(owner.x + 1) + 3 * (owner.y + 1) + 9 * (owner.z + 1)]) + q - 2 * owner;
        imageStore(uOpacityPlus, origin + q, imageLoad(uOpacityPlus, source));
        imageStore(uOpacityMinus, origin + q, imageLoad(uOpacityMinus, source));
    }
}
