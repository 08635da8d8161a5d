#pragma once
// The external files a glTF model refers to, checked before Assimp reads it: Assimp 5.2 fails on
// a missing buffer with "could not open referenced file", which names neither the model nor where
// it looked. A missing buffer is an error naming the buffer, the file looked for and what to do.
// (Missing images are warnings from the texture library, which names the file too.)
#include <filesystem>

#include <nlohmann/json.hpp>

namespace vct {

void checkGltfResources(const nlohmann::json& gltf, const std::filesystem::path& modelPath);

}  // namespace vct
