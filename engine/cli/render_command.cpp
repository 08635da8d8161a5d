// `vct render`: one frame of a scene, headless, to PNG (+ linear HDR, AOVs, timings).
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "core/error.hpp"
#include "core/image.hpp"
#include "core/log.hpp"
#include "gl/context.hpp"
#include "pipeline/renderer.hpp"
#include "pipeline/timings_report.hpp"

namespace vct::cli {
namespace {

struct RenderOptions {
    SceneOptions scene;
    std::string out = "vct.png";
    std::string hdrOut;
    std::string timingsOut;
    std::string backend = "osmesa";
    std::string aov = "final";
    std::string toneCurve = "aces";
    std::optional<double> exposureEV;
    int width = 1280;
    int height = 720;
    int lightViewResolution = 2048;
    int pcfRadius = 1;
    int frames = 1;
    std::string view = "lit";
    int voxelLevels = 8;
    int voxelViewLevel = 0;
    bool noBricks = false;
    bool fullFrames = false;
    std::string lightPath;
    std::string cameraPath;
    std::string gi = "on";
    bool noPhotons = false;
    ConeSettings cones;
    float giScale = 1.0f;
};

// The lights turned by `turn` (0..1 of a full circle) around the vertical axis through the scene's
// centre: directions rotate, spot positions orbit.
std::vector<Light> orbit(const std::vector<Light>& lights, const Scene& scene, double turn) {
    const double angle = turn * 2.0 * 3.14159265358979323846;
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
    // Check what the user can get wrong before the expensive steps.
    ensureWritable(o.out);
    if (!o.hdrOut.empty()) ensureWritable(o.hdrOut);
    if (!o.timingsOut.empty()) ensureWritable(o.timingsOut);
    const auto backend = gl::parseBackend(o.backend);
    RenderSettings settings;
    settings.width = o.width;
    settings.height = o.height;
    settings.lightViewResolution = o.lightViewResolution;
    settings.pcfRadius = o.pcfRadius;
    settings.display.aov = parseAov(o.aov);
    settings.display.toneCurve = parseToneCurve(o.toneCurve);
    settings.view = parseViewMode(o.view);
    settings.voxelLevels = o.voxelLevels;
    settings.voxelViewLevel = o.voxelViewLevel;
    settings.bricks = !o.noBricks;
    settings.fullFrames = o.fullFrames;
    if (!o.lightPath.empty() && o.lightPath != "orbit")
        fail("unknown --light-path '", o.lightPath, "'; the only path is orbit");
    if (!o.cameraPath.empty() && o.cameraPath != "orbit")
        fail("unknown --camera-path '", o.cameraPath, "'; the only path is orbit");
    if (o.gi != "on" && o.gi != "off") fail("--gi must be on or off, not '", o.gi, "'");
    settings.gi = o.gi == "on";
    settings.photons = !o.noPhotons;
    settings.cones = o.cones;
    settings.display.giScale = o.giScale;
    if (o.width < 1 || o.height < 1 || o.width > 16384 || o.height > 16384)
        fail("image size ", o.width, "x", o.height, " is out of range; --width and --height must be within 1..16384");

    const Scene scene = loadSceneFromOptions(o.scene);
    const Camera camera = cameraFromOptions(o.scene, scene);
    settings.display.exposureEV = o.exposureEV.value_or(scene.exposureEV);
    if (!std::isfinite(settings.display.exposureEV)) fail("--exposure must be a finite number of stops");

    auto context = gl::createContext(backend);
    Renderer renderer(scene, settings);
    const std::vector<Light> startLights = renderer.lights();
    for (int frame = 0; frame < o.frames; ++frame) {
        if (!o.lightPath.empty() && frame > 0) renderer.setLights(orbit(startLights, scene, double(frame) / o.frames));
        Camera view = camera;
        if (!o.cameraPath.empty() && frame > 0) {
            // A small turn of the eye around the target's vertical axis: a typical interactive move.
            const double angle = 0.05 * frame;
            const glm::dvec3 d = camera.eye - camera.target;
            view.eye = camera.target + glm::dvec3(std::cos(angle) * d.x + std::sin(angle) * d.z, d.y,
                                                  -std::sin(angle) * d.x + std::cos(angle) * d.z);
        }
        renderer.renderFrame(view);
    }

    const ImageF hdr = renderer.readHdr();
    std::size_t nonFinite = 0;
    for (float v : hdr.rgba) nonFinite += !std::isfinite(v);
    if (nonFinite) fail("the rendered image has ", nonFinite, " non-finite values (an engine bug: please report it)");
    writePng(o.out, renderer.readLdr());
    if (!o.hdrOut.empty()) writeHdrImage(o.hdrOut, hdr);

    TimingsReport report{context->info(), o.width, o.height, {}, renderer.memory(), std::nullopt,
                         renderer.lastFrame(), renderer.statistics()};
    if (renderer.octree()) {
        report.voxels = renderer.octree()->memory();
        if (logLevel() >= LogLevel::Info) std::printf("%s", formatVoxelMemory(*report.voxels).c_str());
    }
    if (auto timings = renderer.timer().waitForLatest()) report.timings = *timings;
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
    command->add_option("--timings", o.timingsOut, "per-pass GPU/CPU timings as JSON (schema in README)");
    command->add_option("--backend", o.backend, "osmesa (offscreen CPU), egl (headless GPU) or glfw (hidden window)")
        ->capture_default_str();
    command->add_option("--width", o.width, "image width in pixels")->capture_default_str();
    command->add_option("--height", o.height, "image height in pixels")->capture_default_str();
    command->add_option("--aov", o.aov, "output buffer: final, direct, albedo, normal, depth")->capture_default_str();
    command->add_option("--exposure", o.exposureEV, "exposure in stops (EV); default: the scene's");
    command->add_option("--tonemap", o.toneCurve, "tone curve: aces, reinhard, clamp")->capture_default_str();
    command->add_option("--light-view-res", o.lightViewResolution, "light-view (shadow) map texels per side")
        ->capture_default_str();
    command->add_option("--pcf-radius", o.pcfRadius, "shadow filter radius in texels (0 = one tap)")
        ->capture_default_str();
    command->add_option("--frames", o.frames, "render this many frames; timings are the last frame's")
        ->capture_default_str();
    command->add_option("--view", o.view,
                        "lit (the lit image), voxels (the octree's albedo) or radiance (the octree's radiance)")
        ->capture_default_str();
    command->add_option("--gi", o.gi, "indirect light by cone tracing: on or off")->capture_default_str();
    command->add_flag("--no-photons", o.noPhotons, "inject no light (cones then see only emission; AO stays)");
    command->add_option("--cones", o.cones.cones, "diffuse cone set: 1, 5, 6, 9 or 16 cones")->capture_default_str();
    command->add_option("--cone-aperture", o.cones.apertureScale, "factor on the derived cone apertures (tan)")
        ->capture_default_str();
    command->add_option("--cone-step", o.cones.step, "cone step length as a fraction of its diameter")
        ->capture_default_str();
    command->add_option("--cone-offset", o.cones.offset, "cone start offset along the normal, in voxels")
        ->capture_default_str();
    command->add_option("--cone-lift", o.cones.lift,
                        "extra offset along the normal per unit of cone diameter (against self-illumination)")
        ->capture_default_str();
    command->add_option("--gi-scale", o.giScale, "artistic factor on indirect light (1 = physically consistent)")
        ->capture_default_str();
    command->add_option("--voxel-levels", o.voxelLevels, "octree resolution 2^L voxels per axis, L in 5..10")
        ->capture_default_str();
    command->add_option("--voxel-level", o.voxelViewLevel,
                        "octree level shown by --view voxels (1..L; default L, the voxels themselves)");
    command->add_flag("--no-bricks", o.noBricks, "raw node values instead of filtered bricks (cones and voxel views)");
    command->add_flag("--full-frames", o.fullFrames,
                      "run every pass every frame, as if the geometry changed (benchmarks: with --frames 2 a "
                      "warm full frame is timed); otherwise a frame re-runs only what changed");
    command->add_option("--camera-path", o.cameraPath,
                        "orbit: the eye turns around the target, 0.05 rad per frame (only camera-dependent "
                        "passes re-run)");
    command->add_option("--light-path", o.lightPath,
                        "orbit: the lights turn once around the vertical axis over --frames frames (the octree is "
                        "reused; only light-dependent passes re-run)");
    return [options] { run(*options); };
}

}  // namespace vct::cli
