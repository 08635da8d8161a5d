#version 450
layout(local_size_x = 8, local_size_y = 8) in;
// Debug view of the voxelization: per pixel, march the octree at one level and composite the
// albedo (or radiance) and opacity of the nodes it crosses front to back. No lighting: each node
// is only shaded by the face the ray entered it through (x, y, z faces at different brightness),
// so that the voxel structure stays readable where neighbouring surfaces have the same albedo.
// With bricks, each node's bricks are sampled with hardware trilinear filtering at the middle of
// the segment the ray spends in it; without, the node's raw albedo (cells: their own value) and
// its bricks' centre sample.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "directional_pool.glsl"
#include "octree_march.glsl"

layout(rgba32f, binding = IMAGE_VOXEL_VIEW) uniform writeonly image2D uOutput;
layout(binding = TEXTURE_VIEW_ALBEDO_BRICKS) uniform sampler3D uBrickAlbedo;  // (ρ·τ, τ): also the opacity shown
layout(std430, binding = SSBO_CELL_VALUES) buffer CellAlbedo { uint cellAlbedo[]; };
layout(std430, binding = SSBO_RAW_VALUE) buffer RawValue { vec4 rawValue[]; };
// The radiance view: of the voxels, the light they send towards the eye, and for nodes the mean
// over the six directions of the radiance their bricks' slabs send (brick_layout.hpp, "Slabs").
#include "cell_radiance.glsl"
#include "facing.glsl"
layout(std430, binding = SSBO_CELL_OPACITY) buffer CellOpacity { uint cellOpacity[]; };  // RGBA8 (αx, αy, αz, α)
layout(binding = TEXTURE_DIRECTIONAL_RADIANCE) uniform sampler3D uDirectional;  // directional_pool.glsl

uniform vec3 uEyeVoxel;      // camera position in voxel space
uniform vec3 uForward, uRight, uUp;  // camera basis (voxel space = scaled scene-local, same directions)
uniform vec2 uTanHalfFov;    // tan(fovX/2), tan(fovY/2)
uniform int uViewLevel;      // 1..uLevels
uniform int uUseBricks;
uniform int uShowRadiance;   // radiance instead of albedo: no face shading

// Radiance L of node `node` at brick position `inBrick` (texels from the brick's first sample).
vec3 nodeRadiance(uint node, vec3 inBrick) {
    vec3 poolSize = vec3(textureSize(uDirectional, 0));
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 6; ++i) {
        vec4 d = texture(uDirectional, (vec3(directionalBrickOrigin(node, i)) + inBrick) / poolSize);
        if (d.a > 1e-6) sum += max(d.rgb / d.a, vec3(0.0));  // a surface's dark side: nothing (radiance_common.glsl)
    }
    return sum / 6.0;
}

// The light voxel `cell` sends towards a ray travelling along `direction`: what the ray meets of
// it along each axis (facing.glsl), mixed by |d_a| as a narrow cone reading the voxels mixes them
// (cone_march.glsl, sampleVoxels). A wall lit on one side shows its light on that side only, as
// the cones see it; the voxel's radiance alone is the mean over both of its sides.
vec3 cellRadianceSeen(uint cell, vec3 direction) {
    vec4 opacity = unpackUnorm4x8(cellOpacity[cell]);
    vec4 seen = vec4(0.0);
    for (int a = 0; a < 3; ++a) seen += abs(direction[a]) * voxelSeenAlong(cell, 2 * a + (direction[a] < 0.0 ? 1 : 0), opacity[a]);
    return seen.a > 0.0 ? max(seen.rgb / seen.a, vec3(0.0)) : vec3(0.0);  // as a cone's sample (traceCone)
}

// (value·τ, τ) of a node at p, seen along `direction`: albedo or radiance, τ the geometry's (per
// voxel length).
vec4 nodeValue(uint node, int level, vec3 p, vec3 direction) {
    if (level == uLevels) {
        uint cell = node - uLevelStart[uLevels];
        vec4 a = unpackUnorm4x8(cellAlbedo[cell]);
        float tau = opticalDepth(a.a);
        if (uShowRadiance != 0) return vec4(cellRadianceSeen(cell, direction) * tau, tau);
        return vec4(a.rgb * tau, tau);
    }
    float size = float(1 << (uLevels - level));
    vec3 local = clamp((p - vec3(unpackCell(nodeCoord[node])) * size) / size, 0.0, 1.0);  // 0..1 in the node
    vec3 inBrick = 0.5 + (uUseBricks != 0 ? local : vec3(0.5)) * 2.0;
    vec4 albedo = uUseBricks != 0 ? texture(uBrickAlbedo, (vec3(brickOrigin(node)) + inBrick) / vec3(textureSize(uBrickAlbedo, 0)))
                                  : rawValue[node];
    if (uShowRadiance != 0) return vec4(nodeRadiance(node, inBrick) * albedo.a, albedo.a);
    return albedo;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOutput);
    if (any(greaterThanEqual(pixel, size))) return;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec3 direction = normalize(uForward + ndc.x * uTanHalfFov.x * uRight + ndc.y * uTanHalfFov.y * uUp);
    vec3 invDirection = 1.0 / direction;  // ±inf for axis-parallel rays is what rayBox wants
    float n = float(1 << uLevels);
    vec2 span = rayBox(uEyeVoxel, invDirection, vec3(0.0), vec3(n));
    vec4 color = vec4(0.0);
    float t = max(span.x, 0.0);
    for (int step = 0; step < 4096 && t < span.y && color.a < 0.99; ++step) {
        vec3 p = uEyeVoxel + direction * (t + 1e-4);
        OctreeHit hit = octreeLookup(p, uEyeVoxel, invDirection, uViewLevel);
        float tExit = max(hit.tExit, t + 1e-4);
        if (hit.node != NONE) {
            vec3 middle = uEyeVoxel + direction * (0.5 * (t + tExit));
            vec4 v = nodeValue(hit.node, hit.level, middle, direction);  // (value·τ, τ), τ per voxel length
            float alpha = opacityOver(v.a, tExit - t);
            const float faceShade[3] = float[3](0.8, 1.0, 0.6);
            vec3 albedo = (v.a > 0.0 ? v.rgb / v.a : vec3(0.0)) * (uShowRadiance != 0 ? 1.0 : faceShade[hit.entryAxis]);
            color.rgb += (1.0 - color.a) * alpha * albedo;
            color.a += (1.0 - color.a) * alpha;
        }
        t = tExit;
    }
    imageStore(uOutput, pixel, color);
}
