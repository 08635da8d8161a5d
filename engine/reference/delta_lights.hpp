#pragma once
// Next-event estimation for the scene's lights. Every light type is a delta light (a direction,
// a point): a bounce ray can never hit them, so sampling them explicitly at every surface hit is
// the only way they contribute, and it is exact (no pdf: one shadow ray per light).
//
//   directional: E = irradiance · colour,                       shadow ray to infinity
//   spot:        E = I · colour · spotFalloff(cos α) / d²,      shadow ray to the light position
//   point:       E = I · colour / d²,                           shadow ray to the light position
//   L = ρ/π · E · cosθ · visibility,   θ against the shading normal turned to the viewer
//
// spotFalloff is the one in engine/scene/light.hpp, which the GLSL side mirrors.
#include <vector>

#include <glm/glm.hpp>

#include "reference/ray_scene.hpp"
#include "scene/light.hpp"
#include "scene/scene.hpp"

namespace vct::reference {

class DeltaLights {
public:
    explicit DeltaLights(const Scene& scene);  // takes the lights into the scene-local frame

    // Reflected radiance ρ/π · Σ E·cosθ·V at `hit`. `normal` is the shading normal and
    // `geometricNormal` the triangle's normal, both already turned to face the incoming ray: a
    // light counts only where both see it (cosθ > 0 against the shading normal, and in front of
    // the triangle itself, so an interpolated normal cannot let light through a closed wall).
    glm::dvec3 reflected(const RayScene& rays, const SurfaceHit& hit, glm::vec3 normal, glm::vec3 geometricNormal,
                         glm::vec3 albedo) const;

    bool empty() const { return lights_.empty(); }

private:
    struct LocalLight {
        LightType type;
        glm::dvec3 position;     // scene-local (spot, point)
        glm::dvec3 direction;    // unit, direction of travel (spot, directional)
        glm::dvec3 radiometric;  // E·colour (W/m²) or I·colour (W/sr)
        double innerDeg, outerDeg;
    };
    std::vector<LocalLight> lights_;
};

}  // namespace vct::reference
