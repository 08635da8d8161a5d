#include "viewer/camera_controller.hpp"

#include <algorithm>
#include <cmath>

namespace vct::viewer {

CameraController::CameraController(const Camera& start, double sceneSize)
    : speed_(std::max(0.15 * sceneSize, 1e-6)) {
    setCamera(start);
}

void CameraController::setCamera(const Camera& camera) {
    camera_ = camera;
    worldUp_ = glm::normalize(camera.up);
    targetDistance_ = glm::length(camera.target - camera.eye);
}

glm::dvec3 CameraController::forward() const { return glm::normalize(camera_.target - camera_.eye); }

void CameraController::move(const glm::dvec3& move, double seconds) {
    if (move == glm::dvec3(0.0) || seconds <= 0.0) return;
    const glm::dvec3 f = forward();
    const glm::dvec3 right = glm::normalize(glm::cross(f, worldUp_));
    const glm::dvec3 step = (right * move.x + worldUp_ * move.y + f * move.z) * (speed_ * seconds);
    camera_.eye += step;
    camera_.target += step;
}

void CameraController::look(double dxPixels, double dyPixels) {
    if (dxPixels == 0.0 && dyPixels == 0.0) return;
    const glm::dvec3 f = forward();
    // Current yaw/pitch in the frame of the world up axis.
    const double pitch = std::asin(std::clamp(glm::dot(f, worldUp_), -1.0, 1.0));
    const glm::dvec3 horizontal = f - worldUp_ * glm::dot(f, worldUp_);
    glm::dvec3 heading = glm::length(horizontal) > 1e-9 ? glm::normalize(horizontal)
                                                        : glm::normalize(glm::cross(worldUp_, glm::dvec3(1, 0, 0)));
    const double yawStep = -glm::radians(dxPixels * kDegreesPerPixel);
    const double newPitch = std::clamp(pitch - glm::radians(dyPixels * kDegreesPerPixel), glm::radians(-89.0),
                                       glm::radians(89.0));
    // Rotate the heading about world up (Rodrigues; heading ⟂ up).
    heading = heading * std::cos(yawStep) + glm::cross(worldUp_, heading) * std::sin(yawStep);
    const glm::dvec3 newForward = heading * std::cos(newPitch) + worldUp_ * std::sin(newPitch);
    camera_.target = camera_.eye + newForward * targetDistance_;
    camera_.up = worldUp_;
}

void CameraController::scaleSpeed(double notches) { speed_ = std::clamp(speed_ * std::pow(1.25, notches), 1e-9, 1e12); }

}  // namespace vct::viewer
