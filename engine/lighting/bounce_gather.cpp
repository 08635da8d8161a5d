#include "lighting/bounce_gather.hpp"

#include <algorithm>

#include "gl/driver_checks.hpp"

namespace vct {

BounceGather::BounceGather()
    : shareWithSiblings_(gl::buildProgram({{GL_COMPUTE_SHADER, "bounce_gather.comp"}}, {"SHARE_WITH_SIBLINGS 1"})),
      shareWithSecond_(gl::buildProgram({{GL_COMPUTE_SHADER, "bounce_gather.comp"}}, {"SHARE_WITH_SECOND 1"})) {}

const BounceGather::Gathers& BounceGather::gathers(int lanes) {
    Gathers& g = gathers_[lanes];
    if (!g.firstChildren.id()) {
        g.firstChildren = gl::buildProgram({{GL_COMPUTE_SHADER, "bounce_gather.comp"}},
                                           {"GATHER_FIRST_CHILDREN 1", coneLanesDefine(lanes)});
        g.listed = gl::buildProgram({{GL_COMPUTE_SHADER, "bounce_gather.comp"}}, {"GATHER_LISTED 1", coneLanesDefine(lanes)});
    }
    return g;
}

void BounceGather::run(const Octree& octree, RadianceVolume& volume, RadianceFilter& filter, int bounces,
                       const ConeSettings& cones) {
    const std::size_t cells = octree.cellCount();
    const std::size_t vec4s = cells * 16;  // one vec4 per cell
    // The first bounce's radiance (one vec4 per cell) and exit shares (two), the gathered
    // irradiance (two), this bounce's radiance (one) and exit shares (two): bounce_gather.comp.
    if (baseBytes_ != 8 * vec4s) {
        base_ = gl::createBuffer(GLsizeiptr(8 * vec4s), nullptr, 0,
                                 "first-bounce radiance, gathered irradiance, the bounce's radiance");
        baseBytes_ = 8 * vec4s;
        listBytes_ = 4 * std::max<std::size_t>(cells, 1);
        ownGatherCells_ = gl::createBuffer(GLsizeiptr(listBytes_), nullptr, 0, "cells that gather their own bounce");
    }
    gl::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glCopyNamedBufferSubData(volume.cellRadiance.id(), base_.id(), 0, 0, GLsizeiptr(vec4s));
    glCopyNamedBufferSubData(volume.cellExitShares.id(), base_.id(), 0, GLintptr(vec4s), GLsizeiptr(2 * vec4s));
    constexpr GLbitfield kBarrier = GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT;
    const ConeSettings bounceCones = voxelGatherCones(cones);
    const Gathers& gather = gathers(coneLanes(bounceCones));
    const GLintptr bounceRadiance = GLintptr(5 * vec4s), bounceShares = GLintptr(6 * vec4s);
    for (int bounce = 2; bounce <= bounces; ++bounce) {
        // The cones read the last bounce's radiance, the gathers write this one's beside it: a cell
        // that stores nothing keeps the last bounce's.
        gl::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        glCopyNamedBufferSubData(volume.cellRadiance.id(), base_.id(), 0, bounceRadiance, GLsizeiptr(vec4s));
        glCopyNamedBufferSubData(volume.cellExitShares.id(), base_.id(), 0, bounceShares, GLsizeiptr(2 * vec4s));
        clearListCounts(volume, gl::BOUNCE_LIST_COUNT_SLOT, gl::SECOND_SHARE_COUNT_SLOT + 1);
        // First children (one per leaf node), then their siblings (one per cell), which read what
        // the first children gathered or list themselves, then the listed cells, then the cells
        // that take what a leaf's second gatherer (a listed cell) gathered.
        auto prepare = [&](const gl::Program& program) {
            gl::ComputeCall call(program);
            setConeMarchUniforms(call, octree, volume, bounceCones);
            bindRadianceVolume(volume);
            call.storage(gl::SSBO_CELL_VALUES, octree.cellAlbedo)
                .storage(gl::SSBO_CELL_NORMAL, octree.cellNormal)
                .storage(gl::SSBO_BOUNCE_BASE, base_)
                .storage(gl::SSBO_BOUNCE_LIST, ownGatherCells_);
            return call;
        };
        prepare(gather.firstChildren).dispatch1D(std::uint32_t(octree.leafCount()), 64, kBarrier);
        prepare(shareWithSiblings_).dispatch1D(std::uint32_t(cells), 64, kBarrier);
        listDispatch_.dispatch(prepare(gather.listed), volume, gl::BOUNCE_LIST_COUNT_SLOT, kBarrier);
        listDispatch_.dispatch(prepare(shareWithSecond_), volume, gl::SECOND_SHARE_COUNT_SLOT, kBarrier);
        gl::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        glCopyNamedBufferSubData(base_.id(), volume.cellRadiance.id(), bounceRadiance, 0, GLsizeiptr(vec4s));
        glCopyNamedBufferSubData(base_.id(), volume.cellExitShares.id(), bounceShares, 0, GLsizeiptr(2 * vec4s));
        gl::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        filter.leaves(octree, volume);
        filter.mip(octree, volume);
    }
    gl::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    gl::fitBuffer(volume.bouncedCellRadiance, GLsizeiptr(vec4s), 0, "cell radiance after the bounces");
    gl::fitBuffer(volume.bouncedCellExitShares, GLsizeiptr(2 * vec4s), 0, "cell exit shares after the bounces");
    glCopyNamedBufferSubData(volume.cellRadiance.id(), volume.bouncedCellRadiance.id(), 0, 0, GLsizeiptr(vec4s));
    glCopyNamedBufferSubData(volume.cellExitShares.id(), volume.bouncedCellExitShares.id(), 0, 0, GLsizeiptr(2 * vec4s));
    glCopyNamedBufferSubData(base_.id(), volume.cellRadiance.id(), 0, 0, GLsizeiptr(vec4s));
    glCopyNamedBufferSubData(base_.id(), volume.cellExitShares.id(), GLintptr(vec4s), 0, GLsizeiptr(2 * vec4s));
    gl::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    gl::checkErrors("gathering further bounces");
}

std::uint32_t BounceGather::ownGathers(const RadianceVolume& volume) const {
    std::uint32_t count = 0;
    gl::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(volume.listCounts.id(), GLintptr(4 * gl::BOUNCE_LIST_COUNT_SLOT), 4, &count);
    return count;
}

}  // namespace vct
