// Shared by cone_trace.comp and cone_upsample.comp. Requires cone_march.glsl.
#include "traced_pixel.glsl"

// What the cone passes did and saved, as 64-bit counts (low word, high word): samples taken,
// samples that empty-space skipping saved (the steps the skipped nodes would have cost), pixels
// that saw the sky, pixels whose own cones were traced. Read back by ConeTrace::statistics.
// Then the length of cone_upsample's list of pixels that trace their own cones.
layout(std430, binding = SSBO_CONE_COUNTERS) buffer ConeCounters { uint coneCounters[9]; };

const uint CONE_COUNTER_SAMPLES = 0u;
const uint CONE_COUNTER_SAMPLES_SAVED = 2u;
const uint CONE_COUNTER_SKY_PIXELS = 4u;
const uint CONE_COUNTER_TRACED_PIXELS = 6u;
const uint CONE_COUNTER_OWN_TRACES = 8u;

void count64(uint index, uint value) {
    if (value == 0u) return;
    uint old = atomicAdd(coneCounters[index], value);
    if (old + value < old) atomicAdd(coneCounters[index + 1u], 1u);
}

layout(binding = TEXTURE_GBUFFER_GEOMETRIC_NORMAL) uniform sampler2D uGeometricNormal;
uniform int uDownscale;  // pixels per side of a traced block: 1 (every pixel), 2 or 4
// Where the traced irradiance goes: the indirect image, or the traced blocks' image.
layout(rgba32f, binding = IMAGE_INDIRECT) uniform image2D uIndirect;

// Whether this dispatch continues what earlier ones traced for the same pixels (narrow cones
// traced a few per dispatch: cone_march.glsl, uRayFirst).
bool continuesTrace() { return uRayFirst > 0; }

// Stores what tracePixel returned for `at`, added to what the dispatches before stored there.
void storeTraced(ivec2 at, vec4 traced) {
    imageStore(uIndirect, at, continuesTrace() ? imageLoad(uIndirect, at) + traced : traced);
}

// The invocations that trace one pixel's cones side by side (the work group's z, CONE_LANES of
// them, cone_trace.cpp): each traces every CONE_LANES-th cone (cone_march.glsl, coneLane), and
// the group adds their parts in shared memory. A GPU hides the latency of a cone's dependent
// lookups only with many invocations in flight, and a frame's few traced pixels (one per block)
// are too few for that; a pixel's cones in one invocation also make its runtime the sum of their
// lengths. With one lane per cone of the dispatch (or one lane for all), the parts are added in
// the cones' order, the order one invocation adds them in: the same bits either way.
#ifndef CONE_LANES
#define CONE_LANES 1
#endif
#if CONE_LANES > 1
shared vec4 coneLaneParts[gl_WorkGroupSize.x * gl_WorkGroupSize.y * CONE_LANES];
#endif

// The surface point of `pixel` (scene-local position, unit normal facing the camera): what this
// invocation's cones gather there (gatherIrradiance: E in rgb, Σ weight·opacity in a), its samples
// counted. No light arrives from behind the pixel's triangle (gatherIrradiance), however far
// smooth shading leans the normal from it. The pixel's block of traced pixels continues one
// sequence of narrow-cone directions over the samples (narrowConeShift).
vec4 gatherPixel(ivec2 pixel, vec3 position, vec3 normal) {
    coneLane = int(gl_LocalInvocationID.z);
    coneLanes = CONE_LANES;
    const vec3 origin = (position - uVoxelOrigin) * uVoxelScale + normal * uConeOffset;
    const vec4 gathered = gatherIrradiance(origin, normal, texelFetch(uGeometricNormal, pixel, 0).xyz,
                                           narrowConeShift(pixel / uDownscale));
    count64(CONE_COUNTER_SAMPLES, samplesTaken);
    count64(CONE_COUNTER_SAMPLES_SAVED, samplesSaved);
    return gathered;
}

// The sum of the lanes' parts of this invocation's pixel. Every invocation of the group calls it
// (it holds a barrier), whether it traced or not (a part of zero).
vec4 sumConeLanes(vec4 part) {
#if CONE_LANES > 1
    const uint pixelsPerLane = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
    const uint pixelSlot = gl_LocalInvocationIndex % pixelsPerLane;
    coneLaneParts[gl_LocalInvocationIndex] = part;
    barrier();
    precise vec4 sum = vec4(0.0);  // unfused, as in gatherNarrowCones
    for (uint lane = 0u; lane < uint(CONE_LANES); ++lane) sum += coneLaneParts[pixelSlot + lane * pixelsPerLane];
    return sum;
#else
    return part;
#endif
}

// Whether this invocation stores its pixel's result: the first lane.
bool storesConeLanes() { return gl_LocalInvocationID.z == 0u; }

// A pixel's gathered cones (sumConeLanes) as indirect irradiance E (rgb) and ambient visibility
// (a: 1 = nothing in the way), counted as one traced pixel. A dispatch that continues the trace
// returns its part: the irradiance its cones add and the visibility they take away (storeTraced
// adds it).
vec4 finishTrace(vec4 gathered) {
    if (!continuesTrace()) count64(CONE_COUNTER_TRACED_PIXELS, 1u);
    return vec4(gathered.rgb, (continuesTrace() ? 0.0 : 1.0) - gathered.a / PI);
}
