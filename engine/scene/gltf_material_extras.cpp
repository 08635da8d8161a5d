#include "scene/gltf_material_extras.hpp"

#include <cmath>
#include <unordered_set>

#include <assimp/material.h>
#include <assimp/scene.h>

#include "core/error.hpp"
#include "core/log.hpp"
#include "scene/gltf_json.hpp"
#include "scene/texture_mapping.hpp"

namespace vct {
namespace {

// Assimp 5.2's glTF reader loads objects lazily, depth first from the default scene: a node's
// children before its mesh, a mesh's primitives in order, each material when first referred to.
// Its aiScene::mMaterials are the materials in that order, then one default material.
class MaterialOrder {
public:
    explicit MaterialOrder(const nlohmann::json& gltf) : gltf_(gltf) {
        const std::size_t sceneIndex = gltfIndex(gltf, "scene").value_or(0);
        const nlohmann::json& scenes = gltfArray(gltf, "scenes");
        if (sceneIndex < scenes.size())
            for (const nlohmann::json& node : gltfArray(scenes[sceneIndex], "nodes"))
                if (node.is_number_unsigned()) visitNode(node.get<std::size_t>());
    }
    const std::vector<std::size_t>& order() const { return order_; }

private:
    void visitNode(std::size_t index) {
        const nlohmann::json& nodes = gltfArray(gltf_, "nodes");
        // Iterative walk (no recursion limit), children visited in order before the node's mesh.
        struct Item { std::size_t node; bool childrenDone; };
        std::vector<Item> stack{{index, false}};
        while (!stack.empty()) {
            Item item = stack.back();
            stack.pop_back();
            if (item.node >= nodes.size()) continue;
            const nlohmann::json& node = nodes[item.node];
            if (item.childrenDone) {
                if (const auto mesh = gltfIndex(node, "mesh")) visitMesh(*mesh);
                continue;
            }
            if (!nodesSeen_.insert(item.node).second) continue;
            stack.push_back({item.node, true});
            const nlohmann::json& children = gltfArray(node, "children");
            for (std::size_t c = children.size(); c-- > 0;)
                if (children[c].is_number_unsigned()) stack.push_back({children[c].get<std::size_t>(), false});
        }
    }
    void visitMesh(std::size_t index) {
        const nlohmann::json& meshes = gltfArray(gltf_, "meshes");
        if (index >= meshes.size() || !meshesSeen_.insert(index).second) return;
        for (const nlohmann::json& primitive : gltfArray(meshes[index], "primitives"))
            if (const auto material = gltfIndex(primitive, "material");
                material && *material < gltfArray(gltf_, "materials").size() && materialsSeen_.insert(*material).second)
                order_.push_back(*material);
    }

