#version 450
// Final image: direct (shadowed) + emissive (+ indirect, with the GI pipeline), written as linear
// HDR and as a tone-mapped 8-bit sRGB image. With an AOV selected, that buffer is written instead
// (raw values in HDR, a visualisation in 8 bits).
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

const int AOV_FINAL = 0;
const int AOV_DIRECT = 1;
const int AOV_ALBEDO = 2;
const int AOV_NORMAL = 3;
const int AOV_DEPTH = 4;
const int AOV_INDIRECT = 5;
const int AOV_AO = 6;

uniform int uAov;
uniform float uExposure;     // 2^EV
uniform int uToneCurve;
uniform vec3 uEye;
uniform vec3 uForward;
uniform float uDepthScale;   // depth shown as white in the 8-bit depth view
uniform int uShowDebugImage;  // 0: no, 1: as it is (albedo), 2: tone-mapped (radiance)
uniform int uHasIndirect;
uniform float uGiScale;  // 1 in every accuracy measurement (DESIGN 5.3)

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(uHdr)))) return;
    vec4 position = texelFetch(uPosition, pixel, 0);
    bool sky = position.w <= 0.0;
    vec3 hdr;
    vec3 ldr;
    if (uShowDebugImage != 0) {
        hdr = texelFetch(uDebugImage, pixel, 0).rgb;
        ldr = linearToSrgb(uShowDebugImage == 2 ? toneCurve(hdr * uExposure, uToneCurve) : hdr);
        sky = false;
    } else if (uAov == AOV_ALBEDO) {
        hdr = sky ? vec3(0.0) : texelFetch(uAlbedo, pixel, 0).rgb;
        ldr = linearToSrgb(hdr);
    } else if (uAov == AOV_NORMAL) {
        hdr = sky ? vec3(0.0) : texelFetch(uNormal, pixel, 0).xyz;
        ldr = sky ? vec3(0.0) : hdr * 0.5 + 0.5;
    } else if (uAov == AOV_DEPTH) {
        float depth = sky ? 0.0 : dot(position.xyz - uEye, uForward);
        hdr = vec3(depth);
        ldr = vec3(sky ? 0.0 : 1.0 - clamp(depth / uDepthScale, 0.0, 1.0));
    } else if (uAov == AOV_INDIRECT) {
        hdr = (sky || uHasIndirect == 0) ? vec3(0.0) : texelFetch(uIndirect, pixel, 0).rgb;  // irradiance, W/m²
        ldr = linearToSrgb(toneCurve(hdr / PI * uExposure, uToneCurve));
    } else if (uAov == AOV_AO) {
        hdr = vec3(sky || uHasIndirect == 0 ? 1.0 : texelFetch(uIndirect, pixel, 0).a);
        ldr = hdr;
    } else {
        hdr = texelFetch(uDirect, pixel, 0).rgb;
        // The direct AOV is what the reference's --direct-out holds: emission of the surface seen
        // plus light arriving straight from the lights.
        if (!sky) hdr += texelFetch(uEmissive, pixel, 0).rgb;
        if (uAov == AOV_FINAL && !sky) {
            // Lambertian: outgoing radiance = ρ/π × irradiance, added with weight exactly uGiScale.
            if (uHasIndirect != 0)
                hdr += uGiScale * texelFetch(uAlbedo, pixel, 0).rgb / PI * texelFetch(uIndirect, pixel, 0).rgb;
        }
        ldr = linearToSrgb(toneCurve(hdr * uExposure, uToneCurve));
    }
    imageStore(uHdr, pixel, vec4(hdr, sky ? 0.0 : 1.0));
    imageStore(uLdr, pixel, vec4(ldr, 1.0));
}
