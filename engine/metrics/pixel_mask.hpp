#pragma once
// Which pixels an error metric counts. A mask image selects the pixels whose mask luminance
// (Rec. 709 weights on the stored values) is > 0.5; without a mask every pixel counts.
#include <filesystem>
#include <optional>
#include <vector>

#include "core/image.hpp"

namespace vct::metrics {

// Rec. 709 / sRGB luminance of linear RGB.
inline double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

struct PixelMask {
    int width = 0, height = 0;
    std::vector<std::uint8_t> counts;  // 1 = counted, row-major, top row first
    std::size_t countedPixels = 0;

    bool operator()(int x, int y) const { return counts[std::size_t(y) * width + x] != 0; }
};

PixelMask allPixels(int width, int height);
PixelMask maskFromImage(const ImageF& mask);  // luminance > 0.5
// Reads .pfm/.exr as stored, anything else (PNG, …) through stb_image with values / 255 (no
// sRGB decoding: white is 1, black is 0).
ImageF readMaskImage(const std::filesystem::path& path);

}  // namespace vct::metrics
