// Buffers of the radiance volume (engine/lighting/radiance_volume.hpp). Requires octree.glsl.
layout(std430, binding = 6) buffer ListCounts { uint listCounts[]; };  // touched [0..11], border [12..23], missed [24]
// Per cell: reflected flux R, G, B as 64-bit fixed point (low, high words) [0..5]; the lit-side
// normals of the photons summed as two's-complement integers × LIT_NORMAL_SCALE [6..8]; the
// photon count [9].
const uint ACCUMULATOR_WORDS = 10u;
const float LIT_NORMAL_SCALE = 31.0;  // 2^31 / 31: 69 M photons per voxel before a sum could wrap
layout(std430, binding = 13) buffer RadianceAccumulators { uint radianceAccumulator[]; };
layout(std430, binding = 14) buffer TouchedFlag { uint touchedFlag[]; };
layout(std430, binding = 15) buffer TouchedList { uint touchedList[]; };
layout(std430, binding = 16) buffer BorderFlag { uint borderFlag[]; };
layout(std430, binding = 17) buffer BorderList { uint borderList[]; };
layout(std430, binding = 18) buffer CellRadiance { vec4 cellRadiance[]; };  // premultiplied (L·τ, τ)
// The mean lit-side normal of the voxel's reflected light (radiance_normalize), premultiplied
// (N·τ, τ); bound at 18 in place of CellRadiance when the brick passes filter it.
layout(std430, binding = 23) buffer CellDirection { vec4 cellDirection[]; };

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
