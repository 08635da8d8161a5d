#version 450
layout(local_size_x = 64) in;
// radiance_mip: the radiance of one level above the leaves, seen along each of the six axis
// directions (brick_layout.hpp, "Slabs"), for the nodes beside light (the border list). Along +a,
// a sample's slab is two child slabs long (at 2Q, then 2Q + 1 along a), composited front to back:
// what the first sends plus what the second sends through the first; across the slab the child
// slabs around 2Q are averaged ¼ ½ ¼ per axis. Radiance seen from the dark side of a wall is then
// what lies on that side, and light behind a pillar is hidden only behind it. Only the samples the
// node owns (shared_samples.glsl); radiance_share.comp copies the others.
#define WORK_LIST_BORDER
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "directional_pool.glsl"
#include "radiance_common.glsl"
#include "work_list.glsl"
#include "brick_gather.glsl"
#include "shared_samples.glsl"

layout(binding = TEXTURE_OPACITY_PLUS) uniform sampler3D uOpacityPlus;    // (τ+x, τ+y, τ+z, ·)
layout(binding = TEXTURE_OPACITY_MINUS) uniform sampler3D uOpacityMinus;  // (τ−x, τ−y, τ−z, ·)
layout(rgba32f, binding = IMAGE_DIRECTIONAL_RADIANCE) uniform coherent image3D uDirectional;

void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    uint around[27];
    nodesAround(node, around);
    uint children[64];
    childrenAround(around, children);
    uint present = bordersAround(around);
    float hChild = float(1 << (uLevels - uLevel - 2));  // the child level's sample spacing, voxels
    ivec3 origin = brickOrigin(node);
    const float w[3] = float[3](0.25, 0.5, 0.25);
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int x = 0; x < 3; ++x) {
                ivec3 q = ivec3(x, j, k);
                if (sampleOwner(q, present) != ivec3(0)) continue;  // radiance_share.comp copies it
                // Where the 27 child samples around 2Q lie in the pool's +x bricks (the other
                // directions' lie a fixed offset along z), index (d + 1) · (1, 3, 9); w = 0 where no
                // child holds one. Only their places are kept (not the six directions' values,
                // which are read as each direction needs them): a small array, since run-time-indexed
                // local arrays are slow on some drivers (llvmpipe spills them).
                ivec4 texels[27];
                for (int o = 0; o < 27; ++o) {
                    uint child;
                    ivec3 local;
                    bool found = childSampleAt(children, 2 * q + blockCoord3(o) - 1, child, local);
                    texels[o] = ivec4(found ? directionalBrickOrigin(child, 0) + local : ivec3(0), found ? 1 : 0);
                }
                vec4 tauPlus = texelFetch(uOpacityPlus, origin + q, 0), tauMinus = texelFetch(uOpacityMinus, origin + q, 0);
                for (int i = 0; i < 6; ++i) {
                    int a = i >> 1;
                    ivec3 direction = directionOffset(i);
                    int ahead = (i & 1) == 0 ? aroundStride(a) : -aroundStride(a);
                    vec3 total = vec3(0.0);
                    float meanTransmittance = 0.0;
                    for (int db = -1; db <= 1; ++db)
                        for (int dc = -1; dc <= 1; ++dc) {
                            int front = aroundAcross(a, db, dc);
                            int back = front + ahead;
                            // The child slab at each: (L·τ, τ), the density of unlit geometry too
                            // (radiance_clear.comp): it sends L·α and lets 1 − α through.
                            vec4 frontStored = texels[front].w != 0 ? imageLoad(uDirectional, texels[front].xyz + direction) : vec4(0.0);
                            vec4 backStored = texels[back].w != 0 ? imageLoad(uDirectional, texels[back].xyz + direction) : vec4(0.0);
                            float frontAlpha = 1.0 - exp(-frontStored.a * hChild);
                            float backAlpha = 1.0 - exp(-backStored.a * hChild);
                            vec3 frontSeen = frontStored.a > 0.0 ? frontStored.rgb * (frontAlpha / frontStored.a) : vec3(0.0);
                            vec3 backSeen = backStored.a > 0.0 ? backStored.rgb * (backAlpha / backStored.a) : vec3(0.0);
                            float weight = w[db + 1] * w[dc + 1];
                            total += weight * (frontSeen + (1.0 - frontAlpha) * backSeen);
                            meanTransmittance += weight * (1.0 - frontAlpha) * (1.0 - backAlpha);
                        }
                    float tau = (i & 1) == 0 ? tauPlus[a] : tauMinus[a];
                    imageStore(uDirectional, directionalBrickOrigin(node, i) + q, slabRadiance(total, 1.0 - meanTransmittance, tau, 2.0 * hChild));
                }
            }
}
