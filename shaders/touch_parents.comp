#version 450
layout(local_size_x = 64) in;
// radiance_mip, step 1 per level: the parents of the touched nodes of level uLevel + 1 are
// touched at level uLevel, so filtering goes up the tree only where light arrived.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "radiance_common.glsl"


void main() {
    uint i = linearInvocation();
    if (i >= listCounts[uLevel + 1]) return;
    touch(nodeParent[touchedList[uLevelStart[uLevel + 1] + i]], uLevel);
}
