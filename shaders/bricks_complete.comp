#version 450
layout(local_size_x = 64) in;
// bricks / bricks_mip, last step of a level: complete samples S(q) = Σ of the partials of every
// node of the level whose closed cube contains q, written into the 3D brick pool. The nodes are
// visited in a canonical order (offset −1 before 0 before +1, z then y then x), so every node that
// shares q sums the same numbers in the same order and stores the bit-identical value.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "work_list.glsl"

layout(rgba32f, binding = IMAGE_PARTIAL_BRICKS) uniform readonly imageBuffer uPartial;
layout(rgba16f, binding = IMAGE_BRICK_POOL) uniform writeonly image3D uBrickPool;  // the albedo pool (ρ·τ ≤ 6.9)


void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    ivec3 coord = ivec3(unpackCell(nodeCoord[node]));
    int size = 1 << uLevel;
    // The 3×3×3 block of same-level nodes around this one (index (o + 1) · (1, 3, 9)).
    uint around[27];
    for (int o = 0; o < 27; ++o) {
        ivec3 offset = blockCoord3(o) - 1;
        ivec3 target = coord + offset;
        uint found = NONE;
        if (offset == ivec3(0)) found = node;
        else if (all(greaterThanEqual(target, ivec3(0))) && all(lessThan(target, ivec3(size)))) {
            int nonZero = int(offset.x != 0) + int(offset.y != 0) + int(offset.z != 0);
            if (nonZero == 1) {  // a face neighbour: the neighbour links have it
                int axis = offset.x != 0 ? 0 : (offset.y != 0 ? 1 : 2);
                found = nodeNeighbour[node * 6u + uint(axis * 2 + (offset[axis] > 0 ? 1 : 0))];
            } else {
                found = findNode(uvec3(target), uLevel);
            }
        }
        around[o] = found;
    }
    ivec3 origin = brickOrigin(node);
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int x = 0; x < 3; ++x) {
                ivec3 q = ivec3(x, j, k);
                // Per axis, the nodes containing q: offset −1 and 0 when q = 0, 0 when q = 1, 0 and +1 when q = 2.
                ivec3 lo = ivec3(q.x == 0 ? -1 : 0, q.y == 0 ? -1 : 0, q.z == 0 ? -1 : 0);
                ivec3 hi = ivec3(q.x == 2 ? 1 : 0, q.y == 2 ? 1 : 0, q.z == 2 ? 1 : 0);
                vec4 sum = vec4(0.0);
                for (int oz = lo.z; oz <= hi.z; ++oz)
                    for (int oy = lo.y; oy <= hi.y; ++oy)
                        for (int ox = lo.x; ox <= hi.x; ++ox) {
                            uint other = around[(ox + 1) + 3 * (oy + 1) + 9 * (oz + 1)];
                            if (other == NONE) continue;
                            ivec3 local = q - 2 * ivec3(ox, oy, oz);
                            sum += imageLoad(uPartial, int(other - uLevelStart[uLevel]) * 27 + sampleIndex(local));
                        }
                imageStore(uBrickPool, origin + q, sum);
            }
}
