#version 450
layout(local_size_x = 64) in;
// svo_build, step 3 of a level: each node initialises its new children (coordinate, parent,
// empty mask). One thread per parent, so every child is written by exactly one thread.
#include "voxel_common.glsl"
#include "octree.glsl"


void main() {
    uint i = linearInvocation();
    if (i >= uLevelCount[uLevel]) return;
    uint node = uLevelStart[uLevel] + i;
    uint mask = nodeMask[node];
    uvec3 coord = unpackCell(nodeCoord[node]);
    uint child = nodeChild[node];
    for (uint slot = 0u; slot < 8u; ++slot) {
        if ((mask & (1u << slot)) == 0u) continue;
        uvec3 offset = uvec3(slot & 1u, (slot >> 1) & 1u, (slot >> 2) & 1u);
        nodeCoord[child] = packCell(coord * 2u + offset);
        nodeParent[child] = node;
        nodeMask[child] = 0u;
        nodeChild[child] = NONE;
        ++child;
    }
}
