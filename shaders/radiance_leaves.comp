#version 450
// Invocations per node's work group (node_group.glsl), before any use of gl_WorkGroupSize.
#ifndef NODE_GROUP_SIZE
#define NODE_GROUP_SIZE 64
#endif
layout(local_size_x = NODE_GROUP_SIZE) in;
// radiance_leaves: the leaf level's radiance, seen along each of the six axis directions, for the
// leaves beside light (the border list: the touched leaves and their 3³ neighbours; the rest keep
// what radiance_clear wrote: no light). Along ±a, a sample's slab (brick_layout.hpp, "Slabs";
// bricks_opacity.comp) holds halves of the 4 voxels ahead of it; what a cone there sees is the
// mean over them of the radiance that leaves each towards it times its opacity along a: the
// voxel's radiance L times the share of it that leaves against ±a (facing.glsl).
// Stored premultiplied by the slab's density (radiance_common.glsl, slabRadiance).
// A work group takes one node (node_group.glsl): its invocations find the 27 nodes around it, then
// read the 4×4×4 voxels around it into shared memory, then share the node's 27 samples × 6
// directions. One invocation per node holding those voxels
// in its own arrays (3 KB) ran twice as long on a GPU, which keeps such arrays in slow memory.
#define WORK_LIST_BORDER
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "directional_pool.glsl"
#include "radiance_common.glsl"
#include "work_list.glsl"
#include "brick_gather.glsl"
#include "node_group.glsl"
#include "facing.glsl"

layout(std430, binding = SSBO_CELL_OPACITY) buffer CellOpacity { uint cellOpacity[]; };  // RGBA8 (αx, αy, αz, α)
layout(binding = TEXTURE_OPACITY_PLUS) uniform sampler3D uOpacityPlus;
layout(binding = TEXTURE_OPACITY_MINUS) uniform sampler3D uOpacityMinus;
layout(rgba32f, binding = IMAGE_DIRECTIONAL_RADIANCE) uniform writeonly image3D uDirectional;

shared vec3 sSent[64][6];      // what each voxel sends towards each direction through its opacity
shared float sClear[64][3];    // 1 − its opacity along each axis

void main() {
    bool valid;
    uint node = groupWorkNode(valid);
    if (!valid) return;  // the whole group: the node is the group's
    uint t = gl_LocalInvocationIndex;
    findNodesAroundTogether(node);
    barrier();

    // The 4×4×4 voxels around the node, in gatherChildren's order.
    for (uint v = t; v < 64u; v += gl_WorkGroupSize.x) {
        uint child = sharedChildAround(int(v));
        vec3 opacity = vec3(0.0), outgoing = vec3(0.0);
        float shares[6] = float[6](0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        if (child != NONE) {
            uint index = child - uLevelStart[uLevels];
            opacity = min(unpackUnorm4x8(cellOpacity[index]).xyz, vec3(MAX_OPACITY));
            vec4 radiance = cellRadiance[index];
            if (radiance.a > 0.0) {
                outgoing = radiance.rgb / radiance.a;
                exitShares(index, shares);
            }
        }
        for (int i = 0; i < 6; ++i) sSent[v][i] = opacity[i >> 1] * outgoing * shares[i];
        for (int a = 0; a < 3; ++a) sClear[v][a] = 1.0 - opacity[a];
    }
    barrier();

    ivec3 origin = brickOrigin(node);
    for (uint work = t; work < 27u * 6u; work += gl_WorkGroupSize.x) {
        ivec3 q = blockCoord3(int(work / 6u));
        int i = int(work % 6u), a = i >> 1;
        bool plus = (i & 1) == 0;
        vec3 seen = vec3(0.0);
        float transmittance = 0.0;
        for (int column = 0; column < 4; ++column) {
            int v = leafSlabVoxel(q, a, plus, column);
            seen += 0.25 * sSent[v][i];
            transmittance += 0.25 * sClear[v][a];
        }
        float tau = plus ? texelFetch(uOpacityPlus, origin + q, 0)[a] : texelFetch(uOpacityMinus, origin + q, 0)[a];
        imageStore(uDirectional, directionalBrickOrigin(node, i) + q, slabRadiance(seen, 1.0 - transmittance, tau, 1.0));
    }
}
