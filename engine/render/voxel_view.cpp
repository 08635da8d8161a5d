#include "render/voxel_view.hpp"

#include <cmath>

#include "core/error.hpp"
#include "gl/shader.hpp"
#include "voxel/brick_pool.hpp"

namespace vct {

VoxelView::VoxelView(int width, int height)
    : width_(width),
      height_(height),
      image_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "voxel view")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "voxel_view.comp"}})) {}

void VoxelView::render(const Octree& octree, const Source& source, const Camera& camera, const Scene& scene, int level,
                       bool useBricks) {
    if (level < 1 || level > octree.levels)
        fail("--voxel-level ", level, " is out of range; this octree has levels 1..", octree.levels,
             " (", octree.levels, " = the voxels themselves)");
    const glm::dvec3 eye = octree.grid.toVoxel(camera.eye - scene.origin);
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    glm::dvec3 right = glm::cross(forward, camera.up);
    if (glm::length(right) < 1e-9) right = glm::cross(forward, glm::dvec3(1, 0, 0));
    right = glm::normalize(right);
    const glm::dvec3 up = glm::cross(right, forward);
    const double tanY = std::tan(glm::radians(camera.fovYDeg) * 0.5);
    const double tanX = tanY * double(width_) / double(height_);

    const GLuint p = program_.id();
    glUseProgram(p);
    octree.bind(p);
    setBrickPoolUniforms(p, octree);
    gl::setUniform(p, "uEyeVoxel", glm::vec3(eye));
    gl::setUniform(p, "uForward", glm::vec3(forward));
    gl::setUniform(p, "uRight", glm::vec3(right));
    gl::setUniform(p, "uUp", glm::vec3(up));
    gl::setUniform(p, "uTanHalfFov", glm::vec2(tanX, tanY));
    gl::setUniform(p, "uViewLevel", level);
    gl::setUniform(p, "uUseBricks", useBricks ? 1 : 0);
    gl::setUniform(p, "uShowRadiance", source.radiance ? 1 : 0);
    glBindTextureUnit(0, source.bricks);
    glBindTextureUnit(1, octree.brickAlbedo.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, octree.cellAlbedo.id());
    if (source.radiance) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 18, source.cells);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, source.raw);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 20, octree.rawValue.id());
    glBindImageTexture(0, image_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(GLuint((width_ + 7) / 8), GLuint((height_ + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace vct
