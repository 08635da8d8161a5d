// Walking a ray through the octree with empty-space skipping: from any point, descend from the
// root until either the target level is reached (a node to shade) or a node is missing (an empty
// region of that size, skipped in one step). Positions always come from the ray parameter
// (origin + t·direction), never accumulated, so long rays stay exact.
// Requires voxel_common.glsl and octree.glsl.

struct OctreeHit {
    uint node;     // NONE: empty region
    int level;     // level of the node or of the empty region
    float tExit;   // ray parameter where the ray leaves that node or region
    int entryAxis; // axis of the face through which the ray entered it
};

// Ray parameters where the ray enters and leaves the box [lo, hi] (tEnter > tExit: missed).
vec2 rayBox(vec3 origin, vec3 invDirection, vec3 lo, vec3 hi) {
    vec3 t0 = (lo - origin) * invDirection, t1 = (hi - origin) * invDirection;
    vec3 tMin = min(t0, t1), tMax = max(t0, t1);
    return vec2(max(max(tMin.x, tMin.y), tMin.z), min(min(tMax.x, tMax.y), tMax.z));
}

// The node at `targetLevel` (≤ uLevels) containing voxel-space point p, or the largest empty
// region containing it.
OctreeHit octreeLookup(vec3 p, vec3 origin, vec3 invDirection, int targetLevel) {
    uvec3 cell = uvec3(clamp(floor(p), vec3(0.0), vec3(float((1 << uLevels) - 1))));
    uint node = 0u;
    int level = 0;
    while (level < targetLevel) {
        uint child = childOf(node, childSlot(cell >> uint(uLevels - level - 1)));
        ++level;
        if (child == NONE) {
            node = NONE;
            break;
        }
        node = child;
    }
    float size = float(1 << (uLevels - level));
    vec3 lo = vec3(cell >> uint(uLevels - level)) * size;
    OctreeHit hit;
    hit.node = node;
    hit.level = level;
    vec3 t0 = (lo - origin) * invDirection, t1 = (lo + size - origin) * invDirection;
    vec3 tMin = min(t0, t1), tMax = max(t0, t1);
    hit.tExit = min(min(tMax.x, tMax.y), tMax.z);
    hit.entryAxis = (tMin.x >= tMin.y && tMin.x >= tMin.z) ? 0 : (tMin.y >= tMin.z ? 1 : 2);
    return hit;
}
