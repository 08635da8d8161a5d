#pragma once
// Where in its pixel each sample of an accumulated frame looks (`vct render --samples N`, the
// viewer's progressive refinement). Sample 0 is the pixel centre, so a one-sample frame is the
// plain frame; sample k > 0 is the k-th point of the Halton (2, 3) sequence, a low-discrepancy
// set: every prefix of it covers the pixel evenly, so the average converges to the pixel's area
// integral (what the reference renderer computes) at any sample count, not only at squares.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace vct {

constexpr int kMaxPixelSamples = 65536;  // far beyond where a float sum of samples stops converging

// Radical inverse of `index` in `base`: its digits mirrored behind the point.
inline double radicalInverse(unsigned index, unsigned base) {
    double inverse = 0.0, digitWeight = 1.0 / base;
    for (; index > 0; index /= base, digitWeight /= base) inverse += double(index % base) * digitWeight;
    return inverse;
}

// Offset from the pixel centre in pixels, each component in [−½, ½).
inline glm::dvec2 pixelSampleOffset(int sample) {
    if (sample <= 0) return glm::dvec2(0.0);
    return {radicalInverse(unsigned(sample), 2) - 0.5, radicalInverse(unsigned(sample), 3) - 0.5};
}

// How sample k looks up the scene's textures. The first, alone in a plain frame, filters them over
// its pixel's footprint (shaders/material.glsl, footprintTexel). A filter one pixel wide, though,
// averaged over N lookups at jittered points blurs textures over about two pixels, while the
// pixel's own area (what the reference integrates, with level-0 lookups) is one. The later samples therefore filter less and
// leave the integration over the pixel to the jitter: a footprint of 1/√(k+1) of the pixel's
// shorter axis (a mip-level bias of −½·log2(k + 1), down to −3, which keeps the aliasing of
// single samples bounded; shaders/material.glsl measures it from the shorter axis), isotropic,
// because an anisotropic filter spreads its probes along the pixel's whole footprint whatever the
// bias (with it, Sponza's floor converged to a texture blurred along the view:
// docs/benchmark.md). Returns sample k's bias; < 0 tells the G-buffer to take one lookup at that
// bias instead of the footprint filter.
inline float textureLodBias(int sample) {
    return sample <= 0 ? 0.0f : std::max(-3.0f, -0.5f * std::log2(float(sample + 1)));
}

}  // namespace vct
