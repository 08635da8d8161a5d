// Where a pixel's narrow cones point (cone_march.glsl, gatherNarrowCones): cone k as a point
// (sin²θ, azimuth / 2π) of the unit square, both uniform for cosine-weighted directions.

// The R2 sequence's step (1/g, 1/g², g the plastic number, g³ = g + 1) in 32-bit fixed point,
// and as floats.
const uvec2 R2_STEP_FIXED = uvec2(3242174889u, 2447445414u);
const vec2 R2_STEP = vec2(R2_STEP_FIXED) / 4294967296.0;

// Point j of the R2 sequence (Roberts' additive recurrence by the plastic number) in [0, 1)²,
// in fixed point, so exact at any index: every prefix of it covers the square evenly.
vec2 r2Point(uint j) {
    return vec2(uvec2(2147483648u) + j * R2_STEP_FIXED) / 4294967296.0;
}

// Cone k of `count` traced at once: a Fibonacci lattice, k/N against k/φ. With `sequence` >= 0
// (the later samples of an accumulated frame, which trace a few cones each) point sequence + k of
// the R2 sequence, so a block of pixels that continues it from sample to sample has its directions
// stratified after any number of samples. Shifted by `shift` (toroidally: narrowConeShift).
vec2 narrowConePoint(int k, float count, vec2 shift, int sequence) {
    if (sequence >= 0) return fract(r2Point(uint(sequence + k)) + shift);
    const float goldenFraction = 0.61803398875;  // 1/φ
    return vec2(fract((float(k) + 0.5) / count + shift.x), fract(float(k) * goldenFraction + shift.y));
}
