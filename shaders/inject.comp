#version 450
layout(local_size_x = 8, local_size_y = 8) in;
// inject: every texel of a light-view map is a photon. It finds the voxel containing its surface
// point and adds its reflected flux ρ·Φ (W) to the voxel's 64-bit fixed-point sums; the voxel is
// marked touched, and the photon's lit-side normal is summed (which way the light leaves).
// radiance_normalize later divides by π × the voxel's surface area.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "radiance_common.glsl"
#include "radiance_accumulators.glsl"

layout(binding = TEXTURE_LIGHT_POSITION) uniform sampler2D uLightPosition;  // scene-local, w = 0: no surface
layout(binding = TEXTURE_LIGHT_FLUX) uniform sampler2D uLightFlux;      // reflected flux per texel / the light's largest
layout(binding = TEXTURE_LIGHT_NORMAL) uniform sampler2D uLightNormal;    // unit normal on the side facing the light
layout(std430, binding = SSBO_CELL_AREA) buffer CellArea { float cellArea[]; };
layout(std430, binding = SSBO_CELL_COLUMNS) buffer CellColumns { uint cellColumns[]; };

uniform vec3 uVoxelOrigin;  // scene-local position of voxel (0,0,0)
uniform float uVoxelScale;  // voxels per scene-local unit
uniform float uUnitsPerRelativeFlux;  // fixed-point units of this light's largest texel flux (≤ 2^24)

// The cells that share a triangle's pixel column with `node` (svo_leaves_normalize.comp): they
// pool their photons with it in radiance_normalize, so they must be normalized too, even those
// no photon landed in (a sliver of the triangle).
void touchColumnPartners(uint node) {
    uint partners = cellColumns[node - uLevelStart[uLevels]];
    if (partners == 0u) return;
    ivec3 cell = ivec3(unpackCell(nodeCoord[node]));
    for (int bit = 0; bit < 6; ++bit) {
        if ((partners & (1u << bit)) == 0u) continue;
        ivec3 partner = cell;
        partner[bit >> 1] += (bit & 1) == 0 ? -1 : 1;
        if (any(lessThan(partner, ivec3(0))) || any(greaterThanEqual(partner, ivec3(1 << uLevels)))) continue;
        uint partnerNode = findNode(uvec3(partner), uLevels);
        if (partnerNode != NONE) touch(partnerNode, uLevels);
    }
}

// Integer sums only, so the result does not depend on the order of the photons.
// `place`: the photon's place in the cell, 0..1 along each axis.
void addPhoton(uint node, vec3 units, vec3 litNormal, vec3 place) {
    uint index = (node - uLevelStart[uLevels]) * ACCUMULATOR_WORDS;
    uvec3 rounded = uvec3(round(units));
    for (uint c = 0u; c < 3u; ++c) accumulate64(index + 2u * c, rounded[c]);
    // The flux as the sums above hold it, so that the lit sides' mean over it never exceeds 1.
    float weight = (float(rounded.r) + float(rounded.g) + float(rounded.b)) * LIT_SIDE_SCALE;
    for (uint a = 0u; a < 3u; ++a) {
        accumulate64(index + LIT_SIDE_WORDS + 4u * a, uint(min(round(weight * max(litNormal[a], 0.0)), 4.0e9)));
        accumulate64(index + LIT_SIDE_WORDS + 4u * a + 2u, uint(min(round(weight * max(-litNormal[a], 0.0)), 4.0e9)));
        accumulate64(index + LIT_PLACE_WORDS + 2u * a, uint(min(round(weight * clamp(place[a], 0.0, 1.0)), 4.0e9)));
    }
    // The first photon of the node touches its partners, also when the node itself was touched
    // before as another cell's partner.
    if ((touchWith(node, uLevels, TOUCHED_BY_PHOTONS) & TOUCHED_BY_PHOTONS) == 0u) touchColumnPartners(node);
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, textureSize(uLightPosition, 0)))) return;
    vec4 position = texelFetch(uLightPosition, texel, 0);
    if (position.w <= 0.0) return;
    vec3 flux = max(texelFetch(uLightFlux, texel, 0).rgb, vec3(0.0));
    if (flux == vec3(0.0)) return;
    vec3 voxel = (position.xyz - uVoxelOrigin) * uVoxelScale;
    float n = float(1 << uLevels);
    uvec3 cell = uvec3(clamp(floor(voxel), vec3(0.0), vec3(n - 1.0)));
    uint node = findNode(cell, uLevels);
    // A point on (or within rounding of) a voxel face belongs to the voxels on both sides: a
    // surface lying exactly on a voxel boundary has its area split between them by the
    // voxelization, so its flux is split the same way, in proportion to their surface areas.
    // On an edge or a corner (a spot light straight above a grid-aligned floor puts photons on
    // voxel edges) it is split among all four or eight: which of them floor() picks is decided by
    // rounding, which the scene's scale and place change.
    vec3 f = voxel - floor(voxel);
    vec3 toFace = min(f, 1.0 - f);
    bvec3 onFace = lessThan(toFace, vec3(1e-3));
    // Rounding may also have moved the point out of the voxel the conservative voxelization
    // marked: the neighbour across the nearest face takes it.
    if (node == NONE && !any(onFace))
        onFace[toFace.x < toFace.y ? (toFace.x < toFace.z ? 0 : 2) : (toFace.y < toFace.z ? 1 : 2)] = true;
    // Clamped so that even an albedo far above 1 (a broken material) cannot wrap a word.
    vec3 units = min(flux * uUnitsPerRelativeFlux, vec3(2147483648.0));
    vec3 litNormal = normalize(texelFetch(uLightNormal, texel, 0).xyz);
    if (!any(onFace)) {  // most photons: inside their voxel
        addPhoton(node, units, litNormal, f);
        return;
    }
    ivec3 side = ivec3(f.x < 0.5 ? -1 : 1, f.y < 0.5 ? -1 : 1, f.z < 0.5 ? -1 : 1);
    uint sharers[8];
    vec3 places[8];  // the photon's place across each sharer (on the face it shares with `cell`)
    float areas[8];
    int count = 0;
    float totalArea = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        ivec3 neighbour = ivec3(cell);
        vec3 place = f;
        bool valid = true;
        for (int a = 0; a < 3; ++a) {
            if ((corner & (1 << a)) == 0) continue;
            valid = valid && onFace[a];
            neighbour[a] += side[a];
            place[a] = side[a] < 0 ? 1.0 : 0.0;
        }
        if (!valid || any(lessThan(neighbour, ivec3(0))) || any(greaterThanEqual(neighbour, ivec3(n)))) continue;
        uint sharer = corner == 0 ? node : findNode(uvec3(neighbour), uLevels);
        if (sharer == NONE) continue;
        sharers[count] = sharer;
        places[count] = place;
        areas[count] = cellArea[sharer - uLevelStart[uLevels]];
        totalArea += areas[count];
        ++count;
    }
    if (count == 0) {
        atomicAdd(listCounts[MISSED_COUNT], 1u);
        return;
    }
    for (int k = 0; k < count; ++k) {
        float share = totalArea > 0.0 ? areas[k] / totalArea : 1.0 / float(count);
        addPhoton(sharers[k], units * share, litNormal, places[k]);
    }
}
