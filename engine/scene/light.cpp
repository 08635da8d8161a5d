#include "scene/light.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/error.hpp"
#include "core/vector_text.hpp"

namespace vct {
namespace {
// The shaders work in float: a quantity far outside float's range would reach them as 0 or Inf
// (and the image as NaN). kMinLightQuantity..kMaxLightQuantity leaves room for 1/d² and the
// albedo (light.hpp).
void checkLightRange(double quantity, const glm::dvec3& color, const std::string& what, const char* kind,
                     const char* name, const char* unit) {
    const double tinted = quantity * std::max({color.x, color.y, color.z});
    if (tinted < kMinLightQuantity || tinted > kMaxLightQuantity)
        fail(what, " (", kind, "): ", name, " ", quantity, " ", unit, " × colour ", toText(color), " = ", tinted,
             " is outside the supported range ", kMinLightQuantity, "..", kMaxLightQuantity, " ", unit,
             "; rescale the scene's lights (and the exposure)");
}
}  // namespace

const char* lightKindName(LightType type) {
    switch (type) {
        case LightType::Directional: return "directional light";
        case LightType::Spot: return "spot light";
        case LightType::Point: return "point light";
    }
    return "light";
}

void validateLight(const Light& light, const std::string& what) {
    const char* kind = lightKindName(light.type);
    if (light.type != LightType::Point) {
        if (!isFinite(light.direction))
            fail(what, " (", kind, "): direction ", toText(light.direction),
                 " is not finite; give a direction such as (0, -1, 0)");
        if (glm::length(light.direction) == 0.0)
            fail(what, " (", kind, "): direction is the zero vector; give the direction in which the "
                       "light travels, e.g. (0, -1, 0) for light from straight above");
    }
    if (!isFinite(light.color) || light.color.x < 0.0 || light.color.y < 0.0 ||
        light.color.z < 0.0)
        fail(what, " (", kind, "): colour ", toText(light.color),
             " must be finite and non-negative (linear RGB, e.g. (1, 1, 1))");
    if (light.color == glm::dvec3(0.0))
        fail(what, " (", kind, "): colour is black, so the light emits nothing; use a positive "
                   "colour such as (1, 1, 1)");
    if (light.type == LightType::Directional) {
        if (!std::isfinite(light.irradiance) || light.irradiance <= 0.0)
            fail(what, " (directional light): irradiance ", light.irradiance,
                 " W/m² must be a positive finite number (bright daylight is ~1000 W/m²; "
                 "scenes here use 1-20 with a matching exposure)");
        checkLightRange(light.irradiance, light.color, what, "directional light", "irradiance", "W/m²");
        return;
    }
    if (!isUsableCoordinate(light.position))
        fail(what, " (", kind, "): position ", toText(light.position), " is not finite or beyond ±",
             kMaxWorldCoordinate);
    if (!std::isfinite(light.intensity) || light.intensity <= 0.0)
        fail(what, " (", kind, "): intensity ", light.intensity, " W/sr must be a positive finite number");
    checkLightRange(light.intensity, light.color, what, kind, "intensity", "W/sr");
    if (light.type == LightType::Point) return;
    if (!std::isfinite(light.innerAngleDeg) || !std::isfinite(light.outerAngleDeg))
        fail(what, " (spot light): cone angles inner ", light.innerAngleDeg, "°, outer ",
             light.outerAngleDeg, "° must be finite");
    if (light.innerAngleDeg < 0.0)
        fail(what, " (spot light): inner cone angle ", light.innerAngleDeg,
             "° is negative; use a half-angle in [0°, outer angle]");
    if (light.outerAngleDeg < 0.01)
        fail(what, " (spot light): outer cone angle ", light.outerAngleDeg,
             "° must be at least 0.01° (it is the half-angle outside which the spot is dark)");
    if (light.innerAngleDeg > light.outerAngleDeg)
        fail(what, " (spot light): inner cone angle ", light.innerAngleDeg,
             "° is larger than the outer angle ", light.outerAngleDeg,
             "°; the inner half-angle must not exceed the outer one");
    if (light.outerAngleDeg >= 90.0)
        fail(what, " (spot light): outer cone angle ", light.outerAngleDeg,
             "° must be below 90° (half-angle; a spot lights at most a hemisphere)");
}

std::string describe(const Light& light) {
    std::ostringstream out;
    out << std::setprecision(4);
    const glm::dvec3 d = light.direction;
    if (light.type == LightType::Directional) {
        out << "directional light: direction (" << d.x << ", " << d.y << ", " << d.z
            << "), irradiance " << light.irradiance << " W/m²";
    } else if (light.type == LightType::Point) {
        const glm::dvec3 p = light.position;
        out << "point light: position (" << p.x << ", " << p.y << ", " << p.z << "), intensity " << light.intensity
            << " W/sr";
    } else {
        const glm::dvec3 p = light.position;
        out << "spot light: position (" << p.x << ", " << p.y << ", " << p.z << "), direction ("
            << d.x << ", " << d.y << ", " << d.z << "), intensity " << light.intensity
            << " W/sr, cone " << light.innerAngleDeg << "°–" << light.outerAngleDeg << "°";
    }
    if (light.color != glm::dvec3(1.0))
        out << ", colour (" << light.color.x << ", " << light.color.y << ", " << light.color.z
            << ")";
    return out.str();
}

}  // namespace vct
