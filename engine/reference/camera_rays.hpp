#pragma once
// Primary rays of the engine's pinhole camera (engine/render/view.cpp cameraView), so that a
// reference pixel sees exactly what the rasterized pixel sees:
//   * scene-local frame (world − Scene::origin), computed in double;
//   * right-handed lookAt: forward = normalize(target − eye), right = normalize(forward × up),
//     up' = right × forward; an up parallel to forward falls back to x, then z (stableUp);
//   * vertical field of view fovYDeg, aspect = width / height;
//   * image position (px, py) in pixels, py = 0 at the TOP edge; the pixel centre of (x, y) is
//     (x + ½, y + ½), and ndc = (px/w·2 − 1, 1 − py/h·2);
//   * direction = normalize(forward + ndc.x·tan(fovY/2)·aspect·right + ndc.y·tan(fovY/2)·up').
#include <glm/glm.hpp>

#include "scene/camera.hpp"
#include "scene/scene.hpp"

namespace vct::reference {

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction;  // unit
};

class CameraRays {
public:
    CameraRays(const Camera& camera, const Scene& scene, int width, int height);
    Ray at(double px, double py) const;  // continuous image position, see above

private:
    glm::dvec3 eye_, forward_, right_, up_;
    double tanHalfY_, aspect_;
    int width_, height_;
};

}  // namespace vct::reference
