// `vct render`: one frame of a scene, headless, to PNG (+ linear HDR, AOVs, timings).
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/render_options.hpp"
#include "cli/scene_options.hpp"
#include "core/error.hpp"
#include "core/image.hpp"
#include "core/log.hpp"
#include "core/math_constants.hpp"
#include "gl/context.hpp"
#include "pipeline/renderer.hpp"
#include "pipeline/timings_report.hpp"
#include "render/memory_budget.hpp"
#include "render/pixel_samples.hpp"

namespace vct::cli {
namespace {

struct RenderOptions {
    SceneOptions scene;
    std::string out = "vct.png";
    std::string hdrOut;
    std::string timingsOut;
    std::string backend = gl::defaultBackendName();
    int width = 1280;
    int height = 720;
    int frames = 1;
    int samples = 1;
    bool fullFrames = false;
    bool finishEachPass = false;
    std::string lightPath;
    std::string cameraPath;
    double cameraStep = 0.05;  // radians per frame of the camera's orbit
    RenderSettingsOptions render;  // shared with `vct view`
    std::optional<double> memoryBudgetMiB;
};

// The lights turned by `turn` (0..1 of a full circle) around the vertical axis through the scene's
// centre: directions rotate, spot positions orbit.
std::vector<Light> orbit(const std::vector<Light>& lights, const Scene& scene, double turn) {
    const double angle = turn * 2.0 * kPi;
    const double c = std::cos(angle), s = std::sin(angle);
    auto rotate = [&](glm::dvec3 v) { return glm::dvec3(c * v.x + s * v.z, v.y, -s * v.x + c * v.z); };
    std::vector<Light> turned = lights;
    const glm::dvec3 centre = scene.worldBounds.centre();
    for (Light& l : turned) {
        l.direction = rotate(l.direction);
        l.position = centre + rotate(l.position - centre);
    }
    return turned;
}

void run(const RenderOptions& o) {
    if (o.frames < 1 || o.frames > 100000) fail("--frames ", o.frames, " is out of range; use 1..100000");
    if (o.samples < 1 || o.samples > kMaxPixelSamples)
        fail("--samples ", o.samples, " is out of range; use 1..", kMaxPixelSamples);
    // Check what the user can get wrong before the expensive steps.
    ensureWritablePng(o.out, "--out");
    if (!o.hdrOut.empty()) ensureWritableHdr(o.hdrOut, "--hdr-out");
    if (!o.timingsOut.empty()) ensureWritable(o.timingsOut);
    const auto backend = gl::parseBackend(o.backend);
    if (!o.lightPath.empty() && o.lightPath != "orbit")
        fail("unknown --light-path '", o.lightPath, "'; the only path is orbit");
    if (!o.cameraPath.empty() && o.cameraPath != "orbit")
        fail("unknown --camera-path '", o.cameraPath, "'; the only path is orbit");
    if (!(o.cameraStep > 0.0 && o.cameraStep <= 1.0))
        fail("--camera-step ", o.cameraStep, " is out of range; use radians per frame in (0, 1]");
    // Bad names and values fail here, before the scene loads.
    RenderSettings settings = renderSettingsFromOptions(o.render, Scene{});
    settings.width = o.width;
    settings.height = o.height;
    settings.fullFrames = o.fullFrames;
    validateRenderSettings(settings);

    const Scene scene = loadSceneFromOptions(o.scene);
    const Camera camera = cameraFromOptions(o.scene, scene);
    // The scene's own display defaults (its exposure) apply once it is loaded.
    settings.display = renderSettingsFromOptions(o.render, scene).display;
    // Before any GPU allocation: with a memory budget, a frame that would not fit fails here.
    if (o.memoryBudgetMiB) setMemoryBudgetMiB(*o.memoryBudgetMiB);
    checkMemoryBudget(scene, MemoryRequest{settings.width, settings.height, photonMapResolution(settings),
                                           settings.voxelLevels, needsOctree(settings), needsRadiance(settings),
                                           settings.bounces > 1, settings.shadowMapResolution,
                                           settings.giResolution, settings.cones.rays});

    auto context = gl::createContext(backend);
    Renderer renderer(scene, settings);
    renderer.timer().setFinishEachPass(o.finishEachPass);
    const std::vector<Light> startLights = renderer.lights();
    Camera view = camera;
    for (int frame = 0; frame < o.frames; ++frame) {
        if (!o.lightPath.empty() && frame > 0) renderer.setLights(orbit(startLights, scene, double(frame) / o.frames));
        if (!o.cameraPath.empty() && frame > 0) {
            // A small turn of the eye around the target's vertical axis: a typical interactive move.
            const double angle = o.cameraStep * frame;
            const glm::dvec3 d = camera.eye - camera.target;
            view.eye = camera.target + glm::dvec3(std::cos(angle) * d.x + std::sin(angle) * d.z, d.y,
                                                  -std::sin(angle) * d.x + std::cos(angle) * d.z);
        }
        renderer.renderFrame(view);
    }
    // The last frame is the first sample (the pixel centres); the others look elsewhere in the
    // pixel and re-run only the camera's passes. Each sample's timings are read as it finishes.
    SampleTimings samples;
    std::optional<gl::FrameTimings> lastTimings;
    for (int sample = 0; sample < o.samples; ++sample) {
        if (sample > 0) renderer.renderFrame(view, sample);
        lastTimings = renderer.timer().waitForLatest();
        samples.add(lastTimings);
    }

    const ImageF hdr = renderer.readHdr();
    std::size_t nonFinite = 0;
    for (float v : hdr.rgba) nonFinite += !std::isfinite(v);
    if (nonFinite) fail("the rendered image has ", nonFinite, " non-finite values (an engine bug: please report it)");
    writePng(o.out, renderer.readLdr());
    if (!o.hdrOut.empty()) writeHdrImage(o.hdrOut, hdr);

    TimingsReport report{context->info(), o.width, o.height, {}, renderer.memory(), std::nullopt,
                         renderer.lastFrame(), renderer.statistics(), {}};
    if (renderer.octree()) {
        report.voxels = renderer.octree()->memory();
        if (logLevel() >= LogLevel::Info) std::printf("%s", formatVoxelMemory(*report.voxels).c_str());
    }
    if (lastTimings) report.timings = *lastTimings;
    report.samples = samples;
    if (logLevel() >= LogLevel::Info) std::printf("%s", formatTimingsTable(report).c_str());
    if (!o.timingsOut.empty()) writeTimingsJson(o.timingsOut, report);
    logInfo(concat("wrote ", o.out, o.hdrOut.empty() ? "" : " and " + o.hdrOut));
}

}  // namespace

Run addRenderCommand(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    RenderOptions& o = *options;
    CLI::App* command = app.add_subcommand("render", "render one frame headless to a PNG (and HDR/AOV/timings)");
    addSceneOptions(*command, o.scene, true);
    command->add_option("--out,-o", o.out, "output PNG (tone-mapped sRGB)")->capture_default_str();
    command->add_option("--hdr-out", o.hdrOut, "linear float output: .pfm or .exr");
    command->add_option("--timings", o.timingsOut, "per-pass GPU/CPU timings as JSON (schema: docs/timings.md)");
    command->add_option("--backend", o.backend, "osmesa (offscreen CPU), egl (headless GPU) or glfw (hidden window)")
        ->capture_default_str();
    command->add_option("--width", o.width, "image width in pixels")->capture_default_str();
    command->add_option("--height", o.height, "image height in pixels")->capture_default_str();
    command->add_option("--frames", o.frames, "render this many frames; timings are the last frame's")
        ->capture_default_str();
    command->add_option("--samples", o.samples,
                        "average this many samples per pixel (anti-aliasing): the first at the pixel centre, the "
                        "others jittered inside the pixel; only the camera's passes re-run per sample")
        ->capture_default_str();
    addRenderSettingsOptions(*command, o.render);
    command->add_option("--memory-budget", o.memoryBudgetMiB,
                        "GPU memory budget in MiB (default: $VCT_MEMORY_BUDGET_MIB, else none): a frame whose "
                        "estimate exceeds it fails before allocating, naming the largest setting that fits");
    command->add_flag("--full-frames", o.fullFrames,
                      "run every pass every frame, as if the geometry changed (benchmarks: with --frames 2 a "
                      "warm full frame is timed; further --samples re-run only the camera's passes); otherwise a "
                      "frame re-runs only what changed");
    command->add_flag("--finish-each-pass", o.finishEachPass,
                      "end every pass with glFinish, so each pass's time in --timings is its whole cost (drivers "
                      "like llvmpipe otherwise let one pass's work spill into the next one's time); frames get "
                      "slower");
    command->add_option("--camera-path", o.cameraPath,
                        "orbit: the eye turns around the target, --camera-step radians per frame (only "
                        "camera-dependent passes re-run)");
    command->add_option("--camera-step", o.cameraStep,
                        "radians the --camera-path orbit turns per frame (0 < step <= 1; the default turns the eye "
                        "about a metre a frame on Sponza: the target lies half the scene's diagonal ahead)")
        ->capture_default_str();
    command->add_option("--light-path", o.lightPath,
                        "orbit: the lights turn once around the vertical axis over --frames frames (the octree is "
                        "reused; only light-dependent passes re-run)");
    return [options] { run(*options); };
}

}  // namespace vct::cli
