#pragma once
// Camera and light projections in the scene-local frame (world − Scene::origin), computed in
// double precision and only then rounded to float.
//
// Depth convention everywhere in vct: clip control [0,1] with *reversed* depth (near → 1,
// far → 0, cleared to 0, test GL_GREATER). With a float depth buffer this keeps precision
// uniform over distance, so a 10⁻⁴ m scene and a 10⁵ m scene rasterize alike.
#include <glm/glm.hpp>

#include "scene/camera.hpp"
#include "scene/light.hpp"
#include "scene/scene.hpp"

namespace vct {

struct ViewTransform {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f};
    glm::vec3 eye{0.0f};      // scene-local
    glm::vec3 forward{0.0f};  // unit
    int width = 0;
    int height = 0;
};

// Perspective camera with an infinite far plane (reversed depth). `jitter` moves the point each
// pixel samples away from its centre, in pixels (x right, y down, within ±½): the image position
// (x + ½ + jitter.x, y + ½ + jitter.y) of reference/camera_rays.hpp is what pixel (x, y) shows.
ViewTransform cameraView(const Camera& camera, const Scene& scene, int width, int height,
                         glm::dvec2 jitter = glm::dvec2(0.0));

// Light-view projection: orthographic over the scene's bounding sphere for a directional light,
// perspective with the outer cone angle for a spot. `texelFootprint` is what one texel covers:
// area in m² perpendicular to the light (directional) or solid angle in sr at the axis (spot).
struct LightViewTransform {
    ViewTransform view;
    bool perspective = false;
    double texelFootprint = 0.0;  // double: (scene size / resolution)² leaves float's range for 1e±18 scenes
    float texelWorldSize = 0.0f;  // directional: texel edge in metres; spot: edge at distance 1
};
// The view of a light's light-view map; `face` (0..5, render/cube_faces.hpp) picks a point
// light's cube face and is ignored for the other lights.
LightViewTransform lightView(const Light& light, const Scene& scene, int resolution, int face = 0);

}  // namespace vct
