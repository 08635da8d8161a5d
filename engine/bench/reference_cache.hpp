#pragma once
// The benchmark's ground truth: a high-spp path-traced reference (`bounces` indirect bounces) and
// a direct-only one (bounces 0, same seed and spp), rendered once and cached on disk.
//
// Cache key: a hash of everything the images depend on: the scene's content (vertex positions,
// normals, UVs, indices, draw ranges, materials, texture texels: a changed model file or a changed
// built-in scene gives a new key even at the same path), the local origin, the camera, the
// lights, the image size, bounces, spp, seed, and kReferenceCacheVersion (bump it when the path
// tracer's output changes for the same inputs). Files in the cache folder:
//   ref_<scene>_<key>_full.pfm, ref_<scene>_<key>_direct.pfm, ref_<scene>_<key>.json (metadata)
// The direct render of the path tracer uses no random numbers but the pixel jitter, so with the
// same seed the reference's indirect part full − direct is exactly its own direct/indirect split.
#include <cstdint>
#include <filesystem>
#include <string>

#include "core/image.hpp"
#include "reference/reference_renderer.hpp"
#include "scene/scene.hpp"

namespace vct::bench {

inline constexpr int kReferenceCacheVersion = 2;

struct ReferenceImages {
    ImageF full;      // radiance, `bounces` indirect bounces
    ImageF direct;    // bounces 0
    ImageF indirect;  // full − direct
    int spp = 0;
    int bounces = 0;
    std::uint64_t seed = 0;
    double seconds = 0.0;        // render time of the full reference (when it was rendered)
    double directSeconds = 0.0;
    double meanVariance = 0.0;   // of the full reference: ≈ its own MSE (noise floor of every error)
    int threads = 0;
    std::string key;             // hex
    bool fromCache = false;
    std::filesystem::path fullPath, directPath;
};

// A 64-bit hash of the scene's content (see above).
std::uint64_t sceneContentHash(const Scene& scene);
std::string referenceKey(const Scene& scene, const Camera& camera, const reference::ReferenceSettings& settings);

// Loads the pair from `cacheDir` when present and complete, else renders both and stores them
// (creating the folder). `settings.bounces` is the full reference's; the direct one uses 0.
// With `useCache` false, renders and stores anyway (refreshing the cache).
ReferenceImages loadOrRenderReference(const Scene& scene, const Camera& camera,
                                      const reference::ReferenceSettings& settings,
                                      const std::filesystem::path& cacheDir, bool useCache);

// a − b per pixel (RGB; alpha of a).
ImageF subtractImages(const ImageF& a, const ImageF& b);

}  // namespace vct::bench
