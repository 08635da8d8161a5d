#pragma once
// A small deterministic random number generator for the path tracer.
//
// Why not one generator per thread: the image must not depend on how many threads ran or which
// thread rendered which tile. Every camera sample therefore gets its own generator, seeded from
// (user seed, pixel index, sample index) alone, so the random numbers a sample consumes are a
// pure function of those three values and the rendered image is bit-identical for any --threads.
//
// PCG32 (O'Neill 2014, "PCG: a family of simple fast space-efficient statistically good
// algorithms"): 64-bit LCG state, 32-bit output through an xorshift and a random rotation.
// The (pixel, sample) pair picks the stream (increment), the seed the starting state; both
// are scrambled with SplitMix64 first so that neighbouring pixels are not correlated.
#include <cstdint>

namespace vct::reference {

// SplitMix64 finalizer (Steele et al. 2014): a bijective 64-bit mix.
constexpr std::uint64_t mix64(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

class Pcg32 {
public:
    Pcg32(std::uint64_t initialState, std::uint64_t stream) : state_(0), increment_((stream << 1u) | 1u) {
        nextUint();
        state_ += initialState;
        nextUint();
    }

    // The generator of camera sample `sample` of pixel `pixel` (pixel = y · width + x).
    static Pcg32 forSample(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample) {
        const std::uint64_t a = mix64(seed ^ mix64(pixel));
        const std::uint64_t b = mix64(mix64(sample) + 0x632be59bd9b4e019ull * (pixel + 1));
        return Pcg32(a, b);
    }

    std::uint32_t nextUint() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + increment_;
        const auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
        const auto rotation = std::uint32_t(old >> 59u);
        return (xorshifted >> rotation) | (xorshifted << ((32u - rotation) & 31u));
    }

    // Uniform in [0, 1): the top 24 bits, so the result is exactly representable and never 1.
    float uniform() { return float(nextUint() >> 8) * 0x1p-24f; }

private:
    std::uint64_t state_;
    std::uint64_t increment_;
};

}  // namespace vct::reference
