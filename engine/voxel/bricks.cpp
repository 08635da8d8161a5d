#include "voxel/bricks.hpp"

#include "gl/compute.hpp"
#include "gl/shader.hpp"

namespace vct {

Bricks::Bricks()
    : albedoLeaf_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_leaf.comp"}})),
      opacityLeaf_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_leaf.comp"}}, {"OPACITY 1"})) {}

LeafPartials Bricks::run(Octree& octree) {
    allocateBrickPool(octree);
    const int leafLevel = octree.levels - 1;
    LeafPartials partials{createPartialBricks(octree, leafLevel), createPartialBricks(octree, leafLevel)};
    struct Channel {
        GLuint program, cells, raw, pool;
        const PartialBricks& partial;
    };
    const Channel channels[] = {
        {albedoLeaf_.id(), octree.cellAlbedo.id(), octree.rawValue.id(), octree.brickAlbedo.id(), partials.albedo},
        {opacityLeaf_.id(), octree.cellOpacity.id(), octree.rawOpacity.id(), octree.brickOpacity.id(), partials.opacity}};
    for (const Channel& channel : channels) {
        glUseProgram(channel.program);
        octree.bind(channel.program);
        setBrickPoolUniforms(channel.program, octree);
        gl::setUniform(channel.program, "uLevel", leafLevel);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, channel.cells);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, channel.raw);
        glBindImageTexture(0, channel.partial.texture.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        gl::dispatch1D(octree.levelCount[leafLevel], 64);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        completion_.run(octree, channel.partial, channel.pool);
    }
    gl::checkErrors("filling the leaf bricks");
    return partials;
}

}  // namespace vct
