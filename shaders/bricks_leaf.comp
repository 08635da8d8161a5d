#version 450
layout(local_size_x = 64) in;
// bricks, step 1: partial bricks of the leaf nodes from their cells (brick_layout.hpp):
// P(q) = 1/8 · Σ V(c) over the node's cells c whose closed cube contains q, V = (ρ·α, α).
// Also the node's raw value: the mean of V over its 8 cells.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "work_list.glsl"

layout(std430, binding = SSBO_CELL_VALUES) buffer CellAlbedo { uint cellAlbedo[]; };
layout(rgba32f, binding = IMAGE_PARTIAL_BRICKS) uniform writeonly imageBuffer uPartial;  // 27 per node of this level
layout(std430, binding = SSBO_RAW_VALUE) buffer RawValue { vec4 rawValue[]; };


void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    uint i = node - uLevelStart[uLevel];
    vec4 cells[8];
    vec4 raw = vec4(0.0);
    for (uint slot = 0u; slot < 8u; ++slot) {
        uint cell = childOf(node, slot);
        vec4 v = vec4(0.0);
        if (cell != NONE) {
            vec4 albedo = unpackUnorm4x8(cellAlbedo[cell - uLevelStart[uLevels]]);
            float tau = opticalDepth(albedo.a);
            v = vec4(albedo.rgb * tau, tau);
        }
        cells[slot] = v;
        raw += v;
    }
    rawValue[node] = raw / 8.0;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int x = 0; x < 3; ++x) {
                vec4 sum = vec4(0.0);
                // Cell s (s ∈ {0,1}³) spans [s, s+1]: it contains q when q − s ∈ {0, 1} per axis.
                for (uint slot = 0u; slot < 8u; ++slot) {
                    ivec3 s = ivec3(slot & 1u, (slot >> 1) & 1u, (slot >> 2) & 1u);
                    ivec3 d = ivec3(x, j, k) - s;
                    if (all(greaterThanEqual(d, ivec3(0))) && all(lessThanEqual(d, ivec3(1)))) sum += cells[slot];
                }
                imageStore(uPartial, int(i) * 27 + sampleIndex(ivec3(x, j, k)), sum / 8.0);
            }
}
