#version 450
layout(local_size_x = 64) in;
// svo_build, step 4 of a level: every fragment moves to its node one level down, so the next
// level's flag pass does not walk down from the root again.
#include "voxel_common.glsl"
#include "octree.glsl"

layout(rgba32ui, binding = IMAGE_FRAGMENTS) uniform readonly uimageBuffer uFragments;
layout(r32ui, binding = IMAGE_FRAGMENT_NODE) uniform uimageBuffer uFragmentNode;

uniform uint uFragmentCount;

void main() {
    uint f = linearInvocation();
    if (f >= uFragmentCount) return;
    uvec3 cell = unpackCell(imageLoad(uFragments, int(f)).x);
    uint node = uLevel == 0 ? 0u : imageLoad(uFragmentNode, int(f)).x;
    imageStore(uFragmentNode, int(f), uvec4(childOf(node, childSlot(cell >> uint(uLevels - uLevel - 1)))));
}
