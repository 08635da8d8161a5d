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

// The share of its pixel that sample k filters over, along each axis of the pixel's footprint on
// its surface: its texture lookups (shaders/material.glsl, footprintTexel) and its shadow lookups
// (shaders/direct_lighting.comp) average that much of the footprint. The first, alone in a plain
// frame, filters over its whole pixel. A filter one pixel wide, though, averaged over N lookups at
// jittered points blurs over about two pixels, while the pixel's own area (what the reference
// integrates, with level-0 lookups) is one. The later samples therefore filter over 1/√(k+1) of
// the footprint (down to 1/8, which keeps the aliasing of single samples bounded) and leave the
// rest of the pixel to the jitter. The footprint keeps its shape: shrunk to a disc as wide as its
// shorter axis, a floor seen at a grazing angle aliased along the view in every later sample,
// and 2 or 4 samples came out further from the pixel's area than one (docs/benchmark.md).
inline float pixelSampleFootprint(int sample) {
    return sample <= 0 ? 1.0f : std::max(0.125f, 1.0f / std::sqrt(float(sample + 1)));
}

}  // namespace vct
