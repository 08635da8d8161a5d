#version 450
// Exclusive prefix sum of uint values, one block of 256 per work group (Hillis–Steele in shared
// memory). uPhase 0 scans blocks in place and writes each block's total to uBlockSums; uPhase 1
// adds the scanned block sums back. The driver recurses on the block sums.
layout(local_size_x = 256) in;

layout(std430, binding = SSBO_PREFIX_VALUES) buffer Values { uint values[]; };
layout(std430, binding = SSBO_PREFIX_BLOCK_SUMS) buffer BlockSums { uint blockSums[]; };

uniform uint uCount;
uniform int uPhase;

shared uint scratch[256];

uint linearInvocation() {
    return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
}

void main() {
    uint i = linearInvocation();
    uint block = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (uPhase == 1) {
        if (i < uCount) values[i] += blockSums[block];
        return;
    }
    uint lane = gl_LocalInvocationID.x;
    uint value = i < uCount ? values[i] : 0u;
    scratch[lane] = value;
    barrier();
    for (uint offset = 1u; offset < 256u; offset <<= 1) {
        uint add = lane >= offset ? scratch[lane - offset] : 0u;
        barrier();
        scratch[lane] += add;
        barrier();
    }
    if (i < uCount) values[i] = scratch[lane] - value;  // inclusive → exclusive
    if (lane == 255u) blockSums[block] = scratch[255];
}
