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


void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    uint i = node - uLevelStart[uLevel];
    uint children[8];
    vec4 raw = vec4(0.0);
    for (uint slot = 0u; slot < 8u; ++slot) {
        children[slot] = childOf(node, slot);
        if (children[slot] != NONE) raw += rawValue[children[slot]];
    }
    rawValue[node] = raw / 8.0;
    uint childLevelStart = uLevelStart[uLevel + 1];
    const float w[3] = float[3](0.25, 0.5, 0.25);
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int x = 0; x < 3; ++x) {
                vec4 sum = vec4(0.0);
                for (int dz = -1; dz <= 1; ++dz)
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            ivec3 p = 2 * ivec3(x, j, k) + ivec3(dx, dy, dz);  // child-lattice point
                            if (any(lessThan(p, ivec3(0))) || any(greaterThan(p, ivec3(4)))) continue;
                            float weight = w[dx + 1] * w[dy + 1] * w[dz + 1];
                            for (uint slot = 0u; slot < 8u; ++slot) {
                                if (children[slot] == NONE) continue;
                                ivec3 s = ivec3(slot & 1u, (slot >> 1) & 1u, (slot >> 2) & 1u);
                                ivec3 local = p - 2 * s;
                                if (any(lessThan(local, ivec3(0))) || any(greaterThan(local, ivec3(2)))) continue;
                                sum += weight * imageLoad(uChildPartial, int(children[slot] - childLevelStart) * 27 +
                                                                             sampleIndex(local));
                            }
                        }
                imageStore(uPartial, int(i) * 27 + sampleIndex(ivec3(x, j, k)), sum);
            }
}
