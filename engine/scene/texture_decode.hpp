#pragma once
// Image files and in-memory images to Scene textures: stb_image, always 8-bit RGBA (grey, grey +
// alpha and RGB are expanded; 16-bit images are reduced to 8 bits), rows top to bottom as stored.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "scene/scene.hpp"

namespace vct {

// Decodes an image file (PNG, JPEG, TGA, BMP, …). On failure returns nothing and sets `error`
// to stb_image's reason ("can't fopen", "bad png sig", …).
std::optional<Texture> decodeImageFile(const std::filesystem::path& file, const std::string& name,
                                       std::string& error);

// Same for an encoded image held in memory (e.g. a texture embedded in a glTF/GLB file).
std::optional<Texture> decodeImageMemory(const std::uint8_t* data, std::size_t size,
                                         const std::string& name, std::string& error);

// True when any texel has alpha < 255.
bool hasTransparentTexel(const Texture& texture);

// Copies a coverage mask into `target`'s alpha channel. The mask value of a texel is its alpha
// when `mask` has any transparent texel, else its red channel (= luma for grey images). A mask of
// another size is resampled (nearest texel); returns false in that case so the caller can warn.
bool foldMaskIntoAlpha(Texture& target, const Texture& mask);

}  // namespace vct
