#version 450
layout(local_size_x = 64) in;
// radiance_leaves, first step: this filtering's border is still to be found, so every node's border
// flag turns from "on the border now" into "on the border before" (radiance_common.glsl);
// radiance_clear.comp then clears the bricks of those that do not come back.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "radiance_common.glsl"

uniform uint uNodeCount;

void main() {
    uint node = linearInvocation();
    if (node >= uNodeCount) return;
    borderFlag[node] = (borderFlag[node] & BORDER_NOW) != 0u ? BORDER_BEFORE : 0u;
}
