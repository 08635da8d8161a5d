#version 450
layout(local_size_x = 64) in;
// svo_neighbours: the six face neighbours of every node of one level (−x +x −y +y −z +z), or NONE.
// A neighbour is either a sibling (same parent) or a child of the parent's neighbour on that
// side, so levels are processed top-down and each lookup is O(1).
#include "voxel_common.glsl"
#include "octree.glsl"


void main() {
    uint i = linearInvocation();
    if (i >= uLevelCount[uLevel]) return;
    uint node = uLevelStart[uLevel] + i;
    ivec3 coord = ivec3(unpackCell(nodeCoord[node]));
    int size = 1 << uLevel;
    for (int direction = 0; direction < 6; ++direction) {
        int axis = direction >> 1;
        ivec3 target = coord;
        target[axis] += (direction & 1) == 0 ? -1 : 1;
        uint neighbour = NONE;
        if (uLevel > 0 && target[axis] >= 0 && target[axis] < size) {
            uint parent = nodeParent[node];
            uint parentSide = (target[axis] >> 1) == (coord[axis] >> 1) ? parent : nodeNeighbour[parent * 6u + uint(direction)];
            if (parentSide != NONE) neighbour = childOf(parentSide, childSlot(uvec3(target)));
        }
        nodeNeighbour[node * 6u + uint(direction)] = neighbour;
    }
}
