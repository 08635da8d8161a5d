#include "voxel/svo_neighbours.hpp"

#include "gl/compute.hpp"

namespace vct {

SvoNeighbours::SvoNeighbours() : program_(gl::buildProgram({{GL_COMPUTE_SHADER, "svo_neighbours.comp"}})) {}

void SvoNeighbours::run(Octree& octree) {
    octree.neighbours = gl::createBuffer(GLsizeiptr(octree.nodeCount) * 6 * 4, nullptr, 0, "octree neighbours");
    gl::ComputeCall call(program_);
    octree.bind(call.program());
    for (int level = 0; level < octree.levels; ++level)
        call.uniform("uLevel", level).dispatch1D(octree.levelCount[level], 64, GL_SHADER_STORAGE_BARRIER_BIT);
    gl::checkErrors("linking octree neighbours");
}

}  // namespace vct
