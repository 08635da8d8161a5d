#include "bench/bench_run.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.hpp"
#include "core/log.hpp"
#include "metrics/pixel_mask.hpp"

namespace vct::bench {
namespace {

double meanLuminance(const ImageF& image) {
    double sum = 0.0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) sum += metrics::luminance(&image.rgba[i]);
    const std::size_t pixels = image.rgba.size() / 4;
    return pixels ? sum / double(pixels) : 0.0;
}

double frameCost(const gl::FrameTimings& t) { return std::max(t.totalGpuMs, t.totalCpuMs); }

std::vector<PassCost> passCosts(const gl::FrameTimings& t) {
    std::vector<PassCost> passes;
    for (const auto& p : t.passes) passes.push_back({p.name, p.gpuMs, p.cpuMs});
    return passes;
}

std::string ranPasses(const std::vector<PassRun>& frame) {
    std::string list;
    for (const auto& p : frame)
        if (p.ran) list += (list.empty() ? "" : ";") + p.name;
    return list;
}

// GPU memory the point needs: with GI off the octree pools the renderer keeps from earlier points
// are not counted.
std::size_t memoryOf(const Renderer& renderer) {
    static const std::set<std::string> withoutGi = {"scene geometry and textures", "gbuffer", "direct radiance",
                                                    "composite output", "light-view maps"};
    std::size_t bytes = 0;
    for (const auto& pool : renderer.memory())
        if (renderer.settings().gi || withoutGi.count(pool.name)) bytes += pool.bytes;
    return bytes;
}

RenderSettings withAov(RenderSettings s, Aov aov, bool fullFrames) {
    s.display.aov = aov;
    s.fullFrames = fullFrames;
    return s;
}

// One image of `samples` pixel samples: the frame that follows whatever changed (sample 0), then
// the jittered ones, which re-run only the camera's passes.
struct SampledImage {
    double cost = 0.0;              // all samples together
    std::vector<PassCost> passes;   // each pass's cost summed over the samples
    std::vector<PassRun> ran;       // every pass, marked ran when any sample ran it
};

SampledImage renderSamples(Renderer& renderer, const Camera& camera, int samples) {
    SampledImage image;
    for (int sample = 0; sample < samples; ++sample) {
        renderer.renderFrame(camera, sample);
        const auto t = renderer.timer().waitForLatest();
        if (!t) fail("the GPU timer returned no frame (engine bug)");
        if (sample == 0) image.ran = renderer.lastFrame();
        for (std::size_t i = 0; i < image.ran.size(); ++i) image.ran[i].ran |= renderer.lastFrame()[i].ran;
        image.cost += frameCost(*t);
        for (const PassCost& p : passCosts(*t)) {
            auto same = std::find_if(image.passes.begin(), image.passes.end(),
                                     [&](const PassCost& q) { return q.name == p.name; });
            if (same == image.passes.end()) {
                image.passes.push_back(p);
            } else {
                same->gpuMs += p.gpuMs;
                same->cpuMs += p.cpuMs;
            }
        }
    }
    if (renderer.samplesInOutput() != samples)
        fail("the image averages ", renderer.samplesInOutput(), " samples, not ", samples, " (engine bug)");
    return image;
}

}  // namespace

ErrorMetrics measureErrors(const ImageF& final, const ImageF& direct, const ImageF& indirect,
                           const ReferenceImages& reference, const metrics::DisplaySettings& display) {
    const metrics::PixelMask all = metrics::allPixels(final.width, final.height);
    const metrics::ImageMetrics m = metrics::compareImages(final, reference.full, all, display);
    ErrorMetrics e;
    e.rmse = m.rmse;
    e.relMse = m.relMse;
    e.psnr = m.psnr;
    e.ssim = m.ssim;
    e.directRmse = metrics::rmse(direct, reference.direct, all);
    e.indirectRmse = metrics::rmse(indirect, reference.indirect, all);
    e.indirectRelMse = metrics::relativeMse(indirect, reference.indirect, all);
    const double refMean = meanLuminance(reference.indirect);
    e.indirectRatio = refMean > 0.0 ? meanLuminance(indirect) / refMean : 0.0;
    return e;
}

std::vector<BenchRow> runPathTracerCurve(const Scene& scene, const Camera& camera, const SweepDefinition& sweep,
                                         const ReferenceImages& reference, const metrics::DisplaySettings& display,
                                         int threads, const Progress& progress) {
    std::vector<BenchRow> rows;
    for (std::size_t i = 0; i < sweep.curveSpp.size(); ++i) {
        reference::ReferenceSettings s;
        s.width = sweep.width;
        s.height = sweep.height;
        s.samplesPerPixel = sweep.curveSpp[i];
        s.bounces = sweep.referenceBounces;
        s.seed = sweep.curveSeed;
        s.threads = threads;
        s.progress = false;
        const reference::ReferenceResult r = reference::renderReference(scene, camera, s);
        // Timed `repeats` times like the engine (the image is a pure function of the settings).
        std::vector<double> samples = {r.seconds * 1000.0};
        for (int k = 1; k < sweep.repeats; ++k) samples.push_back(reference::renderReference(scene, camera, s).seconds * 1000.0);
        BenchRow row;
        row.kind = "pathtracer";
        row.spp = r.samplesPerPixel;
        row.label = concat(row.spp, " spp");
        row.parameter = "spp";
        row.value = std::to_string(row.spp);
        row.frameMs = *std::min_element(samples.begin(), samples.end());
        row.frameStaticMs = row.frameMs;
        row.frameSamplesMs = samples;
        row.setupMs = r.buildSeconds * 1000.0;
        row.error = measureErrors(r.radiance, r.direct, r.indirect, reference, display);
        rows.push_back(row);
        if (progress) progress(rows.back(), i, sweep.curveSpp.size());
    }
    return rows;
}

