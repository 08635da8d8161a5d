#include "render/eye_rays.hpp"

#include <cmath>

namespace vct {

EyeRays eyeRaysInVoxels(const Octree& octree, const Camera& camera, const Scene& scene, int width, int height) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    glm::dvec3 right = glm::cross(forward, camera.up);
    if (glm::length(right) < 1e-9) right = glm::cross(forward, glm::dvec3(1, 0, 0));
    right = glm::normalize(right);
    const double tanY = std::tan(glm::radians(camera.fovYDeg) * 0.5);
    EyeRays rays;
    rays.eye = glm::vec3(octree.grid.toVoxel(camera.eye - scene.origin));
    rays.forward = glm::vec3(forward);
    rays.right = glm::vec3(right);
    rays.up = glm::vec3(glm::cross(right, forward));
    rays.tanHalfFov = glm::vec2(tanY * double(width) / double(height), tanY);
    return rays;
}

EyeRayView::EyeRayView(int width, int height, const char* label, const char* shader)
    : program_(gl::buildProgram({{GL_COMPUTE_SHADER, shader}})),
      width_(width),
      height_(height),
      image_(gl::createTexture2D(GL_RGBA32F, width, height, 1, label)) {}

void EyeRayView::march(gl::ComputeCall& call, const Octree& octree, const Camera& camera, const Scene& scene) const {
    const EyeRays rays = eyeRaysInVoxels(octree, camera, scene, width_, height_);
    call.uniform("uEyeVoxel", rays.eye)
        .uniform("uForward", rays.forward)
        .uniform("uRight", rays.right)
        .uniform("uUp", rays.up)
        .uniform("uTanHalfFov", rays.tanHalfFov)
        .image(gl::IMAGE_VOXEL_VIEW, image_.id(), GL_WRITE_ONLY, GL_RGBA32F)
        .dispatchImage(width_, height_, GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace vct
