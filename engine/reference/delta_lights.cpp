#include "reference/delta_lights.hpp"

#include <cmath>

#include "reference/sampling.hpp"

namespace vct::reference {

DeltaLights::DeltaLights(const Scene& scene) {
    for (const Light& light : scene.lights) {
        LocalLight l;
        l.type = light.type;
        l.position = light.position - scene.origin;
        l.direction = light.type == LightType::Point ? glm::dvec3(0.0) : glm::normalize(light.direction);
        l.radiometric = light.color * lightQuantity(light);
        l.innerDeg = light.innerAngleDeg;
        l.outerDeg = light.outerAngleDeg;
        lights_.push_back(l);
    }
}

glm::dvec3 DeltaLights::reflected(const RayScene& rays, const SurfaceHit& hit, glm::vec3 normal,
                                  glm::vec3 geometricNormal, glm::vec3 albedo) const {
    glm::dvec3 irradiance(0.0);  // Σ E·cosθ·V
    const glm::dvec3 p(hit.position);
    for (const LocalLight& light : lights_) {
        if (light.type == LightType::Directional) {
            const glm::dvec3 toLight = -light.direction;
            const double cosTheta = glm::dot(glm::dvec3(normal), toLight);
            if (cosTheta <= 0.0 || glm::dot(glm::dvec3(geometricNormal), toLight) <= 0.0) continue;
            const glm::vec3 d(toLight);
            if (rays.occluded(hit.spawnPoint(d), glm::normalize(d))) continue;
            irradiance += light.radiometric * cosTheta;
        } else {
            const glm::dvec3 toLightVector = light.position - p;
            const double d2 = std::max(glm::dot(toLightVector, toLightVector), 1e-30);
            const glm::dvec3 toLight = toLightVector / std::sqrt(d2);
            const double cosTheta = glm::dot(glm::dvec3(normal), toLight);
            if (cosTheta <= 0.0 || glm::dot(glm::dvec3(geometricNormal), toLight) <= 0.0) continue;
            const double falloff = light.type == LightType::Point
                                       ? 1.0
                                       : spotFalloff(glm::dot(-toLight, light.direction), light.innerDeg, light.outerDeg);
            if (falloff <= 0.0) continue;
            // The shadow ray runs from the offset origin to the light itself, and stops just
            // short of it so that geometry touching the light does not count.
            const glm::vec3 origin = hit.spawnPoint(glm::vec3(toLight));
            const glm::dvec3 span = light.position - glm::dvec3(origin);
            const double distance = glm::length(span);
            if (!(distance > 0.0)) continue;
            if (rays.occluded(origin, glm::vec3(span / distance), float(distance * (1.0 - 1e-5)))) continue;
            irradiance += light.radiometric * (falloff * cosTheta / d2);
        }
    }
    return glm::dvec3(albedo) / kPi * irradiance;
}

}  // namespace vct::reference
