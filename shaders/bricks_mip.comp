#version 450
layout(local_size_x = 64) in;
// bricks_mip: partial bricks of one level from its children's partial bricks (brick_layout.hpp):
// P(Q) = Σ_children Σ_{d ∈ {−1,0,1}³, Q+d·h/2 in the child's closed cube} w(d) · P_child(Q + d·h/2),
// w = ¼ ½ ¼ per axis. In child-lattice units (spacing h/2) the parent sample Q is at 2Q and the
// child in slot s covers [2s, 2s+2] per axis. Also the raw value: the mean of the children's.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "work_list.glsl"

layout(rgba32f, binding = IMAGE_PARTIAL_BRICKS) uniform writeonly imageBuffer uPartial;        // this level
layout(rgba32f, binding = IMAGE_CHILD_PARTIAL_BRICKS) uniform readonly imageBuffer uChildPartial;    // level + 1
layout(std430, binding = SSBO_RAW_VALUE) buffer RawValue { vec4 rawValue[]; };


// Per axis, the child-lattice points p = 2Q + d (d = −1, 0, 1, inside [0, 4]) that parent sample
// Q ∈ {0, 1, 2} gathers: for each, the child slot s along the axis whose closed cube [2s, 2s + 2]
// holds it, the sample inside that child (p − 2s) and the weight w(d). p = 2 lies in both
// children: each holds its own partial value there. Entries of Q: kFirst[Q] … kFirst[Q + 1] − 1.
const int kFirst[4] = int[4](0, 2, 6, 8);
const int kSlot[8] = int[8](0, 0, 0, 0, 1, 1, 1, 1);
const int kLocal[8] = int[8](0, 1, 1, 2, 0, 1, 1, 2);
const float kWeight[8] = float[8](0.5, 0.25, 0.25, 0.5, 0.5, 0.25, 0.25, 0.5);

void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    uint i = node - uLevelStart[uLevel];
    // Children from the node's mask and first child (octree.glsl childOf), without an array:
    // indexing a local array at run time spills on llvmpipe.
    const uint mask = nodeMask[node];
    const uint firstChild = nodeChild[node];
    vec4 raw = vec4(0.0);
    for (uint slot = 0u; slot < 8u; ++slot)
        if ((mask & (1u << slot)) != 0u) raw += rawValue[firstChild + uint(bitCount(mask & ((1u << slot) - 1u)))];
    rawValue[node] = raw / 8.0;
    const int firstChildBrick = int(firstChild - uLevelStart[uLevel + 1]);
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int x = 0; x < 3; ++x) {
                vec4 sum = vec4(0.0);
                for (int ez = kFirst[k]; ez < kFirst[k + 1]; ++ez)
                    for (int ey = kFirst[j]; ey < kFirst[j + 1]; ++ey)
                        for (int ex = kFirst[x]; ex < kFirst[x + 1]; ++ex) {
                            const uint slot = uint(kSlot[ex] | (kSlot[ey] << 1) | (kSlot[ez] << 2));
                            if ((mask & (1u << slot)) == 0u) continue;
                            const int child = firstChildBrick + bitCount(mask & ((1u << slot) - 1u));
                            const ivec3 local = ivec3(kLocal[ex], kLocal[ey], kLocal[ez]);
                            sum += kWeight[ex] * kWeight[ey] * kWeight[ez] *
                                   imageLoad(uChildPartial, child * 27 + sampleIndex(local));
                        }
                imageStore(uPartial, int(i) * 27 + sampleIndex(ivec3(x, j, k)), sum);
            }
}
