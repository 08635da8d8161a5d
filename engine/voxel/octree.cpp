#include "voxel/octree.hpp"

#include "gl/shader.hpp"

namespace vct {

std::size_t Octree::brickPoolBytes() const {
    return 2 * (std::size_t(brickPoolBricks.x) * brickPoolBricks.y * brickPoolBricks.z * 27 * 8 + std::size_t(nodeCount) * 16);
}

std::size_t Octree::denseTextureBytes() const {
    std::size_t total = 0;
    for (std::size_t n = std::size_t(grid.resolution()); n >= 1; n /= 2) total += n * n * n * 8;
    return total;
}

void Octree::bind(GLuint program) const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, child.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, mask.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, coord.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, parent.id());
    if (neighbours) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, neighbours.id());
    gl::setUniform(program, "uLevels", levels);
    glProgramUniform1uiv(program, glGetUniformLocation(program, "uLevelStart"), kMaxOctreeLevels + 1, levelStart.data());
    glProgramUniform1uiv(program, glGetUniformLocation(program, "uLevelCount"), kMaxOctreeLevels + 1, levelCount.data());
}

}  // namespace vct
