#pragma once
// Fly camera of the viewer: W A S D move in the view plane, R / F along the world up axis, a
// left-button drag turns (yaw about world up, pitch kept within ±89°), the wheel scales the speed.
// It edits a vct::Camera in world space (double precision), so presets and `--eye/--target` are
// exactly what it starts from and what Home returns to.
#include <glm/glm.hpp>

#include "scene/camera.hpp"
#include "scene/scene.hpp"

namespace vct::viewer {

class CameraController {
public:
    // `sceneSize` (the bounds' diagonal) sets the initial speed: 15 % of it per second.
    CameraController(const Camera& start, double sceneSize);

    void setCamera(const Camera& camera);  // jump to a preset (speed stays)
    // `move`: x right, y world up, z forward, each in -1..1; `seconds` of travel at the speed.
    void move(const glm::dvec3& move, double seconds);
    void look(double dxPixels, double dyPixels);  // drag: pixels to the right / down
    void scaleSpeed(double notches);              // ×1.25 per notch

    const Camera& camera() const { return camera_; }
    double speed() const { return speed_; }  // world units per second
    static constexpr double kDegreesPerPixel = 0.2;

private:
    glm::dvec3 forward() const;

    Camera camera_;
    glm::dvec3 worldUp_;
    double targetDistance_;
    double speed_;
};

}  // namespace vct::viewer
