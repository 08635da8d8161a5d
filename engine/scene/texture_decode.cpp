#include "scene/texture_decode.hpp"

#include <climits>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "scene/image_payload.hpp"

#include <stb_image.h>  // implementation in libstb (Debian's libstb-dev)

namespace vct {
namespace {

std::string concatSize(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height) +
           " texels, more than vct decodes (16384 per side, 134217728 in all)";
}

std::optional<Texture> adopt(stbi_uc* pixels, int width, int height, const std::string& name,
                             std::string& error) {
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        error = reason ? reason : "unknown stb_image error";
        return std::nullopt;
    }
    Texture texture;
    texture.name = name;
    texture.width = width;
    texture.height = height;
    const std::size_t bytes = std::size_t(width) * std::size_t(height) * 4;
    texture.rgba.assign(pixels, pixels + bytes);
    stbi_image_free(pixels);
    return texture;
}

// Textures up to 16384 texels per side (GL_MAX_TEXTURE_SIZE on llvmpipe and most GPUs) and 2^27
// texels (512 MiB decoded) are decoded; larger ones are refused from their header, before
// stb_image allocates what a 100-byte file may declare (20000² texels: 1.6 GB).
constexpr int kMaxTextureSide = 16384;
constexpr long long kMaxTextureTexels = 1ll << 27;

bool tooLarge(bool headerRead, int width, int height, std::string& error) {
    if (!headerRead || (width <= kMaxTextureSide && height <= kMaxTextureSide &&
                        (long long)width * height <= kMaxTextureTexels))
        return false;
    error = concatSize(width, height);
    return true;
}

}  // namespace

// The file read whole: the payload check needs its size and header, and stb_image then decodes
// from memory what was checked.
std::optional<Texture> decodeImageFile(const std::filesystem::path& file, const std::string& name,
                                       std::string& error) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        error = "can't fopen";
        return std::nullopt;
    }
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return decodeImageMemory(bytes.data(), bytes.size(), name, error);
}

std::optional<Texture> decodeImageMemory(const std::uint8_t* data, std::size_t size,
                                         const std::string& name, std::string& error) {
    if (!data || size == 0) {
        error = "empty image data";
        return std::nullopt;
    }
    if (size > std::size_t(INT_MAX)) {
        error = "image data larger than 2 GiB";
        return std::nullopt;
    }
    int width = 0, height = 0, channels = 0;
    const bool headerRead = stbi_info_from_memory(data, static_cast<int>(size), &width, &height, &channels) != 0;
    if (tooLarge(headerRead, width, height, error)) return std::nullopt;
    if (headerRead) {
        if (std::optional<std::string> reason = implausibleImagePayload(data, size, width, height)) {
            error = *reason;
            return std::nullopt;
        }
    }
    stbi_uc* pixels =
        stbi_load_from_memory(data, static_cast<int>(size), &width, &height, &channels, 4);
    return adopt(pixels, width, height, name, error);
}

bool hasTransparentTexel(const Texture& texture) {
    for (std::size_t i = 3; i < texture.rgba.size(); i += 4)
        if (texture.rgba[i] < 255) return true;
    return false;
}

bool foldMaskIntoAlpha(Texture& target, const Texture& mask) {
    const int channel = hasTransparentTexel(mask) ? 3 : 0;
    const bool sameSize = target.width == mask.width && target.height == mask.height;
    for (int y = 0; y < target.height; ++y) {
        const int my = sameSize ? y : int((std::int64_t(y) * mask.height) / target.height);
        for (int x = 0; x < target.width; ++x) {
            const int mx = sameSize ? x : int((std::int64_t(x) * mask.width) / target.width);
            const std::size_t from = (std::size_t(my) * mask.width + mx) * 4 + channel;
            target.rgba[(std::size_t(y) * target.width + x) * 4 + 3] = mask.rgba[from];
        }
    }
    return sameSize;
}

}  // namespace vct
