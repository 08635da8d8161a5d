// Buffers of the radiance volume (engine/lighting/radiance_volume.hpp). Requires octree.glsl.
layout(std430, binding = 6) buffer ListCounts { uint listCounts[]; };  // touched [0..11], border [12..23], missed [24]
layout(std430, binding = 13) buffer RadianceAccumulators { uint radianceAccumulator[]; };  // 6 per cell
layout(std430, binding = 14) buffer TouchedFlag { uint touchedFlag[]; };
layout(std430, binding = 15) buffer TouchedList { uint touchedList[]; };
layout(std430, binding = 16) buffer BorderFlag { uint borderFlag[]; };
layout(std430, binding = 17) buffer BorderList { uint borderList[]; };
layout(std430, binding = 18) buffer CellRadiance { vec4 cellRadiance[]; };  // premultiplied (L·α, α)

const uint BORDER_COUNTS = 12u;
const uint MISSED_COUNT = 24u;

// Marks `node` of `level` touched; the first to do so appends it to the level's list.
void touch(uint node, int level) {
    if (atomicExchange(touchedFlag[node], 1u) == 0u) {
        uint slot = atomicAdd(listCounts[level], 1u);
        touchedList[uLevelStart[level] + slot] = node;
    }
}

// 64-bit fixed-point accumulation: low word, carry into the high word. Exact and
// order-independent, so the result does not depend on thread scheduling.
void accumulate64(uint index, uint value) {
    uint old = atomicAdd(radianceAccumulator[index], value);
    if (old + value < old) atomicAdd(radianceAccumulator[index + 1u], 1u);
}
