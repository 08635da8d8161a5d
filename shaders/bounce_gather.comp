#version 450
#if defined(GATHER_FIRST_CHILDREN) || defined(GATHER_LISTED)
#define GATHERS 1
// The work group's z holds the lanes that share each voxel's cones (cone_lanes.glsl).
layout(local_size_x = 64, local_size_z = CONE_LANES) in;
#else
layout(local_size_x = 64) in;
#endif
// bounce_gather (multiple bounces, docs/frame.md "Further bounces"): per occupied voxel, the
// indirect irradiance arriving at its surface, gathered with the cone set (cone_march.glsl)
// through the radiance bricks as they are, over both sides of the voxel's mean normal (a voxel's
// surface may face either way, and a thin wall is lit on both sides). The voxel's outgoing
// radiance becomes its first-bounce radiance L₀ (photons and emission, kept in `bounceBase`)
// plus ρ/π·E of each side; the radiance filter then runs again over it, so each call adds one
// bounce: L_k = L₀ + ρ/π·E[L_{k−1}]. The cones read L_{k−1} (narrow cones read the voxels
// themselves, cell_radiance.glsl) while the voxels' L_k goes to bounceBase, copied over the cell
// radiance once every voxel has gathered (bounce_gather.cpp): no voxel reads a neighbour's new
// light, whichever gathers first.
// The shares of that radiance leaving towards each axis direction follow (facing.glsl).
// Sixteen storage blocks at most (GL's least per compute shader): the gather needs no border lists.
#define RADIANCE_WITHOUT_BORDER_LISTS
#include "cone_march.glsl"
#include "cone_lanes.glsl"
#include "radiance_common.glsl"

layout(std430, binding = SSBO_CELL_VALUES) buffer CellAlbedo { uint cellAlbedo[]; };   // RGBA8 albedo, opacity
layout(std430, binding = SSBO_CELL_NORMAL) buffer CellNormal { uint cellNormal[]; };   // octahedral
// The first bounce: (L₀·τ, τ) of every cell, then its six exit shares (two vec4) of every cell;
// then the irradiance gathered on both sides of every cell (written for first children, see below);
// then this bounce's result: (L_k·τ, τ) and the exit shares of every cell (the last bounce's where
// a cell stores none).
layout(std430, binding = SSBO_BOUNCE_BASE) buffer BounceBase { vec4 bounceBase[]; };
// Cells that gather their own (GATHER_LISTED reads them; its count is a list count).
layout(std430, binding = SSBO_BOUNCE_LIST) buffer BounceList { uint ownGatherCells[]; };
// To save cones, the cells that share a parent node with a cell of nearly the same normal share
// its gather: the first pass (GATHER_FIRST_CHILDREN) gathers for the first child of every parent
// and keeps its irradiance, the second (SHARE_WITH_SIBLINGS) gives each other cell that
// irradiance when their normals agree within ~25° (cos ≥ kShareCosine; opposite normals share
// with their sides swapped). Of the cells that do not (an edge of two surfaces, a corner), the
// first in slot order is the parent's second gatherer: it is listed, with every cell that agrees
// with neither, and the third pass (GATHER_LISTED) gathers for the listed cells and keeps their
// irradiance; the cells that agree with the second gatherer are listed apart (from the list's
// end) and take its irradiance in the fourth (SHARE_WITH_SECOND). Listing them first keeps every
// invocation of a gather busy: scattered among cells that only copy, each would hold up its whole
// SIMD group.
// Siblings lie within a voxel of each other and cones start 2 voxels off their centre (grazing
// ones at least two thirds of that: cone_march.glsl, grazingConeStart), so a shared gather
// differs from the cell's own by far less than the cones' own blur.
const float kShareCosine = 0.9;


