#pragma once
// The textures that a model's materials refer to: where each reference points (a file relative
// to the model, repaired when written on another system, or an image embedded in the file), each
// image decoded once however many materials use it, and the used ones handed to Scene::textures
// in order of first use. A texture that is missing or cannot be decoded is a warning (once per
// file) and is listed in LoadReport::missingTextures.
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "scene/scene.hpp"

struct aiScene;
struct aiTexture;

namespace vct {

// Where a texture reference in a material points to.
struct TextureSource {
    std::string key;          // cache key: "file:<path>", "embedded:<index>" or "missing:<path>"
    std::string displayName;  // for messages and Texture::name
    std::filesystem::path file;  // external file (empty when embedded or not found)
    const aiTexture* embedded = nullptr;
    bool found = false;
};

class TextureLibrary {
public:
    // `modelPath` is the model file; its folder resolves relative texture paths.
    TextureLibrary(const aiScene& ai, const std::filesystem::path& modelPath, Scene& scene);

    // Where the reference `raw` (as the material writes it) points to.
    TextureSource resolve(const std::string& raw) const;

    // Decodes (once) and returns the image, or nothing with a warning naming file and material.
    const Texture* image(const TextureSource& source, const std::string& materialName);

    // Index in scene.textures of the decoded image `key` (which image() returned), added on
    // first use.
    int use(const std::string& key);
    // Same for a texture made by the caller (a base texture with a folded-in mask).
    int use(const std::string& key, Texture texture);
    // Index in scene.textures of `key`, or −1 when it is not used (yet).
    int indexOf(const std::string& key) const;

    // Moves the used images into scene.textures (no copies: a decoded image lives in one place).
    void finish();

private:
    const aiScene& ai_;
    std::filesystem::path modelDir_;
    Scene& scene_;
    std::map<std::string, std::optional<Texture>> images_;  // decoded once per source
    std::vector<std::string> order_;                        // keys of scene.textures, in order
    std::map<std::string, int> indices_;                    // key -> index in scene.textures
    std::set<std::string> reportedMissing_;
};

}  // namespace vct
