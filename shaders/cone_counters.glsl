// What the cone passes did and saved (cone_carry.comp, cone_trace.comp, cone_upsample.comp), as
// 64-bit counts (low word, high word): samples taken, samples that empty-space skipping saved (the
// steps the skipped nodes would have cost), pixels that saw the sky, pixels whose own cones were
// traced, pixels that took the last frame's light (pixel_carry.glsl). Then the lengths of two lists: cone_upsample's
// pixels that trace their own cones, and cone_carry's cells that cone_trace traces. Read back by
// ConeTrace::statistics.
layout(std430, binding = SSBO_CONE_COUNTERS) buffer ConeCounters { uint coneCounters[CONE_COUNTER_WORDS]; };

const uint CONE_COUNTER_SAMPLES = 0u;
const uint CONE_COUNTER_SAMPLES_SAVED = 2u;
const uint CONE_COUNTER_SKY_PIXELS = 4u;
const uint CONE_COUNTER_TRACED_PIXELS = 6u;
const uint CONE_COUNTER_CARRIED_PIXELS = 8u;
const uint CONE_COUNTER_OWN_TRACES = OWN_TRACE_COUNT_SLOT;
const uint CONE_COUNTER_TRACE_CELLS = TRACE_CELL_COUNT_SLOT;

void count64(uint index, uint value) {
    if (value == 0u) return;
    uint old = atomicAdd(coneCounters[index], value);
    if (old + value < old) atomicAdd(coneCounters[index + 1u], 1u);
}
