#include "metrics/pixel_mask.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "core/file_extension.hpp"

namespace vct::metrics {

PixelMask allPixels(int width, int height) {
    PixelMask m;
    m.width = width;
    m.height = height;
    m.counts.assign(std::size_t(width) * height, 1);
    m.countedPixels = m.counts.size();
    return m;
}

PixelMask maskFromImage(const ImageF& mask) {
    PixelMask m = allPixels(mask.width, mask.height);
    m.countedPixels = 0;
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x) {
            const bool counted = luminance(mask.at(x, y)) > 0.5;
            m.counts[std::size_t(y) * mask.width + x] = counted;
            m.countedPixels += counted;
        }
    return m;
}

ImageF readMaskImage(const std::filesystem::path& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".pfm" || ext == ".exr") return readHdrImage(path);
    const Image8 image = readPng(path);
    ImageF out(image.width, image.height);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) out.rgba[i] = float(image.rgba[i]) / 255.0f;
    return out;
}

}  // namespace vct::metrics
