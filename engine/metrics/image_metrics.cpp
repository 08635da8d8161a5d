#include "metrics/image_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "metrics/ssim.hpp"

namespace vct::metrics {
namespace {

void checkMask(const PixelMask& mask, const ImageF& image) {
    if (mask.width != image.width || mask.height != image.height)
        fail("the mask is ", mask.width, "x", mask.height, " but the images are ", image.width, "x", image.height,
             "; use a mask of the same size");
    if (mask.countedPixels == 0) fail("the mask selects no pixel (pixels count where the mask luminance is > 0.5)");
}

}  // namespace

double meanLuminance(const ImageF& image, const PixelMask& mask) {
    if (mask.countedPixels == 0) return 0.0;
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (mask(x, y)) sum += luminance(image.at(x, y));
    return sum / double(mask.countedPixels);
}

void checkFinite(const ImageF& image, const char* name) {
    std::size_t bad = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) bad += !std::isfinite(image.at(x, y)[c]);
    if (bad) fail(name, " holds ", bad, " non-finite (NaN or Inf) values; metrics need finite radiance");
}

void checkSameSize(const ImageF& a, const ImageF& b, const char* nameA, const char* nameB) {
    if (a.width != b.width || a.height != b.height)
        fail("the images differ in size: ", nameA, " is ", a.width, "x", a.height, ", ", nameB, " is ", b.width, "x",
             b.height, "; compare images rendered at the same --width and --height");
}

double rmse(const ImageF& a, const ImageF& b, const PixelMask& mask) {
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (!mask(x, y)) continue;
            for (int c = 0; c < 3; ++c) {
                const double d = double(a.at(x, y)[c]) - double(b.at(x, y)[c]);
                sum += d * d;
            }
        }
    return std::sqrt(sum / (3.0 * double(mask.countedPixels)));
}

double rmse(const ImageF& a, const ImageF& b) { return rmse(a, b, allPixels(a.width, a.height)); }

double relativeMse(const ImageF& a, const ImageF& b, const PixelMask& mask) {
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (!mask(x, y)) continue;
            for (int c = 0; c < 3; ++c) {
                const double va = a.at(x, y)[c], vb = b.at(x, y)[c];
                sum += (va - vb) * (va - vb) / (vb * vb + kRelMseEpsilon);
            }
        }
    return sum / (3.0 * double(mask.countedPixels));
}

std::vector<double> signedRelativeErrors(const ImageF& a, const ImageF& b, const PixelMask& mask) {
    const double floor = std::max(kRelativeErrorFloor * meanLuminance(b, mask), 1e-30);
    std::vector<double> errors(std::size_t(a.width) * a.height, 0.0);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (!mask(x, y)) continue;
            const double ya = luminance(a.at(x, y)), yb = luminance(b.at(x, y));
            errors[std::size_t(y) * a.width + x] = (ya - yb) / std::max(yb, floor);
        }
    return errors;
}

ImageMetrics compareImages(const ImageF& a, const ImageF& b, const PixelMask& mask, const DisplaySettings& display) {
    checkSameSize(a, b, "A", "B");
    checkMask(mask, a);
    checkFinite(a, "image A");
    checkFinite(b, "image B");
    ImageMetrics m;
    m.width = a.width;
    m.height = a.height;
    m.pixels = mask.countedPixels;
    m.rmse = rmse(a, b, mask);
    m.relMse = relativeMse(a, b, mask);
    const auto lumaA = displayLuma(a, display.exposureEV, display.curve);
    const auto lumaB = displayLuma(b, display.exposureEV, display.curve);
    m.psnr = psnr(lumaA, lumaB, mask);
    m.ssim = ssim(lumaA, lumaB, mask);

    double sumA = 0.0, sumB = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            if (mask(x, y)) {
                sumA += luminance(a.at(x, y));
                sumB += luminance(b.at(x, y));
            }
    m.meanLuminanceA = sumA / double(m.pixels);
    m.meanLuminanceB = sumB / double(m.pixels);

    const auto signedErrors = signedRelativeErrors(a, b, mask);
    std::vector<double> errors;
    errors.reserve(m.pixels);
    for (std::size_t i = 0; i < signedErrors.size(); ++i)
        if (mask.counts[i]) errors.push_back(std::abs(signedErrors[i]));
    std::sort(errors.begin(), errors.end());
    auto quantile = [&](double q) {  // nearest rank
        const std::size_t rank = std::size_t(std::ceil(q * double(errors.size())));
        return errors[std::min(errors.size() - 1, rank > 0 ? rank - 1 : 0)];
    };
    m.relErrorMedian = errors.size() % 2 ? errors[errors.size() / 2]
                                         : 0.5 * (errors[errors.size() / 2 - 1] + errors[errors.size() / 2]);
    m.relErrorP95 = quantile(0.95);
    const auto within = [&](double limit) {
        return double(std::upper_bound(errors.begin(), errors.end(), limit) - errors.begin()) / double(errors.size());
    };
    m.fractionWithin1Percent = within(0.01);
    m.fractionWithin5Percent = within(0.05);
    return m;
}

}  // namespace vct::metrics
