#pragma once
// False-colour picture of where and how A differs from the reference B: the signed per-pixel
// relative luminance error r = (Y(a) − Y(b)) / max(Y(b), 0.01·mean Y(b)) (image_metrics.hpp)
// on a diverging blue–white–red scale (Moreland's cool-warm end points):
//   r ≤ −scale   blue  (59, 76, 192):  A darker than the reference by `scale` or more
//   r = 0        white
//   r ≥ +scale   red   (180, 4, 38):   A brighter by `scale` or more
// linear in r between them (interpolated in sRGB-encoded values). Pixels outside the mask are
// black.
#include <string>

#include "core/image.hpp"
#include "metrics/pixel_mask.hpp"

namespace vct::metrics {

inline constexpr double kDefaultErrorScale = 0.2;

Image8 relativeErrorImage(const ImageF& a, const ImageF& b, const PixelMask& mask, double scale);

// One line that explains the colours, for the command's output.
std::string errorImageLegend(double scale);

}  // namespace vct::metrics
