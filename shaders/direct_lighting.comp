#version 450
// Direct Lambertian lighting from one light with its shadow: L = ρ/π · E · cosθ · visibility.
// Dispatched once per light; uAccumulate adds into the image instead of overwriting it.
#include "lights.glsl"
#include "shadow.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = TEXTURE_GBUFFER_ALBEDO) uniform sampler2D uAlbedo;
layout(binding = TEXTURE_GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = TEXTURE_GBUFFER_POSITION) uniform sampler2D uPosition;
layout(rgba32f, binding = IMAGE_DIRECT) uniform image2D uDirect;

uniform LightParams uLight;
uniform int uAccumulate;
uniform vec3 uCameraEye;        // scene-local
uniform float uPixelWidth;      // a pixel's width at distance 1 from the eye
uniform float uSampleFootprint; // 1: the first sample; < 1: a later one's share of the pixel (pixel_samples.hpp)

// The span of the pixel sample on its surface, as two vectors in the tangent plane from the
// neighbouring pixels' points (the pixel's footprint is the parallelogram ±½ of each): the first
// sample, alone in a plain frame, integrates its whole pixel; a later, jittered one the same
// parallelogram shrunk to its share, as its texture lookups do (material.glsl): the jitter
// integrates the rest. A neighbour far away or sky (a silhouette) is no part of the footprint; one close by
// on another surface (a floor's contact line with a wall or a box) would put taps under that
// surface, where the camera sees no floor and the map sees shadow: there, and where an axis has
// no neighbour on the pixel's surface, the span is 0 and the filter keeps its texels.
// "Far" is 8 pixel widths, or 3 times the neighbours' spacing on a surface seen at a grazing
// angle, a pixel's width over the cosine (up to 16): a floor seen at 4° has its neighbouring rows
// 13 pixel widths apart, and with them taken for a silhouette its pixels sampled the shadow map at
// their centres, where a shadow line a quarter of a pixel wide blacked out a whole row of them.
void sampleSpan(ivec2 pixel, vec3 p, vec3 n, out vec3 spanX, out vec3 spanY) {
    spanX = spanY = vec3(0.0);
    vec3 toEye = uCameraEye - p;
    float eyeDistance = length(toEye), facing = eyeDistance * uPixelWidth;
    float reach = max(8.0 * facing, 3.0 * facing / max(abs(dot(toEye, n)) / eyeDistance, 1.0 / 16.0));
    ivec2 last = imageSize(uDirect) - 1;
    vec3 span[2] = vec3[2](vec3(0.0), vec3(0.0));
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            ivec2 next = clamp(pixel + ivec2(x, y), ivec2(0), last);
            vec4 q = texelFetch(uPosition, next, 0);
            vec3 offset = q.xyz - p;
            float d = length(offset);
            if (q.w <= 0.0 || d >= reach || d == 0.0) continue;
            bool samePlane = dot(texelFetch(uNormal, next, 0).xyz, n) >= 0.9 && abs(dot(offset, n)) <= 0.25 * d;
            if (!samePlane) return;
            if (y == 0) span[0] = float(x) * offset;
            if (x == 0) span[1] = float(y) * offset;
        }
    if (span[0] == vec3(0.0) || span[1] == vec3(0.0)) return;
    spanX = span[0] * uSampleFootprint;
    spanY = span[1] * uSampleFootprint;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(uDirect)))) return;
    vec4 position = texelFetch(uPosition, pixel, 0);
    vec3 radiance = vec3(0.0);
    if (position.w > 0.0) {  // sky pixels get no light
        vec3 albedo = texelFetch(uAlbedo, pixel, 0).rgb;
        vec3 n = texelFetch(uNormal, pixel, 0).xyz;
        vec3 toLight;
        float distanceToLight;
        vec3 irradiance = incidentIrradiance(uLight, position.xyz, toLight, distanceToLight);
        float cosTheta = dot(n, toLight);
        if (cosTheta > 0.0 && any(greaterThan(irradiance, vec3(0.0)))) {
            vec3 spanX, spanY;
            sampleSpan(pixel, position.xyz, n, spanX, spanY);
            radiance = albedo / PI * irradiance * cosTheta *
                       shadowVisibility(position.xyz, n, toLight, distanceToLight, spanX, spanY);
        }
    }
    if (uAccumulate != 0) radiance += imageLoad(uDirect, pixel).rgb;
    imageStore(uDirect, pixel, vec4(radiance, 1.0));
}
