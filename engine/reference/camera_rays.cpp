#include "reference/camera_rays.hpp"

#include <cmath>

namespace vct::reference {
namespace {

// The engine's stableUp (engine/render/view.cpp): keep the preferred up unless it is (nearly)
// parallel to the view direction.
glm::dvec3 stableUp(const glm::dvec3& forward, const glm::dvec3& preferred) {
    if (glm::length(glm::cross(forward, preferred)) > 1e-6) return preferred;
    return std::abs(forward.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
}

}  // namespace

CameraRays::CameraRays(const Camera& camera, const Scene& scene, int width, int height)
    : width_(width), height_(height) {
    eye_ = camera.eye - scene.origin;
    const glm::dvec3 target = camera.target - scene.origin;
    forward_ = glm::normalize(target - eye_);
    right_ = glm::normalize(glm::cross(forward_, stableUp(forward_, camera.up)));
    up_ = glm::cross(right_, forward_);
    tanHalfY_ = std::tan(glm::radians(camera.fovYDeg) * 0.5);
    aspect_ = double(width) / double(height);
}

Ray CameraRays::at(double px, double py) const {
    const double ndcX = px / width_ * 2.0 - 1.0;
    const double ndcY = 1.0 - py / height_ * 2.0;
    const glm::dvec3 d = forward_ + ndcX * tanHalfY_ * aspect_ * right_ + ndcY * tanHalfY_ * up_;
    return {glm::vec3(eye_), glm::vec3(glm::normalize(d))};
}

}  // namespace vct::reference
