#version 450
layout(local_size_x = 64) in;
// svo_build, step 2 of a level: the children of the level's nodes are allocated in node order.
// uPhase 0 writes each node's child count (popcount of its mask) into uCounts; the driver turns
// that into an exclusive prefix sum; uPhase 1 turns the prefix into the first-child index.
#include "octree.glsl"

layout(std430, binding = SSBO_CHILD_COUNTS) buffer Counts { uint counts[]; };
uniform int uPhase;

void main() {
    uint i = linearInvocation();
    if (i >= uLevelCount[uLevel]) return;
    uint node = uLevelStart[uLevel] + i;
    if (uPhase == 0) counts[i] = uint(bitCount(nodeMask[node]));
    else nodeChild[node] = uLevelStart[uLevel + 1] + counts[i];
}
