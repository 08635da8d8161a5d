#version 450
layout(local_size_x = 64) in;
// bricks / bricks_mip, opacity: the opacity of one level's brick samples, seen along each of the
// six axis directions (brick_layout.hpp, "Slabs"). The slab of sample Q along +a is the box that
// starts at Q and reaches one sample spacing h along +a, with the cross-section of the sample's
// lattice cell (h × h around Q): what a cone at Q travelling along +a crosses first. Along the
// slab the optical depths of what it crosses add up; across it the transmittances are averaged.
// A sample stores the effective density τ±a = −ln(mean transmittance) / h, into two pools:
// (τ+x, τ+y, τ+z, ·) and (τ−x, τ−y, τ−z, ·); the fourth channel is the mean of the three.
//   Variant LEAF (h = 1 voxel): the slab along ±a holds halves of the 4 voxels ahead of q; a
//   voxel's opacity along a is its surface's area projected along a (cellOpacity).
//   Otherwise: the slab is two child slabs long (at 2Q and 2Q ± 1 along a) and, across, the child
//   slabs around 2Q weighted ¼ ½ ¼ per axis; only the samples the node owns (shared_samples.glsl),
//   bricks_share.comp copies the others.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "brick_gather.glsl"
#include "shared_samples.glsl"

layout(std430, binding = SSBO_CELL_OPACITY) buffer CellOpacity { uint cellOpacity[]; };  // RGBA8 (αx, αy, αz, α)
layout(rgba16f, binding = IMAGE_OPACITY_PLUS) uniform coherent image3D uOpacityPlus;
layout(rgba16f, binding = IMAGE_OPACITY_MINUS) uniform coherent image3D uOpacityMinus;

void storeOpacity(ivec3 texel, vec3 transmittancePlus, vec3 transmittanceMinus, float length) {
    vec3 plus, minus;
    for (int a = 0; a < 3; ++a) {
        plus[a] = densityFromTransmittance(transmittancePlus[a], length);
        minus[a] = densityFromTransmittance(transmittanceMinus[a], length);
    }
    imageStore(uOpacityPlus, texel, vec4(plus, (plus.x + plus.y + plus.z) / 3.0));
    imageStore(uOpacityMinus, texel, vec4(minus, (minus.x + minus.y + minus.z) / 3.0));
}

void main() {
    uint i = linearInvocation();
    if (i >= uLevelCount[uLevel]) return;
    uint node = uLevelStart[uLevel] + i;
    uint around[27];
    nodesAround(node, around);
    uint children[64];
    childrenAround(around, children);
    uint present = nodesPresent(around);
    ivec3 origin = brickOrigin(node);
#ifdef LEAF
    // Each of the 64 cells' transmittance along the three axes, read once: the 27 samples' slabs
    // read 648 cells, about ten reads of each, and on llvmpipe a buffer read costs more than a
    // read of this array.
    vec3 clear[64];
    for (int v = 0; v < 64; ++v)
        clear[v] = children[v] == NONE ? vec3(1.0) : 1.0 - min(unpackUnorm4x8(cellOpacity[children[v] - uLevelStart[uLevels]]).xyz, vec3(MAX_OPACITY));
#endif
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int x = 0; x < 3; ++x) {
                ivec3 q = ivec3(x, j, k);
                vec3 transmittance[2] = vec3[2](vec3(0.0), vec3(0.0));  // along +a, along −a
#ifdef LEAF
                for (int a = 0; a < 3; ++a) {
                    for (int side = 0; side < 2; ++side)
                        for (int column = 0; column < 4; ++column)
                            transmittance[side][a] += 0.25 * clear[leafSlabVoxel(q, a, side == 0, column)][a];
                }
                storeOpacity(origin + q, transmittance[0], transmittance[1], 1.0);
#else
                if (sampleOwner(q, present) != ivec3(0)) continue;  // bricks_share.comp copies it
                float hChild = float(1 << (uLevels - uLevel - 2));  // the child level's sample spacing, voxels
                const float w[3] = float[3](0.25, 0.5, 0.25);
                // The child slabs' transmittance at the 27 child samples around 2Q, index (d + 1) · (1, 3, 9).
                vec3 plus[27], minus[27];
                for (int o = 0; o < 27; ++o) {
                    ivec3 d = blockCoord3(o) - 1;
                    uint child;
                    ivec3 local;
                    plus[o] = vec3(1.0);
                    minus[o] = vec3(1.0);
                    if (childSampleAt(children, 2 * q + d, child, local)) {
                        plus[o] = exp(-imageLoad(uOpacityPlus, brickOrigin(child) + local).xyz * hChild);
                        minus[o] = exp(-imageLoad(uOpacityMinus, brickOrigin(child) + local).xyz * hChild);
                    }
                }
                for (int a = 0; a < 3; ++a) {
                    for (int db = -1; db <= 1; ++db)
                        for (int dc = -1; dc <= 1; ++dc) {
                            int at = aroundAcross(a, db, dc);
                            int next = at + aroundStride(a);
                            int previous = at - aroundStride(a);
                            float weight = w[db + 1] * w[dc + 1];
                            transmittance[0][a] += weight * plus[at][a] * plus[next][a];
                            transmittance[1][a] += weight * minus[at][a] * minus[previous][a];
                        }
                }
                storeOpacity(origin + q, transmittance[0], transmittance[1], 2.0 * hChild);
#endif
            }
}
