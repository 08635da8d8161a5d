#include "voxel/octree.hpp"

#include "gl/shader.hpp"
#include "voxel/brick_pool.hpp"
#include "gl/shader_interface.hpp"

namespace vct {

std::size_t Octree::cellBytes() const {
    std::size_t total = 0;
    for (const gl::Buffer* b : {&cellAlbedo, &cellNormal, &cellArea, &cellFragments, &cellEmissive, &cellColumns, &cellOpacity})
        total += std::size_t(gl::bufferBytes(*b));
    return total;
}

std::size_t Octree::brickPoolBytes() const {
    return 3 * vct::brickPoolBytes(brickPoolBricks, 8) + std::size_t(gl::bufferBytes(rawValue));
}

std::size_t Octree::denseTextureBytes() const {
    std::size_t total = 0;
    for (std::size_t n = std::size_t(grid.resolution()); n >= 1; n /= 2) total += n * n * n * 8;
    return total;
}

void Octree::bind(GLuint program) const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_NODE_CHILD, child.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_NODE_MASK, mask.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_NODE_COORD, coord.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_NODE_PARENT, parent.id());
    if (neighbours) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_NODE_NEIGHBOUR, neighbours.id());
    gl::setUniform(program, "uLevels", levels);
    glProgramUniform1uiv(program, glGetUniformLocation(program, "uLevelStart"), kMaxOctreeLevels + 1, levelStart.data());
    glProgramUniform1uiv(program, glGetUniformLocation(program, "uLevelCount"), kMaxOctreeLevels + 1, levelCount.data());
}

}  // namespace vct
