#include "voxel/bricks.hpp"

namespace vct {

Bricks::Bricks()
    : albedoLeaf_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_leaf.comp"}})),
      opacityLeaf_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_opacity.comp"}}, {"LEAF 1"})) {}

PartialBricks Bricks::run(Octree& octree) {
    fitBrickPools(octree);
    const int leafLevel = octree.levels - 1;
    PartialBricks albedo = createPartialBricks(octree, leafLevel);
    brickLevelCall(albedoLeaf_, octree, leafLevel)
        .storage(gl::SSBO_CELL_VALUES, octree.cellAlbedo)
        .storage(gl::SSBO_RAW_VALUE, octree.rawValue)
        .image(gl::IMAGE_PARTIAL_BRICKS, albedo.texture.id(), GL_WRITE_ONLY, GL_RGBA32F)
        .dispatch1D(octree.levelCount[leafLevel], 64, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    completion_.run(octree, albedo, octree.brickAlbedo.id());
    runOpacityPass(opacityLeaf_, octree, leafLevel);
    gl::checkErrors("filling the leaf bricks");
    return albedo;
}

void runOpacityPass(const gl::Program& program, const Octree& octree, int level) {
    brickLevelCall(program, octree, level)
        .storage(gl::SSBO_CELL_OPACITY, octree.cellOpacity)
        .image(gl::IMAGE_OPACITY_PLUS, octree.brickOpacityPlus.id(), GL_READ_WRITE, GL_RGBA16F, true)
        .image(gl::IMAGE_OPACITY_MINUS, octree.brickOpacityMinus.id(), GL_READ_WRITE, GL_RGBA16F, true)
        .dispatch1D(octree.levelCount[level], 64, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace vct
