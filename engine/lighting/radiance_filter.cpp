#include "lighting/radiance_filter.hpp"

#include <array>

#include "gl/shader.hpp"

namespace vct {
namespace {
constexpr GLbitfield kBarrier = GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
}  // namespace

RadianceFilter::RadianceFilter()
    : touchParents_(gl::buildProgram({{GL_COMPUTE_SHADER, "touch_parents.comp"}})),
      leaf_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_leaf.comp"}}, {"RADIANCE 1", "WORK_LIST_TOUCHED 1"})),
      parent_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_mip.comp"}}, {"WORK_LIST_TOUCHED 1"})),
      touchBorder_(gl::buildProgram({{GL_COMPUTE_SHADER, "touch_border.comp"}})),
      completion_({"WORK_LIST_BORDER 1", "POOL_RGBA32F 1"}),
      directionCompletion_({"WORK_LIST_BORDER 1"}) {}

std::array<RadianceFilter::Channel, 2> RadianceFilter::channelsOf(const RadianceVolume& volume) {
    return {Channel{volume.cellRadiance.id(), volume.rawRadiance.id(), volume.partial, volume.brickRadiance.id(),
                    completion_},
            Channel{volume.cellDirection.id(), volume.rawDirection.id(), volume.partialDirection,
                    volume.brickDirection.id(), directionCompletion_}};
}

void RadianceFilter::mip(const Octree& octree, RadianceVolume& volume) {
    const auto channels = channelsOf(volume);
    for (int level = octree.levels - 1; level >= 0; --level) {
        GLuint p = touchParents_.id();
        glUseProgram(p);
        octree.bind(p);
        bindRadianceVolume(volume);
        gl::setUniform(p, "uLevel", level);
        listDispatch_.dispatch(volume, kTouchedCountSlot + unsigned(level + 1));
        glMemoryBarrier(kBarrier);

        const bool leafLevel = level == octree.levels - 1;
        for (const Channel& channel : channels) {
            p = leafLevel ? leaf_.id() : parent_.id();
            glUseProgram(p);
            octree.bind(p);
            setBrickPoolUniforms(p, octree);
            bindRadianceVolume(volume);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 18, channel.cells);
            gl::setUniform(p, "uLevel", level);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, channel.raw);
            glBindImageTexture(0, channel.partial[level].texture.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
            if (!leafLevel)
                glBindImageTexture(1, channel.partial[level + 1].texture.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
            listDispatch_.dispatch(volume, kTouchedCountSlot + unsigned(level));
            glMemoryBarrier(kBarrier);
        }
    }
    gl::checkErrors("filtering radiance up the octree");
}

void RadianceFilter::border(const Octree& octree, RadianceVolume& volume) {
    const auto channels = channelsOf(volume);
    for (int level = 0; level < octree.levels; ++level) {
        GLuint p = touchBorder_.id();
        glUseProgram(p);
        octree.bind(p);
        bindRadianceVolume(volume);
        gl::setUniform(p, "uLevel", level);
        listDispatch_.dispatch(volume, kTouchedCountSlot + unsigned(level));
        glMemoryBarrier(kBarrier);

        for (const Channel& channel : channels) {
            channel.completion.prepare(octree, channel.partial[level], channel.pool);
            bindRadianceVolume(volume);
            listDispatch_.dispatch(volume, kBorderCountSlot + unsigned(level));
            glMemoryBarrier(kBarrier | GL_TEXTURE_FETCH_BARRIER_BIT);
        }
    }
    gl::checkErrors("completing radiance bricks");
}

}  // namespace vct