// The cell's outgoing radiance from its first bounce and the irradiance E gathered on each side,
// and the share of it that leaves towards each axis direction (facing.glsl): the first bounce's
// shares and the gathered light's, which leaves the side of the voxel's normal it arrived on
// (switching over a few degrees either side of edge-on), weighted by their radiance.
void storeBounced(uint cell, uint cellCount, uint node, vec4 albedo, vec3 normal, vec3 irradiance[2]) {
    vec3 sent[2] = vec3[2](albedo.rgb / PI * irradiance[0], albedo.rgb / PI * irradiance[1]);
    vec4 base = bounceBase[cell];
    vec3 first = base.a > 0.0 ? base.rgb / base.a : vec3(0.0);
    vec3 radiance = first + sent[0] + sent[1];
    float total = dot(radiance, vec3(1.0));
    if (!(total > 0.0)) return;  // unlit and dark still: nothing to add
    float firstWeight = dot(first, vec3(1.0)), frontWeight = dot(sent[0], vec3(1.0)), backWeight = dot(sent[1], vec3(1.0));
    vec4 shares[2] = vec4[2](bounceBase[cellCount + 2u * cell], bounceBase[cellCount + 2u * cell + 1u]);
    for (int i = 0; i < 6; ++i) {
        float front = clamp(0.5 + 8.0 * dot(normal, -poolDirection(i)), 0.0, 1.0);
        shares[i >> 2][i & 3] = (firstWeight * shares[i >> 2][i & 3] + frontWeight * front + backWeight * (1.0 - front)) / total;
    }
    float tau = radianceWeight(albedo.a);
    bounceBase[5u * cellCount + cell] = vec4(radiance * tau, tau);
    bounceBase[6u * cellCount + 2u * cell] = shares[0];
    bounceBase[6u * cellCount + 2u * cell + 1u].xy = shares[1].xy;  // beside them the lit place (facing.glsl)
    touch(node, uLevels);
}

// Whether the side of a voxel's surface that faces `n` looks into solid geometry: the voxel next
// to it that way is occupied and mostly opaque, as behind the surface of anything thicker than a
// voxel. That side receives no light (its cones would start inside the solid and gather what
// lies beyond it); a sheet one voxel thick has empty voxels on both sides and gathers on both.
bool facesSolid(vec3 centre, vec3 n) {
    vec3 next = centre + n;
    if (any(lessThan(next, vec3(0.0))) || any(greaterThanEqual(next, vec3(float(1 << uLevels))))) return false;
    uint neighbour = findNode(uvec3(next), uLevels);
    return neighbour != NONE && unpackUnorm4x8(cellAlbedo[neighbour - uLevelStart[uLevels]]).a >= 0.5;
}

// Whether a cell of leaf node `parent` other than `gatherer` (normal `normal`) would take the
// gatherer's irradiance on its side towards `n` and does not face a solid that way.
bool siblingTakesSide(uint parent, uint gatherer, vec3 normal, vec3 n) {
    uint first = nodeChild[parent] - uLevelStart[uLevels];
    uint cells = uint(bitCount(nodeMask[parent]));
    for (uint k = 0u; k < cells; ++k) {
        uint sibling = first + k;
        if (sibling == gatherer) continue;
        vec3 siblingNormal = unpackNormal(cellNormal[sibling]);
        if (abs(dot(siblingNormal, normal)) < kShareCosine) continue;
        vec3 centre = vec3(unpackCell(nodeCoord[uLevelStart[uLevels] + sibling])) + 0.5;
        if (!facesSolid(centre, dot(siblingNormal, n) >= 0.0 ? siblingNormal : -siblingNormal)) return true;
    }
    return false;
}

// The irradiance that `gatherer` kept (GATHER_FIRST_CHILDREN, GATHER_LISTED), for a cell of
// normal `normal`: true when their normals agree (sides swapped for opposite normals).
bool sharedIrradiance(uint gatherer, uint cellCount, vec3 normal, out vec3 irradiance[2]) {
    float agreement = dot(normal, unpackNormal(cellNormal[gatherer]));
    if (abs(agreement) < kShareCosine) return false;
    int flip = agreement < 0.0 ? 1 : 0;
    irradiance[0] = bounceBase[3u * cellCount + 2u * gatherer + uint(flip)].rgb;
    irradiance[1] = bounceBase[3u * cellCount + 2u * gatherer + uint(1 - flip)].rgb;
    return true;
}

// The second gatherer among the cells of leaf node `parent`: the first, in slot order, whose
// normal does not agree with the first child's (NONE when every cell agrees). A cell index.
uint secondGatherer(uint parent) {
    uint first = nodeChild[parent] - uLevelStart[uLevels];
    vec3 firstNormal = unpackNormal(cellNormal[first]);
    uint cells = uint(bitCount(nodeMask[parent]));
    for (uint k = 1u; k < cells; ++k)
        if (abs(dot(unpackNormal(cellNormal[first + k]), firstNormal)) < kShareCosine) return first + k;
    return NONE;
}

