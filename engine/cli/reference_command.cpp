// `vct reference`: the ground truth. A CPU path tracer on Embree over the very same scene, camera
// and lights as `vct render` (the scene options are shared), writing linear radiance.
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "core/error.hpp"
#include "core/image.hpp"
#include "core/log.hpp"
#include "core/tonemap.hpp"
#include "reference/reference_renderer.hpp"

namespace vct::cli {
namespace {

struct ReferenceOptions {
    SceneOptions scene;
    std::string out = "reference.pfm";
    std::string png, directOut, indirectOut, varianceOut;
    std::optional<int> spp;
    std::vector<double> firstBounceDistance;
    reference::ReferenceSettings settings;
    std::optional<double> exposureEV;
    std::string toneCurve = "aces";
};

void run(ReferenceOptions& o) {
    // Everything the user can get wrong, before the expensive steps.
    reference::ReferenceSettings settings = o.settings;
    settings.samplesPerPixel = o.spp.value_or(settings.timeLimitSeconds > 0 ? reference::kUnlimitedSpp : 16);
    if (!o.firstBounceDistance.empty()) {
        if (o.firstBounceDistance.size() != 2)
            fail("--first-bounce-distance needs two numbers: MIN,MAX (world units; MAX may be inf)");
        settings.firstBounceDistance = {float(o.firstBounceDistance[0]), float(o.firstBounceDistance[1])};
    }
    reference::validate(settings);
    const TonemapCurve curve = parseTonemapCurve(o.toneCurve);
    const std::pair<const std::string*, const char*> hdrOutputs[] = {
        {&o.out, "--out"}, {&o.directOut, "--direct-out"}, {&o.indirectOut, "--indirect-out"}, {&o.varianceOut, "--variance-out"}};
    for (const auto& [path, option] : hdrOutputs)
        if (!path->empty()) ensureWritableHdr(*path, option);
    if (!o.png.empty()) ensureWritablePng(o.png, "--png");

    const Scene scene = loadSceneFromOptions(o.scene);
    const Camera camera = cameraFromOptions(o.scene, scene);
    const double exposure = o.exposureEV.value_or(scene.exposureEV);
    if (!std::isfinite(exposure)) fail("--exposure must be a finite number of stops");
    settings.progress = logLevel() >= LogLevel::Info;

    const reference::ReferenceResult r = reference::renderReference(scene, camera, settings);
    writeHdrImage(o.out, r.radiance);
    if (!o.png.empty()) writePng(o.png, tonemapImage(r.radiance, exposure, curve));
    if (!o.directOut.empty()) writeHdrImage(o.directOut, r.direct);
    if (!o.indirectOut.empty()) writeHdrImage(o.indirectOut, r.indirect);
    if (!o.varianceOut.empty()) writeHdrImage(o.varianceOut, r.variance);

    if (logLevel() >= LogLevel::Info) {
        const double rate = r.seconds > 0 ? double(r.paths) / r.seconds / 1e6 : 0.0;
        std::printf("reference %s %dx%d: %d spp, bounces %d%s, %.2f s (+%.2f s setup), %d threads, %.2f Mpaths/s, "
                    "mean variance %.4g (RMSE estimate %.4g)\n",
                    scene.name.c_str(), settings.width, settings.height, r.samplesPerPixel, settings.bounces,
                    settings.centerOnly ? ", centre only" : "", r.seconds, r.buildSeconds, r.threads, rate,
                    r.meanVariance, std::sqrt(r.meanVariance));
        std::fflush(stdout);
    }
    logInfo(concat("wrote ", o.out, o.png.empty() ? "" : " and " + o.png));
}

}  // namespace

Run addReferenceCommand(CLI::App& app) {
    auto options = std::make_shared<ReferenceOptions>();
    ReferenceOptions& o = *options;
    reference::ReferenceSettings& s = o.settings;
    CLI::App* command = app.add_subcommand(
        "reference", "path-traced ground truth (CPU, Embree) of the same scene, camera and lights as vct render");
    addSceneOptions(*command, o.scene, true);
    command->add_option("--out,-o", o.out, "linear radiance W/(m²·sr): .pfm or .exr")->capture_default_str();
    command->add_option("--png", o.png, "also a tone-mapped 8-bit sRGB image (same display transform as vct render)");
    command->add_option("--direct-out", o.directOut, "direct part: emission and light at the first hit (.pfm/.exr)");
    command->add_option("--indirect-out", o.indirectOut, "indirect part: everything after the first bounce (.pfm/.exr)");
    command->add_option("--variance-out", o.varianceOut, "per-pixel variance of the estimate, s²/n per channel (.pfm/.exr)");
    s.width = 1280;
    s.height = 720;
    command->add_option("--width", s.width, "image width in pixels")->capture_default_str();
    command->add_option("--height", s.height, "image height in pixels")->capture_default_str();
    command->add_option("--spp", o.spp,
                        "samples per pixel (default 16; with --time-limit and no --spp: as many as the time allows)");
    command->add_option("--bounces", s.bounces, "indirect bounces: 0 = direct only, 1 = what the voxel GI models")
        ->capture_default_str();
    command->add_option("--seed", s.seed, "random seed; the image is a pure function of seed and settings")
        ->capture_default_str();
    command->add_option("--threads", s.threads, "worker threads (0 = all cores); does not change the image")
        ->capture_default_str();
    command->add_option("--time-limit", s.timeLimitSeconds,
                        "seconds; stop after the sample pass that ends past it (0 = no limit)")
        ->capture_default_str();
    command->add_option("--cone-region", s.coneRegion,
                        "diagnostic: count only light whose first bounce leaves in region K of the engine's cone set "
                        "(what vct render --only-cone K gathers); -1: every direction")
        ->capture_default_str();
    command->add_option("--cones", s.coneRegionSet, "the cone set whose regions --cone-region names: 1, 5, 6, 9 or 16")
        ->capture_default_str();
    command
        ->add_option("--first-bounce-distance", o.firstBounceDistance,
                     "diagnostic: count only light whose first bounce meets a surface MIN to MAX world units from the "
                     "pixel's surface (e.g. 0,0.3: the near field that the engine's cones, starting 1.5 voxels off "
                     "the surface, do not see); default: every distance")
        ->delimiter(',')
        ->type_name("MIN,MAX");
    command->add_flag("--center-only", s.centerOnly,
                      "every sample through the pixel centre (no antialiasing), as the rasterizer samples");
    command->add_option("--exposure", o.exposureEV, "exposure in stops (EV) of --png; default: the scene's");
    command->add_option("--tonemap", o.toneCurve, "tone curve of --png: aces, reinhard, clamp")->capture_default_str();
    return [options] { run(*options); };
}

}  // namespace vct::cli
