#include "scene/material_import.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/scene.h>

#include "core/error.hpp"
#include "core/log.hpp"
#include "scene/texture_decode.hpp"

namespace fs = std::filesystem;

namespace vct {
namespace {

// Where a texture reference in a material points to.
struct TextureSource {
    std::string key;          // cache key: "file:<path>" or "embedded:<index>"
    std::string displayName;  // for messages and Texture::name
    fs::path file;            // external file (empty when embedded or not found)
    const aiTexture* embedded = nullptr;
    bool found = false;
};

std::string percentDecode(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
            out.push_back(static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16)));
            i += 2;
        } else {
            out.push_back(s[i]);
        }
    }
    return out;
}

bool isRegularFile(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec);
}

class TextureLibrary {
public:
    TextureLibrary(const aiScene& ai, const fs::path& modelPath, Scene& scene)
        : ai_(ai), modelDir_(modelPath.parent_path()), scene_(scene) {}

    TextureSource resolve(const std::string& raw) const {
        TextureSource source;
        if (auto [texture, index] = ai_.GetEmbeddedTextureAndIndex(raw.c_str()); texture) {
            source.key = concat("embedded:", index);
            source.displayName = concat("embedded:", index);
            source.embedded = texture;
            source.found = true;
            return source;
        }
        // As written, relative to the model's folder; then the usual repairs for paths written
        // on another system: backslashes, %-encoded URIs, and finally the bare file name.
        std::string slashes = raw;
        for (char& c : slashes)
            if (c == '\\') c = '/';
        const std::string candidates[] = {raw, slashes, percentDecode(slashes),
                                          fs::path(slashes).filename().string()};
        for (const std::string& candidate : candidates) {
            if (candidate.empty()) continue;
            const fs::path p = fs::path(candidate).is_absolute() ? fs::path(candidate)
                                                                 : modelDir_ / candidate;
            if (isRegularFile(p)) {
                source.file = p.lexically_normal();
                source.key = "file:" + source.file.string();
                source.displayName = source.file.string();
                source.found = true;
                return source;
            }
        }
        const fs::path expected = fs::path(raw).is_absolute() ? fs::path(raw) : modelDir_ / raw;
        source.displayName = expected.lexically_normal().string();
        source.key = "missing:" + source.displayName;
        return source;
    }

    // Decodes (once) and returns the image, or nothing with a warning naming file and material.
    const Texture* image(const TextureSource& source, const std::string& materialName) {
        auto it = images_.find(source.key);
        if (it == images_.end()) {
            std::string error;
            std::optional<Texture> decoded;
            if (!source.found) {
                error = "not found";
            } else if (source.embedded) {
                decoded = decodeEmbedded(*source.embedded, source.displayName, error);
            } else {
                decoded = decodeImageFile(source.file, source.displayName, error);
                if (!decoded) error = "cannot be decoded (" + error + ")";
            }
            if (!decoded) {
                logWarnOnce("texture:" + source.displayName,
                            concat("texture '", source.displayName, "' of material '",
                                   materialName, "' ", error,
                                   "; the material is drawn without it"));
                if (reportedMissing_.insert(source.displayName).second)
                    scene_.report.missingTextures.push_back(source.displayName);
            }
            it = images_.emplace(source.key, std::move(decoded)).first;
        }
        return it->second ? &*it->second : nullptr;
    }

