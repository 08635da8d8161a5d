#pragma once
// The camera's pixel rays in voxel space, for the debug views that march the octree from the eye
// (voxel_view.comp, cone_view.comp): pixel (x, y) of a width × height image looks along
// normalize(forward + u·tanHalfFov.x·right + v·tanHalfFov.y·up), u and v its centre in [−1, 1].
#include <glm/glm.hpp>

#include "gl/compute.hpp"
#include "gl/objects.hpp"
#include "gl/shader.hpp"
#include "scene/camera.hpp"
#include "scene/scene.hpp"
#include "voxel/octree.hpp"

namespace vct {

struct EyeRays {
    glm::vec3 eye{0.0f};  // voxel space
    glm::vec3 forward{0.0f}, right{0.0f}, up{0.0f};
    glm::vec2 tanHalfFov{0.0f};
};

EyeRays eyeRaysInVoxels(const Octree& octree, const Camera& camera, const Scene& scene, int width, int height);

// A debug view that marches one ray or cone per pixel from the eye, with one compute shader,
// into an image of its own: one RGBA32F texel per output pixel, bound at gl::IMAGE_VOXEL_VIEW
// (VoxelView, ConeView).
class EyeRayView {
public:
    GLuint image() const { return image_.id(); }
    std::size_t bytes() const { return std::size_t(width_) * height_ * 16; }

protected:
    EyeRayView(int width, int height, const char* label, const char* shader);
    // Sets the eye rays of `camera` (uEyeVoxel, uForward, uRight, uUp, uTanHalfFov) and the image
    // on `call` (a call of program_ with the view's own inputs bound), then runs it once per pixel.
    void march(gl::ComputeCall& call, const Octree& octree, const Camera& camera, const Scene& scene) const;

    gl::Program program_;

private:
    int width_, height_;
    gl::Texture image_;
};

}  // namespace vct
