#version 450
layout(local_size_x = 64) in;
// radiance_mip: the radiance of one level above the leaves, seen along each of the six axis
// directions (brick_layout.hpp, "Slabs"), for the nodes beside light (the border list). Along +a,
// a sample's slab is two child slabs long (at 2Q, then 2Q + 1 along a), composited front to back:
// what the first sends plus what the second sends through the first; across the slab the child
// slabs around 2Q are averaged ¼ ½ ¼ per axis. Radiance seen from the dark side of a wall is then
// what lies on that side, and light behind a pillar is hidden only behind it.
#define WORK_LIST_BORDER
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "radiance_common.glsl"
#include "work_list.glsl"
#include "brick_gather.glsl"

layout(binding = TEXTURE_OPACITY_PLUS) uniform sampler3D uOpacityPlus;    // (τ+x, τ+y, τ+z, ·)
layout(binding = TEXTURE_OPACITY_MINUS) uniform sampler3D uOpacityMinus;  // (τ−x, τ−y, τ−z, ·)
layout(rgba32f, binding = IMAGE_DIRECTIONAL_RADIANCE) uniform coherent image3D uDirectional[6];

void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    uint children[64];
    gatherChildren(node, children);
    float hChild = float(1 << (uLevels - uLevel - 2));  // the child level's sample spacing, voxels
    ivec3 origin = brickOrigin(node);
    const float w[3] = float[3](0.25, 0.5, 0.25);
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int x = 0; x < 3; ++x) {
                ivec3 q = ivec3(x, j, k);
                // The child slabs at the 27 child samples around 2Q, index (d + 1) · (1, 3, 9): for
                // each direction, the radiance that reaches the slab's front (seen) and its transmittance.
                vec3 seen[27][6];
                float transmittance[27][6];
                for (int o = 0; o < 27; ++o) {
                    uint child;
                    ivec3 local;
                    bool found = childSampleAt(children, 2 * q + ivec3(o % 3, (o / 3) % 3, o / 9) - 1, child, local);
                    ivec3 texel = brickOrigin(child) + local;
                    for (int i = 0; i < 6; ++i) {
                        // (L·τ, τ), the density of unlit geometry too (radiance_clear.comp): the slab
                        // sends L·α.
                        vec4 stored = found ? imageLoad(uDirectional[i], texel) : vec4(0.0);
                        float alpha = 1.0 - exp(-stored.a * hChild);
                        transmittance[o][i] = 1.0 - alpha;
                        seen[o][i] = stored.a > 0.0 ? stored.rgb * (alpha / stored.a) : vec3(0.0);
                    }
                }
                vec4 tauPlus = texelFetch(uOpacityPlus, origin + q, 0), tauMinus = texelFetch(uOpacityMinus, origin + q, 0);
                for (int i = 0; i < 6; ++i) {
                    int a = i >> 1;
                    int ahead = (i & 1) == 0 ? aroundStride(a) : -aroundStride(a);
                    vec3 total = vec3(0.0);
                    float meanTransmittance = 0.0;
                    for (int db = -1; db <= 1; ++db)
                        for (int dc = -1; dc <= 1; ++dc) {
                            int front = aroundAcross(a, db, dc);
                            int back = front + ahead;
                            float weight = w[db + 1] * w[dc + 1];
                            total += weight * (seen[front][i] + transmittance[front][i] * seen[back][i]);
                            meanTransmittance += weight * transmittance[front][i] * transmittance[back][i];
                        }
                    float tau = (i & 1) == 0 ? tauPlus[a] : tauMinus[a];
                    imageStore(uDirectional[i], origin + q, slabRadiance(total, 1.0 - meanTransmittance, tau, 2.0 * hChild));
                }
            }
}
