#include "voxel/bricks_mip.hpp"

#include "gl/compute.hpp"
#include "gl/shader.hpp"

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
            const GLuint p = program_.id();
            glUseProgram(p);
            octree.bind(p);
            setBrickPoolUniforms(p, octree);
            gl::setUniform(p, "uLevel", level);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, channel.raw);
            glBindImageTexture(0, partial.texture.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
            glBindImageTexture(1, channel.child.texture.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
            gl::dispatch1D(octree.levelCount[level], 64);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
            completion_.run(octree, partial, channel.pool);
            channel.child = std::move(partial);
        }
    }
    gl::checkErrors("filtering bricks up the octree");
}

}  // namespace vct
