#pragma once
// Pinhole camera. World-space values are kept in double precision; the renderer converts them
// to the scene-local frame (world − Scene::origin) before going to float, so a scene far from
// the world origin renders exactly like one centred on it.
#include <glm/glm.hpp>
#include <optional>
#include <string>

namespace vct {

struct Camera {
    std::string name;                 // preset name ("default", glTF camera name, …)
    glm::dvec3 eye{0.0, 0.0, 5.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovYDeg = 45.0;            // vertical field of view

    bool operator==(const Camera&) const = default;
};

// Throws vct::Error when eye/target/up/fov are non-finite, eye == target, up ∥ view direction
// or fov outside (0, 180).
void validateCamera(const Camera& camera);

// A view of its own on top of a preset (`vct render --eye --target --up --fov`, a sweep's camera
// object): the parts given replace the preset's.
struct CameraChanges {
    std::optional<glm::dvec3> eye, target, up;
    std::optional<double> fovYDeg;

    bool any() const { return eye || target || up || fovYDeg; }
};
// `preset` with `changes` applied; throws as validateCamera.
Camera changedCamera(Camera preset, const CameraChanges& changes);

}  // namespace vct
