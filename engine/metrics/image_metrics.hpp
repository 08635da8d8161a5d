#pragma once
// Error of an image A (e.g. the engine's) against a reference B (e.g. `vct reference`'s), both
// linear radiance of the same size. Definitions (all over the counted pixels of the mask):
//
//   RMSE     sqrt( mean over pixels and RGB channels of (a − b)² )            linear radiance
//   relMSE   mean over pixels and channels of (a − b)² / (b² + ε),  ε = 1e-2  (Rousselle et al.
//            2011; ε keeps black reference pixels from dominating; with radiance of order 1 it
//            weighs errors in pixels darker than ~0.1 W/(m²·sr) less)
//   PSNR     10·log10(1 / MSE) of the luma of the *displayed* images (see ssim.hpp), in dB;
//            +inf for identical images
//   SSIM     structural similarity of the same luma images (ssim.hpp)
//   per-pixel relative error  r = |Y(a) − Y(b)| / max(Y(b), 0.01·mean Y(b)),  Y = Rec. 709
//            luminance of the linear radiance; the floor at 1 % of the mean reference luminance
//            keeps black pixels finite and makes r independent of the units. Reported as the
//            median, the 95th percentile and the fractions of pixels within 1 % and 5 %.
#include <cstddef>
#include <vector>

#include "core/image.hpp"
#include "core/tonemap.hpp"
#include "metrics/pixel_mask.hpp"

namespace vct::metrics {

inline constexpr double kRelMseEpsilon = 1e-2;
inline constexpr double kRelativeErrorFloor = 0.01;  // × mean reference luminance

struct DisplaySettings {
    double exposureEV = 0.0;
    TonemapCurve curve = TonemapCurve::Aces;
};

struct ImageMetrics {
    int width = 0, height = 0;
    std::size_t pixels = 0;  // counted pixels
    double rmse = 0.0;
    double relMse = 0.0;
    double psnr = 0.0;  // dB, +inf when identical
    double ssim = 1.0;
    double meanLuminanceA = 0.0, meanLuminanceB = 0.0;
    double relErrorMedian = 0.0, relErrorP95 = 0.0;
    double fractionWithin1Percent = 0.0, fractionWithin5Percent = 0.0;
};

// Throws vct::Error when the sizes differ (naming both), the mask has another size or selects
// no pixel, or an image holds NaN/Inf values.
ImageMetrics compareImages(const ImageF& a, const ImageF& b, const PixelMask& mask, const DisplaySettings& display);

// The parts, for tests and other tools.
double rmse(const ImageF& a, const ImageF& b, const PixelMask& mask);
double rmse(const ImageF& a, const ImageF& b);  // over every pixel
double relativeMse(const ImageF& a, const ImageF& b, const PixelMask& mask);
// Signed per-pixel relative luminance error (Y(a) − Y(b)) / max(Y(b), floor), floor as above;
// 0 outside the mask.
std::vector<double> signedRelativeErrors(const ImageF& a, const ImageF& b, const PixelMask& mask);

// Mean Rec. 709 luminance over the counted pixels (0 when none counts).
double meanLuminance(const ImageF& image, const PixelMask& mask);

void checkSameSize(const ImageF& a, const ImageF& b, const char* nameA, const char* nameB);
// Throws naming `name` and the count when an RGB value is NaN or Inf.
void checkFinite(const ImageF& image, const char* name);

}  // namespace vct::metrics
