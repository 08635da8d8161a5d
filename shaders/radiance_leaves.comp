#version 450
layout(local_size_x = 64) in;
// radiance_leaves: the leaf level's radiance, seen along each of the six axis directions, for the
// leaves beside light (the border list: the touched leaves and their 3³ neighbours; the rest keep
// what radiance_clear wrote: no light). Along ±a, a sample's slab (brick_layout.hpp, "Slabs";
// bricks_opacity.comp) holds halves of the 4 voxels ahead of it; what a cone there sees is the
// mean over them of the radiance that leaves each towards it times its opacity along a: the
// voxel's radiance L times the share of it that leaves against ±a (facing.glsl).
// Stored premultiplied by the slab's density (radiance_common.glsl, slabRadiance).
#define WORK_LIST_BORDER
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "directional_pool.glsl"
#include "radiance_common.glsl"
#include "work_list.glsl"
#include "brick_gather.glsl"
#include "facing.glsl"

layout(std430, binding = SSBO_CELL_OPACITY) buffer CellOpacity { uint cellOpacity[]; };  // RGBA8 (αx, αy, αz, α)
layout(binding = TEXTURE_OPACITY_PLUS) uniform sampler3D uOpacityPlus;
layout(binding = TEXTURE_OPACITY_MINUS) uniform sampler3D uOpacityMinus;
layout(rgba32f, binding = IMAGE_DIRECTIONAL_RADIANCE) uniform writeonly image3D uDirectional;

void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    uint children[64];
    gatherChildren(node, children);
    // The 4×4×4 voxels around the node (−1..2 per axis), each read once: its opacity along each
    // axis, its outgoing radiance and the shares of it that leave towards the six directions. (The
    // products, what each voxel sends each way through its opacity, would be 18 floats a voxel
    // instead of 12: on a CPU rasterizer that local array's traffic is what this pass waits on.)
    vec3 opacity[64], outgoing[64];
    float shares[64][6];
    for (int v = 0; v < 64; ++v) {
        opacity[v] = vec3(0.0);
        outgoing[v] = vec3(0.0);
        shares[v] = float[6](0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        if (children[v] == NONE) continue;
        uint index = children[v] - uLevelStart[uLevels];
        opacity[v] = min(unpackUnorm4x8(cellOpacity[index]).xyz, vec3(MAX_OPACITY));
        vec4 radiance = cellRadiance[index];
        if (radiance.a <= 0.0) continue;
        outgoing[v] = radiance.rgb / radiance.a;
        exitShares(index, shares[v]);
    }
    ivec3 origin = brickOrigin(node);
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int x = 0; x < 3; ++x) {
                ivec3 q = ivec3(x, j, k);
                vec4 tauPlus = texelFetch(uOpacityPlus, origin + q, 0), tauMinus = texelFetch(uOpacityMinus, origin + q, 0);
                for (int i = 0; i < 6; ++i) {
                    int a = i >> 1;
                    vec3 seen = vec3(0.0);
                    float transmittance = 0.0;
                    for (int column = 0; column < 4; ++column) {
                        int v = leafSlabVoxel(q, a, (i & 1) == 0, column);
                        seen += 0.25 * (opacity[v][a] * outgoing[v] * shares[v][i]);
                        transmittance += 0.25 * (1.0 - opacity[v][a]);
                    }
                    float tau = (i & 1) == 0 ? tauPlus[a] : tauMinus[a];
                    imageStore(uDirectional, directionalBrickOrigin(node, i) + q, slabRadiance(seen, 1.0 - transmittance, tau, 1.0));
                }
            }
}
