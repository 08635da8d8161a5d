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

// The photons' sums of `cell`: flux (rgb, fixed-point units) and, per axis a, the flux that lit
// it from the +a side and from the −a side (radiance_accumulators.glsl, × LIT_SIDE_SCALE).
// The vectors are built whole: NVIDIA's compiler cannot write a double vector's component chosen
// by a variable (flux[c] = ...), it fails to link with an internal error.
void photonSums(uint cell, out dvec3 flux, out dvec3 litPlus, out dvec3 litMinus) {
    uint base = cell * ACCUMULATOR_WORDS, sides = base + LIT_SIDE_WORDS;
    flux = dvec3(wideSum(base), wideSum(base + 2u), wideSum(base + 4u));
    litPlus = dvec3(wideSum(sides), wideSum(sides + 4u), wideSum(sides + 8u));
    litMinus = dvec3(wideSum(sides + 2u), wideSum(sides + 6u), wideSum(sides + 10u));
}

// The flux-weighted sums of the photons' places across `cell` (radiance_accumulators.glsl).
dvec3 litPlaceSums(uint cell) {
    uint base = cell * ACCUMULATOR_WORDS + LIT_PLACE_WORDS;
    return dvec3(wideSum(base), wideSum(base + 2u), wideSum(base + 4u));
}

// The six shares as the cones read them: a cone mixes the axes it travels along by |d_a|
// (cone_march.glsl), so a surface whose lit side faces +x and −z at once (a wall at 45° to the
// grid) would show its −z light to a cone that travels +x and +z, coming from its dark side: that
// cone reads the −z share by d_z and the zero −x share by d_x, where the surface sends it
// max(n·ω, 0) = 0. On the dark side of each axis the share is therefore negative by what the lit
// side sends on the other axes, up to the lit side's own share: for one flat surface the cone's
// sum is then n·ω, which its samples clip at 0 (cone_march.glsl, traceCone). A surface that faces
// one axis keeps its 0 there (it cannot show light on another axis), and a voxel lit on both
// sides of an axis (a sheet lit from either side, a fold) keeps what each side sends. `toward`:
// the flux-weighted mean of max(±n_a, 0) towards the side wanted, `away` towards the other.
vec3 darkSideSigned(vec3 toward, vec3 away) {
    vec3 lit = max(toward, away), dark = min(toward, away);
    vec3 oneSided = (lit - dark) / max(lit + dark, vec3(1e-30));  // 1: lit on one side only, 0: both alike
    vec3 otherAxes = vec3(max(lit.y, lit.z), max(lit.x, lit.z), max(lit.x, lit.y));
    vec3 signedDark = dark - oneSided * min(otherAxes, lit);
    return mix(toward, signedDark, lessThan(toward, away));
}

void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    uint cell = node - uLevelStart[uLevels];
    // In double until the radiance itself: the watts of a texel can exceed float's range (a 1e20
    // W/m² sun over a 1e18 m scene) while the radiance ρ/π·E cannot.
    dvec3 flux, litPlus, litMinus;
    photonSums(cell, flux, litPlus, litMinus);
    double area = double(cellArea[cell]);
    uint partners = cellColumns[cell];
    bool pooled = area < double(POOLING_AREA) && partners != 0u;
    if (pooled) {
        ivec3 coord = ivec3(unpackCell(nodeCoord[node]));
        for (int bit = 0; bit < 6; ++bit) {
            if ((partners & (1u << bit)) == 0u) continue;
            ivec3 partner = coord;
            partner[bit >> 1] += (bit & 1) == 0 ? -1 : 1;
            if (any(lessThan(partner, ivec3(0))) || any(greaterThanEqual(partner, ivec3(1 << uLevels)))) continue;
            uint partnerNode = findNode(uvec3(partner), uLevels);
            if (partnerNode == NONE) continue;
            uint partnerCell = partnerNode - uLevelStart[uLevels];
            dvec3 partnerFlux, partnerPlus, partnerMinus;
            photonSums(partnerCell, partnerFlux, partnerPlus, partnerMinus);
            flux += partnerFlux;
            litPlus += partnerPlus;
            litMinus += partnerMinus;
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
    // below, 1 on the lit side of a flat surface (A·|n_a| = α_a) and at most 0 on its dark side
    // (darkSideSigned), but for a curtain's folds or a column's curve it follows the lit parts: a
    // fold lit from above is brighter seen from above than its mean radiance, and darker from
    // below, where a single mean normal gave every direction in front of it the mean. Emission
    // leaves every way (an emitter that is also lit at an angle to the axes shows its dark side
    // the emission less the lit side's cancelled share: the cones add both shares in one sum).
    float reflectedShare = dot(radiance, vec3(1.0)) / max(dot(radiance + emitted, vec3(1.0)), 1e-30);
    vec3 opacity = min(unpackUnorm4x8(cellOpacity[cell]).xyz, vec3(MAX_OPACITY));
    // Flux-weighted means of max(n·e, 0) over the photons' lit-side normals, towards +a and −a.
    double litWeight = (flux.r + flux.g + flux.b) * double(LIT_SIDE_SCALE);
    vec3 meanPlus = litWeight > 0.0lf ? min(vec3(litPlus / litWeight), vec3(1.0)) : vec3(0.0);
    vec3 meanMinus = litWeight > 0.0lf ? min(vec3(litMinus / litWeight), vec3(1.0)) : vec3(0.0);
    vec3 perOpacity = float(area) / max(opacity, vec3(1e-3));
    // Towards −a (what a cone travelling along +a meets) and towards +a.
    vec3 towardMinus = clamp(darkSideSigned(meanMinus, meanPlus) * perOpacity, vec3(-MAX_EXIT_SHARE), vec3(MAX_EXIT_SHARE));
    vec3 towardPlus = clamp(darkSideSigned(meanPlus, meanMinus) * perOpacity, vec3(-MAX_EXIT_SHARE), vec3(MAX_EXIT_SHARE));
    float emittedShare = 1.0 - reflectedShare;
    storeExitShares(cell, emittedShare + reflectedShare * vec4(towardMinus.x, towardPlus.x, towardMinus.y, towardPlus.y),
                    emittedShare + reflectedShare * vec2(towardMinus.z, towardPlus.z));
    // Where the reflected light lies in the cell; not known where it is pooled with other cells'
    // or where the cell emits (emission leaves all of its surface, lit or not).
    storeLitPlace(cell, !pooled && litWeight > 0.0lf && emitted == vec3(0.0),
                  litWeight > 0.0lf ? vec3(litPlaceSums(cell) / litWeight) : vec3(0.0));
}
