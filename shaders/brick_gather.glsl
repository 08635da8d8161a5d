// Gathering what a node's brick samples are made of, for the filters that are not linear
// (opacity by transmittance, radiance by direction: brick_layout.hpp). A node's 3³ samples sit on
// its corners, edge and face midpoints and centre; what lies around them belongs to the node's
// children and to the children of the nodes beside it. gatherChildren() collects those children,
// a 4×4×4 block per axis from the child slot −1 (the neighbour's last) to 2 (the next one's first).
// Every node sharing a sample gathers the same values in the same order, so a shared sample is
// bit-identical in every brick that holds it.
// Requires voxel_common.glsl and octree.glsl.

// The 3×3×3 nodes around `node` (level uLevel), itself in the middle: index aroundIndex(e) for the
// offset e ∈ {−1,0,1}³; NONE where there is none.
int aroundIndex(ivec3 e) { return (e.x + 1) + 3 * (e.y + 1) + 9 * (e.z + 1); }
void nodesAround(uint node, out uint around[27]) {
    ivec3 coord = ivec3(unpackCell(nodeCoord[node]));
    int size = 1 << uLevel;
    for (int o = 0; o < 27; ++o) {
        ivec3 target = coord + blockCoord3(o) - 1;
        around[o] = NONE;
        if (o == 13) around[o] = node;
        else if (all(greaterThanEqual(target, ivec3(0))) && all(lessThan(target, ivec3(size))))
            around[o] = findNode(uvec3(target), uLevel);
    }
}

// The children around the node in the middle of `around`: index (s.x+1) + 4(s.y+1) + 16(s.z+1)
// for child slot s ∈ {−1,0,1,2}³ relative to the node's own children; NONE where there is none.
void childrenAround(const uint around[27], out uint children[64]) {
    for (int o = 0; o < 27; ++o) {
        ivec3 offset = blockCoord3(o) - 1;
        for (uint slot = 0u; slot < 8u; ++slot) {
            ivec3 s = 2 * offset + ivec3(slot & 1u, (slot >> 1) & 1u, (slot >> 2) & 1u);
            if (any(lessThan(s, ivec3(-1))) || any(greaterThan(s, ivec3(2)))) continue;
            children[(s.x + 1) + 4 * (s.y + 1) + 16 * (s.z + 1)] = around[o] == NONE ? NONE : childOf(around[o], slot);
        }
    }
}

void gatherChildren(uint node, out uint children[64]) {
    uint around[27];
    nodesAround(node, around);
    childrenAround(around, children);
}

// At the leaf level (children = voxels): the index in gatherChildren's block of one of the 4
// voxels that the slab of sample q along +a (plus) or −a holds (brick_layout.hpp, "Slabs"),
// column 0..3 across the slab.
int leafSlabVoxel(ivec3 q, int a, bool plus, int column) {
    ivec3 cell = q - 1;
    cell[a] += plus ? 1 : 0;  // +a: the voxel after q, −a: the one before
    cell[(a + 1) % 3] += column & 1;
    cell[(a + 2) % 3] += column >> 1;
    return (cell.x + 1) + 4 * (cell.y + 1) + 16 * (cell.z + 1);
}

// In a 3×3×3 block of child samples around 2Q, index (d + 1) · (1, 3, 9): the index step along
// axis a, and the index of the sample at offset (db, dc) across axis a (d_a = 0), the front of a
// child column along a.
int aroundStride(int a) { return a == 0 ? 1 : (a == 1 ? 3 : 9); }
int aroundAcross(int a, int db, int dc) {
    ivec3 d = ivec3(0);
    d[(a + 1) % 3] = db;
    d[(a + 2) % 3] = dc;
    return (d.x + 1) + 3 * (d.y + 1) + 9 * (d.z + 1);
}

// The child node holding child-lattice point p (child-lattice units from the node's minimum
// corner, p ∈ [−1, 5]³; child slot s spans [2s, 2s + 2]) and p's sample in that child's brick.
// A point on a child's boundary belongs to up to eight children, any of which holds its complete
// value; they are tried in a fixed order. False when no child holds p (empty space).
bool childSampleAt(const uint children[64], ivec3 p, out uint child, out ivec3 local) {
    ivec3 s = ivec3(floor(vec3(p) * 0.5));
    ivec3 onBoundary = ivec3(equal(p & 1, ivec3(0))) * ivec3(greaterThan(s, ivec3(-1)));  // may use s − 1
    for (int k = 0; k < 8; ++k) {
        ivec3 down = ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1);
        if (any(greaterThan(down, onBoundary))) continue;
        ivec3 slot = min(s - down, ivec3(2));
        child = children[(slot.x + 1) + 4 * (slot.y + 1) + 16 * (slot.z + 1)];
        if (child != NONE) {
            local = p - 2 * slot;
            return true;
        }
    }
    return false;
}

// Transmittance is what a node's cross-section averages (brick_layout.hpp): the effective
// density that gives transmittance T over a path of `length` voxels, capped like opticalDepth()
// (and never below 0: a mean of transmittances 1 can round to just above 1).
float densityFromTransmittance(float transmittance, float length) {
    return clamp(-log(max(transmittance, 1e-30)) / length, 0.0, -log(1.0 - MAX_OPACITY));
}
