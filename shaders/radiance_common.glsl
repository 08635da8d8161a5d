// Buffers of the radiance volume (engine/lighting/radiance_volume.hpp). Requires octree.glsl.
// Touched counts per level from 0, border counts from BORDER_COUNT_SLOT, then missed photons and
// the cells that gather their own bounce (bounce_gather.comp).
layout(std430, binding = SSBO_LIST_COUNTS) buffer ListCounts { uint listCounts[]; };
layout(std430, binding = SSBO_TOUCHED_FLAG) buffer TouchedFlag { uint touchedFlag[]; };
layout(std430, binding = SSBO_TOUCHED_LIST) buffer TouchedList { uint touchedList[]; };
// A pass that needs every one of its 16 storage blocks (GL's least per compute shader) and not
// the border lists defines RADIANCE_WITHOUT_BORDER_LISTS.
#ifndef RADIANCE_WITHOUT_BORDER_LISTS
layout(std430, binding = SSBO_BORDER_FLAG) buffer BorderFlag { uint borderFlag[]; };
layout(std430, binding = SSBO_BORDER_LIST) buffer BorderList { uint borderList[]; };
#endif
#include "cell_radiance.glsl"

const uint BORDER_COUNTS = BORDER_COUNT_SLOT;
const uint MISSED_COUNT = MISSED_COUNT_SLOT;

// A node's touched flag: bit 0 once it is on its level's touched list; bit 1 once a photon landed
// in it (inject.comp, which then also touches the cells it pools its photons with).
const uint TOUCHED_LISTED = 1u;
const uint TOUCHED_BY_PHOTONS = 2u;

// Sets `bits` of `node`'s touched flag; whoever sets TOUCHED_LISTED first appends the node to
// `level`'s list. Returns the bits that were set before: a caller acts on a bit once, whichever
// invocation came first, so what gets touched does not depend on the order they run in.
uint touchWith(uint node, int level, uint bits) {
    uint before = atomicOr(touchedFlag[node], bits | TOUCHED_LISTED);
    if ((before & TOUCHED_LISTED) == 0u) {
        uint slot = atomicAdd(listCounts[level], 1u);
        touchedList[uLevelStart[level] + slot] = node;
    }
    return before;
}

// Marks `node` of `level` touched; the first to do so appends it to the level's list and gets true.
bool touch(uint node, int level) { return (touchWith(node, level, TOUCHED_LISTED) & TOUCHED_LISTED) == 0u; }

#ifndef RADIANCE_WITHOUT_BORDER_LISTS
// A node's border flag: BORDER_NOW once it is on this filtering's border list (touch_border.comp),
// BORDER_BEFORE when it was on the previous one's (border_age.comp): only those bricks can hold
// light, and only those that are not on the border again need clearing (radiance_clear.comp).
const uint BORDER_NOW = 1u;
const uint BORDER_BEFORE = 2u;

// Bit o of the result: node o of a 3×3×3 neighbourhood (brick_gather.glsl, nodesAround) is on this
// filtering's border list: the nodes whose shared samples it computes (shared_samples.glsl).
bool onBorderNow(uint node) { return node != NONE && (borderFlag[node] & BORDER_NOW) != 0u; }
uint bordersAround(const uint around[27]) {
    uint present = 0u;
    for (int o = 0; o < 27; ++o)
        if (onBorderNow(around[o])) present |= 1u << uint(o);
    return present;
}
#endif

// A slab's radiance for the pools: `seen` is what reaches its front face (mean over its cross-
// section), `alpha` its opacity (1 − mean transmittance), `tau` its density, `length` its length
// (voxels). Stored as L·τ, L = seen / α being the radiance of a uniform medium of that opacity
// that sends `seen`; for an almost empty slab α ≈ τ·length, so the value tends to seen / length.
// Negative where the slab shows the dark side of a surface lit at an angle to the axes
// (radiance_normalize.comp, darkSideSigned): kept, for the cone that adds it to what it reads
// along the other axes (cone_march.glsl, traceCone clips the sum).
vec4 slabRadiance(vec3 seen, float alpha, float tau, float length) {
    vec3 premultiplied = alpha > 1e-4 ? seen * (tau / alpha) : seen / length;
    return vec4(premultiplied, tau);
}
