#pragma once
// False-colour pictures of where and how A differs from the reference B, on one diverging
// blue–white–red scale (Moreland's cool-warm end points), interpolated in sRGB-encoded values:
//   t = −1   blue  (59, 76, 192):  A darker than the reference by the full-colour amount or more
//   t =  0   white
//   t = +1   red   (180, 4, 38):   A brighter by that amount or more
// Pixels outside the mask are black.
//
// relativeErrorImage: t = r / scale, r the signed per-pixel relative luminance error
//   (Y(a) − Y(b)) / max(Y(b), 0.01·mean Y(b)) (image_metrics.hpp); full colour at ±scale.
// ratioImage: t = log2(Y'(a) / Y'(b)) / stops, Y' = max(Y, floor), floor = kRatioDarkFraction ×
//   mean Y(b) over the mask; full colour at a ratio of 2^stops (or its inverse). Pixels where
//   both Y(a) and Y(b) are below the floor are grey (128, 128, 128): their ratio is noise. A
//   ratio in stops reads the same in dark and bright regions, where the relative error saturates
//   at +100 % in one direction only, so it shows "half as bright" as strongly as "twice as
//   bright".
#include <string>

#include "core/image.hpp"
#include "metrics/pixel_mask.hpp"

namespace vct::metrics {

inline constexpr double kDefaultErrorScale = 0.2;
inline constexpr double kDefaultRatioStops = 2.0;
inline constexpr double kRatioDarkFraction = 1e-3;  // × mean reference luminance

Image8 relativeErrorImage(const ImageF& a, const ImageF& b, const PixelMask& mask, double scale);
Image8 ratioImage(const ImageF& a, const ImageF& b, const PixelMask& mask, double stops);

// One line that explains the colours, for the command's output.
std::string errorImageLegend(double scale);
std::string ratioImageLegend(double stops);

}  // namespace vct::metrics
