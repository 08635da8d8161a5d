#version 450
layout(local_size_x = 64) in;
// inject, last step: per touched voxel, the area-average outgoing radiance of its surface,
//   L = Σ ρ·Φ / (π · A) + L_emitted      (A: the voxel's surface area in scene units²),
// stored weighted by the voxel's optical depth τ (voxel_common.glsl): (L·τ, τ), the form the
// brick filters and the cone tracer use. Unlit parts of the surface count as
// dark because A is the whole surface inside the voxel, lit or not. Beside it, the direction the
// reflected light leaves in (cellDirection), which cone_trace uses to let a surface light only
// what lies in front of its lit side.
#define WORK_LIST_TOUCHED
#define RADIANCE_WITHOUT_BORDER_LISTS
#include "voxel_common.glsl"
#include "octree.glsl"
#include "radiance_common.glsl"
#include "radiance_accumulators.glsl"
#include "work_list.glsl"

layout(std430, binding = SSBO_CELL_VALUES) buffer CellAlbedo { uint cellAlbedo[]; };
layout(std430, binding = SSBO_CELL_AREA) buffer CellArea { float cellArea[]; };
layout(std430, binding = SSBO_CELL_EMISSIVE) buffer CellEmissive { vec4 cellEmissive[]; };
layout(std430, binding = SSBO_CELL_COLUMNS) buffer CellColumns { uint cellColumns[]; };  // svo_leaves_normalize.comp

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

// The photons' sums of `cell`: flux (rgb, fixed-point units), lit-normal sum (3) and count.
// The flux is built whole: NVIDIA's compiler cannot write a double vector's component chosen by
// a variable (flux[c] = ...), it fails to link with an internal error.
void photonSums(uint cell, out dvec3 flux, out ivec3 litNormal, out uint photons) {
    uint base = cell * ACCUMULATOR_WORDS;
    flux = dvec3(wideSum(base), wideSum(base + 2u), wideSum(base + 4u));
    litNormal = ivec3(int(radianceAccumulator[base + 6u]), int(radianceAccumulator[base + 7u]), int(radianceAccumulator[base + 8u]));
    photons = radianceAccumulator[base + 9u];
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
    photonSums(cell, flux, litNormal, photons);
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
            photonSums(partnerCell, partnerFlux, partnerNormal, partnerPhotons);
            flux += partnerFlux;
            litNormal += partnerNormal;
            photons += partnerPhotons;
            area += double(cellArea[partnerCell]);
        }
    }
    vec3 radiance = area > 0.0lf ? vec3(flux * uRadiancePerUnit / area) : vec3(0.0);
    vec3 emitted = uHasEmissive != 0 ? cellEmissive[cell].rgb : vec3(0.0);
    // Which way the reflected light leaves: the photons' mean lit-side normal (length < 1 where
    // they disagree, e.g. a thin wall lit from both sides). Emission leaves both ways, so the
    // direction is shortened by the emitted share of the radiance.
    vec3 direction = photons > 0u ? vec3(litNormal) / (LIT_NORMAL_SCALE * float(photons)) : vec3(0.0);
    float reflectedShare = dot(radiance, vec3(1.0)) / max(dot(radiance + emitted, vec3(1.0)), 1e-30);
    direction *= reflectedShare;
    float tau = radianceWeight(unpackUnorm4x8(cellAlbedo[cell]).a);
    cellRadiance[cell] = vec4((radiance + emitted) * tau, tau);
    cellDirection[cell] = vec4(direction * tau, tau);
}
