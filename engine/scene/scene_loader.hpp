#pragma once
// Turning a `--scene` value into a Scene.
//   "cornell"   built-in procedural Cornell box (no files needed)
//   "sponza"    Sponza.gltf found through the asset search path, with Sponza's sun and camera
//   otherwise   a path to a model file (glTF 2.0 / GLB, OBJ+MTL, anything Assimp reads)
#include <filesystem>
#include <optional>
#include <string>

#include "scene/scene.hpp"

namespace vct {

struct LoadOptions {
    // Non-finite vertex positions are an error by default (the model is broken and the user
    // should know). With `sanitize`, triangles touching such vertices are dropped and counted.
    bool sanitize = false;
};

Scene loadScene(const std::string& sceneSpec, const LoadOptions& options = {});

// Imports a model file with Assimp: node transforms flattened (in double precision), missing
// normals generated, base-colour textures decoded with stb_image (embedded or external),
// glTF alpha masks and emissive colours, glTF cameras as presets, a default camera and sun
// derived from the bounds when the file has none.
Scene loadModelFile(const std::filesystem::path& path, const LoadOptions& options = {});

Scene makeCornellBox();

// Search path for bundled assets: $VCT_ASSET_DIR, ./assets, <source>/assets,
// ./../shared/assets, <source>/../shared/assets. Returns the first existing match.
std::optional<std::filesystem::path> findAsset(const std::filesystem::path& relative);
std::string assetSearchPathDescription();

}  // namespace vct
