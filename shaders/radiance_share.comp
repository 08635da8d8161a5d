#version 450
layout(local_size_x = 64) in;
// radiance_mip, last step of a level: the brick samples a border node shares with another that owns
// them (shared_samples.glsl) are copied from the owner's bricks, all six directions; the filter
// itself wrote only the samples each node owns.
#define WORK_LIST_BORDER
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "directional_pool.glsl"
#include "radiance_common.glsl"
#include "work_list.glsl"
#include "brick_gather.glsl"
#include "shared_samples.glsl"

layout(rgba32f, binding = IMAGE_DIRECTIONAL_RADIANCE) uniform coherent image3D uDirectional;

void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    uint around[27];
    nodesAround(node, around);
    uint present = bordersAround(around);
    ivec3 origin = directionalBrickOrigin(node, 0);
    for (int s = 0; s < 27; ++s) {
        ivec3 q = blockCoord3(s);
        uint owner;
        ivec3 ownerSample;
        if (!sampleFromOwner(around, present, q, owner, ownerSample)) continue;
        ivec3 source = directionalBrickOrigin(owner, 0) + ownerSample;
        for (int i = 0; i < 6; ++i)
            imageStore(uDirectional, origin + q + directionOffset(i), imageLoad(uDirectional, source + directionOffset(i)));
    }
}
