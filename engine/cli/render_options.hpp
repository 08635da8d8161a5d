#pragma once
// The command-line options that map onto RenderSettings (display, lights' shadow maps, GI, cones,
// octree), shared by the subcommands that render through vct::Renderer so that the same option
// means the same thing everywhere. Image size and backend are each command's own business.
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "pipeline/render_settings.hpp"
#include "scene/scene.hpp"

namespace vct::cli {

struct RenderSettingsOptions {
    std::string aov = "final";
    std::string toneCurve = "aces";
    std::optional<double> exposureEV;  // default: the scene's
    int lightViewResolution = 0;
    int shadowMapResolution = RenderSettings{}.shadowMapResolution;
    int pcfRadius = 1;
    std::string view = "lit";
    int voxelLevels = 8;
    int voxelViewLevel = 0;
    bool noBricks = false;
    std::string gi = "on";
    std::string nearField = "on";
    std::string nearDetail = "on";
    bool noPhotons = false;
    int bounces = 1;
    ConeSettings cones;
    std::string sampleCones = sampleConesName(ConeSettings{}.narrowConesAfterFirstSample);
    std::string giResolution = "auto";
    float giFilter = kDefaultGiFilterVoxels;
    float giScale = 1.0f;
};

void addRenderSettingsOptions(CLI::App& command, RenderSettingsOptions& options);

// Parses the names and checks every value (clear errors, no GL needed); width and height are left
// at their defaults.
RenderSettings renderSettingsFromOptions(const RenderSettingsOptions& options, const Scene& scene);

}  // namespace vct::cli
