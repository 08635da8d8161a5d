#version 450
#ifdef TRACE_LISTED
layout(local_size_x = 64) in;
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif
// cone_upsample (with cone_trace at half or quarter resolution): every pixel's indirect irradiance
// from the traced pixels of the four nearest blocks (cone_trace.comp), each weighted by how near
// its block is (bilinear), how alike the normals are and how close the traced point lies to this
// pixel's tangent plane. Irradiance varies slowly along a surface but jumps across edges, so a neighbour on
// another surface must not count. A pixel that no neighbour shares its surface with (a thin
// object, a silhouette) traces its own cones, so no pixel takes light from the wrong surface:
// the upsampling lists those pixels, and a second dispatch (TRACE_LISTED) traces them. Scattered
// among pixels that only interpolate, each would hold up its whole SIMD group; listed, every
// invocation of the second dispatch traces.
#include "cone_march.glsl"
#include "cone_trace_common.glsl"

layout(binding = TEXTURE_GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = TEXTURE_GBUFFER_POSITION) uniform sampler2D uPosition;
layout(binding = TEXTURE_TRACED_IRRADIANCE) uniform sampler2D uTraced;
layout(binding = TEXTURE_TRACED_PIXEL) uniform usampler2D uTracedPixel;

uniform int uDownscale;  // pixels per side of a traced block: 2 or 4

// Pixels that trace their own cones (packTracedPixel), their count in coneCounters.
layout(std430, binding = SSBO_OWN_TRACE_PIXELS) buffer OwnTracePixels { uint ownTracePixels[]; };

#ifdef TRACE_LISTED
void main() {
    const uint listed = linearInvocation();
    if (listed >= coneCounters[CONE_COUNTER_OWN_TRACES]) return;
    const ivec2 pixel = unpackTracedPixel(ownTracePixels[listed]);
    const vec3 position = texelFetch(uPosition, pixel, 0).xyz;
    storeTraced(pixel, tracePixel(pixel, pixel / uDownscale, position, normalize(texelFetch(uNormal, pixel, 0).xyz)));
}
#else

// Weights of a neighbour (sameSurfaceWeight): a point one voxel off the tangent plane keeps e⁻¹
// of it; below kMinWeight the pixel has no neighbour on its surface.
const float kPlaneVoxels = 1.0;
const float kMinWeight = 0.05;

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(uIndirect)))) return;
    const vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w <= 0.0) {
        imageStore(uIndirect, pixel, vec4(0.0, 0.0, 0.0, 1.0));
        count64(CONE_COUNTER_SKY_PIXELS, 1u);
        return;
    }
    const vec3 normal = normalize(texelFetch(uNormal, pixel, 0).xyz);
    const ivec2 blocks = textureSize(uTraced, 0);
    // Block centres sit at B·cell + (B − 1)/2 in pixels: the four around this pixel and their
    // bilinear weights.
    const vec2 at = (vec2(pixel) + 0.5) / float(uDownscale) - 0.5;
    const ivec2 base = ivec2(floor(at));
    const vec2 f = at - vec2(base);
    vec4 sum = vec4(0.0);
    float weightSum = 0.0;
    for (int k = 0; k < 4; ++k) {
        const ivec2 offset = ivec2(k & 1, k >> 1);
        const ivec2 cell = clamp(base + offset, ivec2(0), blocks - 1);
        const uint traced = texelFetch(uTracedPixel, cell, 0).r;
        if (traced == NO_TRACED_PIXEL) continue;
        const ivec2 tracedPixel = unpackTracedPixel(traced);
        const vec3 tracedNormal = normalize(texelFetch(uNormal, tracedPixel, 0).xyz);
        const vec3 tracedPosition = texelFetch(uPosition, tracedPixel, 0).xyz;
        const float bilinear = (offset.x == 1 ? f.x : 1.0 - f.x) * (offset.y == 1 ? f.y : 1.0 - f.y);
        const float weight = bilinear * sameSurfaceWeight(normal, tracedNormal,
                                                          (tracedPosition - position.xyz) * uVoxelScale, kPlaneVoxels);
        sum += weight * texelFetch(uTraced, cell, 0);
        weightSum += weight;
    }
    if (weightSum >= kMinWeight) {
        imageStore(uIndirect, pixel, sum / weightSum);
        return;
    }
    ownTracePixels[atomicAdd(coneCounters[CONE_COUNTER_OWN_TRACES], 1u)] = packTracedPixel(pixel);
}
#endif
