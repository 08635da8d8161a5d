#include "voxel/bricks.hpp"

#include "gl/compute.hpp"
#include "gl/shader.hpp"

namespace vct {

Bricks::Bricks() : leaf_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_leaf.comp"}})) {}

PartialBricks Bricks::run(Octree& octree) {
    allocateBrickPool(octree);
    const int leafLevel = octree.levels - 1;
    PartialBricks partial = createPartialBricks(octree, leafLevel);
    const GLuint p = leaf_.id();
    glUseProgram(p);
    octree.bind(p);
    setBrickPoolUniforms(p, octree);
    gl::setUniform(p, "uLevel", leafLevel);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, octree.cellAlbedo.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, octree.rawValue.id());
    glBindImageTexture(0, partial.texture.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    gl::dispatch1D(octree.levelCount[leafLevel], 64);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    completion_.run(octree, partial, octree.brickAlbedo.id());
    gl::checkErrors("filling the leaf bricks");
    return partial;
}

}  // namespace vct