    // Index in scene.textures of the decoded image `key` (which image() returned), added on
    // first use.
    int use(const std::string& key) {
        auto it = indices_.find(key);
        if (it != indices_.end()) return it->second;
        const int index = static_cast<int>(order_.size());
        order_.push_back(key);
        indices_.emplace(key, index);
        return index;
    }
    // Same for a texture made here (a base texture with a folded-in mask).
    int use(const std::string& key, Texture texture) {
        images_.emplace(key, std::move(texture));
        return use(key);
    }
    int indexOf(const std::string& key) const {
        auto it = indices_.find(key);
        return it == indices_.end() ? -1 : it->second;
    }
    // Moves the used images into scene.textures (no copies: a decoded image lives in one place).
    void finish() {
        scene_.textures.reserve(order_.size());
        for (const std::string& key : order_) scene_.textures.push_back(std::move(*images_.at(key)));
        images_.clear();
    }

private:
    static std::optional<Texture> decodeEmbedded(const aiTexture& t, const std::string& name,
                                                 std::string& error) {
        if (!t.pcData) {
            error = "has no data";
            return std::nullopt;
        }
        if (t.mHeight == 0) {  // compressed (PNG, JPEG, …), mWidth bytes
            auto decoded = decodeImageMemory(reinterpret_cast<const std::uint8_t*>(t.pcData),
                                             t.mWidth, name, error);
            if (!decoded) error = "cannot be decoded (" + error + ")";
            return decoded;
        }
        if (std::uint64_t(t.mWidth) * t.mHeight > (std::uint64_t(1) << 28)) {
            error = concat("is too large (", t.mWidth, "x", t.mHeight, ")");
            return std::nullopt;
        }
        Texture texture;  // raw aiTexel array, BGRA
        texture.name = name;
        texture.width = static_cast<int>(t.mWidth);
        texture.height = static_cast<int>(t.mHeight);
        texture.rgba.resize(std::size_t(t.mWidth) * t.mHeight * 4);
        for (std::size_t i = 0; i < std::size_t(t.mWidth) * t.mHeight; ++i) {
            texture.rgba[4 * i + 0] = t.pcData[i].r;
            texture.rgba[4 * i + 1] = t.pcData[i].g;
            texture.rgba[4 * i + 2] = t.pcData[i].b;
            texture.rgba[4 * i + 3] = t.pcData[i].a;
        }
        return texture;
    }

    const aiScene& ai_;
    fs::path modelDir_;
    Scene& scene_;
    std::map<std::string, std::optional<Texture>> images_;  // decoded once per source
    std::vector<std::string> order_;                        // keys of scene.textures, in order
    std::map<std::string, int> indices_;                    // key -> index in scene.textures
    std::set<std::string> reportedMissing_;
};

std::optional<std::string> textureOf(const aiMaterial& m, aiTextureType type) {
    if (m.GetTextureCount(type) == 0) return std::nullopt;
    aiString path;
    if (m.GetTexture(type, 0, &path) != AI_SUCCESS || path.length == 0) return std::nullopt;
    return std::string(path.C_Str());
}

bool finite3(const aiColor4D& c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

// A colour property sanitized to finite values in [0, max]; warns (once per material/key) when
// it had to change anything.
glm::vec3 sanitizeColour(glm::vec3 c, float max, const std::string& material, const char* what) {
    glm::vec3 out = c;
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(out[i]) || out[i] < 0.0f) out[i] = 0.0f;
        if (out[i] > max) out[i] = max;
    }
    if (out != c)
        logWarnOnce(concat("material-colour:", material, ":", what),
                    concat("material '", material, "': ", what, " (", c.x, ", ", c.y, ", ", c.z,
                           ") is outside [0, ", max, "]; clamped to (", out.x, ", ", out.y, ", ",
                           out.z, ")"));
    return out;
}

}  // namespace

