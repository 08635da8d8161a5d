// Brick samples that several nodes share. A node's 3³ samples lie on its corners, edges, faces and
// centre, so only the centre is its alone: a face sample belongs to two bricks, an edge sample to
// four, a corner to eight, and every brick holds its own copy (trilinear lookups stay inside one
// brick). The filters compute a shared sample the same way from any brick that holds it
// (brick_gather.glsl), so one brick can compute it and the others copy it: above the leaves,
// radiance_mip and bricks_opacity compute only the samples their node owns, then
// radiance_share.comp and bricks_share.comp copy the rest from their owners. On a surface that
// continues on every side a node owns 8 of its 27. Copying pays where a sample costs many reads
// (18 or 27 child samples there); at the leaves a sample costs about what its copy does, so the
// leaf filters compute all of their own.
//
// The sharers of sample q of a node: along each axis where q lies on the node's low face (q_a = 0)
// the node and its neighbour below, on its high face (q_a = 2) the node and its neighbour above,
// inside (q_a = 1) the node alone. Its owner is the sharer that comes last in (z, y, x) order
// among those the filter works on (`present`: every node of the level, or the radiance filter's
// border nodes): every sharer finds the same one, and the node itself always counts.

// Bit o of the result: node o of `around` exists (bricks_opacity works on every node of a level).
uint nodesPresent(const uint around[27]) {
    uint present = 0u;
    for (int o = 0; o < 27; ++o)
        if (around[o] != NONE) present |= 1u << uint(o);
    return present;
}

// The offset (−1, 0 or 1 per axis) of the node that owns sample q, among those `present`.
ivec3 sampleOwner(ivec3 q, uint present) {
    ivec3 high = ivec3(equal(q, ivec3(2))), low = -ivec3(equal(q, ivec3(0)));
    for (int z = high.z; z >= low.z; --z)
        for (int y = high.y; y >= low.y; --y)
            for (int x = high.x; x >= low.x; --x)
                if ((present & (1u << uint(aroundIndex(ivec3(x, y, z))))) != 0u) return ivec3(x, y, z);
    return ivec3(0);  // not reached: the node itself is always present
}

// For the copy passes: where the node in the middle of `around` finds sample q, when another node
// owns it: that node (`owner`) and q's place in its brick. False when the node owns q itself.
bool sampleFromOwner(const uint around[27], uint present, ivec3 q, out uint owner, out ivec3 ownerSample) {
    ivec3 offset = sampleOwner(q, present);
    owner = around[aroundIndex(offset)];
    ownerSample = q - 2 * offset;
    return offset != ivec3(0);
}
