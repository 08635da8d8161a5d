#version 450
#ifdef SUM_CONE_LANES
layout(local_size_x = 64) in;
#else
layout(local_size_x = 64, local_size_z = CONE_LANES) in;
#endif
// cone_trace (DESIGN §4 pass 12, §5.5): diffuse cones over the hemisphere around the normal march
// through the radiance bricks (cone_march.glsl) and add up to the indirect irradiance E.
// Output: E (rgb) and ambient visibility (a: 1 = nothing in the way).
//
// It traces the cells of the traced image that cone_carry.comp listed (those whose light it could
// not carry over from the last frame), one per invocation, from the pixel the list names: with
// uDownscale = 1 every pixel is a cell, traced straight into the indirect image; with B = 2 or 4,
// one pixel of each B×B block (block_pixel.glsl) into an image 1/B the size per side, which
// cone_upsample.comp spreads over the pixels that share its surface. Listed, every invocation of a
// SIMD group traces, wherever its cell lies.
// The work group's z holds the lanes that share each pixel's cones (cone_lanes.glsl). Each lane
// stores its part, and the same list run again with SUM_CONE_LANES adds the parts in the cones'
// order and stores the cell: a sum in shared memory behind a barrier came out wrong on a GPU.
#if CONE_LANES > 1
#define CONE_LANE_PARTS_IN_BUFFER 1
#endif
#include "cone_march.glsl"
#include "cone_trace_common.glsl"

// The pixels to trace (packTracedPixel), one per listed cell, their count in coneCounters.
layout(std430, binding = SSBO_TRACE_CELLS) readonly buffer TraceCells { uint traceCells[]; };

#if CONE_LANES > 1
// Each listed cell's lanes' parts, CONE_LANES in a row.
layout(std430, binding = SSBO_CONE_LANE_PARTS) buffer ConeLaneParts { vec4 laneParts[]; };
#endif

#ifdef SUM_CONE_LANES
void main() {
    const uint listed = linearInvocation();
    if (listed >= coneCounters[CONE_COUNTER_TRACE_CELLS]) return;
    precise vec4 gathered = vec4(0.0);  // in the cones' order, unfused, as one lane adds them
    for (uint lane = 0u; lane < uint(CONE_LANES); ++lane) gathered += laneParts[listed * uint(CONE_LANES) + lane];
    storeTraced(unpackTracedPixel(traceCells[listed]) / uDownscale, finishTrace(gathered));
}
#else
void main() {
    const uint listed = linearInvocation();
    const bool traces = listed < coneCounters[CONE_COUNTER_TRACE_CELLS];
    const ivec2 pixel = traces ? unpackTracedPixel(traceCells[listed]) : ivec2(0);
    const ivec2 cell = pixel / uDownscale;
    const vec4 position = traces ? texelFetch(uPosition, pixel, 0) : vec4(0.0);
#ifdef STORE_CONE_SAMPLES
    if (traces) coneSampleCell = cell;
#endif
    const vec4 part = traces ? gatherPixel(pixel, position.xyz, normalize(texelFetch(uNormal, pixel, 0).xyz)) : vec4(0.0);
#if CONE_LANES > 1
    if (traces) laneParts[listed * uint(CONE_LANES) + gl_LocalInvocationID.z] = part;
#else
    if (traces) storeTraced(cell, finishTrace(part));
#endif
}
#endif
