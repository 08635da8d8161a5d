#include "lighting/radiance_filter.hpp"

#include <array>


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
        gl::ComputeCall touch(touchParents_);
        octree.bind(touch.program());
        bindRadianceVolume(volume);
        touch.uniform("uLevel", level);
        listDispatch_.dispatch(touch, volume, kTouchedCountSlot + unsigned(level + 1), kBarrier);

        const bool leafLevel = level == octree.levels - 1;
        for (const Channel& channel : channels) {
            gl::ComputeCall filter(leafLevel ? leaf_ : parent_);
            octree.bind(filter.program());
            setBrickPoolUniforms(filter.program(), octree);
            bindRadianceVolume(volume);
            filter.storage(gl::SSBO_CELL_RADIANCE, channel.cells)
                .uniform("uLevel", level)
                .storage(gl::SSBO_RAW_VALUE, channel.raw)
                .image(gl::IMAGE_PARTIAL_BRICKS, channel.partial[level].texture.id(), GL_WRITE_ONLY, GL_RGBA32F);
            if (!leafLevel)
                filter.image(gl::IMAGE_CHILD_PARTIAL_BRICKS, channel.partial[level + 1].texture.id(), GL_READ_ONLY,
                             GL_RGBA32F);
            listDispatch_.dispatch(filter, volume, kTouchedCountSlot + unsigned(level), kBarrier);
        }
    }
    gl::checkErrors("filtering radiance up the octree");
}

void RadianceFilter::border(const Octree& octree, RadianceVolume& volume) {
    const auto channels = channelsOf(volume);
    for (int level = 0; level < octree.levels; ++level) {
        gl::ComputeCall touch(touchBorder_);
        octree.bind(touch.program());
        bindRadianceVolume(volume);
        touch.uniform("uLevel", level);
        listDispatch_.dispatch(touch, volume, kTouchedCountSlot + unsigned(level), kBarrier);

        for (const Channel& channel : channels) {
            const gl::ComputeCall complete = channel.completion.prepare(octree, channel.partial[level], channel.pool);
            bindRadianceVolume(volume);
            listDispatch_.dispatch(complete, volume, kBorderCountSlot + unsigned(level), kBarrier | GL_TEXTURE_FETCH_BARRIER_BIT);
        }
    }
    gl::checkErrors("completing radiance bricks");
}

}  // namespace vct
