#pragma once
// Small helpers for validating and printing vectors in error messages.
#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "core/error.hpp"

namespace vct {

inline bool isFinite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// World coordinates (vertices, camera, lights) beyond ±kMaxWorldCoordinate are treated like
// non-finite ones: differences of such points overflow float on the GPU (1e18 leaves room for
// squares of distances and texel areas), and no real scene needs them.
constexpr double kMaxWorldCoordinate = 1e18;
inline bool isUsableCoordinate(const glm::dvec3& v) {
    return isFinite(v) && std::abs(v.x) <= kMaxWorldCoordinate && std::abs(v.y) <= kMaxWorldCoordinate &&
           std::abs(v.z) <= kMaxWorldCoordinate;
}

inline std::string toText(const glm::dvec3& v) { return concat("(", v.x, ", ", v.y, ", ", v.z, ")"); }

}  // namespace vct
