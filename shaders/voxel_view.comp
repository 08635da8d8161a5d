#version 450
layout(local_size_x = 8, local_size_y = 8) in;
// Debug view of the voxelization: per pixel, march the octree at one level and composite the
// albedo and opacity of the nodes it crosses front to back. No lighting: each node is only shaded
// by the face the ray entered it through (x, y, z faces at different brightness), so that the
// voxel structure stays readable where neighbouring surfaces have the same albedo. With bricks, each
// node's 3³ brick is sampled with hardware trilinear filtering at the middle of the segment the
// ray spends in it; without, the node's raw value (cells: their own value) is used.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "octree_march.glsl"

layout(rgba32f, binding = IMAGE_VOXEL_VIEW) uniform writeonly image2D uOutput;
layout(binding = TEXTURE_VIEW_BRICKS) uniform sampler3D uBrickAlbedo;
layout(std430, binding = SSBO_CELL_VALUES) buffer CellAlbedo { uint cellAlbedo[]; };
layout(std430, binding = SSBO_CELL_RADIANCE) buffer CellRadiance { vec4 cellRadiance[]; };
layout(binding = TEXTURE_VIEW_ALBEDO_BRICKS) uniform sampler3D uBrickOpacity;  // the albedo pool: opacity is the geometry's
layout(std430, binding = SSBO_RAW_ALBEDO) buffer RawOpacity { vec4 rawOpacity[]; };
layout(std430, binding = SSBO_RAW_VALUE) buffer RawValue { vec4 rawValue[]; };

uniform vec3 uEyeVoxel;      // camera position in voxel space
uniform vec3 uForward, uRight, uUp;  // camera basis (voxel space = scaled scene-local, same directions)
uniform vec2 uTanHalfFov;    // tan(fovX/2), tan(fovY/2)
uniform int uViewLevel;      // 1..uLevels
uniform int uUseBricks;
uniform int uShowRadiance;   // radiance pool instead of albedo: no face shading

vec4 nodeValue(uint node, int level, vec3 p) {
    if (level == uLevels) {
        vec4 a = unpackUnorm4x8(cellAlbedo[node - uLevelStart[uLevels]]);
        float tau = opticalDepth(a.a);
        if (uShowRadiance != 0) return vec4(cellRadiance[node - uLevelStart[uLevels]].rgb, tau);
        return vec4(a.rgb * tau, tau);
    }
    if (uUseBricks == 0) return vec4(rawValue[node].rgb, rawOpacity[node].a);
    float size = float(1 << (uLevels - level));
    vec3 local = clamp((p - vec3(unpackCell(nodeCoord[node])) * size) / size, 0.0, 1.0);  // 0..1 in the node
    vec3 texel = vec3(brickOrigin(node)) + 0.5 + local * 2.0;
    vec3 uvw = texel / vec3(textureSize(uBrickAlbedo, 0));
    return vec4(texture(uBrickAlbedo, uvw).rgb, texture(uBrickOpacity, uvw).a);
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
            vec4 v = nodeValue(hit.node, hit.level, middle);  // (value·τ, τ), τ per voxel length
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
