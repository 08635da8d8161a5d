#version 450
// Invocations per node's work group (node_group.glsl), before any use of gl_WorkGroupSize.
#ifndef NODE_GROUP_SIZE
#define NODE_GROUP_SIZE 64
#endif
layout(local_size_x = NODE_GROUP_SIZE) in;
// radiance_mip: the radiance of one level above the leaves, seen along each of the six axis
// directions (brick_layout.hpp, "Slabs"), for the nodes beside light (the border list). Along +a,
// a sample's slab is two child slabs long (at 2Q, then 2Q + 1 along a), composited front to back:
// what the first sends plus what the second sends through the first; across the slab the child
// slabs around 2Q are averaged ¼ ½ ¼ per axis. Radiance seen from the dark side of a wall is then
// what lies on that side, and light behind a pillar is hidden only behind it. Only the samples the
// node owns (shared_samples.glsl); radiance_share.comp copies the others.
// A work group takes one node (node_group.glsl): its invocations find the nodes and children
// around it, then where each of the 7³ child samples its bricks can read lies
// (each found once, not once per sample that reads it), then share the 27 samples × 6 directions.
#define WORK_LIST_BORDER
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "directional_pool.glsl"
#include "radiance_common.glsl"
#include "work_list.glsl"
#include "brick_gather.glsl"
#include "node_group.glsl"
#include "shared_samples.glsl"

layout(binding = TEXTURE_OPACITY_PLUS) uniform sampler3D uOpacityPlus;    // (τ+x, τ+y, τ+z, ·)
layout(binding = TEXTURE_OPACITY_MINUS) uniform sampler3D uOpacityMinus;  // (τ−x, τ−y, τ−z, ·)
layout(rgba32f, binding = IMAGE_DIRECTIONAL_RADIANCE) uniform coherent image3D uDirectional;

shared uint sChildren[64];
shared uint sPresent;
// Child-lattice point p ∈ [−1, 5]³ (index (p.x+1) + 7(p.y+1) + 49(p.z+1)): where its sample lies
// in the pool's +x bricks (the other directions' lie a fixed offset along z); w = 0 where no child
// holds one.
shared ivec4 sTexel[343];

int latticeIndex(ivec3 p) { return (p.x + 1) + 7 * (p.y + 1) + 49 * (p.z + 1); }

void main() {
    bool valid;
    uint node = groupWorkNode(valid);
    if (!valid) return;  // the whole group: the node is the group's
    uint t = gl_LocalInvocationIndex;
    findNodesAroundTogether(node);
    barrier();
    for (uint v = t; v < 64u; v += gl_WorkGroupSize.x) sChildren[v] = sharedChildAround(int(v));
    if (t == 0u) {  // bordersAround over the shared nodes
        uint present = 0u;
        for (int o = 0; o < 27; ++o)
            if (onBorderNow(sAround[o])) present |= 1u << uint(o);
        sPresent = present;
    }
    barrier();
    for (uint e = t; e < 343u; e += gl_WorkGroupSize.x) {
        ivec3 p = ivec3(e % 7u, (e / 7u) % 7u, e / 49u) - 1;
        ivec4 texel = ivec4(0);
        for (int k = 0; k < 8; ++k) {  // childSampleAt over the shared children
            ivec3 local;
            int v = childCandidate(p, k, local);
            if (v < 0 || sChildren[v] == NONE) continue;
            texel = ivec4(directionalBrickOrigin(sChildren[v], 0) + local, 1);
            break;
        }
        sTexel[e] = texel;
    }
    barrier();

    uint present = sPresent;
    float hChild = float(1 << (uLevels - uLevel - 2));  // the child level's sample spacing, voxels
    ivec3 origin = brickOrigin(node);
    const float w[3] = float[3](0.25, 0.5, 0.25);
    for (uint work = t; work < 27u * 6u; work += gl_WorkGroupSize.x) {
        ivec3 q = blockCoord3(int(work / 6u));
        if (sampleOwner(q, present) != ivec3(0)) continue;  // radiance_share.comp copies it
        int i = int(work % 6u), a = i >> 1;
        ivec3 direction = directionOffset(i);
        int ahead = (i & 1) == 0 ? aroundStride(a) : -aroundStride(a);
        vec3 total = vec3(0.0);
        float meanTransmittance = 0.0;
        for (int db = -1; db <= 1; ++db)
            for (int dc = -1; dc <= 1; ++dc) {
                int front = aroundAcross(a, db, dc);
                int back = front + ahead;
                ivec4 frontTexel = sTexel[latticeIndex(2 * q + blockCoord3(front) - 1)];
                ivec4 backTexel = sTexel[latticeIndex(2 * q + blockCoord3(back) - 1)];
                // The child slab at each: (L·τ, τ), the density of unlit geometry too
                // (radiance_clear.comp): it sends L·α and lets 1 − α through.
                vec4 frontStored = frontTexel.w != 0 ? imageLoad(uDirectional, frontTexel.xyz + direction) : vec4(0.0);
                vec4 backStored = backTexel.w != 0 ? imageLoad(uDirectional, backTexel.xyz + direction) : vec4(0.0);
                float frontAlpha = 1.0 - exp(-frontStored.a * hChild);
                float backAlpha = 1.0 - exp(-backStored.a * hChild);
                vec3 frontSeen = frontStored.a > 0.0 ? frontStored.rgb * (frontAlpha / frontStored.a) : vec3(0.0);
                vec3 backSeen = backStored.a > 0.0 ? backStored.rgb * (backAlpha / backStored.a) : vec3(0.0);
                float weight = w[db + 1] * w[dc + 1];
                total += weight * (frontSeen + (1.0 - frontAlpha) * backSeen);
                meanTransmittance += weight * (1.0 - frontAlpha) * (1.0 - backAlpha);
            }
        float tau = (i & 1) == 0 ? texelFetch(uOpacityPlus, origin + q, 0)[a] : texelFetch(uOpacityMinus, origin + q, 0)[a];
        imageStore(uDirectional, directionalBrickOrigin(node, i) + q, slabRadiance(total, 1.0 - meanTransmittance, tau, 2.0 * hChild));
    }
}
