#version 450
layout(local_size_x = 64) in;
// svo_build, step 1 of a level: every fragment marks the child slot of its node at this level.
// atomicOr is order-independent, so the masks are the same whatever the thread order.
#include "voxel_common.glsl"
#include "octree.glsl"

layout(rgba32ui, binding = IMAGE_FRAGMENTS) uniform readonly uimageBuffer uFragments;
layout(r32ui, binding = IMAGE_FRAGMENT_NODE) uniform uimageBuffer uFragmentNode;  // node of each fragment at this level

uniform uint uFragmentCount;

void main() {
    uint f = linearInvocation();
    if (f >= uFragmentCount) return;
    uvec3 cell = unpackCell(imageLoad(uFragments, int(f)).x);
    uint node = uLevel == 0 ? 0u : imageLoad(uFragmentNode, int(f)).x;
    uint slot = childSlot(cell >> uint(uLevels - uLevel - 1));
    atomicOr(nodeMask[node], 1u << slot);
}
