#version 450
#if defined(TRACE_LISTED) || defined(SMOOTH_LISTED)
layout(local_size_x = 64) in;  // one invocation per listed pixel
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif
// cone_upsample (with cone_trace at half or quarter resolution): every pixel's indirect irradiance
// from the traced pixels of the four nearest blocks (cone_trace.comp), each weighted by how near
// its block is (bilinear), how alike the normals are and how close the traced point lies to this
// pixel's tangent plane. Irradiance varies slowly along a surface but jumps across edges, so a neighbour on
// another surface must not count. Where none of the four shares the pixel's surface (a silhouette,
// the rim of a vase), the sixteen blocks around it are asked, each weighted by a tent twice as
// wide: a surface that the nearest traced pixels miss is usually met one block further, and a
// traced pixel two blocks away on the same plane is as good a source of slowly varying light. A
// pixel that none of those shares its surface with (a thin object) traces its own cones, so no
// pixel takes light from the wrong surface: the upsampling lists those pixels, and a second
// dispatch (TRACE_LISTED) traces them. Scattered among pixels that only interpolate, each would
// hold up its whole SIMD group; listed, every invocation of the second dispatch traces, but each
// still costs a whole trace, which is why the wider ring is asked first. Four cones of its own,
// which no filter averages, leave such a pixel far noisier than its neighbours (a leaf or a
// curtain's edge black or several times too bright); so a third dispatch (SMOOTH_LISTED) averages
// each listed pixel with the pixels around it on its own surface, listed or not, into a buffer,
// and a fourth writes the averages back (reading neighbours that are being rewritten would race).
#include "cone_march.glsl"
#include "cone_trace_common.glsl"

layout(binding = TEXTURE_TRACED_IRRADIANCE) uniform sampler2D uTraced;
layout(binding = TEXTURE_TRACED_PIXEL) uniform usampler2D uTracedPixel;

// Pixels that trace their own cones (packTracedPixel), their count in coneCounters.
layout(std430, binding = SSBO_OWN_TRACE_PIXELS) buffer OwnTracePixels { uint ownTracePixels[]; };

#ifdef TRACE_LISTED
void main() {
    const uint listed = linearInvocation();
    if (listed >= coneCounters[CONE_COUNTER_OWN_TRACES]) return;
    const ivec2 pixel = unpackTracedPixel(ownTracePixels[listed]);
    storeTraced(pixel, finishTrace(gatherPixel(pixel, texelFetch(uPosition, pixel, 0).xyz,
                                               normalize(texelFetch(uNormal, pixel, 0).xyz))));
}
#elif defined(SMOOTH_LISTED)
layout(std430, binding = SSBO_OWN_TRACE_SMOOTHED) buffer OwnTraceSmoothed { vec4 ownTraceSmoothed[]; };
uniform int uWriteBack;  // 0: average into ownTraceSmoothed; 1: write the averages into the image

// 5 × 5 pixels, a Gaussian of σ 1.5 pixels; a neighbour a voxel off the tangent plane keeps e⁻¹.
const int kSmoothRadius = 2;
const float kSmoothSigma = 1.5;
const float kPlaneVoxels = 1.0;

void main() {
    const uint listed = linearInvocation();
    if (listed >= coneCounters[CONE_COUNTER_OWN_TRACES]) return;
    const ivec2 pixel = unpackTracedPixel(ownTracePixels[listed]);
    if (uWriteBack != 0) {
        imageStore(uIndirect, pixel, ownTraceSmoothed[listed]);
        return;
    }
    const vec3 position = texelFetch(uPosition, pixel, 0).xyz;
    const vec3 normal = normalize(texelFetch(uNormal, pixel, 0).xyz);
    const ivec2 size = imageSize(uIndirect);
    vec4 sum = vec4(0.0);
    float weightSum = 0.0;
    for (int dy = -kSmoothRadius; dy <= kSmoothRadius; ++dy)
        for (int dx = -kSmoothRadius; dx <= kSmoothRadius; ++dx) {
            const ivec2 q = pixel + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            const vec4 qPosition = texelFetch(uPosition, q, 0);
            if (!(qPosition.w > 0.0)) continue;
            const float w = exp(-float(dx * dx + dy * dy) / (2.0 * kSmoothSigma * kSmoothSigma)) *
                            sameSurfaceWeight(normal, normalize(texelFetch(uNormal, q, 0).xyz),
                                              (qPosition.xyz - position) * uVoxelScale, kPlaneVoxels);
            sum += w * imageLoad(uIndirect, q);
            weightSum += w;
        }
    ownTraceSmoothed[listed] = sum / weightSum;  // the pixel itself weighs 1
}
#else
// Before any of that, a pixel that the last frame's light serves (pixel_carry.glsl: only the camera
// moved, and a pixel of the last frame saw this surface point; cone_carry.comp found which) takes
// it. Every pixel records the point its light belongs to and its normal, for the next frame.
#include "carried_light.glsl"
layout(binding = TEXTURE_CARRIED_FROM) uniform usampler2D uCarriedFrom;
layout(rgba32f, binding = IMAGE_PIXEL_AT) uniform writeonly image2D uPixelAt;
layout(rgba8_snorm, binding = IMAGE_PIXEL_NORMAL) uniform writeonly image2D uPixelNormal;

