#include "cli/render_options.hpp"

#include <cmath>

#include "core/error.hpp"

namespace vct::cli {

void addRenderSettingsOptions(CLI::App& command, RenderSettingsOptions& o) {
    command.add_option("--aov", o.aov,
                       "output buffer: final, direct, gi (final - direct, as vct reference --indirect-out), indirect "
                       "(irradiance), ao, albedo, normal, depth")
        ->capture_default_str();
    command.add_option("--exposure", o.exposureEV, "exposure in stops (EV); default: the scene's");
    command.add_option("--tonemap", o.toneCurve, "tone curve: aces, reinhard, clamp")->capture_default_str();
    command.add_option("--light-view-res", o.lightViewResolution,
                       "light-view (photon) map texels per side: the light injected into the voxels; 0 = four per "
                       "voxel side, 2^(levels+2) within 256..4096")
        ->capture_default_str();
    command.add_option("--shadow-res", o.shadowMapResolution,
                       "shadow map texels per side (the direct light's shadow edges; at least --light-view-res)")
        ->capture_default_str();
    command.add_option("--pcf-radius", o.pcfRadius, "shadow filter radius in texels (0 = one tap)")
        ->capture_default_str();
    command.add_option("--view", o.view,
                       "lit (the lit image), voxels (the octree's albedo), radiance (the octree's radiance: of the voxels, the light each sends towards the eye) or cones (what a narrow "
                       "cone, or with --cone-rays 0 a cone of the set's cap, brings back from the eye: compare with --aov direct)")
        ->capture_default_str();
    command.add_option("--gi", o.gi, "indirect light by cone tracing: on or off")->capture_default_str();
    command.add_flag("--no-photons", o.noPhotons, "inject no light (cones then see only emission; AO stays)");
    command.add_option("--bounces", o.bounces,
                       "light bounces of the indirect light, 1..8: each further one gathers cones at every voxel")
        ->capture_default_str();
    command.add_option("--cones", o.cones.cones, "diffuse cone set: 1, 5, 6, 9 or 16 cones")->capture_default_str();
    command.add_option("--cone-aperture", o.cones.apertureScale, "factor on the derived cone apertures (tan)")
        ->capture_default_str();
    command.add_option("--cone-step", o.cones.step,
                       "cone step length as a fraction of its diameter (0: 0.5 for the cone set, 1 for narrow cones)")
        ->capture_default_str();
    command.add_option("--cone-offset", o.cones.offset, "cone start offset along the normal, in voxels")
        ->capture_default_str();
    command.add_option("--cone-lift", o.cones.lift,
                       "extra offset along the normal per unit of cone diameter (against self-illumination)")
        ->capture_default_str();
    command.add_option("--cone-rays", o.cones.rays,
                       "narrow cones per traced pixel (1..64), or 0: the cone set (--cones), about 2.6x faster "
                       "to trace than 4 narrow cones and further from the path tracer")
        ->capture_default_str();
    command.add_option("--bounce-cone-rays", o.cones.bounceRays,
                       "narrow cones per side of each voxel that gathers a further bounce (--bounces), or 0: the "
                       "cone set (--cones), whose wide cones lose a third of each further bounce across a room")
        ->capture_default_str();
    command.add_option("--cone-max-distance", o.cones.maxDistance,
                       "diagnostic: cones stop this many voxels from where they start (0: through the whole volume); "
                       "against vct reference --first-bounce-distance 0,D (D in world units) it says how far from a "
                       "surface its light is right")
        ->capture_default_str();
    command.add_option("--near-field", o.nearField,
                       "before each narrow cone of a pixel is traced, follow its axis against the G-buffer to where "
                       "the cone starts (1.5 voxels off the surface): a surface met there takes the cone's place, with "
                       "its direct light, and blocks it (on), or the cones alone (off)")
        ->capture_default_str();
    command.add_option("--near-detail", o.nearDetail,
                       "scale each pixel's indirect light by its visibility within the cones' start offset (the "
                       "near field's test, 8 directions) over that visibility's mean on its surface around it: the "
                       "shade inside creases and at the foot of walls that the traced, filtered cones cannot resolve "
                       "(on), or the cones' light as filtered (off)")
        ->capture_default_str();
    command.add_option("--cone-reuse", o.cones.reuseVoxels,
                       "narrow cones shared between neighbouring traced pixels: sigma in voxels of the weight a "
                       "neighbour's cones get by its distance (0: every traced pixel keeps its own cones); it lowers "
                       "their noise where surfaces are too small for the edge-aware filter")
        ->capture_default_str();
    command.add_option("--cone-carry", o.cones.carryVoxels,
                       "when only the camera moved, a pixel takes the last frame's indirect light where a pixel of it "
                       "saw the same surface point (within this many voxels plus the pixel's footprint, facing the same "
                       "way), for a frame or two, instead of tracing cones anew (0: every frame traces all its pixels)")
        ->capture_default_str();
    command.add_option("--sample-cones", o.sampleCones,
                       "what the samples after the first of an accumulated frame (--samples, the viewer) trace: "
                       "narrow (one narrow cone per traced pixel, its direction stratified over the samples: the "
                       "average converges to the narrow cones' small error) or frame (the frame's cones at every "
                       "sample)")
        ->capture_default_str();
    command.add_option("--only-cone", o.cones.onlyCone,
                       "diagnostic: only cone K of the set gathers light (0 = the cone along the normal; with "
                       "--cone-rays the narrow cones in its region of the hemisphere; compare with vct reference "
                       "--cone-region K); -1: every cone")
        ->capture_default_str();
    command.add_option("--gi-resolution", o.giResolution,
                       "half: cones at one pixel of each 2x2 block, the others take the irradiance of traced "
                       "pixels on their own surface (about 4x fewer cones, as close to the path tracer); quarter: "
                       "one of each 4x4 block; full: at every pixel; auto: quarter from 360 lines up, else half")
        ->capture_default_str();
    command.add_option("--gi-filter", o.giFilter,
                       "width of the edge-aware filter of the indirect light along surfaces, in voxels (0: off); "
                       "it removes the steps the octree's nodes print into the cones' result")
        ->capture_default_str();
    command.add_option("--gi-scale", o.giScale, "artistic factor on indirect light (1 = physically consistent)")
        ->capture_default_str();
    command.add_option("--voxel-levels", o.voxelLevels, "octree resolution 2^L voxels per axis, L in 5..10")
        ->capture_default_str();
    command.add_option("--voxel-level", o.voxelViewLevel,
                       "octree level shown by the voxel views (1..L; default L, the voxels themselves)");
    command.add_flag("--no-bricks", o.noBricks, "unfiltered voxel data: cones read the nearest brick sample, voxel views each node's mean (instead of trilinear in the bricks)");
}

namespace {
// The value of a switch given as `on` or `off`; anything else fails naming the option.
bool parseOnOff(const std::string& value, const char* option) {
    if (value != "on" && value != "off") fail(option, " must be on or off, not '", value, "'");
    return value == "on";
}
}  // namespace

RenderSettings renderSettingsFromOptions(const RenderSettingsOptions& o, const Scene& scene) {
    RenderSettings settings;
    settings.lightViewResolution = o.lightViewResolution;
    settings.shadowMapResolution = o.shadowMapResolution;
    settings.pcfRadius = o.pcfRadius;
    settings.display.aov = parseAov(o.aov);
    settings.display.toneCurve = parseToneCurve(o.toneCurve);
    settings.display.giScale = o.giScale;
    settings.display.exposureEV = o.exposureEV.value_or(scene.exposureEV);
    settings.view = parseViewMode(o.view);
    settings.voxelLevels = o.voxelLevels;
    settings.voxelViewLevel = o.voxelViewLevel;
    settings.bricks = !o.noBricks;
    settings.gi = parseOnOff(o.gi, "--gi");
    settings.photons = !o.noPhotons;
    settings.bounces = o.bounces;
    settings.cones = o.cones;
    settings.cones.nearField = parseOnOff(o.nearField, "--near-field");
    settings.cones.nearDetail = parseOnOff(o.nearDetail, "--near-detail");
    settings.cones.narrowConesAfterFirstSample = parseSampleCones(o.sampleCones);
    settings.giResolution = parseGiResolution(o.giResolution);
    settings.giFilter = o.giFilter;
    validateRenderSettings(settings);
    return settings;
}

}  // namespace vct::cli
