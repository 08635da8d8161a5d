#include "metrics/error_image.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "metrics/image_metrics.hpp"

namespace vct::metrics {
namespace {

constexpr std::uint8_t kOutsideMask[3] = {0, 0, 0};
constexpr std::uint8_t kBothDark[3] = {128, 128, 128};

void setColour(std::uint8_t* pixel, const std::uint8_t* rgb) {
    std::copy(rgb, rgb + 3, pixel);
    pixel[3] = 255;
}

// t in [−1, 1] (clamped) on the blue–white–red scale.
void setDiverging(std::uint8_t* pixel, double t) {
    static const double white[3] = {255, 255, 255}, blue[3] = {59, 76, 192}, red[3] = {180, 4, 38};
    t = std::clamp(t, -1.0, 1.0);
    const double* end = t < 0 ? blue : red;
    for (int c = 0; c < 3; ++c) pixel[c] = std::uint8_t(std::lround(white[c] + (end[c] - white[c]) * std::abs(t)));
    pixel[3] = 255;
}

}  // namespace

Image8 relativeErrorImage(const ImageF& a, const ImageF& b, const PixelMask& mask, double scale) {
    if (!(scale > 0.0) || !std::isfinite(scale)) fail("the error image scale must be a positive number, got ", scale);
    const auto errors = signedRelativeErrors(a, b, mask);
    Image8 out(a.width, a.height);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (!mask(x, y)) setColour(out.at(x, y), kOutsideMask);
            else setDiverging(out.at(x, y), errors[std::size_t(y) * a.width + x] / scale);
        }
    return out;
}

Image8 ratioImage(const ImageF& a, const ImageF& b, const PixelMask& mask, double stops) {
    if (!(stops > 0.0) || !std::isfinite(stops))
        fail("the ratio image's full-colour ratio must be a positive number of stops (e.g. 2 for 4x), got ", stops);
    checkSameSize(a, b, "A", "B");
    if (mask.width != a.width || mask.height != a.height)
        fail("the mask is ", mask.width, "x", mask.height, " but the images are ", a.width, "x", a.height,
             "; use a mask of the same size");
    // The floor keeps black pixels finite; relative to the reference's mean so it needs no units.
    const double floor = std::max(kRatioDarkFraction * meanLuminance(b, mask), 1e-30);
    Image8 out(a.width, a.height);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (!mask(x, y)) {
                setColour(out.at(x, y), kOutsideMask);
                continue;
            }
            const double ya = luminance(a.at(x, y)), yb = luminance(b.at(x, y));
            if (ya < floor && yb < floor) setColour(out.at(x, y), kBothDark);
            else setDiverging(out.at(x, y), std::log2(std::max(ya, floor) / std::max(yb, floor)) / stops);
        }
    return out;
}

std::string errorImageLegend(double scale) {
    return concat("blue = A darker than B, white = equal, red = A brighter; full colour at ±", scale * 100.0,
                  " % relative luminance error; black = outside the mask");
}

std::string ratioImageLegend(double stops) {
    return concat("blue = A darker, red = A brighter, white = equal, full colour at ", std::pow(2.0, stops), "x (",
                  stops, stops == 1.0 ? " stop" : " stops", "), grey = both dark, black = outside the mask");
}

}  // namespace vct::metrics
