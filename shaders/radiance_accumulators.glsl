// The photons' sums per cell, which inject accumulates and radiance_normalize turns into radiance
// (engine/lighting/radiance_volume.hpp). A file of its own because only those two passes use it,
// and a compute program may bind only so many storage blocks (16 on llvmpipe).
// Per cell: reflected flux R, G, B as 64-bit fixed point (low, high words) [0..5]; then, for the
// axes x, y, z, the flux that lit the surface from the +a side and from the −a side [6..17]: each
// photon adds its flux (R + G + B units) times max(±n_a, 0) of its lit-side normal n, × LIT_SIDE_SCALE,
// in 64 bits. Weighted by flux, not counted: photons of a bright and a dim light that meet in one
// voxel (a wall lit outside by the sun and inside by a lamp) send each side its own light.
// Then where in the cell its light lands [18..23]: per axis the flux (× LIT_SIDE_SCALE) times the
// photon's place across the cell along that axis (0..1), in 64 bits; over the flux, the lit
// surface's mean place (facing.glsl, litPlace).
const uint ACCUMULATOR_WORDS = RADIANCE_ACCUMULATOR_WORDS;
const uint LIT_SIDE_WORDS = 6u;  // first word of the lit sides
const uint LIT_PLACE_WORDS = 18u;  // first word of the lit place
// A photon's flux is at most 3 × 2^24 units (the brightest texel is 2^24, an albedo at most 1), so
// one photon's term stays below 2^32 and keeps ~1/31 of a unit's resolution.
const float LIT_SIDE_SCALE = 31.0;
layout(std430, binding = SSBO_RADIANCE_ACCUMULATORS) buffer RadianceAccumulators { uint radianceAccumulator[]; };

// 64-bit fixed-point accumulation: low word, carry into the high word. Exact and
// order-independent, so the result does not depend on thread scheduling.
void accumulate64(uint index, uint value) {
    uint old = atomicAdd(radianceAccumulator[index], value);
    if (old + value < old) atomicAdd(radianceAccumulator[index + 1u], 1u);
}
