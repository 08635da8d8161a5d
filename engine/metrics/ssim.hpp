#pragma once
// Image quality on the displayed images: both linear images go through the display transform
// (core/tonemap.hpp: exposure, tone curve, sRGB OETF, values in [0, 1], not quantized) and are
// reduced to luma Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' of the encoded values.
//
// PSNR = 10·log10(1 / mean (Y'a − Y'b)²)  (peak 1), +inf when the images are identical.
//
// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, "Image quality assessment: from error visibility
// to structural similarity"): at each pixel, Gaussian-weighted means, variances and covariance
// over an 11×11 window with σ = 1.5, then
//     SSIM = (2 μa μb + C1)(2 σab + C2) / ((μa² + μb² + C1)(σa² + σb² + C2)),
//     C1 = (0.01·L)², C2 = (0.03·L)², L = 1 (the dynamic range of Y').
// The window is clipped at the image border and to the mask's counted pixels, and its weights are
// renormalized (no padding): every pixel has a value, small images work, and pixels outside the
// mask influence nothing. The reported SSIM is the mean over counted pixels.
#include <vector>

#include "core/image.hpp"
#include "core/tonemap.hpp"
#include "metrics/pixel_mask.hpp"

namespace vct::metrics {

std::vector<double> displayLuma(const ImageF& image, double exposureEV, TonemapCurve curve);

double psnr(const std::vector<double>& a, const std::vector<double>& b, const PixelMask& mask);
double ssim(const std::vector<double>& a, const std::vector<double>& b, const PixelMask& mask);

}  // namespace vct::metrics
