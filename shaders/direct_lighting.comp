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
        if (cosTheta > 0.0 && any(greaterThan(irradiance, vec3(0.0))))
            radiance = albedo / PI * irradiance * cosTheta *
                       shadowVisibility(position.xyz, n, toLight, distanceToLight);
    }
    if (uAccumulate != 0) radiance += imageLoad(uDirect, pixel).rgb;
    imageStore(uDirect, pixel, vec4(radiance, 1.0));
}
