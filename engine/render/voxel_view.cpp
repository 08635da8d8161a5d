#include "render/voxel_view.hpp"

#include <cmath>

#include "core/error.hpp"
#include "gl/compute.hpp"
#include "voxel/brick_pool.hpp"

namespace vct {

VoxelView::VoxelView(int width, int height)
    : width_(width),
      height_(height),
      image_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "voxel view")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "voxel_view.comp"}})) {}

void VoxelView::render(const Octree& octree, const RadianceVolume* radiance, const Camera& camera, const Scene& scene,
                       int level, bool useBricks) {
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

    gl::ComputeCall call(program_);
    octree.bind(call.program());
    setBrickPoolUniforms(call.program(), octree);
    call.uniform("uEyeVoxel", glm::vec3(eye))
        .uniform("uForward", glm::vec3(forward))
        .uniform("uRight", glm::vec3(right))
        .uniform("uUp", glm::vec3(up))
        .uniform("uTanHalfFov", glm::vec2(tanX, tanY))
        .uniform("uViewLevel", level)
        .uniform("uUseBricks", useBricks ? 1 : 0)
        .uniform("uShowRadiance", radiance ? 1 : 0)
        .texture(gl::TEXTURE_VIEW_ALBEDO_BRICKS, octree.brickAlbedo.id())
        .storage(gl::SSBO_CELL_VALUES, octree.cellAlbedo)
        .storage(gl::SSBO_RAW_VALUE, octree.rawValue)
        .image(gl::IMAGE_VOXEL_VIEW, image_.id(), GL_WRITE_ONLY, GL_RGBA32F);
    if (radiance) {
        call.storage(gl::SSBO_CELL_RADIANCE, radiance->cellRadiance);
        bindDirectionalTexture(call, *radiance);
    }
    call.dispatchImage(width_, height_, GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace vct
