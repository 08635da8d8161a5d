#pragma once
// The parts of glTF materials that Debian 12's Assimp 5.2 does not pass on, read from the file's
// JSON (gltf_json.hpp):
//   * KHR_texture_transform on the base-colour texture: Assimp 5.2 stores offset, rotation and
//     scale in its own, undocumented UV-transform convention and drops the extension's texCoord
//     override, so both are read here;
//   * KHR_materials_emissive_strength: Assimp 5.2 does not read it.
//
// Assimp numbers materials in the order the scene graph first uses them (its lazy glTF reader),
// not in the file's order, and leaves unused ones out. materialOrder() follows the same walk;
// the result is checked against Assimp's own materials (name and base colour) and, if they do
// not agree (another Assimp version), the extras are left out with a warning rather than put on
// the wrong material.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

struct aiScene;

namespace vct {

struct GltfMaterialExtras {
    std::optional<int> texCoord;          // KHR_texture_transform's texCoord override
    std::optional<glm::mat3> transform;   // KHR_texture_transform in vct's UV convention
    std::optional<float> emissiveStrength;
};

// One entry per Assimp material (aiScene::mMaterials order); empty when they could not be matched.
std::vector<GltfMaterialExtras> gltfMaterialExtras(const nlohmann::json& gltf, const aiScene& ai,
                                                   const std::string& source);

}  // namespace vct
