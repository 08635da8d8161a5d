#include "scene/camera.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/vector_text.hpp"

namespace vct {
Camera changedCamera(Camera camera, const CameraChanges& changes) {
    if (changes.eye) camera.eye = *changes.eye;
    if (changes.target) camera.target = *changes.target;
    if (changes.up) camera.up = *changes.up;
    if (changes.fovYDeg) camera.fovYDeg = *changes.fovYDeg;
    validateCamera(camera);
    return camera;
}

void validateCamera(const Camera& camera) {
    const std::string what = concat("camera '", camera.name, "'");
    if (!isUsableCoordinate(camera.eye))
        fail(what, ": eye ", toText(camera.eye), " is not finite or beyond ±", kMaxWorldCoordinate);
    if (!isUsableCoordinate(camera.target))
        fail(what, ": target ", toText(camera.target), " is not finite or beyond ±", kMaxWorldCoordinate);
    if (!isFinite(camera.up)) fail(what, ": up vector ", toText(camera.up), " is not finite");
    // Below 0.001° the projection's scale (1/tan) leaves float's useful range.
    if (!std::isfinite(camera.fovYDeg) || camera.fovYDeg < 1e-3 || camera.fovYDeg >= 180.0)
        fail(what, ": vertical field of view ", camera.fovYDeg,
             "° must be at least 0.001° and below 180°; 40°-60° is typical");
    const glm::dvec3 view = camera.target - camera.eye;
    const double viewLength = glm::length(view);
    if (viewLength == 0.0 || !std::isfinite(viewLength))
        fail(what, ": eye and target are the same point ", toText(camera.eye),
             "; the target must be a point the camera looks at, away from the eye");
    const double upLength = glm::length(camera.up);
    if (upLength == 0.0 || !std::isfinite(upLength))
        fail(what, ": up vector is zero; use e.g. (0, 1, 0)");
    // Parallel when the sine of the angle between them is (numerically) zero.
    const double sine = glm::length(glm::cross(view / viewLength, camera.up / upLength));
    if (sine < 1e-6)
        fail(what, ": up vector ", toText(camera.up), " is parallel to the view direction ",
             toText(view / viewLength), "; choose an up vector not along the line of sight");
}

}  // namespace vct
