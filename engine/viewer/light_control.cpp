#include "viewer/light_control.hpp"

#include <algorithm>
#include <cmath>

namespace vct::viewer {

LightAngles anglesOfDirection(const glm::dvec3& direction) {
    const glm::dvec3 toLight = -glm::normalize(direction);
    LightAngles angles;
    angles.elevationDeg = glm::degrees(std::asin(std::clamp(toLight.y, -1.0, 1.0)));
    angles.azimuthDeg = glm::degrees(std::atan2(toLight.x, toLight.z));
    return angles;
}

glm::dvec3 directionOfAngles(const LightAngles& angles) {
    const double elevation = glm::radians(angles.elevationDeg), azimuth = glm::radians(angles.azimuthDeg);
    const glm::dvec3 toLight(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                             std::cos(elevation) * std::cos(azimuth));
    return -toLight;
}

int steeredLight(const std::vector<Light>& lights) {
    // A point light shines every way: it has no direction to steer.
    for (LightType type : {LightType::Directional, LightType::Spot})
        for (std::size_t i = 0; i < lights.size(); ++i)
            if (lights[i].type == type) return int(i);
    return -1;
}

void rotateLight(Light& light, double azimuthStepDeg, double elevationStepDeg) {
    LightAngles angles = anglesOfDirection(light.direction);
    angles.azimuthDeg = std::remainder(angles.azimuthDeg + azimuthStepDeg, 360.0);
    angles.elevationDeg = std::clamp(angles.elevationDeg + elevationStepDeg, -89.0, 89.0);
    light.direction = directionOfAngles(angles);
}

}  // namespace vct::viewer
