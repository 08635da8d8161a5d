#pragma once
// Small helpers for validating and printing vectors in error messages.
#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "core/error.hpp"

namespace vct {

inline bool isFinite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline std::string toText(const glm::dvec3& v) { return concat("(", v.x, ", ", v.y, ", ", v.z, ")"); }

}  // namespace vct
