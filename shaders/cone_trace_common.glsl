// Shared by cone_trace.comp and cone_upsample.comp. Requires cone_march.glsl.
#include "traced_pixel.glsl"
#include "cone_lanes.glsl"
#include "cone_counters.glsl"

layout(binding = TEXTURE_GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = TEXTURE_GBUFFER_POSITION) uniform sampler2D uPosition;
layout(binding = TEXTURE_GBUFFER_GEOMETRIC_NORMAL) uniform sampler2D uGeometricNormal;
#ifdef SCREEN_NEAR_FIELD
#include "near_field.glsl"
#endif
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

// The surface point of `pixel` (scene-local position, unit normal facing the camera): what this
// invocation's cones gather there (gatherIrradiance: E in rgb, Σ weight·opacity in a), its samples
// counted. No light arrives from behind the pixel's triangle (gatherIrradiance), however far
// smooth shading leans the normal from it. The pixel's block of traced pixels continues one
// sequence of narrow-cone directions over the samples (narrowConeShift).
vec4 gatherPixel(ivec2 pixel, vec3 position, vec3 normal) {
    enterConeLane();
#ifdef SCREEN_NEAR_FIELD
    nearFieldPoint = position;
    nearFieldNormal = normal;
    nearFieldJitter = hashToUnitSquare(vec3(vec2(pixel), float(uRaySequence))).x;
#endif
    const vec3 origin = (position - uVoxelOrigin) * uVoxelScale + normal * uConeOffset;
    const vec4 gathered = gatherIrradiance(origin, normal, texelFetch(uGeometricNormal, pixel, 0).xyz,
                                           narrowConeShift(pixel / uDownscale));
    count64(CONE_COUNTER_SAMPLES, samplesTaken);
    count64(CONE_COUNTER_SAMPLES_SAVED, samplesSaved);
    return gathered;
}

// A pixel's gathered cones (sumConeLanes) as indirect irradiance E (rgb) and ambient visibility
// (a: 1 = nothing in the way), counted as one traced pixel. A dispatch that continues the trace
// returns its part: the irradiance its cones add and the visibility they take away (storeTraced
// adds it).
vec4 finishTrace(vec4 gathered) {
    if (!continuesTrace()) count64(CONE_COUNTER_TRACED_PIXELS, 1u);
    return vec4(gathered.rgb, (continuesTrace() ? 0.0 : 1.0) - gathered.a / PI);
}
