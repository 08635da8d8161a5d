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
#include "voxel_common.glsl"
#include "octree.glsl"
#include "radiance_common.glsl"
#include "radiance_accumulators.glsl"
#include "work_list.glsl"

layout(std430, binding = SSBO_CELL_VALUES) buffer CellAlbedo { uint cellAlbedo[]; };
layout(std430, binding = SSBO_CELL_AREA) buffer CellArea { float cellArea[]; };
layout(std430, binding = SSBO_CELL_EMISSIVE) buffer CellEmissive { vec4 cellEmissive[]; };

uniform double uRadiancePerUnit;  // watts of one fixed-point unit / (π · one voxel face in scene units²)
uniform int uHasEmissive;

void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    uint cell = node - uLevelStart[uLevels];
    // In double until the radiance itself: the watts of a texel can exceed float's range (a 1e20
    // W/m² sun over a 1e18 m scene) while the radiance ρ/π·E cannot.
    vec3 radiance = vec3(0.0);
    double area = double(cellArea[cell]);
    if (area > 0.0lf)
        for (uint c = 0u; c < 3u; ++c) {
            uint index = cell * ACCUMULATOR_WORDS + 2u * c;
            double units = double(radianceAccumulator[index]) + 4294967296.0lf * double(radianceAccumulator[index + 1u]);
            radiance[c] = float(units * uRadiancePerUnit / area);
        }
    vec3 emitted = uHasEmissive != 0 ? cellEmissive[cell].rgb : vec3(0.0);
    // Which way the reflected light leaves: the photons' mean lit-side normal (length < 1 where
    // they disagree, e.g. a thin wall lit from both sides). Emission leaves both ways, so the
    // direction is shortened by the emitted share of the radiance.
    uint base = cell * ACCUMULATOR_WORDS;
    uint photons = radianceAccumulator[base + 9u];
    vec3 direction = vec3(0.0);
    if (photons > 0u)
        direction = vec3(int(radianceAccumulator[base + 6u]), int(radianceAccumulator[base + 7u]),
                         int(radianceAccumulator[base + 8u])) / (LIT_NORMAL_SCALE * float(photons));
    float reflectedShare = dot(radiance, vec3(1.0)) / max(dot(radiance + emitted, vec3(1.0)), 1e-30);
    direction *= reflectedShare;
    float tau = opticalDepth(unpackUnorm4x8(cellAlbedo[cell]).a);
    cellRadiance[cell] = vec4((radiance + emitted) * tau, tau);
    cellDirection[cell] = vec4(direction * tau, tau);
}
