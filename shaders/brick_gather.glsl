// Gathering what a node's brick samples are made of, for the filters that are not linear
// (opacity by transmittance, radiance by direction: brick_layout.hpp). A node's 3³ samples sit on
// its corners, edge and face midpoints and centre; what lies around them belongs to the node's
// children and to the children of the nodes beside it. gatherChildren() collects those children,
// a 4×4×4 block per axis from the child slot −1 (the neighbour's last) to 2 (the next one's first).
// Every node sharing a sample gathers the same values in the same order, so a shared sample is
// bit-identical in every brick that holds it.
// Requires voxel_common.glsl and octree.glsl.

// The node at offset blockCoord3(o) − 1 ∈ {−1,0,1}³ from `node` (level uLevel), index
// aroundIndex of that offset; NONE where there is none.
int aroundIndex(ivec3 e) { return (e.x + 1) + 3 * (e.y + 1) + 9 * (e.z + 1); }
uint nodeAround(uint node, int o) {
    if (o == 13) return node;
    ivec3 target = ivec3(unpackCell(nodeCoord[node])) + blockCoord3(o) - 1;
    int size = 1 << uLevel;
    if (any(lessThan(target, ivec3(0))) || any(greaterThanEqual(target, ivec3(size)))) return NONE;
    return findNode(uvec3(target), uLevel);
}
// The 3×3×3 nodes around `node`, itself in the middle.
void nodesAround(uint node, out uint around[27]) {
    for (int o = 0; o < 27; ++o) around[o] = nodeAround(node, o);
}

// Child v of the 4×4×4 block around the node in the middle of a 3×3×3 neighbourhood, index
// (s.x+1) + 4(s.y+1) + 16(s.z+1) for child slot s ∈ {−1,0,1,2}³ relative to the node's own
// children: child `slot` of the neighbour aroundIndex(⌊s/2⌋).
int childAround(int v, out uint slot) {
    ivec3 s = ivec3(v & 3, (v >> 2) & 3, v >> 4) - 1;
    ivec3 bit = (s + 2) & 1;
    slot = uint(bit.x | (bit.y << 1) | (bit.z << 2));
    return aroundIndex((s + 2) / 2 - 1);
}
// The children around the node in the middle of `around`, index v as in childAround; NONE where
// there is none.
void childrenAround(const uint around[27], out uint children[64]) {
    for (int v = 0; v < 64; ++v) {
        uint slot;
        uint parent = around[childAround(v, slot)];
        children[v] = parent == NONE ? NONE : childOf(parent, slot);
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

// Child-lattice point p (child-lattice units from the node's minimum corner, p ∈ [−1, 5]³; child
// slot s spans [2s, 2s + 2]) lies in up to eight children (on their boundaries), any of which
// holds its complete value; they are tried in a fixed order. Candidate k (0..7) of that order: the
// child's index in the 4×4×4 block (gatherChildren) and p's sample in its brick; −1 when p is not
// on that child.
int childCandidate(ivec3 p, int k, out ivec3 local) {
    ivec3 s = ivec3(floor(vec3(p) * 0.5));
    ivec3 onBoundary = ivec3(equal(p & 1, ivec3(0))) * ivec3(greaterThan(s, ivec3(-1)));  // may use s − 1
    ivec3 down = ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    if (any(greaterThan(down, onBoundary))) return -1;
    ivec3 slot = min(s - down, ivec3(2));
    local = p - 2 * slot;
    return (slot.x + 1) + 4 * (slot.y + 1) + 16 * (slot.z + 1);
}

// The child node holding point p and p's sample in its brick: the first candidate that exists.
// False when no child holds p (empty space).
bool childSampleAt(const uint children[64], ivec3 p, out uint child, out ivec3 local) {
    for (int k = 0; k < 8; ++k) {
        int v = childCandidate(p, k, local);
        if (v < 0) continue;
        child = children[v];
        if (child != NONE) return true;
    }
    return false;
}

// Transmittance is what a node's cross-section averages (brick_layout.hpp): the effective
// density that gives transmittance T over a path of `length` voxels, capped like opticalDepth()
// (and never below 0: a mean of transmittances 1 can round to just above 1).
float densityFromTransmittance(float transmittance, float length) {
    return clamp(-log(max(transmittance, 1e-30)) / length, 0.0, -log(1.0 - MAX_OPACITY));
}
