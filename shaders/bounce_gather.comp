#version 450
layout(local_size_x = 64) in;
// bounce_gather (multiple bounces, docs/frame.md "Further bounces"): per occupied voxel, the
// indirect irradiance arriving at its surface, gathered with the cone set (cone_march.glsl)
// through the radiance bricks as they are, over both sides of the voxel's mean normal (a voxel's
// surface may face either way, and a thin wall is lit on both sides). The voxel's outgoing
// radiance becomes its first-bounce radiance L₀ (photons and emission, kept in `bounceBase`)
// plus ρ/π·E of each side; the radiance filter then runs again over it, so each call adds one
// bounce: L_k = L₀ + ρ/π·E[L_{k−1}].
// The lit-side direction follows the same bookkeeping as photons (facing.glsl): the sum of the
// radiance sent to the front minus that sent to the back, over the whole, along the normal.
#include "cone_march.glsl"
#include "radiance_common.glsl"

layout(std430, binding = SSBO_CELL_VALUES) buffer CellAlbedo { uint cellAlbedo[]; };   // RGBA8 albedo, opacity
layout(std430, binding = SSBO_CELL_NORMAL) buffer CellNormal { uint cellNormal[]; };   // octahedral
// The first bounce: (L₀·τ, τ) of every cell, then (N₀·τ, τ) of every cell.
layout(std430, binding = SSBO_BOUNCE_BASE) buffer BounceBase { vec4 bounceBase[]; };

void main() {
    uint cell = gl_GlobalInvocationID.x;
    uint cellCount = uLevelCount[uLevels];
    if (cell >= cellCount) return;
    uint node = uLevelStart[uLevels] + cell;
    vec4 albedo = unpackUnorm4x8(cellAlbedo[cell]);
    vec3 normal = unpackNormal(cellNormal[cell]);
    vec3 centre = vec3(unpackCell(nodeCoord[node])) + 0.5;
    vec3 sent[2];
    for (int side = 0; side < 2; ++side) {
        vec3 n = side == 0 ? normal : -normal;
        sent[side] = albedo.rgb / PI * gatherIrradiance(centre + n * uConeOffset, n).rgb;
    }
    vec4 base = bounceBase[cell], baseDirection = bounceBase[cellCount + cell];
    vec3 first = base.a > 0.0 ? base.rgb / base.a : vec3(0.0);
    vec3 firstDirection = baseDirection.a > 0.0 ? baseDirection.rgb / baseDirection.a : vec3(0.0);
    vec3 radiance = first + sent[0] + sent[1];
    float total = dot(radiance, vec3(1.0));
    if (!(total > 0.0)) return;  // unlit and dark still: nothing to add
    vec3 direction = (firstDirection * dot(first, vec3(1.0)) +
                      normal * (dot(sent[0], vec3(1.0)) - dot(sent[1], vec3(1.0)))) / total;
    float tau = opticalDepth(albedo.a);
    cellRadiance[cell] = vec4(radiance * tau, tau);
    cellDirection[cell] = vec4(direction * tau, tau);
    touch(node, uLevels);
}
