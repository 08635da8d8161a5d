#version 450
layout(local_size_x = 8, local_size_y = 8) in;
// cone_trace (DESIGN §4 pass 12, §5.5): per pixel, diffuse cones over the hemisphere around the
// normal march through the radiance bricks (cone_march.glsl) and add up to the indirect
// irradiance E. Output: E (rgb) and ambient visibility (a: 1 = nothing in the way).
#include "cone_march.glsl"

layout(binding = TEXTURE_GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = TEXTURE_GBUFFER_POSITION) uniform sampler2D uPosition;
layout(rgba32f, binding = IMAGE_INDIRECT) uniform writeonly image2D uIndirect;
// What the pass did and saved, as 64-bit counts (low, high): samples taken, samples that empty-
// space skipping saved (the steps the skipped nodes would have cost), pixels that saw the sky.
layout(std430, binding = SSBO_CONE_COUNTERS) buffer Counters { uint counters[6]; };
void count64(uint index, uint value) {
    if (value == 0u) return;
    uint old = atomicAdd(counters[index], value);
    if (old + value < old) atomicAdd(counters[index + 1u], 1u);
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(uIndirect)))) return;
    vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w <= 0.0) {  // sky: no GI work
        imageStore(uIndirect, pixel, vec4(0.0, 0.0, 0.0, 1.0));
        count64(4u, 1u);
        return;
    }
    vec3 normal = normalize(texelFetch(uNormal, pixel, 0).xyz);
    vec3 origin = (position.xyz - uVoxelOrigin) * uVoxelScale + normal * uConeOffset;
    vec4 gathered = gatherIrradiance(origin, normal);
    imageStore(uIndirect, pixel, vec4(gathered.rgb, 1.0 - gathered.a / PI));
    count64(0u, samplesTaken);
    count64(2u, samplesSaved);
}