void main() {
    uint cellCount = uLevelCount[uLevels];
#ifdef GATHER_FIRST_CHILDREN
    // One invocation per leaf node, so that every invocation gathers: an invocation per cell that
    // returned for all but first children would cost as much on a SIMD machine as gathering for all.
    // An invocation past the end still joins its lanes' sums (their barriers), on cell 0.
    uint leaf = gl_GlobalInvocationID.x;
    const bool valid = leaf < uLevelCount[uLevels - 1];
    uint node = valid ? nodeChild[uLevelStart[uLevels - 1] + leaf] : uLevelStart[uLevels];
    uint cell = node - uLevelStart[uLevels];
#elif defined(SHARE_WITH_SIBLINGS)
    uint cell = gl_GlobalInvocationID.x;
    if (cell >= cellCount) return;
    uint node = uLevelStart[uLevels] + cell;
    uint firstSibling = nodeChild[nodeParent[node]];
    if (firstSibling == node) return;
#elif defined(SHARE_WITH_SECOND)
    uint listed = linearInvocation();
    if (listed >= listCounts[SECOND_SHARE_COUNT_SLOT]) return;
    uint cell = ownGatherCells[cellCount - 1u - listed];
    uint node = uLevelStart[uLevels] + cell;
#else  // GATHER_LISTED
    uint listed = linearInvocation();
    const bool valid = listed < listCounts[BOUNCE_LIST_COUNT_SLOT];
    uint cell = valid ? ownGatherCells[listed] : 0u;
    uint node = uLevelStart[uLevels] + cell;
#endif
    vec4 albedo = unpackUnorm4x8(cellAlbedo[cell]);
    vec3 normal = unpackNormal(cellNormal[cell]);
    vec3 centre = vec3(unpackCell(nodeCoord[node])) + 0.5;
    bool solid[2] = bool[2](facesSolid(centre, normal), facesSolid(centre, -normal));
    vec3 irradiance[2];
#if defined(SHARE_WITH_SIBLINGS)
    if (!sharedIrradiance(firstSibling - uLevelStart[uLevels], cellCount, normal, irradiance)) {
        uint second = secondGatherer(nodeParent[node]);
        if (second != cell && abs(dot(normal, unpackNormal(cellNormal[second]))) >= kShareCosine)
            ownGatherCells[cellCount - 1u - atomicAdd(listCounts[SECOND_SHARE_COUNT_SLOT], 1u)] = cell;
        else
            ownGatherCells[atomicAdd(listCounts[BOUNCE_LIST_COUNT_SLOT], 1u)] = cell;
        return;
    }
#elif defined(SHARE_WITH_SECOND)
    sharedIrradiance(secondGatherer(nodeParent[node]), cellCount, normal, irradiance);
#else
    // A side that faces a solid receives nothing, but a gatherer still gathers it where a sibling
    // that takes its irradiance does not face a solid that way: a surface that spans two voxel
    // layers has its inner layer facing the outer one, whose cells share the inner cell's gather.
    // The cones then start beyond the outer layer, where the outer cells' own would start.
    enterConeLane();
    for (int side = 0; side < 2; ++side) {
        vec3 n = side == 0 ? normal : -normal;
        bool gather = valid && (!solid[side] || siblingTakesSide(nodeParent[node], cell, normal, n));
        // Narrow cones (voxelGatherCones) point along a lattice shifted by a hash of the voxel and
        // side, so that neighbouring voxels sample other directions; the cone set takes no shift.
        vec2 shift = hashToUnitSquare(vec3(centre.xy, 2.0 * centre.z + float(side)));
        vec4 part = gather ? gatherIrradiance(centre + n * uConeOffset, n, n, shift) : vec4(0.0);
        irradiance[side] = sumConeLanes(part).rgb;
    }
    if (!valid || !storesConeLanes()) return;
#endif
#ifdef GATHERS
    bounceBase[3u * cellCount + 2u * cell] = vec4(irradiance[0], 0.0);
    bounceBase[3u * cellCount + 2u * cell + 1u] = vec4(irradiance[1], 0.0);
#endif
    // Whoever gathered it, a cell's own side that faces a solid receives nothing.
    for (int side = 0; side < 2; ++side)
        if (solid[side]) irradiance[side] = vec3(0.0);
    storeBounced(cell, cellCount, node, albedo, normal, irradiance);
}
