#pragma once
// `vct reference`'s engine: the path tracer run over the image, progressively, on all cores.
//
// Pixel sampling (box filter over the pixel): sample 0 of every pixel goes through the pixel
// centre, exactly the ray the rasterizer shades; samples 1, 2, … are uniformly jittered inside
// the pixel's square. `centerOnly` keeps every sample on the centre, for comparisons with the
// (non-antialiased) rasterizer, where only the light transport should differ.
//
// Progressive passes: pass s renders sample s of every pixel, then the time limit is checked, so
// `timeLimitSeconds` stops after the first pass that ends past it (the image always holds the
// same number of samples in every pixel).
//
// Determinism: sample s of pixel p uses its own generator, Pcg32::forSample(seed, p, s), and
// each pixel's accumulators are only touched by the thread rendering its tile in that pass, in
// pass order. The output is therefore bit-identical for any thread count and any scheduling.
#include <cstdint>

#include "core/image.hpp"
#include "reference/path_tracer.hpp"
#include "scene/camera.hpp"
#include "scene/scene.hpp"

namespace vct::reference {

// --spp when only the time limit should stop the render.
inline constexpr int kUnlimitedSpp = std::numeric_limits<int>::max();

struct ReferenceSettings {
    int width = 640;
    int height = 360;
    int samplesPerPixel = 16;           // the maximum; the time limit may stop earlier
    int bounces = 1;                    // indirect bounces (0 = direct only)
    std::uint64_t seed = 1;
    int threads = 0;                    // 0 = std::thread::hardware_concurrency()
    double timeLimitSeconds = 0.0;      // 0 = none
    bool centerOnly = false;
    bool progress = true;               // progress on stderr
    // Diagnostic: count only the light whose first bounce leaves in this region of the engine's
    // cone set of `coneRegionSet` cones (render/cone_set.hpp coneRegionOf; −1: every direction).
    int coneRegion = -1;
    int coneRegionSet = 5;
    // Diagnostic: count only the light whose first bounce meets its surface within this range of
    // distances (`--first-bounce-distance`; default: every distance).
    FirstBounceDistanceFilter firstBounceDistance;
};

struct ReferenceResult {
    ImageF radiance;   // mean radiance W/(m²·sr); alpha = fraction of samples that hit geometry
    ImageF direct;     // its direct part (camera hit's emission + NEE there)
    ImageF indirect;   // the rest (radiance = direct + indirect up to rounding)
    ImageF variance;   // per channel: variance of the pixel's mean, s²/n (0 while n < 2)
    int samplesPerPixel = 0;   // samples actually taken (every pixel has the same)
    double seconds = 0.0;      // wall time of the rendering (without BVH build)
    double buildSeconds = 0.0; // scene preparation (textures, BVH)
    double meanVariance = 0.0; // mean of `variance` over pixels and channels ≈ expected MSE
    int threads = 0;
    std::uint64_t paths = 0;
};

// Throws vct::Error for invalid settings (sizes, spp, bounces, threads, time limit).
void validate(const ReferenceSettings& settings);

ReferenceResult renderReference(const Scene& scene, const Camera& camera, const ReferenceSettings& settings);

}  // namespace vct::reference
