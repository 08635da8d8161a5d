#include "lighting/bounce_gather.hpp"

#include "lighting/list_dispatch.hpp"

namespace vct {

BounceGather::BounceGather() : gather_(gl::buildProgram({{GL_COMPUTE_SHADER, "bounce_gather.comp"}})) {}

void BounceGather::run(const Octree& octree, RadianceVolume& volume, RadianceFilter& filter, int bounces,
                       const ConeSettings& cones) {
    const std::size_t cells = octree.cellCount();
    const std::size_t half = cells * 16;  // one vec4 per cell
    if (baseBytes_ != 2 * half) {
        base_ = gl::createBuffer(GLsizeiptr(2 * half), nullptr, 0, "first-bounce radiance");
        baseBytes_ = 2 * half;
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glCopyNamedBufferSubData(volume.cellRadiance.id(), base_.id(), 0, 0, GLsizeiptr(half));
    glCopyNamedBufferSubData(volume.cellDirection.id(), base_.id(), 0, GLintptr(half), GLsizeiptr(half));
    for (int bounce = 2; bounce <= bounces; ++bounce) {
        gl::ComputeCall call(gather_);
        setConeMarchUniforms(call, octree, volume, cones);
        bindRadianceVolume(volume);
        call.storage(gl::SSBO_CELL_VALUES, octree.cellAlbedo)
            .storage(gl::SSBO_CELL_NORMAL, octree.cellNormal)
            .storage(gl::SSBO_BOUNCE_BASE, base_)
            .dispatch1D(std::uint32_t(cells), 64,
                        GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
        filter.leaves(octree, volume);
        filter.mip(octree, volume);
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glCopyNamedBufferSubData(base_.id(), volume.cellRadiance.id(), 0, 0, GLsizeiptr(half));
    glCopyNamedBufferSubData(base_.id(), volume.cellDirection.id(), GLintptr(half), 0, GLsizeiptr(half));
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    gl::checkErrors("gathering further bounces");
}

}  // namespace vct
