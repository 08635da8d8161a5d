#include "voxel/bricks_mip.hpp"

#include "gl/compute.hpp"

namespace vct {

BricksMip::BricksMip() : program_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_mip.comp"}})) {}

void BricksMip::run(const Octree& octree, LeafPartials leafPartials) {
    struct Channel {
        GLuint raw, pool;
        PartialBricks child;
    };
    Channel channels[] = {{octree.rawValue.id(), octree.brickAlbedo.id(), std::move(leafPartials.albedo)},
                          {octree.rawOpacity.id(), octree.brickOpacity.id(), std::move(leafPartials.opacity)}};
    for (Channel& channel : channels) {
        // Only two levels of partial bricks are alive at a time: the level and its children.
        for (int level = octree.levels - 2; level >= 0; --level) {
            PartialBricks partial = createPartialBricks(octree, level);
            gl::ComputeCall call(program_);
            octree.bind(call.program());
            setBrickPoolUniforms(call.program(), octree);
            call.uniform("uLevel", level)
                .storage(gl::SSBO_RAW_VALUE, channel.raw)
                .image(gl::IMAGE_PARTIAL_BRICKS, partial.texture.id(), GL_WRITE_ONLY, GL_RGBA32F)
                .image(gl::IMAGE_CHILD_PARTIAL_BRICKS, channel.child.texture.id(), GL_READ_ONLY, GL_RGBA32F)
                .dispatch1D(octree.levelCount[level], 64, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
            completion_.run(octree, partial, channel.pool);
            channel.child = std::move(partial);
        }
    }
    gl::checkErrors("filtering bricks up the octree");
}

}  // namespace vct
