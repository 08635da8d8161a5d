// Cone lanes: the invocations that trace the cones of one apex side by side, in the work group's
// z (CONE_LANES of them; cone_trace.cpp, coneLanes). Requires cone_march.glsl.
//
// Each lane traces every CONE_LANES-th cone from its own (cone_march.glsl, coneLane). The bounce
// gathers add the lanes' parts in shared memory (sumConeLanes); cone_trace.comp
// (CONE_LANE_PARTS_IN_BUFFER) has each lane store its part and a second dispatch add them, as on
// an H200 the shared-memory sum of the narrow cones came out wrong. A GPU hides the latency of a
// cone's dependent lookups only with many invocations in flight, and the apexes that trace are
// too few for that (a frame's one pixel per block, a bounce's gathering voxels); an apex's cones
// in one invocation also make its runtime the sum of their lengths. With one lane per cone (or
// one lane for all), the parts are added in the cones' order, the order one invocation adds them
// in: the same bits either way.
#ifndef CONE_LANES
#define CONE_LANES 1
#endif
#if CONE_LANES > 1 && !defined(CONE_LANE_PARTS_IN_BUFFER)
#define CONE_LANES_SHARED 1
shared vec4 coneLaneParts[gl_WorkGroupSize.x * gl_WorkGroupSize.y * CONE_LANES];
#endif

// Makes this invocation's cones its lane's (before gatherIrradiance).
void enterConeLane() {
    coneLane = int(gl_LocalInvocationID.z);
    coneLanes = CONE_LANES;
}

// The sum of the lanes' parts of this invocation's apex. Every invocation of the group calls it
// (it holds barriers), whether it traced or not (a part of zero); it may be called again.
vec4 sumConeLanes(vec4 part) {
#ifdef CONE_LANES_SHARED
    const uint apexesPerLane = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
    const uint apexSlot = gl_LocalInvocationIndex % apexesPerLane;
    coneLaneParts[gl_LocalInvocationIndex] = part;
    barrier();
    precise vec4 sum = vec4(0.0);  // unfused, as in gatherIrradiance
    for (uint lane = 0u; lane < uint(CONE_LANES); ++lane) sum += coneLaneParts[apexSlot + lane * apexesPerLane];
    barrier();  // every lane has read the parts before they are written again
    return sum;
#else
    return part;
#endif
}

// Whether this invocation stores its apex's result: the first lane.
bool storesConeLanes() { return gl_LocalInvocationID.z == 0u; }