void importMaterials(const aiScene& ai, const std::vector<std::uint32_t>& used,
                     const fs::path& modelPath, Scene& scene) {
    TextureLibrary library(ai, modelPath, scene);
    scene.materials.clear();
    scene.textures.clear();

    for (std::uint32_t index : used) {
        Material material;
        if (index >= ai.mNumMaterials || !ai.mMaterials[index]) {
            material.name = "default";
            scene.materials.push_back(material);
            continue;
        }
        const aiMaterial& m = *ai.mMaterials[index];

        aiString name;
        material.name = (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length > 0)
                            ? std::string(name.C_Str())
                            : concat("material ", index);

        // Base colour: glTF's baseColorFactor, else the diffuse colour (OBJ Kd, FBX, …). Both
        // are linear already.
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

        // Emissive radiance W/(m²·sr): colour × strength (KHR_materials_emissive_strength).
        aiColor4D emissive(0.0f, 0.0f, 0.0f, 1.0f);
        if (m.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == AI_SUCCESS && finite3(emissive)) {
            float strength = 1.0f;
            if (m.Get(AI_MATKEY_EMISSIVE_INTENSITY, strength) != AI_SUCCESS ||
                !std::isfinite(strength) || strength < 0.0f)
                strength = 1.0f;
            material.emissive =
                sanitizeColour(glm::vec3(emissive.r, emissive.g, emissive.b) * strength, 1e9f,
                               material.name, "emissive colour");
        }

        // Base-colour texture.
        std::optional<std::string> baseRef = textureOf(m, aiTextureType_BASE_COLOR);
        if (!baseRef) baseRef = textureOf(m, aiTextureType_DIFFUSE);
        const Texture* baseImage = nullptr;
        TextureSource baseSource;
        if (baseRef) {
            baseSource = library.resolve(*baseRef);
            baseImage = library.image(baseSource, material.name);
        }

        // Alpha mode. glTF says it explicitly; other formats (OBJ, …) have no such notion, so a
        // separate opacity map (OBJ map_d) or a base texture with transparent texels is a mask.
        aiString alphaMode;
        if (m.Get(AI_MATKEY_GLTF_ALPHAMODE, alphaMode) == AI_SUCCESS) {
            const std::string mode = alphaMode.C_Str();
            float cutoff = 0.5f;
            if (m.Get(AI_MATKEY_GLTF_ALPHACUTOFF, cutoff) != AI_SUCCESS || !std::isfinite(cutoff))
                cutoff = 0.5f;
            if (mode == "MASK") {
                material.alphaMode = AlphaMode::Mask;
                material.alphaCutoff = std::clamp(cutoff, 0.0f, 1.0f);
            } else if (mode == "BLEND") {
                // No blending in a voxel GI pipeline: see-through parts become holes, the rest
                // is solid.
                material.alphaMode = AlphaMode::Mask;
                material.alphaCutoff = 0.5f;
                logWarnOnce("blend:" + material.name,
                            concat("material '", material.name,
                                   "': alphaMode BLEND is not supported; drawn as MASK with "
                                   "cutoff 0.5"));
            }
            if (baseImage) material.baseColorTexture = library.use(baseSource.key);
        } else {
            std::optional<std::string> maskRef = textureOf(m, aiTextureType_OPACITY);
            const Texture* maskImage = nullptr;
            TextureSource maskSource;
            if (maskRef) {
                maskSource = library.resolve(*maskRef);
                if (maskSource.key == baseSource.key) {
                    maskRef.reset();  // map_d names the base texture: its alpha is the mask
                    material.alphaMode = AlphaMode::Mask;
                } else {
                    maskImage = library.image(maskSource, material.name);
                }
            }
            if (maskImage) {
                material.alphaMode = AlphaMode::Mask;
                const std::string key = concat("fold:", baseSource.key, "|", maskSource.key);
                int folded = library.indexOf(key);
                if (folded < 0) {
                    Texture texture;
                    if (baseImage) {
                        texture = *baseImage;
                        texture.name = baseImage->name + " (alpha from " + maskImage->name + ")";
                    } else {  // white base, the mask as alpha: baseColor × 1
                        texture.name = maskImage->name + " (as alpha)";
                        texture.width = maskImage->width;
                        texture.height = maskImage->height;
                        texture.rgba.assign(maskImage->rgba.size(), 255);
                    }
                    if (!foldMaskIntoAlpha(texture, *maskImage))
                        logWarnOnce("mask-size:" + key,
                                    concat("material '", material.name, "': opacity map '",
                                           maskImage->name, "' (", maskImage->width, "x",
                                           maskImage->height, ") does not match base colour "
                                           "texture '", baseImage->name, "' (", texture.width,
                                           "x", texture.height,
                                           "); resampled it to that size (nearest texel)"));
                    folded = library.use(key, std::move(texture));
                }
                material.baseColorTexture = folded;
            } else if (baseImage) {
                material.baseColorTexture = library.use(baseSource.key);
                if (hasTransparentTexel(*baseImage)) material.alphaMode = AlphaMode::Mask;
            }
            material.alphaCutoff = 0.5f;
        }
        scene.materials.push_back(material);
    }
    library.finish();

    if (scene.materials.empty()) {
        Material grey;
        grey.name = "default";
        scene.materials.push_back(grey);
    }
}

}  // namespace vct
