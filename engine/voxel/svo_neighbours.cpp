#include "voxel/svo_neighbours.hpp"

#include "gl/compute.hpp"
#include "gl/shader.hpp"

namespace vct {

SvoNeighbours::SvoNeighbours() : program_(gl::buildProgram({{GL_COMPUTE_SHADER, "svo_neighbours.comp"}})) {}

void SvoNeighbours::run(Octree& octree) {
    octree.neighbours = gl::createBuffer(GLsizeiptr(octree.nodeCount) * 6 * 4, nullptr, 0, "octree neighbours");
    const GLuint p = program_.id();
    glUseProgram(p);
    octree.bind(p);
    for (int level = 0; level < octree.levels; ++level) {
        gl::setUniform(p, "uLevel", level);
        gl::dispatch1D(octree.levelCount[level], 64);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    gl::checkErrors("linking octree neighbours");
}

}  // namespace vct
