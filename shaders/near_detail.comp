#version 450
layout(local_size_x = 8, local_size_y = 8) in;
// near_detail (render/near_detail.hpp): the near field's detail at every pixel. The cones'
// irradiance is traced at one pixel of each block and filtered along surfaces over several
// voxels, so what changes from pixel to pixel within a voxel or two (the inside of a crease, a
// moulding's shade, the foot of a column) is gone from it, while the path tracer keeps it. Two
// dispatches put it back:
//   NEAR_VISIBILITY: each pixel's visibility V within the cones' start offset: the share of a
//     fixed cosine-weighted set of directions whose ray, followed from the surface point to where
//     a cone would start, meets no surface the camera sees (near_field.glsl's test, the same one
//     the narrow cones use before they are traced).
//   otherwise: V̄, the mean of V over the pixel's own surface around it (the weights of
//     indirect_filter.comp's taps: Gaussian, normals alike, close to the tangent plane), and the
//     indirect irradiance times V / V̄. Over a patch of surface the factor averages to about one:
//     the cones keep the amount of light, V only says where within the patch it lands.
#include "math.glsl"
#include "traced_pixel.glsl"

layout(binding = TEXTURE_GBUFFER_POSITION) uniform sampler2D uPosition;
layout(binding = TEXTURE_GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = TEXTURE_GBUFFER_GEOMETRIC_NORMAL) uniform sampler2D uGeometricNormal;
uniform float uVoxelScale;  // voxels per scene-local unit
uniform float uConeOffset;  // voxels: where the cones start, how far the near field reaches
// Pixels per side of a visibility cell: 1, or 2 from 360 lines up (as the cones are traced in
// larger blocks there): the cell's first pixel stands for it.
uniform int uBlock;

#ifdef NEAR_VISIBILITY
#define NEAR_FIELD_STEPS 4
// Visibility only: what a surface met sends does not matter here.
bool hiddenSideLight(vec3 point, vec3 normal, vec3 direction, float length, out vec3 radiance) {
    radiance = vec3(0.0);
    return false;
}
#include "near_field.glsl"
#include "narrow_cone_directions.glsl"
layout(r32f, binding = IMAGE_NEAR_VISIBILITY) uniform writeonly image2D uVisibility;

// Eight directions, the narrow cones' Fibonacci lattice over the cosine-weighted hemisphere (not
// shifted), four steps along each (near_field.glsl's six serve one cone; here every pixel follows
// eight): the same set at every pixel, so V carries no noise of its own (a jittered set would
// print its noise into the image at one sample per pixel).
const int DIRECTIONS = 8;

void main() {
    const ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(cell, imageSize(uVisibility)))) return;
    const ivec2 pixel = cell * uBlock;
    const vec4 position = texelFetch(uPosition, pixel, 0);
    if (!(position.w > 0.0)) {
        imageStore(uVisibility, cell, vec4(1.0));
        return;
    }
    const vec3 normal = normalize(texelFetch(uNormal, pixel, 0).xyz);
    nearFieldPoint = position.xyz;
    nearFieldNormal = normal;
    nearFieldJitter = 0.5;
    vec3 tangent, bitangent;
    orthonormalBasis(normal, tangent, bitangent);
    int open = 0;
    for (int k = 0; k < DIRECTIONS; ++k) {
        const vec3 d = cosineWeightedDirection(narrowConePoint(k, float(DIRECTIONS), vec2(0.0), -1));
        const vec3 direction = d.x * tangent + d.y * bitangent + d.z * normal;
        vec4 seen;
        if (!nearFieldHit(direction, seen)) ++open;
    }
    imageStore(uVisibility, cell, vec4(float(open) / float(DIRECTIONS)));
}

#else
// Weights shared by the two dispatches below.
// A tap a voxel off the tangent plane keeps e⁻¹ of its weight (sameSurfaceWeight).
const float kPlaneVoxels = 1.0;

// How much cell `cell` counts for the surface point (position, normal), times `w`; 0 outside the
// grid `cells` or on the sky.
float cellWeight(ivec2 cell, ivec2 cells, vec3 position, vec3 normal, float w) {
    if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, cells))) return 0.0;
    const ivec2 cellPixel = cell * uBlock;
    const vec4 cellPosition = texelFetch(uPosition, cellPixel, 0);
    if (!(cellPosition.w > 0.0)) return 0.0;
    const vec3 offset = (cellPosition.xyz - position) * uVoxelScale;
    return w * sameSurfaceWeight(normal, normalize(texelFetch(uNormal, cellPixel, 0).xyz), offset, kPlaneVoxels);
}

