#pragma once
// Options every subcommand that needs a scene shares: which scene, which camera, which lights.
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "scene/scene.hpp"

namespace vct::cli {

struct SceneOptions {
    std::string scene = "cornell";
    bool sanitize = false;
    std::string cameraPreset;
    std::vector<double> eye, target, up;
    std::optional<double> fovDeg;
    std::vector<double> sunDirection;
    std::optional<double> sunIrradiance;
    std::vector<double> spotPosition, spotDirection, spotAngles;
    std::optional<double> spotIntensity;
    std::vector<double> pointPosition;
    std::optional<double> pointIntensity;
    std::vector<double> lightColor;
    std::vector<std::string> darkMaterials;  // names or patterns with '*': albedo 0
};

void addSceneOptions(CLI::App& command, SceneOptions& options, bool withCameraAndLights);

// Loads the scene and replaces its lights when any --sun-* / --spot-* / --point-* option is given
// (a sun option gives one sun, a spot option one spot, a point option one point light, together
// they give each; parameters not given keep the scene's own light of that type, or a documented
// default). Materials named by --dark-material reflect nothing (albedo 0, emission kept).
Scene loadSceneFromOptions(const SceneOptions& options);

// The scene's default camera, or the chosen preset, with --eye/--target/--up/--fov applied.
Camera cameraFromOptions(const SceneOptions& options, const Scene& scene);

}  // namespace vct::cli
