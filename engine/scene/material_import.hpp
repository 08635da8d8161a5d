#pragma once
// Assimp materials to vct materials: base colour (glTF base colour or diffuse), base alpha,
// emissive radiance, alpha mode, and the base-colour texture decoded to RGBA8 with its mapping
// (UV set, KHR_texture_transform, wrap modes: scene/texture_mapping.hpp) (external files
// relative to the model's folder, or embedded in the file). Every image is decoded once however
// many materials use it (texture_library.hpp). A texture that is missing or cannot be decoded is
// a warning (once per file), is listed in LoadReport::missingTextures, and leaves the material
// untextured.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "scene/gltf_material_extras.hpp"
#include "scene/scene.hpp"

struct aiScene;

namespace vct {

// Imports the materials `used` (indices into aiScene::mMaterials, in that order) into
// scene.materials, and the textures they use into scene.textures. Unreferenced textures are not
// kept. `modelPath` is the model file (its folder resolves relative texture paths). `extras`:
// what a glTF file's JSON adds per Assimp material (gltf_material_extras.hpp), or empty.
void importMaterials(const aiScene& ai, const std::vector<std::uint32_t>& used,
                     const std::vector<GltfMaterialExtras>& extras, const std::filesystem::path& modelPath,
                     Scene& scene);

}  // namespace vct