// Weights of a neighbour (sameSurfaceWeight): a point one voxel off the tangent plane keeps e⁻¹
// of it; below kMinWeight the pixel has no neighbour on its surface.
const float kPlaneVoxels = 1.0;
const float kMinWeight = 0.05;

// The traced pixels of the blocks within `radius` blocks of `at` (the pixel in block units) that
// share the surface at `position` with `normal`: their irradiance summed,
// each weighted by a tent of that radius (bilinear for radius 1) and by sameSurfaceWeight; the
// sum of the weights in `weightSum`.
vec4 sameSurfaceTraced(vec3 position, vec3 normal, vec2 at, int radius, out float weightSum) {
    const ivec2 blocks = textureSize(uTraced, 0);
    const ivec2 base = ivec2(floor(at));
    const vec2 f = at - vec2(base);
    vec4 sum = vec4(0.0);
    weightSum = 0.0;
    for (int y = 1 - radius; y <= radius; ++y)
        for (int x = 1 - radius; x <= radius; ++x) {
            const ivec2 offset = ivec2(x, y);
            const ivec2 cell = clamp(base + offset, ivec2(0), blocks - 1);
            const uint traced = texelFetch(uTracedPixel, cell, 0).r;
            if (traced == NO_TRACED_PIXEL) continue;
            const ivec2 tracedPixel = unpackTracedPixel(traced);
            const vec3 tracedNormal = normalize(texelFetch(uNormal, tracedPixel, 0).xyz);
            const vec3 tracedPosition = texelFetch(uPosition, tracedPixel, 0).xyz;
            const vec2 tent = max(1.0 - abs(vec2(offset) - f) / float(radius), 0.0);
            const float weight = tent.x * tent.y * sameSurfaceWeight(normal, tracedNormal,
                                                                     (tracedPosition - position) * uVoxelScale, kPlaneVoxels);
            sum += weight * texelFetch(uTraced, cell, 0);
            weightSum += weight;
        }
    return sum;
}

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(uIndirect)))) return;
    const vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w <= 0.0) {
        imageStore(uIndirect, pixel, vec4(0.0, 0.0, 0.0, 1.0));
        imageStore(uPixelAt, pixel, vec4(0.0));
        count64(CONE_COUNTER_SKY_PIXELS, 1u);
        return;
    }
    const vec3 normal = normalize(texelFetch(uNormal, pixel, 0).xyz);
    const uint carriedFrom = uCarry != 0 ? texelFetch(uCarriedFrom, pixel, 0).r : NO_TRACED_PIXEL;
    if (carriedFrom != NO_TRACED_PIXEL) {
        const ivec2 carried = unpackTracedPixel(carriedFrom);
        imageStore(uIndirect, pixel, texelFetch(uCarriedIrradiance, carried, 0));
        imageStore(uPixelAt, pixel, texelFetch(uCarriedAt, carried, 0) + vec4(0.0, 0.0, 0.0, 1.0));  // a frame older
        imageStore(uPixelNormal, pixel, texelFetch(uCarriedNormal, carried, 0));
        count64(CONE_COUNTER_CARRIED_PIXELS, 1u);
        return;
    }
    imageStore(uPixelAt, pixel, vec4(position.xyz, 1.0));
    imageStore(uPixelNormal, pixel, vec4(normal, 0.0));
    // Block centres sit at B·cell + (B − 1)/2 in pixels.
    const vec2 at = (vec2(pixel) + 0.5) / float(uDownscale) - 0.5;
    float weightSum;
    vec4 sum = sameSurfaceTraced(position.xyz, normal, at, 1, weightSum);
    if (weightSum < kMinWeight) sum = sameSurfaceTraced(position.xyz, normal, at, 2, weightSum);
    if (weightSum >= kMinWeight) {
        imageStore(uIndirect, pixel, sum / weightSum);
        return;
    }
    ownTracePixels[atomicAdd(coneCounters[CONE_COUNTER_OWN_TRACES], 1u)] = packTracedPixel(pixel);
}
#endif
