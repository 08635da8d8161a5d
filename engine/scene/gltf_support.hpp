#pragma once
// What vct does with each part of a glTF file that it does not draw as the file says, so that
// nothing is dropped without a word (docs/robustness.md, "glTF features"):
//
//   * extensionsRequired naming an extension vct does not implement: the file is refused (the
//     spec's rule: a loader that cannot honour a required extension must not load the file), with
//     the extensions named;
//   * extensionsUsed naming ones it does not implement: one warning listing them (the file still
//     renders, without what they add);
//   * skins and morph targets (drawn at rest pose), animations (not played), alpha mode BLEND
//     (drawn as MASK), single-sided materials (drawn two-sided: voxels and photons have no side,
//     and the reference must see the same scene): one line each in
//     LoadReport::unsupportedFeatures, logged once as a warning.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"

namespace vct {

// The extensions vct implements (KHR_lights_punctual, KHR_materials_emissive_strength,
// KHR_texture_transform, KHR_draco_mesh_compression through Assimp), sorted.
const std::vector<std::string>& supportedGltfExtensions();

// Throws vct::Error naming the required extensions vct does not implement.
void checkRequiredGltfExtensions(const nlohmann::json& gltf, const std::string& source);

// Adds the unsupported used extensions and dropped features of the file to `report` and logs
// each once as a warning.
void reportUnsupportedGltfFeatures(const nlohmann::json& gltf, const std::string& source, LoadReport& report);

}  // namespace vct
