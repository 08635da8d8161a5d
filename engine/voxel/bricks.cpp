#include "voxel/bricks.hpp"

#include "gl/compute.hpp"

namespace vct {

Bricks::Bricks()
    : albedoLeaf_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_leaf.comp"}})),
      opacityLeaf_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_leaf.comp"}}, {"OPACITY 1"})) {}

LeafPartials Bricks::run(Octree& octree) {
    allocateBrickPool(octree);
    const int leafLevel = octree.levels - 1;
    LeafPartials partials{createPartialBricks(octree, leafLevel), createPartialBricks(octree, leafLevel)};
    struct Channel {
        const gl::Program& program;
        GLuint cells, raw, pool;
        const PartialBricks& partial;
    };
    const Channel channels[] = {
        {albedoLeaf_, octree.cellAlbedo.id(), octree.rawValue.id(), octree.brickAlbedo.id(), partials.albedo},
        {opacityLeaf_, octree.cellOpacity.id(), octree.rawOpacity.id(), octree.brickOpacity.id(), partials.opacity}};
    for (const Channel& channel : channels) {
        gl::ComputeCall call(channel.program);
        octree.bind(call.program());
        setBrickPoolUniforms(call.program(), octree);
        call.uniform("uLevel", leafLevel)
            .storage(gl::SSBO_CELL_VALUES, channel.cells)
            .storage(gl::SSBO_RAW_VALUE, channel.raw)
            .image(gl::IMAGE_PARTIAL_BRICKS, channel.partial.texture.id(), GL_WRITE_ONLY, GL_RGBA32F)
            .dispatch1D(octree.levelCount[leafLevel], 64, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        completion_.run(octree, channel.partial, channel.pool);
    }
    gl::checkErrors("filling the leaf bricks");
    return partials;
}

}  // namespace vct
