#pragma once
// The display transform on the CPU: the C++ twin of shaders/tonemap.glsl and of the composite
// pass's exposure. `vct reference` writes its PNG with it and `vct compare` computes PSNR/SSIM on
// its output, so a reference PNG, an engine PNG and the image metrics all see the same pixels.
//
//   display = linearToSrgb(toneCurve(radiance · 2^EV, curve))        each channel in [0, 1]
//   8 bits  = round(display · 255)                                   (GL's unorm8 conversion)
//
// Arithmetic is in float, as in GLSL, with the same formulas; keep the two files identical.
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "core/image.hpp"

namespace vct {

enum class TonemapCurve {
    Aces,      // Narkowicz's fit of the ACES filmic curve
    Reinhard,  // x / (1 + x)
    Clamp,     // no curve: values above 1 clip
};

TonemapCurve parseTonemapCurve(const std::string& name);  // throws listing the valid names
const char* tonemapCurveName(TonemapCurve curve);

glm::vec3 toneCurve(glm::vec3 x, TonemapCurve curve);
glm::vec3 linearToSrgb(glm::vec3 linear);  // clamps to [0, 1], then the sRGB OETF
float srgbToLinear(float encoded);         // the inverse EOTF, for 8-bit sRGB data

// Linear radiance → display-referred sRGB-encoded value in [0, 1] (before 8-bit quantization).
glm::vec3 displayTransform(glm::vec3 radiance, double exposureEV, TonemapCurve curve);
std::uint8_t toUnorm8(float value);  // round(clamp(value, 0, 1) · 255)

// The whole image through displayTransform and toUnorm8; alpha is 255 (as the engine's PNG).
Image8 tonemapImage(const ImageF& hdr, double exposureEV, TonemapCurve curve);

}  // namespace vct
