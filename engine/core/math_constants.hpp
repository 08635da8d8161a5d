#pragma once
// Mathematical constants of the C++ side (GLSL: shaders/math.glsl).
#include <numbers>

namespace vct {

inline constexpr double kPi = std::numbers::pi;
inline constexpr float kPiF = std::numbers::pi_v<float>;

}  // namespace vct
