#pragma once
// Steering the sun: azimuth and elevation of the first directional light (or, in a scene
// without one, of the first light's axis, e.g. the Cornell box's spot).
//   elevation: angle of the direction *towards* the light above the horizontal (y up), degrees;
//   azimuth:   angle of that direction about +y, measured from +z towards +x, degrees.
#include <vector>

#include <glm/glm.hpp>

#include "scene/light.hpp"

namespace vct::viewer {

struct LightAngles {
    double azimuthDeg = 0.0;
    double elevationDeg = 90.0;
};

// `direction` is the direction of travel (as in vct::Light).
LightAngles anglesOfDirection(const glm::dvec3& direction);
glm::dvec3 directionOfAngles(const LightAngles& angles);  // unit, direction of travel

// Index of the light the arrow keys steer: the first directional light, else the first light;
// -1 when there is none.
int steeredLight(const std::vector<Light>& lights);

// Rotates `light` by the given steps; elevation stays within [-89, 89]°.
void rotateLight(Light& light, double azimuthStepDeg, double elevationStepDeg);

}  // namespace vct::viewer
