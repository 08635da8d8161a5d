#pragma once
// In-memory images and their files. Rows are stored top to bottom (as in PNG); PFM files,
// which are bottom to top, are flipped on read and write.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace vct {

// Linear float RGBA, e.g. HDR radiance or an AOV.
struct ImageF {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;  // width * height * 4

    ImageF() = default;
    ImageF(int w, int h) : width(w), height(h), rgba(std::size_t(w) * h * 4, 0.0f) {}
    float* at(int x, int y) { return &rgba[(std::size_t(y) * width + x) * 4]; }
    const float* at(int x, int y) const { return &rgba[(std::size_t(y) * width + x) * 4]; }
};

// 8-bit RGBA, display-referred (sRGB encoded).
struct Image8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;

    Image8() = default;
    Image8(int w, int h) : width(w), height(h), rgba(std::size_t(w) * h * 4, 0) {}
    std::uint8_t* at(int x, int y) { return &rgba[(std::size_t(y) * width + x) * 4]; }
    const std::uint8_t* at(int x, int y) const { return &rgba[(std::size_t(y) * width + x) * 4]; }
};

void writePng(const std::filesystem::path& path, const Image8& image);
Image8 readPng(const std::filesystem::path& path);  // any format stb_image reads

// Linear float image by extension: ".pfm" (RGB float) or ".exr" (OpenEXR, RGBA float).
void writeHdrImage(const std::filesystem::path& path, const ImageF& image);
ImageF readHdrImage(const std::filesystem::path& path);

// Largest image side vct accepts anywhere (the GL limits of a context may be lower).
constexpr int kMaxImageSide = 16384;
// Throws naming `what` (e.g. "image size") when width × height is outside 1..kMaxImageSide.
void validateImageSize(int width, int height, const char* what = "image size");

// Throws a clear error when `path`'s folder does not exist or is not writable.
void ensureWritable(const std::filesystem::path& path);
// ensureWritable, and the name must say the format written there (`.png` for the tone-mapped
// images, `.pfm`/`.exr` for linear ones), so that whatever opens the file reads it as what it is.
// `option` names the flag in the message.
void ensureWritablePng(const std::filesystem::path& path, const char* option);
void ensureWritableHdr(const std::filesystem::path& path, const char* option);

}  // namespace vct
