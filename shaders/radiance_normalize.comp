#version 450
layout(local_size_x = 64) in;
// inject, last step: per touched voxel, the area-average outgoing radiance of its surface,
//   L = Σ ρ·Φ / (π · A) + L_emitted      (A: the voxel's surface area in scene units²),
// stored weighted by the voxel's optical depth τ (voxel_common.glsl): (L·τ, τ), the form the
// brick filters and the cone tracer use. Unlit parts of the surface count as
// dark because A is the whole surface inside the voxel, lit or not. Beside it, which share of that
// light leaves towards each of the six axis directions (cellExitShares, facing.glsl), from the
// photons' lit-side normals: a surface lights only what lies in front of its lit side.
#define WORK_LIST_TOUCHED
#define RADIANCE_WITHOUT_BORDER_LISTS
#include "voxel_common.glsl"
#include "octree.glsl"
#include "radiance_common.glsl"
#include "radiance_accumulators.glsl"
#include "work_list.glsl"
#include "facing.glsl"

layout(std430, binding = SSBO_CELL_VALUES) buffer CellAlbedo { uint cellAlbedo[]; };
layout(std430, binding = SSBO_CELL_AREA) buffer CellArea { float cellArea[]; };
layout(std430, binding = SSBO_CELL_EMISSIVE) buffer CellEmissive { vec4 cellEmissive[]; };
layout(std430, binding = SSBO_CELL_COLUMNS) buffer CellColumns { uint cellColumns[]; };  // svo_leaves_normalize.comp
layout(std430, binding = SSBO_CELL_OPACITY) buffer CellOpacity { uint cellOpacity[]; };  // RGBA8 (αx, αy, αz, α)

uniform double uRadiancePerUnit;  // watts of one fixed-point unit / (π · one voxel face in scene units²)
uniform int uHasEmissive;

// Below this much surface (voxel-face units) a cell's photons are pooled with those of the cells
// holding the rest of its triangles' pixel columns. Such a cell blocks as much of the column as
// the whole triangle does (voxelize.frag: a ray along the column meets it in one of them), so the
// first one a cone meets shows its radiance for all of the column; a sliver of the triangle gets
// few of the light-view map's photons (four per voxel side), often none, and a dark sliver in
// front hid the lit triangle behind it. Pooled, it shows the radiance of the column's surface.
const float POOLING_AREA = 0.5;

// One 64-bit fixed-point sum, stored as its low word then its high word.
double wideSum(uint word) {
    return double(radianceAccumulator[word]) + 4294967296.0lf * double(radianceAccumulator[word + 1u]);
}

// The photons' sums of `cell`: flux (rgb, fixed-point units), lit-normal sum (3), count and the
// sum of the lit normals' absolute values (3).
// The flux is built whole: NVIDIA's compiler cannot write a double vector's component chosen by
// a variable (flux[c] = ...), it fails to link with an internal error.
void photonSums(uint cell, out dvec3 flux, out ivec3 litNormal, out uint photons, out uvec3 litAbs) {
    uint base = cell * ACCUMULATOR_WORDS;
    flux = dvec3(wideSum(base), wideSum(base + 2u), wideSum(base + 4u));
    litNormal = ivec3(int(radianceAccumulator[base + 6u]), int(radianceAccumulator[base + 7u]), int(radianceAccumulator[base + 8u]));
    photons = radianceAccumulator[base + 9u];
    litAbs = uvec3(radianceAccumulator[base + 10u], radianceAccumulator[base + 11u], radianceAccumulator[base + 12u]);
}

