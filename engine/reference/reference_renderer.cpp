#include "reference/reference_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "reference/camera_rays.hpp"
#include "reference/delta_lights.hpp"
#include "reference/materials.hpp"
#include "reference/path_tracer.hpp"
#include "render/cone_set.hpp"
#include "reference/progress.hpp"
#include "reference/ray_scene.hpp"

namespace vct::reference {
namespace {

constexpr int kTileSize = 16;

// Running sums of one pixel. The mean and variance of the full radiance follow Welford's
// update (stable for many samples with a large mean), with the running mean derived from the
// sums of the two parts.
struct PixelAccumulator {
    glm::dvec3 direct{0.0};
    glm::dvec3 indirect{0.0};
    glm::dvec3 m2{0.0};  // Σ (x − mean_old)(x − mean_new)
    std::uint32_t hits = 0;

    void add(const RadianceSample& s, int n) {  // n = samples so far including this one
        const glm::dvec3 meanOld = n > 1 ? (direct + indirect) / double(n - 1) : glm::dvec3(0.0);
        direct += s.direct;
        indirect += s.indirect;
        const glm::dvec3 x = s.direct + s.indirect;
        const glm::dvec3 meanNew = (direct + indirect) / double(n);
        m2 += (x - meanOld) * (x - meanNew);
        hits += s.hit;
    }
};

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

void validate(const ReferenceSettings& s) {
    validateImageSize(s.width, s.height);
    if (s.samplesPerPixel < 1) fail("--spp ", s.samplesPerPixel, " must be at least 1");
    if (s.bounces < 0 || s.bounces > 100000) fail("--bounces ", s.bounces, " is out of range; use 0..100000");
    if (s.threads < 0 || s.threads > 1024) fail("--threads ", s.threads, " is out of range; use 0 (all cores)..1024");
    if (!std::isfinite(s.timeLimitSeconds) || s.timeLimitSeconds < 0)
        fail("--time-limit must be a finite number of seconds ≥ 0 (0 = no limit)");
    if (s.coneRegion >= 0) {
        const int regions = int(makeConeSet(s.coneRegionSet).size());  // throws for an unknown set
        if (s.coneRegion >= regions)
            fail("--cone-region ", s.coneRegion, " is not a region of the ", s.coneRegionSet, "-cone set; use 0..",
                 regions - 1);
    } else if (s.coneRegion != -1) {
        fail("--cone-region ", s.coneRegion, " is out of range; use -1 (every direction) or a cone of the set");
    }
    const FirstBounceDistanceFilter& range = s.firstBounceDistance;
    if (!(range.nearest >= 0.0f) || !(range.farthest > range.nearest))
        fail("--first-bounce-distance ", range.nearest, ",", range.farthest,
             " is not a range of distances; give MIN,MAX with 0 <= MIN < MAX (world units; MAX may be inf)");
}

ReferenceResult renderReference(const Scene& scene, const Camera& camera, const ReferenceSettings& settings) {
    validate(settings);
    const auto buildStart = std::chrono::steady_clock::now();
    const MaterialTable materials(scene);
    const RayScene rays(scene, materials);
    const DeltaLights lights(scene);
    const PathTracer tracer(rays, materials, lights, settings.bounces, {settings.coneRegionSet, settings.coneRegion},
                            settings.firstBounceDistance);
    const CameraRays cameraRays(camera, scene, settings.width, settings.height);

    ReferenceResult result;
    result.buildSeconds = seconds(buildStart);
    const int width = settings.width, height = settings.height;
    const int tilesX = (width + kTileSize - 1) / kTileSize, tilesY = (height + kTileSize - 1) / kTileSize;
    const int tileCount = tilesX * tilesY;
    int threads = settings.threads > 0 ? settings.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::min(threads, tileCount);
    result.threads = threads;

    std::vector<PixelAccumulator> pixels(std::size_t(width) * height);
    Progress progress(concat("reference ", width, "x", height), settings.progress);
    const double limit = settings.timeLimitSeconds;
    const int maxSpp = settings.samplesPerPixel;
    const bool unlimitedSpp = limit > 0 && maxSpp >= kUnlimitedSpp;
    auto fractionDone = [&](int pass, int tilesDone) {
        const double bySamples = (pass + double(tilesDone) / tileCount) / maxSpp;
        return limit > 0 ? std::max(bySamples, progress.elapsedSeconds() / limit) : bySamples;
    };

    const auto start = std::chrono::steady_clock::now();
    int pass = 0;
    for (; pass < maxSpp; ++pass) {
        std::atomic<int> nextTile{0};
        std::atomic<int> tilesDone{0};
        auto worker = [&] {
            for (int tile; (tile = nextTile.fetch_add(1)) < tileCount;) {
                const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
                const int x1 = std::min(x0 + kTileSize, width), y1 = std::min(y0 + kTileSize, height);
                for (int y = y0; y < y1; ++y)
                    for (int x = x0; x < x1; ++x) {
                        const std::uint64_t index = std::uint64_t(y) * width + x;
                        Pcg32 rng = Pcg32::forSample(settings.seed, index, std::uint64_t(pass));
                        double px = x + 0.5, py = y + 0.5;
                        if (pass > 0 && !settings.centerOnly) {
                            px = x + rng.uniform();
                            py = y + rng.uniform();
                        }
                        pixels[index].add(tracer.trace(cameraRays.at(px, py), rng), pass + 1);
                    }
                const int done = tilesDone.fetch_add(1) + 1;
                progress.update(fractionDone(pass, done),
                                unlimitedSpp ? concat(pass, " spp") : concat(pass, "/", maxSpp, " spp"));
            }
        };
        std::vector<std::thread> pool;
        for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
        worker();  // the calling thread works too
        for (auto& thread : pool) thread.join();
        if (limit > 0 && seconds(start) >= limit) {
            ++pass;
            break;
        }
    }
    progress.finish();
    result.seconds = seconds(start);
    const int n = pass;
    result.samplesPerPixel = n;
    result.paths = std::uint64_t(n) * width * height;

    result.radiance = ImageF(width, height);
    result.direct = ImageF(width, height);
    result.indirect = ImageF(width, height);
    result.variance = ImageF(width, height);
    double varianceSum = 0.0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const PixelAccumulator& a = pixels[std::size_t(y) * width + x];
            const glm::dvec3 direct = a.direct / double(n), indirect = a.indirect / double(n);
            const glm::dvec3 mean = (a.direct + a.indirect) / double(n);
            const glm::dvec3 variance = n > 1 ? a.m2 / (double(n - 1) * n) : glm::dvec3(0.0);
            const float coverage = float(a.hits) / float(n);
            for (int c = 0; c < 3; ++c) {
                result.radiance.at(x, y)[c] = float(mean[c]);
                result.direct.at(x, y)[c] = float(direct[c]);
                result.indirect.at(x, y)[c] = float(indirect[c]);
                result.variance.at(x, y)[c] = float(variance[c]);
            }
            result.radiance.at(x, y)[3] = result.direct.at(x, y)[3] = result.indirect.at(x, y)[3] = coverage;
            result.variance.at(x, y)[3] = 1.0f;
            varianceSum += (variance.x + variance.y + variance.z) / 3.0;
        }
    result.meanVariance = varianceSum / (double(width) * height);
    return result;
}

}  // namespace vct::reference
