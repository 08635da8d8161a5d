#include "metrics/error_image.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "metrics/image_metrics.hpp"

namespace vct::metrics {

Image8 relativeErrorImage(const ImageF& a, const ImageF& b, const PixelMask& mask, double scale) {
    if (!(scale > 0.0) || !std::isfinite(scale)) fail("the error image scale must be a positive number, got ", scale);
    const auto errors = signedRelativeErrors(a, b, mask);
    const double white[3] = {255, 255, 255}, blue[3] = {59, 76, 192}, red[3] = {180, 4, 38};
    Image8 out(a.width, a.height);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            std::uint8_t* p = out.at(x, y);
            p[3] = 255;
            if (!mask(x, y)) {
                p[0] = p[1] = p[2] = 0;
                continue;
            }
            const double t = std::clamp(errors[std::size_t(y) * a.width + x] / scale, -1.0, 1.0);
            const double* end = t < 0 ? blue : red;
            for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(std::lround(white[c] + (end[c] - white[c]) * std::abs(t)));
        }
    return out;
}

std::string errorImageLegend(double scale) {
    return concat("blue = A darker than B, white = equal, red = A brighter; full colour at ±", scale * 100.0,
                  " % relative luminance error; black = outside the mask");
}

}  // namespace vct::metrics