#ifdef NEAR_MEAN
layout(binding = TEXTURE_NEAR_VISIBILITY) uniform sampler2D uVisibility;
layout(rg32f, binding = IMAGE_NEAR_VISIBILITY) uniform writeonly image2D uMeans;  // (V, V̄) per cell
uniform int uTapSpacing;  // cells between the taps, so that the taps reach alike at any resolution

// 5 × 5 taps (3 pixels apart at 180 lines), a Gaussian of σ = 1 tap: wide enough that V̄ is the
// patch's mean, not the pixel's, and few enough to cost less than the cones' upsampling.
const int TAP_RADIUS = 2;
const float TAP_SIGMA = 1.0;

void main() {
    const ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 cells = imageSize(uMeans);
    if (any(greaterThanEqual(cell, cells))) return;
    const float own = texelFetch(uVisibility, cell, 0).r;
    const vec4 position = texelFetch(uPosition, cell * uBlock, 0);
    if (!(position.w > 0.0)) {
        imageStore(uMeans, cell, vec4(own, own, 0.0, 0.0));
        return;
    }
    const vec3 normal = normalize(texelFetch(uNormal, cell * uBlock, 0).xyz);
    const float inverseTwoSigma2 = 0.5 / (TAP_SIGMA * TAP_SIGMA);
    float weightSum = 0.0, visibilitySum = 0.0;
    for (int dy = -TAP_RADIUS; dy <= TAP_RADIUS; ++dy)
        for (int dx = -TAP_RADIUS; dx <= TAP_RADIUS; ++dx) {
            const ivec2 tap = cell + ivec2(dx, dy) * uTapSpacing;
            const float w = cellWeight(tap, cells, position.xyz, normal, exp(-float(dx * dx + dy * dy) * inverseTwoSigma2));
            weightSum += w;
            visibilitySum += w * texelFetch(uVisibility, tap, 0).r;
        }
    imageStore(uMeans, cell, vec4(own, visibilitySum / weightSum, 0.0, 0.0));  // its own tap weighs 1
}

#else
layout(binding = TEXTURE_NEAR_VISIBILITY) uniform sampler2D uMeans;  // (V, V̄) per cell
layout(binding = TEXTURE_INDIRECT) uniform sampler2D uIndirect;       // irradiance (rgb), visibility (a)
layout(rgba32f, binding = IMAGE_INDIRECT) uniform writeonly image2D uDetailed;

// The factor's range: where V̄ is tiny (a pixel deep in a crease among others like it) the ratio
// says little, and one pixel should not take many times its patch's light.
const float kLowestFactor = 0.25, kHighestFactor = 2.0;

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(uDetailed)))) return;
    const vec4 indirect = texelFetch(uIndirect, pixel, 0);
    const vec4 position = texelFetch(uPosition, pixel, 0);
    if (!(position.w > 0.0)) {
        imageStore(uDetailed, pixel, indirect);
        return;
    }
    const vec3 normal = normalize(texelFetch(uNormal, pixel, 0).xyz);
    // V and V̄ at the pixel: its own cell's, or between the cells around it on its own surface.
    const ivec2 cells = textureSize(uMeans, 0);
    const ivec2 base = pixel / uBlock;
    const vec2 fraction = vec2(pixel - base * uBlock) / float(uBlock);
    vec2 means = vec2(0.0);
    float weight = 0.0;
    for (int j = 0; j <= min(uBlock - 1, 1); ++j)
        for (int i = 0; i <= min(uBlock - 1, 1); ++i) {
            const float bilinear = (i == 0 ? 1.0 - fraction.x : fraction.x) * (j == 0 ? 1.0 - fraction.y : fraction.y);
            const ivec2 cell = base + ivec2(i, j);
            const float w = bilinear > 0.0 ? cellWeight(cell, cells, position.xyz, normal, bilinear) : 0.0;
            if (w > 0.0) means += w * texelFetch(uMeans, cell, 0).rg;
            weight += w;
        }
    // Where no cell nearby lies on the pixel's surface (a sliver thinner than a cell), it keeps
    // the cones' light as it is.
    const float factor = weight > 1e-3 && means.y > 0.0 ? clamp(means.x / means.y, kLowestFactor, kHighestFactor) : 1.0;
    imageStore(uDetailed, pixel, vec4(indirect.rgb * factor, indirect.a));
}
#endif
#endif
