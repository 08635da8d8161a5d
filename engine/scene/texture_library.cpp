#include "scene/texture_library.hpp"

#include <cstdint>

#include <assimp/scene.h>

#include "core/error.hpp"
#include "core/log.hpp"
#include "scene/texture_decode.hpp"
#include "scene/uri_path.hpp"

namespace fs = std::filesystem;

namespace vct {
namespace {

// The paths to try for a reference written in a material: as written, then the usual repairs
// for paths written on another system: backslashes, %-encoded URIs, and finally the bare file
// name.
std::vector<std::string> candidatePaths(const std::string& raw) {
    std::string slashes = raw;
    for (char& c : slashes)
        if (c == '\\') c = '/';
    return {raw, slashes, percentDecoded(slashes), fs::path(slashes).filename().string()};
}

// An uncompressed embedded texture: an array of aiTexel, BGRA.
Texture fromTexels(const aiTexture& t, const std::string& name) {
    Texture texture;
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

std::optional<Texture> decodeEmbedded(const aiTexture& t, const std::string& name, std::string& error) {
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
    return fromTexels(t, name);
}

// The image of a resolved reference, or nothing with `error` completing the sentence
// "texture '<name>' of material '<material>' …".
std::optional<Texture> decode(const TextureSource& source, std::string& error) {
    if (!source.found) {
        error = "not found";
        return std::nullopt;
    }
    if (source.embedded) return decodeEmbedded(*source.embedded, source.displayName, error);
    std::optional<Texture> decoded = decodeImageFile(source.file, source.displayName, error);
    if (!decoded) error = "cannot be decoded (" + error + ")";
    return decoded;
}

}  // namespace

TextureLibrary::TextureLibrary(const aiScene& ai, const fs::path& modelPath, Scene& scene)
    : ai_(ai), modelDir_(modelPath.parent_path()), scene_(scene) {}

TextureSource TextureLibrary::resolve(const std::string& raw) const {
    TextureSource source;
    if (auto [texture, index] = ai_.GetEmbeddedTextureAndIndex(raw.c_str()); texture) {
        source.key = concat("embedded:", index);
        source.displayName = concat("embedded:", index);
        source.embedded = texture;
        source.found = true;
        return source;
    }
    for (const std::string& candidate : candidatePaths(raw)) {
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

const Texture* TextureLibrary::image(const TextureSource& source, const std::string& materialName) {
    auto it = images_.find(source.key);
    if (it == images_.end()) {
        std::string error;
        std::optional<Texture> decoded = decode(source, error);
        if (!decoded) {
            logWarnOnce("texture:" + source.displayName,
                        concat("texture '", source.displayName, "' of material '", materialName,
                               "' ", error, "; the material is drawn without it"));
            if (reportedMissing_.insert(source.displayName).second)
                scene_.report.missingTextures.push_back(source.displayName);
        }
        it = images_.emplace(source.key, std::move(decoded)).first;
    }
    return it->second ? &*it->second : nullptr;
}

int TextureLibrary::use(const std::string& key) {
    auto it = indices_.find(key);
    if (it != indices_.end()) return it->second;
    const int index = static_cast<int>(order_.size());
    order_.push_back(key);
    indices_.emplace(key, index);
    return index;
}

int TextureLibrary::use(const std::string& key, Texture texture) {
    images_.emplace(key, std::move(texture));
    return use(key);
}

int TextureLibrary::indexOf(const std::string& key) const {
    auto it = indices_.find(key);
    return it == indices_.end() ? -1 : it->second;
}

void TextureLibrary::finish() {
    scene_.textures.reserve(order_.size());
    for (const std::string& key : order_) scene_.textures.push_back(std::move(*images_.at(key)));
    images_.clear();
}

}  // namespace vct
