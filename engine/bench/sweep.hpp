#pragma once
// The benchmark's sweep definition (`vct bench`, benchmarks/sweeps/*.json) and its expansion into
// points. The sweep is one-at-a-time: every point is the default setting with exactly one
// parameter changed, plus the default point itself, so each point's effect on time and error is
// that parameter's alone (interactions between parameters are not measured).
//
// File format (unknown keys are errors, so that a typo cannot silently do nothing):
//   {
//     "name": "cornell",                 optional; default: the file's stem. Output: bench_<name>.*
//     "scene": "cornell",                cornell | sponza | a model path (relative to the file)
//     "camera": "default",               a preset; "default" = the scene's first camera; or a view of
//                                        its own: {"preset": …, "eye": [x, y, z], "target": [x, y, z],
//                                        "up": [x, y, z], "fov": degrees}, each key optional, on top of
//                                        the preset (as `vct render --eye --target …`)
//     "width": 320, "height": 240,
//     "exposure": 0, "tonemap": "aces",  display transform of PSNR/SSIM (default: the scene's EV)
//     "repeats": 3,                      warm full frames timed per point (the fastest counts)
//     "reference": {"bounces": 1, "spp": 1024, "seed": 1},
//     "pathtracer_curve": {"spp": [1, 2, 4], "seed": 2},   seed default: reference seed + 1
//     "default": {"voxel_levels": 8, ...},                  omitted keys: the engine's defaults
//     "sweep": {"voxel_levels": [6, 7], "cones": [1, 9], ...}
//   }
// Parameters (in "default" and "sweep"): voxel_levels, cones, cone_aperture, cone_step,
// cone_offset, cone_lift, bricks, light_view_res, pcf_radius, gi, bounces (each bounces point is measured
// against a reference with as many bounces), samples (pixel samples each image averages, as
// `vct render --samples`; the point's times are those of all its samples together),
// gi_resolution ("auto", "full", "half" or "quarter", `--gi-resolution`), shadow_res
// (`--shadow-res`), gi_filter (`--gi-filter`, voxels; 0: off), cone_rays (`--cone-rays`; 0: the
// cone set), sample_cones ("narrow" or "frame", `--sample-cones`), cone_reuse (`--cone-reuse`,
// voxels; 0: off).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/renderer.hpp"
#include "scene/camera.hpp"

namespace vct::bench {

// The parameters a sweep may vary, in the order the CSV lists them.
const std::vector<std::string>& parameterNames();

// What an engine point renders: the renderer's settings, and how many pixel samples its image
// averages. Samples are not a renderer setting but a number of frames (Renderer::renderFrame's
// `sample`), so they sit beside the settings rather than in them.
struct PointSettings : RenderSettings {
    int pixelSamples = 1;
};

struct SweepPoint {
    std::string label;      // "default", "cones=16", …
    std::string parameter;  // empty for the default point
    std::string value;      // the parameter's value as written in the CSV
    PointSettings settings;
    bool isDefault = false;
};

struct SweepDefinition {
    std::string name;
    std::filesystem::path file;  // where it was read from (empty when parsed from a string)
    std::string scene = "cornell";
    std::string camera = "default";
    CameraChanges view;  // the "camera" object's keys on top of the preset

    int width = 320, height = 240;
    std::optional<double> exposureEV;
    std::string tonemap = "aces";
    int repeats = 3;
    int referenceBounces = 1;
    int referenceSpp = 1024;
    std::uint64_t referenceSeed = 1;
    std::vector<int> curveSpp{1, 2, 4, 8, 16, 32, 64};
    std::uint64_t curveSeed = 2;
    PointSettings defaults;  // width/height/display filled in by the runner
    std::vector<std::pair<std::string, std::vector<nlohmann::ordered_json>>> sweep;  // in file order
};

// Throws vct::Error naming the file and the offending key or value.
SweepDefinition loadSweep(const std::filesystem::path& file);
SweepDefinition parseSweep(const nlohmann::ordered_json& json, const std::string& name,
                           const std::filesystem::path& file = {});

// The default point first, then one point per swept value in file order; a swept value equal to
// the default is the default point and is not repeated.
std::vector<SweepPoint> expandSweep(const SweepDefinition& sweep);

// Sets one parameter; throws naming it when the value has the wrong type or range.
void applyParameter(PointSettings& settings, const std::string& name, const nlohmann::ordered_json& value);
// The parameter's value in `settings`, formatted as in the CSV ("0.75", "true", "7").
std::string parameterValue(const PointSettings& settings, const std::string& name);

// The scene argument resolved against the sweep file's folder (built-in names stay as they are).
std::string resolveScenePath(const SweepDefinition& sweep);

}  // namespace vct::bench
