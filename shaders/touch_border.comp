#version 450
layout(local_size_x = 64) in;
// radiance_border, step 1 per level: every node that shares a brick sample with a touched node
// (its 3×3×3 neighbourhood) needs its complete samples recomputed; collect them once each.
#define WORK_LIST_TOUCHED
#include "voxel_common.glsl"
#include "octree.glsl"
#include "radiance_common.glsl"
#include "work_list.glsl"


void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    ivec3 coord = ivec3(unpackCell(nodeCoord[node]));
    int size = 1 << uLevel;
    for (int o = 0; o < 27; ++o) {
        ivec3 target = coord + blockCoord3(o) - 1;
        if (any(lessThan(target, ivec3(0))) || any(greaterThanEqual(target, ivec3(size)))) continue;
        uint other = o == 13 ? node : findNode(uvec3(target), uLevel);
        if (other == NONE) continue;
        if ((atomicOr(borderFlag[other], BORDER_NOW) & BORDER_NOW) == 0u) {
            uint slot = atomicAdd(listCounts[BORDER_COUNTS + uint(uLevel)], 1u);
            borderList[uLevelStart[uLevel] + slot] = other;
        }
    }
}
