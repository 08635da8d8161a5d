// The photons' sums per cell, which inject accumulates and radiance_normalize turns into radiance
// (engine/lighting/radiance_volume.hpp). A file of its own because only those two passes use it,
// and a compute program may bind only so many storage blocks (16 on llvmpipe).
// Per cell: reflected flux R, G, B as 64-bit fixed point (low, high words) [0..5]; the lit-side
// normals of the photons summed as two's-complement integers × LIT_NORMAL_SCALE [6..8]; the
// photon count [9]; the lit-side normals' absolute values summed likewise [10..12] (with the sums
// of the normals, how much of the lit surface faces +a and how much −a).
const uint ACCUMULATOR_WORDS = RADIANCE_ACCUMULATOR_WORDS;
const float LIT_NORMAL_SCALE = 31.0;  // 2^31 / 31: 69 M photons per voxel before a sum could wrap
layout(std430, binding = SSBO_RADIANCE_ACCUMULATORS) buffer RadianceAccumulators { uint radianceAccumulator[]; };

// 64-bit fixed-point accumulation: low word, carry into the high word. Exact and
// order-independent, so the result does not depend on thread scheduling.
void accumulate64(uint index, uint value) {
    uint old = atomicAdd(radianceAccumulator[index], value);
    if (old + value < old) atomicAdd(radianceAccumulator[index + 1u], 1u);
}
