#version 450
layout(local_size_x = 8, local_size_y = 8) in;
// inject: every texel of a light-view map is a photon. It finds the voxel containing its surface
// point and adds its reflected flux ρ·Φ (W) to the voxel's 64-bit fixed-point sums; the voxel is
// marked touched. radiance_normalize later divides by π × the voxel's surface area.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "radiance_common.glsl"

layout(binding = 0) uniform sampler2D uLightPosition;  // scene-local, w = 0: no surface
layout(binding = 1) uniform sampler2D uLightFlux;      // reflected flux per texel, W

uniform vec3 uVoxelOrigin;  // scene-local position of voxel (0,0,0)
uniform float uVoxelScale;  // voxels per scene-local unit
uniform float uFluxScale;   // fixed-point units per watt

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
    if (node == NONE) {
        // The point rounds into a voxel the conservative voxelization did not mark (only possible
        // within float rounding of a voxel face): try the nearest neighbour across that face.
        vec3 f = voxel - floor(voxel);
        vec3 towards = vec3(f.x < 0.5 ? -1.0 : 1.0, f.y < 0.5 ? -1.0 : 1.0, f.z < 0.5 ? -1.0 : 1.0);
        vec3 distanceToFace = min(f, 1.0 - f);
        int axis = distanceToFace.x < distanceToFace.y ? (distanceToFace.x < distanceToFace.z ? 0 : 2)
                                                       : (distanceToFace.y < distanceToFace.z ? 1 : 2);
        ivec3 other = ivec3(cell);
        other[axis] += int(towards[axis]);
        if (all(greaterThanEqual(other, ivec3(0))) && all(lessThan(other, ivec3(n)))) node = findNode(uvec3(other), uLevels);
        if (node == NONE) {
            atomicAdd(listCounts[MISSED_COUNT], 1u);
            return;
        }
    }
    uint index = (node - uLevelStart[uLevels]) * 6u;
    // Clamped so that even an albedo far above 1 (a broken material) cannot wrap a word.
    for (uint c = 0u; c < 3u; ++c) accumulate64(index + 2u * c, uint(round(min(flux[c] * uFluxScale, 2147483648.0))));
    touch(node, uLevels);
}