    const nlohmann::json& gltf_;
    std::unordered_set<std::size_t> nodesSeen_, meshesSeen_, materialsSeen_;
    std::vector<std::size_t> order_;
};

// Does Assimp's material `m` look like the file's `material` (name and base colour factor)?
bool sameMaterial(const aiMaterial& m, const nlohmann::json& material) {
    aiString name;
    const bool hasName = m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length > 0;
    const nlohmann::json* fileName = gltfMember(material, "name");
    const bool fileHasName = fileName && fileName->is_string() && !fileName->get<std::string>().empty();
    if (hasName != fileHasName || (hasName && fileName->get<std::string>() != name.C_Str())) return false;
    double factor[4] = {1, 1, 1, 1};
    if (const nlohmann::json* pbr = gltfMember(material, "pbrMetallicRoughness")) {
        const nlohmann::json& f = gltfArray(*pbr, "baseColorFactor");
        for (std::size_t i = 0; i < 4 && i < f.size(); ++i) factor[i] = f[i].is_number() ? f[i].get<double>() : 1.0;
    }
    aiColor4D colour;
    if (m.Get(AI_MATKEY_BASE_COLOR, colour) != AI_SUCCESS) return true;  // nothing more to compare
    const double got[4] = {colour.r, colour.g, colour.b, colour.a};
    for (int i = 0; i < 4; ++i)
        if (std::abs(got[i] - factor[i]) > 1e-6 * std::max(1.0, std::abs(factor[i]))) return false;
    return true;
}

glm::vec2 vec2Of(const nlohmann::json& object, const char* key, glm::vec2 fallback) {
    const nlohmann::json& a = gltfArray(object, key);
    if (a.size() != 2 || !a[0].is_number() || !a[1].is_number()) return fallback;
    return {a[0].get<float>(), a[1].get<float>()};
}

GltfMaterialExtras extrasOf(const nlohmann::json& material, const std::string& what) {
    GltfMaterialExtras extras;
    const nlohmann::json* pbr = gltfMember(material, "pbrMetallicRoughness");
    const nlohmann::json* base = pbr ? gltfMember(*pbr, "baseColorTexture") : nullptr;
    const nlohmann::json* extensions = base ? gltfMember(*base, "extensions") : nullptr;
    if (const nlohmann::json* t = extensions ? gltfMember(*extensions, "KHR_texture_transform") : nullptr) {
        const glm::vec2 offset = vec2Of(*t, "offset", glm::vec2(0.0f));
        const glm::vec2 scale = vec2Of(*t, "scale", glm::vec2(1.0f));
        const float rotation = float(gltfNumber(*t, "rotation", 0.0));
        // Offsets and scales beyond ±2^24 are refused like the coordinates themselves
        // (mesh_cleanup.cpp): they move texture coordinates where no texel can be told apart, and
        // where multiplied by a texture's size they overflow (NaN texels on llvmpipe).
        if (isUsableTextureCoordinate(offset.x) && isUsableTextureCoordinate(offset.y) &&
            isUsableTextureCoordinate(scale.x) && isUsableTextureCoordinate(scale.y) && std::isfinite(rotation))
            extras.transform = fromGltfTransform(offset, rotation, scale);
        else
            logWarn(concat(what, ": KHR_texture_transform has a non-finite value or an offset or scale beyond ±2^24; "
                                 "ignored"));
        if (const auto texCoord = gltfIndex(*t, "texCoord")) extras.texCoord = int(std::min<std::size_t>(*texCoord, 2));
    }
    const nlohmann::json* materialExtensions = gltfMember(material, "extensions");
    if (const nlohmann::json* e = materialExtensions ? gltfMember(*materialExtensions, "KHR_materials_emissive_strength")
                                                     : nullptr) {
        const double strength = gltfNumber(*e, "emissiveStrength", 1.0);
        if (std::isfinite(strength) && strength >= 0.0) extras.emissiveStrength = float(strength);
        else logWarn(concat(what, ": emissiveStrength ", strength, " is not a finite value ≥ 0; 1 used"));
    }
    return extras;
}

}  // namespace

std::vector<GltfMaterialExtras> gltfMaterialExtras(const nlohmann::json& gltf, const aiScene& ai,
                                                   const std::string& source) {
    const nlohmann::json& materials = gltfArray(gltf, "materials");
    if (materials.empty()) return {};
    const std::vector<std::size_t> order = MaterialOrder(gltf).order();
    bool matched = ai.mNumMaterials == order.size() + 1;
    for (std::size_t i = 0; matched && i < order.size(); ++i)
        matched = ai.mMaterials[i] && sameMaterial(*ai.mMaterials[i], materials[order[i]]);
    if (!matched) {
        logWarn(concat(source, ": cannot match Assimp's materials to the file's (another Assimp version?); "
                               "KHR_texture_transform and KHR_materials_emissive_strength are ignored"));
        return {};
    }
    std::vector<GltfMaterialExtras> extras(ai.mNumMaterials);
    for (std::size_t i = 0; i < order.size(); ++i)
        extras[i] = extrasOf(materials[order[i]], concat(source, ": material ", order[i]));
    return extras;
}

}  // namespace vct
