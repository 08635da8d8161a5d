#version 450
// Final image: direct (shadowed) + emissive (+ indirect, with the GI pipeline), written as linear
// HDR and as a tone-mapped 8-bit sRGB image. With an AOV selected, that buffer is written instead
// (raw values in HDR, a visualisation in 8 bits). Frames jittered inside the pixel are averaged
// here, in linear HDR, and the 8-bit image shows the average: their indirect light weighted by the
// cones each traced (uIndirectWeight), the rest alike.
#include "math.glsl"
#include "tonemap.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = TEXTURE_GBUFFER_ALBEDO) uniform sampler2D uAlbedo;
layout(binding = TEXTURE_GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = TEXTURE_GBUFFER_POSITION) uniform sampler2D uPosition;
layout(binding = TEXTURE_GBUFFER_EMISSIVE) uniform sampler2D uEmissive;
layout(binding = TEXTURE_DIRECT) uniform sampler2D uDirect;
layout(binding = TEXTURE_DEBUG_IMAGE) uniform sampler2D uDebugImage;  // a debug view's linear colour, shown as it is
layout(binding = TEXTURE_INDIRECT) uniform sampler2D uIndirect;    // indirect irradiance (rgb), visibility (a)
layout(rgba32f, binding = IMAGE_HDR) uniform writeonly image2D uHdr;
layout(rgba8, binding = IMAGE_LDR) uniform writeonly image2D uLdr;
layout(rgba32f, binding = IMAGE_HDR_SUM) uniform image2D uHdrSum;  // Σ of the samples averaged so far
layout(rgba32f, binding = IMAGE_INDIRECT_SUM) uniform image2D uIndirectSum;  // Σ weight × indirect light, Σ weight

const int AOV_FINAL = 0;
const int AOV_DIRECT = 1;
const int AOV_ALBEDO = 2;
const int AOV_NORMAL = 3;
const int AOV_DEPTH = 4;
const int AOV_INDIRECT = 5;
const int AOV_AO = 6;
const int AOV_GI = 7;

uniform int uAov;
uniform float uExposure;     // 2^EV
uniform int uToneCurve;
uniform vec3 uEye;
uniform vec3 uForward;
uniform float uDepthScale;   // depth shown as white in the 8-bit depth view
uniform int uShowDebugImage;  // 0: no, 1: as it is (albedo), 2: tone-mapped (radiance)
uniform int uHasIndirect;
uniform float uGiScale;  // 1 in every accuracy measurement (DESIGN 5.3)
uniform int uSamplesInAverage;  // 1: this frame starts the average; n > 1: its n-th sample
uniform float uIndirectWeight;  // > 0: this sample's weight in the average of the indirect light

// Lambertian: outgoing radiance = ρ/π × irradiance, added with weight exactly uGiScale.
vec3 indirectRadiance(ivec2 pixel) {
    return uGiScale * texelFetch(uAlbedo, pixel, 0).rgb / PI * texelFetch(uIndirect, pixel, 0).rgb;
}

// The frame's own value at `pixel`: linear HDR (radiance, or the AOV's raw value) and coverage
// (0 = sky), less the cones' part, `indirect`, which accumulated frames average with other weights.
vec4 pixelValue(ivec2 pixel, out vec3 indirect) {
    indirect = vec3(0.0);
    if (uShowDebugImage != 0) return vec4(texelFetch(uDebugImage, pixel, 0).rgb, 1.0);
    vec4 position = texelFetch(uPosition, pixel, 0);
    bool sky = position.w <= 0.0;
    vec3 hdr;
    if (uAov == AOV_ALBEDO) {
        hdr = sky ? vec3(0.0) : texelFetch(uAlbedo, pixel, 0).rgb;
    } else if (uAov == AOV_NORMAL) {
        hdr = sky ? vec3(0.0) : texelFetch(uNormal, pixel, 0).xyz;
    } else if (uAov == AOV_DEPTH) {
        hdr = vec3(sky ? 0.0 : dot(position.xyz - uEye, uForward));
    } else if (uAov == AOV_INDIRECT) {
        hdr = vec3(0.0);
        if (!sky && uHasIndirect != 0) indirect = texelFetch(uIndirect, pixel, 0).rgb;  // irradiance, W/m²
    } else if (uAov == AOV_AO) {
        hdr = vec3(sky || uHasIndirect == 0 ? 1.0 : texelFetch(uIndirect, pixel, 0).a);
    } else if (uAov == AOV_GI) {
        // The indirect light the final image adds: what the reference's --indirect-out holds.
        hdr = vec3(0.0);
        if (!sky && uHasIndirect != 0) indirect = indirectRadiance(pixel);
    } else {
        hdr = texelFetch(uDirect, pixel, 0).rgb;
        // The direct AOV is what the reference's --direct-out holds: emission of the surface seen
        // plus light arriving straight from the lights.
        if (!sky) hdr += texelFetch(uEmissive, pixel, 0).rgb;
        if (uAov == AOV_FINAL && !sky && uHasIndirect != 0) indirect = indirectRadiance(pixel);
    }
    return vec4(hdr, sky ? 0.0 : 1.0);
}

// The 8-bit picture of a (possibly averaged) value: the tone curve for radiance, a visualisation
// for the other AOVs. `sky`: no sample of the pixel hit a surface.
vec3 displayed(vec3 hdr, bool sky) {
    if (uShowDebugImage != 0) return linearToSrgb(uShowDebugImage == 2 ? toneCurve(hdr * uExposure, uToneCurve) : hdr);
    if (uAov == AOV_ALBEDO) return linearToSrgb(hdr);
    if (uAov == AOV_NORMAL) return sky ? vec3(0.0) : hdr * 0.5 + 0.5;
    if (uAov == AOV_DEPTH) return vec3(sky ? 0.0 : 1.0 - clamp(hdr.x / uDepthScale, 0.0, 1.0));
    if (uAov == AOV_INDIRECT) return linearToSrgb(toneCurve(hdr / PI * uExposure, uToneCurve));
    if (uAov == AOV_AO) return hdr;
    return linearToSrgb(toneCurve(hdr * uExposure, uToneCurve));
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(uHdr)))) return;
    vec3 indirect;
    vec4 value = pixelValue(pixel, indirect);
    // Samples of one pixel add up in float in a fixed order (one invocation per pixel), so an
    // accumulated image is as deterministic as a single frame; the first sample is stored as it is.
    vec4 average = value + vec4(indirect, 0.0);
    vec4 indirectSum = vec4(indirect * uIndirectWeight, uIndirectWeight);
    if (uSamplesInAverage > 1) {
        vec4 sum = imageLoad(uHdrSum, pixel) + value;
        imageStore(uHdrSum, pixel, sum);
        indirectSum += imageLoad(uIndirectSum, pixel);
        average = sum / float(uSamplesInAverage) + vec4(indirectSum.rgb / indirectSum.a, 0.0);
    } else {
        imageStore(uHdrSum, pixel, value);
    }
    imageStore(uIndirectSum, pixel, indirectSum);
    imageStore(uHdr, pixel, average);
    imageStore(uLdr, pixel, vec4(displayed(average.rgb, average.a <= 0.0), 1.0));
}