void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    uint cell = node - uLevelStart[uLevels];
    // In double until the radiance itself: the watts of a texel can exceed float's range (a 1e20
    // W/m² sun over a 1e18 m scene) while the radiance ρ/π·E cannot.
    dvec3 flux;
    ivec3 litNormal;
    uint photons;
    uvec3 litAbs;
    photonSums(cell, flux, litNormal, photons, litAbs);
    double area = double(cellArea[cell]);
    uint partners = cellColumns[cell];
    if (area < double(POOLING_AREA) && partners != 0u) {
        ivec3 coord = ivec3(unpackCell(nodeCoord[node]));
        for (int bit = 0; bit < 6; ++bit) {
            if ((partners & (1u << bit)) == 0u) continue;
            ivec3 partner = coord;
            partner[bit >> 1] += (bit & 1) == 0 ? -1 : 1;
            if (any(lessThan(partner, ivec3(0))) || any(greaterThanEqual(partner, ivec3(1 << uLevels)))) continue;
            uint partnerNode = findNode(uvec3(partner), uLevels);
            if (partnerNode == NONE) continue;
            uint partnerCell = partnerNode - uLevelStart[uLevels];
            dvec3 partnerFlux;
            ivec3 partnerNormal;
            uint partnerPhotons;
            uvec3 partnerAbs;
            photonSums(partnerCell, partnerFlux, partnerNormal, partnerPhotons, partnerAbs);
            flux += partnerFlux;
            litNormal += partnerNormal;
            photons += partnerPhotons;
            litAbs += partnerAbs;
            area += double(cellArea[partnerCell]);
        }
    }
    vec3 radiance = area > 0.0lf ? vec3(flux * uRadiancePerUnit / area) : vec3(0.0);
    vec3 emitted = uHasEmissive != 0 ? cellEmissive[cell].rgb : vec3(0.0);
    float tau = radianceWeight(unpackUnorm4x8(cellAlbedo[cell]).a);
    cellRadiance[cell] = vec4((radiance + emitted) * tau, tau);

    // Which share of L leaves towards each axis direction. The reflected light of a surface
    // patch of area A_p and radiance L_p leaves towards e with intensity L_p·A_p·max(n·e, 0), and
    // L_p·A_p is its share of the flux: so the voxel sends towards e the flux-weighted mean of
    // max(n·e, 0) over its photons' lit-side normals, times L·A (A: its surface, in voxel faces).
    // Seen along axis a through its opacity α_a, that is L·(A·mean max(n·e, 0)/α_a): the share
    // below, 1 on the lit side of a flat surface (A·|n_a| = α_a) and 0 on its dark side, but for a
    // curtain's folds or a column's curve it follows the lit parts: a fold lit from above is
    // brighter seen from above than its mean radiance, and darker from below, where a single mean
    // normal gave every direction in front of it the mean. Emission leaves every way.
    float reflectedShare = dot(radiance, vec3(1.0)) / max(dot(radiance + emitted, vec3(1.0)), 1e-30);
    vec3 opacity = min(unpackUnorm4x8(cellOpacity[cell]).xyz, vec3(MAX_OPACITY));
    vec3 meanNormal = photons > 0u ? vec3(litNormal) / (LIT_NORMAL_SCALE * float(photons)) : vec3(0.0);
    vec3 meanAbs = photons > 0u ? vec3(litAbs) / (LIT_NORMAL_SCALE * float(photons)) : vec3(0.0);
    vec3 perOpacity = float(area) / max(opacity, vec3(1e-3));
    // Towards −a (what a cone travelling along +a meets) and towards +a.
    vec3 towardMinus = min(0.5 * max(meanAbs - meanNormal, 0.0) * perOpacity, vec3(MAX_EXIT_SHARE));
    vec3 towardPlus = min(0.5 * max(meanAbs + meanNormal, 0.0) * perOpacity, vec3(MAX_EXIT_SHARE));
    float emittedShare = 1.0 - reflectedShare;
    storeExitShares(cell, emittedShare + reflectedShare * vec4(towardMinus.x, towardPlus.x, towardMinus.y, towardPlus.y),
                    emittedShare + reflectedShare * vec2(towardMinus.z, towardPlus.z));
}
