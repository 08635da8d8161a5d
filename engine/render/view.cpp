#include "render/view.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/cube_faces.hpp"

namespace vct {
namespace {

// Maps [0,1] depth to [1,0]: z' = w − z in clip space.
glm::dmat4 reverseDepth() {
    glm::dmat4 m(1.0);
    m[2][2] = -1.0;
    m[3][2] = 1.0;
    return m;
}

glm::dvec3 stableUp(const glm::dvec3& forward, const glm::dvec3& preferred) {
    if (glm::length(glm::cross(forward, preferred)) > 1e-6) return preferred;
    return std::abs(forward.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
}

ViewTransform finish(const glm::dmat4& view, const glm::dmat4& projection, const glm::dvec3& eye,
                     const glm::dvec3& forward, int width, int height) {
    ViewTransform t;
    t.view = glm::mat4(view);
    t.projection = glm::mat4(projection);
    t.viewProjection = glm::mat4(projection * view);
    t.eye = glm::vec3(eye);
    t.forward = glm::vec3(forward);
    t.width = width;
    t.height = height;
    return t;
}

}  // namespace

ViewTransform cameraView(const Camera& camera, const Scene& scene, int width, int height, glm::dvec2 jitter) {
    const glm::dvec3 eye = camera.eye - scene.origin;
    const glm::dvec3 target = camera.target - scene.origin;
    const glm::dvec3 forward = glm::normalize(target - eye);
    const glm::dmat4 view = glm::lookAtRH(eye, target, stableUp(forward, camera.up));
    // Near plane relative to the scene size: never in absolute units, so scale does not matter.
    const double radius = 0.5 * glm::length(scene.worldBounds.size());
    const double nearPlane = std::max(radius * 1e-4, 1e-30);
    const double aspect = double(width) / double(height);
    const double f = 1.0 / std::tan(glm::radians(camera.fovYDeg) * 0.5);
    // Infinite reversed perspective: depth = near / view distance.
    glm::dmat4 projection(0.0);
    projection[0][0] = f / aspect;
    projection[1][1] = f;
    projection[2][3] = -1.0;
    projection[3][2] = nearPlane;
    // A shear that moves the image by −jitter: ndc' = ndc − projection[2].xy, since w = −z_view.
    projection[2][0] = 2.0 * jitter.x / width;
    projection[2][1] = -2.0 * jitter.y / height;  // image y runs down, ndc y up
    return finish(view, projection, eye, forward, width, height);
}

LightViewTransform lightView(const Light& light, const Scene& scene, int resolution, int face) {
    const Bounds bounds = scene.localBounds();
    const glm::dvec3 centre = bounds.centre();
    const double radius = std::max(0.5 * glm::length(bounds.size()), 1e-30);
    const glm::dvec3 direction = glm::normalize(light.direction);
    LightViewTransform result;
    if (light.type == LightType::Directional) {
        const glm::dvec3 eye = centre - direction * (2.0 * radius);
        const glm::dmat4 view = glm::lookAtRH(eye, centre, stableUp(direction, {0, 1, 0}));
        const glm::dmat4 projection =
            reverseDepth() * glm::orthoRH_ZO(-radius, radius, -radius, radius, radius * 0.5, radius * 3.5);
        result.view = finish(view, projection, eye, direction, resolution, resolution);
        const double texel = 2.0 * radius / resolution;
        result.texelWorldSize = float(texel);
        result.texelFootprint = texel * texel;
    } else {
        // A spot's view covers its outer cone; a point light's face covers the face's square,
        // 90°, widened by a margin of texels (kCubeFaceMarginTexels) on every side.
        const bool point = light.type == LightType::Point;
        const glm::dvec3 axis = point ? cubeFaceAxis(face) : direction;
        const glm::dvec3 eye = light.position - scene.origin;
        const double fov = point ? 2.0 * std::atan(resolution / double(resolution - 2 * kCubeFaceMarginTexels))
                                 : 2.0 * glm::radians(std::min(light.outerAngleDeg, 85.0));
        const double farthest = glm::length(eye - centre) + radius;
        const double nearPlane = std::max(farthest * 1e-4, 1e-30);
        const glm::dmat4 view = glm::lookAtRH(eye, eye + axis, stableUp(axis, {0, 1, 0}));
        const glm::dmat4 projection = reverseDepth() * glm::perspectiveRH_ZO(fov, 1.0, nearPlane, farthest);
        result.view = finish(view, projection, eye, axis, resolution, resolution);
        result.perspective = true;
        const double edge = 2.0 * std::tan(fov * 0.5) / resolution;  // texel edge on the plane at distance 1
        result.texelWorldSize = float(edge);
        result.texelFootprint = edge * edge;  // solid angle at the axis; texels off the axis: × cos³
    }
    return result;
}

}  // namespace vct