std::vector<BenchRow> runEnginePoints(const Scene& scene, const Camera& camera, const std::vector<SweepPoint>& points,
                                      int repeats, const ReferenceForBounces& reference,
                                      const metrics::DisplaySettings& display, const Progress& progress) {
    if (points.empty() || !points.front().isDefault) fail("the benchmark needs the default point first (engine bug)");
    if (repeats < 1) fail("repeats must be at least 1");
    const RenderSettings base = withAov(points.front().settings, Aov::Final, false);
    Renderer renderer(scene, base);
    // Warm-up: the first frame compiles shaders and allocates; a full frame warms every pass.
    renderer.renderFrame(camera);
    renderer.setSettings(withAov(base, Aov::Final, true));
    renderer.renderFrame(camera);
    renderer.setSettings(base);
    renderer.renderFrame(camera);
    renderer.timer().waitForLatest();
    // A nudge too small to see that still re-runs every light- and camera-dependent pass.
    const std::vector<Light> lights = renderer.lights();
    std::vector<Light> nudgedLights = lights;
    for (Light& l : nudgedLights) {
        l.irradiance *= 1.0 + 1e-4;
        l.intensity *= 1.0 + 1e-4;
    }
    Camera nudgedCamera = camera;
    nudgedCamera.eye += (camera.target - camera.eye) * 1e-4;

    std::vector<BenchRow> rows;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const SweepPoint& point = points[i];
        BenchRow row;
        row.kind = "engine";
        row.label = point.label;
        row.parameter = point.parameter;
        row.value = point.value;
        row.isDefault = point.isDefault;
        row.settings = point.settings;

        // 1. The update frame and the image.
        const int samples = point.settings.pixelSamples;
        renderer.setSettings(withAov(point.settings, Aov::Final, false));
        const SampledImage update = renderSamples(renderer, camera, samples);
        row.updateMs = update.cost;
        row.updatePasses = ranPasses(update.ran);
        const ImageF final = renderer.readHdr();
        // 2. The direct part (its samples again: the output averages what composite showed).
        renderer.setSettings(withAov(point.settings, Aov::Direct, false));
        renderSamples(renderer, camera, samples);
        const ImageF direct = renderer.readHdr();
        // 3. Warm full frames.
        renderer.setSettings(withAov(point.settings, Aov::Final, true));
        double best = -1.0;
        for (int r = 0; r < repeats; ++r) {
            const SampledImage full = renderSamples(renderer, camera, samples);
            row.frameSamplesMs.push_back(full.cost);
            if (best < 0.0 || full.cost < best) {
                best = full.cost;
                row.passes = full.passes;
            }
        }
        row.frameMs = best;
        row.memoryBytes = memoryOf(renderer);
        row.coneSamples = renderer.settings().gi ? renderer.statistics().cones.samples : 0;
        const ImageF check = renderer.readHdr();
        row.incrementalIdentical = check.rgba == final.rgba;
        if (!row.incrementalIdentical)
            logWarn(concat("bench: point ", point.label,
                           ": the incrementally updated image differs from the full frame's (pass-graph bug?)"));
        // 4. Static-geometry frames: lights and camera nudged every frame, the octree kept.
        renderer.setSettings(withAov(point.settings, Aov::Final, false));
        for (int r = 0; r < repeats; ++r) {
            const bool nudged = r % 2 == 0;
            renderer.setLights(nudged ? nudgedLights : lights);
            const SampledImage moved = renderSamples(renderer, nudged ? nudgedCamera : camera, samples);
            if (r == 0 || moved.cost < row.frameStaticMs) row.frameStaticMs = moved.cost;
            for (const PassRun& p : moved.ran)
                if (p.ran && declaration(p.pass).stage == Stage::Octree)
                    fail("bench: the static-geometry frame ran ", p.name, " (pass-graph bug?)");
        }
        renderer.setLights(lights);
        // 5. Back to the default point.
        renderer.setSettings(base);
        renderer.renderFrame(camera);
        renderer.timer().waitForLatest();

        std::size_t nonFinite = 0;
        for (float v : final.rgba) nonFinite += !std::isfinite(v);
        for (float v : direct.rgba) nonFinite += !std::isfinite(v);
        if (nonFinite) fail("point ", point.label, ": the engine image has ", nonFinite, " non-finite values (engine bug)");
        const ImageF indirect = subtractImages(final, direct);
        const ReferenceImages& truth = reference(point.settings.bounces);
        row.error = measureErrors(final, direct, indirect, truth, display);
        if (point.isDefault)
            row.indirectRegions = metrics::regionRatios(indirect, truth.indirect, kIndirectRegionGrid, kIndirectRegionGrid);
        rows.push_back(row);
        if (progress) progress(rows.back(), i, points.size());
    }
    return rows;
}

}  // namespace vct::bench
