#include "scene/material_import.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/scene.h>

#include "core/error.hpp"
#include "core/log.hpp"
#include "scene/texture_decode.hpp"
#include "scene/texture_library.hpp"

namespace vct {
namespace {

std::optional<std::string> textureOf(const aiMaterial& m, aiTextureType type) {
    if (m.GetTextureCount(type) == 0) return std::nullopt;
    aiString path;
    if (m.GetTexture(type, 0, &path) != AI_SUCCESS || path.length == 0) return std::nullopt;
    return std::string(path.C_Str());
}

bool finite3(const aiColor4D& c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

// A colour property sanitized to finite values in [0, max]: NaN and negative values become 0,
// values above max (+Inf too: a product such as emission × strength that overflowed float) max.
// Warns (once per material/key) when it had to change anything.
glm::vec3 sanitizeColour(glm::vec3 c, float max, const std::string& material, const char* what) {
    glm::vec3 out = c;
    for (int i = 0; i < 3; ++i) {
        if (std::isnan(out[i]) || out[i] < 0.0f) out[i] = 0.0f;
        if (out[i] > max) out[i] = max;
    }
    if (out != c)
        logWarnOnce(concat("material-colour:", material, ":", what),
                    concat("material '", material, "': ", what, " (", c.x, ", ", c.y, ", ", c.z,
                           ") is outside [0, ", max, "]; clamped to (", out.x, ", ", out.y, ", ",
                           out.z, ")"));
    return out;
}

std::string materialName(const aiMaterial& m, std::uint32_t index) {
    aiString name;
    return (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length > 0)
               ? std::string(name.C_Str())
               : concat("material ", index);
}

// ------------------------------------------------------------------------------------------------
// Colours

// Base colour: glTF's baseColorFactor, else the diffuse colour (OBJ Kd, FBX, …). Both are linear
// already. The base alpha is the base colour's alpha in glTF, else the opacity (OBJ d).
void importBaseColour(const aiMaterial& m, Material& material) {
    aiColor4D colour(0.8f, 0.8f, 0.8f, 1.0f);
    bool hasBaseAlpha = false;
    if (m.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS && finite3(colour)) {
        hasBaseAlpha = true;
    } else if (m.Get(AI_MATKEY_COLOR_DIFFUSE, colour) != AI_SUCCESS || !finite3(colour)) {
        colour = aiColor4D(0.8f, 0.8f, 0.8f, 1.0f);
    }
    material.baseColor = sanitizeColour({colour.r, colour.g, colour.b}, 1.0f, material.name,
                                        "base colour");

    float alpha = 1.0f;
    if (hasBaseAlpha) {
        alpha = colour.a;
    } else if (float opacity = 1.0f; m.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS) {
        alpha = opacity;
    }
    material.baseAlpha = std::isfinite(alpha) ? std::clamp(alpha, 0.0f, 1.0f) : 1.0f;
}

// Emissive radiance W/(m²·sr): colour × strength (KHR_materials_emissive_strength, read from the
// file's JSON where Assimp does not pass it on: `fileStrength`).
void importEmissive(const aiMaterial& m, std::optional<float> fileStrength, Material& material) {
    aiColor4D emissive(0.0f, 0.0f, 0.0f, 1.0f);
    if (m.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) != AI_SUCCESS || !finite3(emissive)) return;
    float strength = 1.0f;
    if (fileStrength)
        strength = *fileStrength;
    else if (m.Get(AI_MATKEY_EMISSIVE_INTENSITY, strength) != AI_SUCCESS || !std::isfinite(strength) ||
             strength < 0.0f)
        strength = 1.0f;
    material.emissive = sanitizeColour(glm::vec3(emissive.r, emissive.g, emissive.b) * strength,
                                       1e9f, material.name, "emissive colour");
}

// ------------------------------------------------------------------------------------------------
// Textures and alpha mode

// A texture reference of the material, resolved and decoded (`image` is null when the material
// has none or it could not be decoded; the library has warned then).
struct MaterialTexture {
    TextureSource source;
    const Texture* image = nullptr;
    aiTextureType type = aiTextureType_NONE;  // the slot it was found in
};

MaterialTexture baseColourTexture(const aiMaterial& m, TextureLibrary& library,
                                  const std::string& materialName) {
    MaterialTexture base;
    std::optional<std::string> reference = textureOf(m, aiTextureType_BASE_COLOR);
    base.type = aiTextureType_BASE_COLOR;
    if (!reference) {
        reference = textureOf(m, aiTextureType_DIFFUSE);
        base.type = aiTextureType_DIFFUSE;
    }
    if (reference) {
        base.source = library.resolve(*reference);
        base.image = library.image(base.source, materialName);
    } else {
        base.type = aiTextureType_NONE;
    }
    return base;
}

TextureWrap wrapOf(const aiMaterial& m, const char* key, aiTextureType type, const std::string& materialName) {
    int mode = aiTextureMapMode_Wrap;
    if (m.Get(key, type, 0, mode) != AI_SUCCESS) return TextureWrap::Repeat;
    switch (mode) {
        case aiTextureMapMode_Wrap: return TextureWrap::Repeat;
        case aiTextureMapMode_Clamp: return TextureWrap::ClampToEdge;
        case aiTextureMapMode_Mirror: return TextureWrap::MirroredRepeat;
        default:
            logWarnOnce(concat("wrap:", materialName), concat("material '", materialName, "': texture wrap mode ", mode,
                                                             " (decal) is not supported; clamped to the edge"));
            return TextureWrap::ClampToEdge;
    }
}

// Which UV set the base texture reads, how it is transformed and wrapped: the UV set and wrap
// modes as Assimp gives them (glTF texCoord and sampler wrapS/wrapT; OBJ has no such
// statements), the glTF KHR_texture_transform from the file (`extras`).
TextureMapping baseColourMapping(const aiMaterial& m, const MaterialTexture& base, const GltfMaterialExtras& extras,
                                 const std::string& materialName) {
    TextureMapping mapping;
    if (base.type == aiTextureType_NONE) return mapping;
    int uvSet = 0;
    if (m.Get(AI_MATKEY_UVWSRC(base.type, 0), uvSet) == AI_SUCCESS) mapping.texCoord = uvSet;
    if (extras.texCoord) mapping.texCoord = *extras.texCoord;
    if (mapping.texCoord < 0 || mapping.texCoord > 1) {
        logWarnOnce(concat("texcoord:", materialName),
                    concat("material '", materialName, "': base colour texture reads texture coordinates ",
                           mapping.texCoord, "; vct keeps sets 0 and 1 only, set 0 used"));
        mapping.texCoord = 0;
    }
    if (extras.transform) mapping.transform = *extras.transform;
    mapping.wrapS = wrapOf(m, _AI_MATKEY_MAPPINGMODE_U_BASE, base.type, materialName);
    mapping.wrapT = wrapOf(m, _AI_MATKEY_MAPPINGMODE_V_BASE, base.type, materialName);
    return mapping;
}

// glTF states the alpha mode; `mode` is its value.
void applyGltfAlphaMode(const aiMaterial& m, const std::string& mode, const MaterialTexture& base,
                        TextureLibrary& library, Material& material) {
    float cutoff = 0.5f;
    if (m.Get(AI_MATKEY_GLTF_ALPHACUTOFF, cutoff) != AI_SUCCESS || !std::isfinite(cutoff))
        cutoff = 0.5f;
    if (mode == "MASK") {
        material.alphaMode = AlphaMode::Mask;
        material.alphaCutoff = std::clamp(cutoff, 0.0f, 1.0f);
    } else if (mode == "BLEND") {
        // No blending in a voxel GI pipeline: see-through parts become holes, the rest is solid.
        // Reported once per file, with the materials named, in the load report (gltf_support.cpp).
        material.alphaMode = AlphaMode::Mask;
        material.alphaCutoff = 0.5f;
    }
    if (base.image) material.baseColorTexture = library.use(base.source.key);
}

// One texture with the base colour in RGB and the opacity map in alpha (a white base when the
// material has no base texture), made once per base/mask pair. Returns its index.
int foldedMaskTexture(const MaterialTexture& base, const MaterialTexture& mask,
                      TextureLibrary& library, const std::string& materialName) {
    const std::string key = concat("fold:", base.source.key, "|", mask.source.key);
    if (const int folded = library.indexOf(key); folded >= 0) return folded;
    Texture texture;
    if (base.image) {
        texture = *base.image;
        texture.name = base.image->name + " (alpha from " + mask.image->name + ")";
    } else {  // white base, the mask as alpha: baseColor × 1
        texture.name = mask.image->name + " (as alpha)";
        texture.width = mask.image->width;
        texture.height = mask.image->height;
        texture.rgba.assign(mask.image->rgba.size(), 255);
    }
    if (!foldMaskIntoAlpha(texture, *mask.image))
        logWarnOnce("mask-size:" + key,
                    concat("material '", materialName, "': opacity map '", mask.image->name, "' (",
                           mask.image->width, "x", mask.image->height,
                           ") does not match base colour texture '", base.image->name, "' (",
                           texture.width, "x", texture.height,
                           "); resampled it to that size (nearest texel)"));
    return library.use(key, std::move(texture));
}

// Formats without an alpha mode (OBJ, …): a separate opacity map (OBJ map_d) or a base texture
// with transparent texels makes the material a mask.
void inferAlphaMode(const aiMaterial& m, const MaterialTexture& base, TextureLibrary& library,
                    Material& material) {
    MaterialTexture mask;
    if (std::optional<std::string> reference = textureOf(m, aiTextureType_OPACITY)) {
        mask.source = library.resolve(*reference);
        if (mask.source.key == base.source.key)
            material.alphaMode = AlphaMode::Mask;  // map_d names the base texture: its alpha is the mask
        else
            mask.image = library.image(mask.source, material.name);
    }
    if (mask.image) {
        material.alphaMode = AlphaMode::Mask;
        material.baseColorTexture = foldedMaskTexture(base, mask, library, material.name);
    } else if (base.image) {
        material.baseColorTexture = library.use(base.source.key);
        if (hasTransparentTexel(*base.image)) material.alphaMode = AlphaMode::Mask;
    }
    material.alphaCutoff = 0.5f;
}

// ------------------------------------------------------------------------------------------------

Material importMaterial(const aiMaterial& m, std::uint32_t index, const GltfMaterialExtras& extras,
                        TextureLibrary& library) {
    Material material;
    material.name = materialName(m, index);
    importBaseColour(m, material);
    importEmissive(m, extras.emissiveStrength, material);
    const MaterialTexture base = baseColourTexture(m, library, material.name);
    material.baseColorMapping = baseColourMapping(m, base, extras, material.name);
    if (aiString alphaMode; m.Get(AI_MATKEY_GLTF_ALPHAMODE, alphaMode) == AI_SUCCESS)
        applyGltfAlphaMode(m, alphaMode.C_Str(), base, library, material);
    else
        inferAlphaMode(m, base, library, material);
    return material;
}

Material defaultMaterial() {
    Material material;
    material.name = "default";
    return material;
}

}  // namespace

void importMaterials(const aiScene& ai, const std::vector<std::uint32_t>& used,
                     const std::vector<GltfMaterialExtras>& extras, const std::filesystem::path& modelPath,
                     Scene& scene) {
    TextureLibrary library(ai, modelPath, scene);
    scene.materials.clear();
    scene.textures.clear();
    const GltfMaterialExtras none;
    for (std::uint32_t index : used) {
        const bool exists = index < ai.mNumMaterials && ai.mMaterials[index];
        const GltfMaterialExtras& fromFile = index < extras.size() ? extras[index] : none;
        scene.materials.push_back(exists ? importMaterial(*ai.mMaterials[index], index, fromFile, library)
                                         : defaultMaterial());
    }
    library.finish();
    if (scene.materials.empty()) scene.materials.push_back(defaultMaterial());
}

}  // namespace vct
