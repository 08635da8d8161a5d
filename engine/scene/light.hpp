#pragma once
// Lights in physical units (DESIGN 5.3). The reference path tracer evaluates exactly the same
// functions, so engine and reference agree on what a light delivers.
//
//   Directional (sun): `irradiance` E in W/m² on a surface perpendicular to the light.
//       A Lambertian surface of albedo ρ at angle θ to the light reflects L = ρ/π · E · cosθ.
//   Spot: `intensity` I in W/sr along its axis, attenuated by 1/d² and by spotFalloff():
//       E(point) = I · spotFalloff(cos α) · cosθ / d²,   α = angle between axis and the point.
//   Point: `intensity` I in W/sr in every direction, attenuated by 1/d²:
//       E(point) = I · cosθ / d².   (`direction` and the cone angles are not used.)
//
// `direction` is always the direction in which light travels (from the light into the scene):
// a sun overhead has direction (0,-1,0); a spot pointing at the floor too.
#include <glm/glm.hpp>
#include <string>

namespace vct {

enum class LightType { Directional, Spot, Point };

struct Light {
    LightType type = LightType::Directional;
    glm::dvec3 position{0.0};             // world space; spot and point
    glm::dvec3 direction{0.0, -1.0, 0.0};  // unit, direction of travel
    glm::dvec3 color{1.0};                // linear RGB tint multiplying the scalar quantity
    double irradiance = 1.0;              // directional: W/m²
    double intensity = 1.0;               // spot and point: W/sr
    double innerAngleDeg = 30.0;          // spot: full intensity inside this half-angle
    double outerAngleDeg = 45.0;          // spot: zero outside this half-angle

    bool operator==(const Light&) const = default;
};

// Angular falloff of a spot light. With c = cos α, ci = cos(inner), co = cos(outer):
//   t = clamp((c − co) / (ci − co), 0, 1),   falloff = t² (3 − 2t)   (smoothstep in cos α).
// The GLSL twin lives in shaders/lights.glsl; keep the two identical.
inline double spotFalloff(double cosAngle, double innerAngleDeg, double outerAngleDeg) {
    const double ci = std::cos(glm::radians(innerAngleDeg));
    const double co = std::cos(glm::radians(outerAngleDeg));
    if (ci - co <= 0.0) return cosAngle >= co ? 1.0 : 0.0;
    const double t = glm::clamp((cosAngle - co) / (ci - co), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Irradiance (W/m²) or intensity (W/sr) times the largest colour component must lie in this
// range: the GPU computes in float (1e-38..3e38), and E = I/d² and ρ/π·E must stay inside it.
constexpr double kMinLightQuantity = 1e-20;
constexpr double kMaxLightQuantity = 1e20;

// Throws vct::Error naming the light and the bad parameter (non-finite, non-positive, outside
// kMinLightQuantity..kMaxLightQuantity, zero direction, inner > outer, outer ≥ 90°).
void validateLight(const Light& light, const std::string& what);

std::string describe(const Light& light);

// The light's scalar quantity: irradiance (W/m²) for a directional light, intensity (W/sr) else.
inline double lightQuantity(const Light& light) {
    return light.type == LightType::Directional ? light.irradiance : light.intensity;
}

// "directional light", "spot light" or "point light", for messages.
const char* lightKindName(LightType type);

}  // namespace vct
