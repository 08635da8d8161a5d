#include "scene/gltf_support.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/log.hpp"
#include "scene/gltf_json.hpp"

namespace vct {
namespace {

bool isSupported(const std::string& extension) {
    const std::vector<std::string>& supported = supportedGltfExtensions();
    return std::binary_search(supported.begin(), supported.end(), extension);
}

std::vector<std::string> unsupportedIn(const nlohmann::json& gltf, const char* list) {
    std::vector<std::string> out;
    for (const std::string& name : gltfStrings(gltf, list))
        if (!isSupported(name) && std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
    return out;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

std::size_t count(const nlohmann::json& gltf, const char* list) { return gltfArray(gltf, list).size(); }

std::size_t morphedPrimitives(const nlohmann::json& gltf) {
    std::size_t n = 0;
    for (const nlohmann::json& mesh : gltfArray(gltf, "meshes"))
        for (const nlohmann::json& primitive : gltfArray(mesh, "primitives")) n += !gltfArray(primitive, "targets").empty();
    return n;
}

// glTF's default is single-sided: a material is two-sided only with "doubleSided": true.
std::size_t singleSidedMaterials(const nlohmann::json& gltf) {
    std::size_t n = 0;
    for (const nlohmann::json& material : gltfArray(gltf, "materials")) {
        const nlohmann::json* doubleSided = gltfMember(material, "doubleSided");
        n += !(doubleSided && doubleSided->is_boolean() && doubleSided->get<bool>());
    }
    return n;
}

// "3 materials with alphaMode BLEND ('glass', 'water', 'leaves')": at most 5 names.
std::string blendedMaterials(const nlohmann::json& gltf) {
    std::size_t n = 0;
    std::string names;
    const nlohmann::json& materials = gltfArray(gltf, "materials");
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const nlohmann::json* mode = gltfMember(materials[i], "alphaMode");
        if (!mode || !mode->is_string() || mode->get<std::string>() != "BLEND") continue;
        const nlohmann::json* name = gltfMember(materials[i], "name");
        if (++n <= 5)
            names += (names.empty() ? "'" : ", '") +
                     (name && name->is_string() ? name->get<std::string>() : concat("material ", i)) + "'";
    }
    if (n == 0) return {};
    return concat(n, n > 1 ? " materials" : " material", " with alphaMode BLEND (", names, n > 5 ? ", …" : "",
                  "): drawn as MASK with cutoff 0.5 (no blending in the voxel pipeline)");
}

}  // namespace

const std::vector<std::string>& supportedGltfExtensions() {
    static const std::vector<std::string> supported = [] {
        std::vector<std::string> names{
            "KHR_draco_mesh_compression",       // decoded by Assimp (Debian's is built with Draco)
            "KHR_lights_punctual",              // scene_loader.cpp, importLights
            "KHR_materials_emissive_strength",  // gltf_material_extras.cpp
            "KHR_texture_transform",            // gltf_material_extras.cpp, base-colour texture
        };
        std::sort(names.begin(), names.end());
        return names;
    }();
    return supported;
}

void checkRequiredGltfExtensions(const nlohmann::json& gltf, const std::string& source) {
    const std::vector<std::string> missing = unsupportedIn(gltf, "extensionsRequired");
    if (missing.empty()) return;
    fail("cannot read model '", source, "': it requires the glTF extension", missing.size() > 1 ? "s " : " ",
         joined(missing), ", which vct does not implement (vct implements ", joined(supportedGltfExtensions()),
         "); export the model without ", missing.size() > 1 ? "them" : "it");
}

void reportUnsupportedGltfFeatures(const nlohmann::json& gltf, const std::string& source, LoadReport& report) {
    std::vector<std::string> lines;
    if (const std::vector<std::string> used = unsupportedIn(gltf, "extensionsUsed"); !used.empty())
        lines.push_back(concat("uses the glTF extension", used.size() > 1 ? "s " : " ", joined(used),
                               ", which vct does not implement; drawn without ", used.size() > 1 ? "them" : "it"));
    if (const std::size_t skins = count(gltf, "skins"))
        lines.push_back(concat(skins, " skin", skins > 1 ? "s" : "", ": skinned meshes are drawn at their rest pose"));
    if (const std::size_t morphed = morphedPrimitives(gltf))
        lines.push_back(concat(morphed, " primitive", morphed > 1 ? "s" : "",
                               " with morph targets: drawn without them (base shape)"));
    if (const std::size_t animations = count(gltf, "animations"))
        lines.push_back(concat(animations, " animation", animations > 1 ? "s" : "", ": not played (static scene)"));
    if (std::string blend = blendedMaterials(gltf); !blend.empty()) lines.push_back(blend);
    if (const std::size_t single = singleSidedMaterials(gltf))
        lines.push_back(concat(single, " of ", count(gltf, "materials"),
                               " materials single-sided (doubleSided false): drawn two-sided, like every vct surface"));
    for (const std::string& line : lines) {
        report.unsupportedFeatures.push_back(line);
        logWarnOnce(concat("gltf-feature:", source, ":", line), concat(source, ": ", line));
    }
}

}  // namespace vct
