#version 450
layout(local_size_x = 1) in;
// Turns a list length counted on the GPU into dispatch arguments (groups of uItemsPerGroup items,
// x ≤ 65535), so passes over touched nodes run without reading the count back to the CPU.
layout(std430, binding = SSBO_LIST_COUNTS) buffer ListCounts { uint listCounts[]; };
layout(std430, binding = SSBO_INDIRECT_ARGS) buffer IndirectArgs { uint indirectArgs[]; };

uniform uint uCountSlot;
uniform uint uArgsSlot;
uniform uint uItemsPerGroup;

void main() {
    uint groups = (listCounts[uCountSlot] + uItemsPerGroup - 1u) / uItemsPerGroup;
    uint x = min(groups, 65535u);
    indirectArgs[uArgsSlot * 3u + 0u] = x;
    indirectArgs[uArgsSlot * 3u + 1u] = x == 0u ? 0u : (groups + x - 1u) / x;
    indirectArgs[uArgsSlot * 3u + 2u] = 1u;
}
