// The sparse voxel octree as the compute passes see it (engine/voxel/octree.hpp is the C++ side).
//
// Nodes live in one pool, level after level: level l occupies [uLevelStart[l], uLevelStart[l] +
// uLevelCount[l]). Level 0 is the root; level uLevels − 1 holds the leaf nodes (2³ cells each);
// level uLevels holds the occupied cells themselves. The children of a node are stored
// contiguously from nodeChild[n], only those that exist, in slot order; nodeMask[n] has bit
// s = x | y<<1 | z<<2 set for each existing child slot. No atomics decide where a node goes, so
// the pool is bit-identical from run to run.
const uint NONE = 0xFFFFFFFFu;

layout(std430, binding = SSBO_NODE_CHILD) buffer NodeChild { uint nodeChild[]; };
layout(std430, binding = SSBO_NODE_MASK) buffer NodeMask { uint nodeMask[]; };
layout(std430, binding = SSBO_NODE_COORD) buffer NodeCoord { uint nodeCoord[]; };    // packCell of the coordinate at its level
layout(std430, binding = SSBO_NODE_PARENT) buffer NodeParent { uint nodeParent[]; };
layout(std430, binding = SSBO_NODE_NEIGHBOUR) buffer NodeNeighbour { uint nodeNeighbour[]; };  // 6 per node: −x +x −y +y −z +z

uniform int uLevels;                    // L: cells are level L, leaves level L − 1
uniform int uLevel;                     // the level a per-level pass works on
uniform uint uLevelStart[MAX_OCTREE_LEVELS + 1];
uniform uint uLevelCount[MAX_OCTREE_LEVELS + 1];

// Child slot of a coordinate given at `level` (its lowest bit per axis).
uint childSlot(uvec3 coordAtLevel) { return (coordAtLevel.x & 1u) | ((coordAtLevel.y & 1u) << 1) | ((coordAtLevel.z & 1u) << 2); }

// The child of `node` in `slot`, or NONE.
uint childOf(uint node, uint slot) {
    uint mask = nodeMask[node];
    if ((mask & (1u << slot)) == 0u) return NONE;
    return nodeChild[node] + uint(bitCount(mask & ((1u << slot) - 1u)));
}

// The node at `level` whose coordinate is `coord` (in that level's units), or NONE.
uint findNode(uvec3 coord, int level) {
    uint node = 0u;
    for (int l = 1; l <= level && node != NONE; ++l) node = childOf(node, childSlot(coord >> uint(level - l)));
    return node;
}

// Linear index of this invocation for 1D work laid out over a 2D dispatch (x ≤ 65535 groups).
uint linearInvocation() {
    return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
}
// Linear index of this work group, for passes that give each item a whole group.
uint linearWorkGroup() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }
